//! Planners: one interface for every way of producing a path. An optimization planner joins an
//! encoding, a cost model and an optimizer; graph and sampling planners (later issues)
//! implement the same trait and search the world directly.

mod objective;
mod optimizer_planner;
pub mod registry;

pub use objective::PathObjective;
pub use optimizer_planner::OptimizerPlanner;
pub use registry::{build_optimizer, build_planner, planner_info, PlannerInfo, PLANNERS};

use std::time::Duration;

use crate::cost::CostModel;
use crate::encoding::Encoding;
use crate::geom::Vec3;
use crate::optim::{Budget, Progress, StopReason};
use crate::path::PathModel;
use crate::rng::Rng;

/// One planning query: judge paths with `model` and `cost`, from `start` to `goal`.
pub struct Problem<'a> {
    pub model: PathModel<'a>,
    pub cost: &'a dyn CostModel,
    /// The decision-vector layout optimization planners search over.
    pub encoding: &'a dyn Encoding,
    pub start: Vec3,
    pub goal: Vec3,
}

/// What a planner returns: the path (start and goal included) and how the search went.
#[derive(Clone, Debug)]
pub struct PlanOutcome {
    pub waypoints: Vec<Vec3>,
    pub cost: f64,
    pub evaluations: u64,
    pub iterations: u64,
    /// Best cost after initialisation and after each iteration.
    pub history: Vec<f64>,
    pub stop_reason: StopReason,
    pub elapsed: Duration,
}

pub trait Planner: Send {
    fn id(&self) -> &'static str;
    /// Plans within `budget`, drawing every random number from `rng`. `parallel` allows
    /// evaluating populations on the rayon pool; results do not depend on it.
    fn plan(
        &mut self,
        problem: &Problem<'_>,
        budget: &Budget,
        rng: Rng,
        parallel: bool,
        observer: &mut dyn FnMut(&Progress),
    ) -> PlanOutcome;
}
