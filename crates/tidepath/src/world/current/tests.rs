use super::*;
use crate::world::grid::RegularGrid2;
use std::f64::consts::FRAC_PI_2;
use std::f64::consts::PI;

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

// ---- Lamb-Oseen -------------------------------------------------------------------------

fn vortex() -> LambOseen {
    LambOseen { x: 3.0, y: 4.0, strength: 2.0, core_radius: 1.2 }
}

#[test]
fn lamb_oseen_speed_at_core_radius() {
    let w = vortex();
    let expected = 2.0 * (1.0 - (-1.0f64).exp()) / (2.0 * PI * 1.2);
    let current = Current::Vortices(vec![w.clone()]);
    // Several directions around the centre: east, north-east-ish, south-west.
    for (dx, dy) in [(1.0, 0.0), (0.6, 0.8), (-0.28, -0.96)] {
        let r = Vec3::new(dx * 1.2, dy * 1.2, 0.0);
        let v = current.velocity(Vec3::new(3.0, 4.0, -7.0) + r, 0.0);
        assert!(close(v.length(), expected, 1e-12), "{v}");
        assert!(close(v.dot(r), 0.0, 1e-12), "not perpendicular: {v}");
        // Counter-clockwise for positive strength: z of (R - R0) x V is positive.
        assert!(r.cross(v).z > 0.0);
        assert_eq!(v.z, 0.0);
    }
    // East of the centre the flow goes due north.
    let v = current.velocity(Vec3::new(4.2, 4.0, 0.0), 0.0);
    assert!(close(v.x, 0.0, 1e-15) && close(v.y, expected, 1e-12));
}

#[test]
fn lamb_oseen_negative_strength_turns_clockwise() {
    let w = LambOseen { strength: -2.0, ..vortex() };
    let v = w.velocity(4.2, 4.0);
    assert!(v.y < 0.0 && close(v.x, 0.0, 1e-15));
}

#[test]
fn lamb_oseen_is_zero_at_centre() {
    let current = Current::Vortices(vec![vortex()]);
    assert_eq!(current.velocity(Vec3::new(3.0, 4.0, 0.0), 0.0), Vec3::ZERO);
    assert_eq!(current.velocity(Vec3::new(3.0 + 1e-7, 4.0, 0.0), 0.0), Vec3::ZERO);
}

#[test]
fn lamb_oseen_far_field_shortcut_is_seamless() {
    // Just inside and just outside r^2/zeta^2 = 50 the speed is eta / (2 pi r) to 1e-15.
    let w = vortex();
    for q in [49.999_999, 50.000_001] {
        let r = 1.2 * f64::sqrt(q);
        let v = w.velocity(3.0 + r, 4.0);
        assert!(close(v.y, 2.0 / (TAU * r), 1e-15), "q = {q}: {}", v.y);
    }
}

#[test]
fn vortices_superpose() {
    let a = vortex();
    let b = LambOseen { x: -1.0, y: 2.5, strength: -0.7, core_radius: 0.5 };
    let both = Current::Vortices(vec![a.clone(), b.clone()]);
    for p in [Vec3::new(0.0, 0.0, 0.0), Vec3::new(2.0, 3.0, -1.0), Vec3::new(-1.3, 2.9, 0.0)] {
        let sum = a.velocity(p.x, p.y) + b.velocity(p.x, p.y);
        let v = both.velocity(p, 5.0);
        assert!(close(v.x, sum.x, 1e-15) && close(v.y, sum.y, 1e-15) && v.z == 0.0);
    }
    // At a's centre only b contributes.
    let v = both.velocity(Vec3::new(3.0, 4.0, 0.0), 0.0);
    assert_eq!(v.truncate(), b.velocity(3.0, 4.0));
}

#[test]
fn vortex_speed_hint_finds_peak_ring() {
    // Core much smaller than the 64 x 64 spacing: the ring samples must catch the peak.
    let w = LambOseen { x: 10.3, y: 20.7, strength: 2.0, core_radius: 0.05 };
    let current = Current::Vortices(vec![w]);
    let bounds = Aabb::new(Vec3::ZERO, Vec3::new(100.0, 100.0, 0.0));
    // Peak of (1 - e^{-q}) / sqrt(q) at q = VORTEX_PEAK_RADIUS^2.
    let q = VORTEX_PEAK_RADIUS * VORTEX_PEAK_RADIUS;
    let exact = 2.0 / (TAU * 0.05) * (1.0 - (-q).exp()) / q.sqrt();
    let hint = current.max_speed_hint(&bounds, 0.0);
    assert!(close(hint, exact, 1e-9 * exact), "{hint} vs {exact}");
}

// ---- None and Uniform -------------------------------------------------------------------

#[test]
fn none_and_uniform() {
    let p = Vec3::new(1.0, 2.0, 3.0);
    let b = Aabb::new(Vec3::ZERO, Vec3::ONE);
    assert_eq!(Current::None.velocity(p, 9.0), Vec3::ZERO);
    assert_eq!(Current::None.max_speed_hint(&b, 0.0), 0.0);
    let u = Current::Uniform(Vec3::new(0.3, -0.4, 0.1));
    assert_eq!(u.velocity(p, 9.0), Vec3::new(0.3, -0.4, 0.1));
    assert!(close(u.max_speed_hint(&b, 0.0), 0.5, 1e-15));
}

// ---- Meandering jet ---------------------------------------------------------------------

fn jet(magnitude: Magnitude) -> MeanderingJet {
    // 10 km x 3 km: 1000 m per jet unit in x, 500 m per jet unit in y.
    MeanderingJet::new(JetConfig::new(0.0, 10_000.0, -1_500.0, 1_500.0, magnitude), "current.jet").unwrap()
}

const JET_POINTS: [(f64, f64, f64); 5] =
    [(0.3, -1.1, 0.0), (2.0, 0.4, 1.7), (4.9, 1.3, 12.5), (7.7, -2.4, 3.3), (9.1, 0.05, 40.0)];

#[test]
fn jet_matches_hand_computed_values() {
    let j = jet(Magnitude::Fixed(1.0));
    // t = 0: a = 1.2 - 0.3 cos(pi/2) = 1.2.
    // x = pi: sin = 0, cos = -1, D = 1; at y = -1.2, s = 0, so (u, v) = (1, 0).
    let (u, v) = j.jet_velocity(PI, -1.2, 0.0);
    assert!(close(u, 1.0, 1e-12) && close(v, 0.0, 1e-12), "{u} {v}");
    // x = pi/2: sin = 1, cos = 0, D = sqrt(1 + (0.84 * 1.2)^2); at y = 0, s = 0:
    // u = 1/D, v = -a kappa / D = -1.2 / D.
    let d = (1.0 + (0.84f64 * 1.2).powi(2)).sqrt();
    let (u, v) = j.jet_velocity(FRAC_PI_2, 0.0, 0.0);
    assert!(close(u, 1.0 / d, 1e-12) && close(v, -1.2 / d, 1e-12), "{u} {v}");
    // World: x = 1000 pi/2 m, y = -1500 + 500 * 3 = 0 m; the chain rule makes the world
    // direction (1000, -600) / |.|, not (1, -1.2) / |.|.
    let w = j.velocity(Vec3::new(1000.0 * FRAC_PI_2, 0.0, -50.0), 0.0);
    let n = 1000.0f64.hypot(600.0);
    assert!(close(w.x, 1000.0 / n, 1e-12) && close(w.y, -600.0 / n, 1e-12) && w.z == 0.0, "{w}");
}

#[test]
fn jet_velocity_matches_stream_function_differences() {
    let j = jet(Magnitude::Fixed(1.0));
    let h = 1e-6;
    for (x, y, t) in JET_POINTS {
        let (u, v) = j.jet_velocity(x, y, t);
        let dxi_dy = (j.stream_function(x, y + h, t) - j.stream_function(x, y - h, t)) / (2.0 * h);
        let dxi_dx = (j.stream_function(x + h, y, t) - j.stream_function(x - h, y, t)) / (2.0 * h);
        assert!(close(u, -dxi_dy, 1e-8), "u at {x} {y} {t}: {u} vs {}", -dxi_dy);
        assert!(close(v, dxi_dx, 1e-8), "v at {x} {y} {t}: {v} vs {dxi_dx}");
    }
}

#[test]
fn jet_is_divergence_free() {
    let j = jet(Magnitude::Fixed(1.0));
    let h = 1e-4;
    for (x, y, t) in JET_POINTS {
        let du_dx = (j.jet_velocity(x + h, y, t).0 - j.jet_velocity(x - h, y, t).0) / (2.0 * h);
        let dv_dy = (j.jet_velocity(x, y + h, t).1 - j.jet_velocity(x, y - h, t).1) / (2.0 * h);
        assert!(close(du_dx + dv_dy, 0.0, 1e-6), "div at {x} {y} {t}: {}", du_dx + dv_dy);
    }
}

#[test]
fn jet_fixed_magnitude_has_that_speed_everywhere() {
    let j = jet(Magnitude::Fixed(0.257));
    for (x, y, t) in JET_POINTS {
        // Jet units to metres, and jet time to seconds.
        let p = Vec3::new(x * 1000.0, -1500.0 + (y + 3.0) * 500.0, 0.0);
        let v = j.velocity(p, t * 2000.0);
        assert!(close(v.length(), 0.257, 1e-12), "{v}");
    }
    // Outside the rectangle the position clamps onto its edge.
    let inside = j.velocity(Vec3::new(10_000.0, 1_500.0, 0.0), 10.0);
    assert_eq!(j.velocity(Vec3::new(25_000.0, 9_000.0, 0.0), 10.0), inside);
}

#[test]
fn jet_scaled_magnitude_peaks_at_requested_speed() {
    let j = jet(Magnitude::Scaled(0.8));
    // The same 200 x 120 grid, in world units, at t = 0.
    let mut peak: f64 = 0.0;
    for jj in 0..120 {
        for ii in 0..200 {
            let p = Vec3::new(10_000.0 * ii as f64 / 199.0, -1500.0 + 3000.0 * jj as f64 / 119.0, 0.0);
            peak = peak.max(j.velocity(p, 0.0).length());
        }
    }
    assert!(close(peak, 0.8, 1e-9), "{peak}");
    // The hint samples other points (some between the 200 x 120 nodes, a little faster),
    // so it only agrees to within sampling error.
    let bounds = Aabb::new(Vec3::new(0.0, -1500.0, -100.0), Vec3::new(10_000.0, 1500.0, 0.0));
    let hint = Current::Jet(j).max_speed_hint(&bounds, 0.0);
    assert!(close(hint, 0.8, 0.01), "{hint}");
}

#[test]
fn jet_time_mapping_uses_seconds_per_unit() {
    let j = jet(Magnitude::Scaled(1.0));
    let p = Vec3::new(3_000.0, 200.0, 0.0);
    let (xj, yj, tj) = j.to_jet(p.x, p.y, 5_000.0);
    assert!(close(xj, 3.0, 1e-12) && close(yj, 0.4, 1e-12) && close(tj, 2.5, 1e-15));
    let (u, v) = j.jet_velocity(xj, yj, tj);
    let w = j.velocity(p, 5_000.0);
    assert!(close(w.x / w.y, (u * 1000.0) / (v * 500.0), 1e-9));
}

#[test]
fn jet_rejects_bad_config() {
    let ok = JetConfig::new(0.0, 1.0, 0.0, 1.0, Magnitude::Fixed(1.0));
    let bad = [
        JetConfig { x_max: 0.0, ..ok },
        JetConfig { jet_y: [3.0, -3.0], ..ok },
        JetConfig { alpha0: f64::NAN, ..ok },
        JetConfig { seconds_per_unit: 0.0, ..ok },
        JetConfig { magnitude: Magnitude::Scaled(-1.0), ..ok },
    ];
    for cfg in bad {
        assert!(MeanderingJet::new(cfg, "j").is_err(), "{cfg:?}");
    }
    let e = MeanderingJet::new(JetConfig { omega0: f64::INFINITY, ..ok }, "current.jet").unwrap_err();
    assert!(e.to_string().starts_with("current.jet.omega0"), "{e}");
}

// ---- Grid -------------------------------------------------------------------------------

fn grid() -> RegularGrid2 {
    // Nodes x = 10, 12, 14; y = 20, 24.
    RegularGrid2::new(10.0, 20.0, 2.0, 4.0, 3, 2, "g").unwrap()
}

fn grid_current() -> CurrentGrid {
    let u0 = vec![1.0, 3.0, 5.0, 2.0, 6.0, 4.0];
    let v0 = vec![0.0, -1.0, -2.0, 1.0, 2.0, 3.0];
    let u1 = u0.iter().map(|x| 3.0 * x).collect();
    let v1 = v0.iter().map(|x| x - 1.0).collect();
    CurrentGrid::new(grid(), vec![100.0, 200.0], vec![u0, u1], vec![v0, v1], "current.grid").unwrap()
}

#[test]
fn grid_reproduces_nodes() {
    let c = Current::Grid(grid_current());
    assert_eq!(c.velocity(Vec3::new(12.0, 24.0, -3.0), 100.0), Vec3::new(6.0, 2.0, 0.0));
    assert_eq!(c.velocity(Vec3::new(14.0, 20.0, 0.0), 200.0), Vec3::new(15.0, -3.0, 0.0));
}

#[test]
fn grid_is_bilinear_at_cell_centre() {
    let c = grid_current();
    // Centre of the first cell: u = mean(1, 3, 2, 6) = 3, v = mean(0, -1, 0 + 1, 2) = 0.5.
    let v = c.velocity(11.0, 22.0, 100.0);
    assert!(close(v.x, 3.0, 1e-12) && close(v.y, 0.5, 1e-12), "{v}");
    // (13, 21), u = 0.5, v = 0.25 in cell (1, 0): u: lo 4, hi 5 -> 4.25;
    // v: lo -1.5, hi 2.5 -> -0.5. Bit-identical to the shared grid interpolation.
    let v = c.velocity(13.0, 21.0, 100.0);
    assert!(close(v.x, 4.25, 1e-12) && close(v.y, -0.5, 1e-12), "{v}");
    assert_eq!(v.x, c.grid.bilinear(&c.u[0], 13.0, 21.0));
}

#[test]
fn grid_is_linear_in_time() {
    let c = grid_current();
    // Halfway: u = (3 + 9) / 2 = 6, v = (0.5 + -0.5) / 2 = 0 at the first cell's centre.
    let v = c.velocity(11.0, 22.0, 150.0);
    assert!(close(v.x, 6.0, 1e-12) && close(v.y, 0.0, 1e-12), "{v}");
    // A quarter of the way at a node: u = 6 + 0.25 (18 - 6) = 9, v = 2 - 0.25 = 1.75.
    let v = c.velocity(12.0, 24.0, 125.0);
    assert!(close(v.x, 9.0, 1e-12) && close(v.y, 1.75, 1e-12), "{v}");
}

#[test]
fn grid_clamps_outside_time_range() {
    let c = grid_current();
    assert_eq!(c.velocity(12.0, 24.0, -1e9), Vec3::new(6.0, 2.0, 0.0));
    assert_eq!(c.velocity(12.0, 24.0, 1e9), Vec3::new(18.0, 1.0, 0.0));
    assert_eq!(c.velocity(12.0, 24.0, f64::NAN), Vec3::new(6.0, 2.0, 0.0));
}

#[test]
fn grid_single_layer_is_steady() {
    let g = grid();
    let c = CurrentGrid::new(g, vec![0.0], vec![vec![1.0; 6]], vec![vec![-2.0; 6]], "c").unwrap();
    for t in [-5.0, 0.0, 7.0] {
        assert_eq!(c.velocity(11.0, 22.0, t), Vec3::new(1.0, -2.0, 0.0));
    }
}

#[test]
fn grid_speed_hint_is_node_maximum() {
    let c = Current::Grid(grid_current());
    let all = Aabb::new(Vec3::new(0.0, 0.0, -1.0), Vec3::new(100.0, 100.0, 0.0));
    // At t = 100 the fastest node is (12, 24): (6, 2).
    assert!(close(c.max_speed_hint(&all, 100.0), 40f64.sqrt(), 1e-12));
    // Halfway, node (12, 24) is (12, 1.5).
    assert!(close(c.max_speed_hint(&all, 150.0), 12f64.hypot(1.5), 1e-12));
    // Only the first cell (nodes x = 10, 12) touches this box: (12, 24) still leads.
    let left = Aabb::new(Vec3::new(10.0, 20.0, 0.0), Vec3::new(11.0, 21.0, 0.0));
    assert!(close(c.max_speed_hint(&left, 100.0), 40f64.sqrt(), 1e-12));
}

#[test]
fn grid_rejects_non_increasing_times() {
    let l = || vec![vec![0.0; 6], vec![0.0; 6]];
    let e = CurrentGrid::new(grid(), vec![1.0, 1.0], l(), l(), "cur").unwrap_err();
    assert!(e.to_string().starts_with("cur.times") && e.to_string().contains("times[1]"), "{e}");
    assert!(CurrentGrid::new(grid(), vec![2.0, 1.0], l(), l(), "cur").is_err());
    assert!(CurrentGrid::new(grid(), vec![0.0, f64::INFINITY], l(), l(), "cur").is_err());
    assert!(CurrentGrid::new(grid(), vec![], vec![], vec![], "cur").is_err());
}

#[test]
fn grid_rejects_wrong_layer_length() {
    let e = CurrentGrid::new(grid(), vec![0.0], vec![vec![0.0; 6]], vec![vec![0.0; 5]], "cur").unwrap_err();
    assert!(e.to_string().starts_with("cur.v") && e.to_string().contains("layer 0 has 5"), "{e}");
    // Layer count must match the times.
    assert!(CurrentGrid::new(grid(), vec![0.0, 1.0], vec![vec![0.0; 6]; 2], vec![vec![0.0; 6]], "cur").is_err());
}

#[test]
fn grid_rejects_nan_values() {
    let mut u = vec![vec![0.0; 6], vec![0.0; 6]];
    u[1][4] = f64::NAN;
    let e = CurrentGrid::new(grid(), vec![0.0, 1.0], u, vec![vec![0.0; 6]; 2], "cur").unwrap_err();
    let msg = e.to_string();
    assert!(msg.starts_with("cur.u") && msg.contains("layer 1, value 4") && msg.contains("NaN"), "{msg}");
}
