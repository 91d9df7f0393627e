//! The planner contract's promises, each pinned: what `exact` means and that graph planners
//! minimise the cost the evaluation reports.

use tidepath::geom::Vec3;
use tidepath::planner::Status;
use tidepath_io::scenario::{PlanRequest, Scenario};

/// A 700 x 500 m world with one disc between start and goal, still water: the case where
/// `astar` and `visibility` both said `exact` with different costs.
fn one_disc() -> Scenario {
    let text =
        "name = \"one-disc\"\n[world]\ndimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [700.0, 500.0, 0.0] }\n\
        [[world.obstacles]]\nkind = \"cylinder\"\ncenter = [350.0, 250.0]\nradius = 80.0\n\
        [vehicle]\nspeed = 1.5\nsafety_distance = 5.0\nmax_turn_deg = 180.0\n\
        [mission]\nstart = [50.0, 240.0, 0.0]\ngoal = [650.0, 260.0, 0.0]\n";
    Scenario::from_toml(text, "one-disc.toml").unwrap()
}

fn plan(s: &Scenario, id: &str) -> tidepath_io::PlanReport {
    s.plan(&PlanRequest { planner: Some(id.into()), ..PlanRequest::default() }, &mut |_| {}).unwrap()
}

#[test]
fn exact_names_its_search_space_and_the_plane_beats_the_raster() {
    let s = one_disc();
    let a = plan(&s, "astar");
    let v = plan(&s, "visibility");
    assert_eq!(a.status, Status::Exact, "{}", a.reason);
    assert_eq!(v.status, Status::Exact, "{}", v.reason);
    assert!(a.reason.contains("on the 8-connected") && a.reason.contains("raster"), "{}", a.reason);
    assert!(a.reason.contains("scenario's cost model"), "{}", a.reason);
    assert!(a.reason.contains("path-level terms"), "{}", a.reason);
    assert!(v.reason.contains("over all paths in the plane"), "{}", v.reason);
    let (ca, cv) = (a.cost.unwrap(), v.cost.unwrap());
    assert!(cv < ca, "visibility {cv} should be below astar {ca}");
}

/// In a current, the time term makes an edge's cost depend on its direction; the grid
/// planner's path costs exactly the sum of `motion_cost` over its edges (plus the path-level
/// terms, zero here), so what it minimises is what `eval` reports.
#[test]
fn a_grid_path_costs_the_sum_of_its_motion_costs() {
    let text = "name = \"stream\"\n[world]\ndimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [1000.0, 600.0, 0.0] }\n\
        [[world.obstacles]]\nkind = \"cylinder\"\ncenter = [500.0, 300.0]\nradius = 120.0\n\
        [world.current]\nkind = \"uniform\"\nvelocity = [0.0, 0.6, 0.0]\n\
        [vehicle]\nspeed = 2.0\nsafety_distance = 5.0\nmax_turn_deg = 180.0\n\
        [mission]\nstart = [60.0, 300.0, 0.0]\ngoal = [940.0, 300.0, 0.0]\n\
        [cost]\nmodel = \"general\"\nweights = { length = 1.0, time = 2.0, collision = 10.0, turn = 1.0, pitch = 1.0 }\n";
    let s = Scenario::from_toml(text, "stream.toml").unwrap();
    // Every raster planner (the planners that count expansions).
    let raster_planners =
        tidepath::planner::PLANNERS.iter().filter(|e| e.build.caps.counts_unit(tidepath::planner::Unit::Expansions));
    for id in raster_planners.map(|e| e.id) {
        let r = plan(&s, id);
        assert!(r.status.is_success(), "{id}: {}", r.reason);
        let cost = s.cost_model().unwrap();
        let model = s.path_model();
        let path: Vec<Vec3> = r.missions[0].waypoints.iter().map(|p| Vec3::from_array(*p)).collect();
        let (mut sum, mut t) = (0.0, s.departure_time);
        for w in path.windows(2) {
            let (c, arrival) = cost.motion_cost(&model, w[0], w[1], t).expect("every edge valid");
            sum += c;
            t = arrival;
        }
        let (total, terms) = cost.breakdown(&model, &path);
        let path_level: f64 = terms.iter().filter(|(n, _)| !cost.additive_terms().contains(n)).map(|(_, v)| v).sum();
        assert_eq!(path_level, 0.0, "{id}: {terms:?}");
        assert!((total - sum).abs() <= 1e-9 * total, "{id}: evaluation {total} vs sum of motion costs {sum}");
        assert!((r.cost.unwrap() - total).abs() <= 1e-12 * total);
    }
    // On the same raster, the path A* finds by the cost model costs no more than the one it
    // finds by length: it minimises the cost eval reports.
    let by_length = format!("{text}[planner.params.astar]\nobjective = \"length\"\n");
    let s_len = Scenario::from_toml(&by_length, "stream-length.toml").unwrap();
    let (by_cost, by_len) = (plan(&s, "astar"), plan(&s_len, "astar"));
    assert!(by_cost.cost.unwrap() <= by_len.cost.unwrap() + 1e-12, "{:?} vs {:?}", by_cost.cost, by_len.cost);
    assert!(by_len.length_m().unwrap() <= by_cost.length_m().unwrap() + 1e-9);
    assert_eq!(by_len.status, Status::Feasible, "length is not the scenario's cost: {}", by_len.reason);
}

/// A fleet in which one mission starts inside an obstacle: that mission is `invalid-start`,
/// by name, and the other is still planned.
#[test]
fn one_invalid_mission_does_not_sink_the_fleet() {
    let text =
        "name = \"pair\"\n[world]\ndimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [1000.0, 1000.0, 0.0] }\n\
        [[world.obstacles]]\nkind = \"cylinder\"\ncenter = [200.0, 800.0]\nradius = 50.0\n\
        [vehicle]\nspeed = 2.0\nsafety_distance = 5.0\nmax_turn_deg = 180.0\n\
        [[missions]]\nname = \"alpha\"\nstart = [100.0, 100.0, 0.0]\ngoal = [900.0, 100.0, 0.0]\n\
        [[missions]]\nname = \"bravo\"\nstart = [200.0, 800.0, 0.0]\ngoal = [900.0, 800.0, 0.0]\n";
    let s = Scenario::from_toml(text, "pair.toml").unwrap();
    for id in tidepath::planner::PLANNERS.iter().map(|e| e.id) {
        let r = plan(&s, id);
        assert_eq!(r.status, Status::InvalidStart, "{id}: {}", r.reason);
        assert!(r.reason.starts_with("mission bravo: missions[1].start"), "{id}: {}", r.reason);
        assert_eq!(r.missions[1].status, Status::InvalidStart);
        assert!(r.missions[1].waypoints.is_empty());
        assert!(r.missions[0].status.is_success(), "{id}: alpha {}: {}", r.missions[0].status, r.missions[0].reason);
        assert!(r.missions[0].waypoints.len() >= 2);
    }
}

mod short {
    use tidepath::optim::Progress;
    use tidepath::planner::{Planner, PlannerOutput, Problem, RunOptions, SearchStats};
    use tidepath::rng::Rng;
    use tidepath::termination::{StopReason, Termination};

    /// A planner that gets only half way: the path a tree planner returns when time runs out.
    pub struct HalfWay;

    impl Planner for HalfWay {
        fn id(&self) -> &'static str {
            "half-way"
        }

        fn plan(
            &mut self,
            problem: &Problem<'_>,
            _: &Termination,
            _: &mut Rng,
            _: RunOptions<'_>,
            _: &mut dyn FnMut(&Progress),
        ) -> PlannerOutput {
            let paths = problem.missions.iter().map(|m| vec![m.start, (m.start + m.goal) * 0.5]).collect();
            PlannerOutput {
                paths,
                speeds: Vec::new(),
                claim: None,
                stats: SearchStats { stop_reason: StopReason::WallTime, ..SearchStats::default() },
                graphs: Vec::new(),
            }
        }
    }
}

#[test]
fn a_path_that_stops_short_reports_the_distance_left() {
    use tidepath::planner::{BuildPlanner, Capabilities, PlannerSettings};
    use tidepath::registry::Entry;
    let caps = Capabilities { counts: &[], warm_start: false, ..Capabilities::OPTIMIZER };
    let registry = tidepath::planner::registry().with(Entry {
        id: "half-way",
        description: "stops half way",
        citation: "test",
        params: &[],
        build: BuildPlanner::direct(caps, |_: &PlannerSettings| Ok(Box::new(short::HalfWay))),
    });
    let s = one_disc();
    let req = PlanRequest { planner: Some("half-way".into()), time_limit_s: Some(1.0), ..PlanRequest::default() };
    let r = s.plan_with(&registry, &req, &mut |_| {}).unwrap();
    let m = &r.missions[0];
    let expected = Vec3::new(50.0, 240.0, 0.0).distance(Vec3::new(650.0, 260.0, 0.0)) / 2.0;
    assert!((m.goal_distance_m.unwrap() - expected).abs() < 1e-9, "{:?}", m.goal_distance_m);
    assert_eq!(r.status, Status::Timeout, "{}", r.reason);
    assert!(!m.feasible);
    assert!(r.reason.contains("short of the goal"), "{}", r.reason);
}

/// Graph planners report the checks they made and the size of the graph (OMPL's "valid
/// motions" and graph states), optimizers the motions their evaluations judged.
#[test]
fn searches_report_their_checks_and_graph_sizes() {
    let s = one_disc();
    let a = plan(&s, "astar");
    assert!(
        a.motion_checks >= a.expansions && a.expansions > 0,
        "{} checks, {} expansions",
        a.motion_checks,
        a.expansions
    );
    assert!(
        a.graph_nodes > 0 && a.state_checks >= a.graph_nodes,
        "{} nodes of {} cells",
        a.graph_nodes,
        a.state_checks
    );
    let v = plan(&s, "visibility");
    assert!(v.graph_nodes >= 2 && v.graph_edges >= 1, "{} nodes, {} edges", v.graph_nodes, v.graph_edges);
    let p = s
        .plan(&PlanRequest { planner: Some("pso".into()), iterations: Some(3), ..PlanRequest::default() }, &mut |_| {})
        .unwrap();
    assert_eq!(p.motion_checks, p.evaluations * (s.encoding.waypoints as u64 + 1));
}
