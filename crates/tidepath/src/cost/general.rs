//! The general cost model: weighted length, travel time, collision penalty and turn and pitch
//! penalties. Not from a paper; it is the model for users' own missions, where each term is
//! normalised by its straight-line value so the weights are comparable.
//!
//! cost = w_length L / L0 + w_time T / T0 + w_collision N_violations
//!      + w_turn (N_turn + sum turn excess in rad) + w_pitch (N_pitch + sum pitch excess in rad)
//!
//! With a turning radius, N_turn also counts the turns whose fillet does not fit in their legs,
//! and the turn excess adds each one's shortfall 1 - (radius flown / the vehicle's radius).
//!
//! L0 is the straight start-goal distance and T0 = L0 / cruise speed. N_violations counts
//! collisions (segment-object pairs within the safety distance), waypoints out of the domain or
//! depth band, and pieces where the current stops the vehicle. Penalties are a count plus the
//! excess: the count makes each violation cost about as much as the whole straight path, so a
//! feasible path always wins, and the excess gives the search a direction.

use super::CostModel;
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::params::{Bound, Checked, Range};
use crate::path::PathModel;
use crate::scratch::Scratch;

crate::params! {
    /// The general model's weights (`[cost] weights`).
    pub struct GeneralWeights {
        /// Weight of length over the straight start-goal distance.
        length: f64 = 1.0, NON_NEGATIVE, "tidepath";
        /// Weight of travel time over the still-water straight time.
        time: f64 = 1.0, NON_NEGATIVE, "tidepath";
        /// Per collision, bounds, endpoint or current violation.
        collision: f64 = 10.0, NON_NEGATIVE, "tidepath";
        /// Per turn violation plus its excess (rad).
        turn: f64 = 1.0, NON_NEGATIVE, "tidepath";
        /// Per pitch violation plus its excess (rad).
        pitch: f64 = 1.0, NON_NEGATIVE, "tidepath";
    }
    check = some_length_or_time;
}

const NON_NEGATIVE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded };

/// A model that weighs neither length nor time has nothing to minimise.
fn some_length_or_time(w: &GeneralWeights, prefix: &str) -> Result<()> {
    if w.length + w.time == 0.0 {
        return Err(Error::input(prefix, "length and time cannot both be 0"));
    }
    Ok(())
}

#[derive(Clone, Debug)]
pub struct GeneralCost {
    pub weights: GeneralWeights,
}

impl GeneralCost {
    pub fn new(weights: Checked<GeneralWeights>) -> Self {
        Self { weights: weights.into_inner() }
    }

    /// Straight start-goal distance L0 (m) and the time to cover it in still water T0 (s) for
    /// the mission of `model`: the normalisation of the length and time terms.
    pub fn references(model: &PathModel<'_>) -> (f64, f64) {
        let l0 = model.start.distance(model.goal).max(1e-9);
        (l0, l0 / model.vehicle.speed)
    }
}

const TERMS: [&str; 5] = ["length", "time", "collision", "turn", "pitch"];

impl CostModel for GeneralCost {
    fn id(&self) -> &'static str {
        "general"
    }

    fn term_names(&self) -> &'static [&'static str] {
        &TERMS
    }

    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch, terms: &mut [f64]) -> f64 {
        let a = model.assess(points, &mut scratch.times);
        let w = &self.weights;
        let (l0, t0) = Self::references(model);
        terms[0] = w.length * a.length / l0;
        terms[1] = w.time * a.travel_time / t0;
        terms[2] = w.collision
            * (a.collisions + a.bounds_violations + a.endpoint_violations + a.current_blocked + a.current_gaps) as f64;
        // A turn whose fillet does not fit (a vehicle with a turning radius) is a turn
        // violation too: one each, plus its shortfall 1 - radius flown / radius, in [0, 1].
        terms[3] = w.turn * ((a.turn_violations + a.radius_violations) as f64 + a.turn_excess + a.radius_excess);
        terms[4] = w.pitch * (a.pitch_violations as f64 + a.pitch_excess);
        terms[..5].iter().sum()
    }

    fn additive_terms(&self) -> &'static [&'static str] {
        &TERMS[..2]
    }

    /// Covering `distance` takes at least `distance / max_ground_speed`.
    fn motion_lower_bound(&self, model: &PathModel<'_>, distance: f64, max_ground_speed: f64) -> f64 {
        let (l0, t0) = Self::references(model);
        let w = &self.weights;
        w.length * distance / l0 + w.time * distance / max_ground_speed.max(f64::MIN_POSITIVE) / t0
    }

    /// In still water the time is the length over the vehicle's speed.
    fn cost_per_metre(&self, model: &PathModel<'_>) -> Option<f64> {
        if !matches!(model.validator.world.current, crate::world::Current::None) {
            return None;
        }
        let (l0, t0) = Self::references(model);
        Some(self.weights.length / l0 + self.weights.time / (model.vehicle.speed * t0))
    }

    /// Length and time are additive: a valid motion costs w_length l / L0 + w_time dt / T0.
    /// The turn and pitch penalties are path-level (they depend on joints); planners that build
    /// paths edge by edge check them on the finished path, where the evaluation counts them.
    fn motion_cost_at(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64, v: f64) -> Option<(f64, f64)> {
        let m = model.validator.motion_at(a, b, t0, v);
        if !m.valid() {
            return None;
        }
        let (l0, tt0) = Self::references(model);
        let w = &self.weights;
        Some((w.length * a.distance(b) / l0 + w.time * (m.arrival - t0) / tt0, m.arrival))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Aabb;
    use crate::mission::Mission;
    use crate::path::ModelSettings;
    use crate::vehicle::Vehicle;
    use crate::world::World;

    /// A turn too sharp for the radius costs the turn weight times (1 + its shortfall); the
    /// same path without a radius pays nothing for it.
    #[test]
    fn a_turn_that_does_not_fit_is_a_turn_violation_with_its_shortfall() {
        let w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -10.0), Vec3::new(300.0, 300.0, 0.0)));
        let p = [Vec3::new(0.0, 0.0, -5.0), Vec3::new(100.0, 0.0, -5.0), Vec3::new(100.0, 100.0, -5.0)];
        let s = ModelSettings::default();
        let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
        let turn_term = |radius| {
            let v = Vehicle { turn_radius: radius, max_turn: std::f64::consts::PI, ..Vehicle::default() };
            let mission = Mission::new("m", v, p[0], p[2], 0.0);
            let model = PathModel::new(&w, &mission, &s);
            let (_, terms) = cost.breakdown(&model, &p);
            terms.iter().find(|t| t.0 == "turn").unwrap().1
        };
        assert_eq!(turn_term(None), 0.0);
        assert_eq!(turn_term(Some(100.0)), 0.0, "a 90 degree turn at r = 100 fits 100 m legs");
        // r = 200 needs 200 m of each leg; 100 m allow r = 100: shortfall 1/2.
        assert!((turn_term(Some(200.0)) - 1.5).abs() < 1e-12);
    }
}
