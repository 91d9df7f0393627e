//! Moving the vehicle along its route on the travel clock, and re-checking the track it flew.
//!
//! The vehicle flies each segment in the pieces of constant ground speed the shared validator
//! flies it in ([`Validator::for_each_piece`]), so positions at times come from the same clock
//! that judged the route; inside a piece the position is linear in time, so stopping there is
//! exact.

use crate::geom::Vec3;
use crate::validity::Validator;
use crate::world::changes::Trigger;

/// Where the vehicle has been: its points with arrival times, and the distance flown.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Track {
    pub points: Vec<Vec3>,
    pub times: Vec<f64>,
    pub travelled: f64,
}

impl Track {
    pub fn new(start: Vec3, t: f64) -> Self {
        Self { points: vec![start], times: vec![t], travelled: 0.0 }
    }

    /// The vehicle's position and time now.
    pub fn now(&self) -> (Vec3, f64) {
        (*self.points.last().expect("a track starts with a point"), *self.times.last().expect("and a time"))
    }

    fn push(&mut self, p: Vec3, t: f64) {
        self.travelled += self.now().0.distance(p);
        self.points.push(p);
        self.times.push(t);
    }
}

/// Whether `trigger` has fired for a vehicle at time `t` after `travelled` metres.
pub fn due(trigger: Trigger, t: f64, travelled: f64) -> bool {
    match trigger {
        Trigger::AtTime(at) => at <= t,
        Trigger::AfterDistance(d) => d <= travelled,
    }
}

/// The fraction of the piece from (`p0`, `t0`) to (`p1`, `t1`), entered after `travelled`
/// metres, at which `trigger` fires, if it does within the piece.
fn fires_at(trigger: Trigger, p0: Vec3, p1: Vec3, t0: f64, t1: f64, travelled: f64) -> Option<f64> {
    match trigger {
        Trigger::AtTime(at) if at <= t1 => Some(if t1 > t0 { ((at - t0) / (t1 - t0)).clamp(0.0, 1.0) } else { 0.0 }),
        Trigger::AfterDistance(d) => {
            let len = p0.distance(p1);
            (travelled + len >= d).then(|| if len > 0.0 { ((d - travelled) / len).clamp(0.0, 1.0) } else { 0.0 })
        }
        _ => None,
    }
}

/// Flies `route` (its first point is where the track ends) until the first of `pending`
/// fires, appending every waypoint passed and the stopping point to `track`. Returns which
/// trigger fired (its index in `pending`; the first listed on a tie) and the route still
/// ahead (starting at the vehicle's position), or `None` when the vehicle reached the route's
/// end first. The fired trigger is returned rather than re-tested, so rounding in the stop
/// time can never leave it pending.
pub fn advance(
    v: &Validator<'_>,
    route: &[Vec3],
    pending: &[Trigger],
    track: &mut Track,
) -> Option<(usize, Vec<Vec3>)> {
    for (i, w) in route.windows(2).enumerate() {
        let (_, t0) = track.now();
        let mut stop: Option<(usize, Vec3, f64)> = None;
        let mut travelled = track.travelled;
        v.for_each_piece(w[0], w[1], t0, |pc| {
            if stop.is_some() {
                return;
            }
            let mut first: Option<(usize, f64)> = None;
            for (k, &g) in pending.iter().enumerate() {
                if let Some(f) = fires_at(g, pc.p0, pc.p1, pc.t0, pc.t1, travelled) {
                    if first.is_none_or(|(_, best)| f < best) {
                        first = Some((k, f));
                    }
                }
            }
            match first {
                Some((k, f)) => stop = Some((k, pc.p0.lerp(pc.p1, f), pc.t0 + f * (pc.t1 - pc.t0))),
                None => travelled += pc.p0.distance(pc.p1),
            }
        });
        let Some((k, p, t)) = stop else {
            let (arrival, _) = v.for_each_piece(w[0], w[1], t0, |_| {});
            track.push(w[1], arrival);
            continue;
        };
        // A stop on the next waypoint itself keeps no zero-length segment in the route.
        let ahead = &route[i + 1..];
        if p == w[1] {
            track.push(p, t);
            return Some((k, ahead.to_vec()));
        }
        if p != w[0] {
            track.push(p, t);
        }
        return Some((k, std::iter::once(p).chain(ahead.iter().copied()).collect()));
    }
    None
}

/// Every way the flown track breaks the rules of `v`'s world: each point at its time and each
/// segment leaving at its time (moving obstacles where they were then). The times are the
/// track's own; the segment's arrival is re-flown through this world's current.
pub fn track_violations(v: &Validator<'_>, points: &[Vec3], times: &[f64]) -> Vec<String> {
    let mut out = Vec::new();
    for (i, (&p, &t)) in points.iter().zip(times).enumerate() {
        if let Err(issue) = v.state(p, t) {
            out.push(format!("track point {i} at t = {t:.1} s: {}", v.describe(p, issue)));
        }
    }
    for (i, (w, &t)) in points.windows(2).zip(times).enumerate() {
        if let Some(issue) = v.motion(w[0], w[1], t).first {
            out.push(format!("track segment {i} leaving at t = {t:.1} s: {issue:?}"));
        }
    }
    out
}
