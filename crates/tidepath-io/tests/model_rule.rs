//! A cost model's own feasibility rule (lfhh2019: F < 2) in the plan JSON: reported beside
//! tidepath's verdict for a model that has one, absent for the others.

use tidepath_io::scenario::{PlanRequest, Scenario};

/// A 700 x 500 m world with one disc between start and goal, still water, the given cost.
fn one_disc(cost: &str) -> Scenario {
    let text = format!(
        "name = \"one-disc\"\n[world]\ndimensions = 2\nbounds = {{ min = [0.0, 0.0, 0.0], max = [700.0, 500.0, 0.0] }}\n\
        [[world.obstacles]]\nkind = \"cylinder\"\ncenter = [350.0, 250.0]\nradius = 80.0\n\
        [vehicle]\nspeed = 1.5\nsafety_distance = 5.0\nmax_turn_deg = 180.0\n\
        [mission]\nstart = [50.0, 240.0, 0.0]\ngoal = [650.0, 260.0, 0.0]\n{cost}"
    );
    Scenario::from_toml(&text, "one-disc.toml").unwrap()
}

fn plan_json(s: &Scenario) -> serde_json::Value {
    let req = PlanRequest { planner: Some("visibility".into()), ..PlanRequest::default() };
    let r = s.plan(&req, &mut |_| {}).unwrap();
    serde_json::from_str(&r.to_json()).unwrap()
}

#[test]
fn the_rule_is_met_by_a_path_round_the_disc() {
    let v = plan_json(&one_disc("[cost]\nmodel = \"lfhh2019\"\n"));
    let m = &v["missions"][0];
    assert_eq!(m["feasible"], true);
    let cost = m["cost"].as_f64().unwrap();
    // Still water: the current term is 1/2; the detour adds a little length.
    assert!(cost > 0.5 && cost < 0.6, "{cost}");
    assert_eq!(m["model_rule"], serde_json::json!({ "below": 2.0, "met": true }));
}

/// With T_theta = 180 degrees every bend is unable: F >= 2 breaks the paper's rule while
/// tidepath (which allows any turn here) calls the same path feasible.
#[test]
fn the_rule_can_fail_where_tidepath_is_satisfied() {
    let v = plan_json(&one_disc("[cost]\nmodel = \"lfhh2019\"\nweights = { min_interior_angle_deg = 180.0 }\n"));
    let m = &v["missions"][0];
    assert_eq!(m["feasible"], true);
    assert!(m["cost"].as_f64().unwrap() >= 2.0);
    assert_eq!(m["model_rule"], serde_json::json!({ "below": 2.0, "met": false }));
}

#[test]
fn models_without_a_rule_write_no_field() {
    let v = plan_json(&one_disc(""));
    assert_eq!(v["cost_model"], "general");
    assert!(v["missions"][0].get("model_rule").is_none(), "{}", v["missions"][0]);
}
