//! The fillet model: the curve a vehicle with turning radius r flies along a polyline.
//!
//! At each interior waypoint the horizontal heading turns by theta. The vehicle starts the
//! turn `r tan(theta/2)` before the waypoint and ends it as far after it, on a circular arc of
//! radius r tangent to both legs; between turns it flies the legs straight. A leg is shared by
//! the turns at its two ends: when their demands together exceed its horizontal length, each
//! turn gets a share of the leg in proportion to its demand, and flies the smaller radius that
//! share allows. Such a turn does not fit: the evaluation reports it, naming the waypoint and
//! the radius its legs allow.
//!
//! Heights: along a leg's straight part z changes linearly, as on the polyline; on a fillet it
//! changes linearly with the turned angle, from the height of the polyline at the first tangent
//! point to its height at the second.
//!
//! Legs without horizontal extent (vertical moves, repeated points) have no heading: a turn
//! next to one has no room (radius 0) unless the headings on either side agree.
//!
//! The flown curve never leaves the convex hull of the waypoints, so a polyline inside the
//! domain box and depth band flies inside them.

use crate::geom::{Vec2, Vec3};

/// Legs shorter than this fraction of the radius count as without horizontal extent: their
/// heading is rounding noise.
const DEGENERATE: f64 = 1e-9;

/// Heading changes below this (rad) are rounding noise at collinear waypoints (the tangent
/// points a tangent polygon marks), not turns.
const NO_TURN: f64 = 1e-9;

/// Relative slack on "the fillet fits", for tangent polygons whose legs are exactly used up.
pub const FIT_TOLERANCE: f64 = 1e-9;

/// The turn at one interior waypoint.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Corner {
    /// Heading change (rad, in [0, pi]).
    pub turn: f64,
    /// +1 for a left (counter-clockwise) turn, -1 for a right one, 0 for none.
    pub side: i8,
    /// Distance of each tangent point from the waypoint (m, horizontal).
    pub tangent: f64,
    /// The radius flown (m): the vehicle's when the fillet fits, else the largest the legs
    /// allow; +inf when there is no turn.
    pub radius: f64,
    /// Whether the vehicle's radius fits.
    pub fits: bool,
}

impl Corner {
    /// How far (m) the vehicle's own fillet (radius `r`) would lie from the one flown when the
    /// turn does not fit: (r - radius) (sec(turn/2) - 1), the distance between the two arcs'
    /// midpoints (both are tangent to the same legs). 0 when the turn fits. The evaluation
    /// lets a turn pass when this is within its arc tolerance: then the vehicle flying its own
    /// radius stays as close to the judged curve as the judged chords do to their arcs (a
    /// turn of a few degrees on legs of a metre, as a route rounded to centimetres in a file
    /// makes them, is no longer a violation; any real corner still is).
    pub fn deviation(&self, r: f64) -> f64 {
        if self.fits {
            return 0.0;
        }
        let sec = 1.0 / (self.turn * 0.5).cos();
        ((r - self.radius).max(0.0) * (sec - 1.0)).max(0.0)
    }
}

/// One piece of the flown curve, in flight order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FlownPiece {
    /// The straight part of leg `segment` (from waypoint `segment` to `segment + 1`).
    Line { a: Vec3, b: Vec3, segment: usize },
    /// The fillet at interior waypoint `waypoint` (of zero length when there is no turn or no
    /// room for one).
    Arc(Arc),
}

/// A fillet: a horizontal circular arc with a height changing linearly along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arc {
    pub waypoint: usize,
    pub corner: Corner,
    pub center: Vec2,
    /// Angle of the radius vector to the first tangent point (rad).
    pub start_angle: f64,
    /// Signed sweep (rad, positive counter-clockwise).
    pub sweep: f64,
    pub a: Vec3,
    pub b: Vec3,
}

impl Arc {
    /// Horizontal length (m).
    pub fn horizontal_length(&self) -> f64 {
        if self.corner.radius.is_finite() {
            self.corner.radius * self.sweep.abs()
        } else {
            0.0
        }
    }

    /// The point at fraction `f` of the arc.
    pub fn point(&self, f: f64) -> Vec3 {
        if f <= 0.0 {
            return self.a;
        }
        if f >= 1.0 {
            return self.b;
        }
        let ang = self.start_angle + self.sweep * f;
        let r = self.corner.radius;
        Vec3::new(self.center.x + r * ang.cos(), self.center.y + r * ang.sin(), self.a.z + (self.b.z - self.a.z) * f)
    }

    /// How many equal chords keep every point of the arc within `tolerance` metres of them
    /// (the sagitta r (1 - cos(delta/2)) of each chord): an even number, at least 2, so the
    /// arc's middle is a chord end. 0 for an arc of no length.
    pub fn chords(&self, tolerance: f64) -> usize {
        let len = self.horizontal_length();
        if len <= 0.0 || self.a == self.b {
            return 0;
        }
        let r = self.corner.radius;
        let half = if tolerance >= r { std::f64::consts::FRAC_PI_2 } else { (1.0 - tolerance / r).acos() };
        let n = (self.sweep.abs() / (2.0 * half.max(1e-6))).ceil().clamp(1.0, 1e5) as usize;
        (n + n % 2).max(2)
    }

    /// |dz| over horizontal length: the tangent of the pitch flown on the arc.
    pub fn slope(&self) -> f64 {
        let dz = (self.b.z - self.a.z).abs();
        if dz == 0.0 {
            0.0
        } else {
            dz / self.horizontal_length()
        }
    }
}

/// Horizontal direction and length of leg j.
#[inline]
fn leg(points: &[Vec3], j: usize) -> (Vec2, f64) {
    let d = (points[j + 1] - points[j]).truncate();
    let l = d.length();
    (if l > 0.0 { d / l } else { Vec2::ZERO }, l)
}

/// Whether a leg is too short to have a heading (a NaN length counts as too short).
#[inline]
fn degenerate(len: f64, r: f64) -> bool {
    len.partial_cmp(&(DEGENERATE * r)) != Some(std::cmp::Ordering::Greater)
}

/// Heading change and side between two unit directions.
#[inline]
fn turn_between(u: Vec2, v: Vec2) -> (f64, i8) {
    let c = u.dot(v).clamp(-1.0, 1.0);
    let s = u.perp_dot(v);
    let turn = s.abs().atan2(c);
    if turn <= NO_TURN {
        return (0.0, 0);
    }
    let side = if s >= 0.0 { 1 } else { -1 };
    (turn, side)
}

/// The turn at interior waypoint `i` before legs are shared: heading change, side, and the
/// tangent length the vehicle's radius needs (0 when there is no turn; +inf when a leg next
/// to it has no heading and the headings either side differ).
fn demand(points: &[Vec3], i: usize, r: f64) -> (f64, i8, f64) {
    let (u, lu) = leg(points, i - 1);
    let (v, lv) = leg(points, i);
    if !degenerate(lu, r) && !degenerate(lv, r) {
        let (turn, side) = turn_between(u, v);
        return (turn, side, r * (turn * 0.5).tan());
    }
    // A leg without heading: compare the nearest headings either side.
    let before = (0..i).rev().map(|j| leg(points, j)).find(|l| !degenerate(l.1, r));
    let after = (i..points.len() - 1).map(|j| leg(points, j)).find(|l| !degenerate(l.1, r));
    match (before, after) {
        (Some((u, _)), Some((v, _))) => {
            let (turn, side) = turn_between(u, v);
            (turn, side, if turn > 0.0 { f64::INFINITY } else { 0.0 })
        }
        _ => (0.0, 0, 0.0),
    }
}

/// The part of leg j (horizontal length `len`) the turn at its one end gets, given both ends'
/// demands.
#[inline]
fn share(len: f64, mine: f64, other: f64) -> f64 {
    if mine <= 0.0 {
        return 0.0;
    }
    if mine + other <= len {
        return mine;
    }
    if mine.is_infinite() {
        return if other.is_infinite() { 0.5 * len } else { (len - other.min(0.5 * len)).max(0.0) };
    }
    if other.is_infinite() {
        return mine.min(0.5 * len);
    }
    len * mine / (mine + other)
}

/// The turn at interior waypoint `i` (0 < i < len - 1) of `points` for turning radius `r`.
pub fn corner(points: &[Vec3], i: usize, r: f64) -> Corner {
    let n = points.len();
    let (turn, side, d) = demand(points, i, r);
    if turn == 0.0 {
        return Corner { turn: 0.0, side: 0, tangent: 0.0, radius: f64::INFINITY, fits: true };
    }
    let d_prev = if i >= 2 { demand(points, i - 1, r).2 } else { 0.0 };
    let d_next = if i + 2 < n { demand(points, i + 1, r).2 } else { 0.0 };
    let (_, l_in) = leg(points, i - 1);
    let (_, l_out) = leg(points, i);
    let t = if degenerate(l_in, r) || degenerate(l_out, r) {
        0.0
    } else {
        d.min(share(l_in, d, d_prev)).min(share(l_out, d, d_next))
    };
    let tan_half = (turn * 0.5).tan();
    let radius = if tan_half > 0.0 { t / tan_half } else { f64::INFINITY };
    Corner { turn, side, tangent: t, radius, fits: t >= d * (1.0 - FIT_TOLERANCE) }
}

/// The fillet at interior waypoint `i`, given its corner.
fn arc_at(points: &[Vec3], i: usize, c: Corner) -> Arc {
    let (a3, v3, b3) = (points[i - 1], points[i], points[i + 1]);
    let (u, l_in) = leg(points, i - 1);
    let (_, l_out) = leg(points, i);
    if c.tangent <= 0.0 || c.side == 0 {
        return Arc { waypoint: i, corner: c, center: v3.truncate(), start_angle: 0.0, sweep: 0.0, a: v3, b: v3 };
    }
    // Tangent points on the 3-D legs, so their heights are the polyline's there.
    let a = v3 + (a3 - v3) * (c.tangent / l_in);
    let b = v3 + (b3 - v3) * (c.tangent / l_out);
    let normal = Vec2::new(-u.y, u.x) * f64::from(c.side);
    let center = a.truncate() + normal * c.radius;
    let ra = a.truncate() - center;
    Arc { waypoint: i, corner: c, center, start_angle: ra.y.atan2(ra.x), sweep: f64::from(c.side) * c.turn, a, b }
}

/// Calls `f` with every piece of the curve flown along `points` with turning radius `r`, in
/// flight order: each leg's straight part, then the fillet at its end waypoint (every interior
/// waypoint gets one, possibly of zero length). Allocation-free.
pub fn for_each_piece(points: &[Vec3], r: f64, mut f: impl FnMut(FlownPiece)) {
    let n = points.len();
    if n < 2 {
        return;
    }
    // The end of the previous fillet: where the current leg's straight part starts.
    let mut from = points[0];
    for j in 0..n - 1 {
        if j + 2 < n {
            let c = corner(points, j + 1, r);
            let arc = arc_at(points, j + 1, c);
            f(FlownPiece::Line { a: from, b: arc.a, segment: j });
            f(FlownPiece::Arc(arc));
            from = arc.b;
        } else {
            f(FlownPiece::Line { a: from, b: points[j + 1], segment: j });
        }
    }
}

/// Every turn of `points` at radius `r`, indexed by waypoint (entries 0 and n-1 are no turn).
pub fn corners(points: &[Vec3], r: f64) -> Vec<Corner> {
    let n = points.len();
    (0..n)
        .map(|i| {
            if i == 0 || i + 1 >= n {
                Corner { radius: f64::INFINITY, fits: true, ..Corner::default() }
            } else {
                corner(points, i, r)
            }
        })
        .collect()
}

#[cfg(test)]
mod tests;
