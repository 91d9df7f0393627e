//! The allocation-free pass every cost model builds on.

use super::PathModel;
use crate::geom::{Vec2, Vec3};
use crate::world::Dims;

/// Everything about a path that a cost model or a feasibility verdict needs, except
/// clearance (which costs more and is only reported, see [`super::Metrics`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Assessment {
    /// 3-D length (m).
    pub length: f64,
    /// Travel time from departure to arrival (s).
    pub travel_time: f64,
    /// (segment, object) pairs closer than the safety distance; the seabed counts as one object.
    pub collisions: u32,
    /// Waypoints outside the domain or (3-D) outside the vehicle's depth band.
    pub bounds_violations: u32,
    /// 1 when the path does not start at the mission's start, 1 more when it does not end at
    /// its goal.
    pub endpoint_violations: u32,
    /// Segment pieces where the current stops the vehicle from holding its track.
    pub current_blocked: u32,
    /// Segment pieces through places where the current forecast has no data.
    pub current_gaps: u32,
    /// Joints whose heading change exceeds the vehicle's limit, and the summed excess (rad).
    pub turn_violations: u32,
    pub turn_excess: f64,
    /// Segments steeper than the vehicle's pitch limit, and the summed excess (rad).
    pub pitch_violations: u32,
    pub pitch_excess: f64,
    /// With a turning radius: turns whose fillet does not fit in their legs, and the summed
    /// shortfall 1 - (radius flown / the vehicle's radius), each in [0, 1].
    pub radius_violations: u32,
    pub radius_excess: f64,
    /// Largest heading change at a joint and largest |pitch| of a segment (rad).
    pub max_turn: f64,
    pub max_pitch: f64,
}

impl Assessment {
    pub fn violation_count(&self) -> u32 {
        self.collisions
            + self.bounds_violations
            + self.endpoint_violations
            + self.current_blocked
            + self.current_gaps
            + self.turn_violations
            + self.radius_violations
            + self.pitch_violations
    }

    pub fn feasible(&self) -> bool {
        self.violation_count() == 0
    }
}

impl PathModel<'_> {
    /// Judges `points` (start and goal included). `times` receives the arrival time at each
    /// point, on the clock every segment's motion check used.
    pub fn assess(&self, points: &[Vec3], times: &mut Vec<f64>) -> Assessment {
        if let Some(r) = self.vehicle.turn_radius {
            return self.assess_flown(points, times, r);
        }
        let mut out = Assessment::default();
        let veh = self.vehicle;
        let three_d = self.world.dims == Dims::Three;
        let validator = &self.validator;

        self.waypoint_checks(points, &mut out);
        // Angles are compared through their cosine and tangent so the common case needs no
        // inverse trigonometry; acos/atan run only for violations and once for the maxima.
        let cos_turn_limit = veh.max_turn.cos();
        let tan_pitch_limit = veh.max_pitch.tan();
        let mut min_cos_turn = 1.0f64;
        let mut max_slope = 0.0f64;
        let mut prev_h: Option<(Vec2, f64)> = None;
        times.clear();
        let mut t = self.departure_time;
        times.push(t);
        for (i, w) in points.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            let dir = b - a;
            out.length += dir.length();
            let m = validator.motion_at(a, b, t, self.segment_speed(i));
            out.collisions += m.collisions;
            out.current_blocked += m.blocked;
            out.current_gaps += m.gaps;
            t = m.arrival;
            times.push(t);
            let h = dir.truncate();
            let h_len = h.length();
            if three_d && dir.z != 0.0 {
                let slope = slope(dir, h_len);
                max_slope = max_slope.max(slope);
                if slope > tan_pitch_limit {
                    out.pitch_violations += 1;
                    out.pitch_excess += dir.z.abs().atan2(h_len) - veh.max_pitch;
                }
            }
            joint(&mut out, &mut prev_h, &mut min_cos_turn, (h, h_len), cos_turn_limit, veh.max_turn);
        }
        out.max_turn = min_cos_turn.acos();
        out.max_pitch = max_slope.atan();
        out.travel_time = t - self.departure_time;
        out
    }
}

impl PathModel<'_> {
    /// The checks on waypoints alone: in the domain and depth band, first and last at the
    /// mission's start and goal.
    pub(super) fn waypoint_checks(&self, points: &[Vec3], out: &mut Assessment) {
        let validator = &self.validator;
        for p in points {
            if validator.in_bounds(*p).is_err() {
                out.bounds_violations += 1;
            }
        }
        let tol = self.endpoint_tolerance();
        // A NaN distance counts as off.
        let off = |p: Option<&Vec3>, q: Vec3| {
            p.is_none_or(|p| {
                let d = p.distance(q);
                d.is_nan() || d > tol
            })
        };
        out.endpoint_violations = u32::from(off(points.first(), self.start)) + u32::from(off(points.last(), self.goal));
    }
}

/// One joint's waypoint angle check: the heading change from the previous segment with
/// horizontal extent to this one (`h`, of length `h_len`) counted against the limit, and the
/// smallest cosine so far kept. A segment without horizontal extent keeps the previous heading.
/// Shared by the polyline and the flown-curve assessments.
#[inline]
pub(super) fn joint(
    out: &mut Assessment,
    prev_h: &mut Option<(Vec2, f64)>,
    min_cos_turn: &mut f64,
    (h, h_len): (Vec2, f64),
    cos_turn_limit: f64,
    max_turn: f64,
) {
    if h_len > 0.0 {
        if let Some((ph, ph_len)) = *prev_h {
            let c = turn_cos(ph, ph_len, h, h_len);
            *min_cos_turn = min_cos_turn.min(c);
            if c < cos_turn_limit {
                out.turn_violations += 1;
                out.turn_excess += c.acos() - max_turn;
            }
        }
        *prev_h = Some((h, h_len));
    }
}

/// |dz| / horizontal length of a segment (+inf when vertical). Shared with the violation list
/// so both agree exactly at the limit.
#[inline]
pub(super) fn slope(dir: Vec3, h_len: f64) -> f64 {
    if h_len > 0.0 {
        dir.z.abs() / h_len
    } else {
        f64::INFINITY
    }
}

/// Cosine of the heading change between two horizontal directions of known lengths.
#[inline]
pub(super) fn turn_cos(a: Vec2, a_len: f64, b: Vec2, b_len: f64) -> f64 {
    (a.dot(b) / (a_len * b_len)).clamp(-1.0, 1.0)
}
