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
}

impl World {
    /// An empty 3-D box: no seabed, no obstacles, still water.
    pub fn open(bounds: Aabb) -> Self {
        Self { bounds, dims: Dims::Three, terrain: Terrain::None, obstacles: Vec::new(), current: Current::None }
    }
}
