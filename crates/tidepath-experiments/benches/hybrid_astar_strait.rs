//! Hybrid-A* (issue #27) on the built-in `salish-strait-turns`: a 3-D transit of 133 km on the
//! real seabed for a vehicle with a 40 m turning radius (target: under 1 s on one core). One
//! whole run as `plan` makes it: start and goal checks, the reachability check, the search and
//! the evaluation of the flown curve. Here (in the experiments crate) because it needs the
//! scenario reader and criterion both.

use criterion::{criterion_group, criterion_main, Criterion};
use tidepath_io::scenario::PlanRequest;

fn bench(c: &mut Criterion) {
    let s = tidepath_io::scenario::load("salish-strait-turns").unwrap();
    let req = PlanRequest { planner: Some("hybrid-astar".into()), parallel: false, ..PlanRequest::default() };
    let r = s.plan(&req, &mut |_| {}).unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    eprintln!("salish-strait-turns, hybrid-astar: {}, {} expansions", r.status, r.expansions);
    let mut group = c.benchmark_group("hybrid-astar");
    group.sample_size(20);
    group.bench_function("salish-strait-turns", |b| b.iter(|| s.plan(&req, &mut |_| {}).unwrap()));
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
