//! Small geometric vocabulary shared by every layer.
//!
//! Positions are metres in a local ENU frame: x east, y north, z up, sea surface at z = 0.

pub use glam::{DVec2 as Vec2, DVec3 as Vec3};

/// An axis-aligned box, used for the domain and for cheap rejection tests.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    pub fn new(min: Vec3, max: Vec3) -> Self {
        Self { min, max }
    }

    /// The smallest box holding both points.
    pub fn from_points(a: Vec3, b: Vec3) -> Self {
        Self { min: a.min(b), max: a.max(b) }
    }

    pub fn contains(&self, p: Vec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// Grows the box by `d` on every side.
    pub fn inflate(&self, d: f64) -> Self {
        Self { min: self.min - Vec3::splat(d), max: self.max + Vec3::splat(d) }
    }

    pub fn overlaps(&self, other: &Aabb) -> bool {
        self.min.cmple(other.max).all() && other.min.cmple(self.max).all()
    }

    pub fn size(&self) -> Vec3 {
        self.max - self.min
    }

    pub fn center(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }
}

/// Horizontal heading change from direction `a` to direction `b`, in radians in [0, pi].
/// Returns `None` when either direction has no horizontal extent (heading undefined).
pub fn heading_change(a: Vec3, b: Vec3) -> Option<f64> {
    let (ha, hb) = (a.truncate(), b.truncate());
    let (na, nb) = (ha.length(), hb.length());
    if na <= 1e-12 || nb <= 1e-12 {
        return None;
    }
    let c = (ha.dot(hb) / (na * nb)).clamp(-1.0, 1.0);
    Some(c.acos())
}

/// Climb (positive) or dive (negative) angle of a direction, in radians.
pub fn pitch(d: Vec3) -> f64 {
    d.z.atan2(d.truncate().length())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heading_change_of_right_angle_is_half_pi() {
        let h = heading_change(Vec3::new(1.0, 0.0, 5.0), Vec3::new(0.0, 2.0, -1.0)).unwrap();
        assert!((h - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }

    #[test]
    fn heading_of_vertical_segment_is_undefined() {
        assert!(heading_change(Vec3::new(0.0, 0.0, 1.0), Vec3::X).is_none());
    }

    #[test]
    fn pitch_of_45_degree_climb() {
        let p = pitch(Vec3::new(3.0, 4.0, 5.0));
        assert!((p - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
    }

    #[test]
    fn aabb_overlap_and_contains() {
        let a = Aabb::new(Vec3::ZERO, Vec3::ONE);
        let b = Aabb::new(Vec3::splat(0.5), Vec3::splat(2.0));
        let c = Aabb::new(Vec3::splat(1.5), Vec3::splat(2.0));
        assert!(a.overlaps(&b) && !a.overlaps(&c));
        assert!(a.contains(Vec3::splat(1.0)) && !a.contains(Vec3::splat(1.0001)));
    }
}
