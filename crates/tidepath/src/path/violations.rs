//! The list of reasons a path is infeasible, for `eval` and the plan JSON.

use super::assess::{slope, turn_cos};
use super::{PathModel, TravelModel};
use crate::geom::{Vec2, Vec3};
use crate::world::Dims;

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ViolationKind {
    Terrain,
    Obstacle,
    Bounds,
    Depth,
    Current,
    Turn,
    Pitch,
}

/// One violated constraint. `index` is a waypoint index for bounds, depth and turn, a segment
/// index (segment i joins waypoints i and i+1) for the others.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Violation {
    pub kind: ViolationKind,
    pub index: usize,
    pub message: String,
}

impl PathModel<'_> {
    /// Every violated constraint, in path order. Empty exactly when
    /// [`super::Assessment::feasible`] holds.
    pub fn violations(&self, points: &[Vec3]) -> Vec<Violation> {
        let mut times = Vec::with_capacity(points.len());
        self.arrival_times(points, &mut times);
        let world = self.world;
        let veh = self.vehicle;
        let three_d = world.dims == Dims::Three;
        let slack = world.bounds.size().max_element() * 1e-9;
        let outer = world.bounds.inflate(slack);
        let mut out = Vec::new();
        let mut push = |kind, index, message: String| out.push(Violation { kind, index, message });

        for (i, p) in points.iter().enumerate() {
            if !outer.contains(*p) {
                push(ViolationKind::Bounds, i, format!("waypoint {i} {} is outside the domain", fmt_point(*p)));
            } else if three_d && (p.z > veh.z_max() + slack || p.z < veh.z_min() - slack) {
                push(
                    ViolationKind::Depth,
                    i,
                    format!(
                        "waypoint {i} at depth {:.1} m is outside the depth band [{}, {}] m",
                        -p.z, veh.depth_min, veh.depth_max
                    ),
                );
            }
        }
        let safety = veh.safety_distance;
        let mut prev_h: Option<(Vec2, f64)> = None;
        for (i, w) in points.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            let dir = b - a;
            if world.segment_hits_terrain(a, b, safety) {
                let c = world.segment_terrain_clearance(a, b);
                push(
                    ViolationKind::Terrain,
                    i,
                    format!("segment {i} passes {c:.2} m above the seabed (safety distance {safety} m)"),
                );
            }
            for (k, o) in world.obstacles.iter().enumerate() {
                if o.segment_hits(a, b, times[i], times[i + 1], safety) {
                    let c = o.segment_clearance(a, b, times[i], times[i + 1]);
                    push(
                        ViolationKind::Obstacle,
                        i,
                        format!("segment {i} passes {c:.2} m from obstacle {k} (safety distance {safety} m)"),
                    );
                }
            }
            if self.settings.travel == TravelModel::Crab {
                let blocked = self.segment_time(a, b, times[i]).1;
                if blocked > 0 {
                    push(
                        ViolationKind::Current,
                        i,
                        format!(
                            "segment {i}: the current stops a {} m/s vehicle from holding the track on {blocked} piece(s)",
                            veh.speed
                        ),
                    );
                }
            }
            let h = dir.truncate();
            let h_len = h.length();
            if three_d && dir.z != 0.0 && slope(dir, h_len) > veh.max_pitch.tan() {
                push(
                    ViolationKind::Pitch,
                    i,
                    format!(
                        "segment {i} pitch {:.1} deg exceeds the limit {:.1} deg",
                        dir.z.abs().atan2(h_len).to_degrees(),
                        veh.max_pitch.to_degrees()
                    ),
                );
            }
            if h_len > 0.0 {
                if let Some((ph, ph_len)) = prev_h {
                    let c = turn_cos(ph, ph_len, h, h_len);
                    if c < veh.max_turn.cos() {
                        push(
                            ViolationKind::Turn,
                            i,
                            format!(
                                "waypoint {i} turn {:.1} deg exceeds the limit {:.1} deg",
                                c.acos().to_degrees(),
                                veh.max_turn.to_degrees()
                            ),
                        );
                    }
                }
                prev_h = Some((h, h_len));
            }
        }
        out
    }
}

fn fmt_point(p: Vec3) -> String {
    format!("[{:.1}, {:.1}, {:.1}]", p.x, p.y, p.z)
}
