//! The general cost model: weighted length, travel time, collision penalty and turn and pitch
//! penalties. Not from a paper; it is the model for users' own missions, where each term is
//! normalised by its straight-line value so the weights are comparable.
//!
//! cost = w_length L / L0 + w_time T / T0 + w_collision N_violations
//!      + w_turn (N_turn + sum turn excess in rad) + w_pitch (N_pitch + sum pitch excess in rad)
//!
//! L0 is the straight start-goal distance and T0 = L0 / cruise speed. N_violations counts
//! collisions (segment-object pairs within the safety distance), waypoints out of the domain or
//! depth band, and pieces where the current stops the vehicle. Penalties are a count plus the
//! excess: the count makes each violation cost about as much as the whole straight path, so a
//! feasible path always wins, and the excess gives the search a direction.

use serde::{Deserialize, Serialize};

use super::CostModel;
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::optim::Scratch;
use crate::path::PathModel;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GeneralWeights {
    pub length: f64,
    pub time: f64,
    pub collision: f64,
    pub turn: f64,
    pub pitch: f64,
}

impl Default for GeneralWeights {
    fn default() -> Self {
        Self { length: 1.0, time: 1.0, collision: 10.0, turn: 1.0, pitch: 1.0 }
    }
}

impl GeneralWeights {
    pub fn check(&self) -> Result<()> {
        for (name, w) in [
            ("length", self.length),
            ("time", self.time),
            ("collision", self.collision),
            ("turn", self.turn),
            ("pitch", self.pitch),
        ] {
            if !(w >= 0.0 && w.is_finite()) {
                return Err(Error::input(format!("cost.weights.{name}"), format!("must be finite and >= 0, got {w}")));
            }
        }
        if self.length + self.time == 0.0 {
            return Err(Error::input("cost.weights", "length and time cannot both be 0"));
        }
        Ok(())
    }
}

#[derive(Clone, Debug)]
pub struct GeneralCost {
    pub weights: GeneralWeights,
    /// Straight start-goal distance (m) and the time to cover it in still water (s).
    pub ref_length: f64,
    pub ref_time: f64,
}

impl GeneralCost {
    pub fn new(weights: GeneralWeights, start: Vec3, goal: Vec3, speed: f64) -> Result<Self> {
        weights.check()?;
        let ref_length = start.distance(goal).max(1e-9);
        Ok(Self { weights, ref_length, ref_time: ref_length / speed })
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
        terms[0] = w.length * a.length / self.ref_length;
        terms[1] = w.time * a.travel_time / self.ref_time;
        terms[2] = w.collision * (a.collisions + a.bounds_violations + a.current_blocked) as f64;
        terms[3] = w.turn * (a.turn_violations as f64 + a.turn_excess);
        terms[4] = w.pitch * (a.pitch_violations as f64 + a.pitch_excess);
        terms[..5].iter().sum()
    }
}
