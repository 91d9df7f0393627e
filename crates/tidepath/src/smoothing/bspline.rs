//! The `bspline` smoother: the B-spline with midpoint insertion of ijs2023 (the improved
//! jellyfish search paper, section III-D, eqs. 25–26, Fig. 8), which fits a curve to the
//! optimized waypoints so the path is smooth to fly. The curve is
//!
//! ```text
//! Sp(u) = Σᵢ φᵢ Bᵢ,ₖ(u)                                                  (eq. 25)
//! ```
//!
//! with the waypoints (and the points inserted between them) as control points φᵢ and the
//! Cox–de Boor basis of eq. 26 ([`curve::basis`]; evaluated by de Boor's algorithm,
//! [`curve::de_boor`]). Readings (docs/papers/shared.md, "Cubic B-spline with midpoint
//! insertion"; docs/papers/ijs2023.md A11):
//!
//! - **Eq. 26's second numerator** is printed (u_{i+n+1} − u); the recursion needs
//!   (u_{i+k+1} − u) (A11). B_{i,0} is printed on the open interval u_i < u < u_{i+1}, which
//!   makes every basis function vanish at a knot: read half-open, the last span closed.
//! - **"Order 3, i.e. k = 3"** with B_{i,0} the step functions is degree 3 (cubic, as the
//!   abstract's "cubic spline"): the `degree` parameter, default 3, lowered to m − 1 when the
//!   control polygon has only m ≤ degree points.
//! - **Knots:** "a node vector, typically taken in [0, 1]": clamped and uniform on [0, 1]
//!   ([`curve::clamped_knots`]), so the curve starts at the start and ends at the goal; both
//!   are written exactly.
//! - **Midpoint insertion** (Elbanhawi et al. 2015, ijs2023's reference 36; `midpoints`): before
//!   fitting, the midpoint of every leg of the control polygon is added as a control point,
//!   so the curve follows the legs more closely (Fig. 8).
//! - **Local correction** ("the AUV still needs to perform obstacle avoidance … the B-spline
//!   can act as a local correction"; no procedure is printed): where the sampled curve has a
//!   violation, the input legs under the control points of that knot span (a waypoint counts
//!   for the legs either side) get their pieces' midpoints inserted too, and the curve is
//!   refitted, up to `repair_depth` rounds. A leg cut into 2^L pieces holds the curve on the
//!   leg itself except within about 2^−L of its length of each end (four collinear control
//!   points make a cubic straight), so the repairs converge to the input polyline, which the
//!   planner found free.
//! - **Sampling:** `samples` equal parameter steps per knot span (a curve of degree p over m
//!   control points has m − p spans, about one per control-polygon leg); points on a straight
//!   stretch of the curve (within 1e-9 of the domain's size of the segment between their
//!   neighbours) are left out.
//!
//! **Contract.** Every fitted curve is judged as a whole path: its polyline goes through
//! [`PathModel::assess`] (the motion validator on the travel clock; with a turning radius the
//! flown curve) and the scenario's cost model, with a plan's segment speeds carried onto it as
//! the caller will ([`crate::path::resample_speeds`]). One path is better than another when it
//! is feasible and the other is not; among infeasible ones when it has fewer violations, then
//! a lower cost; among feasible ones when it costs less (the rule of the `dubins` smoother).
//! The best curve found is returned when it is no worse than the input judged the same way,
//! else the input unchanged: the trait's "never worse under cost, never infeasible when the
//! input is feasible" holds, as in `dubins` (its step 5). ijs2023 smooths for flyability and
//! keeps its curve whatever it costs; here a curve that is feasible but costlier than its
//! input (against a current, say) is declined. A B-spline is never longer than its control
//! polygon (knot insertion converges to it by cutting corners), and the sampled polyline is
//! inscribed in the curve, so in still water at one speed the result is never slower: it is
//! declined there only for a violation no repair clears. Elsewhere currents, moving obstacles
//! and the vehicle's pitch and turn limits (a curve that climbs while it turns can be steeper
//! than either leg) can make it decline. The [`Smoother`] trait has no way to say
//! that it declined: the plan shows it as a smoothed path equal to its waypoints.
//!
//! Each round (one fit, one judgement, and when it is infeasible one list of violations)
//! polls the termination first; when it fires, the best curve so far goes through the same
//! final comparison. Buffers (control polygon, knots, samples) are reused across rounds.

mod curve;

pub use curve::{basis, clamped_knots, de_boor, span_of, MAX_DEGREE};

use super::Smoother;
use crate::cost::CostModel;
use crate::geom::Vec3;
use crate::params::{Checked, Range};
use crate::path::{resample_speeds, PathModel, Violation};
use crate::scratch::Scratch;
use crate::termination::Termination;
use curve::Samples;

crate::params! {
    /// B-spline smoother parameters.
    pub struct BsplineParams {
        /// Degree of the B-spline (3: cubic); lowered to the control points less one when
        /// there are fewer.
        degree: usize = 3, Range::integer(1, MAX_DEGREE as u64), "ijs2023 eqs. 25-26 (k = 3)";
        /// Insert the midpoint of every control-polygon leg before fitting.
        midpoints: bool = true, Range::Flag, "ijs2023 Fig. 8 (Elbanhawi et al. 2015)";
        /// Curve points per knot span (about one span per control-polygon leg).
        samples: usize = 8, Range::integer(1, 256), "tidepath";
        /// Rounds of refitting with the midpoints of the pieces inserted where the curve has
        /// violations (0: the first fit or the input).
        repair_depth: usize = 4, Range::integer(0, 8), "tidepath (ijs2023 section III-D, local correction)";
    }
}

#[derive(Clone, Debug, Default)]
pub struct BsplineSmoother {
    params: BsplineParams,
}

impl BsplineSmoother {
    pub fn new(params: Checked<BsplineParams>) -> Self {
        Self { params: params.into_inner() }
    }
}

impl Smoother for BsplineSmoother {
    fn id(&self) -> &'static str {
        "bspline"
    }

    fn smooth(
        &self,
        model: &PathModel<'_>,
        cost: &dyn CostModel,
        points: &[Vec3],
        termination: &Termination,
    ) -> Vec<Vec3> {
        // Two points are already a straight line; a non-finite point has no curve.
        if points.len() < 3 || !points.iter().all(|p| p.is_finite()) || termination.interrupted().is_some() {
            return points.to_vec();
        }
        let mut run = Run { model, cost, original: points, scratch: Scratch::default() };
        let input = run.score(points);
        match self.best_curve(&mut run, termination) {
            Some((path, score)) if !input.better_than(&score) => path,
            _ => points.to_vec(),
        }
    }
}

impl BsplineSmoother {
    /// The best curve of the fit and its repairs, with its score; `None` when the termination
    /// fired before the first fit was judged.
    fn best_curve(&self, run: &mut Run<'_, '_>, termination: &Termination) -> Option<(Vec<Vec3>, Score)> {
        let points = run.original;
        let first = u8::from(self.params.midpoints);
        let cap = first + self.params.repair_depth as u8;
        let mut fit = Fit::new(points.len(), first);
        let tol = run.model.endpoint_tolerance();
        let mut best: Option<(Vec<Vec3>, Score)> = None;
        for round in 0..=self.params.repair_depth {
            if termination.interrupted().is_some() {
                break;
            }
            fit.fit(points, self.params.degree, self.params.samples, tol);
            let score = run.score(&fit.samples.points);
            if best.as_ref().is_none_or(|(_, b)| score.better_than(b)) {
                best = Some((fit.samples.points.clone(), score));
            }
            if score.feasible() || round == self.params.repair_depth || termination.interrupted().is_some() {
                break;
            }
            let violations = run.violations(&fit.samples.points);
            if !fit.refine(&violations, cap) {
                break;
            }
        }
        best
    }
}

/// How good a path is: feasible first, then fewer violations, then cost (as `dubins`).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Score {
    violations: u32,
    cost: f64,
}

impl Score {
    fn feasible(&self) -> bool {
        self.violations == 0
    }

    fn better_than(&self, other: &Score) -> bool {
        match (self.feasible(), other.feasible()) {
            (true, false) => true,
            (false, true) => false,
            (true, true) => self.cost < other.cost,
            (false, false) => {
                self.violations < other.violations || (self.violations == other.violations && self.cost < other.cost)
            }
        }
    }
}

/// The judge: the model, the cost and the input whose speeds a curve takes over.
struct Run<'a, 'm> {
    model: &'a PathModel<'m>,
    cost: &'a dyn CostModel,
    original: &'a [Vec3],
    scratch: Scratch,
}

impl Run<'_, '_> {
    /// `f` with the model judging `points`: the plan's segment speeds, if any, carried from
    /// the input onto them.
    fn with_model<R>(&mut self, points: &[Vec3], f: impl FnOnce(&PathModel<'_>, &mut Scratch) -> R) -> R {
        match self.model.speeds {
            Some(v) if points != self.original => {
                let moved = resample_speeds(self.original, v, points);
                f(&self.model.with_speeds(Some(&moved)), &mut self.scratch)
            }
            _ => f(self.model, &mut self.scratch),
        }
    }

    fn score(&mut self, points: &[Vec3]) -> Score {
        let cost = self.cost;
        self.with_model(points, |m, scratch| {
            let violations = m.assess(points, &mut scratch.times).violation_count();
            let c = cost.cost(m, points, scratch);
            Score { violations, cost: if c.is_nan() { f64::INFINITY } else { c } }
        })
    }

    fn violations(&mut self, points: &[Vec3]) -> Vec<Violation> {
        self.with_model(points, |m, _| m.violations(points))
    }
}

/// The fit's state: the level of each input leg (cut into 2^level pieces) and the buffers.
struct Fit {
    levels: Vec<u8>,
    ctrl: Vec<Vec3>,
    legs: Vec<(u32, u32)>,
    knots: Vec<f64>,
    /// The degree used (the parameter, at most the control points less one).
    degree: usize,
    samples: Samples,
}

impl Fit {
    fn new(n: usize, first: u8) -> Self {
        Self {
            levels: vec![first; n - 1],
            ctrl: Vec::new(),
            legs: Vec::new(),
            knots: Vec::new(),
            degree: 0,
            samples: Samples::default(),
        }
    }

    /// Builds the control polygon at the current levels and samples its curve.
    fn fit(&mut self, points: &[Vec3], degree: usize, per_span: usize, tol: f64) {
        curve::control_polygon(points, &self.levels, &mut self.ctrl, &mut self.legs);
        let m = self.ctrl.len();
        self.degree = degree.min(m - 1);
        curve::clamped_knots(m, self.degree, &mut self.knots);
        curve::sample(&self.ctrl, &self.knots, self.degree, per_span, tol, &mut self.samples);
    }

    /// Raises by one level (below `cap`) every input leg under the knot spans of the
    /// violations: for a violation at point or segment k, the spans of points k − 1 .. k + 1.
    /// `false` when no level changed.
    fn refine(&mut self, violations: &[Violation], cap: u8) -> bool {
        let spans = &self.samples.spans;
        let last = spans.len() - 1;
        let mut raise = vec![false; self.levels.len()];
        for v in violations {
            let k = v.index.min(last);
            let (s0, s1) = (spans[k.saturating_sub(1)] as usize, spans[(k + 1).min(last)] as usize);
            // Span s is shaped by control points s ..= s + degree.
            let lo = self.legs[s0].0 as usize;
            let hi = self.legs[(s1 + self.degree).min(self.legs.len() - 1)].1 as usize;
            raise[lo..=hi].iter_mut().for_each(|r| *r = true);
        }
        let mut changed = false;
        for (level, r) in self.levels.iter_mut().zip(raise) {
            if r && *level < cap {
                *level += 1;
                changed = true;
            }
        }
        changed
    }
}

#[cfg(test)]
mod tests;
