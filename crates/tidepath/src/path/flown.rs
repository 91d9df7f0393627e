//! The evaluation of a vehicle with a turning radius: every check on the curve it flies.
//!
//! With `vehicle.turn_radius = Some(r)` the vehicle flies each polyline by the fillet model
//! ([`crate::kinematics::fillet`]): straight legs joined by circular turns of radius r. The
//! evaluation walks that curve as *motions*: each leg's straight part, and each turn as equal
//! chords that stray at most `settings.arc_tolerance` from the arc. Every motion goes through
//! the shared motion validator on the running clock (seabed, obstacles at the vehicle's own
//! time, current), so travel time, collisions and the current are judged where the vehicle
//! really is. A chord's time is scaled by the arc's length over the chord's, so in still water
//! the time is exactly the flown length over the speed.
//!
//! On top of the polyline's checks (waypoints in the domain and depth band, the waypoint angle
//! limit `max_turn`), a turn whose fillet does not fit in its legs is a violation, and pitch is
//! judged on the flown pieces (a straight part's slope, a turn's climb over its length).
//!
//! Reported times at waypoints: the departure at the start, the arrival at the goal, and at an
//! interior waypoint the moment the vehicle is halfway round its turn (closest to it).

use super::PathModel;
use crate::geom::Vec3;
use crate::kinematics::fillet::{self, Arc, FlownPiece};
use crate::validity::{MotionCheck, MotionIssue};

/// One motion of the flown curve: a straight part of leg `segment`, or chord `chord` of
/// `chords` of the turn at waypoint `segment + 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlownMotion {
    pub a: Vec3,
    pub b: Vec3,
    pub segment: usize,
    /// The turn this chord belongs to, with its chord index and count; `None` on a straight.
    pub turn: Option<(Arc, usize, usize)>,
}

/// The flown curve sampled at the motions' ends, with the arrival time at each point.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Flown {
    pub points: Vec<Vec3>,
    pub times: Vec<f64>,
}

impl PathModel<'_> {
    /// The vehicle's turning radius, when it has one.
    pub fn turn_radius(&self) -> Option<f64> {
        self.vehicle.turn_radius
    }

    /// Walks the curve flown along `points` with radius `r` from the departure time: `f` gets
    /// each motion, its check, and the times it is entered and left (the clock of the next);
    /// `on_issue` gets every issue of every motion, for the violation list. Returns the
    /// arrival time.
    pub fn walk_flown(
        &self,
        points: &[Vec3],
        r: f64,
        mut f: impl FnMut(&FlownMotion, &MotionCheck, f64, f64),
        mut on_issue: impl FnMut(&FlownMotion, f64, MotionIssue),
    ) -> f64 {
        let validator = &self.validator;
        let tol = self.settings.arc_tolerance;
        let mut t = self.departure_time;
        let mut fly = |m: FlownMotion, scale: f64, t: &mut f64| {
            let t0 = *t;
            let v = self.motion_speed(&m);
            let check = validator.motion_with_at(m.a, m.b, t0, v, |issue| on_issue(&m, t0, issue));
            *t = t0 + (check.arrival - t0) * scale;
            f(&m, &check, t0, *t);
        };
        fillet::for_each_piece(points, r, |piece| match piece {
            FlownPiece::Line { a, b, segment } => fly(FlownMotion { a, b, segment, turn: None }, 1.0, &mut t),
            FlownPiece::Arc(arc) => {
                let k = arc.chords(tol);
                if k == 0 {
                    return;
                }
                let (mut p, segment) = (arc.a, arc.waypoint - 1);
                // Equal chords: one scale turns each chord's time into its arc's.
                let chord_len = p.distance(arc.point(1.0 / k as f64));
                let arc_len = arc.horizontal_length().hypot(arc.b.z - arc.a.z) / k as f64;
                let scale = if chord_len > 0.0 { arc_len / chord_len } else { 1.0 };
                for c in 0..k {
                    let q = arc.point((c + 1) as f64 / k as f64);
                    fly(FlownMotion { a: p, b: q, segment, turn: Some((arc, c, k)) }, scale, &mut t);
                    p = q;
                }
            }
        });
        t
    }

    /// The through-water speed a flown motion is flown at: its leg's, and on a turn the
    /// incoming leg's for the first half of the chords and the outgoing leg's after (the speed
    /// changes where the vehicle is closest to the waypoint).
    pub fn motion_speed(&self, m: &FlownMotion) -> f64 {
        match m.turn {
            Some((_, c, k)) if 2 * c >= k => self.segment_speed(m.segment + 1),
            _ => self.segment_speed(m.segment),
        }
    }

    /// How many pieces of current integration judging `points` takes (the motions' pieces; a
    /// turn's chords each count), so callers can bound the work a hostile path asks for before
    /// starting it. Geometry only: no motion is checked.
    pub fn pieces_to_judge(&self, points: &[Vec3]) -> u64 {
        let v = &self.validator;
        let Some(r) = self.turn_radius() else {
            return points.windows(2).map(|w| u64::from(v.pieces_of(w[0].distance(w[1])))).sum();
        };
        let tol = self.settings.arc_tolerance;
        let mut n = 0u64;
        fillet::for_each_piece(points, r, |piece| match piece {
            FlownPiece::Line { a, b, .. } => n += u64::from(v.pieces_of(a.distance(b))),
            FlownPiece::Arc(arc) => {
                let k = arc.chords(tol) as u64;
                if k > 0 {
                    n += k * u64::from(v.pieces_of(arc.a.distance(arc.point(1.0 / k as f64))));
                }
            }
        });
        n
    }

    /// The flown curve of `points` (the motions' ends) with the arrival time at each point, on
    /// the evaluation's clock; `None` when the vehicle has no turning radius (it then flies
    /// the polyline itself).
    pub fn flown(&self, points: &[Vec3]) -> Option<Flown> {
        let r = self.turn_radius()?;
        let mut out = Flown::default();
        let Some(&p0) = points.first() else { return Some(out) };
        out.points.push(p0);
        out.times.push(self.departure_time);
        self.walk_flown(
            points,
            r,
            |m, _, _, t1| {
                if m.a != m.b {
                    out.points.push(m.b);
                    out.times.push(t1);
                }
            },
            |_, _, _| {},
        );
        Some(out)
    }
}
