//! A vehicle's timed path as legs of constant ground speed, on the evaluation's own clock.

use crate::geom::Vec3;
use crate::path::PathModel;

/// From `p0` at `t0` to `p1` at `t1`, at constant velocity.
pub type Leg = (Vec3, Vec3, f64, f64);

/// The legs the vehicle of `model` flies along `points` (the polyline, or with a turning
/// radius the flown curve's chords), each cut into the pieces of constant ground speed the
/// validator flies it in. Stops at a piece the current blocks (its time is not finite).
pub fn timed_legs(model: &PathModel<'_>, points: &[Vec3], out: &mut Vec<Leg>) {
    out.clear();
    let v = &model.validator;
    let fly = |a: Vec3, b: Vec3, t0: f64, speed: f64, out: &mut Vec<Leg>| -> f64 {
        let (t1, _) = v.for_each_piece_at(a, b, t0, speed, |pc| {
            if pc.t1.is_finite() && pc.t0.is_finite() {
                out.push((pc.p0, pc.p1, pc.t0, pc.t1));
            }
        });
        t1
    };
    match model.turn_radius() {
        Some(r) => {
            let mut stopped = false;
            model.walk_flown(
                points,
                r,
                |m, _, t0, _| {
                    stopped |= !t0.is_finite();
                    if !stopped && m.a != m.b {
                        fly(m.a, m.b, t0, model.motion_speed(m), out);
                    }
                },
                |_, _, _| {},
            );
        }
        None => {
            let mut t = model.departure_time;
            for (i, w) in points.windows(2).enumerate() {
                if !t.is_finite() {
                    return;
                }
                t = fly(w[0], w[1], t, model.segment_speed(i), out);
            }
        }
    }
}
