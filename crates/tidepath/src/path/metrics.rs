//! The metrics a user reads in a plan summary and in the plan JSON.

use super::PathModel;
use crate::geom::Vec3;

#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Metrics {
    pub length_m: f64,
    pub travel_time_s: f64,
    /// Largest change of horizontal heading at a waypoint.
    pub max_turn_deg: f64,
    /// Largest climb or dive angle of a segment.
    pub max_pitch_deg: f64,
    /// Smallest clearance along the path: vertical to the seabed (negative when below it) and
    /// Euclidean to obstacle surfaces (0 when touching or inside). `null` in JSON when the world
    /// has neither seabed nor obstacles.
    pub min_clearance_m: Option<f64>,
    /// (segment, object) pairs closer than the safety distance.
    pub collisions: u32,
    /// With a turning radius: the smallest radius of a turn flown (the vehicle's own when
    /// every fillet fits; `null` when the path has no turn; turns passing only by the arc
    /// tolerance's slack, rounding in a file, are left out). Absent without a radius.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_turn_radius_m: Option<f64>,
    /// With a turning radius: the flown curve's largest curvature (1/m), 1 / min_turn_radius_m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_curvature_per_m: Option<f64>,
}

impl PathModel<'_> {
    pub fn metrics(&self, points: &[Vec3]) -> Metrics {
        let mut times = Vec::with_capacity(points.len());
        let a = self.assess(points, &mut times);
        Metrics {
            length_m: a.length,
            travel_time_s: a.travel_time,
            max_turn_deg: a.max_turn.to_degrees(),
            max_pitch_deg: a.max_pitch.to_degrees(),
            min_clearance_m: self.min_clearance(points, &times),
            collisions: a.collisions,
            min_turn_radius_m: self.turn_radius().and_then(|r| min_turn_radius(points, r, self.settings.arc_tolerance)),
            max_curvature_per_m: self.turn_radius().map(|r| {
                min_turn_radius(points, r, self.settings.arc_tolerance).map_or(0.0, |m| {
                    if m > 0.0 {
                        1.0 / m
                    } else {
                        f64::INFINITY
                    }
                })
            }),
        }
    }

    /// Smallest clearance over all segments (over the flown curve's motions with a turning
    /// radius); see [`Metrics::min_clearance_m`].
    pub fn min_clearance(&self, points: &[Vec3], times: &[f64]) -> Option<f64> {
        let mut best = f64::INFINITY;
        if let Some(r) = self.turn_radius() {
            let v = &self.validator;
            self.walk_flown(
                points,
                r,
                |m, _, t0, _| best = best.min(v.motion_clearance_at(m.a, m.b, t0, self.motion_speed(m))),
                |_, _, _| {},
            );
            return best.is_finite().then_some(best);
        }
        for (i, w) in points.windows(2).enumerate() {
            best = best.min(self.validator.motion_clearance_at(w[0], w[1], times[i], self.segment_speed(i)));
        }
        best.is_finite().then_some(best)
    }
}

/// The smallest radius flown at a turn of `points` with radius `r` (`None`: no turn). Turns
/// that pass only by the arc tolerance's slack (a heading change of rounding at points a
/// centimetre apart, as files written to centimetres make them) are not counted: their
/// "radius" measures the rounding, not a turn the vehicle makes.
fn min_turn_radius(points: &[Vec3], r: f64, tolerance: f64) -> Option<f64> {
    let mut best: Option<f64> = None;
    crate::kinematics::fillet::for_each_piece(points, r, |p| {
        if let crate::kinematics::FlownPiece::Arc(a) = p {
            let c = a.corner;
            if c.turn > 0.0 && (c.fits || c.deviation(r) > tolerance) {
                best = Some(best.map_or(c.radius, |b| b.min(c.radius)));
            }
        }
    });
    best
}
