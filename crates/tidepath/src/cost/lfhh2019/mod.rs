//! The lfhh2019 cost model (eqs. 6-10): path length ratio, joints the vehicle cannot turn,
//! blocked segments and the angle to the current. See `docs/papers/lfhh2019.md`, section
//! "cost" and A2-A3.
//!
//! F = C_length + C_curvature + C_block + C_current
//!
//! - C_length = 1 - L_straight / L_path, L_straight the 3-D start-goal distance of the mission,
//!   L_path the path's 3-D length; 0 for a path of zero length.
//! - C_curvature = N_unable / N_all + 2 when N_unable > 0, else 0. N_all is the number of
//!   segments (points - 1). A joint is unable when the interior angle between its two segments
//!   (pi = straight on, measured in 3-D, A2) is below T_theta (`min_interior_angle_deg`, pi/6 in
//!   the paper). Our reading: a joint that breaks the vehicle's own limits is unable too, so
//!   that F < 2 implies tidepath's feasibility. N_unable counts *segments*: segment i is unable
//!   when the joint at its start is (interior angle below T_theta, or a heading change over the
//!   vehicle's `max_turn` measured as [`PathModel::assess`] does it, from the last segment with
//!   horizontal extent), or when it is steeper than the vehicle's `max_pitch` (3-D). With a
//!   turning radius, a turn whose fillet does not fit (as `assess` judges it) or that climbs
//!   too steeply makes the segment after it unable. So N_unable <= N_all and the term stays in
//!   (2, 3] when any joint is unable. With a radius the straight legs' pitch is judged on the
//!   whole leg, a little stricter than `assess` (which judges the part flown straight).
//! - C_block = N_block / N_all + 2 when N_block > 0, else 0. Segment i is blocked when its
//!   motion is invalid under tidepath's validator on the vehicle's clock (seabed or obstacle
//!   within the safety distance, moving obstacles at the vehicle's time, a current the vehicle
//!   cannot stem, no current data), when one of its ends is outside the domain or (3-D) the
//!   depth band (the domain is a box: a segment leaves it exactly when an end does), or, for
//!   the first and last segments, when the path does not start at the mission's start or end
//!   at its goal. With a turning radius the motions judged are the flown curve's, as in
//!   `assess`; a turn belongs to the segment entering it. The paper samples the seabed every
//!   0.1 km; tidepath's exact seabed and obstacle tests replace it.
//! - C_current = (1 / N_all) sum_n alpha_n / pi (A3: alpha_min = 0, alpha_max = pi), alpha_n the
//!   angle between the horizontal projection of segment n and the horizontal current at its
//!   midpoint, at the mid time of the segment on the vehicle's clock. Where the current is
//!   slower than `still_current` m/s, or the segment has no horizontal extent, alpha_n = pi/2
//!   (neutral). So still water adds 0.5 whatever the path.
//! - Zero-length segments (a repeated waypoint) count in N_all like any other segment (they are
//!   checked for blocks like any other motion and add pi/2 to the current term); they have no
//!   direction, so the joint across them is measured between the segments on either side and
//!   charged to the one after.
//! - A path of fewer than two points has no segment: every term is 0, except C_block = 3 when
//!   it misses the mission's start or goal or lies outside the domain.
//!
//! The paper's own rule is that a path is feasible exactly when F < 2
//! ([`CostModel::feasible_below`]). With the vehicle-limit reading above, F < 2 implies
//! [`crate::path::Assessment::feasible`]; the converse fails only for a path whose joints are
//! sharper than T_theta while the vehicle allows them.
//!
//! Graph and sampling planners (A*, RRT*, PRM*) build paths edge by edge: a valid motion costs
//! its length over L_straight, so they minimise the path's length as the paper's RRT* and PRM*
//! do. Those motion costs add up to L_path / L_straight = 1 / (1 - C_length), which orders
//! paths as C_length does: `length` is the model's additive term. Curvature, block and
//! current depend on joints, on the clock along the whole path or on normalisation by N_all:
//! they are path-level, and these planners do not see them (they are checked on the
//! finished path, where the evaluation counts them).

use super::CostModel;
use crate::error::Result;
use crate::geom::Vec3;
use crate::kinematics::fillet::{self, FlownPiece};
use crate::params::{Bound, Checked, Range};
use crate::path::PathModel;
use crate::scratch::Scratch;
use crate::world::Dims;
use std::f64::consts::{FRAC_PI_2, PI};

crate::params! {
    /// The lfhh2019 model's parameters (`[cost] weights`); the paper's terms are unweighted.
    pub struct Lfhh2019Params {
        /// T_theta (degrees): a joint whose interior angle (180 = straight on) is below this
        /// is unable.
        min_interior_angle_deg: f64 = 30.0, ANGLE, "lfhh2019";
        /// Current speed (m/s) below which the flow counts as zero: the angle to it is then
        /// neutral (pi/2).
        still_current: f64 = 1e-9, NON_NEGATIVE, "lfhh2019 (chosen, A3)";
    }
}

const ANGLE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Closed(180.0) };
const NON_NEGATIVE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded };

/// The paper's feasibility threshold: any unable joint or blocked segment adds at least 2.
pub const FEASIBLE_BELOW: f64 = 2.0;

/// Per-segment flags in `Scratch::values`: blocked at `i`, unable at `n + i`.
const SET: f64 = 1.0;

#[derive(Clone, Debug)]
pub struct Lfhh2019Cost {
    pub params: Lfhh2019Params,
}

const TERMS: [&str; 4] = ["length", "curvature", "block", "current"];

impl Lfhh2019Cost {
    pub fn new(params: Checked<Lfhh2019Params>) -> Self {
        Self { params: params.into_inner() }
    }

    /// N / N_all + 2 when N > 0, else 0 (eqs. 8 and 9).
    pub fn count_term(n: usize, n_all: usize) -> f64 {
        if n == 0 {
            0.0
        } else {
            n as f64 / n_all.max(1) as f64 + 2.0
        }
    }

    /// alpha / pi for a segment of horizontal direction `h` in a horizontal current `c`: the
    /// angle between them over pi, 1/2 where either is (practically) zero.
    pub fn current_angle_ratio(&self, h: crate::geom::Vec2, c: crate::geom::Vec2) -> f64 {
        let (h_len, c_len) = (h.length(), c.length());
        // A NaN length fails both tests: neutral too.
        if h_len > 0.0 && c_len > self.params.still_current {
            (h.dot(c) / (h_len * c_len)).clamp(-1.0, 1.0).acos() / PI
        } else {
            FRAC_PI_2 / PI
        }
    }

    /// Marks the unable segments (joints and pitch of the polyline) and the segments with an
    /// end outside the domain or depth band, in `flags` (`n` segments).
    fn geometry_flags(&self, model: &PathModel<'_>, points: &[Vec3], flags: &mut [f64]) {
        let n = points.len() - 1;
        let veh = model.vehicle;
        let three_d = model.world.dims == Dims::Three;
        let validator = &model.validator;
        // Interior angle theta < T  <=>  the angle between the directions > pi - T
        //                           <=>  cos(direction change) < -cos(T).
        let cos_limit = -self.params.min_interior_angle_deg.to_radians().cos();
        // The same comparisons as `PathModel::assess`, so the verdicts agree at the limits.
        let cos_turn_limit = veh.max_turn.cos();
        let tan_pitch_limit = veh.max_pitch.tan();
        let mut prev_dir: Option<(Vec3, f64)> = None;
        let mut prev_h: Option<(crate::geom::Vec2, f64)> = None;
        let mut a_in = validator.in_bounds(points[0]).is_ok();
        for (i, w) in points.windows(2).enumerate() {
            let dir = w[1] - w[0];
            let b_in = validator.in_bounds(w[1]).is_ok();
            if !a_in || !b_in {
                flags[i] = SET;
            }
            a_in = b_in;
            let len = dir.length();
            let mut unable = false;
            if len > 0.0 {
                if let Some((pd, pl)) = prev_dir {
                    unable |= (pd.dot(dir) / (pl * len)).clamp(-1.0, 1.0) < cos_limit;
                }
                prev_dir = Some((dir, len));
            }
            let h = dir.truncate();
            let h_len = h.length();
            if h_len > 0.0 {
                if let Some((ph, ph_len)) = prev_h {
                    unable |= (ph.dot(h) / (ph_len * h_len)).clamp(-1.0, 1.0) < cos_turn_limit;
                }
                prev_h = Some((h, h_len));
            }
            if three_d && dir.z != 0.0 {
                let slope = if h_len > 0.0 { dir.z.abs() / h_len } else { f64::INFINITY };
                unable |= slope > tan_pitch_limit;
            }
            if unable {
                flags[n + i] = SET;
            }
        }
        let tol = model.endpoint_tolerance();
        let off = |p: Vec3, q: Vec3| {
            let d = p.distance(q);
            d.is_nan() || d > tol
        };
        if off(points[0], model.start) {
            flags[0] = SET;
        }
        if off(points[n], model.goal) {
            flags[n - 1] = SET;
        }
    }

    /// Flies the path on the evaluation's clock: marks the segments whose motions are
    /// invalid, and (with a turning radius) the segments after a turn that does not fit or
    /// climbs too steeply, and fills `times` with the arrival time at each point.
    fn clock_flags(model: &PathModel<'_>, points: &[Vec3], flags: &mut [f64], times: &mut Vec<f64>) {
        let n = points.len() - 1;
        let validator = &model.validator;
        times.clear();
        let Some(r) = model.vehicle.turn_radius else {
            let mut t = model.departure_time;
            times.push(t);
            for (i, w) in points.windows(2).enumerate() {
                let m = validator.motion_at(w[0], w[1], t, model.segment_speed(i));
                if !m.valid() {
                    flags[i] = SET;
                }
                t = m.arrival;
                times.push(t);
            }
            return;
        };
        // As `PathModel::assess` on the flown curve: the times at interior waypoints are
        // halfway round their turns.
        times.resize(n + 1, model.departure_time);
        let arrival = model.walk_flown(
            points,
            r,
            |m, check, _, t1| {
                if !check.valid() {
                    flags[m.segment] = SET;
                }
                match m.turn {
                    None => times[m.segment + 1] = t1,
                    Some((arc, c, k)) => {
                        if 2 * (c + 1) == k {
                            times[arc.waypoint] = t1;
                        }
                    }
                }
            },
            |_, _, _| {},
        );
        times[n] = arrival;
        let tol = model.settings.arc_tolerance;
        let three_d = model.world.dims == Dims::Three;
        let tan_pitch_limit = model.vehicle.max_pitch.tan();
        fillet::for_each_piece(points, r, |piece| {
            if let FlownPiece::Arc(arc) = piece {
                // The same test as the flown assessment's "too tight".
                let tight = !arc.corner.fits && arc.corner.deviation(r) > tol;
                let steep = three_d && arc.a != arc.b && arc.slope() > tan_pitch_limit;
                if tight || steep {
                    flags[n + arc.waypoint] = SET;
                }
            }
        });
    }
}

impl CostModel for Lfhh2019Cost {
    fn id(&self) -> &'static str {
        "lfhh2019"
    }

    fn term_names(&self) -> &'static [&'static str] {
        &TERMS
    }

    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch, terms: &mut [f64]) -> f64 {
        terms[..4].fill(0.0);
        if points.len() < 2 {
            let tol = model.endpoint_tolerance();
            let missed = match points.first() {
                None => true,
                Some(p) => {
                    !(p.distance(model.start) <= tol && p.distance(model.goal) <= tol)
                        || model.validator.in_bounds(*p).is_err()
                }
            };
            terms[2] = Self::count_term(usize::from(missed), 1);
            return terms[2];
        }
        let n = points.len() - 1;
        let flags = &mut scratch.values;
        flags.clear();
        flags.resize(2 * n, 0.0);
        self.geometry_flags(model, points, flags);
        Self::clock_flags(model, points, flags, &mut scratch.times);
        let times = &scratch.times;
        let n_block = flags[..n].iter().filter(|&&f| f == SET).count();
        let n_unable = flags[n..].iter().filter(|&&f| f == SET).count();

        let straight = model.start.distance(model.goal);
        let length = PathModel::length(points);
        let mut current = 0.0;
        for (i, w) in points.windows(2).enumerate() {
            let mid = (w[0] + w[1]) * 0.5;
            let t_mid = 0.5 * (times[i] + times[i + 1]);
            let c = model.world.current.velocity(mid, t_mid).truncate();
            current += self.current_angle_ratio((w[1] - w[0]).truncate(), c);
        }
        terms[0] = if length > 0.0 { 1.0 - straight / length } else { 0.0 };
        terms[1] = Self::count_term(n_unable, n);
        terms[2] = Self::count_term(n_block, n);
        terms[3] = current / n as f64;
        terms[..4].iter().sum()
    }

    /// The motion costs add up to L_path / L_straight, which orders paths as C_length does.
    fn additive_terms(&self) -> &'static [&'static str] {
        &TERMS[..1]
    }

    /// A motion costs its length over L_straight, whatever the current.
    fn motion_lower_bound(&self, model: &PathModel<'_>, distance: f64, _max_ground_speed: f64) -> f64 {
        distance / reference_length(model)
    }

    /// 1 / L_straight per metre, in any current: the motion cost is the length's share.
    fn cost_per_metre(&self, model: &PathModel<'_>) -> Option<f64> {
        Some(1.0 / reference_length(model))
    }

    /// A valid motion costs l / L_straight (a shortest path minimises C_length); curvature,
    /// block and current are path-level.
    fn motion_cost_at(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64, v: f64) -> Option<(f64, f64)> {
        let m = model.validator.motion_at(a, b, t0, v);
        if !m.valid() {
            return None;
        }
        Some((a.distance(b) / reference_length(model), m.arrival))
    }

    fn feasible_below(&self) -> Option<f64> {
        Some(FEASIBLE_BELOW)
    }
}

/// L_straight for the motion costs, kept away from 0 (a mission whose start is its goal).
fn reference_length(model: &PathModel<'_>) -> f64 {
    model.start.distance(model.goal).max(1e-9)
}

/// Builds the model from `[cost.weights]`.
pub fn build(table: &toml::Table) -> Result<Box<dyn CostModel>> {
    Ok(Box::new(Lfhh2019Cost::new(Lfhh2019Params::from_table(table, "cost.weights")?)))
}

#[cfg(test)]
mod tests;
