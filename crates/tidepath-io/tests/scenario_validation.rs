//! Every rejected scenario value gets one clear message naming its field (one test row each).

use tidepath_io::scenario::{builtin, Scenario};

fn demo() -> String {
    builtin("demo").unwrap().to_string()
}

/// Loads `text` and expects an error that names `field` and contains `value`.
fn rejects(text: &str, field: &str, value: &str) {
    match Scenario::from_toml(text, "test.toml") {
        Ok(_) => panic!("accepted a scenario that should fail on {field}"),
        Err(e) => {
            let msg = e.to_string();
            assert!(msg.contains(field) && msg.contains(value), "expected {field} / {value} in: {msg}");
            assert!(!msg.contains('\n'), "multi-line message: {msg}");
        }
    }
}

fn with(old: &str, new: &str) -> String {
    let d = demo();
    assert!(d.contains(old), "demo lacks {old}");
    d.replacen(old, new, 1)
}

#[test]
fn demo_loads() {
    Scenario::from_toml(&demo(), "demo").unwrap();
}

#[test]
fn world_values() {
    rejects(&with("dimensions = 3", "dimensions = 4"), "world.dimensions", "4");
    rejects(
        &with("max = [20000.0, 12000.0, 0.0]", "max = [0.0, 12000.0, 0.0]"),
        "world.bounds",
        "min must be below max",
    );
    rejects(&with("sigma_x = 1800.0", "sigma_x = -1.0"), "world.terrain.peaks[0].sigma_x", "-1");
    rejects(&with("radius = 700.0", "radius = 0.0"), "world.obstacles[0].radius", "0");
    rejects(
        &with("min = [3500.0, 7000.0, -750.0]", "min = [4600.0, 7000.0, -750.0]"),
        "world.obstacles[3].min",
        "below max",
    );
    rejects(&with("core_radius = 1500.0", "core_radius = 0.0"), "world.current.vortices[0].core_radius", "0");
    rejects(&with("kind = \"peaks\"", "kind = \"mountains\""), "world.terrain", "mountains");
    rejects(&with("kind = \"sphere\"", "kind = \"cube\""), "world.obstacles[0]", "cube");
}

#[test]
fn grid_fields() {
    let grid = "[world.terrain]\nkind = \"grid\"\norigin = [0.0, 0.0]\nspacing = [10000.0, 6000.0]\nshape = [3, 3]\nelevations = [-900.0, -900.0, -900.0, -900.0, -900.0, -900.0, -900.0, -900.0]\n";
    let d = demo();
    let start = d.find("[world.terrain]").unwrap();
    let end = d.find("[[world.obstacles]]").unwrap();
    let text = format!("{}{}\n{}", &d[..start], grid, &d[end..]);
    rejects(&text, "world.terrain.elevations", "9");
    let bad_spacing = text.replace("spacing = [10000.0, 6000.0]", "spacing = [0.0, 6000.0]");
    rejects(&bad_spacing, "world.terrain.spacing", "positive");
    let jet = d.replace(
        "[world.current]\nkind = \"vortices\"",
        "[world.current]\nkind = \"jet\"\n[world.unused]\nkind = \"vortices\"",
    );
    rejects(&jet, "world", "unused");
}

#[test]
fn vehicle_values() {
    rejects(&with("speed = 1.5", "speed = 300.0"), "vehicle.speed", "300");
    rejects(&with("speed = 1.5", "speed = -1.0"), "vehicle.speed", "-1");
    // A speed range must hold the cruise speed, each end a plausible speed.
    rejects(&with("speed = 1.5", "speed = 1.5\nspeed_min = 2.0"), "vehicle.speed", "[2, 1.5]");
    rejects(&with("speed = 1.5", "speed = 1.5\nspeed_max = 1.0"), "vehicle.speed", "[1.5, 1]");
    rejects(&with("speed = 1.5", "speed = 1.5\nspeed_max = 500.0"), "vehicle.speed_max", "500");
    rejects(&with("speed = 1.5", "speed = 1.5\nspeed_min = nan"), "vehicle.speed_min", "NaN");
    rejects(&with("max_turn_deg = 60.0", "max_turn_deg = 270.0"), "vehicle.max_turn_deg", "270");
    rejects(&with("max_pitch_deg = 30.0", "max_pitch_deg = 0.0"), "vehicle.max_pitch_deg", "0");
    rejects(&with("depth_min = 5.0", "depth_min = 2000.0"), "vehicle.depth_min", "2000");
    rejects(&with("safety_distance = 25.0", "safety_distance = -5.0"), "vehicle.safety_distance", "-5");
    rejects(&with("max_pitch_deg = 30.0", "max_pitch_deg = 95.0"), "vehicle.max_pitch_deg", "95");
    rejects(&with("max_turn_deg = 60.0", "max_turn_deg = \"wide\""), "vehicle.max_turn_deg", "wide");
    let radius = |r: &str| with("safety_distance = 25.0", &format!("safety_distance = 25.0\nturn_radius = {r}"));
    rejects(&radius("-5.0"), "vehicle.turn_radius", "-5");
    rejects(&radius("0.0"), "vehicle.turn_radius", "0");
    rejects(&radius("2e6"), "vehicle.turn_radius", "2000000");
    rejects(&radius("nan"), "vehicle.turn_radius", "finite");
    let s = Scenario::from_toml(&radius("35.5"), "test.toml").unwrap();
    assert_eq!(s.missions[0].vehicle.turn_radius, Some(35.5));
    assert!(s.warnings.iter().all(|w| !w.contains("turn_radius")), "{:?}", s.warnings);
    assert_eq!(Scenario::from_toml(&demo(), "demo").unwrap().missions[0].vehicle.turn_radius, None);
}

#[test]
fn mission_values() {
    rejects(&with("goal = [19000.0, 6500.0, -300.0]", "goal = [19000.0, 6500.0]"), "mission.goal", "3");
    rejects(
        &with("start = [1000.0, 6000.0, -400.0]", "start = [-1000.0, 6000.0, -400.0]"),
        "mission.start",
        "outside the domain",
    );
    rejects(&with("departure_time = 0.0", "departure_time = 1e20"), "mission.departure_time", "1e20");
}

/// A start or goal in the seabed, an obstacle or outside the depth band is the plan's status,
/// decided before planning, with one line naming the field.
#[test]
fn invalid_start_and_goal_are_statuses() {
    use tidepath::planner::Status;
    use tidepath_io::scenario::PlanRequest;
    let cases = [
        ("start = [1000.0, 6000.0, -400.0]", "start = [1000.0, 6000.0, -2.0]", Status::InvalidStart, "depth band"),
        ("start = [1000.0, 6000.0, -400.0]", "start = [3600.0, 8000.0, -500.0]", Status::InvalidStart, "obstacle 3"),
        ("start = [1000.0, 6000.0, -400.0]", "start = [9500.0, 6080.0, -450.0]", Status::InvalidStart, "obstacle 0"),
        ("goal = [19000.0, 6500.0, -300.0]", "goal = [19000.0, 6500.0, -990.0]", Status::InvalidGoal, "seabed"),
    ];
    for (old, new, status, what) in cases {
        let s = Scenario::from_toml(&with(old, new), "t.toml").unwrap();
        let r = s.plan(&PlanRequest { iterations: Some(2), ..PlanRequest::default() }, &mut |_| {}).unwrap();
        assert_eq!(r.status, status, "{new}: {}", r.reason);
        let field = if status == Status::InvalidStart { "mission.start" } else { "mission.goal" };
        assert!(r.reason.starts_with(field) && r.reason.contains(what), "{}", r.reason);
        assert_eq!(r.evaluations, 0, "nothing is planned");
    }
}

#[test]
fn model_cost_encoding_planner_values() {
    rejects(&with("travel_time = \"crab\"", "travel_time = \"teleport\""), "model.travel_time", "teleport");
    rejects(&with("current_step = 250.0", "current_step = 0.0"), "model.current_step", "0");
    let tol = |t: &str| with("current_step = 250.0", &format!("current_step = 250.0\narc_tolerance = {t}"));
    rejects(&tol("0.0"), "model.arc_tolerance", "0");
    rejects(&tol("11.0"), "model.arc_tolerance", "11");
    assert_eq!(Scenario::from_toml(&tol("0.2"), "test.toml").unwrap().settings.arc_tolerance, 0.2);
    rejects(&with("model = \"general\"", "model = \"fancy\""), "cost.model", "fancy");
    rejects(&with("collision = 10.0", "collision = -1.0"), "cost.weights.collision", "-1");
    rejects(&with("length = 1.0, time = 1.0", "length = 1.0, tim = 1.0"), "cost.weights", "tim");
    rejects(&with("kind = \"sliced\"", "kind = \"spiral\""), "encoding.kind", "spiral");
    rejects(&with("waypoints = 10", "waypoints = 0"), "encoding.waypoints", "0");
    rejects(&with("waypoints = 10", "waypoints = 10\naxis = \"z\""), "encoding.axis", "z");
    let free_x = with("kind = \"sliced\"", "kind = \"free\"\naxis = \"x\"");
    rejects(&free_x, "encoding.axis", "the free encoding");
    Scenario::from_toml(&with("waypoints = 10", "waypoints = 10\naxis = \"y\""), "test.toml").unwrap();
    rejects(&with("vmax_fraction = 0.2", "vmax_fraction = -0.2"), "planner.params.pso", "-0.2");
    rejects(&with("id = \"pso\"", "id = \"pso\"\nspeed = 3"), "planner", "speed");
    rejects(&format!("{}\nextra = 1\n", demo()), "planner.params.pso", "extra");
}
