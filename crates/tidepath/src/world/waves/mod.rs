//! Sea state behind one interface: the significant wave height (m) at a point and time.
//!
//! Only wave-propelled vehicles read it (acopf2016's wave glider, whose speed grows with the
//! wave height: [`crate::vehicle::GliderSpeed`]); for every other vehicle waves change nothing.
//! Wave forecasts come in the same gridded form as current forecasts (Copernicus Marine's
//! `VHM0`, WAVEWATCH III's `hs`), so the grid mirrors [`crate::world::current::CurrentGrid`]:
//! bilinear in space, linear in time, nodes without data (land, fill) kept apart.

mod grid;

pub use grid::WaveGrid;

use crate::geom::{Aabb, Vec3};

#[derive(Clone, Debug, Default, PartialEq)]
pub enum Waves {
    /// No wave information: a wave glider cannot be planned in such a world.
    #[default]
    None,
    /// The same significant wave height (m) everywhere and always.
    Uniform(f64),
    /// Heights on a regular grid at a list of times.
    Grid(WaveGrid),
}

impl Waves {
    /// Significant wave height (m) at `p` (its horizontal position) and time `t` (s); 0 where
    /// the world has no waves.
    #[inline]
    pub fn height(&self, p: Vec3, t: f64) -> f64 {
        match self {
            Waves::None => 0.0,
            Waves::Uniform(h) => *h,
            Waves::Grid(g) => g.height(p.x, p.y, t),
        }
    }

    pub fn is_none(&self) -> bool {
        matches!(self, Waves::None)
    }

    /// Whether the height changes along a segment or in time, so that a motion must be flown
    /// in pieces to follow it.
    pub fn varies(&self) -> bool {
        matches!(self, Waves::Grid(_))
    }

    /// Whether the height does not change in time.
    pub fn is_steady(&self) -> bool {
        match self {
            Waves::Grid(g) => g.is_steady(),
            _ => true,
        }
    }

    /// Whether the height at `p` comes from data: false only next to a node of a gridded
    /// forecast without data (land or fill in its file).
    #[inline]
    pub fn has_data(&self, p: Vec3) -> bool {
        match self {
            Waves::Grid(g) => g.gaps.has_data(&g.grid, p.x, p.y),
            _ => true,
        }
    }

    /// The first point of the horizontal projection of a -> b where the height has no data.
    pub fn first_gap_on(&self, a: Vec3, b: Vec3) -> Option<(f64, f64)> {
        match self {
            Waves::Grid(g) => g.gaps.first_gap_on(&g.grid, a.x, a.y, b.x, b.y),
            _ => None,
        }
    }

    /// The largest height anywhere and any time (exact: interpolation takes convex
    /// combinations of node values); admissible search heuristics use it.
    pub fn height_bound(&self) -> f64 {
        match self {
            Waves::None => 0.0,
            Waves::Uniform(h) => *h,
            Waves::Grid(g) => g.height_bound(),
        }
    }

    /// The smallest and largest height over the nodes of the cells touching `bounds` at any
    /// time, for colour scales.
    pub fn range_hint(&self, bounds: &Aabb) -> (f64, f64) {
        match self {
            Waves::None => (0.0, 0.0),
            Waves::Uniform(h) => (*h, *h),
            Waves::Grid(g) => g.range(bounds),
        }
    }
}

#[cfg(test)]
mod tests;
