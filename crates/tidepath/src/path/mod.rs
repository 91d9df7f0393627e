//! The one shared evaluation of a path: length, travel time through currents, turn and pitch
//! angles, clearance, collisions and feasibility. Planners, cost models, `eval` and the
//! experiment runner all call this module, so a number means the same thing everywhere.

mod assess;
mod metrics;
mod obstacle_index;
mod travel;
mod violations;

pub use assess::Assessment;
pub use metrics::Metrics;
pub use travel::TravelModel;
pub use violations::{Violation, ViolationKind};

use crate::geom::Vec3;
use crate::vehicle::Vehicle;
use crate::world::World;

/// Numerical settings of the evaluation, set per scenario under `[model]`.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelSettings {
    pub travel: TravelModel,
    /// Longest sub-step (m) over which the current is taken as constant when integrating
    /// travel time along a segment (crab model). Smaller is more accurate and slower.
    pub current_step: f64,
}

impl Default for ModelSettings {
    fn default() -> Self {
        Self { travel: TravelModel::Crab, current_step: 500.0 }
    }
}

/// A world, a vehicle and a departure time: everything needed to judge a path.
#[derive(Clone, Debug)]
pub struct PathModel<'a> {
    pub world: &'a World,
    pub vehicle: &'a Vehicle,
    pub departure_time: f64,
    pub settings: &'a ModelSettings,
    /// Which obstacles each segment needs testing against; built once per model.
    obstacles: obstacle_index::ObstacleIndex,
}

impl<'a> PathModel<'a> {
    pub fn new(world: &'a World, vehicle: &'a Vehicle, departure_time: f64, settings: &'a ModelSettings) -> Self {
        let obstacles = obstacle_index::ObstacleIndex::new(world, vehicle.safety_distance);
        Self { world, vehicle, departure_time, settings, obstacles }
    }

    /// Total 3-D length of a polyline.
    pub fn length(points: &[Vec3]) -> f64 {
        points.windows(2).map(|w| w[0].distance(w[1])).sum()
    }
}

#[cfg(test)]
mod tests;
