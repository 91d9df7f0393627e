//! `rrt-star` and `informed-rrt-star`: RRT* (Karaman & Frazzoli 2011, Alg. 6) and Informed
//! RRT* (Gammell, Srinivasa & Barfoot 2014, Alg. 2) on the scenario's cost model at the
//! vehicle's clock.
//!
//! Each sample (one iteration):
//! 1. x_rand: the goal with probability `goal_bias`, else a uniform sample of the space
//!    ([`super::SampleSpace`]); for Informed RRT*, once a path exists and the cost is a
//!    multiple of length, a uniform sample of the informed set ([`super::informed`]).
//! 2. x_nearest, the tree's nearest vertex; x_new = Steer(x_nearest, x_rand): at most `range`
//!    metres towards x_rand (the eta of the paper). A blocked edge is cut at its last valid
//!    point ([`super::Edges::extend`]).
//! 3. Near vertices within r = min(gamma_RRT* (log n / n)^(1/d), range) (their eq. for
//!    gamma_RRT*, [`super::rewire_radius`]); x_new's parent is the one giving the least cost
//!    to come, trying candidates in order of a lower bound on it and stopping once the bound
//!    cannot win (OMPL's sorted near list).
//! 4. Rewire: each near vertex that x_new reaches more cheaply gets x_new as its parent; in a
//!    world that changes in time its subtree is re-timed and re-checked first
//!    ([`super::tree::Tree::reparent`]).
//!
//! Costs: an edge a -> b is priced by `motion_cost` leaving at a's arrival time, so a path's
//! tree cost is the sum the evaluation makes of the additive terms (length, time). The turn
//! and pitch limits hold at every joint ([`super::Kinematics`]). The goal is a vertex of the
//! tree once a sample reaches it exactly (goal bias draws it); the best cost after each sample
//! is the search history.
//!
//! Termination: polled before every sample (samples, wall time, target cost, stop flag) and in
//! every subtree walk. Without a path to the goal, the path to the vertex nearest the goal is
//! returned (the evaluation reports the distance left; status never `feasible`).
//!
//! Warm start (`--init`): the initial path's waypoints join the tree as a chain from the
//! start, each edge checked and priced as any other (cut at its first invalid point).
//!
//! Not done: pruning of vertices outside the informed set (Gammell et al.'s Alg. 2, line 16);
//! it saves memory and time, not samples, and the tree here stays small enough.

use rand::Rng as _;

use super::informed::Informed;
use super::neighbours::Neighbours;
use super::tree::{Tree, ROOT};
use super::{
    plan_missions, resolution_or, rewire_radius, Budget, Edges, MissionRun, SampleSpace, Variant, DEFAULT_SAMPLES,
    MAX_TREE_VERTICES,
};
use crate::geom::Vec3;
use crate::optim::Progress;
use crate::params::{Bound, Checked, Range};
use crate::planner::{Planner, PlannerOutput, Problem, RunOptions, SearchGraph};
use crate::rng::Rng;
use crate::termination::{StopReason, Termination};

/// Samples closer than this (m) to their nearest vertex add nothing.
const MIN_STEP: f64 = 1e-6;

/// Default steering range as a fraction of the sampled space's diagonal (OMPL's RRT* uses a
/// fifth of the space's maximum extent).
pub const RANGE_OF_DIAGONAL: f64 = 0.2;

crate::params! {
    /// RRT*'s and Informed RRT*'s parameters.
    pub struct RrtStarParams {
        /// Samples when the run sets no sample limit (`--samples` or `[planner] samples` win).
        samples: usize = DEFAULT_SAMPLES, Range::integer(1, 1_000_000_000), "tidepath";
        /// Longest edge (m), the eta of Karaman & Frazzoli; absent: a fifth of the diagonal of
        /// the sampled space (OMPL's default).
        range: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e8) }, "Karaman & Frazzoli 2011; OMPL";
        /// Probability of sampling the goal.
        goal_bias: f64 = 0.05, Range::closed(0.0, 1.0), "OMPL RRTstar";
        /// Factor on the least rewiring constant gamma of the theorems (above 1 keeps their
        /// guarantee).
        rewire_factor: f64 = 1.1, Range::closed(0.1, 10.0), "OMPL RRTstar (rewire_factor)";
        /// Metres to which a blocked edge is cut at its last valid point; absent: a hundredth
        /// of `range`.
        resolution: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e7) }, "tidepath";
    }
}

/// The planner; `informed` selects Informed RRT*.
pub struct RrtStar {
    params: RrtStarParams,
    informed: bool,
}

impl RrtStar {
    pub fn new(params: Checked<RrtStarParams>, informed: bool) -> Self {
        Self { params: params.into_inner(), informed }
    }
}

/// What one mission's growth found.
struct Grown {
    path: Vec<Vec3>,
    reached: bool,
    best: f64,
    stopped: Option<StopReason>,
    /// Informed sampling was asked for but the cost is not a multiple of length.
    uninformed: bool,
    /// The tree reached [`MAX_TREE_VERTICES`].
    full: bool,
}

impl Planner for RrtStar {
    fn id(&self) -> &'static str {
        if self.informed {
            "informed-rrt-star"
        } else {
            "rrt-star"
        }
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        termination: &Termination,
        rng: &mut Rng,
        options: RunOptions<'_>,
        _observer: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput {
        let default = self.params.samples as u64;
        plan_missions(problem, termination, default, |i, share, samples, earlier, out| {
            let init = options.init.and_then(|p| p.get(i)).map(Vec::as_slice);
            let grown = self.grow(problem, i, share, samples, init, rng, out, earlier, options.record_graph);
            let hint = if !grown.reached {
                let why = match grown.stopped {
                    _ if grown.full => format!("before its cap of {MAX_TREE_VERTICES} vertices (memory)"),
                    Some(StopReason::MaxSamples) | None => format!("within {} samples", out.stats.samples),
                    Some(_) => "before the run stopped".into(),
                };
                Some(format!("the tree did not reach the goal {why}; the path leads to its vertex nearest the goal"))
            } else if grown.uninformed {
                Some(
                    "informed sampling needs a cost proportional to length (still water); it sampled the whole space"
                        .into(),
                )
            } else {
                None
            };
            MissionRun { path: grown.path, best: grown.best, stopped: grown.stopped, hint }
        })
    }
}

impl RrtStar {
    /// Grows one tree for mission `i` within `samples` and `termination`; appends the best
    /// cost after each sample (plus `earlier`, the earlier missions' total) to the history.
    #[allow(clippy::too_many_arguments)]
    fn grow(
        &self,
        problem: &Problem<'_>,
        i: usize,
        termination: &Termination,
        samples: u64,
        init: Option<&[Vec3]>,
        rng: &mut Rng,
        out: &mut PlannerOutput,
        earlier: f64,
        record_graph: bool,
    ) -> Grown {
        let m = &problem.missions[i];
        let space = SampleSpace::of(problem, i);
        let range = self.params.range.unwrap_or(RANGE_OF_DIAGONAL * space.diagonal());
        let resolution = resolution_or(self.params.resolution, range);
        let interrupted = || termination.interrupted().is_some();
        let Some(mut edges) = Edges::new(problem, i, resolution, &interrupted) else {
            let stopped = termination.interrupted().or(Some(StopReason::WallTime));
            return Grown {
                path: vec![m.start],
                reached: false,
                best: f64::INFINITY,
                stopped,
                uninformed: false,
                full: false,
            };
        };
        let per_metre = problem.cost.cost_per_metre(&edges.model);
        let uninformed = self.informed && per_metre.is_none();
        let mut tree = Tree::new(m.start, m.departure_time);
        let mut index = Neighbours::new(space.is_flat());
        index.insert(m.start, ROOT);
        let mut goal: Option<u32> = None;
        let is_goal = |p: Vec3| p.distance(m.goal) <= 1e-9 * (1.0 + m.goal.length());
        // The warm start: a chain from the start along the initial path.
        if let Some(path) = init {
            let mut at = ROOT;
            for &w in path.iter().skip(1) {
                let from = tree.pos[at as usize];
                if from.distance(w) < MIN_STEP || !edges.kinematics.joint_ok(tree.from(at), from, w) {
                    break;
                }
                let Some((p, c, t)) = edges.extend(from, w, tree.time[at as usize]) else { break };
                let v = tree.add(p, at, tree.cost[at as usize] + c, t);
                index.insert(p, v);
                at = v;
                if is_goal(p) {
                    goal = Some(v);
                    break;
                }
                if p != w {
                    break;
                }
            }
        }
        let mut budget = Budget { termination, max_samples: samples, samples: 0 };
        let mut full = false;
        // The measure the samples spread over: the space's, then the informed set's.
        let mut measure = space.measure();
        let mut near = Vec::new();
        let mut order: Vec<(f64, u32)> = Vec::new();
        let best = |tree: &Tree, goal: Option<u32>| goal.map_or(f64::INFINITY, |g| tree.cost[g as usize]);
        let stopped = loop {
            // The history holds the best cost after each sample: the previous one's, here.
            if budget.samples > 0 {
                out.stats.history.push(earlier + best(&tree, goal));
            }
            if let Some(r) = budget.stop(earlier + best(&tree, goal)) {
                break Some(r);
            }
            if tree.len() >= MAX_TREE_VERTICES {
                full = true;
                break Some(StopReason::Completed);
            }
            budget.samples += 1;
            out.stats.samples += 1;
            // 1. Sample.
            let x_rand = if rng.random::<f64>() < self.params.goal_bias {
                m.goal
            } else {
                match (self.informed, goal, per_metre) {
                    (true, Some(g), Some(k)) if k > 0.0 => {
                        match Informed::new(m.start, m.goal, tree.cost[g as usize] / k) {
                            Some(set) => {
                                measure = set.measure(space.dims).min(space.measure());
                                set.sample(&space, rng)
                            }
                            None => space.sample(rng),
                        }
                    }
                    _ => space.sample(rng),
                }
            };
            // 2. Nearest and steer.
            let Some(nearest) = index.nearest(x_rand) else { continue };
            let from = tree.pos[nearest as usize];
            let d = from.distance(x_rand);
            if d < MIN_STEP {
                continue;
            }
            let target = if d > range { from + (x_rand - from) * (range / d) } else { x_rand };
            let mut parent = None;
            let mut x_new = target;
            if edges.kinematics.joint_ok(tree.from(nearest), from, target) {
                if let Some((p, c, t)) = edges.extend(from, target, tree.time[nearest as usize]) {
                    x_new = p;
                    parent = Some((nearest, tree.cost[nearest as usize] + c, t));
                }
            }
            if x_new.distance(from) < MIN_STEP {
                continue;
            }
            // 3. Choose the parent among the near vertices.
            let r = rewire_radius(Variant::Rrt, &space, measure, tree.len() + 1, self.params.rewire_factor).min(range);
            index.within(x_new, r, &mut near);
            order.clear();
            order.extend(
                near.iter()
                    .filter(|&&q| q != nearest)
                    .map(|&q| (tree.cost[q as usize] + edges.lower_bound(tree.pos[q as usize].distance(x_new)), q)),
            );
            order.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            for &(bound, q) in &order {
                if parent.is_some_and(|(_, c, _)| bound >= c) {
                    break;
                }
                let at = tree.pos[q as usize];
                if at.distance(x_new) < MIN_STEP
                    || !edges.kinematics.edge_ok(at, x_new)
                    || !edges.kinematics.joint_ok(tree.from(q), at, x_new)
                {
                    continue;
                }
                if let Some((c, t)) = edges.price(at, x_new, tree.time[q as usize]) {
                    let c = tree.cost[q as usize] + c;
                    if parent.is_none_or(|(_, best, _)| c < best) {
                        parent = Some((q, c, t));
                    }
                }
            }
            let Some((p, c_new, t_new)) = parent else { continue };
            let v = tree.add(x_new, p, c_new, t_new);
            index.insert(x_new, v);
            if goal.is_none() && is_goal(x_new) {
                goal = Some(v);
            }
            // 4. Rewire the near vertices through x_new.
            let into_new = tree.pos[p as usize];
            for &q in &near {
                if q == p || q == ROOT {
                    continue;
                }
                let at = tree.pos[q as usize];
                if c_new + edges.lower_bound(at.distance(x_new)) >= tree.cost[q as usize] {
                    continue;
                }
                if at.distance(x_new) < MIN_STEP
                    || !edges.kinematics.edge_ok(x_new, at)
                    || !edges.kinematics.joint_ok(Some(into_new), x_new, at)
                    || !tree.children[q as usize]
                        .iter()
                        .all(|&w| edges.kinematics.joint_ok(Some(x_new), at, tree.pos[w as usize]))
                {
                    continue;
                }
                if let Some((c, t)) = edges.price(x_new, at, t_new) {
                    if c_new + c < tree.cost[q as usize] {
                        tree.reparent(q, v, c_new + c, t, &mut edges, goal, termination);
                    }
                }
            }
        };
        out.stats.motion_checks += edges.motion_checks;
        out.stats.graph_nodes += tree.len() as u64;
        out.stats.graph_edges += tree.len().saturating_sub(1) as u64;
        let (end, reached) = match goal {
            Some(g) => (g, true),
            None => (index.nearest(m.goal).unwrap_or(ROOT), false),
        };
        if record_graph {
            out.graphs.push(SearchGraph {
                mission: i,
                kind: "tree",
                edges: tree.edges(),
                vertices: tree.pos.clone(),
                start: Some(ROOT),
                goal,
            });
        }
        let best = best(&tree, goal);
        Grown { path: tree.path_to(end), reached, best, stopped, uninformed, full }
    }
}
