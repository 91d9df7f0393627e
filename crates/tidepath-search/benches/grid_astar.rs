//! A* on a 1000 x 1000 8-connected random grid, beside the `pathfinding`
//! crate's `astar` on the same grid, moves and costs (checked equal before
//! timing); Theta* on the same grid; 26-connected A* on 200 x 200 x 100.
//!
//! Costs are integers (10000 per orthogonal move, 14142 per diagonal) so that
//! `pathfinding`, which needs `Ord` costs, sees exactly the same numbers as our
//! `f64` search; the heuristic is the matching octile distance.

use criterion::{criterion_group, criterion_main, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath_search::{astar, astar_in, connected, theta_star_in, Grid2, Grid3, Limits, SearchArena, SearchGrid};

const ORTHO: u64 = 10_000;
const DIAG: u64 = 14_142;
/// Fixed random stream for the benchmark worlds.
const RNG_STREAM: u64 = 0x7469_6465_7061_7468;

fn random_grid2(nx: usize, ny: usize, blocked: f64) -> Grid2 {
    let mut rng = ChaCha8Rng::seed_from_u64(RNG_STREAM);
    let mask = (0..nx * ny).map(|_| rng.random_bool(blocked)).collect();
    let mut g = Grid2::from_blocked(nx, ny, mask).unwrap();
    for (i, j) in [(0, 0), (1, 0), (0, 1), (nx - 1, ny - 1), (nx - 2, ny - 1), (nx - 1, ny - 2)] {
        g.set_blocked(i, j, false);
    }
    g
}

fn random_grid3(nx: usize, ny: usize, nz: usize, blocked: f64) -> Grid3 {
    let mut rng = ChaCha8Rng::seed_from_u64(RNG_STREAM);
    let mask = (0..nx * ny * nz).map(|_| rng.random_bool(blocked)).collect();
    let mut g = Grid3::from_blocked(nx, ny, nz, mask).unwrap();
    g.set_blocked(0, 0, 0, false);
    g.set_blocked(nx - 1, ny - 1, nz - 1, false);
    g
}

fn octile2(g: &Grid2, a: usize, b: usize) -> u64 {
    let (ai, aj) = g.coords(a);
    let (bi, bj) = g.coords(b);
    let (dx, dy) = (ai.abs_diff(bi) as u64, aj.abs_diff(bj) as u64);
    ORTHO * dx.max(dy) + (DIAG - ORTHO) * dx.min(dy)
}

fn bench_2d(c: &mut Criterion) {
    let g = random_grid2(1000, 1000, 0.25);
    let (s, t) = (0, g.len() - 1);
    assert!(connected(&g, s, t).unwrap(), "benchmark grid must connect its corners");
    let nx = g.nx();
    let step = move |a: usize, b: usize| {
        let d = a.abs_diff(b);
        if d == 1 || d == nx {
            ORTHO
        } else {
            DIAG
        }
    };
    let ours = |arena: &mut SearchArena| {
        astar_in(arena, &g, s, t, |a, b, _| Some(step(a, b) as f64), |v| octile2(&g, v, t) as f64, &Limits::none())
            .unwrap()
    };
    let theirs = || {
        pathfinding::prelude::astar(
            &s,
            |&u| {
                let mut buf = [(0usize, 0u64); 8];
                let mut n = 0;
                g.for_each_neighbour(u, |v| {
                    buf[n] = (v, step(u, v));
                    n += 1;
                });
                buf.into_iter().take(n)
            },
            |&v| octile2(&g, v, t),
            |&v| v == t,
        )
        .expect("connected")
    };
    let mut arena = SearchArena::new();
    let a = ours(&mut arena);
    let (path, cost) = theirs();
    assert!(a.found());
    assert_eq!(a.cost, cost as f64, "both searches must find the same optimal cost");
    println!(
        "1000x1000, 25% blocked: cost {} ({} moves, {} expansions); pathfinding path {} cells",
        a.cost,
        a.path.len() - 1,
        a.expansions,
        path.len()
    );

    let mut group = c.benchmark_group("astar_2d_1000x1000_25pct");
    group.sample_size(10);
    group.bench_function("tidepath_search_reused_arena", |b| b.iter(|| ours(&mut arena).cost));
    group.bench_function("tidepath_search_fresh", |b| {
        b.iter(|| astar(&g, s, t, |a, b, _| Some(step(a, b) as f64), |v| octile2(&g, v, t) as f64, &Limits::none()))
    });
    group.bench_function("pathfinding_astar", |b| b.iter(|| theirs().1));
    group.finish();

    let theta = |arena: &mut SearchArena| {
        theta_star_in(arena, &g, s, t, |a, b, _| Some(g.euclidean(a, b)), |v| g.euclidean(v, t), &Limits::none())
            .unwrap()
    };
    let th = theta(&mut arena);
    assert!(th.found() && th.cost <= a.cost / ORTHO as f64 + 1e-9);
    println!(
        "theta*: length {:.3} cells ({} turning points, {} expansions) vs A* {:.3}",
        th.cost,
        th.path.len(),
        th.expansions,
        a.cost / ORTHO as f64
    );
    let mut group = c.benchmark_group("theta_star_2d_1000x1000_25pct");
    group.sample_size(10);
    group.bench_function("tidepath_search_reused_arena", |b| b.iter(|| theta(&mut arena).cost));
    group.finish();
}

fn bench_3d(c: &mut Criterion) {
    let g = random_grid3(200, 200, 100, 0.2);
    let (s, t) = (0, g.len() - 1);
    assert!(connected(&g, s, t).unwrap(), "benchmark grid must connect its corners");
    let mut arena = SearchArena::new();
    let run = |arena: &mut SearchArena| {
        astar_in(arena, &g, s, t, |a, b, _| Some(g.step_length(a, b)), |v| g.octile(v, t), &Limits::none()).unwrap()
    };
    let o = run(&mut arena);
    assert!(o.found());
    println!("200x200x100, 20% blocked: cost {:.3} ({} expansions)", o.cost, o.expansions);
    let mut group = c.benchmark_group("astar_3d_200x200x100_20pct");
    group.sample_size(10);
    group.bench_function("tidepath_search_reused_arena", |b| b.iter(|| run(&mut arena).cost));
    group.finish();
}

criterion_group!(benches, bench_2d, bench_3d);
criterion_main!(benches);
