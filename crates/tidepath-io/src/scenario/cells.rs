//! Grids given cell by cell in scenario files (`kind = "cells"` for terrain, current and waves): a
//! map of `#` and `.` or per-cell values, rows from north to south as a map is read, turned
//! into the world's cell terrain ([`CellGrid`]) and a node current or wave height at the
//! cells' centres.

use super::spec::{CellsSpec, CurrentCellsSpec};
use tidepath::error::{Error, Result};
use tidepath::geom::Aabb;
use tidepath::world::current::CurrentGrid;
use tidepath::world::grid::MAX_NODES;
use tidepath::world::terrain::CellGrid;
use tidepath::world::waves::WaveGrid;
use tidepath::world::RegularGrid2;

/// Land height (m above the surface) of `#` cells when the scenario gives none.
const LAND_HEIGHT: f64 = 10.0;
/// Water depth (m) of `.` cells when neither the scenario nor the domain gives one.
const FLAT_DOMAIN_DEPTH: f64 = 10.0;

fn check_resolution(field: &str, r: f64) -> Result<()> {
    if !(r.is_finite() && r > 0.0) {
        return Err(Error::input(format!("{field}.resolution"), format!("must be positive and finite, got {r}")));
    }
    Ok(())
}

/// Rows (north first) of equal length into row-major values from the south-west corner.
fn south_first(field: &str, rows: &[Vec<f64>]) -> Result<([usize; 2], Vec<f64>)> {
    let ny = rows.len();
    let nx = rows.first().map_or(0, Vec::len);
    if nx == 0 {
        return Err(Error::input(field, "needs at least one row of at least one cell"));
    }
    if nx.checked_mul(ny).is_none_or(|n| n > MAX_NODES) {
        return Err(Error::input(field, format!("{nx} x {ny} cells are more than {MAX_NODES}")));
    }
    let mut out = Vec::with_capacity(nx * ny);
    for (r, row) in rows.iter().enumerate().rev() {
        if row.len() != nx {
            return Err(Error::input(
                format!("{field}[{r}]"),
                format!("has {} cells; the first row has {nx}", row.len()),
            ));
        }
        out.extend_from_slice(row);
    }
    Ok(([nx, ny], out))
}

pub(super) fn build_terrain(spec: &CellsSpec, bounds: &Aabb) -> Result<CellGrid> {
    const F: &str = "world.terrain";
    check_resolution(F, spec.resolution)?;
    let rows: Vec<Vec<f64>> = match (&spec.map, &spec.elevations) {
        (Some(map), None) => {
            let land = spec.land_height.unwrap_or(LAND_HEIGHT);
            let depth = spec.water_depth.unwrap_or(if bounds.min.z < 0.0 { -bounds.min.z } else { FLAT_DOMAIN_DEPTH });
            if !(land.is_finite() && land > 0.0) {
                return Err(Error::input(format!("{F}.land_height"), format!("must be positive, got {land}")));
            }
            if !(depth.is_finite() && depth > 0.0) {
                return Err(Error::input(format!("{F}.water_depth"), format!("must be positive, got {depth}")));
            }
            map.iter()
                .enumerate()
                .map(|(r, row)| {
                    row.chars()
                        .enumerate()
                        .map(|(c, ch)| match ch {
                            '#' => Ok(land),
                            '.' => Ok(-depth),
                            other => Err(Error::input(
                                format!("{F}.map[{r}]"),
                                format!("column {c} is {other:?}; use '#' for land and '.' for water"),
                            )),
                        })
                        .collect()
                })
                .collect::<Result<_>>()?
        }
        (None, Some(z)) => {
            if spec.land_height.is_some() || spec.water_depth.is_some() {
                return Err(Error::input(F, "land_height and water_depth go with map, not with elevations"));
            }
            z.clone()
        }
        _ => return Err(Error::input(F, "kind = \"cells\" needs either map or elevations (not both)")),
    };
    let field = if spec.map.is_some() { "world.terrain.map" } else { "world.terrain.elevations" };
    let (shape, z) = south_first(field, &rows)?;
    CellGrid::new(spec.origin, [spec.resolution; 2], shape, z, F)
}

pub(super) fn build_current(spec: &CurrentCellsSpec) -> Result<CurrentGrid> {
    const F: &str = "world.current";
    check_resolution(F, spec.resolution)?;
    let (shape, u) = south_first("world.current.u", &spec.u)?;
    let (shape_v, v) = south_first("world.current.v", &spec.v)?;
    if shape != shape_v {
        return Err(Error::input(
            "world.current.v",
            format!("has {} x {} cells; u has {} x {}", shape_v[0], shape_v[1], shape[0], shape[1]),
        ));
    }
    let (grid, mut layers) = centre_nodes(F, spec.origin, spec.resolution, shape, vec![u, v])?;
    let v = layers.pop().unwrap_or_default();
    let u = layers.pop().unwrap_or_default();
    CurrentGrid::new(grid, vec![0.0], vec![u], vec![v], F)
}

/// A wave height per cell (`[world.waves] kind = "cells"`), at the cells' centres like the
/// current's: rows from north to south.
pub(super) fn build_waves(origin: [f64; 2], resolution: f64, heights: &[Vec<f64>]) -> Result<WaveGrid> {
    const F: &str = "world.waves";
    check_resolution(F, resolution)?;
    let (shape, h) = south_first("world.waves.heights", heights)?;
    let (grid, layers) = centre_nodes(F, origin, resolution, shape, vec![h])?;
    WaveGrid::new(grid, vec![0.0], layers, F).map_err(|e| match e {
        // The grid names its layer `world.waves.height`; the cells are `heights`.
        Error::Input { field, message } if field == "world.waves.height" => {
            Error::input("world.waves.heights", message)
        }
        e => e,
    })
}

/// The node grid at the centres of `shape` cells of side `resolution` from `origin`, with
/// each row-major layer of cell values on it. A single row or column is doubled so the grid
/// has 2 x 2 nodes (the field is then constant across it).
fn centre_nodes(
    field: &str,
    origin: [f64; 2],
    resolution: f64,
    shape: [usize; 2],
    layers: Vec<Vec<f64>>,
) -> Result<(RegularGrid2, Vec<Vec<f64>>)> {
    let (nx, ny) = (shape[0], shape[1]);
    let (wx, wy) = (nx.max(2), ny.max(2));
    let widen = |vals: Vec<f64>| -> Vec<f64> {
        let mut out = Vec::with_capacity(wx * wy);
        for j in 0..wy {
            for i in 0..wx {
                out.push(vals[j.min(ny - 1) * nx + i.min(nx - 1)]);
            }
        }
        out
    };
    let layers = layers.into_iter().map(widen).collect();
    let (half, r) = (resolution / 2.0, resolution);
    let grid = RegularGrid2::new(origin[0] + half, origin[1] + half, r, r, wx, wy, field)?;
    Ok((grid, layers))
}
