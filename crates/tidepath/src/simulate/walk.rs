//! Moving the vehicle along its route on the travel clock, and re-checking the track it flew.
//!
//! The vehicle flies each segment in the pieces of constant ground speed the shared validator
//! flies it in ([`Validator::for_each_piece`]), so positions at times come from the same clock
//! that judged the route; inside a piece the position is linear in time, so stopping there is
//! exact.

use crate::geom::Vec3;
use crate::validity::{MotionIssue, Validator};
use crate::world::changes::{center, Trigger};
use crate::world::{Obstacle, Shape};

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

/// Something that stops the vehicle: a change's trigger, or a moving obstacle coming within
/// sensor range.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    Trigger(Trigger),
    /// `obstacle` (as it moves in the true world) is seen once its centre comes within `reach`
    /// of the vehicle: the sensor range plus the obstacle's bounding radius.
    Sighting {
        obstacle: Obstacle,
        reach: f64,
    },
}

impl Event {
    /// A sighting of `obstacle` at sensor range `range` (m).
    pub fn sighting(obstacle: &Obstacle, range: f64) -> Event {
        Event::Sighting { obstacle: obstacle.clone(), reach: range + bounding_radius(&obstacle.shape) }
    }
}

/// The radius of the smallest ball (a disc for circles and cylinders) about the shape's
/// centre that holds it.
pub fn bounding_radius(s: &Shape) -> f64 {
    match *s {
        Shape::Sphere { radius, .. } | Shape::Circle { radius, .. } | Shape::Cylinder { radius, .. } => radius,
        Shape::Box { min, max } => 0.5 * min.distance(max),
    }
}

/// Whether a sighting compares horizontal distances only (discs and vertical cylinders).
fn horizontal(s: &Shape) -> bool {
    matches!(s, Shape::Circle { .. } | Shape::Cylinder { .. })
}

/// Whether `event` has fired for a vehicle at `p` at time `t` after `travelled` metres.
pub fn due(event: &Event, p: Vec3, t: f64, travelled: f64) -> bool {
    match event {
        Event::Trigger(Trigger::AtTime(at)) => *at <= t,
        Event::Trigger(Trigger::AfterDistance(d)) => *d <= travelled,
        Event::Sighting { .. } => fires_at(event, p, p, t, t, travelled) == Some(0.0),
    }
}

/// The fraction of the piece from (`p0`, `t0`) to (`p1`, `t1`), entered after `travelled`
/// metres, at which `event` fires, if it does within the piece. A sighting solves
/// |a + s b| = reach for the first s in [0, 1], with a the vehicle's offset from the
/// obstacle's centre at the piece's start and b its change over the piece (both move
/// linearly in time along a piece).
fn fires_at(event: &Event, p0: Vec3, p1: Vec3, t0: f64, t1: f64, travelled: f64) -> Option<f64> {
    match event {
        Event::Trigger(Trigger::AtTime(at)) if *at <= t1 => {
            Some(if t1 > t0 { ((at - t0) / (t1 - t0)).clamp(0.0, 1.0) } else { 0.0 })
        }
        Event::Trigger(Trigger::AfterDistance(d)) => {
            let len = p0.distance(p1);
            (travelled + len >= *d).then(|| if len > 0.0 { ((d - travelled) / len).clamp(0.0, 1.0) } else { 0.0 })
        }
        Event::Trigger(_) => None,
        Event::Sighting { obstacle, reach } => {
            let c0 = center(&obstacle.shape_at(t0));
            let c1 = center(&obstacle.shape_at(t1));
            let flat = |v: Vec3| if horizontal(&obstacle.shape) { Vec3::new(v.x, v.y, 0.0) } else { v };
            let a = flat(p0 - c0);
            let b = flat((p1 - p0) - (c1 - c0));
            let r2 = reach * reach;
            let c = a.length_squared() - r2;
            if c <= 0.0 {
                return Some(0.0);
            }
            let (qa, qb) = (b.length_squared(), a.dot(b));
            let disc = qb * qb - qa * c;
            if qa == 0.0 || disc < 0.0 || qb >= 0.0 {
                return None;
            }
            // The smaller root of qa s^2 + 2 qb s + c = 0, in the stable form.
            let s = c / (-qb + disc.sqrt());
            (s <= 1.0).then_some(s.max(0.0))
        }
    }
}

/// Flies `route` (its first point is where the track ends) until the first of `pending`
/// fires, appending every waypoint passed and the stopping point to `track`. Returns which
/// event fired (its index in `pending`; the first listed on a tie) and the route still
/// ahead (starting at the vehicle's position), or `None` when the vehicle reached the route's
/// end first. The fired event is returned rather than re-tested, so rounding in the stop
/// time can never leave it pending.
pub fn advance(v: &Validator<'_>, route: &[Vec3], pending: &[Event], track: &mut Track) -> Option<(usize, Vec<Vec3>)> {
    for (i, w) in route.windows(2).enumerate() {
        let (_, t0) = track.now();
        let mut stop: Option<(usize, Vec3, f64)> = None;
        let mut travelled = track.travelled;
        v.for_each_piece(w[0], w[1], t0, |pc| {
            if stop.is_some() {
                return;
            }
            let mut first: Option<(usize, f64)> = None;
            for (k, g) in pending.iter().enumerate() {
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
        let (p, t) = settle(v, w[0], w[1], t0, p, t, &pending[k]);
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

/// The stop point and time on the track's own clock. The track is judged (and re-flown by
/// any checker) segment by segment, and a segment cut at `p` is flown in pieces of its own,
/// whose ground speeds in a varying current differ slightly from those of the whole
/// segment's pieces: the stop time is therefore the arrival of the cut segment `a -> p`
/// flown from `t0`. For a clock trigger, `p` is moved along `a -> b` (bisection, the arrival
/// grows with the distance) until that arrival is the trigger's time, so the change still
/// applies when it says. In still water or a uniform current the cut is already exact.
fn settle(v: &Validator<'_>, a: Vec3, b: Vec3, t0: f64, p: Vec3, t: f64, event: &Event) -> (Vec3, f64) {
    let arrival = |q: Vec3| v.for_each_piece(a, q, t0, |_| {}).0;
    let tp = arrival(p);
    if (tp - t).abs() <= 1e-12 * t.abs().max(1.0) {
        return (p, t);
    }
    let Event::Trigger(Trigger::AtTime(at)) = *event else {
        return (p, tp);
    };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    let mut best = (p, tp);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        let q = a.lerp(b, mid);
        let tq = arrival(q);
        if (tq - at).abs() < (best.1 - at).abs() {
            best = (q, tq);
        }
        if tq < at {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    best
}

/// Every way the flown track breaks the rules of the world in force when the vehicle was
/// there: `worlds` holds, in time order, each validator with the time from which its world
/// holds (the first from departure). Each point is judged at its time and each segment
/// leaving at its time (moving obstacles where they were then) in the world in force at that
/// time; the loop stops the vehicle at every change, so no segment spans two worlds. The
/// times are the track's own; a segment's arrival is re-flown through its world's current.
pub fn track_violations(worlds: &[(f64, Validator<'_>)], points: &[Vec3], times: &[f64]) -> Vec<String> {
    let at = |t: f64| &worlds[worlds.iter().rposition(|(from, _)| *from <= t).unwrap_or(0)].1;
    let mut out = Vec::new();
    for (i, (&p, &t)) in points.iter().zip(times).enumerate() {
        let v = at(t);
        if let Err(issue) = v.state(p, t) {
            out.push(format!("track point {i} at t = {t:.1} s: {}", v.describe(p, issue)));
        }
    }
    for (i, (w, &t)) in points.windows(2).zip(times).enumerate() {
        if let Some(issue) = at(t).motion(w[0], w[1], t).first {
            let what = match issue {
                MotionIssue::Terrain => "comes closer to the seabed than the safety distance".to_string(),
                MotionIssue::Obstacle(k) => format!("comes closer to obstacle {k} than the safety distance"),
                MotionIssue::Current { pieces } => format!("the current stops the vehicle on {pieces} pieces"),
                MotionIssue::NoCurrentData => "passes where the current forecast has no data".to_string(),
                MotionIssue::NoWaveData => "passes where the wave forecast has no data".to_string(),
            };
            out.push(format!("track segment {i} leaving at t = {t:.1} s {what}"));
        }
    }
    out
}
