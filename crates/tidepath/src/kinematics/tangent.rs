//! Tangent polygons: the polyline whose fillets at radius r are a given chain of arcs and
//! straights, so an exact curve travels through every part of tidepath as waypoints.
//!
//! An arc of radius r and sweep phi is cut into k equal pieces of at most `max_piece` each
//! (delta = phi / k). The tangents at the pieces' ends meet at k vertices, each r tan(delta/2)
//! from the tangent points on either side; consecutive vertices are 2 r tan(delta/2) apart. The
//! fillet of radius r at such a vertex (turn delta) touches both legs exactly at those tangent
//! points and is the piece of the arc: the fillet model ([`super::fillet`]) flies the arc.
//! A straight moves the pen.
//!
//! Heights: every element's ends (the tangent points where arcs and straights meet) are
//! waypoints themselves, at zero turn; so are an arc's interior tangent points when it climbs
//! or dives. The fillet model changes z linearly with the turned angle between a fillet's
//! tangent points and linearly along straights, so the flown height is exactly the one given:
//! a climb spread evenly over each element. A vertex's own z is never flown (the fillet cuts
//! the corner); it is the mean of its tangent points'.

use super::Pose;
use crate::geom::{Vec2, Vec3};

/// Builds the tangent polygon of a chain of arcs and straights from a start pose.
#[derive(Clone, Debug)]
pub struct TangentPolygon {
    radius: f64,
    max_piece: f64,
    /// Horizontal vertices so far, with the z each should get.
    points: Vec<Vec3>,
    /// The pen: where the chain has reached (a tangent point) and its heading.
    pose: Pose,
}

impl TangentPolygon {
    /// Starts at `start` with arcs of `radius` cut into pieces of at most `max_piece` rad
    /// (clamped to [1e-3, 2pi/3]: a vertex of a piece near pi would lie far away).
    pub fn new(start: Pose, radius: f64, max_piece: f64) -> Self {
        Self {
            radius,
            max_piece: max_piece.clamp(1e-3, std::f64::consts::TAU / 3.0),
            points: vec![start.p],
            pose: start,
        }
    }

    /// Where the chain has reached, and its heading.
    pub fn pose(&self) -> Pose {
        self.pose
    }

    /// Flies straight for `len` metres horizontally while the height changes by `dz`.
    pub fn straight(&mut self, len: f64, dz: f64) {
        if len <= 0.0 && dz == 0.0 {
            return;
        }
        self.mark_pen();
        let d = self.pose.dir() * len.max(0.0);
        self.pose.p += Vec3::new(d.x, d.y, dz);
    }

    /// Turns by `sweep` rad (positive: left, counter-clockwise) on the radius while the
    /// height changes by `dz`, spread evenly over the arc's length.
    pub fn arc(&mut self, sweep: f64, dz: f64) {
        if sweep == 0.0 {
            self.straight(0.0, dz);
            return;
        }
        self.mark_pen();
        let k = (sweep.abs() / self.max_piece).ceil().max(1.0) as usize;
        let delta = sweep / k as f64;
        let t = self.radius * (delta.abs() * 0.5).tan();
        let z0 = self.pose.p.z;
        for j in 0..k {
            let (p, u) = (self.pose.p.truncate(), self.pose.dir());
            // The vertex: t along the current heading from the tangent point.
            let v = p + u * t;
            let heading = self.pose.heading + delta;
            let next = v + Vec2::new(heading.cos(), heading.sin()) * t;
            let (za, zb) = (z0 + dz * j as f64 / k as f64, z0 + dz * (j + 1) as f64 / k as f64);
            self.points.push(Vec3::new(v.x, v.y, 0.5 * (za + zb)));
            self.pose = Pose::new(Vec3::new(next.x, next.y, zb), heading);
            // Interior tangent points carry their height only when it changes.
            if dz != 0.0 && j + 1 < k {
                self.points.push(self.pose.p);
            }
        }
        self.mark_pen();
    }

    /// Makes the pen's position a waypoint (an element boundary), unless it already is.
    fn mark_pen(&mut self) {
        let p = self.pose.p;
        if self.points.last().is_none_or(|q| *q != p) {
            self.points.push(p);
        }
    }

    /// The polygon, ending at the pen.
    pub fn finish(mut self) -> Vec<Vec3> {
        self.mark_pen();
        self.points
    }

    /// Appends the chain's vertices so far to `out` without its first point (to join chains).
    pub fn finish_into(self, out: &mut Vec<Vec3>) {
        out.extend(self.finish().into_iter().skip(1));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn quarter_turn_in_one_piece_is_the_corner_of_its_square() {
        let mut tp = TangentPolygon::new(Pose::new(Vec3::ZERO, 0.0), 10.0, FRAC_PI_2);
        tp.arc(FRAC_PI_2, 0.0);
        let end = tp.pose();
        let pts = tp.finish();
        // A left quarter turn of radius 10 from the origin heading east: vertex (10, 0), end (10, 10).
        assert_eq!(pts.len(), 3);
        assert!((pts[1] - Vec3::new(10.0, 0.0, 0.0)).length() < 1e-12);
        assert!((pts[2] - Vec3::new(10.0, 10.0, 0.0)).length() < 1e-12);
        assert!((end.heading - FRAC_PI_2).abs() < 1e-15);
    }

    #[test]
    fn half_turn_in_pieces_ends_where_the_circle_does() {
        let r = 7.0;
        let mut tp = TangentPolygon::new(Pose::new(Vec3::new(1.0, 2.0, -5.0), 0.0), r, 0.5);
        tp.arc(-PI, -3.0);
        let end = tp.pose();
        // A right half turn: the end is 2r to the right (south), heading west, 3 m deeper.
        assert!((end.p - Vec3::new(1.0, 2.0 - 2.0 * r, -8.0)).length() < 1e-12);
        assert!((end.heading + PI).abs() < 1e-12);
        let pts = tp.finish();
        // pi / 0.5 -> 7 pieces: start, 7 vertices with the 6 interior tangent points between
        // them (the arc dives), end.
        assert_eq!(pts.len(), 1 + 7 + 6 + 1);
        assert!((pts[2].z - (-5.0 - 3.0 / 7.0)).abs() < 1e-12, "first interior tangent point");
    }

    #[test]
    fn straights_move_the_pen() {
        let mut tp = TangentPolygon::new(Pose::new(Vec3::ZERO, FRAC_PI_2), 5.0, 0.3);
        tp.straight(3.0, 1.0);
        tp.straight(2.0, 0.0);
        let pts = tp.finish();
        // Each element's ends are waypoints, so each straight keeps its own slope.
        assert_eq!(pts.len(), 3);
        assert!((pts[1] - Vec3::new(0.0, 3.0, 1.0)).length() < 1e-12);
        assert!((pts[2] - Vec3::new(0.0, 5.0, 1.0)).length() < 1e-12);
    }
}
