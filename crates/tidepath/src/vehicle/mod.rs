//! What the robot can do. Angles are stored in radians; scenario files give degrees.

mod glider;

pub use glider::GliderSpeed;

/// How the vehicle is propelled, which decides its speed over ground.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Propulsion {
    /// Thrusters: a through-water speed the plan chooses, combined with the current by the
    /// scenario's travel model.
    #[default]
    Thruster,
    /// A wave glider (acopf2016): the speed over ground follows the sea state and the current
    /// ([`GliderSpeed`]); `speed`, `speed_range` and the travel model do not apply.
    WaveGlider(GliderSpeed),
}

/// Performance limits of one vehicle.
#[derive(Clone, Debug, PartialEq)]
pub struct Vehicle {
    /// Cruise speed through the water (m/s), used for travel time.
    pub speed: f64,
    /// Maximum change of horizontal heading at a waypoint (rad).
    pub max_turn: f64,
    /// Maximum climb or dive angle of a segment (rad).
    pub max_pitch: f64,
    /// Allowed depth band (m, positive down): the vehicle keeps z in [-depth_max, -depth_min].
    pub depth_min: f64,
    pub depth_max: f64,
    /// Minimum distance to keep from the seabed (vertically) and from obstacles (m).
    pub safety_distance: f64,
    /// Minimum horizontal turning radius (m; wpa2017 eq. 9: r_min = V^2 / a_max). With one,
    /// the vehicle flies each polyline with circular fillets at its waypoints
    /// ([`crate::kinematics::fillet`]) and every check runs on that flown curve; `None` keeps
    /// only the angle limit at waypoints.
    pub turn_radius: Option<f64>,
    /// Through-water speeds (m/s) the vehicle may fly a segment at, lowest and highest, with
    /// `speed` between them. With a range, speed is a decision: a plan gives each segment its
    /// own speed in it (fleets meeting an arrival time, energy against time); `None` flies
    /// every segment at `speed`.
    pub speed_range: Option<(f64, f64)>,
    /// Thrusters or waves.
    pub propulsion: Propulsion,
}

impl Vehicle {
    /// Highest allowed z.
    pub fn z_max(&self) -> f64 {
        -self.depth_min
    }

    /// Lowest allowed z.
    pub fn z_min(&self) -> f64 {
        -self.depth_max
    }

    /// The highest through-water speed a segment may be flown at.
    pub fn max_speed(&self) -> f64 {
        self.speed_range.map_or(self.speed, |(_, hi)| hi)
    }

    /// The fastest ground speed possible where waves are at most `wave_bound` (m) and the
    /// current at most `current_bound` (m/s): what admissible heuristics divide distances by.
    pub fn best_ground_speed(&self, wave_bound: f64, current_bound: f64) -> f64 {
        match self.propulsion {
            Propulsion::Thruster => self.max_speed() + current_bound,
            Propulsion::WaveGlider(g) => g.best_speed(wave_bound, current_bound),
        }
    }

    /// The wave glider's speed model, if the vehicle is one.
    pub fn glider(&self) -> Option<&GliderSpeed> {
        match &self.propulsion {
            Propulsion::WaveGlider(g) => Some(g),
            Propulsion::Thruster => None,
        }
    }

    /// The speeds graph and sampling planners try on each edge, fastest first: the range's
    /// top, the cruise speed and the range's bottom (distinct ones only); just the cruise
    /// speed without a range. Three levels keep the edge cost at most three motion checks.
    pub fn speed_choices(&self) -> impl Iterator<Item = f64> {
        let (lo, hi) = self.speed_range.unwrap_or((self.speed, self.speed));
        let levels = [hi, self.speed, lo];
        (0..3).filter_map(move |k| (k == 0 || levels[k] < levels[k - 1]).then_some(levels[k]))
    }

    /// `v` brought into the vehicle's speed range (the cruise speed without one).
    pub fn clamp_speed(&self, v: f64) -> f64 {
        match self.speed_range {
            Some((lo, hi)) if v.is_finite() => v.clamp(lo, hi),
            Some(_) | None => self.speed,
        }
    }
}

impl Default for Vehicle {
    /// A generic survey AUV: 1.5 m/s (about 3 kn), 60 degree turns, 30 degree pitch, 10 m safety,
    /// no turning radius.
    fn default() -> Self {
        Self {
            speed: 1.5,
            max_turn: 60f64.to_radians(),
            max_pitch: 30f64.to_radians(),
            depth_min: 0.0,
            depth_max: 6000.0,
            safety_distance: 10.0,
            turn_radius: None,
            speed_range: None,
            propulsion: Propulsion::Thruster,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn speed_choices_are_distinct_and_fastest_first() {
        let v = Vehicle { speed: 1.5, speed_range: Some((0.5, 2.0)), ..Vehicle::default() };
        assert_eq!(v.speed_choices().collect::<Vec<_>>(), vec![2.0, 1.5, 0.5]);
        assert_eq!(v.max_speed(), 2.0);
        let top = Vehicle { speed: 2.0, speed_range: Some((0.5, 2.0)), ..Vehicle::default() };
        assert_eq!(top.speed_choices().collect::<Vec<_>>(), vec![2.0, 0.5]);
        let fixed = Vehicle::default();
        assert_eq!(fixed.speed_choices().collect::<Vec<_>>(), vec![1.5]);
        assert_eq!(fixed.max_speed(), 1.5);
        assert_eq!(v.clamp_speed(3.0), 2.0);
        assert_eq!(v.clamp_speed(f64::NAN), 1.5);
        assert_eq!(fixed.clamp_speed(3.0), 1.5);
    }
}
