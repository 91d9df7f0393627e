//! Obstacles as triangle meshes (plotly's `mesh3d`: vertices and index triples).
//!
//! Spheres are latitude-longitude meshes, cylinders and 2-D circles are prisms with caps,
//! boxes are twelve triangles. Unbounded extents (a full-depth cylinder, a circle, which is a
//! wall through the whole water column) are cut to the scene's vertical range. Meshes are
//! built at the obstacle's time-0 place; the page moves a moving obstacle by velocity x time.

use tidepath::geom::{Vec2, Vec3};
use tidepath::world::Shape;

/// Segments around a sphere's or cylinder's axis, and a sphere's rings: smooth enough to read
/// as round. A world of many obstacles gets [`Detail::Coarse`] meshes (a quarter of the
/// vertices), so 4,096 spheres stay about 10 MB of page.
const AROUND: usize = 20;
const RINGS: usize = 10;

/// How finely round shapes are cut.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Detail {
    Fine,
    Coarse,
}

impl Detail {
    /// Fine up to 256 obstacles, coarse beyond.
    pub fn for_count(n: usize) -> Self {
        if n <= 256 {
            Detail::Fine
        } else {
            Detail::Coarse
        }
    }

    fn around(self) -> usize {
        match self {
            Detail::Fine => AROUND,
            Detail::Coarse => AROUND / 2,
        }
    }

    fn rings(self) -> usize {
        match self {
            Detail::Fine => RINGS,
            Detail::Coarse => RINGS / 2,
        }
    }
}

/// Vertices (x, y, z) and triangles (i, j, k index triples), rounded to a tenth of a metre.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub z: Vec<f64>,
    pub i: Vec<u32>,
    pub j: Vec<u32>,
    pub k: Vec<u32>,
}

impl Mesh {
    pub fn vertices(&self) -> usize {
        self.x.len()
    }

    pub fn triangles(&self) -> usize {
        self.i.len()
    }

    fn vertex(&mut self, p: Vec3) -> u32 {
        self.x.push(crate::lattice::m(p.x));
        self.y.push(crate::lattice::m(p.y));
        self.z.push(crate::lattice::m(p.z));
        (self.x.len() - 1) as u32
    }

    fn triangle(&mut self, a: u32, b: u32, c: u32) {
        self.i.push(a);
        self.j.push(b);
        self.k.push(c);
    }

    /// Appends `other`, its indices shifted past this mesh's vertices.
    pub fn append(&mut self, other: &Mesh) {
        let base = self.vertices() as u32;
        self.x.extend_from_slice(&other.x);
        self.y.extend_from_slice(&other.y);
        self.z.extend_from_slice(&other.z);
        self.i.extend(other.i.iter().map(|v| v + base));
        self.j.extend(other.j.iter().map(|v| v + base));
        self.k.extend(other.k.iter().map(|v| v + base));
    }

    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({ "x": self.x, "y": self.y, "z": self.z, "i": self.i, "j": self.j, "k": self.k })
    }
}

/// The mesh of `shape`, with unbounded vertical extents cut to [`z_lo`, `z_hi`].
pub fn shape_mesh(shape: &Shape, z_lo: f64, z_hi: f64, detail: Detail) -> Mesh {
    let clamp = |z: f64| z.clamp(z_lo, z_hi);
    match *shape {
        Shape::Sphere { center, radius } => sphere(center, radius, detail),
        Shape::Cylinder { center, radius, z_min, z_max } => prism(center, radius, clamp(z_min), clamp(z_max), detail),
        Shape::Circle { center, radius } => prism(center, radius, z_lo, z_hi, detail),
        Shape::Box { min, max } => cuboid(Vec3::new(min.x, min.y, clamp(min.z)), Vec3::new(max.x, max.y, clamp(max.z))),
    }
}

fn sphere(c: Vec3, r: f64, detail: Detail) -> Mesh {
    let (around, rings) = (detail.around(), detail.rings());
    let mut m = Mesh::default();
    let top = m.vertex(c + Vec3::Z * r);
    // Rings 1..rings-1 between the poles, around vertices each.
    for ring in 1..rings {
        let polar = std::f64::consts::PI * ring as f64 / rings as f64;
        for s in 0..around {
            let az = std::f64::consts::TAU * s as f64 / around as f64;
            let d = Vec3::new(polar.sin() * az.cos(), polar.sin() * az.sin(), polar.cos());
            m.vertex(c + d * r);
        }
    }
    let bottom = m.vertex(c - Vec3::Z * r);
    let at = |ring: usize, s: usize| (1 + (ring - 1) * around + s % around) as u32;
    for s in 0..around {
        m.triangle(top, at(1, s), at(1, s + 1));
        m.triangle(bottom, at(rings - 1, s + 1), at(rings - 1, s));
    }
    for ring in 1..rings - 1 {
        for s in 0..around {
            let (a, b, c2, d) = (at(ring, s), at(ring, s + 1), at(ring + 1, s), at(ring + 1, s + 1));
            m.triangle(a, c2, b);
            m.triangle(b, c2, d);
        }
    }
    m
}

/// A vertical cylinder with caps (a polygon of [`AROUND`] sides).
fn prism(c: Vec2, r: f64, z0: f64, z1: f64, detail: Detail) -> Mesh {
    let around = detail.around();
    let mut m = Mesh::default();
    let bottom_centre = m.vertex(Vec3::new(c.x, c.y, z0));
    let top_centre = m.vertex(Vec3::new(c.x, c.y, z1));
    for s in 0..around {
        let az = std::f64::consts::TAU * s as f64 / around as f64;
        let (x, y) = (c.x + r * az.cos(), c.y + r * az.sin());
        m.vertex(Vec3::new(x, y, z0));
        m.vertex(Vec3::new(x, y, z1));
    }
    let lo = |s: usize| (2 + 2 * (s % around)) as u32;
    let hi = |s: usize| (3 + 2 * (s % around)) as u32;
    for s in 0..around {
        m.triangle(lo(s), lo(s + 1), hi(s));
        m.triangle(hi(s), lo(s + 1), hi(s + 1));
        m.triangle(bottom_centre, lo(s + 1), lo(s));
        m.triangle(top_centre, hi(s), hi(s + 1));
    }
    m
}

fn cuboid(lo: Vec3, hi: Vec3) -> Mesh {
    let mut m = Mesh::default();
    for k in 0..8 {
        let pick = |bit: usize, a: f64, b: f64| if k & bit == 0 { a } else { b };
        m.vertex(Vec3::new(pick(1, lo.x, hi.x), pick(2, lo.y, hi.y), pick(4, lo.z, hi.z)));
    }
    // Two triangles per face; vertex k has bit 1 = x, 2 = y, 4 = z.
    for [a, b, c, d] in [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]] {
        m.triangle(a, b, c);
        m.triangle(a, c, d);
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(m: &Mesh) -> Vec<Vec3> {
        (0..m.vertices()).map(|v| Vec3::new(m.x[v], m.y[v], m.z[v])).collect()
    }

    fn indices_in_range(m: &Mesh) -> bool {
        let n = m.vertices() as u32;
        m.i.iter().chain(&m.j).chain(&m.k).all(|v| *v < n)
    }

    #[test]
    fn a_sphere_s_vertices_lie_on_it() {
        let c = Vec3::new(100.0, -50.0, -300.0);
        let m = shape_mesh(&Shape::Sphere { center: c, radius: 40.0 }, -1e4, 0.0, Detail::Fine);
        // Two poles and RINGS - 1 rings; a closed surface of 2 * AROUND * (RINGS - 1) triangles.
        assert_eq!(m.vertices(), 2 + AROUND * (RINGS - 1));
        assert_eq!(m.triangles(), 2 * AROUND * (RINGS - 1));
        assert!(indices_in_range(&m));
        for p in points(&m) {
            assert!((p.distance(c) - 40.0).abs() < 0.1, "{p}");
        }
    }

    #[test]
    fn a_full_depth_cylinder_is_cut_to_the_scene() {
        let shape = Shape::Cylinder {
            center: Vec2::new(0.0, 0.0),
            radius: 10.0,
            z_min: f64::NEG_INFINITY,
            z_max: f64::INFINITY,
        };
        let m = shape_mesh(&shape, -500.0, 0.0, Detail::Fine);
        assert_eq!(m.triangles(), 4 * AROUND);
        assert!(indices_in_range(&m));
        let zs = points(&m).iter().map(|p| p.z).collect::<Vec<_>>();
        assert_eq!(zs.iter().cloned().fold(f64::INFINITY, f64::min), -500.0);
        assert_eq!(zs.iter().cloned().fold(f64::NEG_INFINITY, f64::max), 0.0);
        for p in points(&m).iter().skip(2) {
            assert!((p.truncate().length() - 10.0).abs() < 0.1);
        }
    }

    #[test]
    fn a_box_has_its_eight_corners_and_twelve_triangles() {
        let m = shape_mesh(
            &Shape::Box { min: Vec3::new(0.0, 0.0, -10.0), max: Vec3::new(2.0, 3.0, -4.0) },
            -100.0,
            0.0,
            Detail::Fine,
        );
        assert_eq!((m.vertices(), m.triangles()), (8, 12));
        assert!(indices_in_range(&m));
        assert!(points(&m).contains(&Vec3::new(2.0, 3.0, -4.0)));
        assert!(points(&m).contains(&Vec3::new(0.0, 0.0, -10.0)));
        // Every triangle is a non-degenerate piece of a face.
        for t in 0..12 {
            let p = points(&m);
            let (a, b, c) = (p[m.i[t] as usize], p[m.j[t] as usize], p[m.k[t] as usize]);
            assert!((b - a).cross(c - a).length() > 0.0);
        }
    }

    #[test]
    fn coarse_spheres_have_a_quarter_of_the_vertices_and_stay_on_the_sphere() {
        let c = Vec3::new(0.0, 0.0, -50.0);
        let m = shape_mesh(&Shape::Sphere { center: c, radius: 10.0 }, -100.0, 0.0, Detail::Coarse);
        assert_eq!(m.vertices(), 2 + (AROUND / 2) * (RINGS / 2 - 1));
        assert!(indices_in_range(&m));
        assert!(points(&m).iter().all(|p| (p.distance(c) - 10.0).abs() < 0.1));
        assert_eq!(Detail::for_count(256), Detail::Fine);
        assert_eq!(Detail::for_count(257), Detail::Coarse);
    }

    #[test]
    fn appending_shifts_indices() {
        let a = shape_mesh(&Shape::Box { min: Vec3::ZERO, max: Vec3::ONE }, -1.0, 1.0, Detail::Fine);
        let mut all = a.clone();
        all.append(&a);
        assert_eq!(all.vertices(), 16);
        assert_eq!(all.i[12], a.i[0] + 8);
        assert!(indices_in_range(&all));
    }
}
