//! A mission's start and goal given as points or as cell numbers (`start_cell`, `goal_cell`):
//! acopf2016 numbers the cells of its grid map 1..M N row by row from the south-west corner
//! (eq. 3, [`CellNumbering`]), and its missions go from one cell's centre to another's. The
//! numbering runs over the terrain's `kind = "cells"` grid.

use super::spec::MissionSpec;
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::world::cell_numbering::CellNumbering;
use tidepath::world::{Dims, Terrain, World};

/// The start and goal of `[mission]` in metres. A cell's centre is on the plane of the world:
/// a 2-D world's plane is the other end's z when that end is a point, else the top of the
/// domain (`bounds.max` z, the sea surface of a surface craft). Cells are refused in 3-D,
/// where a cell does not say the depth.
pub(super) fn endpoints(m: &MissionSpec, world: &World) -> Result<(Vec3, Vec3)> {
    let start = pick("start", m.start, m.start_cell)?;
    let goal = pick("goal", m.goal, m.goal_cell)?;
    let plane = match (start, goal) {
        (End::Point(p), _) | (_, End::Point(p)) => p[2],
        _ => world.bounds.max.z,
    };
    let resolve = |name: &str, end: End| -> Result<Vec3> {
        match end {
            End::Point(p) => Ok(Vec3::from_array(p)),
            End::Cell(s) => {
                let field = format!("mission.{name}_cell");
                let (x, y) = numbering(&field, world)?.centre(s).ok_or_else(|| {
                    let n = numbering(&field, world).map(|g| g.len()).unwrap_or(0);
                    Error::input(&field, format!("is {s}; the terrain grid's cells are numbered 1 to {n}"))
                })?;
                Ok(Vec3::new(x, y, plane))
            }
        }
    };
    Ok((resolve("start", start)?, resolve("goal", goal)?))
}

#[derive(Clone, Copy)]
enum End {
    Point([f64; 3]),
    Cell(usize),
}

fn pick(name: &str, point: Option<[f64; 3]>, cell: Option<usize>) -> Result<End> {
    match (point, cell) {
        (Some(p), None) => Ok(End::Point(p)),
        (None, Some(s)) => Ok(End::Cell(s)),
        (Some(_), Some(s)) => {
            Err(Error::input(format!("mission.{name}_cell"), format!("= {s}: give {name} or {name}_cell, not both")))
        }
        (None, None) => {
            Err(Error::input(format!("mission.{name}"), format!("missing: give {name} = [x, y, z] or {name}_cell = N")))
        }
    }
}

/// The eq. 3 numbering of the world's cell terrain.
fn numbering(field: &str, world: &World) -> Result<CellNumbering> {
    if world.dims != Dims::Two {
        return Err(Error::input(field, "numbers cells of a 2-D grid map: needs world.dimensions = 2"));
    }
    let Terrain::Cells(g) = &world.terrain else {
        return Err(Error::input(
            field,
            "numbers the cells of [world.terrain] kind = \"cells\", which this world has not",
        ));
    };
    Ok(CellNumbering { origin: (g.x0, g.y0), cell: g.dx, columns: g.nx, rows: g.ny })
}
