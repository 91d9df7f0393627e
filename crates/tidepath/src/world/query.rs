//! Segment queries against the seabed.
//!
//! Terrain clearance is vertical: z - h(x, y). A segment is checked by interval subdivision with
//! the terrain's rectangle upper bound, so a stretch far above the seabed costs one bound query
//! and the test is conservative: "clear" is proven, never guessed.

use super::World;
use crate::geom::Vec3;

impl World {
    /// Does any point of segment a -> b come within `safety` (vertically) of the seabed?
    pub fn segment_hits_terrain(&self, a: Vec3, b: Vec3, safety: f64) -> bool {
        let _ = (a, b, safety);
        todo!("geometry helper")
    }

    /// Minimum vertical clearance z - h(x, y) along the segment (negative below the seabed,
    /// +inf without seabed).
    pub fn segment_terrain_clearance(&self, a: Vec3, b: Vec3) -> f64 {
        let _ = (a, b);
        todo!("geometry helper")
    }
}
