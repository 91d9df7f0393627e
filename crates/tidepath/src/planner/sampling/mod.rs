//! Sampling planners: RRT*, Informed RRT* and PRM* (Karaman & Frazzoli 2011; Gammell,
//! Srinivasa & Barfoot 2014), in 2-D and 3-D, on the shared validity module and the
//! scenario's cost model, at the vehicle's own clock.
//!
//! What the three share lives here:
//! * [`SampleSpace`]: the domain box (and in 3-D the vehicle's depth band) sampled uniformly
//!   from the run's RNG; in a 2-D world the samples lie at the start's height.
//! * [`Edges`]: an edge a -> b leaving at t is priced by the cost model's
//!   [`crate::cost::CostModel::motion_cost`] (which also judges it: seabed, obstacles, moving
//!   ones at the vehicle's clock, the current), so the tree's cost of a path is what the
//!   evaluation sums for its additive terms. A blocked edge is cut at its last valid point by
//!   [`crate::validity::Validator::last_valid`] to within `resolution` metres (the one
//!   resolution setting of these planners). The vehicle's path-level limits are kept at every
//!   joint of the tree (see [`Kinematics`]), so a path the tree holds has no turn or pitch
//!   violation for the evaluation to find.
//! * the neighbour index ([`neighbours`]: an R*-tree from the `rstar` crate);
//! * the rewiring radius of Karaman & Frazzoli ([`rewire_radius`]);
//! * the budget ([`Budget`]): samples, wall time, target cost and the stop flag, polled every
//!   sample and inside every long loop.

mod informed;
mod kinematics;
mod neighbours;
mod prm_star;
mod rrt_star;
mod space;
#[cfg(test)]
mod tests;
mod tree;

pub use kinematics::Kinematics;
pub use prm_star::{PrmStar, PrmStarParams};
pub use rrt_star::{RrtStar, RrtStarParams};
pub use space::{rewire_radius, unit_ball_measure, SampleSpace, Variant};

use super::raster_search::{current_speed_bound, time_invariant};
use super::{Claim, PlannerOutput, Problem};
use crate::cost::CostModel;
use crate::geom::Vec3;
use crate::path::PathModel;
use crate::termination::{StopReason, Termination};

/// Samples drawn when the run sets no sample limit (`--samples`, `[planner] samples`): OMPL's
/// benchmarks of RRT* commonly use 10,000 iterations.
pub const DEFAULT_SAMPLES: usize = 10_000;

/// Most vertices a tree keeps (about 130 bytes each with the neighbour index: some 1.1 GB) and
/// most a roadmap keeps (with its edges, some 2 GB): a run that reaches the cap stops growing
/// and says so, so a huge `--samples` cannot exhaust the memory.
pub const MAX_TREE_VERTICES: usize = 1 << 23;
pub const MAX_ROADMAP_VERTICES: usize = 1 << 20;

/// The resolution of edge cuts when `resolution` is not set: a hundredth of the steering
/// range (OMPL checks motions at 1 % of the space's extent by default).
pub const RESOLUTION_OF_RANGE: f64 = 0.01;

/// Edges of one mission: pricing, cutting at the last valid point, and the vehicle's limits.
pub struct Edges<'a> {
    pub model: PathModel<'a>,
    pub cost: &'a dyn CostModel,
    /// Metres to which a blocked edge's last valid point is found.
    pub resolution: f64,
    pub kinematics: Kinematics,
    /// The world changes in time (moving obstacles, a time-varying current): an edge's cost
    /// and validity depend on when the vehicle leaves.
    pub time_varying: bool,
    /// The best ground speed the current allows (m/s), for lower bounds on edge costs.
    pub best_speed: f64,
    /// Motion checks made (every pricing and every bisection step).
    pub motion_checks: u64,
}

impl<'a> Edges<'a> {
    /// The edges of mission `i`; `resolution` in metres. `None` when `stop` ended the
    /// sampling of the current's peak speed (thousands of vortices make it slow).
    pub fn new(problem: &Problem<'a>, i: usize, resolution: f64, stop: &dyn Fn() -> bool) -> Option<Self> {
        let model = problem.path_model(i);
        let v = &problem.missions[i].vehicle;
        let current = match current_speed_bound(problem.world) {
            Some(b) => b,
            // Sampled fields (vortices, jets): 1.5 times the sampled peak, as the raster
            // planners use; the bound then only orders candidates, it proves nothing.
            None => {
                let w = problem.world;
                1.5 * w.current.max_speed_hint_within(&w.bounds, problem.missions[i].departure_time, stop)?
            }
        };
        Some(Self {
            kinematics: Kinematics::of(v, problem.z_range(i).is_some()),
            model,
            cost: problem.cost,
            resolution,
            time_varying: !time_invariant(problem.world),
            best_speed: v.best_ground_speed(problem.world.waves.height_bound(), current),
            motion_checks: 0,
        })
    }

    /// The additive cost of a -> b leaving at `t0` and the arrival time; `None` when the
    /// motion is invalid. With a speed range, at the cheapest of the vehicle's speed levels
    /// (each level a motion check).
    #[inline]
    pub fn price(&mut self, a: Vec3, b: Vec3, t0: f64) -> Option<(f64, f64)> {
        self.motion_checks += self.model.vehicle.speed_choices().count() as u64;
        crate::cost::cheapest_motion(self.cost, &self.model, a, b, t0).map(|(c, t, _)| (c, t))
    }

    /// A lower bound on the additive cost of covering `distance` metres.
    #[inline]
    pub fn lower_bound(&self, distance: f64) -> f64 {
        self.cost.motion_lower_bound(&self.model, distance, self.best_speed)
    }

    /// The edge a -> b leaving at `t0` if valid, else its longest valid prefix (to within the
    /// resolution): the end point, its cost and the arrival time. `None` when not even a
    /// prefix is valid, or when the edge breaks the vehicle's pitch limit.
    pub fn extend(&mut self, a: Vec3, b: Vec3, t0: f64) -> Option<(Vec3, f64, f64)> {
        if !self.kinematics.edge_ok(a, b) {
            return None;
        }
        if let Some((c, t)) = self.price(a, b, t0) {
            return Some((b, c, t));
        }
        let (cut, checks) = self.model.validator.last_valid(a, b, t0, self.resolution);
        self.motion_checks += u64::from(checks);
        let p = cut?;
        self.price(a, p, t0).map(|(c, t)| (p, c, t))
    }
}

/// One run's budget for one mission: a sample limit, and the run's termination (wall time,
/// stop flag, target cost).
pub struct Budget<'t> {
    pub termination: &'t Termination,
    pub max_samples: u64,
    pub samples: u64,
}

impl Budget<'_> {
    /// Why to stop before the next sample, given the best cost so far.
    #[inline]
    pub fn stop(&self, best: f64) -> Option<StopReason> {
        if self.samples >= self.max_samples {
            return Some(StopReason::MaxSamples);
        }
        if self.termination.target_cost.is_some_and(|t| best <= t) {
            return Some(StopReason::TargetCost);
        }
        self.termination.interrupted()
    }
}

/// The sample limit and wall-time share of mission `i` of `n`, planned one after another: an
/// even share of what is left, so a fleet's last mission is not starved.
pub fn mission_budget(termination: &Termination, total: u64, used: u64, i: usize, n: usize) -> (u64, Termination) {
    let left = (n - i).max(1) as u64;
    let samples = total.saturating_sub(used) / left + u64::from(i + 1 == n) * (total.saturating_sub(used) % left);
    (samples, termination.share_of_remaining(1.0 / left as f64))
}

/// What one mission's search gave: its path, its additive cost (+inf without a path to the
/// goal), why its sampling stopped, and a line for the plan's reason (said when it fails).
pub struct MissionRun {
    pub path: Vec<Vec3>,
    pub best: f64,
    pub stopped: Option<StopReason>,
    pub hint: Option<String>,
}

/// Runs a sampling planner's missions one after another: `run(i, termination, samples,
/// earlier, out)` searches mission `i` within its share of the budget, appending to `out`'s
/// history (offset by `earlier`, the earlier missions' total) and counts. The first hint
/// becomes the claim.
pub fn plan_missions(
    problem: &Problem<'_>,
    termination: &Termination,
    default_samples: u64,
    mut run: impl FnMut(usize, &Termination, u64, f64, &mut PlannerOutput) -> MissionRun,
) -> PlannerOutput {
    let watch = termination.start();
    let n = problem.missions.len();
    let total = termination.max_samples.unwrap_or(default_samples);
    let mut out = PlannerOutput::default();
    let (mut earlier, mut hint) = (0.0, None);
    for i in 0..n {
        let (samples, share) = mission_budget(termination, total, out.stats.samples, i, n);
        let r = run(i, &share, samples, earlier, &mut out);
        earlier += r.best;
        if let Some(s) = r.stopped {
            out.stats.stop_reason = s;
        }
        hint = hint.or(r.hint);
        out.paths.push(r.path);
    }
    out.claim = hint.map(Claim::Hint);
    out.stats.elapsed = watch.elapsed();
    out
}

/// The resolution in metres: the parameter, else [`RESOLUTION_OF_RANGE`] of `range`.
pub fn resolution_or(resolution: Option<f64>, range: f64) -> f64 {
    resolution.unwrap_or(RESOLUTION_OF_RANGE * range).max(1e-6)
}
