//! The amfa2015 cost model (eqs. 6-8): path length plus a risk that counts sampled points
//! inside obstacles or the seabed. See `docs/papers/amfa2015.md`, section "cost" and A11.
//!
//! E = w1 E_L + w2 E_D, with w1 + w2 = 1 (eq. 6)
//!
//! - E_L (eq. 7) = |S P_1| + sum_j |P_j P_j+1| + |P_n G|: the 3-D Euclidean length in metres
//!   of the polyline from the start through the route points to the goal (the paper scales
//!   horizontal lengths to degrees; tidepath worlds are in metres throughout).
//! - E_D (eq. 8) = C (k1 + k2).
//!   - k1 counts the route points P_1 ... P_n (every point of the path but its first and last,
//!     the mission's start and goal) that are "inside".
//!   - k2 counts, on every segment (start -> P_1, ..., P_n -> goal, so n + 1 segments), the m
//!     evaluation points that are "inside". The evaluation points of segment a -> b are
//!     a + (i / (m + 1)) (b - a), i = 1 ... m: m interior points evenly spaced, neither end
//!     (the ends are route points, counted by k1, or the start and goal).
//!   - "Inside" is tidepath's point check, [`crate::validity::Validator::state`], at the
//!     time the vehicle reaches the point: a point counts when the validator rejects it, that
//!     is when it lies within the vehicle's safety distance of the seabed (vertically) or of an
//!     obstacle, outside the domain or the vehicle's depth band, or where the current forecast
//!     has no data. With a safety distance of 0 this is the paper's "inside obstacles" (the
//!     seabed is an obstacle; A14); with a safety distance it is inside the inflated
//!     obstacles the validator tests, so a path with k1 = k2 = 0 passes every point check
//!     tidepath would make at those points.
//!   - C (`risk_coefficient`) is |SG|, the straight start-goal distance of the mission, by
//!     default, so one point inside costs about one straight-line length (A11); a number in
//!     the parameters replaces it (metres of cost per point). When start and goal coincide the
//!     default is 1.
//! - Time: each point is tested at the vehicle's arrival time there, on the same clock as
//!   tidepath's evaluation (segments flown in pieces at the ground speed through the currents,
//!   at each segment's speed, leaving at the mission's departure time), so a moving obstacle
//!   is tested where it is when the vehicle passes. The clock is the polyline's: with a
//!   turning radius tidepath flies arcs at the joints, which the paper's point vehicle does
//!   not; tidepath's own check judges the flown curve.
//!
//! Counting points is coarser than tidepath's exact segment check: a segment can graze an
//! obstacle between two evaluation points (k2 = 0) and still be a collision, so E_D = 0 does
//! not prove a path collision-free. Plans are reported feasible or infeasible by tidepath's
//! checker ([`crate::path::PathModel::assess`]), never by this count. The converse holds: a
//! path that tidepath's checker finds collision-free has E_D = 0 (its points all pass
//! the point check on the same clock).
//!
//! Terms reported (their sum is E): `length` = w1 E_L, `risk_k1` = w2 C k1 and `risk_k2` =
//! w2 C k2 (so w2 E_D = `risk_k1` + `risk_k2`). The counts themselves are
//! [`Amfa2015Cost::counts`].
//!
//! Graph and sampling planners build paths edge by edge: a valid motion costs w1 |ab| (its
//! evaluation points all pass the point check, as the motion check is exact and at least as
//! strict), so `length` is the model's additive term; `risk_k1` and `risk_k2` are
//! path-level (zero on any path of valid motions).

use super::CostModel;
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::params::{Bound, Checked, Range};
use crate::path::PathModel;
use crate::scratch::Scratch;

crate::params! {
    /// The amfa2015 model's parameters (`[cost] weights`); w1 + w2 = 1 as the paper states.
    pub struct Amfa2015Params {
        /// w1, the weight of the path length E_L (metres); w_length + w_risk must be 1.
        w_length: f64 = 0.5, UNIT, "tidepath (not given in amfa2015)";
        /// w2, the weight of the risk E_D = C (k1 + k2); w_length + w_risk must be 1.
        w_risk: f64 = 0.5, UNIT, "tidepath (not given in amfa2015)";
        /// m, evaluation points on every segment, at i / (m + 1) of its length, i = 1 ... m.
        eval_points: usize = 10, Range::integer(1, 1000), "tidepath (not given in amfa2015)";
        /// C, cost per point inside (metres); absent: |SG|, the mission's straight start-goal
        /// distance (1 when start and goal coincide).
        risk_coefficient: Option<f64> = None, POSITIVE, "tidepath (not given in amfa2015)";
    }
    check = weights_sum_to_one;
}

const UNIT: Range = Range::closed(0.0, 1.0);
const POSITIVE: Range = Range::Number { lo: Bound::Open(0.0), hi: Bound::Unbounded };

/// How far w1 + w2 may stray from 1 (decimal weights such as 0.3 + 0.7 round).
pub const WEIGHT_SUM_TOLERANCE: f64 = 1e-9;

fn weights_sum_to_one(p: &Amfa2015Params, prefix: &str) -> Result<()> {
    let sum = p.w_length + p.w_risk;
    // Both weights passed their ranges (finite) before this rule runs.
    if (sum - 1.0).abs() > WEIGHT_SUM_TOLERANCE {
        return Err(Error::input(
            prefix,
            format!("w_length + w_risk must be 1 (amfa2015, eq. 6), got {} + {} = {sum}", p.w_length, p.w_risk),
        ));
    }
    Ok(())
}

#[derive(Clone, Debug)]
pub struct Amfa2015Cost {
    pub params: Amfa2015Params,
}

const TERMS: [&str; 3] = ["length", "risk_k1", "risk_k2"];

impl Amfa2015Cost {
    pub fn new(params: Checked<Amfa2015Params>) -> Self {
        Self { params: params.into_inner() }
    }

    /// C for the mission of `model`: the parameter, or |SG| (1 when S = G).
    pub fn risk_coefficient(&self, model: &PathModel<'_>) -> f64 {
        self.params.risk_coefficient.unwrap_or_else(|| {
            let d = model.start.distance(model.goal);
            if d > 0.0 {
                d
            } else {
                1.0
            }
        })
    }

    /// Is `p` "inside" at time `t`: rejected by tidepath's point check?
    #[inline]
    fn inside(model: &PathModel<'_>, p: Vec3, t: f64) -> bool {
        model.validator.state(p, t).is_err()
    }

    /// (k1, k2) of `points` (start and goal included) on the evaluation's clock. No
    /// allocation.
    pub fn counts(&self, model: &PathModel<'_>, points: &[Vec3]) -> (usize, usize) {
        let n = points.len();
        if n < 2 {
            return (0, 0);
        }
        let m = self.params.eval_points;
        let step = 1.0 / (m + 1) as f64;
        let validator = &model.validator;
        let (mut k1, mut k2) = (0, 0);
        let mut t = model.departure_time;
        for (seg, w) in points.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            let len = a.distance(b);
            // The next evaluation point of this segment not yet tested (1-based).
            let mut next = 1;
            let (arrival, _) = validator.for_each_piece_at(a, b, t, model.segment_speed(seg), |pc| {
                // The piece covers the fractions [s0, s1] of the segment, flown from t0 to t1.
                let (s0, s1) = if len > 0.0 { (a.distance(pc.p0) / len, a.distance(pc.p1) / len) } else { (0.0, 1.0) };
                while next <= m {
                    let s = next as f64 * step;
                    if s > s1 {
                        break;
                    }
                    let frac = if s1 > s0 { ((s - s0) / (s1 - s0)).clamp(0.0, 1.0) } else { 0.0 };
                    let time = pc.t0 + (pc.t1 - pc.t0) * frac;
                    k2 += usize::from(Self::inside(model, a.lerp(b, s), time));
                    next += 1;
                }
            });
            // Points the pieces' rounding left out lie at the segment's end.
            while next <= m {
                k2 += usize::from(Self::inside(model, a.lerp(b, next as f64 * step), arrival));
                next += 1;
            }
            t = arrival;
            if seg + 2 < n {
                // b is route point P_(seg+1), reached at `arrival`.
                k1 += usize::from(Self::inside(model, b, t));
            }
        }
        (k1, k2)
    }
}

impl CostModel for Amfa2015Cost {
    fn id(&self) -> &'static str {
        "amfa2015"
    }

    fn term_names(&self) -> &'static [&'static str] {
        &TERMS
    }

    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], _scratch: &mut Scratch, terms: &mut [f64]) -> f64 {
        // Needs no buffer: the clock and the counts run along the path.
        let (k1, k2) = self.counts(model, points);
        let p = &self.params;
        let c = self.risk_coefficient(model);
        terms[0] = p.w_length * PathModel::length(points);
        terms[1] = p.w_risk * c * k1 as f64;
        terms[2] = p.w_risk * c * k2 as f64;
        terms[..3].iter().sum()
    }

    fn additive_terms(&self) -> &'static [&'static str] {
        &TERMS[..1]
    }

    fn motion_lower_bound(&self, _model: &PathModel<'_>, distance: f64, _max_ground_speed: f64) -> f64 {
        self.params.w_length * distance
    }

    /// w1 per metre, in any current.
    fn cost_per_metre(&self, _model: &PathModel<'_>) -> Option<f64> {
        Some(self.params.w_length)
    }

    /// A valid motion with its end in bounds costs w1 |ab|: its evaluation points pass the
    /// point check, so it adds no risk.
    fn motion_cost_at(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64, v: f64) -> Option<(f64, f64)> {
        if model.validator.in_bounds(b).is_err() {
            return None;
        }
        let m = model.validator.motion_at(a, b, t0, v);
        if !m.valid() {
            return None;
        }
        Some((self.params.w_length * a.distance(b), m.arrival))
    }
}

/// Builds the model from `[cost.weights]`.
pub fn build(table: &toml::Table) -> Result<Box<dyn CostModel>> {
    Ok(Box::new(Amfa2015Cost::new(Amfa2015Params::from_table(table, "cost.weights")?)))
}

#[cfg(test)]
mod tests;
