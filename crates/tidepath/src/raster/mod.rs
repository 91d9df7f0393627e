//! Worlds rasterised into occupancy grids for graph search, at a chosen resolution, with the
//! vehicle's safety distance and depth band applied. Two rasterisations, named for what they
//! guarantee:
//!
//! * **conservative**: a free cell is free everywhere in it (every point of the closed cell
//!   keeps the safety distance from the seabed and every fixed obstacle), so a path through
//!   free cells is clear of them;
//! * **optimistic**: a blocked cell is blocked everywhere in it (no point of the closed cell
//!   keeps the safety distance), so if start and goal are not connected on it, no path exists
//!   at all.
//!
//! Both rest on sound bounds: the terrain's upper and lower elevation bounds over a rectangle
//! and, for obstacles, the distance from the cell centre (minus half the cell diagonal) for
//! conservative cells and all cell corners inside the inflated obstacle (obstacles are convex)
//! for optimistic ones. Closed-cell semantics make the grid rule without corner cutting sound
//! for the optimistic grid too: two diagonal cells whose shared corner lies in blocked cells
//! are not connected in the plane either.
//!
//! 2-D worlds rasterise the plane of the mission (z of the start); 3-D worlds rasterise the
//! vehicle's depth band into voxel layers. Moving obstacles are left out of both: planners
//! check them edge by edge with the motion validator, at the time the vehicle is there.

// `!(a >= b)` is deliberate: a NaN bound must block a conservative cell.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use tidepath_search::{Grid2, Grid3};

use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::vehicle::Vehicle;
use crate::world::{Dims, World};

/// Most cells a raster may have: 16 million (the search buffers then take about 400 MB).
pub const MAX_CELLS: usize = 1 << 24;

/// The shape of a raster, from its settings.
struct Geometry {
    nx: usize,
    ny: usize,
    nz: usize,
    z0: f64,
    dz: f64,
    three_d: bool,
    cells: usize,
}

impl Geometry {
    fn of(world: &World, vehicle: &Vehicle, cell: f64, cell_z: f64, plane_z: f64) -> Result<Self> {
        let b = &world.bounds;
        let (w, h) = (b.max.x - b.min.x, b.max.y - b.min.y);
        if !(cell > 0.0 && cell.is_finite() && cell_z > 0.0 && cell_z.is_finite()) {
            return Err(Error::input("raster", format!("cell size must be positive, got {cell} and {cell_z}")));
        }
        let nx = ((w / cell).ceil() as usize).max(1);
        let ny = ((h / cell).ceil() as usize).max(1);
        let three_d = world.dims == Dims::Three;
        let (z0, dz, nz) = if three_d {
            let lo = b.min.z.max(vehicle.z_min());
            let hi = b.max.z.min(vehicle.z_max());
            if hi < lo {
                return Err(Error::input("vehicle.depth_min", "the depth band and the domain do not overlap"));
            }
            let nz = (((hi - lo) / cell_z).ceil() as usize).max(1);
            (lo, ((hi - lo) / nz as f64).max(f64::MIN_POSITIVE), nz)
        } else {
            (plane_z, 0.0, 1)
        };
        let cells = nx.checked_mul(ny).and_then(|n| n.checked_mul(nz)).filter(|&n| n <= MAX_CELLS);
        let Some(cells) = cells else {
            return Err(Error::input(
                "raster",
                format!("{nx} x {ny} x {nz} cells exceed the limit of {MAX_CELLS}; use coarser cells"),
            ));
        };
        Ok(Self { nx, ny, nz, z0, dz, three_d, cells })
    }
}

/// A rasterised world.
#[derive(Clone, Debug)]
pub struct Raster {
    pub x0: f64,
    pub y0: f64,
    /// Cell sizes (cells tile the domain exactly, so they need not be square).
    pub dx: f64,
    pub dy: f64,
    pub nx: usize,
    pub ny: usize,
    /// Layer k spans [z0 + k dz, z0 + (k + 1) dz]; one layer at the mission plane in 2-D.
    pub z0: f64,
    pub dz: f64,
    pub nz: usize,
    pub three_d: bool,
    /// `true` where the cell may not be entered, for each rasterisation, flat index
    /// `i + nx (j + ny k)`.
    pub conservative: Vec<bool>,
    pub optimistic: Vec<bool>,
}

impl Raster {
    /// Rasterises `world` for `vehicle` with cells of about `cell` metres (horizontal), the
    /// 2-D plane at `plane_z`. In 3-D the layers are about `cell_z` metres thick.
    pub fn new(world: &World, vehicle: &Vehicle, cell: f64, cell_z: f64, plane_z: f64) -> Result<Self> {
        Ok(Self::new_within(world, vehicle, cell, cell_z, plane_z, &|| false)?.expect("never stopped"))
    }

    /// The raster's shape `(nx, ny, nz)` for these settings, checked against [`MAX_CELLS`]
    /// without building anything (a planner's settings check).
    pub fn shape(world: &World, vehicle: &Vehicle, cell: f64, cell_z: f64) -> Result<(usize, usize, usize)> {
        let g = Geometry::of(world, vehicle, cell, cell_z, 0.0)?;
        Ok((g.nx, g.ny, g.nz))
    }

    /// [`Raster::new`], polling `stop` once per row of cells and per obstacle row: `Ok(None)`
    /// when it asked to stop (a rasterisation of many thousand cells over a seabed of many
    /// peaks takes minutes; it must not outlive the run's budget).
    pub fn new_within(
        world: &World,
        vehicle: &Vehicle,
        cell: f64,
        cell_z: f64,
        plane_z: f64,
        stop: &dyn Fn() -> bool,
    ) -> Result<Option<Self>> {
        let Geometry { nx, ny, nz, z0, dz, three_d, cells } = Geometry::of(world, vehicle, cell, cell_z, plane_z)?;
        let b = &world.bounds;
        let (w, h) = (b.max.x - b.min.x, b.max.y - b.min.y);
        let (dx, dy) = (w / nx as f64, h / ny as f64);
        let safety = vehicle.safety_distance;
        let terrain = &world.terrain;
        let mut r = Raster {
            x0: b.min.x,
            y0: b.min.y,
            dx,
            dy,
            nx,
            ny,
            z0,
            dz,
            nz,
            three_d,
            conservative: vec![false; cells],
            optimistic: vec![false; cells],
        };
        for j in 0..ny {
            if stop() {
                return Ok(None);
            }
            for i in 0..nx {
                let (xa, ya) = (r.x0 + i as f64 * dx, r.y0 + j as f64 * dy);
                let (xb, yb) = (xa + dx, ya + dy);
                let h_max = terrain.max_elevation_in(xa, ya, xb, yb);
                let h_min = terrain.min_elevation_in(xa, ya, xb, yb);
                for k in 0..nz {
                    let (za, zb) = if three_d { (z0 + k as f64 * dz, z0 + (k + 1) as f64 * dz) } else { (z0, z0) };
                    let idx = i + nx * (j + ny * k);
                    // Conservative: the lowest point of the voxel against the highest seabed.
                    r.conservative[idx] = !(za - h_max >= safety);
                    // Optimistic: even the highest point against the lowest seabed fails.
                    r.optimistic[idx] = zb - h_min < safety;
                }
            }
        }
        // Fixed obstacles, each over the cells under its box grown by the safety distance.
        for o in world.obstacles.iter().filter(|o| o.is_fixed()) {
            let bb = o.shape.aabb();
            let span = |lo: f64, hi: f64, o: f64, d: f64, n: usize| {
                let a = ((lo - safety - o) / d).floor().max(0.0) as usize;
                let z = ((hi + safety - o) / d).floor().max(0.0) as usize;
                (a.min(n - 1), z.min(n - 1))
            };
            let (i0, i1) = span(bb.min.x, bb.max.x, r.x0, dx, nx);
            let (j0, j1) = span(bb.min.y, bb.max.y, r.y0, dy, ny);
            let (k0, k1) = if three_d { span(bb.min.z, bb.max.z, z0, dz, nz) } else { (0, 0) };
            for k in k0..=k1 {
                for j in j0..=j1 {
                    if stop() {
                        return Ok(None);
                    }
                    for i in i0..=i1 {
                        let (xa, ya) = (r.x0 + i as f64 * dx, r.y0 + j as f64 * dy);
                        let (xb, yb) = (xa + dx, ya + dy);
                        let (za, zb) = if three_d { (z0 + k as f64 * dz, z0 + (k + 1) as f64 * dz) } else { (z0, z0) };
                        let idx = i + nx * (j + ny * k);
                        let centre = Vec3::new(0.5 * (xa + xb), 0.5 * (ya + yb), 0.5 * (za + zb));
                        let half_diag = 0.5 * (dx * dx + dy * dy + (zb - za) * (zb - za)).sqrt();
                        if !(o.shape.distance_to_point(centre) - half_diag >= safety) {
                            r.conservative[idx] = true;
                        }
                        let corners = [
                            Vec3::new(xa, ya, za),
                            Vec3::new(xb, ya, za),
                            Vec3::new(xa, yb, za),
                            Vec3::new(xb, yb, za),
                            Vec3::new(xa, ya, zb),
                            Vec3::new(xb, ya, zb),
                            Vec3::new(xa, yb, zb),
                            Vec3::new(xb, yb, zb),
                        ];
                        if corners.iter().all(|&p| o.contains(p, 0.0, safety)) {
                            r.optimistic[idx] = true;
                        }
                    }
                }
            }
        }
        Ok(Some(r))
    }

    pub fn len(&self) -> usize {
        self.nx * self.ny * self.nz
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The centre of cell `c`.
    pub fn centre(&self, c: usize) -> Vec3 {
        let i = c % self.nx;
        let j = (c / self.nx) % self.ny;
        let k = c / (self.nx * self.ny);
        let z = if self.three_d { self.z0 + (k as f64 + 0.5) * self.dz } else { self.z0 };
        Vec3::new(self.x0 + (i as f64 + 0.5) * self.dx, self.y0 + (j as f64 + 0.5) * self.dy, z)
    }

    /// The cell holding `p` (clamped to the grid).
    pub fn cell_of(&self, p: Vec3) -> usize {
        let f = |v: f64, o: f64, d: f64, n: usize| (((v - o) / d).floor().max(0.0) as usize).min(n - 1);
        let i = f(p.x, self.x0, self.dx, self.nx);
        let j = f(p.y, self.y0, self.dy, self.ny);
        let k = if self.three_d { f(p.z, self.z0, self.dz, self.nz) } else { 0 };
        i + self.nx * (j + self.ny * k)
    }

    /// The conservative (`true`) or optimistic grid, for 2-D rasters.
    pub fn grid2(&self, conservative: bool) -> Grid2 {
        let blocked = if conservative { &self.conservative } else { &self.optimistic };
        Grid2::from_blocked(self.nx, self.ny, blocked.clone()).expect("raster sizes are checked")
    }

    /// The conservative or optimistic grid, for 3-D rasters.
    pub fn grid3(&self, conservative: bool) -> Grid3 {
        let blocked = if conservative { &self.conservative } else { &self.optimistic };
        Grid3::from_blocked(self.nx, self.ny, self.nz, blocked.clone()).expect("raster sizes are checked")
    }
}

#[cfg(test)]
mod tests;
