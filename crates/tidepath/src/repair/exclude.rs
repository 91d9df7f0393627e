//! amfa2015's excluding operator (section 4.3.1, eq. 9, read as A9 of docs/papers/amfa2015.md):
//! a route point inside an obstacle or the seabed is moved along the outward normal of the
//! local surface onto that surface plus a margin δ.
//!
//! "Inside" is what the validator calls an invalid state: closer than the vehicle's safety
//! distance s to an obstacle or the seabed ([`crate::validity::Validator::state`]). So the point
//! is moved onto the safety envelope plus δ, that is to distance s + δ from the shape (plus
//! 1e-9 of the domain's size, so that rounding never leaves it on the envelope):
//!
//! * sphere: radially from the centre;
//! * box: inside it, through the nearest face (the coordinate of that face set to face ± (s + δ));
//!   outside it but within s, away from its nearest point (a face, edge or corner);
//! * vertical cylinder: inside it, radially in xy, or through the top or bottom cap when that
//!   is nearer (finite caps only); outside but within s, away from its nearest point;
//! * 2-D circle (a full-depth cylinder): radially in xy;
//! * seabed (3-D worlds): the plane ABC of the paper's Fig. 2 is the tangent plane of the
//!   terrain under P, z = h + ∇h · (x − x_P), its gradient ∇h = (h_x, h_y) by central
//!   differences over 1e-3 of the terrain's feature length (0 on a flat seabed). The validator
//!   measures clearance vertically (z − h ≥ s), so P is moved along the plane's normal
//!   n ∝ (−h_x, −h_y, 1) until its vertical clearance above that plane is s + δ:
//!   P' = P + d (−h_x, −h_y, 1) / (1 + |∇h|²), with d = s + δ − (z − h) the vertical deficit
//!   (exact for a planar seabed; the horizontal move is at most d/2). Where the real seabed
//!   curves and P' still lacks clearance, z is then raised to h(x', y') + s + δ.
//!
//! In a 2-D world every move is horizontal (the travel plane keeps its z): a sphere or box is
//! met as its section at the plane, grown by the safety distance, and there is no seabed to
//! exclude from in z (a point in blocked terrain there is left as it is).
//!
//! Moving obstacles are pushed out of where they are at the vehicle's arrival at the point (see
//! the module [`super`]). A push may land the point in another obstacle, the seabed or outside
//! the domain: the point is clamped into the domain and depth band after each push, and the
//! checks repeat, at most [`MAX_PUSHES`] times per point; what is left after that is left to the
//! cost model.

// `!(x > 0.0)` is deliberate: a NaN must count as "nothing to do", never as a push.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::{arrival, clamp_to_domain, default_margin, Repair, MARGIN_RANGE};
use crate::geom::{Vec2, Vec3};
use crate::params::{Checked, Range};
use crate::path::PathModel;
use crate::validity::StateIssue;
use crate::world::{Dims, Shape, Terrain};

/// Most pushes (out of an obstacle, the seabed, or back into the domain) per route point.
pub const MAX_PUSHES: usize = 6;

crate::params! {
    /// Excluding parameters.
    pub struct ExcludeParams {
        /// Exclusion margin δ beyond the safety distance (m); absent: 1 % of the world's
        /// depth range (its z extent), or 0.1 % of its larger horizontal side in a 2-D world.
        margin: Option<f64> = None, MARGIN_RANGE, "amfa2015 eq. 9 (A9: δ chosen)";
        /// Also move out segments that cut an obstacle's or the seabed's envelope between two
        /// clear route points (tidepath's addition; the paper excludes points only).
        segments: bool = true, Range::Flag, "tidepath (docs/papers/amfa2015.md A9)";
    }
}

/// The excluding operator.
#[derive(Clone, Debug)]
pub struct Exclude {
    margin: Option<f64>,
    segments: bool,
}

impl Default for Exclude {
    fn default() -> Self {
        Self { margin: None, segments: true }
    }
}

impl Exclude {
    pub fn new(params: Checked<ExcludeParams>) -> Self {
        let p = params.into_inner();
        Self::with_margin(p.margin, p.segments)
    }

    pub(crate) fn with_margin(margin: Option<f64>, segments: bool) -> Self {
        Self { margin, segments }
    }
}

impl Repair for Exclude {
    fn id(&self) -> &'static str {
        "exclude"
    }

    fn apply(&self, model: &PathModel<'_>, points: &mut [Vec3]) {
        let n = points.len();
        if n < 3 {
            return;
        }
        let margin = self.margin.unwrap_or_else(|| default_margin(model));
        let size = model.world.bounds.size().max_element();
        let slack = if size.is_finite() { 1e-9 * size } else { 0.0 };
        let safety = model.vehicle.safety_distance.max(0.0);
        let reach = safety + margin + slack;
        // Route points first; then segments that cut an envelope between clear points, and
        // the points again (a moved segment may put an end point somewhere new), a few rounds.
        for _ in 0..MAX_SEGMENT_ROUNDS {
            self.points(model, points, reach, safety + margin);
            if !self.segments || !super::segments::push_segments(model, points, reach, safety + margin) {
                return;
            }
        }
        self.points(model, points, reach, safety + margin);
    }
}

/// Rounds of the segment pass (each followed by the point pass) per application.
pub const MAX_SEGMENT_ROUNDS: usize = 3;

impl Exclude {
    /// The point pass: each interior route point within the safety distance of an obstacle or
    /// the seabed is pushed to `reach` from it (see the module docs).
    fn points(&self, model: &PathModel<'_>, points: &mut [Vec3], reach: f64, need: f64) {
        let n = points.len();
        let planar = model.world.dims == Dims::Two;
        let mut t_prev = model.departure_time;
        for i in 1..n - 1 {
            let prev = points[i - 1];
            let hint = (prev + points[i + 1]) * 0.5;
            let mut p = points[i];
            let mut t = arrival(model, i - 1, prev, p, t_prev);
            for _ in 0..MAX_PUSHES {
                let Err(issue) = model.validator.state(p, t) else { break };
                let moved = match issue {
                    StateIssue::OutsideDomain | StateIssue::OutsideDepthBand => p,
                    StateIssue::Seabed { .. } if planar => break,
                    StateIssue::Seabed { .. } => seabed_push(&model.world.terrain, p, reach, need),
                    StateIssue::Obstacle { index, .. } => {
                        let shape = model.world.obstacles[index].shape_at(t);
                        push_out(&shape, p, reach, planar, hint)
                    }
                    StateIssue::NoCurrentData | StateIssue::NoWaveData => break,
                };
                let next = clamp_to_domain(model, moved);
                if next == p {
                    break;
                }
                p = next;
                t = arrival(model, i - 1, prev, p, t_prev);
            }
            points[i] = p;
            t_prev = t;
        }
    }
}

/// `p` moved out of the seabed: along the normal of the terrain's tangent plane under it until
/// its vertical clearance above that plane is `reach`, then raised if the curved seabed still
/// comes within `need` (see the module docs).
pub fn seabed_push(terrain: &Terrain, p: Vec3, reach: f64, need: f64) -> Vec3 {
    let h = terrain.elevation(p.x, p.y);
    let deficit = reach - (p.z - h);
    if !(deficit > 0.0) || !h.is_finite() {
        return p;
    }
    let (hx, hy) = gradient(terrain, p.x, p.y);
    let s = deficit / (1.0 + hx * hx + hy * hy);
    let mut q = Vec3::new(p.x - hx * s, p.y - hy * s, p.z + s);
    let hq = terrain.elevation(q.x, q.y);
    if hq.is_finite() && q.z - hq < need {
        q.z = hq + reach;
    }
    q
}

/// The seabed's elevation gradient at (x, y) by central differences over 1e-3 of the terrain's
/// feature length; (0, 0) on a flat seabed or where it is not finite.
pub fn gradient(terrain: &Terrain, x: f64, y: f64) -> (f64, f64) {
    let Some(e) = terrain.feature_length().map(|f| 1e-3 * f).filter(|e| *e > 0.0 && e.is_finite()) else {
        return (0.0, 0.0);
    };
    let hx = (terrain.elevation(x + e, y) - terrain.elevation(x - e, y)) / (2.0 * e);
    let hy = (terrain.elevation(x, y + e) - terrain.elevation(x, y - e)) / (2.0 * e);
    let finite = |v: f64| if v.is_finite() { v } else { 0.0 };
    (finite(hx), finite(hy))
}

/// `p` moved to distance `reach` from `shape` along the outward normal (see the module docs);
/// horizontally only when `planar`. `hint` (the neighbours' midpoint) gives the direction when
/// the normal is undefined (a point on a sphere's centre or a cylinder's axis), then +x.
pub fn push_out(shape: &Shape, p: Vec3, reach: f64, planar: bool, hint: Vec3) -> Vec3 {
    match *shape {
        Shape::Sphere { center, radius } => {
            if planar {
                let dz = p.z - center.z;
                let r2 = (radius + reach).powi(2) - dz * dz;
                if !(r2 > 0.0) {
                    return p;
                }
                radial_xy(p, center.truncate(), r2.sqrt(), hint)
            } else {
                let dir = unit_or(p - center, unit_or(hint - center, Vec3::X));
                center + dir * (radius + reach)
            }
        }
        Shape::Circle { center, radius } => radial_xy(p, center, radius + reach, hint),
        Shape::Box { min, max } => {
            if planar {
                let dz = excess(p.z, min.z, max.z);
                let r2 = reach * reach - dz * dz;
                if !(r2 > 0.0) {
                    return p;
                }
                rect_push(p, min.truncate(), max.truncate(), r2.sqrt())
            } else {
                let q = p.clamp(min, max);
                if q != p {
                    return q + (p - q).normalize() * reach;
                }
                // Inside: through the nearest face (ties: x before y before z, min before max).
                let depths = [p.x - min.x, max.x - p.x, p.y - min.y, max.y - p.y, p.z - min.z, max.z - p.z];
                let face = nearest(&depths);
                let mut out = p;
                match face {
                    0 => out.x = min.x - reach,
                    1 => out.x = max.x + reach,
                    2 => out.y = min.y - reach,
                    3 => out.y = max.y + reach,
                    4 => out.z = min.z - reach,
                    _ => out.z = max.z + reach,
                }
                out
            }
        }
        Shape::Cylinder { center, radius, z_min, z_max } => {
            let d2 = p.truncate() - center;
            let rho = d2.length();
            if planar {
                let dz = excess(p.z, z_min, z_max);
                let r2 = reach * reach - dz * dz;
                if !(r2 > 0.0) {
                    return p;
                }
                return radial_xy(p, center, radius + r2.sqrt(), hint);
            }
            let qxy = if rho > radius { center + d2 * (radius / rho) } else { p.truncate() };
            let q = Vec3::new(qxy.x, qxy.y, p.z.clamp(z_min, z_max));
            if q != p {
                return q + (p - q).normalize() * reach;
            }
            // Inside: the side or a finite cap, whichever is nearer (ties: the side).
            let depths = [radius - rho, z_max - p.z, p.z - z_min];
            match nearest(&depths) {
                0 => radial_xy(p, center, radius + reach, hint),
                1 => Vec3::new(p.x, p.y, z_max + reach),
                _ => Vec3::new(p.x, p.y, z_min - reach),
            }
        }
    }
}

/// Index of the smallest value (the first on ties; NaN and infinite depths are never chosen
/// over a finite one).
fn nearest(depths: &[f64]) -> usize {
    let mut best = 0;
    for (k, d) in depths.iter().enumerate() {
        if d < &depths[best] || !depths[best].is_finite() && d.is_finite() {
            best = k;
        }
    }
    best
}

/// How far `v` lies outside [lo, hi] (0 inside).
fn excess(v: f64, lo: f64, hi: f64) -> f64 {
    (lo - v).max(v - hi).max(0.0)
}

/// `v` normalized, or `fallback` when it has no direction.
fn unit_or(v: Vec3, fallback: Vec3) -> Vec3 {
    v.try_normalize().unwrap_or(fallback)
}

/// `p` moved horizontally to distance `r` from the vertical axis through `center`, keeping z.
fn radial_xy(p: Vec3, center: Vec2, r: f64, hint: Vec3) -> Vec3 {
    let fallback = (hint.truncate() - center).try_normalize().unwrap_or(Vec2::X);
    let dir = (p.truncate() - center).try_normalize().unwrap_or(fallback);
    let q = center + dir * r;
    Vec3::new(q.x, q.y, p.z)
}

/// `p` moved horizontally to distance `r` from the rectangle [min, max]: through its nearest
/// side from inside, away from its nearest point from outside; z kept.
fn rect_push(p: Vec3, min: Vec2, max: Vec2, r: f64) -> Vec3 {
    let xy = p.truncate();
    let q = xy.clamp(min, max);
    let out = if q != xy {
        q + (xy - q).normalize() * r
    } else {
        let depths = [xy.x - min.x, max.x - xy.x, xy.y - min.y, max.y - xy.y];
        match nearest(&depths) {
            0 => Vec2::new(min.x - r, xy.y),
            1 => Vec2::new(max.x + r, xy.y),
            2 => Vec2::new(xy.x, min.y - r),
            _ => Vec2::new(xy.x, max.y + r),
        }
    };
    Vec3::new(out.x, out.y, p.z)
}
