//! Travel time along a polyline through a current field.

use super::PathModel;
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
    /// Seed 003 eqs. 16-18: |v_i| = |v d + c(P_i)| at both ends of a segment, time =
    /// Dist/(2|v_i|) + Dist/(2|v_{i+1}|), with |v| floored at 0.05 v. Kept for reproducing
    /// that paper; it ignores that a cross-current pushes the vehicle off the segment.
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
pub(crate) const MIN_SPEED_FRACTION: f64 = 0.05;

/// Ground speed along unit direction `d` with through-water speed `v` in current `c`, or
/// `None` when the vehicle cannot hold the track.
#[inline]
pub(crate) fn crab_ground_speed(d: Vec3, v: f64, c: Vec3) -> Option<f64> {
    let along = c.dot(d);
    let cross2 = (c - d * along).length_squared();
    let disc = v * v - cross2;
    if disc < 0.0 {
        return None;
    }
    let g = along + disc.sqrt();
    (g > 0.0).then_some(g)
}

impl PathModel<'_> {
    /// Fills `times` with the arrival time at each point (`times[0]` = departure) and returns the
    /// number of segment pieces the vehicle cannot traverse against the current.
    pub fn arrival_times(&self, points: &[Vec3], times: &mut Vec<f64>) -> u32 {
        times.clear();
        let mut t = self.departure_time;
        times.push(t);
        let mut blocked = 0;
        for w in points.windows(2) {
            let (dt, b) = self.segment_time(w[0], w[1], t);
            t += dt;
            blocked += b;
            times.push(t);
        }
        blocked
    }

    /// Time to traverse a -> b leaving at `t0`, and the number of impossible pieces.
    pub fn segment_time(&self, a: Vec3, b: Vec3, t0: f64) -> (f64, u32) {
        let v = self.vehicle.speed;
        let len = a.distance(b);
        if len == 0.0 {
            return (0.0, 0);
        }
        let d = (b - a) / len;
        let current = &self.world.current;
        match self.settings.travel {
            TravelModel::Crab => {
                // A field constant in space and time needs one piece, still water none.
                let pieces = match current {
                    Current::None => return (len / v, 0),
                    Current::Uniform(_) => 1.0,
                    _ => (len / self.settings.current_step).ceil().max(1.0),
                };
                let n = pieces as u32;
                let step = len / pieces;
                let (mut t, mut blocked) = (t0, 0);
                for k in 0..n {
                    let mid = a + d * (step * (k as f64 + 0.5));
                    let c = current.velocity(mid, t);
                    let g = match crab_ground_speed(d, v, c) {
                        Some(g) => g,
                        None => {
                            blocked += 1;
                            MIN_SPEED_FRACTION * v
                        }
                    };
                    t += step / g;
                }
                (t - t0, blocked)
            }
            TravelModel::VectorSum => {
                let floor = MIN_SPEED_FRACTION * v;
                let va = (d * v + current.velocity(a, t0)).length().max(floor);
                // The current at the far end is read at the estimated arrival time.
                let vb = (d * v + current.velocity(b, t0 + len / va)).length().max(floor);
                (len / (2.0 * va) + len / (2.0 * vb), 0)
            }
        }
    }
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
