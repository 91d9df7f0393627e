//! The sampling planners' acceptance: near the exact reference on `headland`, every feasible
//! plan in a 3-D world of moving spheres and a time-varying jet clear by the independent
//! re-checker, and the distance left reported when the budget is too small.

use crate::common;
// The search graphs they give back (its own file; one test binary builds faster than two).
#[path = "sampling/graphs.rs"]
mod graphs;

use tidepath::planner::Status;
use tidepath_io::scenario::{PlanRequest, Scenario};

fn plan(s: &Scenario, planner: &str, samples: Option<u64>, seed: u64) -> tidepath_io::PlanReport {
    let req = PlanRequest { planner: Some(planner.into()), samples, seed, ..PlanRequest::default() };
    s.plan(&req, &mut |_| {}).unwrap()
}

#[test]
fn rrt_star_on_headland_is_within_five_percent_of_visibility() {
    let s = tidepath_io::scenario::load("headland").unwrap();
    let exact = plan(&s, "visibility", None, 1);
    assert!(exact.status.is_success(), "{}", exact.reason);
    let r = plan(&s, "rrt-star", Some(20_000), 1);
    assert_eq!(r.status, Status::Feasible, "{}", r.reason);
    assert_eq!(r.samples, 20_000);
    let gap = (r.cost.unwrap() - exact.cost.unwrap()) / exact.cost.unwrap();
    assert!((0.0..0.05).contains(&gap), "gap {gap}");
    common::recheck_plan(&s, &r).unwrap();
}

/// Moving spheres crossing the track and a meandering jet that changes in time: every plan
/// the evaluation calls feasible is clear at the vehicle's own clock by the dense re-checker.
#[test]
fn every_feasible_sampling_plan_in_a_moving_jet_world_passes_the_recheck() {
    use rayon::prelude::*;
    let s = Scenario::from_toml(include_str!("data/moving_jet.toml"), "moving_jet.toml").unwrap();
    let runs: Vec<(&str, u64)> = ["rrt-star", "informed-rrt-star", "prm-star"]
        .iter()
        .flat_map(|&p| (0..if p == "rrt-star" { 12 } else { 3 }).map(move |seed| (p, seed)))
        .collect();
    let feasible: Vec<(&str, usize)> = runs
        .par_iter()
        .map(|&(p, seed)| {
            let r = plan(&s, p, Some(600 + 200 * seed), seed);
            if !r.status.is_success() {
                return (p, 0);
            }
            let samples = common::recheck_plan(&s, &r).unwrap_or_else(|e| panic!("{p} seed {seed}: {e}"));
            assert!(samples > 100, "{p} seed {seed}: {samples} samples");
            (p, 1)
        })
        .collect();
    let rrt: usize = feasible.iter().filter(|(p, _)| *p == "rrt-star").map(|x| x.1).sum();
    assert!(rrt >= 8, "only {rrt} of 12 rrt-star plans feasible");
}

/// A sample limit too small to reach the goal: the path stops short, the plan says how far,
/// and the status is `infeasible`; a wall-time stop is `timeout`. Never `feasible`.
#[test]
fn too_small_a_budget_reports_the_distance_left() {
    let s = tidepath_io::scenario::load("headland").unwrap();
    for p in ["rrt-star", "informed-rrt-star"] {
        let r = plan(&s, p, Some(30), 2);
        assert_eq!(r.status, Status::Infeasible, "{p}: {}", r.reason);
        let m = &r.missions[0];
        let left = m.goal_distance_m.unwrap_or_else(|| panic!("{p}: no distance left: {}", r.reason));
        assert!(left > 100.0, "{p}: {left}");
        assert!(r.reason.contains("short of the goal") && r.reason.contains("within 30 samples"), "{}", r.reason);
    }
    let req = PlanRequest {
        planner: Some("rrt-star".into()),
        samples: Some(1_000_000_000),
        time_limit_s: Some(0.05),
        ..PlanRequest::default()
    };
    // Too little time for a route round the headland: timeout, or feasible only when found.
    let r = s.plan(&req, &mut |_| {}).unwrap();
    assert!(matches!(r.status, Status::Timeout | Status::Feasible), "{}: {}", r.status, r.reason);
    let req = PlanRequest { time_limit_s: Some(1e-4), ..req };
    let r = s.plan(&req, &mut |_| {}).unwrap();
    assert_eq!(r.status, Status::Timeout, "{}", r.reason);
}

/// The search graph, when asked for: a tree of every vertex (edges parent to child) from the
/// start to the goal, and a roadmap holding start and goal.
#[test]
fn the_search_graph_is_kept_when_asked_for() {
    let s = tidepath_io::scenario::load("headland").unwrap();
    for (p, kind) in [("rrt-star", "tree"), ("prm-star", "roadmap")] {
        let req =
            PlanRequest { planner: Some(p.into()), samples: Some(3000), record_graph: true, ..PlanRequest::default() };
        let mut planner = tidepath::planner::registry().build(p, None, None, &s.encoding).unwrap();
        let cost = s.cost_model().unwrap();
        let problem = s.problem(cost.as_ref());
        let (t, _) = s.termination(&req).unwrap();
        let mut rng = tidepath::rng::run_rng(1, 0);
        let options = tidepath::planner::SolveOptions {
            run: tidepath::planner::RunOptions { record_graph: true, ..Default::default() },
            ..Default::default()
        };
        let plan = tidepath::planner::solve(planner.as_mut(), &problem, &t, &mut rng, options, &mut |_| {}).unwrap();
        assert_eq!(plan.graphs.len(), 1, "{p}");
        let g = &plan.graphs[0];
        assert_eq!((g.kind, g.mission, g.start), (kind, 0, Some(0)), "{p}");
        assert_eq!(g.vertices[0], s.missions[0].start);
        assert_eq!(g.vertices[g.goal.unwrap() as usize], s.missions[0].goal);
        assert_eq!(g.vertices.len() as u64, plan.stats.graph_nodes, "{p}");
        assert_eq!(g.edges.len() as u64, plan.stats.graph_edges, "{p}");
        assert!(g.edges.iter().all(|e| (e[0] as usize) < g.vertices.len() && (e[1] as usize) < g.vertices.len()));
        if kind == "tree" {
            // Every vertex but the start has exactly one parent.
            let mut parents = vec![0; g.vertices.len()];
            for e in &g.edges {
                parents[e[1] as usize] += 1;
            }
            assert!(parents[0] == 0 && parents[1..].iter().all(|&n| n == 1));
        }
        // Without the request, no graph is kept.
        let plain = s.plan(&PlanRequest { record_graph: false, ..req }, &mut |_| {}).unwrap();
        assert!(plain.status.is_success(), "{}", plain.reason);
    }
}
