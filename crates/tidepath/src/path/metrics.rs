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
        }
    }

    /// Smallest clearance over all segments; see [`Metrics::min_clearance_m`].
    pub fn min_clearance(&self, points: &[Vec3], times: &[f64]) -> Option<f64> {
        let mut best = f64::INFINITY;
        for (i, w) in points.windows(2).enumerate() {
            best = best.min(self.validator.motion_clearance(w[0], w[1], times[i]));
        }
        best.is_finite().then_some(best)
    }
}
