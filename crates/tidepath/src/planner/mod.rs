//! Planners: one interface for every way of producing a path (OMPL's `Planner::solve` is the
//! model). An optimization planner joins an encoding, a cost model and an optimizer; graph,
//! sampling and composite planners implement the same trait and search the world directly
//! through the shared [`crate::validity`] checks.
//!
//! A planner returns raw paths and its search statistics ([`PlannerOutput`]); [`solve`] wraps
//! every planner the same way: it checks start and goal first, runs the planner, smooths,
//! evaluates each path with the shared path evaluation and sets the [`Status`].

pub mod aco;
pub mod capabilities;
mod fleet_judge;
pub mod fleet_sequential;
pub mod grid_search;
pub mod hybrid;
pub mod hybrid_astar;
mod objective;
mod optimizer_planner;
pub mod presets;
pub mod raster_search;
pub mod reachability;
pub mod registry;
pub mod sampling;
pub mod section_cells;
mod sliced_hint;
pub mod solve;
pub use fleet_judge::judge_fleet;
pub use fleet_sequential::FleetMode;
mod status;
pub mod visibility;

pub use capabilities::{Capabilities, Dimensions, Fleets, Unit};
pub use objective::PathObjective;
pub use optimizer_planner::OptimizerPlanner;
pub use registry::{build_optimizer, registry, BuildPlanner, Make, PlannerSettings, PLANNERS};
pub use solve::{solve, Focus, MissionPlan, Plan, SolveOptions};
pub use status::Status;

use std::time::Duration;

use crate::cost::CostModel;
use crate::geom::Vec3;
use crate::mission::Mission;
use crate::optim::Progress;
use crate::path::{ModelSettings, PathModel};
use crate::rng::Rng;
use crate::termination::{StopReason, Termination};
use crate::world::{Dims, World};

/// One planning query: a world answering at time t, a cost model, and one or more missions.
#[derive(Clone, Copy)]
pub struct Problem<'a> {
    pub world: &'a World,
    pub settings: &'a ModelSettings,
    pub cost: &'a dyn CostModel,
    pub missions: &'a [Mission],
    /// The separation the missions' vehicles keep from each other ([`crate::fleet::NO_FLEET`]
    /// for none).
    pub fleet: &'a crate::fleet::FleetRules,
}

impl<'a> Problem<'a> {
    /// The path evaluation of mission `i` (builds its obstacle index: call once per run).
    pub fn path_model(&self, i: usize) -> PathModel<'a> {
        PathModel::new(self.world, &self.missions[i], self.settings)
    }

    /// The height band a 3-D path of mission `i` may use, or `None` in a 2-D world.
    pub fn z_range(&self, i: usize) -> Option<(f64, f64)> {
        let v = &self.missions[i].vehicle;
        let b = &self.world.bounds;
        (self.world.dims == Dims::Three).then(|| (b.min.z.max(v.z_min()), b.max.z.min(v.z_max())))
    }
}

/// What a planner claims beyond its paths, from a direct check or a proof.
#[derive(Clone, Debug, PartialEq)]
pub enum Claim {
    /// The paths are optimal for `objective` over the planner's search space (status `exact`
    /// if they are feasible and `objective` is the scenario's cost model).
    Optimal {
        /// The search space, as the reason names it ("on the 8-connected 200 x 200 raster").
        space: String,
        /// What was minimised ("the scenario's cost model", "length").
        objective: String,
        /// Whether that is the scenario's own cost model.
        scenario_cost: bool,
    },
    /// No path exists; the reason names the bottleneck.
    Unreachable(String),
    /// A line to add to the reason when the plan is not feasible (why this planner failed).
    Hint(String),
    /// The planner's own search found no route for some missions (indexed like `paths`): the
    /// text says which search and on what ("no route on the 8-connected 200 x 200 raster").
    /// It leads the reason of such a mission, before any violation of a fallback path.
    NoRoute(Vec<Option<String>>),
}

/// Search statistics, in each planner's own units.
#[derive(Clone, Debug, PartialEq)]
pub struct SearchStats {
    pub iterations: u64,
    pub evaluations: u64,
    pub expansions: u64,
    pub samples: u64,
    /// State checks and motion checks made by the shared validator on the planner's behalf
    /// (OMPL's "valid states" and "valid motions" counts); 0 where the planner does not count.
    pub state_checks: u64,
    pub motion_checks: u64,
    /// Size of the graph a graph planner built or searched (nodes and edges); 0 otherwise.
    pub graph_nodes: u64,
    pub graph_edges: u64,
    /// Best cost after initialisation and after each iteration (optimizers).
    pub history: Vec<f64>,
    pub stop_reason: StopReason,
    pub elapsed: Duration,
}

impl Default for SearchStats {
    fn default() -> Self {
        Self {
            iterations: 0,
            evaluations: 0,
            expansions: 0,
            samples: 0,
            state_checks: 0,
            motion_checks: 0,
            graph_nodes: 0,
            graph_edges: 0,
            history: Vec::new(),
            stop_reason: StopReason::Completed,
            elapsed: Duration::ZERO,
        }
    }
}

/// A planner's raw result: one path per mission (start and goal included; empty when none was
/// found), a claim, the search statistics and, when asked for, the graphs it searched.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlannerOutput {
    pub paths: Vec<Vec<Vec3>>,
    /// Each path's segment speeds, when the planner chose them (an optimizer over a vehicle
    /// with a speed range); empty, or `None` for a path, lets [`solve`] give each segment the
    /// cheapest of the vehicle's speed levels on the running clock
    /// ([`crate::cost::edge_speeds`]), the choice edge-by-edge searches make while searching.
    pub speeds: Vec<Option<Vec<f64>>>,
    pub claim: Option<Claim>,
    pub stats: SearchStats,
    /// The tree or roadmap of each mission, when [`RunOptions::record_graph`] asked for it and
    /// the planner builds one (sampling planners); empty otherwise.
    pub graphs: Vec<SearchGraph>,
}

/// The graph a planner built for one mission (OMPL's `PlannerData` is the model): its
/// vertices and edges, for `plan --graph` and for figures that draw it under the path.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SearchGraph {
    /// The mission it belongs to (index into the problem's missions).
    pub mission: usize,
    /// "tree" (RRT*: every edge goes from parent to child) or "roadmap" (PRM*: undirected).
    pub kind: &'static str,
    pub vertices: Vec<Vec3>,
    /// Pairs of vertex indices; in a tree, (parent, child).
    pub edges: Vec<[u32; 2]>,
    /// The start's vertex, and the goal's when the graph reached it.
    pub start: Option<u32>,
    pub goal: Option<u32>,
}

/// Run options that change no result.
#[derive(Clone, Copy, Debug, Default)]
pub struct RunOptions<'a> {
    /// A path per mission to start from (a warm start): optimizers seed part of their
    /// population with it, tree planners their tree, ant colonies their pheromone.
    pub init: Option<&'a [Vec<Vec3>]>,
    /// Evaluate populations on the rayon pool; results are identical either way.
    pub parallel: bool,
    /// Keep the search graph (tree or roadmap) in [`PlannerOutput::graphs`].
    pub record_graph: bool,
}

pub trait Planner: Send {
    fn id(&self) -> &'static str;
    /// Rejects a problem this planner cannot take (an input error naming the setting), before
    /// any planning; the default accepts every problem.
    fn check(&self, _problem: &Problem<'_>) -> crate::error::Result<()> {
        Ok(())
    }
    /// Plans within `termination`, drawing every random number from `rng`.
    fn plan(
        &mut self,
        problem: &Problem<'_>,
        termination: &Termination,
        rng: &mut Rng,
        options: RunOptions<'_>,
        observer: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput;
}
