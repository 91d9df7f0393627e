//! The free-waypoint encoding of amfa2015 (section 4): n route points anywhere in the domain,
//! visited in order between the fixed start and goal. Variables are normalised to [0, 1] per
//! axis (docs/papers/amfa2015.md: degrees and metres have very different scales), so one step size
//! suits every axis.

use crate::error::{Error, Result};
use crate::geom::{Aabb, Vec3};

use super::Encoding;

#[derive(Clone, Debug)]
pub struct FreeWaypoints {
    start: Vec3,
    goal: Vec3,
    min: Vec3,
    size: Vec3,
    three_d: bool,
    n: usize,
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl FreeWaypoints {
    /// `z_range` is the allowed height band (3-D) or `None` for a 2-D plane at the start's z.
    pub fn new(start: Vec3, goal: Vec3, waypoints: usize, domain: &Aabb, z_range: Option<(f64, f64)>) -> Result<Self> {
        if waypoints == 0 {
            return Err(Error::input("encoding.waypoints", "must be at least 1, got 0"));
        }
        let (zlo, zhi) = z_range.unwrap_or((start.z, start.z));
        if zlo > zhi {
            return Err(Error::input(
                "vehicle.depth_min",
                format!("the depth band and the domain leave no room: z range [{zlo}, {zhi}]"),
            ));
        }
        let min = Vec3::new(domain.min.x, domain.min.y, zlo);
        let size = Vec3::new(domain.size().x, domain.size().y, zhi - zlo);
        let per = if z_range.is_some() { 3 } else { 2 };
        Ok(Self {
            start,
            goal,
            min,
            size,
            three_d: z_range.is_some(),
            n: waypoints,
            lower: vec![0.0; per * waypoints],
            upper: vec![1.0; per * waypoints],
        })
    }
}

impl Encoding for FreeWaypoints {
    fn id(&self) -> &'static str {
        "free"
    }

    fn dim(&self) -> usize {
        self.lower.len()
    }

    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    fn decode_into(&self, x: &[f64], out: &mut Vec<Vec3>) {
        out.clear();
        out.push(self.start);
        let per = self.waypoint_dim();
        for k in 0..self.n {
            out.push(self.waypoint_at(k, &x[per * k..per * k + per]));
        }
        out.push(self.goal);
    }

    fn waypoint_dim(&self) -> usize {
        if self.three_d {
            3
        } else {
            2
        }
    }

    fn waypoint_at(&self, _k: usize, u: &[f64]) -> Vec3 {
        let z = if self.three_d { self.min.z + u[2] * self.size.z } else { self.start.z };
        Vec3::new(self.min.x + u[0] * self.size.x, self.min.y + u[1] * self.size.y, z)
    }

    fn set_waypoint(&self, x: &mut [f64], k: usize, p: Vec3) {
        let per = self.waypoint_dim();
        let u = (p - self.min) / self.size.max(Vec3::splat(f64::MIN_POSITIVE));
        x[per * k..per * k + 2].copy_from_slice(&[u.x, u.y]);
        if self.three_d {
            x[per * k + 2] = u.z;
        }
    }

    /// The interior points of `path` when it has exactly `n` of them, else interior
    /// waypoints equally spaced in arc length along it.
    fn encode(&self, path: &[Vec3]) -> Vec<f64> {
        let mut x = Vec::with_capacity(self.lower.len());
        for i in 1..=self.n {
            let p = if path.len() == self.n + 2 {
                path[i]
            } else {
                super::point_at_fraction(path, i as f64 / (self.n + 1) as f64)
            };
            let u = (p - self.min) / self.size.max(Vec3::splat(f64::MIN_POSITIVE));
            x.extend_from_slice(&[u.x, u.y]);
            if self.three_d {
                x.push(u.z);
            }
        }
        for v in &mut x {
            *v = if v.is_finite() { v.clamp(0.0, 1.0) } else { 0.5 };
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_cube_maps_onto_domain_and_depth_band() {
        let d = Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(200.0, 50.0, 0.0));
        let enc =
            FreeWaypoints::new(Vec3::new(1.0, 1.0, -5.0), Vec3::new(199.0, 49.0, -5.0), 2, &d, Some((-80.0, -10.0)))
                .unwrap();
        assert_eq!(enc.dim(), 6);
        let p = enc.decode(&[0.0, 0.0, 0.0, 0.5, 1.0, 1.0]);
        assert_eq!(p[1], Vec3::new(0.0, 0.0, -80.0));
        assert_eq!(p[2], Vec3::new(100.0, 50.0, -10.0));
        assert_eq!(p.len(), 4);
    }
}
