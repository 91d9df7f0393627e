//! The bridge from a path problem to the optimizer's view: a bounded vector and a cost.

use super::Problem;
use crate::optim::{Objective, Scratch};

pub struct PathObjective<'a> {
    problem: &'a Problem<'a>,
}

impl<'a> PathObjective<'a> {
    pub fn new(problem: &'a Problem<'a>) -> Self {
        Self { problem }
    }
}

impl Objective for PathObjective<'_> {
    fn dim(&self) -> usize {
        self.problem.encoding.dim()
    }

    fn lower(&self) -> &[f64] {
        self.problem.encoding.lower()
    }

    fn upper(&self) -> &[f64] {
        self.problem.encoding.upper()
    }

    fn evaluate(&self, x: &[f64], scratch: &mut Scratch) -> f64 {
        // Move the point buffer out so the cost model can borrow the rest of the scratch;
        // moving a Vec does not allocate.
        let mut points = std::mem::take(&mut scratch.points);
        self.problem.encoding.decode_into(x, &mut points);
        let c = self.problem.cost.cost(&self.problem.model, &points, scratch);
        scratch.points = points;
        c
    }

    fn repair(&self, x: &mut [f64]) {
        self.problem.encoding.repair(x)
    }

    fn parallel_hint(&self) -> bool {
        true
    }
}
