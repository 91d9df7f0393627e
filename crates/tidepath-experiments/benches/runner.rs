//! Overhead of the experiment runner (issue #3 target: under 1% of a 10 ms run).
//!
//! Compares ten ~10 ms optimizer runs called directly with the same ten runs executed through
//! `experiments::runner` (task list, seed derivation, thread pool, result collection) on one
//! worker thread, so the difference is the runner's own cost. "runner with no work" isolates that
//! cost per experiment of ten tasks.

use criterion::{criterion_group, criterion_main, Criterion};
use tidepath::optim::functions::{Function, FunctionObjective};
use tidepath::optim::pso::{Pso, PsoParams};
use tidepath::optim::{run, Termination};
use tidepath::rng::run_rng;
use tidepath_experiments::runner::{execute, tasks, RunControl, Task};
use tidepath_experiments::RunRecord;

const RUNS: u64 = 10;

fn one_run(seed: u64) -> f64 {
    let objective = FunctionObjective::new(Function::Rastrigin, 30, -5.12, 5.12);
    let mut pso = Pso::new(PsoParams::default().checked("pso").unwrap());
    run(&mut pso, &objective, &Termination::evaluations(12_000), &mut run_rng(seed, 0), false, &[], &mut |_| {})
        .best_cost
}

fn record(t: &Task, cost: f64) -> RunRecord {
    RunRecord {
        problem: t.problem.clone(),
        planner: t.planner.clone(),
        run: t.run,
        seed: t.seed,
        cost,
        feasible: true,
        length_m: None,
        travel_time_s: None,
        evaluations: 12_000,
        iterations: 0,
        elapsed_s: 0.0,
        stop_reason: tidepath::optim::StopReason::MaxEvaluations,
        history: Vec::new(),
        waypoints: Vec::new(),
        ..RunRecord::default()
    }
}

fn bench(c: &mut Criterion) {
    let all = tasks(1, &["rastrigin".to_string()], &["pso".to_string()], RUNS);
    let mut g = c.benchmark_group("runner overhead (10 runs of ~10 ms)");
    g.sample_size(10);
    g.bench_function("direct calls", |b| b.iter(|| all.iter().map(|t| one_run(t.seed)).sum::<f64>()));
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
    g.bench_function("direct calls on a rayon worker", |b| {
        b.iter(|| pool.install(|| all.iter().map(|t| one_run(t.seed)).sum::<f64>()))
    });
    g.bench_function("through experiments::runner, 1 job", |b| {
        b.iter(|| execute(&all, RunControl::jobs(1), |t| Ok(record(t, one_run(t.seed)))).unwrap())
    });
    g.finish();
    c.bench_function("runner with no work (10 tasks, 1 job)", |b| {
        b.iter(|| execute(&all, RunControl::jobs(1), |t| Ok(record(t, 0.0))).unwrap())
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
