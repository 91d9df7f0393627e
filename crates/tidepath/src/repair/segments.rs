//! The excluding operator's second half (tidepath's addition to amfa2015's eq. 9, A9 of
//! docs/papers/amfa2015.md): a segment whose two route points are clear but which itself cuts
//! an obstacle's or the seabed's safety envelope (a chord across a curved obstacle) is moved
//! out as a whole. Its deepest point q is found (exactly for spheres, cylinders and circles,
//! by 256 samples for boxes and the seabed), q's exclusion Δ (the same push as a route point's)
//! is computed, and the segment is translated by Δ: both interior end points move by Δ; when
//! one end is the fixed start or goal, the other moves by Δ/u (u the fraction of q's distance
//! from that fixed end, at least 1/4), so q itself moves by Δ. The paper's point-counted risk
//! (eq. 8) cannot see such a chord when it dips between its evaluation points, so without this
//! step a planner minimising it ends with segments a few centimetres inside the envelope.

use super::clamp_to_domain;
use super::exclude::{push_out, seabed_push};
use crate::geom::Vec3;
use crate::path::PathModel;
use crate::validity::MotionIssue;
use crate::world::{Dims, Shape};

/// Samples along a segment where its deepest point has no closed form (boxes, the seabed).
const SAMPLES: usize = 256;

/// Moves every segment of `points` that cuts an envelope out by its deepest point's push
/// (`reach` from the surface, `need` the clearance the seabed push checks). True when a point
/// moved.
pub(super) fn push_segments(model: &PathModel<'_>, points: &mut [Vec3], reach: f64, need: f64) -> bool {
    let n = points.len();
    let mut moved = false;
    let mut t = model.departure_time;
    for i in 0..n.saturating_sub(1) {
        let (a, b) = (points[i], points[i + 1]);
        let check = model.validator.motion_at(a, b, t, model.segment_speed(i));
        if let Some((u, delta)) =
            check.first.and_then(|issue| deepest_push(model, a, b, (t, check.arrival), issue, reach, need))
        {
            let (head, tail) = (i >= 1, i + 2 < n);
            let shift = |p: Vec3, by: Vec3| clamp_to_domain(model, p + by);
            match (head, tail) {
                (true, true) => {
                    points[i] = shift(a, delta);
                    points[i + 1] = shift(b, delta);
                }
                (false, true) => points[i + 1] = shift(b, delta / u.max(0.25)),
                (true, false) => points[i] = shift(a, delta / (1.0 - u).max(0.25)),
                (false, false) => {}
            }
            moved |= head || tail;
        }
        t += model.segment_time(i, points[i], points[i + 1], t).0;
    }
    moved
}

/// The fraction u of the segment a -> b at its deepest point in the envelope of `issue`, and
/// the push that takes that point to `reach` from the surface. `None` for issues no push fixes
/// (the current).
fn deepest_push(
    model: &PathModel<'_>,
    a: Vec3,
    b: Vec3,
    (t0, t1): (f64, f64),
    issue: MotionIssue,
    reach: f64,
    need: f64,
) -> Option<(f64, Vec3)> {
    let planar = model.world.dims == Dims::Two;
    let at = |u: f64| a + (b - a) * u;
    match issue {
        MotionIssue::Obstacle(k) => {
            let shape = model.world.obstacles.get(k)?.shape_at(0.5 * (t0 + t1));
            if let (Shape::Box { min, max }, false) = (&shape, planar) {
                return box_push(*min, *max, a, b, reach);
            }
            let u = deepest_fraction(&shape, a, b, planar);
            let q = at(u);
            let hint = q + (b - a).cross(Vec3::Z);
            Some((u, push_out(&shape, q, reach, planar, hint) - q))
        }
        MotionIssue::Terrain if !planar => {
            let terrain = &model.world.terrain;
            let clearance = |u: f64| {
                let q = at(u);
                q.z - terrain.elevation(q.x, q.y)
            };
            let u = (1..SAMPLES)
                .map(|j| j as f64 / SAMPLES as f64)
                .min_by(|&x, &y| clearance(x).total_cmp(&clearance(y)))?;
            let q = at(u);
            Some((u, seabed_push(terrain, q, reach, need) - q))
        }
        _ => None,
    }
}

/// A segment through or beside a box (3-D): its sample deepest inside the box (or nearest to
/// it), pushed through the nearest face across the segment's direction (a push along the
/// segment would only slide it), to `reach` beyond that face.
fn box_push(min: Vec3, max: Vec3, a: Vec3, b: Vec3, reach: f64) -> Option<(f64, Vec3)> {
    let dir = (b - a).try_normalize()?;
    // Depth inside the box (negative: distance outside it).
    let depth = |q: Vec3| {
        let c = q.clamp(min, max);
        if c == q {
            (q - min).min(max - q).min_element()
        } else {
            -q.distance(c)
        }
    };
    let at = |u: f64| a + (b - a) * u;
    let u = (0..=SAMPLES).map(|j| j as f64 / SAMPLES as f64).max_by(|&x, &y| depth(at(x)).total_cmp(&depth(at(y))))?;
    let q = at(u);
    // Faces across the segment: normals at least 45 degrees off its direction.
    let faces = [
        (Vec3::NEG_X, q.x - min.x),
        (Vec3::X, max.x - q.x),
        (Vec3::NEG_Y, q.y - min.y),
        (Vec3::Y, max.y - q.y),
        (Vec3::NEG_Z, q.z - min.z),
        (Vec3::Z, max.z - q.z),
    ];
    let (normal, to_face) = faces
        .into_iter()
        .filter(|(n, _)| n.dot(dir).abs() < std::f64::consts::FRAC_1_SQRT_2)
        .min_by(|x, y| x.1.total_cmp(&y.1))?;
    // Beyond the face by `reach` (from outside the face, the same: to_face is negative).
    Some((u, normal * (to_face + reach)))
}

/// The fraction of a -> b closest to `shape`: to a sphere's centre (in xy for the section of a
/// planar world), to a cylinder's or circle's axis in xy, to a box by samples.
fn deepest_fraction(shape: &Shape, a: Vec3, b: Vec3, planar: bool) -> f64 {
    let closest = |c: Vec3, d: Vec3| {
        let len2 = d.length_squared();
        if len2 > 0.0 {
            ((c - a).dot(d) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        }
    };
    let flat = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
    match *shape {
        Shape::Sphere { center, .. } if planar => closest(flat(center) + Vec3::new(0.0, 0.0, a.z), flat(b - a)),
        Shape::Sphere { center, .. } => closest(center, b - a),
        Shape::Cylinder { center, .. } | Shape::Circle { center, .. } => {
            let c = Vec3::new(center.x, center.y, a.z);
            closest(c, flat(b - a))
        }
        Shape::Box { min, max } => {
            let gap = |u: f64| {
                let q = a + (b - a) * u;
                let q = if planar { Vec3::new(q.x, q.y, q.z.clamp(min.z, max.z)) } else { q };
                q.distance(q.clamp(min, max)) - if q.cmpge(min).all() && q.cmple(max).all() { 1.0 } else { 0.0 }
            };
            (0..=SAMPLES).map(|j| j as f64 / SAMPLES as f64).min_by(|&x, &y| gap(x).total_cmp(&gap(y))).unwrap_or(0.5)
        }
    }
}
