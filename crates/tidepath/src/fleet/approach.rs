//! The exact closest approach of two timed paths.

use super::{Leg, Presence};
use crate::geom::Vec3;

/// Where and when two vehicles come closest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Approach {
    pub distance: f64,
    pub time: f64,
    /// The two vehicles' positions then.
    pub at_a: Vec3,
    pub at_b: Vec3,
}

/// A stretch of linear motion: position `p` at time `t0`, velocity `v`, over [t0, t1]
/// (either end may be infinite for a vehicle waiting, whose velocity is 0).
#[derive(Clone, Copy, Debug)]
struct Stretch {
    p: Vec3,
    v: Vec3,
    t0: f64,
    t1: f64,
}

impl Stretch {
    fn at(&self, t: f64) -> Vec3 {
        if self.v == Vec3::ZERO {
            self.p
        } else {
            self.p + self.v * (t - self.t0)
        }
    }
}

/// The vehicle's `k`-th stretch: with [`Presence::Stays`] the wait at the start, each leg,
/// the stay at the goal; with [`Presence::Leaves`] the legs alone. Indexed rather than
/// collected, so a check allocates nothing.
fn stretch(legs: &[Leg], presence: Presence, k: usize) -> Stretch {
    let leg = |&(p0, p1, t0, t1): &Leg| {
        let v = if t1 > t0 { (p1 - p0) / (t1 - t0) } else { Vec3::ZERO };
        Stretch { p: p0, v, t0, t1 }
    };
    match presence {
        Presence::Leaves => leg(&legs[k]),
        Presence::Stays if k == 0 => Stretch { p: legs[0].0, v: Vec3::ZERO, t0: f64::NEG_INFINITY, t1: legs[0].2 },
        Presence::Stays if k <= legs.len() => leg(&legs[k - 1]),
        Presence::Stays => {
            let last = legs[legs.len() - 1];
            Stretch { p: last.1, v: Vec3::ZERO, t0: last.3, t1: f64::INFINITY }
        }
    }
}

fn stretch_count(legs: &[Leg], presence: Presence) -> usize {
    match presence {
        Presence::Leaves => legs.len(),
        Presence::Stays => legs.len() + 2,
    }
}

/// The closest approach of the vehicles flying `a` and `b` (legs in time order), or `None`
/// when they are never in the water at the same time. On each interval where both are in one
/// stretch, the distance is |r + w s| for s in [0, hi - lo] with r their offset at the
/// interval's start and w their relative velocity: least at s = -r.w / |w|^2, clamped. The
/// earliest time wins a tie.
pub fn closest_approach(a: &[Leg], b: &[Leg], presence: Presence) -> Option<Approach> {
    if a.is_empty() || b.is_empty() {
        return None;
    }
    let (na, nb) = (stretch_count(a, presence), stretch_count(b, presence));
    let (mut i, mut j) = (0, 0);
    let mut best: Option<Approach> = None;
    while i < na && j < nb {
        let (x, y) = (stretch(a, presence, i), stretch(b, presence, j));
        let (lo, hi) = (x.t0.max(y.t0), x.t1.min(y.t1));
        if lo <= hi {
            // A finite reference time in the interval (both infinite only for two waiting
            // vehicles, whose offset is constant).
            let t_ref = if lo.is_finite() {
                lo
            } else if hi.is_finite() {
                hi
            } else {
                0.0
            };
            let r = x.at(t_ref) - y.at(t_ref);
            let w = x.v - y.v;
            let ww = w.length_squared();
            let t = if ww > 0.0 {
                let s = -r.dot(w) / ww;
                (t_ref + s).clamp(lo, hi)
            } else {
                t_ref
            };
            let (pa, pb) = (x.at(t), y.at(t));
            let d = pa.distance(pb);
            if best.is_none_or(|b| d < b.distance) {
                best = Some(Approach { distance: d, time: t, at_a: pa, at_b: pb });
            }
        }
        if x.t1 <= y.t1 {
            i += 1;
        } else {
            j += 1;
        }
    }
    best
}
