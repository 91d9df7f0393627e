//! Cost models: each a sum of named terms, one file per paper, chosen by name in a scenario
//! (`[cost] model = "..."`). `eval` prints the terms, so a user sees why a path costs what it does.

pub mod general;

pub use general::{GeneralCost, GeneralWeights};

use crate::geom::Vec3;
use crate::optim::Scratch;
use crate::path::PathModel;

/// The most terms any model may have; term buffers live on the stack.
pub const MAX_TERMS: usize = 8;

/// A cost to minimise over paths (start and goal included in `points`).
pub trait CostModel: Send + Sync {
    /// The name used in scenario files (`general`, ...).
    fn id(&self) -> &'static str;
    /// Names of the terms, in the order `evaluate` writes them.
    fn term_names(&self) -> &'static [&'static str];
    /// Writes each weighted term into `terms[..term_names().len()]` and returns their sum.
    /// Must not allocate once `scratch` has grown to the path's size.
    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch, terms: &mut [f64]) -> f64;

    /// The total only.
    fn cost(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch) -> f64 {
        let mut terms = [0.0; MAX_TERMS];
        self.evaluate(model, points, scratch, &mut terms)
    }

    /// The terms as (name, value) pairs, for reports.
    fn breakdown(&self, model: &PathModel<'_>, points: &[Vec3]) -> (f64, Vec<(&'static str, f64)>) {
        let mut terms = [0.0; MAX_TERMS];
        let total = self.evaluate(model, points, &mut Scratch::default(), &mut terms);
        (total, self.term_names().iter().copied().zip(terms).collect())
    }
}
