//! Encoding + cost model + optimizer, run by the shared optimizer runner.

use super::{PathObjective, PlanOutcome, Planner, Problem};
use crate::optim::{self, Budget, Optimizer, Progress};
use crate::rng::Rng;

pub struct OptimizerPlanner {
    optimizer: Box<dyn Optimizer>,
}

impl OptimizerPlanner {
    pub fn new(optimizer: Box<dyn Optimizer>) -> Self {
        Self { optimizer }
    }
}

impl Planner for OptimizerPlanner {
    fn id(&self) -> &'static str {
        self.optimizer.id()
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        budget: &Budget,
        rng: Rng,
        parallel: bool,
        observer: &mut dyn FnMut(&Progress),
    ) -> PlanOutcome {
        let objective = PathObjective::new(problem);
        let r = optim::run(self.optimizer.as_mut(), &objective, budget, rng, parallel, observer);
        PlanOutcome {
            waypoints: problem.encoding.decode(&r.best_x),
            cost: r.best_cost,
            evaluations: r.evaluations,
            iterations: r.iterations,
            history: r.history,
            stop_reason: r.stop_reason,
            elapsed: r.elapsed,
        }
    }
}
