//! Property tests: A* = Dijkstra, Theta* ≤ A*, maximin = brute force,
//! `connected` = "A* finds a path", exact line of sight = brute force, and
//! visibility-graph paths are feasible and no longer than a rasterised Theta*.

use proptest::prelude::*;
use tidepath_search::visibility::{self, Circle, Piece, Point, Polygon, Rect, Scene};
use tidepath_search::{
    astar, connected, maximin, theta_star, Grid2, Grid3, Limits, LineOfSight, SearchGrid, SearchOutcome, SearchStatus,
};

fn grid2() -> impl Strategy<Value = (Grid2, usize, usize)> {
    (2usize..24, 2usize..24, 0.0f64..0.45).prop_flat_map(|(nx, ny, p)| {
        let n = nx * ny;
        (proptest::collection::vec(proptest::bool::weighted(p), n), 0..n, 0..n).prop_map(move |(mut b, s, t)| {
            b[s] = false;
            b[t] = false;
            (Grid2::from_blocked(nx, ny, b).unwrap(), s, t)
        })
    })
}

fn grid3() -> impl Strategy<Value = (Grid3, usize, usize)> {
    (2usize..8, 2usize..8, 2usize..8, 0.0f64..0.5).prop_flat_map(|(nx, ny, nz, p)| {
        let n = nx * ny * nz;
        (proptest::collection::vec(proptest::bool::weighted(p), n), 0..n, 0..n).prop_map(move |(mut b, s, t)| {
            b[s] = false;
            b[t] = false;
            (Grid3::from_blocked(nx, ny, nz, b).unwrap(), s, t)
        })
    })
}

fn neighbours<G: SearchGrid>(g: &G, c: usize) -> Vec<usize> {
    let mut v = Vec::new();
    g.for_each_neighbour(c, |n| v.push(n));
    v
}

/// The path is a chain of legal moves from s to t whose lengths add up to the cost.
fn check_grid_path<G: SearchGrid>(g: &G, o: &SearchOutcome, s: usize, t: usize, step: impl Fn(usize, usize) -> f64) {
    assert_eq!((o.path[0], *o.path.last().unwrap()), (s, t));
    let mut sum = 0.0;
    for w in o.path.windows(2) {
        assert!(neighbours(g, w[0]).contains(&w[1]), "illegal move {} -> {}", w[0], w[1]);
        sum += step(w[0], w[1]);
    }
    assert!((sum - o.cost).abs() < 1e-9);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn astar_equals_dijkstra_2d((g, s, t) in grid2()) {
        let cost = |a: usize, b: usize, _: f64| Some(g.step_length(a, b));
        let dij = astar(&g, s, t, cost, |_| 0.0, &Limits::none()).unwrap();
        let ast = astar(&g, s, t, cost, |c| g.octile(c, t), &Limits::none()).unwrap();
        prop_assert_eq!(dij.status, ast.status);
        prop_assert_ne!(dij.status, SearchStatus::Stopped(tidepath_search::StopReason::MaxExpansions));
        prop_assert_eq!(connected(&g, s, t).unwrap(), ast.found());
        if ast.found() {
            prop_assert!((dij.cost - ast.cost).abs() < 1e-9, "{} vs {}", dij.cost, ast.cost);
            prop_assert!(ast.expansions <= dij.expansions);
            check_grid_path(&g, &ast, s, t, |a, b| g.step_length(a, b));
            check_grid_path(&g, &dij, s, t, |a, b| g.step_length(a, b));
        }
    }

    #[test]
    fn time_dependent_search_matches_label_correcting((g, s, t) in grid2(), phase in 0.0f64..6.3) {
        // FIFO costs (t + c(t) is non-decreasing since |c'| ≤ 0.5·√2 < 1): the
        // earliest arrival from label-setting A* (zero heuristic) must equal the
        // fixed point of Bellman–Ford relaxation.
        let cost = |a: usize, b: usize, time: f64| Some(g.step_length(a, b) * (1.0 + 0.5 * (time + phase + a as f64).sin()));
        let o = astar(&g, s, t, cost, |_| 0.0, &Limits::none()).unwrap();
        let mut arr = vec![f64::INFINITY; g.len()];
        arr[s] = 0.0;
        for _ in 0..g.len() {
            let mut changed = false;
            for u in 0..g.len() {
                if arr[u].is_finite() && !g.blocked()[u] {
                    for v in neighbours(&g, u) {
                        let x = arr[u] + cost(u, v, arr[u]).unwrap();
                        if x < arr[v] - 1e-12 {
                            arr[v] = x;
                            changed = true;
                        }
                    }
                }
            }
            if !changed {
                break;
            }
        }
        prop_assert_eq!(o.found(), arr[t].is_finite());
        if o.found() {
            prop_assert!((o.cost - arr[t]).abs() < 1e-9, "{} vs {}", o.cost, arr[t]);
            // Replaying the path on the clock gives the reported arrival time.
            let mut time = 0.0;
            for w in o.path.windows(2) {
                time += cost(w[0], w[1], time).unwrap();
            }
            prop_assert!((time - o.cost).abs() < 1e-9);
        }
    }

    #[test]
    fn expansion_limit_never_claims_no_path((g, s, t) in grid2(), max in 0u64..200) {
        let cost = |a: usize, b: usize, _: f64| Some(g.step_length(a, b));
        let full = astar(&g, s, t, cost, |c| g.octile(c, t), &Limits::none()).unwrap();
        let lim = Limits { max_expansions: Some(max), ..Limits::none() };
        let cut = astar(&g, s, t, cost, |c| g.octile(c, t), &lim).unwrap();
        prop_assert!(cut.expansions <= max);
        match cut.status {
            SearchStatus::Stopped(_) => prop_assert_eq!(cut.expansions, max),
            _ => prop_assert_eq!(&cut, &full),
        }
    }

    #[test]
    fn astar_equals_dijkstra_3d((g, s, t) in grid3()) {
        let cost = |a: usize, b: usize, _: f64| Some(g.step_length(a, b));
        let dij = astar(&g, s, t, cost, |_| 0.0, &Limits::none()).unwrap();
        let ast = astar(&g, s, t, cost, |c| g.octile(c, t), &Limits::none()).unwrap();
        prop_assert_eq!(dij.status, ast.status);
        prop_assert_eq!(connected(&g, s, t).unwrap(), ast.found());
        if ast.found() {
            prop_assert!((dij.cost - ast.cost).abs() < 1e-9, "{} vs {}", dij.cost, ast.cost);
            check_grid_path(&g, &ast, s, t, |a, b| g.step_length(a, b));
        }
    }

    #[test]
    fn theta_never_longer_than_astar_2d((g, s, t) in grid2()) {
        let a = astar(&g, s, t, |a, b, _| Some(g.step_length(a, b)), |c| g.octile(c, t), &Limits::none()).unwrap();
        let th = theta_star(&g, s, t, |a, b, _| Some(g.euclidean(a, b)), |c| g.euclidean(c, t), &Limits::none()).unwrap();
        prop_assert_eq!(a.status, th.status);
        if th.found() {
            prop_assert!(th.cost <= a.cost + 1e-9, "theta {} > astar {}", th.cost, a.cost);
            prop_assert!(th.cost >= g.euclidean(s, t) - 1e-9);
            let sum: f64 = th.path.windows(2).map(|w| g.euclidean(w[0], w[1])).sum();
            prop_assert!((sum - th.cost).abs() < 1e-9);
            prop_assert!(th.path.windows(2).all(|w| g.line_of_sight(w[0], w[1])));
        }
    }

    #[test]
    fn theta_never_longer_than_astar_3d((g, s, t) in grid3()) {
        let a = astar(&g, s, t, |a, b, _| Some(g.step_length(a, b)), |c| g.octile(c, t), &Limits::none()).unwrap();
        let th = theta_star(&g, s, t, |a, b, _| Some(g.euclidean(a, b)), |c| g.euclidean(c, t), &Limits::none()).unwrap();
        prop_assert_eq!(a.status, th.status);
        if th.found() {
            prop_assert!(th.cost <= a.cost + 1e-9, "theta {} > astar {}", th.cost, a.cost);
            prop_assert!(th.path.windows(2).all(|w| g.line_of_sight(w[0], w[1])));
        }
    }

    #[test]
    fn maximin_equals_threshold_search(
        (g, s, t) in grid2(),
        raw in proptest::collection::vec(0u8..8, 24 * 24),
    ) {
        let values: Vec<f64> = raw[..g.len()].iter().map(|&v| v as f64).collect();
        let got = maximin(&g, &values, s, t).unwrap();
        // Brute force: the largest threshold T (among the values) for which s and t
        // stay connected once every cell below T is blocked.
        let mut thresholds: Vec<f64> = values.clone();
        thresholds.sort_by(|a, b| b.total_cmp(a));
        thresholds.dedup();
        let mut want = None;
        for &th in &thresholds {
            if values[s] < th || values[t] < th {
                continue;
            }
            let b: Vec<bool> = (0..g.len()).map(|c| g.blocked()[c] || values[c] < th).collect();
            let gt = Grid2::from_blocked(g.nx(), g.ny(), b).unwrap();
            if connected(&gt, s, t).unwrap() {
                want = Some(th);
                break;
            }
        }
        prop_assert_eq!(got.as_ref().map(|b| b.value), want);
        if let Some(b) = got {
            prop_assert_eq!(values[b.cell], b.value);
            // The path's own bottleneck (cells and diagonal corners) is the value.
            let nx = g.nx();
            let mut m = values[s];
            for w in b.path.windows(2) {
                prop_assert!(neighbours(&g, w[0]).contains(&w[1]));
                let (ui, uj, vi, vj) = (w[0] % nx, w[0] / nx, w[1] % nx, w[1] / nx);
                m = m.min(values[w[1]]).min(values[ui + nx * vj]).min(values[vi + nx * uj]);
            }
            prop_assert_eq!(m, b.value);
        }
    }

    #[test]
    fn grid_moves_are_exactly_the_visible_adjacent_pairs((g, _s, _t) in grid3()) {
        // The connectivity rule and the line-of-sight rule agree on single moves.
        for c in (0..g.len()).filter(|&c| !g.blocked()[c]) {
            let moves = neighbours(&g, c);
            let (i, j, k) = g.coords(c);
            for n in 0..g.len() {
                let (a, b, d) = g.coords(n);
                let adjacent = n != c && i.abs_diff(a) <= 1 && j.abs_diff(b) <= 1 && k.abs_diff(d) <= 1;
                if adjacent && !g.blocked()[n] {
                    prop_assert_eq!(moves.contains(&n), g.line_of_sight(c, n), "{} -> {}", c, n);
                } else {
                    prop_assert!(!moves.contains(&n));
                }
            }
        }
    }

    #[test]
    fn grid2_moves_are_exactly_the_visible_adjacent_pairs((g, _s, _t) in grid2()) {
        for c in (0..g.len()).filter(|&c| !g.blocked()[c]) {
            let moves = neighbours(&g, c);
            let (i, j) = g.coords(c);
            for di in -1i64..=1 {
                for dj in -1i64..=1 {
                    let (a, b) = (i as i64 + di, j as i64 + dj);
                    if (di, dj) == (0, 0) || a < 0 || b < 0 || a >= g.nx() as i64 || b >= g.ny() as i64 {
                        continue;
                    }
                    let n = g.index(a as usize, b as usize);
                    let visible = !g.blocked()[n] && g.line_of_sight(c, n);
                    prop_assert_eq!(moves.contains(&n), visible);
                }
            }
            prop_assert!(moves.len() <= 8);
        }
    }

    #[test]
    fn line_of_sight_matches_brute_force_2d((g, s, t) in grid2()) {
        let (si, sj) = g.coords(s);
        let (ti, tj) = g.coords(t);
        let mut want: Vec<usize> = (0..g.len())
            .filter(|&c| {
                let (i, j) = g.coords(c);
                touches([si as i64, sj as i64], [ti as i64, tj as i64], [i as i64, j as i64])
            })
            .collect();
        let mut got = g.touched_cells(s, t);
        got.sort();
        want.sort();
        prop_assert_eq!(&got, &want);
        prop_assert_eq!(g.line_of_sight(s, t), want.iter().all(|&c| !g.blocked()[c]));
        prop_assert_eq!(g.line_of_sight(s, t), g.line_of_sight(t, s));
    }

    #[test]
    fn line_of_sight_matches_brute_force_3d((g, s, t) in grid3()) {
        let (a, b) = (g.coords(s), g.coords(t));
        let want: Vec<usize> = (0..g.len())
            .filter(|&c| {
                let (i, j, k) = g.coords(c);
                touches(
                    [a.0 as i64, a.1 as i64, a.2 as i64],
                    [b.0 as i64, b.1 as i64, b.2 as i64],
                    [i as i64, j as i64, k as i64],
                )
            })
            .collect();
        let mut got = g.touched_cells(s, t);
        got.sort();
        prop_assert_eq!(got, want);
    }
}

/// Brute force: does the closed segment between the centres of cells `a` and
/// `b` meet the closed box of cell `c`? Liang–Barsky in doubled integer
/// coordinates: along each axis the segment is inside the slab
/// `[2c, 2c + 2]` for `t` in an interval; intersect them all (as fractions
/// compared by cross-multiplication).
fn touches<const D: usize>(a: [i64; D], b: [i64; D], c: [i64; D]) -> bool {
    // Interval [lo, hi] as (num, den) with den > 0.
    let (mut lo, mut hi) = ((0i64, 1i64), (1i64, 1i64));
    for k in 0..D {
        let p0 = 2 * a[k] + 1;
        let dp = 2 * (b[k] - a[k]);
        let (s0, s1) = (2 * c[k], 2 * c[k] + 2);
        if dp == 0 {
            if p0 < s0 || p0 > s1 {
                return false;
            }
            continue;
        }
        let (mut t0, mut t1) = ((s0 - p0, dp), (s1 - p0, dp));
        if dp < 0 {
            t0 = (-t0.0, -t0.1);
            t1 = (-t1.0, -t1.1);
            std::mem::swap(&mut t0, &mut t1);
        }
        if t0.0 * lo.1 > lo.0 * t0.1 {
            lo = t0;
        }
        if t1.0 * hi.1 < hi.0 * t1.1 {
            hi = t1;
        }
    }
    lo.0 * hi.1 <= hi.0 * lo.1
}

fn scene_strategy() -> impl Strategy<Value = (Scene, Point, Point)> {
    let circle = (0.5f64..9.5, 0.5f64..9.5, 0.3f64..2.0).prop_map(|(x, y, r)| Circle { centre: [x, y], radius: r });
    let rect = (0.5f64..8.5, 0.5f64..8.5, 0.3f64..2.5, 0.3f64..2.5)
        .prop_map(|(x, y, w, h)| Polygon { vertices: vec![[x, y], [x + w, y], [x + w, y + h], [x, y + h]] });
    (
        proptest::collection::vec(circle, 0..5),
        proptest::collection::vec(rect, 0..3),
        (0.05f64..9.95, 0.05f64..9.95),
        (0.05f64..9.95, 0.05f64..9.95),
    )
        .prop_map(|(circles, polygons, s, t)| {
            let domain = Some(Rect { min: [0.0, 0.0], max: [10.0, 10.0] });
            (Scene { circles, polygons, domain }, [s.0, s.1], [t.0, t.1])
        })
}

const H: f64 = 0.1;
const N: usize = 100;

/// Cells of a 100 x 100 raster of [0, 10]² whose closed box meets an obstacle's
/// interior: a path through the other cells is feasible in the plane.
fn raster(scene: &Scene) -> Grid2 {
    let mut g = Grid2::new(N, N).unwrap();
    for j in 0..N {
        for i in 0..N {
            let (x0, y0) = (i as f64 * H, j as f64 * H);
            let (x1, y1) = (x0 + H, y0 + H);
            let hit_circle = scene.circles.iter().any(|c| {
                let dx = c.centre[0].clamp(x0, x1) - c.centre[0];
                let dy = c.centre[1].clamp(y0, y1) - c.centre[1];
                dx.hypot(dy) < c.radius
            });
            let hit_rect = scene.polygons.iter().any(|p| {
                let (a, b) = (p.vertices[0], p.vertices[2]);
                x0 < b[0] && x1 > a[0] && y0 < b[1] && y1 > a[1]
            });
            g.set_blocked(i, j, hit_circle || hit_rect);
        }
    }
    g
}

fn strictly_inside(scene: &Scene, q: Point, tol: f64) -> bool {
    scene.circles.iter().any(|c| (q[0] - c.centre[0]).hypot(q[1] - c.centre[1]) < c.radius - tol)
        || scene.polygons.iter().any(|p| {
            let (a, b) = (p.vertices[0], p.vertices[2]);
            q[0] > a[0] + tol && q[0] < b[0] - tol && q[1] > a[1] + tol && q[1] < b[1] - tol
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, ..ProptestConfig::default() })]

    #[test]
    fn visibility_paths_are_feasible_and_no_longer_than_a_raster_route((scene, s, t) in scene_strategy()) {
        prop_assume!(!strictly_inside(&scene, s, 0.0) && !strictly_inside(&scene, t, 0.0));
        let exact = visibility::shortest_path(&scene, s, t, 0.1).unwrap();
        let dist = |a: Point, b: Point| (a[0] - b[0]).hypot(a[1] - b[1]);
        if let Some(p) = &exact {
            prop_assert!(p.length >= dist(s, t) - 1e-9);
            // Feasible: dense samples of every piece stay out of every interior and in the domain.
            for piece in &p.pieces {
                for k in 0..=200 {
                    let u = k as f64 / 200.0;
                    let q = match *piece {
                        Piece::Segment { from, to } => [from[0] + u * (to[0] - from[0]), from[1] + u * (to[1] - from[1])],
                        Piece::Arc { centre, radius, start_angle, sweep } => {
                            let a = start_angle + u * sweep;
                            [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
                        }
                    };
                    prop_assert!(!strictly_inside(&scene, q, 1e-7), "{:?} enters an obstacle at {:?}", piece, q);
                    prop_assert!((-1e-7..=10.0 + 1e-7).contains(&q[0]) && (-1e-7..=10.0 + 1e-7).contains(&q[1]));
                }
            }
        }
        // Upper bound: start -> its cell centre -> Theta* on the raster -> goal.
        let g = raster(&scene);
        let cell = |p: Point| g.index(((p[0] / H) as usize).min(N - 1), ((p[1] / H) as usize).min(N - 1));
        let (cs, ct) = (cell(s), cell(t));
        let centre = |c: usize| {
            let (i, j) = g.coords(c);
            [(i as f64 + 0.5) * H, (j as f64 + 0.5) * H]
        };
        prop_assume!(!g.blocked()[cs] && !g.blocked()[ct]);
        let th = theta_star(&g, cs, ct, |a, b, _| Some(H * g.euclidean(a, b)), |c| H * g.euclidean(c, ct), &Limits::none())
            .unwrap();
        if th.found() {
            let bound = dist(s, centre(cs)) + th.cost + dist(centre(ct), t);
            let p = exact.expect("the raster route is a feasible path, so a path exists");
            prop_assert!(p.length <= bound + 1e-9, "exact {} > raster route {}", p.length, bound);
        }
    }
}
