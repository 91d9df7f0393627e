//! From a scenario spec to the runtime model, checking every value on the way.

use super::spec::*;
use tidepath::cost::{self, CostModel};
use tidepath::encoding::{self, Encoding, EncodingArgs};
use tidepath::error::{Error, Result};
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::mission::Mission;
use tidepath::path::{ModelSettings, PathModel};
use tidepath::planner::Problem;
use tidepath::vehicle::Vehicle;
use tidepath::world::current::{CurrentGrid, LambOseen};
use tidepath::world::terrain::{ElevationGrid, GaussianPeaks, Peak};
use tidepath::world::{Current, Dims, Obstacle, RegularGrid2, Shape, Terrain, World};

/// Most missions a scenario may hold: a fleet, not a swarm; each is planned jointly.
pub const MAX_MISSIONS: usize = 64;
/// Most obstacles a scenario may hold; each segment test scales with them.
pub const MAX_OBSTACLES: usize = 4096;
/// Most Gaussian peaks, and most vortices: every elevation or current query sums over them
/// all (the papers use a handful).
pub const MAX_FEATURES: usize = 4096;

/// Refuses a list of more than [`MAX_FEATURES`] items, naming `field`.
fn check_features(field: &str, n: usize) -> Result<()> {
    if n > MAX_FEATURES {
        return Err(Error::input(field, format!("at most {MAX_FEATURES} entries, got {n}")));
    }
    Ok(())
}

/// A checked scenario, ready to plan on.
#[derive(Clone, Debug)]
pub struct Scenario {
    pub name: String,
    pub description: String,
    /// Where it came from: `builtin:NAME` or a file path.
    pub source: String,
    pub world: World,
    /// The scenario's `[vehicle]`, which every mission uses unless it gives its own.
    pub vehicle: Vehicle,
    /// One or more missions (a fleet).
    pub missions: Vec<Mission>,
    /// The first mission's start, goal and departure, for figures and single-mission callers.
    pub start: Vec3,
    pub goal: Vec3,
    pub departure_time: f64,
    pub settings: ModelSettings,
    pub cost: CostSpec,
    pub encoding: EncodingSpec,
    pub planner: PlannerSpec,
    /// The spec as loaded, for reports.
    pub spec: ScenarioSpec,
    /// Settings that were accepted but have no effect, to show the user.
    pub warnings: Vec<String>,
    /// The latitude/longitude frame of a geographic scenario (`None` in a local one).
    pub frame: Option<tidepath::geo::GeoFrame>,
    /// The UTC instant of the scenario clock's zero, when the scenario gives one.
    pub epoch: Option<chrono::DateTime<chrono::Utc>>,
    /// World changes (`[[changes]]`) in file order, in metres on the scenario clock; the
    /// mission loop reveals each when its trigger fires (`plan` ignores them).
    pub changes: Vec<tidepath::world::changes::Change>,
    /// The mission loop's settings (`[simulate]`; `SimParams::default()` when absent).
    pub simulate: tidepath::simulate::SimParams,
}

impl Scenario {
    pub fn from_toml(text: &str, source: &str) -> Result<Self> {
        let spec: ScenarioSpec = super::parse_toml(text, source)?;
        Self::from_spec(spec, source)
    }

    pub fn from_spec(spec: ScenarioSpec, source: &str) -> Result<Self> {
        let local = super::geographic::localise(&spec, source)?;
        let mut world = build_world(&local.spec.world)?;
        world.frame = local.frame.clone();
        let vehicle = build_vehicle(&spec.vehicle, "vehicle")?;
        let mut warnings = legacy_warnings(&spec.vehicle, "vehicle");
        warnings.extend(local.warnings);
        let missions = build_missions(&local.spec, &vehicle, &world, &mut warnings)?;
        let settings = build_settings(&spec.model, &world)?;
        // Every change is checked now, so a bad one costs no run.
        let cx = super::changes_build::ChangeContext {
            world: &world,
            metric: &local.spec.world,
            frame: local.frame.as_ref(),
            epoch: local.epoch,
            source,
        };
        let changes = super::changes_build::build_changes(&spec.changes, &cx, &mut warnings)?;
        let simulate = super::changes_build::build_simulate(spec.simulate.as_ref())?;
        let first = missions[0].clone();
        let scenario = Self {
            name: spec.name.clone(),
            description: spec.description.clone(),
            source: source.to_string(),
            world,
            vehicle,
            missions,
            start: first.start,
            goal: first.goal,
            departure_time: first.departure_time,
            settings,
            cost: spec.cost.clone(),
            encoding: spec.encoding.clone(),
            planner: spec.planner.clone(),
            frame: local.frame,
            epoch: local.epoch,
            changes,
            simulate,
            spec,
            warnings,
        };
        // Build once so configuration errors surface at load time, not mid-run.
        let p = &scenario.planner;
        for (name, v) in [
            ("planner.iterations", p.iterations),
            ("planner.evaluations", p.evaluations),
            ("planner.expansions", p.expansions),
            ("planner.samples", p.samples),
        ] {
            if let Some(v) = v {
                tidepath::termination::check_count(name, v)?;
            }
        }
        if let Some(t) = p.target_cost {
            if !t.is_finite() {
                return Err(Error::input("planner.target_cost", format!("must be finite, got {t}")));
            }
        }
        if let Some(t) = p.time_limit_s {
            tidepath::termination::check_wall_time("planner.time_limit_s", t)?;
        }
        scenario.cost_model()?;
        scenario.build_encoding()?;
        let planner = &scenario.planner;
        let registry = tidepath::planner::registry();
        // The scenario's population applies to planners that have one.
        let population =
            |id: &str| planner.population.filter(|_| registry.get(id).is_ok_and(|e| e.has_param("population")));
        registry.build(&planner.id, planner.params.get(&planner.id), population(&planner.id), &scenario.encoding)?;
        for (id, table) in &planner.params {
            registry.build(id, Some(table), population(id), &scenario.encoding)?;
        }
        if let Some(id) = planner.smoother.as_deref().filter(|s| *s != "none") {
            tidepath::smoothing::build_smoother(id, planner.smoother_params.get(id))?;
        }
        for (id, table) in &planner.smoother_params {
            tidepath::smoothing::build_smoother(id, Some(table))?;
        }
        Ok(scenario)
    }

    /// The path evaluation of the first mission.
    pub fn path_model(&self) -> PathModel<'_> {
        PathModel::new(&self.world, &self.missions[0], &self.settings)
    }

    /// The path evaluation of mission `i`.
    pub fn mission_model(&self, i: usize) -> PathModel<'_> {
        PathModel::new(&self.world, &self.missions[i], &self.settings)
    }

    /// The planning problem: this world, `cost`, and every mission.
    pub fn problem<'a>(&'a self, cost: &'a dyn CostModel) -> Problem<'a> {
        Problem { world: &self.world, settings: &self.settings, cost, missions: &self.missions }
    }

    pub fn cost_model(&self) -> Result<Box<dyn CostModel>> {
        (cost::registry().get(&self.cost.model)?.build)(&self.cost.weights)
    }

    /// The height band a 3-D encoding may use, or `None` in a 2-D world (first mission).
    pub fn z_range(&self) -> Option<(f64, f64)> {
        (self.world.dims == Dims::Three).then(|| {
            (self.world.bounds.min.z.max(self.vehicle.z_min()), self.world.bounds.max.z.min(self.vehicle.z_max()))
        })
    }

    /// The `[encoding]` of the first mission (every mission's is checked by the planners).
    pub fn build_encoding(&self) -> Result<Box<dyn Encoding>> {
        let build = encoding::registry().get(&self.encoding.kind)?.build;
        let n = self.encoding.checked()?.waypoints;
        build(&EncodingArgs {
            start: self.start,
            goal: self.goal,
            waypoints: n,
            bounds: &self.world.bounds,
            z_range: self.z_range(),
        })
    }
}

/// Largest coordinate (m) a domain may have.
pub const MAX_COORDINATE: f64 = 1e8;

#[allow(unused_imports)]
pub use tidepath::encoding::MAX_WAYPOINTS;

fn build_missions(
    spec: &ScenarioSpec,
    vehicle: &Vehicle,
    world: &World,
    warnings: &mut Vec<String>,
) -> Result<Vec<Mission>> {
    let mut out = Vec::new();
    match (&spec.mission, spec.missions.is_empty()) {
        (Some(_), false) => {
            return Err(Error::input("missions", "give either [mission] or [[missions]], not both"));
        }
        (None, true) => return Err(Error::input("mission", "missing: give [mission] or [[missions]]")),
        (Some(m), true) => {
            let start = Vec3::from_array(m.start);
            let goal = Vec3::from_array(m.goal);
            check_endpoint("mission.start", start, world)?;
            check_endpoint("mission.goal", goal, world)?;
            check_time("mission.departure_time", m.departure_time)?;
            let name = m.name.as_deref().unwrap_or("mission");
            out.push(Mission::new(name, vehicle.clone(), start, goal, m.departure_time));
        }
        (None, false) => {
            if spec.missions.len() > MAX_MISSIONS {
                return Err(Error::input(
                    "missions",
                    format!("at most {MAX_MISSIONS} missions, got {}", spec.missions.len()),
                ));
            }
            for (i, m) in spec.missions.iter().enumerate() {
                let field = |f: &str| format!("missions[{i}].{f}");
                if out.iter().any(|o: &Mission| o.name == m.name) {
                    return Err(Error::input(field("name"), format!("'{}' is used twice", m.name)));
                }
                let v = match &m.vehicle {
                    Some(vs) => {
                        warnings.extend(legacy_warnings(vs, &field("vehicle")));
                        build_vehicle(vs, &field("vehicle"))?
                    }
                    None => vehicle.clone(),
                };
                let (start, goal) = (Vec3::from_array(m.start), Vec3::from_array(m.goal));
                check_endpoint(&field("start"), start, world)?;
                check_endpoint(&field("goal"), goal, world)?;
                check_time(&field("departure_time"), m.departure_time)?;
                out.push(Mission::new(m.name.clone(), v, start, goal, m.departure_time));
            }
        }
    }
    Ok(out)
}

/// Departure times are seconds on the scenario clock; beyond a century they are a typo and the
/// clock loses sub-millisecond precision.
pub const MAX_TIME_S: f64 = 3.2e9;

fn check_time(field: &str, t: f64) -> Result<()> {
    if t.is_nan() || t.abs() > MAX_TIME_S {
        return Err(Error::input(field, format!("must be within +-{MAX_TIME_S} s (about a century), got {t:?}")));
    }
    Ok(())
}

fn legacy_warnings(v: &VehicleSpec, field: &str) -> Vec<String> {
    [("speed_min", v.speed_min), ("speed_max", v.speed_max)]
        .into_iter()
        .filter(|(_, x)| x.is_some())
        .map(|(name, _)| format!("{field}.{name} is accepted for older files but no planner uses it yet; ignored"))
        .collect()
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
    let current = build_current(&spec.current, &bounds, "world.current")?;
    Ok(World { bounds, dims, terrain, obstacles, current, frame: None })
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
    Ok(Obstacle { shape, velocity })
}

fn kind_id(k: ObstacleKind) -> &'static str {
    match k {
        ObstacleKind::Sphere => "sphere",
        ObstacleKind::Cylinder => "cylinder",
        ObstacleKind::Box => "box",
        ObstacleKind::Circle => "circle",
    }
}

/// A current, `at` naming it in errors (`world.current`, `changes[2].current`).
pub(super) fn build_current(spec: &CurrentSpec, bounds: &Aabb, at: &str) -> Result<Current> {
    build_world_current(spec, bounds, at).map_err(|e| match e {
        // The jet, cell and grid builders name `world.current`.
        Error::Input { field, message } if at != "world.current" && field.starts_with("world.current") => {
            Error::input(format!("{at}{}", &field["world.current".len()..]), message)
        }
        e => e,
    })
}

fn build_world_current(spec: &CurrentSpec, bounds: &Aabb, at: &str) -> Result<Current> {
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
        CurrentSpec::Jet(jet) => Current::Jet(super::jet::build_jet(jet, bounds)?),
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

fn build_vehicle(s: &VehicleSpec, at: &str) -> Result<Vehicle> {
    if !(MIN_SPEED..=MAX_SPEED).contains(&s.speed) {
        return Err(Error::input(
            format!("{at}.speed"),
            format!("must be in [{MIN_SPEED}, {MAX_SPEED}] m/s, got {:?}", s.speed),
        ));
    }
    for (name, v, max) in [("max_turn_deg", s.max_turn_deg, 180.0), ("max_pitch_deg", s.max_pitch_deg, 90.0)] {
        if !(v > 0.0 && v <= max) {
            return Err(Error::input(format!("{at}.{name}"), format!("must be in (0, {max}], got {v}")));
        }
    }
    if !(s.depth_min >= 0.0 && s.depth_min <= s.depth_max) {
        return Err(Error::input(
            format!("{at}.depth_min"),
            format!("must satisfy 0 <= depth_min <= depth_max, got {} and {}", s.depth_min, s.depth_max),
        ));
    }
    if s.safety_distance < 0.0 {
        return Err(Error::input(format!("{at}.safety_distance"), format!("must be >= 0, got {}", s.safety_distance)));
    }
    let turn_radius = match s.turn_radius {
        Some(r) if !(r > 0.0 && r <= MAX_TURN_RADIUS_M) => {
            return Err(Error::input(
                format!("{at}.turn_radius"),
                format!("must be in (0, {MAX_TURN_RADIUS_M}] m, got {r:?}"),
            ))
        }
        r => r,
    };
    Ok(Vehicle {
        turn_radius,
        speed: s.speed,
        max_turn: s.max_turn_deg.to_radians(),
        max_pitch: s.max_pitch_deg.to_radians(),
        depth_min: s.depth_min,
        depth_max: s.depth_max,
        safety_distance: s.safety_distance,
    })
}

/// The largest turning radius a vehicle may declare (m): beyond it no waypoint turn fits in a
/// domain the readers accept, and the value is a typo.
pub const MAX_TURN_RADIUS_M: f64 = 1e6;

/// The current step may be no finer than this fraction of the domain's horizontal diagonal:
/// 100,000 pieces across the domain, so one evaluation stays bounded.
pub const MIN_STEP_FRACTION: f64 = 1e-5;

fn build_settings(spec: &ModelSpec, world: &World) -> Result<ModelSettings> {
    let diag = world.bounds.size().truncate().length();
    let current_step = match spec.current_step {
        Some(s) => {
            finite_positive("model.current_step", s)?;
            let min = diag * MIN_STEP_FRACTION;
            if s < min {
                return Err(Error::input(
                    "model.current_step",
                    format!("must be at least {min:.3e} m (1e-5 of the domain diagonal), got {s:e}"),
                ));
            }
            s
        }
        // 100 pieces across the domain: fine enough for vortices the size of a tenth of it.
        None => diag / 100.0,
    };
    let arc_tolerance = match spec.arc_tolerance {
        Some(t) if !(MIN_ARC_TOLERANCE_M..=MAX_ARC_TOLERANCE_M).contains(&t) => {
            return Err(Error::input(
                "model.arc_tolerance",
                format!("must be in [{MIN_ARC_TOLERANCE_M}, {MAX_ARC_TOLERANCE_M}] m, got {t:?}"),
            ))
        }
        Some(t) => t,
        None => tidepath::validity::ARC_TOLERANCE,
    };
    Ok(ModelSettings { travel: spec.travel_time, current_step, arc_tolerance })
}

/// The arc tolerance's range (m): a millimetre keeps a turn's chords countable (at most 10^5
/// per turn), ten metres is already coarser than a safety distance should be.
pub const MIN_ARC_TOLERANCE_M: f64 = 1e-3;
pub const MAX_ARC_TOLERANCE_M: f64 = 10.0;

/// Slowest vehicle accepted (m/s): below any marine robot's cruise speed; slower speeds make
/// travel times overflow.
pub const MIN_SPEED: f64 = 0.01;
/// Fastest vehicle accepted (m/s): faster than any marine robot, slow enough that the clock
/// stays meaningful.
pub const MAX_SPEED: f64 = 100.0;

/// Start and goal must lie in the domain: a point outside it is a typo (exit 2). Whether it
/// lies in the seabed or an obstacle is the plan's status (`invalid-start`, `invalid-goal`).
fn check_endpoint(field: &str, p: Vec3, world: &World) -> Result<()> {
    if !world.bounds.contains(p) {
        return Err(Error::input(field, format!("{} is outside the domain {}", world.point(p), world.domain_text())));
    }
    Ok(())
}

impl Scenario {
    /// This scenario with its mission's start and/or goal replaced (the CLI's `--from` and
    /// `--to`): `LON,LAT[,DEPTH]` in a geographic scenario (depth in metres, positive down),
    /// `X,Y[,Z]` in metres in a local one; an omitted depth or z keeps the scenario's. The
    /// result is checked like a loaded scenario, errors naming `flag`.
    pub fn with_endpoints(&self, from: Option<&str>, to: Option<&str>) -> Result<Scenario> {
        let mut spec = self.spec.clone();
        let geographic = spec.world.frame == FrameKind::Geographic;
        let Some(m) = spec.mission.as_mut() else {
            return Err(Error::input(
                if from.is_some() { "--from" } else { "--to" },
                "a fleet scenario ([[missions]]) has several starts and goals: edit the file instead",
            ));
        };
        for (flag, text, point) in [("--from", from, &mut m.start), ("--to", to, &mut m.goal)] {
            let Some(text) = text else { continue };
            let what = if geographic { "LON,LAT[,DEPTH]" } else { "X,Y[,Z]" };
            let values: Vec<f64> = text
                .split(',')
                .map(|v| v.trim().parse::<f64>())
                .collect::<std::result::Result<_, _>>()
                .map_err(|_| Error::input(flag, format!("'{text}' is not {what} (numbers separated by commas)")))?;
            if !(2..=3).contains(&values.len()) || values.iter().any(|v| !v.is_finite()) {
                return Err(Error::input(flag, format!("'{text}' is not {what} (2 or 3 finite numbers)")));
            }
            point[0] = values[0];
            point[1] = values[1];
            if let Some(&third) = values.get(2) {
                point[2] = if geographic { -third } else { third };
            }
        }
        Scenario::from_spec(spec, &self.source).map_err(|e| {
            let flag = if to.is_some() && e.to_string().starts_with("mission.goal") { "--to" } else { "--from" };
            Error::input(flag, e.to_string())
        })
    }
}
