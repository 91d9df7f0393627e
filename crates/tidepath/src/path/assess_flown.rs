//! [`PathModel::assess`] and [`PathModel::violations`] for a vehicle with a turning radius:
//! the same verdicts, judged on the flown curve (see [`super::flown`]).

use super::assess::{joint, Assessment};
use super::violations::{motion_issue_text, Violation, ViolationKind};
use super::PathModel;
use crate::geom::{Vec2, Vec3};
use crate::kinematics::fillet::{self, FlownPiece};
use crate::validity::MotionIssue;
use crate::world::Dims;

impl PathModel<'_> {
    /// [`PathModel::assess`] on the curve flown with radius `r`. Collisions count (motion,
    /// object) pairs, a turn being several chord motions.
    pub(super) fn assess_flown(&self, points: &[Vec3], times: &mut Vec<f64>, r: f64) -> Assessment {
        let mut out = Assessment::default();
        let tol = self.settings.arc_tolerance;
        self.waypoint_checks(points, &mut out);
        self.waypoint_turns(points, &mut out);
        let veh = self.vehicle;
        let three_d = self.world.dims == Dims::Three;
        let tan_pitch_limit = veh.max_pitch.tan();
        let mut max_slope = 0.0f64;
        let mut pitch = |slope: f64, out: &mut Assessment| {
            max_slope = max_slope.max(slope);
            if slope > tan_pitch_limit {
                out.pitch_violations += 1;
                out.pitch_excess += slope.atan() - veh.max_pitch;
            }
        };
        fillet::for_each_piece(points, r, |piece| {
            if let FlownPiece::Arc(arc) = piece {
                if too_tight(&arc.corner, r, tol) {
                    out.radius_violations += 1;
                    out.radius_excess += (1.0 - arc.corner.radius / r).clamp(0.0, 1.0);
                }
                if three_d && arc.a != arc.b {
                    pitch(arc.slope(), &mut out);
                }
            }
        });
        let n = points.len();
        times.clear();
        times.resize(n, self.departure_time);
        let arrival = self.walk_flown(
            points,
            r,
            |m, check, _, t1| {
                out.collisions += check.collisions;
                out.current_blocked += check.blocked;
                out.current_gaps += check.gaps;
                match m.turn {
                    None => {
                        let d = m.b - m.a;
                        out.length += d.length();
                        if three_d {
                            if let Some(s) = straight_slope(points, m) {
                                pitch(s, &mut out);
                            }
                        }
                        // The waypoint the leg ends at, until its turn (if any) says otherwise.
                        times[m.segment + 1] = t1;
                    }
                    Some((arc, c, k)) => {
                        if c == 0 {
                            out.length += arc.horizontal_length().hypot(arc.b.z - arc.a.z);
                        }
                        if 2 * (c + 1) == k {
                            times[arc.waypoint] = t1;
                        }
                    }
                }
            },
            |_, _, _| {},
        );
        out.max_pitch = max_slope.atan();
        out.travel_time = if n >= 2 { arrival - self.departure_time } else { 0.0 };
        out
    }

    /// The waypoint angle limit (`max_turn`) on the polyline's joints, as without a radius.
    fn waypoint_turns(&self, points: &[Vec3], out: &mut Assessment) {
        let cos_turn_limit = self.vehicle.max_turn.cos();
        let mut min_cos_turn = 1.0f64;
        let mut prev_h: Option<(Vec2, f64)> = None;
        for w in points.windows(2) {
            let h = (w[1] - w[0]).truncate();
            joint(out, &mut prev_h, &mut min_cos_turn, (h, h.length()), cos_turn_limit, self.vehicle.max_turn);
        }
        out.max_turn = min_cos_turn.acos();
    }

    /// [`PathModel::violations`] on the curve flown with radius `r`, after the waypoint checks
    /// already in `out`: turns whose fillet does not fit, then every motion's issues and
    /// pitch, in flight order. An issue on a turn's chords is reported once per turn.
    pub(super) fn flown_violations(&self, points: &[Vec3], r: f64, out: &mut Vec<Violation>) {
        self.turn_angle_violations(points, &mut |kind, index, message| out.push(Violation { kind, index, message }));
        let tol = self.settings.arc_tolerance;
        let veh = self.vehicle;
        let three_d = self.world.dims == Dims::Three;
        let tan_pitch_limit = veh.max_pitch.tan();
        let mut push = |kind, index, message: String| out.push(Violation { kind, index, message });
        fillet::for_each_piece(points, r, |piece| {
            let FlownPiece::Arc(arc) = piece else { return };
            let (i, c) = (arc.waypoint, arc.corner);
            if too_tight(&c, r, tol) {
                let (l_in, l_out) =
                    ((points[i] - points[i - 1]).truncate().length(), (points[i + 1] - points[i]).truncate().length());
                let need = r * (c.turn * 0.5).tan();
                // Say so when a neighbouring turn takes part of a leg.
                let turns_at = |j: usize| j > 0 && j + 1 < points.len() && fillet::corner(points, j, r).turn > 0.0;
                let shared =
                    if turns_at(i - 1) || turns_at(i + 1) { ", shared with the neighbouring turns" } else { "" };
                push(
                    ViolationKind::Turn,
                    i,
                    format!(
                        "waypoint {i}: the {:.1} deg turn needs {need:.1} m of each leg at the vehicle's {r} m turning radius; its legs ({l_in:.1} m and {l_out:.1} m{shared}) allow a radius of at most {:.1} m",
                        c.turn.to_degrees(),
                        c.radius
                    ),
                );
            }
            if three_d && arc.a != arc.b && arc.slope() > tan_pitch_limit {
                push(
                    ViolationKind::Pitch,
                    i - 1,
                    format!(
                        "the turn at waypoint {i} climbs or dives at {:.1} deg, over the limit {:.1} deg",
                        arc.slope().atan().to_degrees(),
                        veh.max_pitch.to_degrees()
                    ),
                );
            }
        });
        // Motion issues in flight order; a turn's chords report each issue once (the first
        // chord's numbers), like a segment reports each object once.
        let mut turn_seen: (usize, Vec<IssueKey>) = (usize::MAX, Vec::new());
        // Both callbacks append, in flight order.
        let issues = std::cell::RefCell::new(Vec::new());
        self.walk_flown(
            points,
            r,
            |m, _, _, _| {
                if m.turn.is_none() && three_d {
                    if let Some(s) = straight_slope(points, m).filter(|&s| s > tan_pitch_limit) {
                        issues.borrow_mut().push(Violation {
                            kind: ViolationKind::Pitch,
                            index: m.segment,
                            message: format!(
                                "segment {} pitch {:.1} deg exceeds the limit {:.1} deg",
                                m.segment,
                                s.atan().to_degrees(),
                                veh.max_pitch.to_degrees()
                            ),
                        });
                    }
                }
            },
            |m, t0, issue| {
                let place = match m.turn {
                    Some((arc, ..)) => {
                        if turn_seen.0 != arc.waypoint {
                            turn_seen = (arc.waypoint, Vec::new());
                        }
                        let key = IssueKey::of(issue);
                        if turn_seen.1.contains(&key) {
                            return;
                        }
                        turn_seen.1.push(key);
                        format!("the turn at waypoint {}", arc.waypoint)
                    }
                    None => format!("segment {}", m.segment),
                };
                let (kind, text) = motion_issue_text(self, issue, &place, (m.a, m.b, t0, self.motion_speed(m)));
                issues.borrow_mut().push(Violation { kind, index: m.segment, message: text });
            },
        );
        out.extend(issues.into_inner());
    }
}

/// Whether a turn is a violation: it does not fit, and the vehicle flying its own radius there
/// would stray from the judged curve by more than the arc tolerance ([`fillet::Corner::deviation`]).
fn too_tight(c: &fillet::Corner, r: f64, tol: f64) -> bool {
    !c.fits && c.deviation(r) > tol
}

/// The slope (|dz| over horizontal length) flown on a leg's straight part: the leg's own, since
/// the part lies on it. `None` when the part has no length (two fillets meet on the leg, as in
/// a tangent polygon), where the ends' rounding would make up a slope nobody flies, or when
/// the leg is level.
fn straight_slope(points: &[Vec3], m: &super::FlownMotion) -> Option<f64> {
    let leg = points[m.segment + 1] - points[m.segment];
    let part = m.b - m.a;
    if leg.z == 0.0 || part.length() <= 1e-9 * leg.length() {
        return None;
    }
    Some(super::assess::slope(leg, leg.truncate().length()))
}

/// What makes two motion issues the same for reporting: their kind and obstacle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum IssueKey {
    Terrain,
    Obstacle(usize),
    Current,
    NoCurrentData,
    NoWaveData,
}

impl IssueKey {
    fn of(issue: MotionIssue) -> Self {
        match issue {
            MotionIssue::Terrain => IssueKey::Terrain,
            MotionIssue::Obstacle(k) => IssueKey::Obstacle(k),
            MotionIssue::Current { .. } => IssueKey::Current,
            MotionIssue::NoCurrentData => IssueKey::NoCurrentData,
            MotionIssue::NoWaveData => IssueKey::NoWaveData,
        }
    }
}
