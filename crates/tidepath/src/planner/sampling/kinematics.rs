//! The vehicle's path-level limits, kept at every joint of a sampling planner's tree or on its
//! roadmap search, so the paths they return pass the evaluation's turn and pitch checks.
//!
//! The evaluation counts a turn at a waypoint whose horizontal heading change exceeds
//! `max_turn`, and a pitch violation on a segment steeper than `max_pitch`. Both are local: a
//! turn depends on the two edges at a vertex, a pitch on one edge. The planners check an edge's
//! pitch before pricing it and a turn whenever a vertex gets a new parent or child. Edges
//! without horizontal extent are refused in 3-D (their heading is undefined, and the
//! evaluation would compare the headings on either side of them instead).
//!
//! For a vehicle with a turning radius r, a turn of theta needs r tan(theta / 2) of each leg
//! for its fillet (see [`crate::kinematics::fillet`]); the joint is accepted when that is at
//! most half of each leg's horizontal length, so the two turns sharing a leg always fit. The
//! motions are checked on the polyline; the curve flown inside each corner is judged by the
//! evaluation (smooth with `dubins`, or plan with `hybrid-astar`, for curves checked as flown).

use crate::geom::Vec3;
use crate::vehicle::Vehicle;

/// Relative slack that keeps the planners' accept strictly inside the evaluation's limits, so
/// rounding never turns an accepted joint into a violation.
const SLACK: f64 = 1e-9;

/// Shortest horizontal extent (m) of an edge in 3-D.
const MIN_HORIZONTAL: f64 = 1e-6;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics {
    /// cos(max_turn) (-1: any turn).
    pub cos_turn: f64,
    /// tan(max_pitch) (+inf at 90 degrees).
    pub tan_pitch: f64,
    pub radius: Option<f64>,
    pub three_d: bool,
}

impl Kinematics {
    pub fn of(v: &Vehicle, three_d: bool) -> Self {
        Self { cos_turn: v.max_turn.cos(), tan_pitch: v.max_pitch.tan(), radius: v.turn_radius, three_d }
    }

    /// Whether the edge a -> b keeps the pitch limit (3-D) and has a heading.
    #[inline]
    pub fn edge_ok(&self, a: Vec3, b: Vec3) -> bool {
        let d = b - a;
        let h = d.truncate().length();
        if !self.three_d {
            return h > 0.0;
        }
        h > MIN_HORIZONTAL && d.z.abs() <= self.tan_pitch * h * (1.0 - SLACK)
    }

    /// Whether the joint at `at`, reached from `from` and left towards `to`, keeps the turn
    /// limit (and, with a turning radius, leaves room for its fillet). `from` is `None` at the
    /// start, where any heading is allowed.
    #[inline]
    pub fn joint_ok(&self, from: Option<Vec3>, at: Vec3, to: Vec3) -> bool {
        let Some(from) = from else { return true };
        let (a, b) = ((at - from).truncate(), (to - at).truncate());
        let (la, lb) = (a.length(), b.length());
        if la <= 0.0 || lb <= 0.0 {
            return true;
        }
        let c = (a.dot(b) / (la * lb)).clamp(-1.0, 1.0);
        // At max_turn = 180 degrees every turn is allowed (cos_turn = -1).
        if c < self.cos_turn + SLACK && self.cos_turn > -1.0 {
            return false;
        }
        match self.radius {
            None => true,
            Some(r) => {
                // tan(theta / 2) = sqrt((1 - c) / (1 + c)).
                let half = ((1.0 - c) / (1.0 + c).max(f64::MIN_POSITIVE)).sqrt();
                r * half <= 0.5 * la.min(lb) * (1.0 - SLACK)
            }
        }
    }
}
