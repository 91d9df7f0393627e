//! Turning-radius kinematics: what a vehicle that cannot turn on the spot flies.
//!
//! A path stays a polyline of waypoints everywhere in tidepath (planners, files, exports). A
//! vehicle with a turning radius r flies it the way waypoint-following autopilots do: it
//! starts turning before each waypoint and flies a circular arc of radius r tangent to both
//! legs (a *fillet*), then the straight rest of the next leg ([`fillet`]). The evaluation
//! judges that flown curve: its length, its clock through the currents, its clearance, and
//! whether each fillet fits in its legs.
//!
//! The converse makes exact curves representable: the polyline whose fillets are a given
//! arc is the arc's *tangent polygon* (its vertices are where the tangents at the ends of
//! equal pieces of the arc meet, [`tangent`]). Dubins paths ([`dubins`]) and Hybrid-A*
//! primitives are written as tangent polygons, so their flown curve is exactly the arcs and
//! straights they were built from.
//!
//! Headings are radians counter-clockwise from east (+x), as in OMPL's `SE2StateSpace`.

pub mod dubins;
pub mod dubins3;
pub mod fillet;
pub mod tangent;

pub use fillet::{Corner, FlownPiece};
pub use tangent::TangentPolygon;

use crate::geom::{Vec2, Vec3};

/// A position and a horizontal heading (rad, counter-clockwise from east).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub p: Vec3,
    pub heading: f64,
}

impl Pose {
    pub fn new(p: Vec3, heading: f64) -> Self {
        Self { p, heading }
    }

    /// The unit horizontal direction of the heading.
    pub fn dir(&self) -> Vec2 {
        Vec2::new(self.heading.cos(), self.heading.sin())
    }
}

/// Heading of a horizontal direction (rad), or `None` when it has no horizontal extent.
pub fn heading_of(d: Vec3) -> Option<f64> {
    let h = d.truncate();
    (h.length_squared() > 0.0).then(|| h.y.atan2(h.x))
}

/// `a` wrapped into (-pi, pi].
pub fn wrap_angle(a: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let w = a.rem_euclid(tau);
    if w > std::f64::consts::PI {
        w - tau
    } else {
        w
    }
}
