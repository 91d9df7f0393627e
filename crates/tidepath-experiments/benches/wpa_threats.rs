//! wpa2017's path experiment on the built-in `wpa-threats`: one whole MWPA run and one WPA run
//! with the paper's N = 300 wolves and K_max = 300 iterations, on one core (`parallel: false`),
//! as `plan` makes them (the search, Step 7, the Dubins smoothing and the evaluation). The
//! paper reports 4.37 s (MWPA) and 10.24 s (WPA) per run in MATLAB; the evaluation counts
//! printed here are what such a run costs (the paper gives none). Here (in the experiments
//! crate) because it needs the scenario reader and criterion both.
//!
//! A run takes seconds, so criterion takes the fewest samples it allows (10); expect about
//! ten minutes for both.

use criterion::{criterion_group, criterion_main, Criterion};
use tidepath_io::scenario::PlanRequest;

fn bench(c: &mut Criterion) {
    let s = tidepath_io::scenario::load("wpa-threats").unwrap();
    let mut group = c.benchmark_group("wpa-threats");
    group.sample_size(10);
    for planner in ["mwpa", "wpa"] {
        let req = PlanRequest { planner: Some(planner.into()), parallel: false, ..PlanRequest::default() };
        let r = s.plan(&req, &mut |_| {}).unwrap();
        eprintln!(
            "wpa-threats, {planner}: {:?} ({}), cost {:?}, {} evaluations in {} iterations",
            r.status, r.reason, r.cost, r.evaluations, r.iterations
        );
        group.bench_function(planner, |b| b.iter(|| s.plan(&req, &mut |_| {}).unwrap()));
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
