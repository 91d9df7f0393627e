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
//! Curves of at most three pieces (turns of radius r and straights: Dubins words, a turn then
//! a straight) become tangent polygons whose turns are level, the height changing evenly along
//! their straight parts within the pitch limit (why: [`super::lattice`]).

use super::heuristic::turn_then_straight;
use super::lattice::PITCH_MARGIN;
use super::search::{Search, POLL_EVERY};
use crate::geom::Vec3;
use crate::kinematics::dubins::Dubins;
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

/// Turns (+1 left, -1 right) and straights (0) of the given lengths (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curve {
    pub turns: [i8; 3],
    pub lengths: [f64; 3],
}

impl Curve {
    pub fn of_dubins(d: &Dubins) -> Self {
        Self { turns: d.word.turns(), lengths: d.lengths }
    }

    /// The shorter turn-then-straight curve from `from` to the point `to` (any final heading).
    pub fn to_point(from: Pose, to: Vec3, r: f64) -> Option<Self> {
        [1, -1]
            .into_iter()
            .filter_map(|side| turn_then_straight(from, to.truncate(), r, side))
            .min_by(|a, b| a.length(r).total_cmp(&b.length(r)))
            .map(|ts| Self { turns: [ts.side, 0, 0], lengths: [r * ts.sweep, ts.straight, 0.0] })
    }

    pub fn length(&self) -> f64 {
        self.lengths.iter().sum()
    }

    fn straight(&self) -> f64 {
        self.turns.iter().zip(&self.lengths).filter(|(t, _)| **t == 0).map(|(_, l)| l).sum()
    }

    /// The heading at its end, from `from`'s.
    pub fn end_heading(&self, from: Pose, r: f64) -> f64 {
        from.heading + self.turns.iter().zip(&self.lengths).map(|(&t, l)| f64::from(t) * l / r).sum::<f64>()
    }
}

impl Search<'_> {
    /// The tangent polygon of `curve` from `from` ending exactly at `to` (whose height it
    /// reaches on its straight parts), or `None` when that climb is steeper than the pitch limit.
    pub(super) fn polygon(&self, curve: &Curve, from: Pose, to: Vec3) -> Option<Vec<Vec3>> {
        let r = self.lattice.radius;
        let dz = if self.three_d { to.z - from.p.z } else { 0.0 };
        let straight = curve.straight();
        let tan_pitch = self.model.vehicle.max_pitch.tan() * (1.0 - PITCH_MARGIN);
        if dz != 0.0 && dz.abs() > tan_pitch * straight {
            return None;
        }
        let mut tp = TangentPolygon::new(from, r, self.max_piece);
        for (turn, len) in curve.turns.into_iter().zip(curve.lengths) {
            if turn == 0 {
                tp.straight(len, if straight > 0.0 { dz * len / straight } else { 0.0 });
            } else {
                tp.arc(f64::from(turn) * len / r, 0.0);
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

    /// The shot curves from `pose` to the goal that respect the pitch limit, shortest first,
    /// at most [`SHOT_TRIES`]: the two turn-then-straight curves (free final heading) and the
    /// Dubins curves to the fixed goal headings.
    pub(super) fn shots(&self, pose: Pose) -> Vec<Vec<Vec3>> {
        let r = self.lattice.radius;
        let mut curves: Vec<Curve> = [1, -1]
            .into_iter()
            .filter_map(|side| turn_then_straight(pose, self.goal.truncate(), r, side))
            .map(|ts| Curve { turns: [ts.side, 0, 0], lengths: [r * ts.sweep, ts.straight, 0.0] })
            .collect();
        for k in 0..self.goal_headings {
            let h = std::f64::consts::TAU * k as f64 / self.goal_headings as f64;
            if let Some(d) = Dubins::shortest(pose, Pose::new(self.goal, h), r) {
                curves.push(Curve::of_dubins(&d));
            }
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
