//! Checks the optimizers' own unit tests share (the registry-wide ones are in
//! `tests/optimizers.rs`): the same assertions, written once.

use super::functions::FunctionObjective;
use super::{run, Optimizer};
use crate::rng::run_rng;
use crate::termination::Termination;

/// Each budget of `budgets` is spent exactly, and the best cost is a number.
pub fn assert_exact_budgets(obj: &FunctionObjective, budgets: &[u64], mut make: impl FnMut() -> Box<dyn Optimizer>) {
    for &budget in budgets {
        let mut opt = make();
        let r = run(opt.as_mut(), obj, &Termination::evaluations(budget), &mut run_rng(5, 0), false, &[], &mut |_| {});
        assert_eq!(r.evaluations, budget);
        assert!(r.best_cost.is_finite());
    }
}

/// A run of 4,000 evaluations gives the same bits evaluated serially and in parallel.
pub fn assert_same_bits(obj: &FunctionObjective, mut make: impl FnMut() -> Box<dyn Optimizer>) {
    let mut go = |parallel| {
        let mut opt = make();
        run(opt.as_mut(), obj, &Termination::evaluations(4_000), &mut run_rng(9, 2), parallel, &[], &mut |_| {})
    };
    let (a, b) = (go(false), go(true));
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&a.best_x), bits(&b.best_x));
    assert_eq!(bits(&a.history), bits(&b.history));
    assert_eq!(a.iterations, b.iterations);
}
