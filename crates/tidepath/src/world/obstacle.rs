//! Obstacles: spheres, vertical cylinders (finite or full depth), axis-aligned boxes and 2-D
//! circles (full-depth vertical cylinders), each optionally moving with a constant velocity.
//!
//! A segment traversed from time ta to tb at constant ground speed is a straight segment in the
//! obstacle's own frame too (subtract the obstacle's motion), so moving obstacles get the same
//! exact tests as fixed ones.

use crate::geom::{Vec2, Vec3};

/// A shape at time 0.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Sphere {
        center: Vec3,
        radius: f64,
    },
    /// Vertical cylinder between z_min and z_max (use +-inf for full depth).
    Cylinder {
        center: Vec2,
        radius: f64,
        z_min: f64,
        z_max: f64,
    },
    Box {
        min: Vec3,
        max: Vec3,
    },
    /// A 2-D circle, i.e. a vertical cylinder through the whole water column.
    Circle {
        center: Vec2,
        radius: f64,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Obstacle {
    pub shape: Shape,
    /// Constant velocity in m/s; the shape at time t is translated by velocity * t.
    pub velocity: Vec3,
}

impl Obstacle {
    pub fn fixed(shape: Shape) -> Self {
        Self { shape, velocity: Vec3::ZERO }
    }

    /// The shape translated to time `t`.
    pub fn shape_at(&self, t: f64) -> Shape {
        let _ = t;
        todo!("geometry helper")
    }

    /// Is point `p` at time `t` closer than `margin` to the obstacle (or inside it)?
    pub fn contains(&self, p: Vec3, t: f64, margin: f64) -> bool {
        let _ = (p, t, margin);
        todo!("geometry helper")
    }

    /// Does the segment a -> b, traversed from time `ta` to `tb`, come closer than `margin`
    /// to the obstacle? Exact (up to floating point).
    pub fn segment_hits(&self, a: Vec3, b: Vec3, ta: f64, tb: f64, margin: f64) -> bool {
        let _ = (a, b, ta, tb, margin);
        todo!("geometry helper")
    }

    /// Minimum Euclidean distance between the moving segment and the obstacle surface;
    /// 0 when they touch or intersect.
    pub fn segment_clearance(&self, a: Vec3, b: Vec3, ta: f64, tb: f64) -> f64 {
        let _ = (a, b, ta, tb);
        todo!("geometry helper")
    }
}
