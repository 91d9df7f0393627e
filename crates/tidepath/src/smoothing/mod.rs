//! Smoothing and repair operators: components any planner's output can go through, as in
//! OMPL's `PathSimplifier`. The paper-specific ones (Dubins for seed 000, B-splines with
//! midpoint insertion for seed 003, excluding and contracting for seed 002) join this folder.

pub mod shortcut;

pub use shortcut::Shortcut;

use crate::cost::CostModel;
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::path::PathModel;

pub trait Smoother: Send + Sync {
    /// The id used on the command line and in scenarios.
    fn id(&self) -> &'static str;
    /// A path with the same start and goal that is never worse under `cost`, and never
    /// infeasible when `points` is feasible.
    fn smooth(&self, model: &PathModel<'_>, cost: &dyn CostModel, points: &[Vec3]) -> Vec<Vec3>;
}

/// Smoother ids and their one-line descriptions.
pub const SMOOTHERS: &[(&str, &str)] = &[("shortcut", "drop waypoints whose bypass is feasible and no costlier")];

pub fn build_smoother(id: &str) -> Result<Box<dyn Smoother>> {
    match id {
        "shortcut" => Ok(Box::new(Shortcut)),
        other => Err(Error::input(
            "smoother",
            format!(
                "unknown smoother '{other}' (known: {})",
                SMOOTHERS.iter().map(|(id, _)| *id).collect::<Vec<_>>().join(", ")
            ),
        )),
    }
}
