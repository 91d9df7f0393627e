//! What the robot can do. Angles are stored in radians; scenario files give degrees.

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
        }
    }
}
