//! amfa2015's contracting operator (section 4.3.2, eq. 10, read as A10 of
//! docs/papers/amfa2015.md): each interior route point, in order along the path, is pulled part
//! of the way toward the midpoint of its neighbours,
//!
//! P'_i = P_i + k ((P'_{i−1} + P_{i+1}) / 2 − P_i),
//!
//! with P'_{i−1} already moved and k the resistance coefficient (0.9553 in the paper). The
//! printed eq. 10 sums the two pulls without halving them, which with k > 1/2 overshoots the
//! midpoint; A10 reads it as a pull toward the midpoint. A pull whose new point would be an
//! invalid state (inside an obstacle or the seabed by the safety distance, out of the domain or
//! the depth band, where the current has no data; moving obstacles at the vehicle's arrival
//! there) is undone for that point, which then stays where it was; so is a pull that would make
//! one of the point's two segments invalid when it was valid before (a chord cutting into a
//! curved obstacle between two points on its envelope, which amfa2015's point-counted risk
//! does not see). So contracting never makes a valid segment invalid: a feasible path stays
//! feasible, at the price of up to four motion checks per point.

use super::{arrival, Repair, RESISTANCE, RESISTANCE_RANGE};
use crate::geom::Vec3;
use crate::params::Checked;
use crate::path::PathModel;

crate::params! {
    /// Contracting parameters.
    pub struct ContractParams {
        /// Resistance coefficient k: the fraction of the way toward the neighbours' midpoint a
        /// point moves.
        k: f64 = RESISTANCE, RESISTANCE_RANGE, "amfa2015 eq. 10 and section 5.2";
    }
}

/// The contracting operator.
#[derive(Clone, Debug)]
pub struct Contract {
    k: f64,
}

impl Default for Contract {
    fn default() -> Self {
        Self { k: RESISTANCE }
    }
}

impl Contract {
    pub fn new(params: Checked<ContractParams>) -> Self {
        Self::with_k(params.into_inner().k)
    }

    pub(crate) fn with_k(k: f64) -> Self {
        Self { k }
    }
}

impl Repair for Contract {
    fn id(&self) -> &'static str {
        "contract"
    }

    fn apply(&self, model: &PathModel<'_>, points: &mut [Vec3]) {
        let n = points.len();
        if n < 3 {
            return;
        }
        let mut t_prev = model.departure_time;
        for i in 1..n - 1 {
            let (prev, p, next) = (points[i - 1], points[i], points[i + 1]);
            let target = p + ((prev + next) * 0.5 - p) * self.k;
            let t = arrival(model, i - 1, prev, target, t_prev);
            if model.validator.state(target, t).is_ok() && keeps_segments(model, i, [prev, p, next], target, t_prev) {
                points[i] = target;
                t_prev = t;
            } else {
                t_prev = arrival(model, i - 1, prev, p, t_prev);
            }
        }
    }
}

/// Whether moving point `i` from `p` to `target` (neighbours `prev` and `next`, leaving `prev`
/// at `t_prev`) leaves each of its two segments valid that was valid before. The new segments
/// are judged first; the old ones only when a new one fails.
fn keeps_segments(model: &PathModel<'_>, i: usize, [prev, p, next]: [Vec3; 3], target: Vec3, t_prev: f64) -> bool {
    let v = &model.validator;
    let (v_in, v_out) = (model.segment_speed(i - 1), model.segment_speed(i));
    let new_in = v.motion_at(prev, target, t_prev, v_in);
    let new_out = v.motion_at(target, next, new_in.arrival, v_out);
    if new_in.valid() && new_out.valid() {
        return true;
    }
    let old_in = v.motion_at(prev, p, t_prev, v_in);
    let old_out = v.motion_at(p, next, old_in.arrival, v_out);
    (new_in.valid() || !old_in.valid()) && (new_out.valid() || !old_out.valid())
}
