//! `prm-star`: PRM* (Karaman & Frazzoli 2011, Alg. 4 with the radius of their Thm. 34) on the
//! scenario's cost model at the vehicle's clock.
//!
//! * **Roadmap**: start and goal are its first two vertices, the warm start's waypoints the
//!   next; each sample valid whatever the time ([`crate::validity::Validator::fixed_state`])
//!   joins it, connected to every vertex within r = gamma_PRM* (log n / n)^(1/d)
//!   ([`super::rewire_radius`]; at most `max_radius` when set) by a valid edge that keeps the pitch limit. In a world that
//!   does not change in time an edge is priced once, by `motion_cost`; in one that does, edges
//!   are checked against what does not move (seabed, fixed obstacles, the current at the
//!   departure time) and priced when the search reaches them, leaving at the vehicle's arrival
//!   time there, moving obstacles included.
//! * **Query**: A* from `tidepath-search` (the heuristic: the cost model's lower bound on the
//!   straight distance left). It keeps one label per vertex, and a move is taken only when the
//!   turn at its vertex, from the label's own parent, keeps `max_turn`: so paths keep the
//!   vehicle's limits, and a route that needs a worse approach to a vertex is missed.
//! * **History**: the query runs `queries` times while the roadmap grows (evenly spaced over the
//!   sample limit, once start and goal are connected) and once at the end; the best cost found
//!   so far is recorded after every sample.
//! * **No route**: the path to the vertex of the start's component nearest the goal (the
//!   evaluation reports the distance left; status never `feasible`).
//!
//! Budgets: samples (counted), wall time, target cost and the stop flag, polled before every
//! sample; the query polls them every 16 expansions. The roadmap stops growing at
//! [`super::MAX_ROADMAP_VERTICES`] (memory), and the run then ends as `completed`.

use super::neighbours::Neighbours;
use super::{
    plan_missions, rewire_radius, Budget, Edges, Kinematics, MissionRun, SampleSpace, Variant, DEFAULT_SAMPLES,
    MAX_ROADMAP_VERTICES,
};
use crate::geom::Vec3;
use crate::optim::Progress;
use crate::params::{Bound, Checked, Range};
use crate::planner::{Planner, PlannerOutput, Problem, RunOptions, SearchGraph};
use crate::rng::Rng;
use crate::termination::{StopReason, Termination};
use crate::validity::Validator;
use crate::world::World;
use tidepath_search::{best_first, Expand, Expanded, Frontier, SearchArena, SearchStatus};

crate::params! {
    /// PRM*'s parameters.
    pub struct PrmStarParams {
        /// Samples when the run sets no sample limit (`--samples` or `[planner] samples` win).
        samples: usize = DEFAULT_SAMPLES, Range::integer(1, 1_000_000_000), "tidepath";
        /// Factor on the least connection constant gamma of the theorem (above 1 keeps its
        /// guarantee).
        rewire_factor: f64 = 1.1, Range::closed(0.1, 10.0), "OMPL (rewire_factor)";
        /// Largest connection radius (m); absent: none (lfhh2019 caps it at 15).
        max_radius: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e8) }, "Karaman & Frazzoli 2011; lfhh2019 (r_PRM)";
        /// Start-goal queries while the roadmap grows, for the convergence history (one more
        /// runs at the end).
        queries: usize = 10, Range::integer(0, 10_000), "tidepath";
    }
}

pub struct PrmStar {
    params: PrmStarParams,
}

impl PrmStar {
    pub fn new(params: Checked<PrmStarParams>) -> Self {
        Self { params: params.into_inner() }
    }
}

const START: u32 = 0;
const GOAL: u32 = 1;

/// The roadmap: vertices, and per vertex its edges with their cost (NaN: priced when
/// searched), and a union-find over what the edges connect.
#[derive(Default)]
struct Roadmap {
    pos: Vec<Vec3>,
    adj: Vec<Vec<(u32, f64)>>,
    edges: u64,
    root: Vec<u32>,
}

impl Roadmap {
    fn add(&mut self, p: Vec3) -> u32 {
        let id = self.pos.len() as u32;
        self.pos.push(p);
        self.adj.push(Vec::new());
        self.root.push(id);
        id
    }

    fn find(&mut self, mut v: u32) -> u32 {
        while self.root[v as usize] != v {
            let up = self.root[self.root[v as usize] as usize];
            self.root[v as usize] = up;
            v = up;
        }
        v
    }

    fn connect(&mut self, a: u32, b: u32, cost: f64) {
        self.adj[a as usize].push((b, cost));
        self.adj[b as usize].push((a, cost));
        self.edges += 1;
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.root[ra.max(rb) as usize] = ra.min(rb);
        }
    }

    fn graph_edges(&self) -> Vec<[u32; 2]> {
        let mut out = Vec::with_capacity(self.edges as usize);
        for (a, list) in self.adj.iter().enumerate() {
            out.extend(list.iter().filter(|(b, _)| *b as usize > a).map(|&(b, _)| [a as u32, b]));
        }
        out
    }
}

/// The A* query's expansion: moves along roadmap edges that keep the turn limit, priced from
/// the roadmap or, in a world that changes in time, at the arrival time of the label.
struct Query<'r, 'e, 'a> {
    map: &'r Roadmap,
    edges: &'e mut Edges<'a>,
    kinematics: Kinematics,
    /// Arrival time of each vertex's label.
    time: Vec<f64>,
}

impl Expand for Query<'_, '_, '_> {
    fn expand<H: FnMut(usize) -> f64>(&mut self, u: Expanded, frontier: &mut Frontier<'_, H>) {
        let at = self.map.pos[u.node];
        let from = u.parent.map(|p| self.map.pos[p]);
        let t = self.time[u.node];
        for &(v, c) in &self.map.adj[u.node] {
            let v = v as usize;
            if frontier.is_closed(v) || !self.kinematics.joint_ok(from, at, self.map.pos[v]) {
                continue;
            }
            let (c, arrival) = if c.is_nan() {
                match self.edges.price(at, self.map.pos[v], t) {
                    Some(x) => x,
                    None => continue,
                }
            } else {
                // A world that does not change in time: no price depends on the arrival time.
                (c, t)
            };
            if frontier.offer(v, u.g + c, u.node) {
                self.time[v] = arrival;
            }
        }
    }
}

impl Planner for PrmStar {
    fn id(&self) -> &'static str {
        "prm-star"
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        termination: &Termination,
        rng: &mut Rng,
        options: RunOptions<'_>,
        _observer: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput {
        // What does not move, for checking roadmap edges before their time is known.
        let fixed: Option<World> = (!super::time_invariant(problem.world)).then(|| {
            let mut w = problem.world.clone();
            w.obstacles.retain(|o| o.is_fixed());
            w
        });
        let default = self.params.samples as u64;
        plan_missions(problem, termination, default, |i, share, samples, earlier, out| {
            let init = options.init.and_then(|p| p.get(i)).map(Vec::as_slice);
            let (path, best, stopped) =
                self.build(problem, i, fixed.as_ref(), share, samples, init, rng, out, earlier, options.record_graph);
            let hint = (!best.is_finite()).then(|| {
                format!(
                    "the roadmap did not connect start and goal within {} samples; the path leads to its vertex nearest the goal that the start reaches",
                    out.stats.samples
                )
            });
            MissionRun { path, best, stopped, hint }
        })
    }
}

impl PrmStar {
    /// Builds mission `i`'s roadmap and answers its query: the path, its additive cost
    /// (+inf without one) and why the sampling stopped.
    #[allow(clippy::too_many_arguments)]
    fn build(
        &self,
        problem: &Problem<'_>,
        i: usize,
        fixed: Option<&World>,
        termination: &Termination,
        samples: u64,
        init: Option<&[Vec3]>,
        rng: &mut Rng,
        out: &mut PlannerOutput,
        earlier: f64,
        record_graph: bool,
    ) -> (Vec<Vec3>, f64, Option<StopReason>) {
        let m = &problem.missions[i];
        let space = SampleSpace::of(problem, i);
        let interrupted = || termination.interrupted().is_some();
        // PRM* cuts no edges: the resolution is unused.
        let Some(mut edges) = Edges::new(problem, i, 1.0, &interrupted) else {
            return (vec![m.start], f64::INFINITY, termination.interrupted().or(Some(StopReason::WallTime)));
        };
        let fixed_validator = fixed.map(|w| Validator::new(w, &m.vehicle, problem.settings));
        let validator = fixed_validator.as_ref().unwrap_or(&edges.model.validator).clone();
        let mut map = Roadmap::default();
        let mut index = Neighbours::new(space.is_flat());
        for p in [m.start, m.goal].into_iter().chain(init.unwrap_or_default().iter().copied()) {
            let v = map.add(p);
            index.insert(p, v);
        }
        let mut near = Vec::new();
        // Connects vertex v to the vertices within the current radius.
        let link = |map: &mut Roadmap, index: &Neighbours, v: u32, edges: &mut Edges<'_>, near: &mut Vec<u32>| {
            let p = map.pos[v as usize];
            let r = rewire_radius(Variant::Prm, &space, space.measure(), map.pos.len(), self.params.rewire_factor)
                .min(self.params.max_radius.unwrap_or(f64::INFINITY));
            index.within(p, r, near);
            for &q in near.iter() {
                let a = map.pos[q as usize];
                if q == v || !edges.kinematics.edge_ok(a, p) {
                    continue;
                }
                if edges.time_varying {
                    edges.motion_checks += 1;
                    if validator.motion(a, p, m.departure_time).valid() {
                        map.connect(q, v, f64::NAN);
                    }
                } else if let Some((c, _)) = edges.price(a, p, m.departure_time) {
                    map.connect(q, v, c);
                }
            }
        };
        for v in 1..map.pos.len() as u32 {
            link(&mut map, &index, v, &mut edges, &mut near);
        }
        let queries = self.params.queries as u64;
        let every = if queries == 0 { u64::MAX } else { (samples / (queries + 1)).max(1) };
        let mut arena = SearchArena::new();
        let mut best: (f64, Vec<Vec3>) = (f64::INFINITY, Vec::new());
        let mut budget = Budget { termination, max_samples: samples, samples: 0 };
        let stopped = loop {
            if budget.samples > 0 {
                out.stats.history.push(earlier + best.0);
            }
            if let Some(r) = budget.stop(earlier + best.0) {
                break Some(r);
            }
            if map.pos.len() >= MAX_ROADMAP_VERTICES {
                break Some(StopReason::Completed);
            }
            budget.samples += 1;
            out.stats.samples += 1;
            let x = space.sample(rng);
            out.stats.state_checks += 1;
            if validator.fixed_state(x).is_ok() {
                let v = map.add(x);
                index.insert(x, v);
                link(&mut map, &index, v, &mut edges, &mut near);
            }
            if budget.samples % every == 0 && map.find(START) == map.find(GOAL) {
                if let Some(found) = query(&map, &mut edges, &mut arena, GOAL, m.departure_time, termination, out) {
                    if found.0 < best.0 {
                        best = found;
                    }
                }
            }
        };
        if map.find(START) == map.find(GOAL) {
            if let Some(found) = query(&map, &mut edges, &mut arena, GOAL, m.departure_time, termination, out) {
                if found.0 < best.0 {
                    best = found;
                }
            }
            if let Some(h) = out.stats.history.last_mut() {
                *h = earlier + best.0;
            }
        }
        if best.1.is_empty() {
            // The vertex of the start's component nearest the goal.
            let root = map.find(START);
            let component: Vec<u32> = (0..map.pos.len() as u32).filter(|&v| map.find(v) == root).collect();
            let target = component
                .into_iter()
                .min_by(|&a, &b| {
                    map.pos[a as usize]
                        .distance(m.goal)
                        .total_cmp(&map.pos[b as usize].distance(m.goal))
                        .then(a.cmp(&b))
                })
                .unwrap_or(START);
            best.1 = query(&map, &mut edges, &mut arena, target, m.departure_time, termination, out)
                .map_or_else(|| vec![m.start], |f| f.1);
        }
        out.stats.motion_checks += edges.motion_checks;
        out.stats.graph_nodes += map.pos.len() as u64;
        out.stats.graph_edges += map.edges;
        if record_graph {
            out.graphs.push(SearchGraph {
                mission: i,
                kind: "roadmap",
                edges: map.graph_edges(),
                vertices: map.pos.clone(),
                start: Some(START),
                goal: Some(GOAL),
            });
        }
        (best.1, best.0, stopped)
    }
}

/// A* from the start to `target` on the roadmap: the cost and the path, or `None` when the
/// search found none (or was stopped).
#[allow(clippy::too_many_arguments)]
fn query(
    map: &Roadmap,
    edges: &mut Edges<'_>,
    arena: &mut SearchArena,
    target: u32,
    departure: f64,
    termination: &Termination,
    out: &mut PlannerOutput,
) -> Option<(f64, Vec<Vec3>)> {
    let goal = map.pos[target as usize];
    let kinematics = edges.kinematics;
    let mut time = vec![f64::NAN; map.pos.len()];
    time[START as usize] = departure;
    let bounds: Vec<f64> = map.pos.iter().map(|p| edges.lower_bound(p.distance(goal))).collect();
    let mut q = Query { map, edges, kinematics, time };
    let limits = termination.search_limits(None);
    let o = best_first(arena, map.pos.len(), START as usize, |u| u == target as usize, |u| bounds[u], &mut q, &limits)
        .ok()?;
    out.stats.expansions += o.expansions;
    (o.status == SearchStatus::Found).then(|| (o.cost, o.path.iter().map(|&v| map.pos[v]).collect()))
}
