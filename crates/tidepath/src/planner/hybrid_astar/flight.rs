//! Flying curves the way the evaluation does, and the curves the search flies besides its
//! primitives: shots to the goal and connections between poses.
//!
//! A curve is priced piece by piece as the evaluation flies it ([`crate::path`]): with a
//! turning radius, the fillet curve of its tangent polygon, straights as one motion and arcs
//! as chords within `model.arc_tolerance`, each chord's cost and time scaled by its arc's length
//! over the chord's; without one, the polygon's legs. Every motion goes through
//! [`crate::cost::CostModel::motion_cost`] at the vehicle's running clock, and every point
//! must be in the domain and depth band (the evaluation's waypoint check).
//!
//! Curves of a few pieces (turns of radius r and straights: a turn then a straight, Dubins
//! words, and in 3-D the Dubins-airplane curves of [`crate::kinematics::dubins3`], which add
//! a turn, or whole helical turns, before the Dubins word when the climb is too steep for it)
//! become tangent polygons, the height changing evenly along their whole length within the
//! pitch limit.

use super::heuristic::turn_then_straight;
use super::lattice::PITCH_MARGIN;
use super::search::{Search, POLL_EVERY};
use crate::geom::Vec3;
use crate::kinematics::dubins::Dubins;
use crate::kinematics::dubins3::Dubins3;
use crate::kinematics::fillet::{self, FlownPiece};
use crate::kinematics::{Pose, TangentPolygon};
use crate::termination::{StopReason, Termination};

/// Shot curves validated per try, shortest first.
pub const SHOT_TRIES: usize = 3;

/// Why a curve was not flown.
pub enum Check {
    Invalid,
    Interrupted(StopReason),
}

/// Turns (+1 left, -1 right) and straights (0) of the given lengths (m), in order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curve {
    pub turns: [i8; 4],
    pub lengths: [f64; 4],
}

impl Curve {
    /// A planar Dubins curve.
    pub fn of_dubins(d: &Dubins) -> Self {
        let [a, b, c] = d.word.turns();
        let [x, y, z] = d.lengths;
        Self { turns: [a, b, c, 0], lengths: [x, y, z, 0.0] }
    }

    /// A Dubins-airplane curve: its turn before the Dubins word (whole turns included), then
    /// the word.
    pub fn of_dubins3(d: &Dubins3) -> Self {
        let [a, b, c] = d.horizontal.word.turns();
        let [x, y, z] = d.horizontal.lengths;
        let side = if d.pre_turn >= 0.0 { 1 } else { -1 };
        Self { turns: [side, a, b, c], lengths: [d.radius * d.pre_turn.abs(), x, y, z] }
    }

    /// The shorter turn-then-straight curve from `from` to the point `to` (any final heading).
    pub fn to_point(from: Pose, to: Vec3, r: f64) -> Option<Self> {
        [1, -1]
            .into_iter()
            .filter_map(|side| turn_then_straight(from, to.truncate(), r, side))
            .min_by(|a, b| a.length(r).total_cmp(&b.length(r)))
            .map(|ts| Self::turn_then_straight(ts.side, r * ts.sweep, ts.straight))
    }

    fn turn_then_straight(side: i8, arc: f64, straight: f64) -> Self {
        Self { turns: [side, 0, 0, 0], lengths: [arc, straight, 0.0, 0.0] }
    }

    /// Horizontal length (m).
    pub fn length(&self) -> f64 {
        self.lengths.iter().sum()
    }

    /// The heading at its end, from `from`'s.
    pub fn end_heading(&self, from: Pose, r: f64) -> f64 {
        from.heading + self.turns.iter().zip(&self.lengths).map(|(&t, l)| f64::from(t) * l / r).sum::<f64>()
    }
}

/// The pitch Dubins-airplane curves are planned with: a little under the limit, so that the
/// curves' own rounding stays within [`PITCH_MARGIN`] of it.
fn planning_pitch(max_pitch: f64) -> f64 {
    (max_pitch.tan() * (1.0 - 2.0 * PITCH_MARGIN)).atan()
}

impl Search<'_> {
    /// The tangent polygon of `curve` from `from` ending exactly at `to`, whose height it
    /// reaches evenly along its length; `None` when that is steeper than the pitch limit.
    pub(super) fn polygon(&self, curve: &Curve, from: Pose, to: Vec3) -> Option<Vec<Vec3>> {
        let r = self.lattice.radius;
        let dz = if self.three_d { to.z - from.p.z } else { 0.0 };
        let length = curve.length();
        let tan_pitch = self.model.vehicle.max_pitch.tan() * (1.0 - PITCH_MARGIN);
        if dz != 0.0 && dz.abs() > tan_pitch * length {
            return None;
        }
        let mut tp = TangentPolygon::new(from, r, self.max_piece);
        for (turn, len) in curve.turns.into_iter().zip(curve.lengths) {
            let climb = if length > 0.0 { dz * len / length } else { 0.0 };
            if turn == 0 {
                tp.straight(len, climb);
            } else {
                tp.arc(f64::from(turn) * len / r, climb);
            }
        }
        let mut pts = tp.finish();
        let last = pts.len() - 1;
        if last == 0 {
            pts.push(to);
        } else {
            pts[last] = to;
        }
        Some(pts)
    }

    /// The shortest curve of curvature at most 1/r from pose `from` to pose `to` within the
    /// pitch limit (a Dubins-airplane curve; the planar Dubins curve in 2-D).
    pub(super) fn connect(&self, from: Pose, to: Pose) -> Option<Curve> {
        let r = self.lattice.radius;
        if self.three_d {
            let pitch = planning_pitch(self.model.vehicle.max_pitch);
            Dubins3::shortest(from, to, r, pitch).map(|d| Curve::of_dubins3(&d))
        } else {
            Dubins::shortest(from, to, r).map(|d| Curve::of_dubins(&d))
        }
    }

    /// The shot curves from `pose` to the goal, shortest first, at most [`SHOT_TRIES`]: the two
    /// turn-then-straight curves (free final heading) when their climb is within the pitch
    /// limit, and the curves to the goal at the fixed goal headings ([`Search::connect`]).
    pub(super) fn shots(&self, pose: Pose) -> Vec<Vec<Vec3>> {
        let r = self.lattice.radius;
        let mut curves: Vec<Curve> = [1, -1]
            .into_iter()
            .filter_map(|side| turn_then_straight(pose, self.goal.truncate(), r, side))
            .map(|ts| Curve::turn_then_straight(ts.side, r * ts.sweep, ts.straight))
            .collect();
        for k in 0..self.goal_headings {
            let h = std::f64::consts::TAU * k as f64 / self.goal_headings as f64;
            curves.extend(self.connect(pose, Pose::new(self.goal, h)));
        }
        curves.sort_by(|a, b| a.length().total_cmp(&b.length()));
        curves.iter().filter_map(|c| self.polygon(c, pose, self.goal)).take(SHOT_TRIES).collect()
    }

    /// Prices the curve flown along `points` leaving at `t0`: its cost and arrival time. Polls
    /// `termination` every few motions when given (long curves).
    pub(super) fn price(
        &self,
        points: &[Vec3],
        t0: f64,
        checks: &mut u64,
        termination: Option<&Termination>,
    ) -> Result<(f64, f64), Check> {
        let v = &self.model.validator;
        if points.iter().any(|&p| v.in_bounds(p).is_err()) {
            return Err(Check::Invalid);
        }
        let (mut cost, mut t) = (0.0, t0);
        let mut bad = None;
        let mut fly = |a: Vec3, b: Vec3, scale: f64| {
            if bad.is_some() {
                return;
            }
            *checks += 1;
            if let Some(r) = termination.filter(|_| *checks % POLL_EVERY == 0).and_then(|t| t.interrupted()) {
                bad = Some(Check::Interrupted(r));
                return;
            }
            match self.cost.motion_cost(&self.model, a, b, t) {
                Some((c, arrival)) => {
                    cost += c * scale;
                    t += (arrival - t) * scale;
                }
                None => bad = Some(Check::Invalid),
            }
        };
        if self.model.vehicle.turn_radius.is_none() {
            // Without a radius the vehicle flies the polygon itself.
            for w in points.windows(2) {
                fly(w[0], w[1], 1.0);
            }
        } else {
            let tol = self.model.settings.arc_tolerance;
            fillet::for_each_piece(points, self.lattice.radius, |piece| match piece {
                FlownPiece::Line { a, b, .. } => fly(a, b, 1.0),
                FlownPiece::Arc(arc) => {
                    let k = arc.chords(tol);
                    if k == 0 {
                        return;
                    }
                    let mut p = arc.a;
                    let chord_len = p.distance(arc.point(1.0 / k as f64));
                    let arc_len = arc.horizontal_length().hypot(arc.b.z - arc.a.z) / k as f64;
                    let scale = if chord_len > 0.0 { arc_len / chord_len } else { 1.0 };
                    for c in 0..k {
                        let q = arc.point((c + 1) as f64 / k as f64);
                        fly(p, q, scale);
                        p = q;
                    }
                }
            });
        }
        match bad {
            Some(b) => Err(b),
            None => Ok((cost, t)),
        }
    }
}
