//! The list of reasons a path is infeasible, for `eval` and the plan JSON.

use super::assess::{slope, turn_cos};
use super::PathModel;
use crate::geom::{Vec2, Vec3};
use crate::validity::{MotionIssue, StateIssue};
use crate::world::Dims;

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ViolationKind {
    Terrain,
    Obstacle,
    Bounds,
    Depth,
    /// The path does not start at the mission's start or end at its goal.
    Endpoint,
    Current,
    Turn,
    Pitch,
    /// Two vehicles of a fleet come closer than their separation at the same time.
    Separation,
    /// A fleet's arrivals break its rule (together within a tolerance, or an order).
    Arrival,
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
        let mut out = self.waypoint_violations(points);
        match self.vehicle.turn_radius {
            Some(r) => self.flown_violations(points, r, &mut out),
            None => self.polyline_violations(points, &mut out),
        }
        out
    }

    /// Endpoint, domain and depth-band violations of the waypoints.
    fn waypoint_violations(&self, points: &[Vec3]) -> Vec<Violation> {
        let world = self.world;
        let veh = self.vehicle;
        let validator = &self.validator;
        let mut out = Vec::new();
        let mut push = |kind, index, message: String| out.push(Violation { kind, index, message });

        let tol = self.endpoint_tolerance();
        let ends =
            [(points.first(), self.start, "start", 0), (points.last(), self.goal, "goal", points.len().max(1) - 1)];
        for (p, want, what, i) in ends {
            match p {
                Some(p) if p.distance(want) <= tol => {}
                Some(p) => push(
                    ViolationKind::Endpoint,
                    i,
                    format!("waypoint {i} ({}) is not the mission {what} ({})", world.point(*p), world.point(want)),
                ),
                None => push(ViolationKind::Endpoint, 0, format!("the path is empty: it does not reach the {what}")),
            }
        }
        for (i, p) in points.iter().enumerate() {
            match validator.in_bounds(*p) {
                Err(StateIssue::OutsideDepthBand) => push(
                    ViolationKind::Depth,
                    i,
                    format!(
                        "waypoint {i} at depth {:.1} m is outside the depth band [{}, {}] m",
                        -p.z, veh.depth_min, veh.depth_max
                    ),
                ),
                Err(_) => {
                    push(ViolationKind::Bounds, i, format!("waypoint {i} ({}) is outside the domain", world.point(*p)))
                }
                Ok(()) => {}
            }
        }
        out
    }

    /// The waypoint angle limit on the polyline's joints (the polyline's own check does it
    /// segment by segment, in path order).
    pub(super) fn turn_angle_violations(&self, points: &[Vec3], push: &mut impl FnMut(ViolationKind, usize, String)) {
        let veh = self.vehicle;
        let mut prev_h: Option<(Vec2, f64)> = None;
        for (i, w) in points.windows(2).enumerate() {
            let h = (w[1] - w[0]).truncate();
            let h_len = h.length();
            if h_len > 0.0 {
                if let Some(text) = prev_h.and_then(|p| joint_turn(veh, i, p, (h, h_len))) {
                    push(ViolationKind::Turn, i, text);
                }
                prev_h = Some((h, h_len));
            }
        }
    }

    /// Every segment's motion issues and pitch, flying the polyline itself.
    fn polyline_violations(&self, points: &[Vec3], out: &mut Vec<Violation>) {
        let world = self.world;
        let veh = self.vehicle;
        let validator = &self.validator;
        let mut push = |kind, index, message: String| out.push(Violation { kind, index, message });
        let three_d = world.dims == Dims::Three;
        let mut prev_h: Option<(Vec2, f64)> = None;
        let mut t = self.departure_time;
        for (i, w) in points.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            let dir = b - a;
            let mut issues = Vec::new();
            let v = self.segment_speed(i);
            let m = validator.motion_with_at(a, b, t, v, |issue| issues.push(issue));
            for issue in issues {
                let (kind, text) = motion_issue_text(self, issue, &format!("segment {i}"), (a, b, t, v));
                push(kind, i, text);
            }
            t = m.arrival;
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
                if let Some(text) = prev_h.and_then(|p| joint_turn(veh, i, p, (h, h_len))) {
                    push(ViolationKind::Turn, i, text);
                }
                prev_h = Some((h, h_len));
            }
        }
    }
}

/// The message for joint `i` (horizontal directions `before` and `after` with their lengths)
/// when its heading change exceeds the vehicle's waypoint angle limit.
fn joint_turn(veh: &crate::vehicle::Vehicle, i: usize, before: (Vec2, f64), after: (Vec2, f64)) -> Option<String> {
    let c = turn_cos(before.0, before.1, after.0, after.1);
    (c < veh.max_turn.cos()).then(|| {
        format!(
            "waypoint {i} turn {:.1} deg exceeds the limit {:.1} deg",
            c.acos().to_degrees(),
            veh.max_turn.to_degrees()
        )
    })
}

/// The violation kind and message of one motion issue of the motion a -> b leaving at `t`
/// at through-water speed `v`; `place` names it ("segment 3", "the turn at waypoint 4").
pub(super) fn motion_issue_text(
    model: &PathModel<'_>,
    issue: MotionIssue,
    place: &str,
    (a, b, t, v): (Vec3, Vec3, f64, f64),
) -> (ViolationKind, String) {
    let world = model.world;
    let veh = model.vehicle;
    let safety = veh.safety_distance;
    match issue {
        MotionIssue::Terrain => {
            let c = world.segment_terrain_clearance(a, b);
            // The ground at the worst point is at least min(z) - c: above the sea surface, the
            // motion crosses land.
            let ground = a.z.min(b.z) - c;
            let text = if ground > 0.0 {
                format!("{place} crosses land (ground at least {ground:.1} m above the sea surface)")
            } else if c < 0.0 {
                format!("{place} passes {:.2} m below the seabed (safety distance {safety} m)", -c)
            } else {
                format!("{place} passes {c:.2} m above the seabed (safety distance {safety} m)")
            };
            (ViolationKind::Terrain, text)
        }
        MotionIssue::Obstacle(k) => {
            let c = obstacle_clearance(model, k, (a, b, t, v));
            (ViolationKind::Obstacle, format!("{place} passes {c:.2} m from obstacle {k} (safety distance {safety} m)"))
        }
        // A wave glider has no through-water speed to stem the current with: the regression
        // (acopf2016 eqs. 1-2) is not positive where the head current outweighs the waves.
        MotionIssue::Current { pieces } if veh.glider().is_some() => (
            ViolationKind::Current,
            format!("{place}: the head current drives the wave glider back on {pieces} piece(s)"),
        ),
        MotionIssue::Current { pieces } => (
            ViolationKind::Current,
            format!("{place}: the current stops a {v} m/s vehicle from holding the track on {pieces} piece(s)"),
        ),
        MotionIssue::NoCurrentData => {
            let at = world.current.first_gap_on(a, b).map(|p| world.place(p.x, p.y)).unwrap_or_default();
            (
                ViolationKind::Current,
                format!("{place} passes where the current forecast has no data (land or fill), first at {at}"),
            )
        }
        MotionIssue::NoWaveData => {
            let at = world.waves.first_gap_on(a, b).map(|(x, y)| world.place(x, y)).unwrap_or_default();
            (
                ViolationKind::Current,
                format!("{place} passes where the wave forecast has no data (land or fill), first at {at}"),
            )
        }
    }
}

/// Clearance of segment a -> b (leaving at `t0` at speed `v`) to obstacle `k`, on the
/// validator's clock.
fn obstacle_clearance(model: &PathModel<'_>, k: usize, (a, b, t0, v): (Vec3, Vec3, f64, f64)) -> f64 {
    let o = &model.world.obstacles[k];
    let mut best = f64::INFINITY;
    model
        .validator
        .for_each_piece_at(a, b, t0, v, |pc| best = best.min(o.segment_clearance(pc.p0, pc.p1, pc.t0, pc.t1)));
    best
}
