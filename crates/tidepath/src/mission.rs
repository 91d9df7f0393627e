//! A mission: one vehicle going from a start to a goal, leaving at a departure time. A planning
//! problem holds one or more (a fleet); a plan gives one timed path per mission.

use crate::geom::Vec3;
use crate::vehicle::Vehicle;

#[derive(Clone, Debug, PartialEq)]
pub struct Mission {
    /// Shown in reports and exports; unique within a problem.
    pub name: String,
    pub vehicle: Vehicle,
    pub start: Vec3,
    pub goal: Vec3,
    /// Seconds on the scenario clock (the clock of moving obstacles and time-varying currents).
    pub departure_time: f64,
}

impl Mission {
    pub fn new(name: impl Into<String>, vehicle: Vehicle, start: Vec3, goal: Vec3, departure_time: f64) -> Self {
        Self { name: name.into(), vehicle, start, goal, departure_time }
    }
}
