//! acopf2016's wave glider: one whole `acopf` run (the paper's T = 60 iterations of K = 30
//! ants, its defaults) beside one `astar` run with `objective = time` (the glider's quickest
//! path on the same cells), on one core, as `plan` makes them (the search and the final
//! evaluation): on `glider-3` (the paper's 20 x 20 grid with waves and a current band) and on
//! `glider-ocean` (200 x 200 cells from a wave forecast). The paper reports no run times. Here
//! (in the experiments crate) because it needs the scenario reader and criterion both.

use criterion::{criterion_group, criterion_main, Criterion};
use tidepath_io::scenario::PlanRequest;

fn bench(c: &mut Criterion) {
    for scenario in ["glider-3", "glider-ocean"] {
        let mut s = tidepath_io::scenario::load(scenario).unwrap();
        s.planner.params.entry("astar".into()).or_default().insert("objective".into(), "time".into());
        let mut group = c.benchmark_group(scenario);
        group.sample_size(10);
        for planner in ["acopf", "astar"] {
            let req = PlanRequest { planner: Some(planner.into()), parallel: false, ..PlanRequest::default() };
            let r = s.plan(&req, &mut |_| {}).unwrap();
            eprintln!(
                "{scenario}, {planner}: {:?} ({}), cost {:?}, length {:?} m, travel time {:?} s, {} iterations, {} \
                 expansions",
                r.status,
                r.reason,
                r.cost,
                r.length_m(),
                r.travel_time_s(),
                r.iterations,
                r.expansions
            );
            group.bench_function(planner, |b| b.iter(|| s.plan(&req, &mut |_| {}).unwrap()));
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
