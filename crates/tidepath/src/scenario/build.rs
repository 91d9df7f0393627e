//! From a scenario spec to the runtime model, checking every value on the way.

use super::spec::*;
use crate::cost::{CostModel, GeneralCost, GeneralWeights};
use crate::encoding::{Encoding, FreeWaypoints, Sliced};
use crate::error::{Error, Result};
use crate::geom::{Aabb, Vec2, Vec3};
use crate::path::{ModelSettings, PathModel};
use crate::vehicle::Vehicle;
use crate::world::current::{CurrentGrid, LambOseen};
use crate::world::terrain::{ElevationGrid, GaussianPeaks, Peak};
use crate::world::{Current, Dims, Obstacle, RegularGrid2, Shape, Terrain, WaveField, World};

/// A checked scenario, ready to plan on.
#[derive(Clone, Debug)]
pub struct Scenario {
    pub name: String,
    pub description: String,
    /// Where it came from: `builtin:NAME` or a file path.
    pub source: String,
    pub world: World,
    pub vehicle: Vehicle,
    pub start: Vec3,
    pub goal: Vec3,
    pub departure_time: f64,
    pub settings: ModelSettings,
    pub cost: CostSpec,
    pub encoding: EncodingSpec,
    pub planner: PlannerSpec,
    /// The spec as loaded, for reports.
    pub spec: ScenarioSpec,
}

impl Scenario {
    pub fn from_toml(text: &str, source: &str) -> Result<Self> {
        let spec: ScenarioSpec = super::parse_toml(text, source)?;
        Self::from_spec(spec, source)
    }

    pub fn from_spec(spec: ScenarioSpec, source: &str) -> Result<Self> {
        let world = build_world(&spec.world)?;
        let vehicle = build_vehicle(&spec.vehicle)?;
        let start = Vec3::from_array(spec.mission.start);
        let goal = Vec3::from_array(spec.mission.goal);
        let settings = build_settings(&spec.model, &world)?;
        let departure_time = spec.mission.departure_time;
        check_endpoint("mission.start", start, &world, &vehicle, departure_time)?;
        check_endpoint("mission.goal", goal, &world, &vehicle, departure_time)?;
        let scenario = Self {
            name: spec.name.clone(),
            description: spec.description.clone(),
            source: source.to_string(),
            world,
            vehicle,
            start,
            goal,
            departure_time,
            settings,
            cost: spec.cost.clone(),
            encoding: spec.encoding.clone(),
            planner: spec.planner.clone(),
            spec,
        };
        // Build once so configuration errors surface at load time, not mid-run.
        scenario.cost_model()?;
        scenario.build_encoding()?;
        let planner = &scenario.planner;
        crate::planner::build_planner(&planner.id, planner.params.get(&planner.id), planner.population)?;
        for (id, table) in &planner.params {
            crate::planner::build_planner(id, Some(table), planner.population)?;
        }
        if let Some(id) = planner.smoother.as_deref().filter(|s| *s != "none") {
            crate::smoothing::build_smoother(id)?;
        }
        Ok(scenario)
    }

    pub fn path_model(&self) -> PathModel<'_> {
        PathModel::new(&self.world, &self.vehicle, self.departure_time, &self.settings)
    }

    pub fn cost_model(&self) -> Result<Box<dyn CostModel>> {
        match self.cost.model.as_str() {
            "general" => {
                let weights: GeneralWeights =
                    super::from_value(toml::Value::Table(self.cost.weights.clone()), "cost.weights")?;
                Ok(Box::new(GeneralCost::new(weights, self.start, self.goal, self.vehicle.speed)?))
            }
            other => Err(Error::input("cost.model", format!("unknown cost model '{other}' (known: general)"))),
        }
    }

    /// The height band a 3-D encoding may use, or `None` in a 2-D world.
    pub fn z_range(&self) -> Option<(f64, f64)> {
        (self.world.dims == Dims::Three).then(|| {
            (self.world.bounds.min.z.max(self.vehicle.z_min()), self.world.bounds.max.z.min(self.vehicle.z_max()))
        })
    }

    pub fn build_encoding(&self) -> Result<Box<dyn Encoding>> {
        let n = self.encoding.waypoints;
        let b = &self.world.bounds;
        match self.encoding.kind.as_str() {
            "sliced" => Ok(Box::new(Sliced::new(self.start, self.goal, n, b, self.z_range())?)),
            "free" => Ok(Box::new(FreeWaypoints::new(self.start, self.goal, n, b, self.z_range())?)),
            other => Err(Error::input("encoding.kind", format!("unknown encoding '{other}' (known: sliced, free)"))),
        }
    }
}

fn finite_positive(field: &str, v: f64) -> Result<f64> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(Error::input(field, format!("must be positive, got {v}")))
    }
}

fn build_world(spec: &WorldSpec) -> Result<World> {
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
    let bounds = Aabb::new(min, max);
    let terrain = build_terrain(&spec.terrain)?;
    let obstacles = spec.obstacles.iter().enumerate().map(|(i, o)| build_obstacle(i, o)).collect::<Result<Vec<_>>>()?;
    let current = build_current(&spec.current, &bounds)?;
    let waves = match &spec.waves {
        None => None,
        Some(w) => {
            let grid = grid2("world.waves", w.origin, w.spacing, w.shape)?;
            Some(WaveField::new(grid, w.heights.clone(), "world.waves")?)
        }
    };
    Ok(World { bounds, dims, terrain, obstacles, current, waves })
}

fn grid2(field: &str, origin: P2, spacing: P2, shape: [usize; 2]) -> Result<RegularGrid2> {
    RegularGrid2::new(origin[0], origin[1], spacing[0], spacing[1], shape[0], shape[1], field)
}

fn build_terrain(spec: &TerrainSpec) -> Result<Terrain> {
    Ok(match spec {
        TerrainSpec::None => Terrain::None,
        TerrainSpec::Peaks { base, peaks, ceiling } => {
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
    })
}

fn build_obstacle(i: usize, spec: &ObstacleSpec) -> Result<Obstacle> {
    let field = |name: &str| format!("world.obstacles[{i}].{name}");
    let (shape, velocity) = match spec {
        ObstacleSpec::Sphere { center, radius, velocity } => {
            finite_positive(&field("radius"), *radius)?;
            (Shape::Sphere { center: Vec3::from_array(*center), radius: *radius }, velocity)
        }
        ObstacleSpec::Cylinder { center, radius, z_min, z_max, velocity } => {
            finite_positive(&field("radius"), *radius)?;
            let (lo, hi) = (z_min.unwrap_or(f64::NEG_INFINITY), z_max.unwrap_or(f64::INFINITY));
            if lo >= hi {
                return Err(Error::input(field("z_min"), format!("must be below z_max, got {lo} >= {hi}")));
            }
            (Shape::Cylinder { center: Vec2::from_array(*center), radius: *radius, z_min: lo, z_max: hi }, velocity)
        }
        ObstacleSpec::Box { min, max, velocity } => {
            let (lo, hi) = (Vec3::from_array(*min), Vec3::from_array(*max));
            if !lo.cmplt(hi).all() {
                return Err(Error::input(
                    field("min"),
                    format!("must be below max on every axis, got {min:?} and {max:?}"),
                ));
            }
            (Shape::Box { min: lo, max: hi }, velocity)
        }
        ObstacleSpec::Circle { center, radius, velocity } => {
            finite_positive(&field("radius"), *radius)?;
            (Shape::Circle { center: Vec2::from_array(*center), radius: *radius }, velocity)
        }
    };
    Ok(Obstacle { shape, velocity: velocity.map(Vec3::from_array).unwrap_or(Vec3::ZERO) })
}

fn build_current(spec: &CurrentSpec, bounds: &Aabb) -> Result<Current> {
    Ok(match spec {
        CurrentSpec::None => Current::None,
        CurrentSpec::Uniform { velocity } => Current::Uniform(Vec3::from_array(*velocity)),
        CurrentSpec::Vortices { vortices } => {
            let mut out = Vec::with_capacity(vortices.len());
            for (i, v) in vortices.iter().enumerate() {
                finite_positive(&format!("world.current.vortices[{i}].core_radius"), v.core_radius)?;
                out.push(LambOseen { x: v.x, y: v.y, strength: v.strength, core_radius: v.core_radius });
            }
            Current::Vortices(out)
        }
        CurrentSpec::Jet(jet) => Current::Jet(super::jet::build_jet(jet, bounds)?),
        CurrentSpec::Grid { origin, spacing, shape, times, u, v } => {
            let grid = grid2("world.current", *origin, *spacing, *shape)?;
            Current::Grid(CurrentGrid::new(grid, times.clone(), u.clone(), v.clone(), "world.current")?)
        }
    })
}

fn build_vehicle(s: &VehicleSpec) -> Result<Vehicle> {
    finite_positive("vehicle.speed", s.speed)?;
    if !(s.speed_min >= 0.0 && s.speed_min <= s.speed && s.speed <= s.speed_max) {
        return Err(Error::input(
            "vehicle.speed",
            format!("must lie in [speed_min, speed_max], got {} not in [{}, {}]", s.speed, s.speed_min, s.speed_max),
        ));
    }
    if s.turn_radius < 0.0 {
        return Err(Error::input("vehicle.turn_radius", format!("must be >= 0, got {}", s.turn_radius)));
    }
    for (name, v) in [("max_turn_deg", s.max_turn_deg), ("max_pitch_deg", s.max_pitch_deg)] {
        if !(v > 0.0 && v <= 180.0) {
            return Err(Error::input(format!("vehicle.{name}"), format!("must be in (0, 180], got {v}")));
        }
    }
    if !(s.depth_min >= 0.0 && s.depth_min <= s.depth_max) {
        return Err(Error::input(
            "vehicle.depth_min",
            format!("must satisfy 0 <= depth_min <= depth_max, got {} and {}", s.depth_min, s.depth_max),
        ));
    }
    if s.safety_distance < 0.0 {
        return Err(Error::input("vehicle.safety_distance", format!("must be >= 0, got {}", s.safety_distance)));
    }
    Ok(Vehicle {
        speed: s.speed,
        speed_min: s.speed_min,
        speed_max: s.speed_max,
        turn_radius: s.turn_radius,
        max_turn: s.max_turn_deg.to_radians(),
        max_pitch: s.max_pitch_deg.to_radians(),
        depth_min: s.depth_min,
        depth_max: s.depth_max,
        safety_distance: s.safety_distance,
    })
}

fn build_settings(spec: &ModelSpec, world: &World) -> Result<ModelSettings> {
    let diag = world.bounds.size().truncate().length();
    let current_step = match spec.current_step {
        Some(s) => finite_positive("model.current_step", s)?,
        // 100 pieces across the domain: fine enough for vortices the size of a tenth of it.
        None => diag / 100.0,
    };
    Ok(ModelSettings { travel: spec.travel_time, current_step })
}

/// Start and goal must lie in the domain and depth band, clear of the seabed and obstacles.
fn check_endpoint(field: &str, p: Vec3, world: &World, veh: &Vehicle, t: f64) -> Result<()> {
    let shown = format!("[{}, {}, {}]", p.x, p.y, p.z);
    if !world.bounds.contains(p) {
        let (lo, hi) = (world.bounds.min, world.bounds.max);
        return Err(Error::input(
            field,
            format!("{shown} is outside the domain [{}, {}, {}] .. [{}, {}, {}]", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z),
        ));
    }
    if world.dims == Dims::Three && (p.z > veh.z_max() || p.z < veh.z_min()) {
        return Err(Error::input(
            field,
            format!("{shown} is outside the vehicle's depth band [{}, {}] m", veh.depth_min, veh.depth_max),
        ));
    }
    let seabed = world.terrain.elevation(p.x, p.y);
    if p.z < seabed + veh.safety_distance {
        let what = if p.z < seabed { "below the seabed" } else { "within the safety distance of the seabed" };
        return Err(Error::input(
            field,
            format!("{shown} is {what} (seabed at {seabed:.1} m, safety distance {} m)", veh.safety_distance),
        ));
    }
    for (k, o) in world.obstacles.iter().enumerate() {
        if o.contains(p, t, veh.safety_distance) {
            let what = if o.contains(p, t, 0.0) { "inside" } else { "within the safety distance of" };
            return Err(Error::input(field, format!("{shown} is {what} obstacle {k} (world.obstacles[{k}])")));
        }
    }
    Ok(())
}
