//! Hand-computed rasterisations and the two guarantees.

use super::*;
use crate::geom::{Aabb, Vec2};
use crate::world::terrain::{GaussianPeaks, Peak};
use crate::world::{Obstacle, Shape, Terrain};

fn plane() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(100.0, 50.0, 0.0)));
    w.dims = Dims::Two;
    w
}

fn vehicle(safety: f64) -> Vehicle {
    Vehicle { safety_distance: safety, ..Vehicle::default() }
}

#[test]
fn a_disc_blocks_its_cells_conservatively_and_optimistically() {
    let mut w = plane();
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(50.0, 25.0), radius: 10.0 }));
    let r = Raster::new(&w, &vehicle(0.0), 10.0, 10.0, 0.0).unwrap();
    assert_eq!((r.nx, r.ny, r.nz), (10, 5, 1));
    // Cell (4, 2) spans [40, 50] x [20, 30]: its corners lie within 11.2 m of the centre, one
    // outside the disc, so it is not blocked everywhere; but its centre is 7.1 m away: blocked
    // conservatively.
    let c = r.cell_of(Vec3::new(45.0, 25.0, 0.0));
    assert!(r.conservative[c] && !r.optimistic[c]);
    // With a 5 m safety distance every corner of that cell is within 15 m: blocked everywhere.
    let r = Raster::new(&w, &vehicle(5.0), 10.0, 10.0, 0.0).unwrap();
    assert!(r.optimistic[c]);
    // Far cells are free in both.
    let far = r.cell_of(Vec3::new(5.0, 5.0, 0.0));
    assert!(!r.conservative[far] && !r.optimistic[far]);
}

#[test]
fn seabed_cells_follow_the_elevation_bounds() {
    let mut w = plane();
    // A hill rising to -2 m at (50, 25) from a -40 m floor; the plane is the surface.
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -40.0,
        peaks: vec![Peak { x: 50.0, y: 25.0, height: 38.0, sigma_x: 30.0, sigma_y: 30.0 }],
        ceiling: None,
    });
    let r = Raster::new(&w, &vehicle(10.0), 5.0, 5.0, 0.0).unwrap();
    let top = r.cell_of(Vec3::new(51.0, 26.0, 0.0));
    assert!(r.conservative[top] && r.optimistic[top], "2 m of water, 10 m needed");
    let open = r.cell_of(Vec3::new(2.0, 2.0, 0.0));
    assert!(!r.conservative[open] && !r.optimistic[open]);
    for k in 0..r.len() {
        assert!(!r.optimistic[k] || r.conservative[k], "cell {k}: blocked everywhere but free somewhere");
    }
}

#[test]
fn three_d_layers_cover_the_depth_band() {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks { base: -60.0, peaks: vec![], ceiling: None });
    let v = Vehicle { safety_distance: 10.0, depth_min: 5.0, depth_max: 95.0, ..Vehicle::default() };
    let r = Raster::new(&w, &v, 20.0, 10.0, 0.0).unwrap();
    assert_eq!((r.nz, r.z0), (9, -95.0));
    // Layers below -50 (seabed -60 plus 10 m) are blocked everywhere; those above are free.
    let deep = r.cell_of(Vec3::new(50.0, 50.0, -80.0));
    let shallow = r.cell_of(Vec3::new(50.0, 50.0, -20.0));
    assert!(r.optimistic[deep] && r.conservative[deep]);
    assert!(!r.optimistic[shallow] && !r.conservative[shallow]);
    assert!(Raster::new(&w, &v, 0.01, 0.01, 0.0).unwrap_err().to_string().contains("limit"));
}
