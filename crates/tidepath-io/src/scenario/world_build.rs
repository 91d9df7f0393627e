//! From a scenario's `[world]` spec to the runtime world: domain, seabed, obstacles and
//! current, every value checked with errors that name the field (split from `build.rs`; the
//! changes of `[[changes]]` build their obstacles and currents here too).

use super::build::{finite_positive, MAX_COORDINATE, MAX_FEATURES, MAX_OBSTACLES, MAX_SPEED};
use super::spec::*;
use tidepath::error::{Error, Result};
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::world::current::{CurrentGrid, LambOseen};
use tidepath::world::terrain::{ElevationGrid, GaussianPeaks, Peak};
use tidepath::world::{Current, Dims, Obstacle, RegularGrid2, Shape, Terrain, World};

/// Refuses a list of more than [`MAX_FEATURES`] items, naming `field`.
fn check_features(field: &str, n: usize) -> Result<()> {
    if n > MAX_FEATURES {
        return Err(Error::input(field, format!("at most {MAX_FEATURES} entries, got {n}")));
    }
    Ok(())
}

/// The world of `spec`; `vehicle_speed` (the scenario's `[vehicle] speed`, m/s) turns a jet's
/// `speed_ratio` into metres per second.
pub(super) fn build_world(spec: &WorldSpec, vehicle_speed: f64) -> Result<World> {
    let dims = match spec.dimensions {
        2 => Dims::Two,
        3 => Dims::Three,
        d => return Err(Error::input("world.dimensions", format!("must be 2 or 3, got {d}"))),
    };
    let (min, max) = (Vec3::from_array(spec.bounds.min), Vec3::from_array(spec.bounds.max));
    let ok = if dims == Dims::Two { min.x < max.x && min.y < max.y && min.z <= max.z } else { min.cmplt(max).all() };
    if !ok {
        return Err(Error::input(
            "world.bounds",
            format!("min must be below max on every axis, got min {:?} max {:?}", spec.bounds.min, spec.bounds.max),
        ));
    }
    if let Some(v) = spec.bounds.min.iter().chain(&spec.bounds.max).find(|v| v.abs() > MAX_COORDINATE) {
        return Err(Error::input(
            "world.bounds",
            format!("coordinates must be within +-{MAX_COORDINATE:e} m (the Earth is 4e7 m around), got {v:e}"),
        ));
    }
    let bounds = Aabb::new(min, max);
    let terrain = build_terrain(&spec.terrain, &bounds)?;
    if spec.obstacles.len() > MAX_OBSTACLES {
        return Err(Error::input(
            "world.obstacles",
            format!("at most {MAX_OBSTACLES} obstacles, got {}", spec.obstacles.len()),
        ));
    }
    let obstacles = spec
        .obstacles
        .iter()
        .enumerate()
        .map(|(i, o)| build_obstacle(&format!("world.obstacles[{i}]"), o))
        .collect::<Result<Vec<_>>>()?;
    let current = build_current(&spec.current, &bounds, "world.current", vehicle_speed)?;
    let waves = super::waves_build::build_waves(spec.waves.as_ref())?;
    Ok(World { waves, bounds, dims, terrain, obstacles, current, frame: None })
}

fn grid2(field: &str, origin: P2, spacing: P2, shape: [usize; 2]) -> Result<RegularGrid2> {
    RegularGrid2::new(origin[0], origin[1], spacing[0], spacing[1], shape[0], shape[1], field)
}

fn build_terrain(spec: &TerrainSpec, bounds: &Aabb) -> Result<Terrain> {
    Ok(match spec {
        TerrainSpec::None => Terrain::None,
        TerrainSpec::Peaks { base, peaks, ceiling } => {
            check_features("world.terrain.peaks", peaks.len())?;
            let mut out = Vec::with_capacity(peaks.len());
            for (i, p) in peaks.iter().enumerate() {
                finite_positive(&format!("world.terrain.peaks[{i}].sigma_x"), p.sigma_x)?;
                finite_positive(&format!("world.terrain.peaks[{i}].sigma_y"), p.sigma_y)?;
                out.push(Peak { x: p.x, y: p.y, height: p.height, sigma_x: p.sigma_x, sigma_y: p.sigma_y });
            }
            Terrain::Peaks(GaussianPeaks { base: *base, peaks: out, ceiling: *ceiling })
        }
        TerrainSpec::Grid { origin, spacing, shape, elevations } => {
            let grid = grid2("world.terrain", *origin, *spacing, *shape)?;
            Terrain::Grid(ElevationGrid::new(grid, elevations.clone(), "world.terrain")?)
        }
        TerrainSpec::Cells(cells) => Terrain::Cells(super::cells::build_terrain(cells, bounds)?),
        // Geographic scenarios turn files into grids before the world is built.
        TerrainSpec::File { .. } => {
            return Err(Error::input("world.terrain.kind", "\"file\" needs world.frame = \"geographic\""))
        }
    })
}

/// One obstacle, `at` naming it in errors (`world.obstacles[3]`, `changes[1].add`).
pub(super) fn build_obstacle(at: &str, spec: &ObstacleSpec) -> Result<Obstacle> {
    let field = |name: &str| format!("{at}.{name}");
    let kind = spec.kind;
    let needs = |name: &str, present: bool| -> Result<()> {
        if present {
            Ok(())
        } else {
            Err(Error::input(field(name), format!("missing: kind = \"{}\" needs it", kind_id(kind))))
        }
    };
    let unused = |name: &str, present: bool| -> Result<()> {
        if present {
            Err(Error::input(field(name), format!("is not a field of kind = \"{}\"", kind_id(kind))))
        } else {
            Ok(())
        }
    };
    let center = |n: usize| -> Result<Vec<f64>> {
        needs("center", spec.center.is_some())?;
        let c = spec.center.clone().unwrap_or_default();
        if c.len() != n {
            return Err(Error::input(field("center"), format!("needs {n} coordinates, got {}", c.len())));
        }
        Ok(c)
    };
    let radius = || -> Result<f64> {
        needs("radius", spec.radius.is_some())?;
        finite_positive(&field("radius"), spec.radius.unwrap_or_default())
    };
    let shape = match kind {
        ObstacleKind::Sphere | ObstacleKind::Circle => {
            for (name, present) in [
                ("z_min", spec.z_min.is_some()),
                ("z_max", spec.z_max.is_some()),
                ("min", spec.min.is_some()),
                ("max", spec.max.is_some()),
            ] {
                unused(name, present)?;
            }
            if kind == ObstacleKind::Sphere {
                let c = center(3)?;
                Shape::Sphere { center: Vec3::new(c[0], c[1], c[2]), radius: radius()? }
            } else {
                let c = center(2)?;
                Shape::Circle { center: Vec2::new(c[0], c[1]), radius: radius()? }
            }
        }
        ObstacleKind::Cylinder => {
            for (name, present) in [("min", spec.min.is_some()), ("max", spec.max.is_some())] {
                unused(name, present)?;
            }
            let c = center(2)?;
            let r = radius()?;
            let (lo, hi) = (spec.z_min.unwrap_or(f64::NEG_INFINITY), spec.z_max.unwrap_or(f64::INFINITY));
            if lo >= hi {
                return Err(Error::input(field("z_min"), format!("must be below z_max, got {lo} >= {hi}")));
            }
            Shape::Cylinder { center: Vec2::new(c[0], c[1]), radius: r, z_min: lo, z_max: hi }
        }
        ObstacleKind::Box => {
            for (name, present) in [
                ("center", spec.center.is_some()),
                ("radius", spec.radius.is_some()),
                ("z_min", spec.z_min.is_some()),
                ("z_max", spec.z_max.is_some()),
            ] {
                unused(name, present)?;
            }
            needs("min", spec.min.is_some())?;
            needs("max", spec.max.is_some())?;
            let (min, max) = (spec.min.unwrap_or_default(), spec.max.unwrap_or_default());
            let (lo, hi) = (Vec3::from_array(min), Vec3::from_array(max));
            if !lo.cmplt(hi).all() {
                return Err(Error::input(
                    field("min"),
                    format!("must be below max on every axis, got {min:?} and {max:?}"),
                ));
            }
            Shape::Box { min: lo, max: hi }
        }
    };
    let velocity = spec.velocity.map(Vec3::from_array).unwrap_or(Vec3::ZERO);
    if velocity.length() > MAX_SPEED {
        return Err(Error::input(
            field("velocity"),
            format!("must be at most {MAX_SPEED} m/s, got {:?}", spec.velocity),
        ));
    }
    Ok(Obstacle { shape, velocity, window: None })
}

fn kind_id(k: ObstacleKind) -> &'static str {
    match k {
        ObstacleKind::Sphere => "sphere",
        ObstacleKind::Cylinder => "cylinder",
        ObstacleKind::Box => "box",
        ObstacleKind::Circle => "circle",
    }
}

/// A current, `at` naming it in errors (`world.current`, `changes[2].current`);
/// `vehicle_speed` (m/s) is what a jet's `speed_ratio` multiplies.
pub(super) fn build_current(spec: &CurrentSpec, bounds: &Aabb, at: &str, vehicle_speed: f64) -> Result<Current> {
    build_world_current(spec, bounds, at, vehicle_speed).map_err(|e| match e {
        // The jet, cell and grid builders name `world.current`.
        Error::Input { field, message } if at != "world.current" && field.starts_with("world.current") => {
            Error::input(format!("{at}{}", &field["world.current".len()..]), message)
        }
        e => e,
    })
}

fn build_world_current(spec: &CurrentSpec, bounds: &Aabb, at: &str, vehicle_speed: f64) -> Result<Current> {
    Ok(match spec {
        CurrentSpec::None => Current::None,
        CurrentSpec::Uniform { velocity } => Current::Uniform(Vec3::from_array(*velocity)),
        CurrentSpec::Vortices { vortices } => {
            check_features(&format!("{at}.vortices"), vortices.len())?;
            let mut out = Vec::with_capacity(vortices.len());
            for (i, v) in vortices.iter().enumerate() {
                finite_positive(&format!("{at}.vortices[{i}].core_radius"), v.core_radius)?;
                out.push(LambOseen { x: v.x, y: v.y, strength: v.strength, core_radius: v.core_radius });
            }
            Current::Vortices(out)
        }
        CurrentSpec::Jet(jet) => Current::Jet(super::jet::build_jet(jet, bounds, vehicle_speed)?),
        // Geographic scenarios turn forecast files into grids before the world is built.
        CurrentSpec::File { .. } => {
            return Err(Error::input(format!("{at}.kind"), "\"file\" needs world.frame = \"geographic\""))
        }
        CurrentSpec::Cells(cells) => Current::Grid(super::cells::build_current(cells)?),
        CurrentSpec::Grid { origin, spacing, shape, times, u, v, no_data } => {
            let grid = grid2(at, *origin, *spacing, *shape)?;
            Current::Grid(
                CurrentGrid::new(grid, times.clone(), u.clone(), v.clone(), at)?.with_gaps(no_data.clone(), at)?,
            )
        }
    })
}
