//! What the profile draws besides paths and seabed: obstacles cut by the vertical curtain under
//! the first path, and the violated segments and waypoints.

use tidepath::geom::Vec3;
use tidepath::world::{Obstacle, Shape};

/// The vertical interval an obstacle fills at horizontal position `p` (z from low to high,
/// clamped to `lo..hi`), `None` where the obstacle is not above or below `p`.
pub(super) fn obstacle_interval(shape: &Shape, p: Vec3, lo: f64, hi: f64) -> Option<(f64, f64)> {
    let (a, b) = match *shape {
        Shape::Sphere { center, radius } => {
            let d2 = (p.truncate() - center.truncate()).length_squared();
            let h = (radius * radius - d2).sqrt();
            (h > 0.0).then_some((center.z - h, center.z + h))?
        }
        Shape::Cylinder { center, radius, z_min, z_max } => {
            ((p.truncate() - center).length() < radius).then_some((z_min, z_max))?
        }
        Shape::Circle { center, radius } => {
            ((p.truncate() - center).length() < radius).then_some((f64::NEG_INFINITY, f64::INFINITY))?
        }
        Shape::Box { min, max } => {
            (p.x > min.x && p.x < max.x && p.y > min.y && p.y < max.y).then_some((min.z, max.z))?
        }
    };
    let (a, b) = (a.max(lo), b.min(hi));
    (b > a).then_some((a, b))
}

/// Polygons (distance, z) of `o` cut by the curtain through `samples`, each sample being
/// (distance along the path, point, time): one polygon per stretch of consecutive samples
/// inside the obstacle.
pub(super) fn obstacle_sections(o: &Obstacle, samples: &[(f64, Vec3, f64)], lo: f64, hi: f64) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut run: Vec<(f64, f64, f64)> = Vec::new();
    let mut flush = |run: &mut Vec<(f64, f64, f64)>| {
        if !run.is_empty() {
            let mut poly: Vec<(f64, f64)> = run.iter().map(|&(s, _, top)| (s, top)).collect();
            poly.extend(run.iter().rev().map(|&(s, bottom, _)| (s, bottom)));
            out.push(poly);
            run.clear();
        }
    };
    for &(s, p, t) in samples {
        match obstacle_interval(&o.shape_at(t), p, lo, hi) {
            Some((a, b)) => run.push((s, a, b)),
            None => flush(&mut run),
        }
    }
    flush(&mut run);
    out
}

/// Points every `ds` metres along `points` (and at each of them) with their distance along
/// the path and time (interpolated from `times` when it matches the points, else `t0`).
pub(super) fn samples(points: &[Vec3], dist: &[f64], times: &[f64], t0: f64, ds: f64) -> Vec<(f64, Vec3, f64)> {
    let timed = times.len() == points.len();
    let mut out = Vec::new();
    for k in 0..points.len() {
        let t_at =
            |f: f64| if timed { times[k] + f * (times.get(k + 1).copied().unwrap_or(times[k]) - times[k]) } else { t0 };
        if k + 1 == points.len() || dist[k + 1].partial_cmp(&dist[k]) != Some(std::cmp::Ordering::Greater) {
            out.push((dist[k], points[k], t_at(0.0)));
            continue;
        }
        let n = ((dist[k + 1] - dist[k]) / ds).ceil().clamp(1.0, 10_000.0) as usize;
        for m in 0..n {
            let f = m as f64 / n as f64;
            out.push((dist[k] + f * (dist[k + 1] - dist[k]), points[k].lerp(points[k + 1], f), t_at(f)));
        }
    }
    out.retain(|(s, p, t)| s.is_finite() && p.is_finite() && !t.is_nan());
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use tidepath::geom::Vec2;

    #[test]
    fn a_sphere_cut_through_its_centre_is_a_disc() {
        let o = Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 0.0, -100.0), radius: 30.0 });
        let pts = [Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 0.0, -100.0)];
        let s = samples(&pts, &[0.0, 100.0], &[], 0.0, 10.0);
        let polys = obstacle_sections(&o, &s, -1000.0, 0.0);
        assert_eq!(polys.len(), 1);
        // Samples at 30, 40, ..., 70 m: at 50 m the full diameter, at 40 m sqrt(900 - 100).
        let top: Vec<(f64, f64)> = polys[0][..5].to_vec();
        assert_eq!(top[2], (50.0, -70.0));
        assert!((top[1].1 - (-100.0 + 800f64.sqrt())).abs() < 1e-9, "{top:?}");
        // A full-depth circle fills the axis range; a box off the curtain is not there.
        let c = Obstacle::fixed(Shape::Circle { center: Vec2::new(50.0, 0.0), radius: 5.0 });
        assert_eq!(obstacle_sections(&c, &s, -1000.0, 0.0), vec![vec![(50.0, 0.0), (50.0, -1000.0)]]);
        let b = Obstacle::fixed(Shape::Box { min: Vec3::new(0.0, 10.0, -50.0), max: Vec3::new(100.0, 20.0, 0.0) });
        assert!(obstacle_sections(&b, &s, -1000.0, 0.0).is_empty());
    }
}
