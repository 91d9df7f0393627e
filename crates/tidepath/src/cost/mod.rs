//! Cost models: each a sum of named terms, one file per paper, chosen by name in a scenario
//! (`[cost] model = "..."`). `eval` prints the terms, so a user sees why a path costs what it does.

pub mod amfa2015;
pub mod general;
pub mod ijs2023;
pub mod lfhh2019;
#[cfg(test)]
mod test_support;
pub mod wpa2017;

pub use amfa2015::{Amfa2015Cost, Amfa2015Params};
pub use general::{GeneralCost, GeneralWeights};
pub use ijs2023::{Ijs2023Cost, Ijs2023Params};
pub use lfhh2019::{Lfhh2019Cost, Lfhh2019Params};
pub use wpa2017::{Wpa2017Cost, Wpa2017Weights};

use crate::error::Result;
use crate::geom::Vec3;
use crate::path::PathModel;
use crate::registry::{Entry, Registry};
use crate::scratch::Scratch;

pub type BuildCost = fn(&toml::Table) -> Result<Box<dyn CostModel>>;

/// The cost models, selected by `[cost] model`; parameters are `[cost.weights]`.
pub const COST_MODELS: &[Entry<BuildCost>] = &[
    Entry {
        id: "general",
        description: "normalised length and time plus violation counts and excesses (users' own missions)",
        citation: "tidepath",
        params: GeneralWeights::SPECS,
        build: |t| Ok(Box::new(GeneralCost::new(GeneralWeights::from_table(t, "cost.weights")?))),
    },
    Entry {
        id: "wpa2017",
        description: "length, depth penalty, buoyancy and rudder energy, large penalty per violation (eqs. 17-21)",
        citation: "wpa2017",
        params: Wpa2017Weights::SPECS,
        build: |t| Ok(Box::new(Wpa2017Cost::new(Wpa2017Weights::from_table(t, "cost.weights")?))),
    },
    Entry {
        id: "lfhh2019",
        description:
            "length ratio, unable joints, blocked segments and angle to the current; feasible when below 2 (eqs. 6-10)",
        citation: "lfhh2019",
        params: Lfhh2019Params::SPECS,
        build: lfhh2019::build,
    },
    Entry {
        id: "amfa2015",
        description:
            "weighted length plus C times the route and evaluation points inside obstacles or the seabed (eqs. 6-8)",
        citation: "amfa2015",
        params: Amfa2015Params::SPECS,
        build: amfa2015::build,
    },
    Entry {
        id: "ijs2023",
        description:
            "normalised time through the current (vector sum) plus side-current and target penalties, times 10 if the seabed is touched and 10 if an obstacle is (eqs. 15-24)",
        citation: "ijs2023",
        params: Ijs2023Params::SPECS,
        build: ijs2023::build,
    },
];

pub fn registry() -> Registry<BuildCost> {
    Registry::new("cost model", "cost.model", "tidepath planners", COST_MODELS)
}

/// The cheapest valid motion a -> b leaving at `t0` over the vehicle's
/// [`crate::vehicle::Vehicle::speed_choices`]: (cost, arrival, speed). How graph and sampling
/// planners choose a speed per edge; without a speed range it is
/// [`CostModel::motion_cost`]. Ties go to the faster speed. A slower speed can be the only
/// valid one (a moving obstacle passes first) or the cheaper one (a cost with an energy term).
pub fn cheapest_motion(
    cost: &dyn CostModel,
    model: &PathModel<'_>,
    a: Vec3,
    b: Vec3,
    t0: f64,
) -> Option<(f64, f64, f64)> {
    let mut best: Option<(f64, f64, f64)> = None;
    for v in model.vehicle.speed_choices() {
        if let Some((c, arrival)) = cost.motion_cost_at(model, a, b, t0, v) {
            if best.is_none_or(|(bc, ..)| c < bc) {
                best = Some((c, arrival, v));
            }
        }
    }
    best
}

/// The speeds [`cheapest_motion`] picks along `points` on the running clock, one per segment
/// (the cruise speed where no speed gives a valid motion): the speeds an edge-by-edge search
/// chose, since it priced each edge of its path the same way at the same departure time.
/// `None` for a vehicle without a speed range.
pub fn edge_speeds(cost: &dyn CostModel, model: &PathModel<'_>, points: &[Vec3]) -> Option<Vec<f64>> {
    model.vehicle.speed_range?;
    let mut t = model.departure_time;
    let mut out = Vec::with_capacity(points.len().saturating_sub(1));
    for w in points.windows(2) {
        let v = match cheapest_motion(cost, model, w[0], w[1], t) {
            Some((_, arrival, v)) => {
                t = arrival;
                v
            }
            None => {
                let v = model.vehicle.speed;
                t += model.validator.travel_time(w[0], w[1], t).0;
                v
            }
        };
        out.push(v);
    }
    Some(out)
}

/// The most terms any model may have; term buffers live on the stack.
pub const MAX_TERMS: usize = 8;

/// A cost to minimise over paths (start and goal included in `points`).
pub trait CostModel: Send + Sync {
    /// The name used in scenario files (`general`, ...).
    fn id(&self) -> &'static str;
    /// Names of the terms, in the order `evaluate` writes them.
    fn term_names(&self) -> &'static [&'static str];
    /// Writes each weighted term into `terms[..term_names().len()]` and returns their sum.
    /// Must not allocate once `scratch` has grown to the path's size. `model` carries the
    /// mission (start, goal, vehicle, departure), so one model serves every mission.
    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch, terms: &mut [f64]) -> f64;

    /// The cost of one motion a -> b leaving at `t0` at through-water speed `v`, for the
    /// model's additive terms, and the arrival time, so graph and sampling planners that build
    /// paths edge by edge accumulate what the evaluation reports; `None` when the motion is
    /// invalid. Path-level terms (turn and pitch penalties at joints, normalisation constants)
    /// are the model's to document.
    fn motion_cost_at(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64, v: f64) -> Option<(f64, f64)>;

    /// [`CostModel::motion_cost_at`] at the vehicle's cruise speed.
    fn motion_cost(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64) -> Option<(f64, f64)> {
        self.motion_cost_at(model, a, b, t0, model.vehicle.speed)
    }

    /// The terms `motion_cost` accumulates (the rest are path-level: they depend on joints or
    /// on the whole path), for the reasons plans give.
    fn additive_terms(&self) -> &'static [&'static str];

    /// A lower bound on the additive cost of covering `distance` metres for the mission of
    /// `model`, at a ground speed of at most `max_ground_speed`: the heuristic of graph
    /// searches, admissible whenever `max_ground_speed` really bounds the ground speed.
    fn motion_lower_bound(&self, model: &PathModel<'_>, distance: f64, max_ground_speed: f64) -> f64;

    /// When every motion's additive cost is this many units per metre whatever its direction
    /// and time (no current), the factor: then a shortest path is a cheapest one.
    fn cost_per_metre(&self, model: &PathModel<'_>) -> Option<f64>;

    /// The model's own feasibility rule, when its paper has one: a path is feasible under it
    /// when its total is below this (lfhh2019: 2). Reported beside tidepath's verdict
    /// ([`crate::path::Assessment::feasible`]), never instead of it.
    fn feasible_below(&self) -> Option<f64> {
        None
    }

    /// The total only.
    fn cost(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch) -> f64 {
        let mut terms = [0.0; MAX_TERMS];
        self.evaluate(model, points, scratch, &mut terms)
    }

    /// The terms as (name, value) pairs, for reports.
    fn breakdown(&self, model: &PathModel<'_>, points: &[Vec3]) -> (f64, Vec<(&'static str, f64)>) {
        let mut terms = [0.0; MAX_TERMS];
        let total = self.evaluate(model, points, &mut Scratch::default(), &mut terms);
        (total, self.term_names().iter().copied().zip(terms).collect())
    }
}
