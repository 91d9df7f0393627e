//! The one shared evaluation of a path: length, travel time through currents, turn and pitch
//! angles, clearance, collisions and feasibility. Planners, cost models, `eval` and the
//! experiment runner all call this module, so a number means the same thing everywhere. Every
//! segment is judged by the [`crate::validity`] motion check, on the clock that gives the
//! reported travel time.

mod assess;
mod assess_flown;
mod flown;
mod metrics;
mod midpoint_smooth;
mod speeds;
mod violations;

pub use crate::validity::{ModelSettings, TravelModel};
pub use assess::Assessment;
pub use flown::{Flown, FlownMotion};
pub use metrics::Metrics;
pub use midpoint_smooth::midpoint_smooth;
pub use speeds::resample_speeds;
pub use violations::{Violation, ViolationKind};

use crate::geom::Vec3;
use crate::mission::Mission;
use crate::validity::Validator;
use crate::vehicle::Vehicle;
use crate::world::World;

/// A world, a mission and the model settings: everything needed to judge a path.
#[derive(Clone, Debug)]
pub struct PathModel<'a> {
    pub world: &'a World,
    pub vehicle: &'a Vehicle,
    pub settings: &'a ModelSettings,
    pub departure_time: f64,
    pub start: Vec3,
    pub goal: Vec3,
    /// State and motion checks; the same the planners use.
    pub validator: Validator<'a>,
    /// The through-water speed of each segment of the path judged, when the plan chose them
    /// (a vehicle with a speed range); `None` flies every segment at the cruise speed. A path
    /// with more segments than speeds flies the extra ones at the last speed given.
    pub speeds: Option<&'a [f64]>,
}

impl<'a> PathModel<'a> {
    pub fn new(world: &'a World, mission: &'a Mission, settings: &'a ModelSettings) -> Self {
        Self {
            world,
            vehicle: &mission.vehicle,
            settings,
            departure_time: mission.departure_time,
            start: mission.start,
            goal: mission.goal,
            validator: Validator::new(world, &mission.vehicle, settings),
            speeds: None,
        }
    }

    /// This model judging paths whose segments are flown at `speeds` (`None`: at the cruise
    /// speed). A copy of references: no allocation, so an optimizer can make one per
    /// evaluation.
    pub fn with_speeds<'b>(&'b self, speeds: Option<&'b [f64]>) -> PathModel<'b> {
        PathModel { validator: self.validator.clone(), speeds, ..*self }
    }

    /// The through-water speed segment `i` is flown at.
    #[inline]
    pub fn segment_speed(&self, i: usize) -> f64 {
        match self.speeds {
            Some(s) if !s.is_empty() => s[i.min(s.len() - 1)],
            _ => self.vehicle.speed,
        }
    }

    /// Total 3-D length of a polyline.
    pub fn length(points: &[Vec3]) -> f64 {
        points.windows(2).map(|w| w[0].distance(w[1])).sum()
    }

    /// Fills `times` with the arrival time at each point (`times[0]` = departure) and returns the
    /// number of segment pieces the vehicle cannot traverse against the current.
    pub fn arrival_times(&self, points: &[Vec3], times: &mut Vec<f64>) -> u32 {
        times.clear();
        let mut t = self.departure_time;
        times.push(t);
        let mut blocked = 0;
        for (i, w) in points.windows(2).enumerate() {
            let (t1, b) = self.validator.for_each_piece_at(w[0], w[1], t, self.segment_speed(i), |_| {});
            let dt = t1 - t;
            t += dt;
            blocked += b;
            times.push(t);
        }
        blocked
    }

    /// Time to traverse a -> b (segment `i` of a path) leaving at `t0`, and the number of
    /// impossible pieces.
    pub fn segment_time(&self, i: usize, a: Vec3, b: Vec3, t0: f64) -> (f64, u32) {
        let (t1, blocked) = self.validator.for_each_piece_at(a, b, t0, self.segment_speed(i), |_| {});
        (t1 - t0, blocked)
    }

    /// Tolerance for "the path starts at the start and ends at the goal": 1e-9 of the domain.
    pub fn endpoint_tolerance(&self) -> f64 {
        self.world.bounds.size().max_element() * 1e-9
    }
}

#[cfg(test)]
mod flown_tests;
#[cfg(test)]
mod tests;
