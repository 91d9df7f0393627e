//! The `dubins` smoother: any planner's polyline turned into a chain of Dubins curves (Dubins
//! 1957) through a subset of its waypoints, written as a tangent polygon so a vehicle with a
//! turning radius flies exactly those arcs and straights ([`crate::kinematics`]). wpa2017
//! (Zhang et al. 2017, IEEE Access) smooths its wolf-pack paths this way.
//!
//! **Radius.** The `radius` parameter, or the vehicle's `turn_radius` when it is absent. With
//! neither there is no curvature to respect: the smoother returns its input unchanged (the
//! evaluation of such a vehicle judges only the angle at each waypoint). Arcs are cut into
//! pieces of at most min(`max_piece_deg`, 0.9 `max_turn`), so each polygon vertex also keeps
//! the vehicle's waypoint angle limit.
//!
//! **Curves.** Between two kept waypoints with headings, the shortest of the six words (LSL,
//! LSR, RSL, RSR, RLR, LRL; [`Dubins`]). In a 3-D world the Dubins-airplane curve with the
//! vehicle's pitch limit ([`Dubins3`]: the climb spread evenly, a partial pre-turn and whole
//! helical turns when the height change is too large for the horizontal curve), planned a
//! hair (1e-9 relative) below the limit so rounding never makes the flown pitch a violation.
//!
//! **Headings** (`headings`). At the start and the goal the direction of the first and last
//! leg; at an interior waypoint the bisector of its two legs (`bisector`, the default: the
//! curve passes the waypoint halfway through its turn) or the direction of its incoming leg
//! (`incoming`: the vehicle passes on its track and turns after). Legs join kept waypoints,
//! so dropping a waypoint changes its neighbours' headings.
//!
//! Every candidate below is judged as a whole path: the assembled tangent polygon goes
//! through [`PathModel::assess`] (the motion validator on the travel clock, with the
//! vehicle's radius: the flown curve) and the scenario's cost model. One path is *better*
//! than another when it is feasible and the other is not; among infeasible ones when it has
//! fewer violations, then a lower cost; among feasible ones when it costs less.
//!
//! 1. **Merging.** Waypoints horizontally within 1e-6 r of the previous kept one are merged
//!    into it (a heading between them is rounding noise).
//! 2. **Dropping** (the shortcut rule, as [`super::Shortcut`] on Dubins chains). Waypoints
//!    closer than the radius allows make loops: between poses less than about 2r apart whose
//!    headings differ, every Dubins curve circles. From each kept waypoint i, in order, the
//!    chain jumps to the farthest later waypoint j whose chain is no worse, dropping the ones
//!    between. A jump is judged only when its new curves (into i, whose heading changes, and
//!    from i to j; for a feasible chain also the one after j) pass the motion validator on
//!    their own, on the clock the chain reaches them: a jump never brings in a curve with
//!    violations of its own.
//! 3. **Heading improvement.** For each kept waypoint in order, the headings `heading_step_deg`
//!    x 1 .. `heading_trials` either side of its rule's are tried; one is kept when the path
//!    is better (so, for a feasible chain, cheaper and still feasible).
//! 4. **Repair**, while the chain is infeasible: for each curve with violations of its own,
//!    in order, (a) the other five words between the same poses, shortest first; (b) the
//!    original waypoints dropped between its ends, back in the chain; (c) up to
//!    `repair_depth` times, the midpoints of the original polyline's legs between its ends
//!    added as waypoints (the curve is pulled towards the polyline the planner found free).
//!    Each is kept when the path is better; then the heading improvement runs again.
//! 5. **Never worse.** The result is the chain when it is no worse than the input polyline
//!    judged the same way, else the input unchanged: a feasible input is never made
//!    infeasible or costlier, and an infeasible one (with a radius, usually its corners that
//!    the fillets cannot fly) is replaced only by something better.
//!
//! Every loop polls the termination; when it fires, step 5 runs on the chain so far.

use super::Smoother;
use crate::cost::CostModel;
use crate::geom::{Vec2, Vec3};
use crate::kinematics::dubins::{Dubins, Word as DubinsWord};
use crate::kinematics::dubins3::{planning_pitch, Dubins3};
use crate::kinematics::{Pose, TangentPolygon};
use crate::params::{Bound, Checked, Range, Word};
use crate::path::PathModel;
use crate::scratch::Scratch;
use crate::termination::Termination;
use crate::world::Dims;

/// The heading rule at interior waypoints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Headings {
    /// The bisector of the two legs.
    Bisector,
    /// The incoming leg's direction.
    Incoming,
}

impl Word for Headings {
    const WORDS: &'static [(&'static str, Self)] =
        &[("bisector", Headings::Bisector), ("incoming", Headings::Incoming)];
}

crate::params::word_param!(Headings);

const POSITIVE: Range = Range::Number { lo: Bound::Open(0.0), hi: Bound::Unbounded };

crate::params! {
    /// Dubins smoother parameters.
    pub struct DubinsParams {
        /// Turning radius of the curves (m); absent: the vehicle's turn_radius (with neither,
        /// the input is returned unchanged).
        radius: Option<f64> = None, POSITIVE, "Dubins 1957; wpa2017 eq. 9";
        /// Heading at interior waypoints: "bisector" of the legs or the "incoming" leg's.
        headings: Headings = Headings::Bisector, Range::Choice(&["bisector", "incoming"]), "tidepath";
        /// Heading offsets tried either side of the rule's at each waypoint (0: none).
        heading_trials: usize = 3, Range::integer(0, 12), "tidepath";
        /// Step between the heading offsets tried (deg).
        heading_step_deg: f64 = 15.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(90.0) }, "tidepath";
        /// Largest arc piece of the tangent polygon (deg; also at most 0.9 of the vehicle's
        /// max_turn).
        max_piece_deg: f64 = 30.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(120.0) }, "tidepath";
        /// Rounds of midpoint insertion when repairing a curve with violations.
        repair_depth: usize = 3, Range::integer(0, 8), "tidepath";
    }
}

#[derive(Clone, Debug, Default)]
pub struct DubinsSmoother {
    params: DubinsParams,
}

impl DubinsSmoother {
    pub fn new(params: Checked<DubinsParams>) -> Self {
        Self { params: params.into_inner() }
    }
}

impl Smoother for DubinsSmoother {
    fn id(&self) -> &'static str {
        "dubins"
    }

    fn smooth(
        &self,
        model: &PathModel<'_>,
        cost: &dyn CostModel,
        points: &[Vec3],
        termination: &Termination,
    ) -> Vec<Vec3> {
        let Some(radius) = self.params.radius.or(model.vehicle.turn_radius) else {
            return points.to_vec();
        };
        if points.len() < 2 || !(radius.is_finite() && radius > 0.0) {
            return points.to_vec();
        }
        let veh = model.vehicle;
        let mut run = Run {
            model,
            cost,
            termination,
            params: &self.params,
            radius,
            max_piece: self.params.max_piece_deg.to_radians().min(0.9 * veh.max_turn),
            pitch: (model.world.dims == Dims::Three).then(|| planning_pitch(veh.max_pitch)),
            original: points,
            scratch: Scratch::default(),
        };
        let input = run.score_of(points);
        let out = run.smooth();
        match out {
            Some((poly, score)) if !input.better_than(&score) => poly,
            _ => points.to_vec(),
        }
    }
}

/// A kept waypoint: its place in the input, position, and heading offset from the rule's.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    /// Index in the original polyline, or the fraction along it for an inserted midpoint.
    at: f64,
    p: Vec3,
    offset: f64,
}

/// The chain: kept waypoints and, per curve between them, the word when one is forced.
#[derive(Clone, Debug, PartialEq)]
struct Chain {
    nodes: Vec<Node>,
    words: Vec<Option<DubinsWord>>,
}

/// How good a path is: feasible first, then fewer violations, then cost.
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

/// One curve of a chain, ready to write.
enum Curve {
    Flat(Dubins, f64),
    Air(Dubins3),
}

impl Curve {
    fn write(&self, tp: &mut TangentPolygon) {
        match self {
            Curve::Flat(d, dz) => d.write(tp, *dz),
            Curve::Air(d) => d.write(tp),
        }
    }
}

struct Run<'a, 'm> {
    model: &'a PathModel<'m>,
    cost: &'a dyn CostModel,
    termination: &'a Termination,
    params: &'a DubinsParams,
    radius: f64,
    max_piece: f64,
    /// The planning pitch in a 3-D world; `None` in 2-D (the plane's height is kept).
    pitch: Option<f64>,
    original: &'a [Vec3],
    scratch: Scratch,
}

/// The horizontal unit direction from a to b, when they are apart horizontally.
fn direction(a: Vec3, b: Vec3) -> Option<Vec2> {
    let d = (b - a).truncate();
    let l = d.length();
    (l > 0.0).then(|| d / l)
}

impl Run<'_, '_> {
    fn stopped(&self) -> bool {
        self.termination.interrupted().is_some()
    }

    fn score_of(&mut self, points: &[Vec3]) -> Score {
        self.score_with_times(points, &mut Vec::new())
    }

    /// The score of `points`; `times` receives the arrival time at each point.
    fn score_with_times(&mut self, points: &[Vec3], times: &mut Vec<f64>) -> Score {
        let a = self.model.assess(points, times);
        let cost = self.cost.cost(self.model, points, &mut self.scratch);
        Score { violations: a.violation_count(), cost: if cost.is_nan() { f64::INFINITY } else { cost } }
    }

    /// The heading at node `k` of `nodes` by the rule, plus its offset.
    fn heading(&self, nodes: &[Node], k: usize) -> f64 {
        let n = nodes.len();
        let inc = (k > 0).then(|| direction(nodes[k - 1].p, nodes[k].p)).flatten();
        let out = (k + 1 < n).then(|| direction(nodes[k].p, nodes[k + 1].p)).flatten();
        let d = match (inc, out, self.params.headings) {
            (Some(u), Some(v), Headings::Bisector) => {
                let s = u + v;
                if s.length() > 1e-9 {
                    s
                } else {
                    u
                }
            }
            (Some(u), _, _) => u,
            (None, Some(v), _) => v,
            (None, None, _) => Vec2::X,
        };
        d.y.atan2(d.x) + nodes[k].offset
    }

    fn pose(&self, nodes: &[Node], k: usize) -> Pose {
        Pose::new(nodes[k].p, self.heading(nodes, k))
    }

    /// The curve from node k to node k + 1.
    fn curve(&self, nodes: &[Node], k: usize, word: Option<DubinsWord>) -> Option<Curve> {
        let (a, b) = (self.pose(nodes, k), self.pose(nodes, k + 1));
        let all = DubinsWord::ALL;
        let one = word.map(|w| [w]);
        let words: &[DubinsWord] = match &one {
            Some(w) => w,
            None => &all,
        };
        match self.pitch {
            Some(g) => Dubins3::shortest_in(a, b, self.radius, g, words).map(Curve::Air),
            None => Dubins::shortest_in(a, b, self.radius, words).map(|d| Curve::Flat(d, b.p.z - a.p.z)),
        }
    }

    /// Appends the polygon of curve k (without its first point) to `out`; `false` when the
    /// curve does not exist.
    fn write_curve(&self, chain: &Chain, k: usize, out: &mut Vec<Vec3>) -> bool {
        let Some(c) = self.curve(&chain.nodes, k, chain.words[k]) else { return false };
        let mut tp = TangentPolygon::new(self.pose(&chain.nodes, k), self.radius, self.max_piece);
        c.write(&mut tp);
        let start = out.len();
        tp.finish_into(out);
        // The curve ends at the next waypoint up to rounding: exactly there.
        if out.len() > start {
            *out.last_mut().expect("written") = chain.nodes[k + 1].p;
        }
        true
    }

    /// The polygon of curves `k0..k1`, and the index of each node k0..=k1 in it.
    fn polygon(&self, chain: &Chain, k0: usize, k1: usize) -> Option<(Vec<Vec3>, Vec<usize>)> {
        let mut pts = vec![chain.nodes[k0].p];
        let mut at = vec![0];
        for k in k0..k1 {
            if !self.write_curve(chain, k, &mut pts) {
                return None;
            }
            at.push(pts.len() - 1);
        }
        Some((pts, at))
    }

    /// The whole chain's polygon and score, with the arrival time at each node.
    fn judge(&mut self, chain: &Chain) -> Option<(Vec<Vec3>, Score, Vec<f64>)> {
        let (pts, at) = self.polygon(chain, 0, chain.nodes.len() - 1)?;
        let mut times = Vec::new();
        let score = self.score_with_times(&pts, &mut times);
        let node_times = at.iter().map(|&i| times[i]).collect();
        Some((pts, score, node_times))
    }

    /// Violations of curves `k0..k1` on their own, flown from node k0 at time `t0`.
    fn local_violations(&self, chain: &Chain, k0: usize, k1: usize, t0: f64) -> u32 {
        let Some((pts, _)) = self.polygon(chain, k0, k1) else { return u32::MAX };
        let mut sub = self.model.clone();
        sub.departure_time = t0;
        sub.start = pts[0];
        sub.goal = *pts.last().expect("a point");
        let mut times = Vec::new();
        let a = sub.assess(&pts, &mut times);
        a.violation_count() - a.endpoint_violations
    }

    fn initial_chain(&self) -> Chain {
        let r = self.radius;
        let pts = self.original;
        let n = pts.len();
        let mut nodes: Vec<Node> = vec![Node { at: 0.0, p: pts[0], offset: 0.0 }];
        for (i, &p) in pts.iter().enumerate().skip(1) {
            let close = (p - nodes.last().expect("start").p).truncate().length() <= 1e-6 * r;
            if close && i + 1 < n {
                continue;
            }
            if close && nodes.len() > 1 {
                // The goal replaces a kept waypoint it coincides with.
                nodes.pop();
            }
            nodes.push(Node { at: i as f64, p, offset: 0.0 });
        }
        let words = vec![None; nodes.len() - 1];
        Chain { nodes, words }
    }

    fn smooth(&mut self) -> Option<(Vec<Vec3>, Score)> {
        let chain = self.initial_chain();
        let (poly, score, times) = self.judge(&chain)?;
        let mut state = State { chain, poly, score, times };
        self.drop_pass(&mut state);
        self.heading_pass(&mut state);
        if !state.score.feasible() {
            self.repair(&mut state);
        }
        Some((state.poly, state.score))
    }

    /// Takes `candidate` when its path is better than the state's (or no worse, with
    /// `ties`).
    fn try_take(&mut self, state: &mut State, candidate: Chain, ties: bool) -> bool {
        let Some((poly, score, times)) = self.judge(&candidate) else { return false };
        let take = score.better_than(&state.score) || (ties && !state.score.better_than(&score));
        if take {
            *state = State { chain: candidate, poly, score, times };
        }
        take
    }

    /// Step 2: from each kept waypoint jump to the farthest later one whose chain is no worse.
    fn drop_pass(&mut self, state: &mut State) {
        let mut i = 0;
        while i + 2 < state.chain.nodes.len() {
            let n = state.chain.nodes.len();
            for j in (i + 2..n).rev() {
                if self.stopped() {
                    return;
                }
                let mut cand = state.chain.clone();
                cand.nodes.drain(i + 1..j);
                cand.words.drain(i + 1..j);
                cand.words[i] = None;
                if i > 0 {
                    cand.words[i - 1] = None;
                }
                // The curves into node i (its heading changed) and on to the old node j must
                // pass on their own; for a feasible chain the curve after j too.
                let k0 = i.saturating_sub(1);
                let k1 = if state.score.feasible() { (i + 2).min(cand.nodes.len() - 1) } else { i + 1 };
                if self.local_violations(&cand, k0, k1, state.times[k0]) != 0 {
                    continue;
                }
                if self.try_take(state, cand, true) {
                    break;
                }
            }
            i += 1;
        }
    }

    /// Step 3: heading offsets at each kept waypoint, kept when the path is better.
    fn heading_pass(&mut self, state: &mut State) {
        let step = self.params.heading_step_deg.to_radians();
        for k in 0..state.chain.nodes.len() {
            for m in 1..=self.params.heading_trials {
                for side in [1.0, -1.0] {
                    if self.stopped() {
                        return;
                    }
                    let mut cand = state.chain.clone();
                    cand.nodes[k].offset = state.chain.nodes[k].offset + side * step * m as f64;
                    // For a feasible chain, the two curves at node k must pass on their own.
                    let k0 = k.saturating_sub(1);
                    let k1 = (k + 1).min(cand.nodes.len() - 1);
                    if state.score.feasible() && self.local_violations(&cand, k0, k1, state.times[k0]) != 0 {
                        continue;
                    }
                    self.try_take(state, cand, false);
                }
            }
        }
    }

    /// Step 4: repairs of the curves with violations of their own.
    fn repair(&mut self, state: &mut State) {
        let mut k = 0;
        while k + 1 < state.chain.nodes.len() && !state.score.feasible() {
            if self.stopped() {
                return;
            }
            if self.local_violations(&state.chain, k, k + 1, state.times[k]) == 0 {
                k += 1;
                continue;
            }
            self.repair_curve(state, k);
            k += 1;
        }
        if !state.score.feasible() {
            self.heading_pass(state);
        }
    }

    fn repair_curve(&mut self, state: &mut State, k: usize) {
        // (a) The other words, shortest first.
        let mut words: Vec<(f64, DubinsWord)> = DubinsWord::ALL
            .into_iter()
            .filter_map(|w| self.curve(&state.chain.nodes, k, Some(w)).map(|c| (curve_length(&c), w)))
            .collect();
        words.sort_by(|a, b| a.0.total_cmp(&b.0));
        for (_, w) in words {
            if self.stopped() {
                return;
            }
            let mut cand = state.chain.clone();
            cand.words[k] = Some(w);
            self.try_take(state, cand, false);
        }
        if self.local_violations(&state.chain, k, k + 1, state.times[k]) == 0 {
            return;
        }
        // (b) The dropped original waypoints back.
        let (a, b) = (state.chain.nodes[k].at, state.chain.nodes[k + 1].at);
        let first = a.floor() as usize + 1;
        let last = b.ceil() as usize;
        let dropped: Vec<Node> = (first..last)
            .filter(|&i| (i as f64) > a && (i as f64) < b)
            .map(|i| Node { at: i as f64, p: self.original[i], offset: 0.0 })
            .collect();
        if !dropped.is_empty() && !self.stopped() {
            let cand = insert(&state.chain, k, &dropped);
            self.try_take(state, cand, false);
        }
        // (c) Midpoints of the original polyline's legs between the curve's ends.
        for _ in 0..self.params.repair_depth {
            if self.stopped() || state.score.feasible() {
                return;
            }
            let (a, b) = (state.chain.nodes[k].at, state.chain.nodes[k + 1].at);
            let mid = 0.5 * (a + b);
            let node = Node { at: mid, p: self.along(mid), offset: 0.0 };
            let cand = insert(&state.chain, k, &[node]);
            if !self.try_take(state, cand, false) {
                return;
            }
            if self.local_violations(&state.chain, k, k + 1, state.times[k]) == 0 {
                return;
            }
        }
    }

    /// The point at fractional index `at` along the original polyline.
    fn along(&self, at: f64) -> Vec3 {
        let i = (at.floor() as usize).min(self.original.len() - 2);
        let f = at - i as f64;
        self.original[i] + (self.original[i + 1] - self.original[i]) * f
    }
}

fn curve_length(c: &Curve) -> f64 {
    match c {
        Curve::Flat(d, dz) => d.length().hypot(*dz),
        Curve::Air(d) => d.length(),
    }
}

/// `chain` with `nodes` inserted between node k and k + 1; the words next to them freed.
fn insert(chain: &Chain, k: usize, nodes: &[Node]) -> Chain {
    let mut out = chain.clone();
    out.nodes.splice(k + 1..k + 1, nodes.iter().copied());
    out.words.splice(k..k + 1, std::iter::repeat_n(None, nodes.len() + 1));
    if k > 0 {
        out.words[k - 1] = None;
    }
    if k + nodes.len() + 1 < out.words.len() {
        out.words[k + nodes.len() + 1] = None;
    }
    out
}

/// The chain being improved, its polygon, score, and the arrival time at each node.
struct State {
    chain: Chain,
    poly: Vec<Vec3>,
    score: Score,
    times: Vec<f64>,
}

#[cfg(test)]
mod tests;
