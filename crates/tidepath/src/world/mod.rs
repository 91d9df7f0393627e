//! The world the robot moves through: domain, seabed, obstacles and currents.
//!
//! The world answers questions (elevation at a point, current at a point and time, does a
//! segment traversed between two times touch the seabed or an obstacle) and knows nothing about
//! planners. Every query takes a time so that moving obstacles and time-varying currents need
//! no special cases in the layers above.

pub mod current;
pub mod grid;
pub mod obstacle;
pub mod query;
pub mod terrain;

pub use current::Current;
pub use grid::RegularGrid2;
pub use obstacle::{Obstacle, Shape};
pub use terrain::Terrain;

use crate::geom::Aabb;

/// Whether motion is confined to a horizontal plane (surface craft, 2-D studies) or free in 3-D.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Dims {
    #[serde(rename = "2")]
    Two,
    #[serde(rename = "3")]
    Three,
}

/// Everything a planner needs to know about the environment.
#[derive(Clone, Debug)]
pub struct World {
    /// The domain box. In 2-D worlds only x and y matter and z holds the travel plane.
    pub bounds: Aabb,
    pub dims: Dims,
    pub terrain: Terrain,
    pub obstacles: Vec<Obstacle>,
    pub current: Current,
    /// The latitude/longitude frame of a geographic world, so messages can name places in
    /// degrees; `None` for a local one.
    pub frame: Option<crate::geo::GeoFrame>,
}

impl World {
    /// A horizontal position for messages: "48.3812 N, 123.2101 W" in a geographic world,
    /// "x, y" metres otherwise.
    pub fn place(&self, x: f64, y: f64) -> String {
        match &self.frame {
            Some(f) => f.place(x, y),
            None => format!("{x:.0}, {y:.0}"),
        }
    }

    /// An empty 3-D box: no seabed, no obstacles, still water.
    pub fn open(bounds: Aabb) -> Self {
        Self {
            bounds,
            dims: Dims::Three,
            terrain: Terrain::None,
            obstacles: Vec::new(),
            current: Current::None,
            frame: None,
        }
    }
}
