//! Search graphs (`plan --graph`): a planner that builds one gives it back only when asked,
//! one per planned mission, named after its mission in the whole problem and in degrees too in
//! a geographic scenario; asking one that builds none is refused before planning, naming
//! `--graph` and the planners that do. A toy graph planner, registered the way a new planner
//! is, pins the plumbing; every built-in planner that says it draws its graph is held to the
//! same promises.

use tidepath::geom::Vec3;
use tidepath::optim::Progress;
use tidepath::planner::{
    self, BuildPlanner, Capabilities, Dimensions, Fleets, Planner, PlannerOutput, PlannerSettings, Problem, RunOptions,
    SearchGraph, SearchStats,
};
use tidepath::registry::{Entry, Registry};
use tidepath::rng::Rng;
use tidepath::termination::{StopReason, Termination};
use tidepath_io::graph_file;
use tidepath_io::scenario::{PlanRequest, Scenario};

/// A "roadmap" of three vertices per mission: start, the midpoint a little aside, goal.
struct Fan;

impl Planner for Fan {
    fn id(&self) -> &'static str {
        "fan"
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        _: &Termination,
        _: &mut Rng,
        options: RunOptions<'_>,
        _: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput {
        let mut out = PlannerOutput {
            stats: SearchStats { stop_reason: StopReason::Completed, ..SearchStats::default() },
            ..PlannerOutput::default()
        };
        for (k, m) in problem.missions.iter().enumerate() {
            let mid = (m.start + m.goal) * 0.5 + Vec3::new(0.0, 30.0, 0.0);
            out.paths.push(vec![m.start, m.goal]);
            if options.record_graph {
                out.graphs.push(SearchGraph {
                    mission: k,
                    kind: "roadmap",
                    vertices: vec![m.start, mid, m.goal],
                    edges: vec![[0, 1], [1, 2], [0, 2]],
                    start: Some(0),
                    goal: Some(2),
                });
            }
        }
        out
    }
}

fn planners() -> Registry<BuildPlanner> {
    let caps = Capabilities {
        dimensions: Dimensions::Both,
        fleets: Fleets::OneAfterAnother,
        warm_start: false,
        counts: &[],
        optimal: None,
        randomised: false,
        graph: true,
    };
    planner::registry().with(Entry {
        id: "fan",
        description: "start, a point aside and the goal, all joined",
        citation: "test",
        params: &[],
        build: BuildPlanner::direct(caps, |_: &PlannerSettings| Ok(Box::new(Fan))),
    })
}

/// Two missions; the first starts inside the disc, so the planner sees only the second.
fn pair(geographic: bool) -> Scenario {
    let text = if geographic {
        "name = \"geo-pair\"\n[world]\ndimensions = 2\nframe = \"geographic\"\n\
        bounds = { min = [-124.0, 48.0, 0.0], max = [-123.9, 48.05, 0.0] }\n\
        [[world.obstacles]]\nkind = \"cylinder\"\ncenter = [-123.99, 48.04]\nradius = 300.0\n\
        [vehicle]\nspeed = 2.0\nsafety_distance = 5.0\nmax_turn_deg = 180.0\n\
        [[missions]]\nname = \"alpha\"\nstart = [-123.99, 48.04, 0.0]\ngoal = [-123.91, 48.04, 0.0]\n\
        [[missions]]\nname = \"bravo <2>\"\nstart = [-123.99, 48.01, 0.0]\ngoal = [-123.91, 48.01, 0.0]\n"
    } else {
        "name = \"pair\"\n[world]\ndimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [1000.0, 1000.0, 0.0] }\n\
        [[world.obstacles]]\nkind = \"cylinder\"\ncenter = [100.0, 800.0]\nradius = 50.0\n\
        [vehicle]\nspeed = 2.0\nsafety_distance = 5.0\nmax_turn_deg = 180.0\n\
        [[missions]]\nname = \"alpha\"\nstart = [100.0, 800.0, 0.0]\ngoal = [900.0, 800.0, 0.0]\n\
        [[missions]]\nname = \"bravo <2>\"\nstart = [100.0, 100.0, 0.0]\ngoal = [900.0, 100.0, 0.0]\n"
    };
    Scenario::from_toml(text, "pair.toml").unwrap()
}

fn request(id: &str, record_graph: bool) -> PlanRequest {
    PlanRequest { planner: Some(id.into()), record_graph, time_limit_s: Some(10.0), ..PlanRequest::default() }
}

#[test]
fn a_graph_is_kept_only_when_asked_and_named_after_its_mission() {
    let s = pair(false);
    let r = s.plan_with(&planners(), &request("fan", false), &mut |_| {}).unwrap();
    assert!(r.graphs.is_empty());
    let r = s.plan_with(&planners(), &request("fan", true), &mut |_| {}).unwrap();
    assert_eq!(r.graphs.len(), 1, "only the planned mission has a graph");
    let g = &r.graphs[0];
    assert_eq!((g.mission.as_str(), g.kind.as_str()), ("bravo <2>", "roadmap"));
    assert_eq!(g.vertices[0], [100.0, 100.0, 0.0]);
    assert_eq!((g.start, g.goal, g.lonlat.as_ref()), (Some(0), Some(2), None));
    // Both files carry it and read back; the plan file does not.
    assert_eq!(graph_file::read_json(&graph_file::json(&r), "g.json").unwrap(), r.graphs);
    assert_eq!(graph_file::read_graphml(&graph_file::graphml(&r).unwrap(), "g.graphml").unwrap(), r.graphs);
    assert!(!r.to_json().contains("vertices"));
}

#[test]
fn a_geographic_graph_comes_in_degrees_too() {
    let s = pair(true);
    let r = s.plan_with(&planners(), &request("fan", true), &mut |_| {}).unwrap();
    let g = &r.graphs[0];
    let ll = g.lonlat.as_ref().expect("degrees in a geographic scenario");
    assert_eq!(ll.len(), g.vertices.len());
    assert!((ll[0][0] + 123.99).abs() < 1e-6 && (ll[0][1] - 48.01).abs() < 1e-6, "{:?}", ll[0]);
    assert!((ll[2][0] + 123.91).abs() < 1e-6 && (ll[2][1] - 48.01).abs() < 1e-6, "{:?}", ll[2]);
    let xml = graph_file::graphml(&r).unwrap();
    assert!(xml.contains("<data key=\"lon\">-123.99</data>"), "{xml}");
    assert_eq!(graph_file::read_graphml(&xml, "g").unwrap(), r.graphs);
    assert_eq!(graph_file::read_json(&graph_file::json(&r), "g").unwrap(), r.graphs);
}

#[test]
fn a_planner_without_a_graph_is_refused_before_planning() {
    let s = pair(false);
    let e = s.check_request_with(&planners(), &request("astar", true)).unwrap_err().to_string();
    assert!(e.starts_with("--graph: astar builds no search graph; planners that do: "), "{e}");
    assert!(e.ends_with("fan"), "{e}");
    let builders: Vec<&str> = planners().entries().iter().filter(|e| e.build.caps.graph).map(|e| e.id).collect();
    assert!(builders.iter().all(|id| e.contains(id)), "{e}");
    assert!(s.plan_with(&planners(), &request("astar", true), &mut |_| {}).is_err());
    s.check_request_with(&planners(), &request("astar", false)).unwrap();
}

/// Every built-in planner that says it draws its graph gives one per planned mission when
/// asked (indices inside its vertices, the start where the mission starts, a tree's edges
/// from parent to child), and none when not.
#[test]
fn every_planner_that_draws_its_graph_gives_one() {
    let s = pair(false);
    for entry in planner::PLANNERS.iter().filter(|e| e.build.caps.graph) {
        let id = entry.id;
        let mut req = request(id, true);
        req.samples = Some(300);
        let r = s.plan(&req, &mut |_| {}).unwrap();
        assert_eq!(r.graphs.len(), 1, "{id}");
        let g = &r.graphs[0];
        assert_eq!(g.mission, "bravo <2>", "{id}");
        assert!(matches!(g.kind.as_str(), "tree" | "roadmap"), "{id}: {}", g.kind);
        assert!(g.vertices.len() >= 2 && !g.edges.is_empty(), "{id}: {} vertices", g.vertices.len());
        let n = g.vertices.len() as u32;
        assert!(g.edges.iter().all(|e| e[0] < n && e[1] < n), "{id}: an edge past the vertices");
        let start = g.start.expect("the start is a vertex") as usize;
        assert_eq!(g.vertices[start], [100.0, 100.0, 0.0], "{id}");
        if g.kind == "tree" {
            // One parent per vertex but the root.
            let mut parents = vec![0u32; g.vertices.len()];
            for e in &g.edges {
                parents[e[1] as usize] += 1;
            }
            assert!(parents.iter().all(|&p| p <= 1) && parents[start] == 0, "{id}: not a tree from the start");
        }
        req.record_graph = false;
        assert!(s.plan(&req, &mut |_| {}).unwrap().graphs.is_empty(), "{id}");
    }
}
