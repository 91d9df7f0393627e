//! Travel time along a polyline through a current field.

use crate::geom::Vec3;
use crate::world::Current;

/// How the vehicle's through-water velocity and the current combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TravelModel {
    /// The ground track follows the segment and the vehicle crabs into the cross-current:
    /// ground speed = c.d + sqrt(v^2 - |c x d|^2), impossible where the cross-current exceeds v
    /// or the ground speed is not positive. This is the model ocean routing uses.
    Crab,
    /// ijs2023 (Guo et al.) eqs. 16-18: |v_i| = |v d + c(P_i)| at both ends of a segment,
    /// time = Dist/(2|v_i|) + Dist/(2|v_{i+1}|), with |v| floored at 0.05 v. Kept for
    /// reproducing that paper; it ignores that a cross-current pushes the vehicle off the
    /// segment. The validator flies such a segment at its mean ground speed.
    VectorSum,
}

impl TravelModel {
    pub fn id(self) -> &'static str {
        match self {
            TravelModel::Crab => "crab",
            TravelModel::VectorSum => "vector-sum",
        }
    }
}

/// Slowest ground speed, as a fraction of the vehicle speed, used to keep the clock finite
/// where the current makes a piece impossible (the piece is flagged separately).
pub const MIN_SPEED_FRACTION: f64 = 0.05;

/// Ground speed along unit direction `d` with through-water speed `v` in current `c`, or
/// `None` when the vehicle cannot hold the track.
#[inline]
pub fn crab_ground_speed(d: Vec3, v: f64, c: Vec3) -> Option<f64> {
    let along = c.dot(d);
    let cross2 = (c - d * along).length_squared();
    let disc = v * v - cross2;
    if disc < 0.0 {
        return None;
    }
    let g = along + disc.sqrt();
    (g > 0.0).then_some(g)
}

/// Vector-sum model (ijs2023 eqs. 16-18): |v_i| = |v d + c(P_i)| at both ends of a segment
/// (the far end read at the estimated arrival), time = L/(2|v_a|) + L/(2|v_b|), speeds floored
/// at [`MIN_SPEED_FRACTION`] v.
pub(crate) fn vector_sum_time(d: Vec3, len: f64, v: f64, current: &Current, a: Vec3, b: Vec3, t0: f64) -> f64 {
    let floor = MIN_SPEED_FRACTION * v;
    let va = (d * v + current.velocity(a, t0)).length().max(floor);
    let vb = (d * v + current.velocity(b, t0 + len / va)).length().max(floor);
    len / (2.0 * va) + len / (2.0 * vb)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crab_speed_with_following_and_cross_current() {
        let d = Vec3::X;
        // Following current adds directly.
        assert!((crab_ground_speed(d, 2.0, Vec3::new(0.5, 0.0, 0.0)).unwrap() - 2.5).abs() < 1e-12);
        // Pure cross-current of 1.2 with v = 2: ground speed sqrt(4 - 1.44) = 1.6.
        assert!((crab_ground_speed(d, 2.0, Vec3::new(0.0, 1.2, 0.0)).unwrap() - 1.6).abs() < 1e-12);
        // Head current 0.6 and cross 0.8 with v = 1: along -0.6 + sqrt(1 - 0.64) = 0.
        assert!(crab_ground_speed(d, 1.0, Vec3::new(-0.6, 0.8, 0.0)).is_none());
        // Cross-current stronger than the vehicle.
        assert!(crab_ground_speed(d, 1.0, Vec3::new(0.0, 1.1, 0.0)).is_none());
    }
}
