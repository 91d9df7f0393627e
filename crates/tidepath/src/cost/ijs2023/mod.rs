//! The ijs2023 cost model (eqs. 15-24): normalised travel time in the current, times a safety
//! factor, plus a penalty for crossing the current and one for missing the target. See
//! `docs/papers/ijs2023.md`, section "Cost model" and A1, A5, A6, A8, A9, A10.
//!
//! Fit = F_p1 (c1 F_t + c2 F_p2 + c3 F_p3) (eq. 15), minimised, with c1 + c2 = 1 (checked, as
//! the paper sets it; c1 = `w_time`, c2 = `w_current`).
//!
//! - Time, eqs. 16-18. ϖ_t = Σ_i [Dist_i / (2|v_i|) + Dist_i / (2|v_(i+1)|)] (eq. 17) over the
//!   segments P_i -> P_(i+1) (3-D Euclidean lengths in metres). v_i = v_rc + v_c(P_i): the
//!   vehicle's through-water velocity (its speed, along the segment; at P_(i+1) the same
//!   segment's direction, A9) plus the horizontal current (vertical components are dropped,
//!   A9); |v_i| is floored at 0.05 |v_rc| ([`MIN_SPEED_FRACTION`]). The current is read on the
//!   vehicle's clock from the mission's departure: at P_i when the vehicle leaves it, at
//!   P_(i+1) at the estimated arrival t_i + Dist_i / |v_i|; the next segment leaves at
//!   t_i + its eq. 17 time. This is exactly the clock of tidepath's `vector-sum` travel model
//!   (`[model] travel_time = "vector-sum"`) in a horizontal current, so there the time here is the
//!   travel time `eval` reports; under the default `crab` model the two differ (eq. 17 ignores
//!   that a cross-current pushes the vehicle off the segment). Each segment is flown at its
//!   plan speed when the vehicle has a speed range (fleets), else at the cruise speed.
//!   ϖ_tmin = |P_start P_end| / (|v_rc| + max |v_c|) (eq. 18), |v_rc| the vehicle's highest
//!   speed, max |v_c| the largest horizontal current over the domain at the departure time
//!   ([`crate::world::Current::max_speed_hint`], computed once per world: [`peak`]) or the
//!   parameter `max_current_speed`. ϖ_tmax = `tmax_factor` ϖ_tmin (2, A1), and
//!   F_t = (ϖ_t - ϖ_tmin) / (ϖ_tmax - ϖ_tmin) (eq. 16), not clipped. A mission whose start is
//!   its goal has ϖ_tmin = 0 and is normalised by 1 s instead.
//! - Safety, eqs. 19-22. F_p1 = J_r1 J_r2 with J = `safety_factor` (10). J_r1 = J when any
//!   segment (its ends, the waypoints, included) comes within the vehicle's safety distance
//!   d_safe of the seabed, vertically, or below it (eqs. 20-21 with the sign of A5: the
//!   printed test would let points lie up to d_safe under the seabed). J_r2 = J when any
//!   segment comes within d_safe of an obstacle (eq. 22: d_k <= R_k + d_safe for a sphere; a
//!   full-depth cylinder measures the horizontal distance to the segment's projection; a box,
//!   which the paper gives a "radius" R_k without defining it, is measured from the box
//!   itself). Both are tidepath's exact segment tests ([`World::segment_hits_terrain`],
//!   [`crate::world::Obstacle::segment_hits`]), the ones the validator makes, in place of the
//!   paper's grid samples; a moving obstacle is tested where it is while the vehicle flies the
//!   segment on the clock above. So under the `vector-sum` travel model F_p1 = 1 exactly when
//!   tidepath's motion check finds no seabed or obstacle on any segment (of the polyline: with
//!   a turning radius tidepath judges the flown curve, which cuts the corners).
//! - Current, eqs. 23-24. U(θ) = 1.5 sin(θ)^11.15 + sin(θ/3)^3, θ in [0, π] the angle between
//!   the segment's horizontal direction and the horizontal current at P_i when the vehicle
//!   leaves it; U = 0 where there is no current or the segment is vertical (or of zero
//!   length). F_p2 = Σ_i U_i / ((D - 1) max U), max U = [`U_MAX`] = 1.626420 at θ = 90.75°
//!   (A6: the paper's 1.62642), so F_p2 lies in [0, 1].
//! - Target, F_p3. c3 F_p3 = `target_penalty` (5) when the target is missed, else 0: when the
//!   path does not end at the goal, or its last leg (the last waypoint to the goal) moves
//!   farther sideways than `lateral_step` or vertically than `vertical_step` (eq. 14's UB and
//!   UR in metres, the values of `[encoding] lateral_step` / `vertical_step`). Sideways is
//!   measured as the sliced encoding measures it (`target_axis`, as `[encoding] axis`):
//!   across the horizontal start-goal axis ("path"), or along y ("x") or x ("y"). An absent or
//!   zero step is not tested.
//!
//! Terms reported, summing to Fit: `time` = c1 F_t, `current` = c2 F_p2, `target` = c3 F_p3,
//! `safety` = (F_p1 - 1)(c1 F_t + c2 F_p2 + c3 F_p3), the part the safety factor adds (0 on a
//! safe path). The raw values (ϖ_t in seconds, ϖ_tmin, F_t, F_p2, F_p1, which test failed) are
//! [`Ijs2023Cost::parts`].
//!
//! A run succeeds in the paper when F_p1 = 1 and the target is reached
//! ([`Ijs2023Parts::succeeded`]). No threshold on Fit says that (an unsafe path near the
//! fastest time costs J (c1 F_t) and can undercut a safe slow one), so the model has no
//! [`CostModel::feasible_below`]; plans are judged feasible by tidepath's checker.
//!
//! Graph and sampling planners build paths edge by edge: a valid motion (tidepath's motion
//! check) costs c1 Δt / ((tmax_factor - 1) ϖ_tmin), Δt its eq. 17 time, and arrives at the
//! departure plus Δt. Along a path these add up to c1 ϖ_t / (ϖ_tmax - ϖ_tmin) = `time` +
//! c1 / (tmax_factor - 1), a constant apart, so `time` is the model's additive term. `current`
//! (a mean over the segments), `target` (the last leg) and `safety` (a factor on the whole
//! sum) are path-level, checked on the finished path.

// `!(d <= limit)` is deliberate: a NaN distance must count as a miss.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod peak;

use super::CostModel;
use crate::error::{Error, Result};
use crate::geom::{Vec2, Vec3};
use crate::params::{Bound, Checked, Range};
use crate::path::PathModel;
use crate::scratch::Scratch;
use crate::validity::MIN_SPEED_FRACTION;
use crate::world::{Current, Obstacle, World};

pub use peak::peak_current;

crate::params! {
    /// The ijs2023 model's parameters (`[cost] weights`); w_time + w_current = 1 as the paper
    /// sets c1 + c2.
    pub struct Ijs2023Params {
        /// c1, the weight of the normalised time F_t; w_time + w_current must be 1.
        w_time: f64 = 1.0, UNIT, "ijs2023 (static experiments; 0.7 with a current)";
        /// c2, the weight of the current penalty F_p2; w_time + w_current must be 1.
        w_current: f64 = 0.0, UNIT, "ijs2023 (static experiments; 0.3 with a current)";
        /// J, the factor of J_r1 (seabed) and of J_r2 (obstacles): F_p1 is 1, J or J^2.
        safety_factor: f64 = 10.0, AT_LEAST_ONE, "ijs2023";
        /// c3 F_p3 when the target is missed.
        target_penalty: f64 = 5.0, NON_NEGATIVE, "ijs2023";
        /// ϖ_tmax / ϖ_tmin (A1).
        tmax_factor: f64 = 2.0, ABOVE_ONE, "tidepath (not given in ijs2023, A1)";
        /// UB (m): the last leg may move at most this far sideways (absent or 0: not tested);
        /// the sliced encoding's `[encoding] lateral_step`.
        lateral_step: Option<f64> = None, NON_NEGATIVE, "ijs2023 (eq. 14; value chosen, A10)";
        /// UR (m): the last leg may move at most this far vertically (absent or 0: not
        /// tested); the sliced encoding's `[encoding] vertical_step`.
        vertical_step: Option<f64> = None, NON_NEGATIVE, "ijs2023 (eq. 14; value chosen, A10)";
        /// How sideways is measured for lateral_step, as `[encoding] axis`: across the
        /// start-goal axis ("path"), as the change in y ("x") or in x ("y").
        target_axis: String = "path".to_string(), Range::Choice(&["path", "x", "y"]), "tidepath";
        /// max |v_c| of eq. 18 (m/s); absent: the largest horizontal current over the domain
        /// at the departure time.
        max_current_speed: Option<f64> = None, NON_NEGATIVE, "ijs2023 (eq. 18)";
    }
    check = weights_sum_to_one;
}

const UNIT: Range = Range::closed(0.0, 1.0);
const NON_NEGATIVE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded };
const AT_LEAST_ONE: Range = Range::Number { lo: Bound::Closed(1.0), hi: Bound::Unbounded };
const ABOVE_ONE: Range = Range::Number { lo: Bound::Open(1.0), hi: Bound::Unbounded };

/// How far c1 + c2 may stray from 1 (decimal weights such as 0.7 + 0.3 round).
pub const WEIGHT_SUM_TOLERANCE: f64 = 1e-9;

fn weights_sum_to_one(p: &Ijs2023Params, prefix: &str) -> Result<()> {
    let sum = p.w_time + p.w_current;
    if (sum - 1.0).abs() > WEIGHT_SUM_TOLERANCE {
        return Err(Error::input(
            prefix,
            format!("w_time + w_current must be 1 (ijs2023, eq. 15), got {} + {} = {sum}", p.w_time, p.w_current),
        ));
    }
    Ok(())
}

/// The maximum of U(θ) over [0, π] (eq. 24), at θ = 90.7517°; the paper's normaliser 1.62642
/// (A6). The unit tests find it again by golden-section search.
pub const U_MAX: f64 = 1.626_419_659_928_444_2;

/// U(θ) of eq. 24, θ in radians in [0, π].
#[inline]
pub fn current_penalty(theta: f64) -> f64 {
    let s = theta.sin().max(0.0);
    // 0^11.15 = 0: no powf along or against the current.
    let first = if s > 0.0 { 1.5 * s.powf(11.15) } else { 0.0 };
    first + (theta / 3.0).sin().powi(3)
}

/// U for a segment of horizontal extent `h` in the horizontal current `c`: 0 when either is
/// zero.
#[inline]
fn segment_penalty(h: Vec2, c: Vec2) -> f64 {
    let (hl, cl) = (h.length(), c.length());
    if hl > 0.0 && cl > 0.0 {
        current_penalty((h.dot(c) / (hl * cl)).clamp(-1.0, 1.0).acos())
    } else {
        0.0
    }
}

/// Sideways measure of the target window.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Axis {
    Path,
    X,
    Y,
}

/// The raw quantities of one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Ijs2023Parts {
    /// ϖ_t (s), eq. 17.
    pub travel_time: f64,
    /// ϖ_tmin (s), eq. 18.
    pub time_min: f64,
    /// F_t, eq. 16.
    pub f_t: f64,
    /// F_p2, eq. 23, in [0, 1].
    pub f_p2: f64,
    /// J_r1 = J: a segment within the safety distance of the seabed or below it.
    pub seabed: bool,
    /// J_r2 = J: a segment within the safety distance of an obstacle.
    pub obstacle: bool,
    /// F_p1 = J_r1 J_r2.
    pub f_p1: f64,
    /// The path misses the goal or its last leg leaves the posture window.
    pub target_missed: bool,
}

impl Ijs2023Parts {
    /// The paper's success: F_p1 = 1 and the target reached.
    pub fn succeeded(&self) -> bool {
        !self.seabed && !self.obstacle && !self.target_missed
    }
}

#[derive(Clone, Debug)]
pub struct Ijs2023Cost {
    pub params: Ijs2023Params,
    axis: Axis,
}

const TERMS: [&str; 4] = ["time", "current", "target", "safety"];

/// The horizontal part of the current at `p` and time `t`, as a 3-D vector.
#[inline]
fn horizontal_current(current: &Current, p: Vec3, t: f64) -> Vec3 {
    let c = current.velocity(p, t);
    Vec3::new(c.x, c.y, 0.0)
}

impl Ijs2023Cost {
    pub fn new(params: Checked<Ijs2023Params>) -> Self {
        let params = params.into_inner();
        let axis = match params.target_axis.as_str() {
            "x" => Axis::X,
            "y" => Axis::Y,
            _ => Axis::Path,
        };
        Self { params, axis }
    }

    /// ϖ_tmin (s) of the mission of `model` (eq. 18).
    pub fn time_min(&self, model: &PathModel<'_>) -> f64 {
        let peak = match self.params.max_current_speed {
            Some(c) => c,
            None => peak_current(model),
        };
        model.start.distance(model.goal) / (model.vehicle.max_speed() + peak)
    }

    /// ϖ_tmax - ϖ_tmin: the denominator of F_t (1 s times the factor when ϖ_tmin is 0).
    fn time_span(&self, time_min: f64) -> f64 {
        let reference = if time_min > 0.0 { time_min } else { 1.0 };
        (self.params.tmax_factor - 1.0) * reference
    }

    /// Eq. 17's time (s) for a -> b leaving at `t0` at through-water speed `v`, given `ca`,
    /// the horizontal current at `a` then, and the horizontal current read at `b` (`None` for
    /// a segment of zero length).
    #[inline]
    fn segment_time(world: &World, a: Vec3, b: Vec3, t0: f64, v: f64, ca: Vec3) -> (f64, Option<Vec3>) {
        let len = a.distance(b);
        if len == 0.0 {
            return (0.0, None);
        }
        // The expression of the validator's `vector-sum` model, so the clocks agree bit for bit.
        let d = (b - a) / len;
        let floor = MIN_SPEED_FRACTION * v;
        let va = (d * v + ca).length().max(floor);
        let cb = horizontal_current(&world.current, b, t0 + len / va);
        let vb = (d * v + cb).length().max(floor);
        (len / (2.0 * va) + len / (2.0 * vb), Some(cb))
    }

    /// Does the last leg `p` -> `goal` leave eq. 14's window?
    fn outside_window(&self, model: &PathModel<'_>, p: Vec3, goal: Vec3) -> bool {
        let over = |step: Option<f64>, value: f64| match step {
            Some(s) if s > 0.0 => !(value <= s * (1.0 + 1e-9)),
            _ => false,
        };
        let d = goal - p;
        let lateral = match self.axis {
            Axis::X => d.y.abs(),
            Axis::Y => d.x.abs(),
            Axis::Path => {
                let axis = (model.goal - model.start).truncate();
                let len = axis.length();
                if len > 0.0 {
                    (axis.perp_dot(d.truncate()) / len).abs()
                } else {
                    d.truncate().length()
                }
            }
        };
        over(self.params.lateral_step, lateral) || over(self.params.vertical_step, d.z.abs())
    }

    /// The raw quantities of `points` (start and goal included). No allocation.
    pub fn parts(&self, model: &PathModel<'_>, points: &[Vec3]) -> Ijs2023Parts {
        let Walk { travel, u_sum, seabed, obstacle } = walk(model, points);
        let time_min = self.time_min(model);
        let segments = points.len().saturating_sub(1);
        let f_p2 = if segments > 0 { u_sum / (segments as f64 * U_MAX) } else { 0.0 };
        let j = self.params.safety_factor;
        let f_p1 = if seabed { j } else { 1.0 } * if obstacle { j } else { 1.0 };
        let target_missed = match points {
            [] => true,
            [.., last] if !(last.distance(model.goal) <= model.endpoint_tolerance()) => true,
            [.., p, last] => self.outside_window(model, *p, *last),
            [_] => false,
        };
        Ijs2023Parts {
            travel_time: travel,
            time_min,
            f_t: (travel - time_min) / self.time_span(time_min),
            f_p2,
            seabed,
            obstacle,
            f_p1,
            target_missed,
        }
    }
}

/// What the passes along the path gather: ϖ_t, Σ U_i and the two safety tests.
struct Walk {
    travel: f64,
    u_sum: f64,
    seabed: bool,
    obstacle: bool,
}

/// Two passes: the clock (ϖ_t, Σ U_i, and moving obstacles, tested where they are on it),
/// then the tests that do not depend on it (the seabed, fixed obstacles), which stop once
/// both have hit: nothing more can change F_p1. Apart, the clock is a tight loop of
/// arithmetic and the tests' calls do not stall it.
fn walk(model: &PathModel<'_>, points: &[Vec3]) -> Walk {
    let world = model.world;
    let safety = model.vehicle.safety_distance;
    let obstacles = ObstacleTest::new(world, safety);
    let (travel, u_sum, mut obstacle) = match world.current {
        Current::None => {
            let (travel, hit) = still_clock(model, points, &obstacles);
            (travel, 0.0, hit)
        }
        _ => current_clock(model, points, &obstacles),
    };
    let mut seabed = false;
    // Moving obstacles were tested on the clock.
    let mut obstacles_done = obstacle || !obstacles.fixed;
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        if !obstacles_done && obstacles.hits_fixed(a, b) {
            obstacle = true;
            obstacles_done = true;
        }
        if !seabed {
            seabed = world.segment_hits_terrain(a, b, safety);
        }
        if seabed && obstacles_done {
            break;
        }
    }
    Walk { travel, u_sum, seabed, obstacle }
}

/// Fixed obstacles whose boxes, grown by the margin, are computed once per evaluation
/// (at most this many; more fall back to the shapes' own tests).
const BOXED: usize = 16;

/// The obstacle tests of one evaluation.
struct ObstacleTest<'a> {
    world: &'a World,
    safety: f64,
    /// All obstacles fixed: the clock plays no part (a fixed obstacle's frame is the world's).
    fixed: bool,
    /// For fixed obstacles, at most [`BOXED`]: each shape's box grown by the margin, the
    /// rejection [`crate::world::Shape::segment_hits`] makes first; `boxed` of them are set.
    boxes: [(Vec3, Vec3); BOXED],
    boxed: usize,
}

impl<'a> ObstacleTest<'a> {
    fn new(world: &'a World, safety: f64) -> Self {
        let fixed = world.obstacles.iter().all(Obstacle::is_fixed);
        let mut boxes = [(Vec3::ZERO, Vec3::ZERO); BOXED];
        let mut boxed = 0;
        if fixed && world.obstacles.len() <= BOXED {
            // The margin as `Shape::segment_hits` grows the box by it.
            let m = Vec3::splat(if safety > 0.0 { safety } else { 0.0 });
            for (slot, o) in boxes.iter_mut().zip(&world.obstacles) {
                let b = o.shape.aabb();
                *slot = (b.min - m, b.max + m);
            }
            boxed = world.obstacles.len();
        }
        Self { world, safety, fixed, boxes, boxed }
    }

    /// Does segment a -> b come within the safety distance of a fixed obstacle (all are)?
    /// The same answer as each obstacle's `segment_hits`: a segment the grown box rejects is
    /// one the shape's own test rejects first.
    #[inline]
    fn hits_fixed(&self, a: Vec3, b: Vec3) -> bool {
        let obstacles = &self.world.obstacles;
        if self.boxed > 0 {
            self.boxes[..self.boxed]
                .iter()
                .zip(obstacles)
                .any(|(&(lo, hi), o)| !apart(a, b, lo, hi) && o.shape.segment_hits(a, b, self.safety))
        } else {
            obstacles.iter().any(|o| o.shape.segment_hits(a, b, self.safety))
        }
    }

    /// Does segment a -> b, flown from `ta` to `tb`, come within the safety distance of an
    /// obstacle (some moving)?
    #[inline]
    fn hits_moving(&self, a: Vec3, b: Vec3, ta: f64, tb: f64) -> bool {
        self.world.obstacles.iter().any(|o| o.segment_hits(a, b, ta, tb, self.safety))
    }
}

/// Is the segment a -> b entirely beyond one face of the box `lo`..`hi`? The expression of
/// the obstacles' own rejection: one branch, and NaN never rejects.
#[inline(always)]
fn apart(a: Vec3, b: Vec3, lo: Vec3, hi: Vec3) -> bool {
    ((a.x < lo.x) & (b.x < lo.x))
        | ((a.y < lo.y) & (b.y < lo.y))
        | ((a.z < lo.z) & (b.z < lo.z))
        | ((a.x > hi.x) & (b.x > hi.x))
        | ((a.y > hi.y) & (b.y > hi.y))
        | ((a.z > hi.z) & (b.z > hi.z))
}

/// The clock in still water (`Current::None`): no current to read, U = 0, and eq. 17's two
/// speeds are one, |v d| floored (bit for bit the general expression with c = 0). Returns
/// ϖ_t and whether a moving obstacle was hit (tested on the clock unless all are fixed).
fn still_clock(model: &PathModel<'_>, points: &[Vec3], obstacles: &ObstacleTest<'_>) -> (f64, bool) {
    let mut t = model.departure_time;
    let mut travel = 0.0;
    let mut hit = false;
    for (i, w) in points.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        let len = a.distance(b);
        let dt = if len == 0.0 {
            0.0
        } else {
            let v = model.segment_speed(i);
            let va = ((b - a) / len * v).length().max(MIN_SPEED_FRACTION * v);
            let half = len / (2.0 * va);
            half + half
        };
        let t1 = t + dt;
        if !obstacles.fixed && !hit {
            hit = obstacles.hits_moving(a, b, t, t1);
        }
        travel += dt;
        t = t1;
    }
    (travel, hit)
}

/// The clock in a current: eq. 17 on the vector-sum clock, Σ U(θ_i), and whether a moving
/// obstacle was hit (tested on the clock unless all are fixed).
fn current_clock(model: &PathModel<'_>, points: &[Vec3], obstacles: &ObstacleTest<'_>) -> (f64, f64, bool) {
    let world = model.world;
    let mut t = model.departure_time;
    let (mut travel, mut u_sum) = (0.0, 0.0);
    let mut hit = false;
    // A current that does not change in time gives P_(i+1) the same velocity at the
    // estimated and at the actual arrival: read once.
    let steady = matches!(world.current, Current::None | Current::Uniform(_) | Current::Vortices(_));
    let mut known: Option<Vec3> = None;
    for (i, w) in points.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        let ca = known.take().unwrap_or_else(|| horizontal_current(&world.current, a, t));
        let (dt, cb) = Ijs2023Cost::segment_time(world, a, b, t, model.segment_speed(i), ca);
        if steady {
            known = cb;
        }
        u_sum += segment_penalty((b - a).truncate(), ca.truncate());
        let t1 = t + dt;
        if !obstacles.fixed && !hit {
            hit = obstacles.hits_moving(a, b, t, t1);
        }
        travel += dt;
        t = t1;
    }
    (travel, u_sum, hit)
}

impl CostModel for Ijs2023Cost {
    fn id(&self) -> &'static str {
        "ijs2023"
    }

    fn term_names(&self) -> &'static [&'static str] {
        &TERMS
    }

    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], _scratch: &mut Scratch, terms: &mut [f64]) -> f64 {
        // Needs no buffer: the clock and the tests run along the path.
        let x = self.parts(model, points);
        let p = &self.params;
        terms[0] = p.w_time * x.f_t;
        terms[1] = p.w_current * x.f_p2;
        terms[2] = if x.target_missed { p.target_penalty } else { 0.0 };
        terms[3] = (x.f_p1 - 1.0) * (terms[0] + terms[1] + terms[2]);
        terms[..4].iter().sum()
    }

    /// The motion costs add up to `time` plus a constant.
    fn additive_terms(&self) -> &'static [&'static str] {
        &TERMS[..1]
    }

    /// Covering `distance` takes at least `distance / max_ground_speed` (eq. 17's speeds
    /// |v_rc + v_c| are at most the vehicle's speed plus the current's).
    fn motion_lower_bound(&self, model: &PathModel<'_>, distance: f64, max_ground_speed: f64) -> f64 {
        let span = self.time_span(self.time_min(model));
        self.params.w_time * distance / max_ground_speed.max(f64::MIN_POSITIVE) / span
    }

    /// In still water eq. 17's time is the length over the speed; in a current it depends
    /// on the direction and time.
    fn cost_per_metre(&self, model: &PathModel<'_>) -> Option<f64> {
        let still = match &model.world.current {
            Current::None => true,
            Current::Uniform(v) => v.x == 0.0 && v.y == 0.0,
            _ => false,
        };
        still.then(|| self.params.w_time / (model.vehicle.speed * self.time_span(self.time_min(model))))
    }

    /// A valid motion (tidepath's motion check) costs c1 Δt / (ϖ_tmax - ϖ_tmin), Δt its
    /// eq. 17 time, and arrives Δt after `t0`.
    fn motion_cost_at(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64, v: f64) -> Option<(f64, f64)> {
        if !model.validator.motion_at(a, b, t0, v).valid() {
            return None;
        }
        let ca = horizontal_current(&model.world.current, a, t0);
        let (dt, _) = Self::segment_time(model.world, a, b, t0, v, ca);
        let span = self.time_span(self.time_min(model));
        Some((self.params.w_time * dt / span, t0 + dt))
    }
}

/// Builds the model from `[cost.weights]`.
pub fn build(table: &toml::Table) -> Result<Box<dyn CostModel>> {
    Ok(Box::new(Ijs2023Cost::new(Ijs2023Params::from_table(table, "cost.weights")?)))
}

#[cfg(test)]
mod fast_pass_tests;
#[cfg(test)]
mod tests;
