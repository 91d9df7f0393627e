//! ijs2023's path experiments on the built-in `ijs-static-1` (Table 1) and `ijs-current`
//! (Table 2): one whole IJS run with the paper's 45 jellyfish and T = 500 iterations, on one
//! core (`parallel: false`), as `plan` makes it (the search and the final evaluation). The
//! paper reports 51.90 s and 54.62 s per IJS run in MATLAB; the acceptance bar is 500 times
//! faster (104 ms and 109 ms). JS and the baselines are timed beside it. Here (in the
//! experiments crate) because it needs the scenario reader and criterion both.

use criterion::{criterion_group, criterion_main, Criterion};
use tidepath_io::scenario::PlanRequest;

fn bench(c: &mut Criterion) {
    for scenario in ["ijs-static-1", "ijs-current"] {
        let s = tidepath_io::scenario::load(scenario).unwrap();
        let mut group = c.benchmark_group(scenario);
        group.sample_size(20);
        for planner in ["ijs", "js", "qpso", "pso", "hho", "mpa"] {
            let req = PlanRequest { planner: Some(planner.into()), parallel: false, ..PlanRequest::default() };
            let r = s.plan(&req, &mut |_| {}).unwrap();
            eprintln!(
                "{scenario}, {planner}: {:?} ({}), cost {:?}, {} evaluations in {} iterations",
                r.status, r.reason, r.cost, r.evaluations, r.iterations
            );
            group.bench_function(planner, |b| b.iter(|| s.plan(&req, &mut |_| {}).unwrap()));
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
