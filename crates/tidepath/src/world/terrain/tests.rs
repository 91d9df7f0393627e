use super::*;
use crate::world::grid::RegularGrid2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn one_peak(ceiling: Option<f64>) -> Terrain {
    Terrain::Peaks(GaussianPeaks {
        base: -100.0,
        peaks: vec![Peak { x: 10.0, y: 20.0, height: 40.0, sigma_x: 2.0, sigma_y: 5.0 }],
        ceiling,
    })
}

#[test]
fn peak_elevation_at_centre_and_one_sigma() {
    let t = one_peak(None);
    assert_eq!(t.elevation(10.0, 20.0), -60.0);
    // One sigma east: -100 + 40 / e.
    let e1 = -100.0 + 40.0 * (-1.0f64).exp();
    assert!((t.elevation(12.0, 20.0) - e1).abs() < 1e-12);
    // One sigma in both directions: -100 + 40 / e^2.
    let e2 = -100.0 + 40.0 * (-2.0f64).exp();
    assert!((t.elevation(8.0, 25.0) - e2).abs() < 1e-12);
    // Far away: the base.
    assert!((t.elevation(1e4, 20.0) + 100.0).abs() < 1e-12);
}

#[test]
fn ceiling_caps_elevation_and_bound() {
    let t = one_peak(Some(-70.0));
    assert_eq!(t.elevation(10.0, 20.0), -70.0);
    assert_eq!(t.max_elevation_in(0.0, 0.0, 50.0, 50.0), -70.0);
    // Below the cap the peak is untouched: at 2 sigma_x, -100 + 40 e^-4 < -70.
    let v = -100.0 + 40.0 * (-4.0f64).exp();
    assert!((t.elevation(14.0, 20.0) - v).abs() < 1e-12);
}

#[test]
fn paper_k_parametrisation_sets_width_from_centre() {
    // x_j = 10, k_x = 5 -> sigma_x = 2; y_j = 20, k_y = 4 -> sigma_y = 5.
    let p = Peak::from_paper_k(10.0, 20.0, 40.0, 5.0, 4.0, "t").unwrap();
    assert_eq!((p.sigma_x, p.sigma_y), (2.0, 5.0));
    let g = GaussianPeaks::from_paper_k(1.0, &[[10.0, 20.0, 40.0, 5.0, 4.0]], Some(30.0), "t").unwrap();
    assert_eq!(g.peaks[0], p);
    assert_eq!(g.ceiling, Some(30.0));
    assert!(Peak::from_paper_k(-1.0, 20.0, 1.0, 1.0, 1.0, "t").is_err());
    assert!(Peak::from_paper_k(1.0, 20.0, 1.0, 0.0, 1.0, "t").is_err());
    let err = GaussianPeaks::from_paper_k(0.0, &[[1.0, 1.0, 1.0, 1.0, 1.0], [0.0, 1.0, 1.0, 1.0, 1.0]], None, "t")
        .unwrap_err()
        .to_string();
    assert!(err.contains("t.peaks[1]"), "{err}");
}

#[test]
fn seabed_eq11_matches_paper_formula() {
    let (x0, y0, h, a, b, s) = (3.0, 4.0, 7.0, 0.8, 1.3, 2.0);
    let p = Peak::from_seabed_eq11(x0, y0, h, a, b, s, "t").unwrap();
    let t = Terrain::Peaks(GaussianPeaks { base: 0.0, peaks: vec![p], ceiling: None });
    let (x, y): (f64, f64) = (4.1, 2.5);
    let want = h * (-((y - y0).powi(2) * a * a + (x - x0).powi(2) * b * b) / (2.0 * s * s)).exp();
    assert!((t.elevation(x, y) - want).abs() < 1e-12);
}

fn small_grid() -> Terrain {
    // Nodes: (10,20)=1 (12,20)=3 (14,20)=5 ; (10,24)=2 (12,24)=6 (14,24)=4
    let g = RegularGrid2::new(10.0, 20.0, 2.0, 4.0, 3, 2, "g").unwrap();
    Terrain::Grid(ElevationGrid::new(g, vec![1.0, 3.0, 5.0, 2.0, 6.0, 4.0], "g").unwrap())
}

#[test]
fn grid_elevation_is_bilinear() {
    let t = small_grid();
    assert_eq!(t.elevation(12.0, 24.0), 6.0);
    assert!((t.elevation(11.0, 22.0) - 3.0).abs() < 1e-12);
    assert!((t.elevation(13.0, 21.0) - 4.25).abs() < 1e-12);
    // Outside: clamped to the edge.
    assert_eq!(t.elevation(-5.0, 100.0), 2.0);
}

#[test]
fn grid_bound_is_exact_on_small_rectangles_and_clamps_outside() {
    let t = small_grid();
    let tol = 1e-12;
    // Whole grid: the highest node.
    assert!((t.max_elevation_in(0.0, 0.0, 100.0, 100.0) - 6.0).abs() < tol);
    // First cell, lower half (v in [0, 0.5]): corners 1, 3, 1.5, 4.5 -> 4.5.
    assert!((t.max_elevation_in(10.0, 20.0, 12.0, 22.0) - 4.5).abs() < tol);
    // A point: its own value.
    assert!((t.max_elevation_in(13.0, 21.0, 13.0, 21.0) - 4.25).abs() < tol);
    // Entirely west of the grid: the west edge, nodes 1 and 2.
    assert!((t.max_elevation_in(-50.0, 0.0, -40.0, 100.0) - 2.0).abs() < tol);
}

#[test]
fn grid_rejects_bad_values() {
    let g = RegularGrid2::new(0.0, 0.0, 1.0, 1.0, 2, 2, "g").unwrap();
    let err = ElevationGrid::new(g.clone(), vec![0.0; 3], "terrain").unwrap_err().to_string();
    assert!(err.contains("terrain.elevations") && err.contains('3'), "{err}");
    let err = ElevationGrid::new(g, vec![0.0, 1.0, f64::NAN, 2.0], "terrain").unwrap_err().to_string();
    assert!(err.contains("terrain.elevations") && err.contains("value 2") && err.contains("NaN"), "{err}");
}

/// Dense sampling of the rectangle (including its corners and edges) must never find a point
/// above the bound.
fn check_bound_against_samples(t: &Terrain, rng: &mut ChaCha8Rng, lo: (f64, f64), hi: (f64, f64)) {
    for _ in 0..300 {
        let (xa, xb) = (rng.random_range(lo.0..hi.0), rng.random_range(lo.0..hi.0));
        let (ya, yb) = (rng.random_range(lo.1..hi.1), rng.random_range(lo.1..hi.1));
        // Mix large and tiny rectangles.
        let shrink = if rng.random_bool(0.3) { 1e-3 } else { 1.0 };
        let (x0, x1) = (xa.min(xb), xa.min(xb) + (xa - xb).abs() * shrink);
        let (y0, y1) = (ya.min(yb), ya.min(yb) + (ya - yb).abs() * shrink);
        let bound = t.max_elevation_in(x0, y0, x1, y1);
        let n = 40;
        let mut sampled = f64::NEG_INFINITY;
        for i in 0..=n {
            for j in 0..=n {
                let x = x0 + (x1 - x0) * i as f64 / n as f64;
                let y = y0 + (y1 - y0) * j as f64 / n as f64;
                sampled = sampled.max(t.elevation(x.min(x1), y.min(y1)));
            }
        }
        assert!(bound >= sampled, "bound {bound} < sampled {sampled} on [{x0}, {x1}] x [{y0}, {y1}]");
    }
}

#[test]
fn peak_bound_never_below_dense_samples() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for _ in 0..20 {
        let peaks = (0..rng.random_range(1..6))
            .map(|_| Peak {
                x: rng.random_range(0.0..100.0),
                y: rng.random_range(0.0..100.0),
                height: rng.random_range(-40.0..40.0),
                sigma_x: rng.random_range(2.0..20.0),
                sigma_y: rng.random_range(2.0..20.0),
            })
            .collect();
        let ceiling = rng.random_bool(0.3).then(|| rng.random_range(-60.0..-20.0));
        let t = Terrain::Peaks(GaussianPeaks { base: -50.0, peaks, ceiling });
        check_bound_against_samples(&t, &mut rng, (-20.0, -20.0), (120.0, 120.0));
    }
}

#[test]
fn grid_bound_never_below_dense_samples() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..20 {
        let (nx, ny) = (rng.random_range(2..40), rng.random_range(2..40));
        let g =
            RegularGrid2::new(-5.0, 3.0, rng.random_range(0.5..5.0), rng.random_range(0.5..5.0), nx, ny, "g").unwrap();
        let z = (0..nx * ny).map(|_| rng.random_range(-100.0..-10.0)).collect();
        let (xm, ym) = (g.x_max(), g.y_max());
        let t = Terrain::Grid(ElevationGrid::new(g, z, "g").unwrap());
        check_bound_against_samples(&t, &mut rng, (-20.0, -10.0), (xm + 10.0, ym + 10.0));
    }
}

/// The least of z - h over n + 1 evenly spaced points of a -> b.
fn sampled_min_clearance(t: &Terrain, a: Vec3, b: Vec3, n: usize) -> f64 {
    (0..=n)
        .map(|k| {
            let p = a + (b - a) * (k as f64 / n as f64);
            p.z - t.elevation(p.x, p.y)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn grid_exact_min_clearance_matches_dense_sampling() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let g = RegularGrid2::new(0.0, 0.0, 2.0, 3.0, 6, 5, "g").unwrap();
    let z: Vec<f64> = (0..30).map(|_| rng.random_range(-50.0..-10.0)).collect();
    let t = Terrain::Grid(ElevationGrid::new(g, z, "g").unwrap());
    let mut settled = 0;
    for _ in 0..500 {
        // Short segments (some leaving the grid) so that many fit in 2 x 2 cells.
        let a = Vec3::new(rng.random_range(-2.0..12.0), rng.random_range(-2.0..14.0), rng.random_range(-40.0..0.0));
        let b = a + Vec3::new(rng.random_range(-3.0..3.0), rng.random_range(-4.0..4.0), rng.random_range(-5.0..5.0));
        let Some(m) = t.exact_min_clearance(a, b, 0.0, 1.0) else { continue };
        settled += 1;
        let n = 4000;
        let sampled = sampled_min_clearance(&t, a, b, n);
        // Exact minimum: never above a sample, and samples 1/4000 apart come within the
        // clearance's change over half a step.
        let step = (b - a).length() * (1.0 + 20.0) / n as f64;
        assert!(m <= sampled + 1e-12 && m >= sampled - step, "exact {m} vs sampled {sampled}");
    }
    assert!(settled > 100, "only {settled} segments settled exactly");
}

#[test]
fn bounds_shrink_to_the_point_value() {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let t = one_peak(None);
    let g = RegularGrid2::new(0.0, 0.0, 1.0, 1.0, 5, 5, "g").unwrap();
    let grid = Terrain::Grid(ElevationGrid::new(g, (0..25).map(|k| (k * 7 % 11) as f64).collect(), "g").unwrap());
    for t in [&t, &grid] {
        for _ in 0..100 {
            let (x, y) = (rng.random_range(0.0..4.0), rng.random_range(0.0..4.0));
            let h = 1e-7;
            let gap = t.max_elevation_in(x, y, x + h, y + h) - t.elevation(x, y);
            assert!((0.0..1e-5).contains(&gap), "gap {gap} at ({x}, {y})");
        }
    }
}

#[test]
fn no_terrain_is_minus_infinity() {
    assert_eq!(Terrain::None.elevation(1.0, 2.0), f64::NEG_INFINITY);
    assert_eq!(Terrain::None.max_elevation_in(0.0, 0.0, 1.0, 1.0), f64::NEG_INFINITY);
}

/// A 4 x 3 map, cells 10 m x 20 m from (100, 200): land (+5) at cells (1, 1) and (2, 1),
/// water at -30 elsewhere, except cell (3, 0) at -12.
fn cell_map() -> Terrain {
    let mut z = vec![-30.0; 12];
    z[4 + 1] = 5.0;
    z[4 + 2] = 5.0;
    z[3] = -12.0;
    Terrain::Cells(CellGrid::new([100.0, 200.0], [10.0, 20.0], [4, 3], z, "cells").unwrap())
}

#[test]
fn cells_are_constant_inside_and_take_the_lowest_value_on_edges() {
    let t = cell_map();
    assert_eq!(t.elevation(115.0, 230.0), 5.0); // inside cell (1, 1)
    assert_eq!(t.elevation(105.0, 230.0), -30.0); // cell (0, 1)
    assert_eq!(t.elevation(110.0, 230.0), -30.0); // on the edge between them
    assert_eq!(t.elevation(120.0, 230.0), 5.0); // between two land cells
    assert_eq!(t.elevation(120.0, 240.0), -30.0); // on the corner of land and water
    assert_eq!(t.elevation(135.0, 210.0), -12.0);
    assert_eq!(t.elevation(0.0, 0.0), -30.0); // beyond the grid the edge cells hold
    assert_eq!(t.elevation(1e6, 210.0), -12.0);
    // Rectangles: exactly the cells whose inside they meet (max) or whose closure (min).
    assert_eq!(t.max_elevation_in(100.0, 200.0, 110.0, 260.0), -30.0); // column 0, edges included
    assert_eq!(t.max_elevation_in(100.0, 200.0, 110.1, 260.0), 5.0);
    assert_eq!(t.max_elevation_in(111.0, 221.0, 111.0, 221.0), 5.0); // a point
    assert_eq!(t.min_elevation_in(111.0, 221.0, 129.0, 239.0), 5.0); // inside the land
    assert_eq!(t.min_elevation_in(110.0, 221.0, 129.0, 239.0), -30.0); // touches water
    assert_eq!(t.max_elevation_in(130.0, 200.0, 140.0, 220.0), -12.0);
    assert_eq!(t.feature_length(), Some(10.0));
    let e = CellGrid::new([0.0, 0.0], [1.0, 1.0], [2, 2], vec![0.0; 3], "world.terrain").unwrap_err().to_string();
    assert!(e.contains("world.terrain") && e.contains("need 4 values, got 3"), "{e}");
    let e = CellGrid::new([0.0, 0.0], [0.0, 1.0], [1, 1], vec![0.0], "world.terrain").unwrap_err().to_string();
    assert!(e.contains("cell_size"), "{e}");
}

#[test]
fn cells_clearance_along_segments_is_exact() {
    let t = cell_map();
    let hit = |a: Vec3, b: Vec3| t.exact_min_clearance(a, b, 0.0, 1.0).unwrap();
    // Along the southern edge of the land (y = 220) at -1 m: 29 m above the water, not in land.
    assert_eq!(hit(Vec3::new(100.0, 220.0, -1.0), Vec3::new(140.0, 220.0, -1.0)), 29.0);
    // Across the land at -1 m: 6 m below its top.
    assert_eq!(hit(Vec3::new(100.0, 230.0, -1.0), Vec3::new(140.0, 230.0, -1.0)), -6.0);
    // Descending from cell (2, 0) at -30 into (3, 0) at -12: 20 m at the edge x = 130 (z = -10),
    // then -7 m at the end (z = -19).
    let m = hit(Vec3::new(125.0, 210.0, -5.0), Vec3::new(139.0, 210.0, -19.0));
    assert!((m - -7.0).abs() < 1e-12, "{m}");
    // Diagonals: through cell (1, 1) is a hit; through the corner (110, 220) of land (1, 1),
    // from water (0, 1) to water (1, 0), only touches it.
    assert_eq!(hit(Vec3::new(110.0, 240.0, -1.0), Vec3::new(130.0, 200.0, -1.0)), -6.0);
    assert_eq!(hit(Vec3::new(100.0, 240.0, -1.0), Vec3::new(120.0, 200.0, -1.0)), 29.0);
    // Dense sampling never finds less than the exact minimum, and (unless a cell is only
    // clipped between two samples) comes within the change of z over a step.
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut close = 0;
    for _ in 0..400 {
        let a = Vec3::new(rng.random_range(90.0..150.0), rng.random_range(190.0..270.0), rng.random_range(-30.0..0.0));
        let b = Vec3::new(rng.random_range(90.0..150.0), rng.random_range(190.0..270.0), rng.random_range(-30.0..0.0));
        let m = hit(a, b);
        let n = 20_000;
        let sampled = sampled_min_clearance(&t, a, b, n);
        assert!(m <= sampled + 1e-9, "exact {m} above sampled {sampled} for {a} -> {b}");
        if sampled - m <= (b.z - a.z).abs() * 2.0 / n as f64 + 1e-9 {
            close += 1;
        }
    }
    assert!(close >= 380, "only {close} of 400 agree with sampling");
}

#[test]
fn cells_take_reversed_and_nan_rectangles_without_panic() {
    let t = cell_map();
    assert_eq!(t.max_elevation_in(129.0, 239.0, 111.0, 221.0), 5.0);
    assert_eq!(t.min_elevation_in(129.0, 239.0, 110.0, 221.0), -30.0);
    for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let _ = t.max_elevation_in(v, 0.0, 1.0, v);
        let _ = t.min_elevation_in(0.0, v, v, 1.0);
        let _ = t.elevation(v, v);
        let _ = t.exact_min_clearance(Vec3::new(v, 0.0, -1.0), Vec3::new(1.0, v, -1.0), 0.0, 1.0);
    }
}

/// The exp-free bound of peaks is never below `max_elevation_in` as computed (rectangles from
/// points to the whole field, near and far, bumps and dips, with and without a ceiling), and
/// at most 1.15 % of a bump's height above it; other terrains have none.
#[test]
fn the_peaks_upper_bound_is_never_below_the_exact_one() {
    let mut rng = ChaCha8Rng::seed_from_u64(23);
    let mut checked = 0;
    for case in 0..60 {
        let peaks = (0..rng.random_range(1..7))
            .map(|_| Peak {
                x: rng.random_range(0.0..1000.0),
                y: rng.random_range(0.0..1000.0),
                height: if case % 3 == 0 { rng.random_range(-400.0..400.0) } else { rng.random_range(0.0..6000.0) },
                sigma_x: rng.random_range(5.0..400.0),
                sigma_y: rng.random_range(5.0..400.0),
            })
            .collect();
        let ceiling = (case % 4 == 1).then(|| rng.random_range(-300.0..0.0));
        let t = Terrain::Peaks(GaussianPeaks { base: -6200.0, peaks, ceiling });
        for _ in 0..2000 {
            let (x0, y0) = (rng.random_range(-3000.0..4000.0), rng.random_range(-3000.0..4000.0));
            let size = match rng.random_range(0..4) {
                0 => 0.0,
                1 => rng.random_range(0.0..1.0),
                2 => rng.random_range(0.0..100.0),
                _ => rng.random_range(0.0..5000.0),
            };
            let (x1, y1) = (x0 + size * rng.random_range(0.0..1.0), y0 + size * rng.random_range(0.0..1.0));
            let exact = t.max_elevation_in(x0, y0, x1, y1);
            let upper = t.max_elevation_upper(x0, y0, x1, y1).unwrap();
            assert!(upper >= exact, "{upper} < {exact} on [{x0}, {x1}] x [{y0}, {y1}], {t:?}");
            checked += 1;
        }
    }
    assert_eq!(checked, 120_000);
    // One 6000 m bump: at most 1.15 % of its height above (the worst, near e = 3.3), 0.05 m
    // at e = 40; at its summit exactly 1 + 1e-9 times the height.
    let t = Terrain::Peaks(GaussianPeaks {
        base: -6000.0,
        peaks: vec![Peak { x: 0.0, y: 0.0, height: 6000.0, sigma_x: 100.0, sigma_y: 100.0 }],
        ceiling: None,
    });
    let gap =
        |x: f64| t.max_elevation_upper(x, 0.0, x + 10.0, 10.0).unwrap() - t.max_elevation_in(x, 0.0, x + 10.0, 10.0);
    for k in 0..=800 {
        let g = gap(k as f64);
        assert!((0.0..0.0115 * 6000.0).contains(&g), "{k}: {g}");
    }
    assert!((0.0..0.06).contains(&gap(100.0 * 40f64.sqrt())));
    assert_eq!(t.max_elevation_upper(-1.0, -1.0, 1.0, 1.0).unwrap(), -6000.0 + 6000.0 * (1.0 + 1e-9));
    // No bound where max_in could meet a NaN.
    let t = Terrain::Peaks(GaussianPeaks {
        base: -100.0,
        peaks: vec![Peak { x: 0.0, y: 0.0, height: f64::NAN, sigma_x: 1.0, sigma_y: 1.0 }],
        ceiling: None,
    });
    assert!(t.max_elevation_upper(0.0, 0.0, 1.0, 1.0).unwrap().is_nan());
    assert_eq!(small_grid().max_elevation_upper(0.0, 0.0, 1.0, 1.0), None);
}
