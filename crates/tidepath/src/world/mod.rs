//! The world the robot moves through: domain, seabed, obstacles, currents and waves.
//!
//! The world answers questions (elevation at a point, current at a point and time, does a
//! segment traversed between two times touch the seabed or an obstacle) and knows nothing about
//! planners. Every query takes a time so that moving obstacles and time-varying currents need
//! no special cases in the layers above.

pub mod cell_numbering;
pub mod changes;
pub mod current;
pub mod grid;
pub mod node_gaps;
pub mod obstacle;
pub mod query;
pub mod terrain;
pub mod waves;

pub use current::Current;
pub use grid::RegularGrid2;
pub use obstacle::{Obstacle, Shape};
pub use terrain::Terrain;
pub use waves::Waves;

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
    /// The sea state: significant wave height, read by wave-propelled vehicles only.
    pub waves: Waves,
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

    /// A point for messages, in the user's frame: "48.3812 N, 123.2101 W, depth 30.0 m" in a
    /// geographic world (depth positive down, as typed), "[x, y, z]" metres otherwise.
    pub fn point(&self, p: crate::geom::Vec3) -> String {
        match &self.frame {
            Some(f) if p.z > 0.0 => format!("{}, {:.1} m above the sea surface", f.place(p.x, p.y), p.z),
            Some(f) => format!("{}, depth {:.1} m", f.place(p.x, p.y), -p.z + 0.0),
            None => format!("[{:.1}, {:.1}, {:.1}]", p.x, p.y, p.z),
        }
    }

    /// The domain for messages: its latitude and longitude ranges and depths in a geographic
    /// world (of the frame-aligned rectangle holding the scenario's box), its corners in metres
    /// otherwise.
    pub fn domain_text(&self) -> String {
        let (lo, hi) = (self.bounds.min, self.bounds.max);
        let Some(f) = &self.frame else {
            return format!("[{:.1}, {:.1}, {:.1}] .. [{:.1}, {:.1}, {:.1}]", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
        };
        // The rectangle's edges, sampled: its extreme latitudes and longitudes.
        let (mut lon, mut lat) = ([f64::INFINITY, f64::NEG_INFINITY], [f64::INFINITY, f64::NEG_INFINITY]);
        const N: usize = 64;
        for k in 0..=N {
            let u = k as f64 / N as f64;
            let (x, y) = (lo.x + u * (hi.x - lo.x), lo.y + u * (hi.y - lo.y));
            for (px, py) in [(x, lo.y), (x, hi.y), (lo.x, y), (hi.x, y)] {
                let (a, b) = f.inverse(px, py);
                // Longitudes relative to the origin's, so a box across the antimeridian stays whole.
                let a = f.lon0 + crate::geo::normalise_lon(a - f.lon0);
                lon = [lon[0].min(a), lon[1].max(a)];
                lat = [lat[0].min(b), lat[1].max(b)];
            }
        }
        let ns = |v: f64| format!("{:.4} {}", v.abs(), if v >= 0.0 { "N" } else { "S" });
        let ew = |v: f64| {
            let v = crate::geo::normalise_lon(v);
            format!("{:.4} {}", v.abs(), if v >= 0.0 { "E" } else { "W" })
        };
        let depths = match self.dims {
            Dims::Two => format!("the plane at depth {:.1} m (a 2-D world)", -hi.z + 0.0),
            Dims::Three => format!("depth {:.1} to {:.1} m", -hi.z + 0.0, -lo.z + 0.0),
        };
        format!("{} to {}, {} to {}, {depths}", ns(lat[0]), ns(lat[1]), ew(lon[0]), ew(lon[1]))
    }

    /// An empty 3-D box: no seabed, no obstacles, still water.
    pub fn open(bounds: Aabb) -> Self {
        Self {
            bounds,
            dims: Dims::Three,
            terrain: Terrain::None,
            obstacles: Vec::new(),
            current: Current::None,
            waves: Waves::None,
            frame: None,
        }
    }
}
