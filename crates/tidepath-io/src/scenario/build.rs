//! From a scenario spec to the runtime model, checking every value on the way.

use super::spec::*;
use super::world_build::build_world;
pub(super) use super::world_build::{build_current, build_obstacle};
use tidepath::cost::{self, CostModel};
use tidepath::encoding::{self, Encoding, EncodingArgs};
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::mission::Mission;
use tidepath::path::{ModelSettings, PathModel};
use tidepath::planner::Problem;
use tidepath::vehicle::Vehicle;
use tidepath::world::{Dims, World};

/// Most missions a scenario may hold: a fleet, not a swarm; each is planned jointly.
pub const MAX_MISSIONS: usize = 64;
/// Most obstacles a scenario may hold; each segment test scales with them.
pub const MAX_OBSTACLES: usize = 4096;
/// Most Gaussian peaks, and most vortices: every elevation or current query sums over them
/// all (the papers use a handful).
pub const MAX_FEATURES: usize = 4096;

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
    /// The separation the missions' vehicles keep (`[fleet]`; none when absent).
    pub fleet: tidepath::fleet::FleetRules,
}

impl Scenario {
    pub fn from_toml(text: &str, source: &str) -> Result<Self> {
        let spec: ScenarioSpec = super::parse_toml(text, source)?;
        Self::from_spec(spec, source)
    }

    pub fn from_spec(spec: ScenarioSpec, source: &str) -> Result<Self> {
        let local = super::geographic::localise(&spec, source)?;
        let mut vehicle = build_vehicle(&spec.vehicle, "vehicle")?;
        let mut world = build_world(&local.spec.world, vehicle.speed)?;
        world.frame = local.frame.clone();
        super::waves_build::fit_to_world(&mut vehicle, "vehicle", &world)?;
        let mut warnings = local.warnings;
        let missions = build_missions(&local.spec, &vehicle, &world)?;
        let settings = build_settings(&spec.model, &world)?;
        // Every change is checked now, so a bad one costs no run.
        let cx = super::changes_build::ChangeContext {
            world: &world,
            metric: &local.spec.world,
            frame: local.frame.as_ref(),
            epoch: local.epoch,
            source,
            vehicle_speed: vehicle.speed,
        };
        let changes = super::changes_build::build_changes(&spec.changes, &cx, &mut warnings)?;
        let simulate = super::changes_build::build_simulate(spec.simulate.as_ref())?;
        let fleet = super::fleet_spec::build_fleet(spec.fleet.as_ref(), &missions, &mut warnings)?;
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
            fleet,
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
        // `[encoding] repair` and every `[encoding.repair_params.ID]`, whichever planner runs.
        scenario.encoding.build_repair(None)?;
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
        Problem { world: &self.world, settings: &self.settings, cost, missions: &self.missions, fleet: &self.fleet }
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
            axis: self.encoding.axis,
            posture: self.encoding.posture()?,
        })
    }
}

/// Largest coordinate (m) a domain may have.
pub const MAX_COORDINATE: f64 = 1e8;

#[allow(unused_imports)]
pub use tidepath::encoding::MAX_WAYPOINTS;

fn build_missions(spec: &ScenarioSpec, vehicle: &Vehicle, world: &World) -> Result<Vec<Mission>> {
    let mut out = Vec::new();
    match (&spec.mission, spec.missions.is_empty()) {
        (Some(_), false) => {
            return Err(Error::input("missions", "give either [mission] or [[missions]], not both"));
        }
        (None, true) => return Err(Error::input("mission", "missing: give [mission] or [[missions]]")),
        (Some(m), true) => {
            let (start, goal) = super::cell_endpoints::endpoints(m, world)?;
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
                        let mut v = build_vehicle(vs, &field("vehicle"))?;
                        super::waves_build::fit_to_world(&mut v, &field("vehicle"), world)?;
                        v
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

/// The vehicle's speed range from `speed_min` and `speed_max` (one given alone pairs with the
/// cruise speed), each a plausible speed and the cruise speed between them.
fn build_speed_range(s: &VehicleSpec, at: &str) -> Result<Option<(f64, f64)>> {
    if s.speed_min.is_none() && s.speed_max.is_none() {
        return Ok(None);
    }
    for (name, v) in [("speed_min", s.speed_min), ("speed_max", s.speed_max)] {
        if let Some(v) = v {
            if !(MIN_SPEED..=MAX_SPEED).contains(&v) {
                return Err(Error::input(
                    format!("{at}.{name}"),
                    format!("must be in [{MIN_SPEED}, {MAX_SPEED}] m/s, got {v:?}"),
                ));
            }
        }
    }
    let (lo, hi) = (s.speed_min.unwrap_or(s.speed), s.speed_max.unwrap_or(s.speed));
    if !(lo <= s.speed && s.speed <= hi) {
        return Err(Error::input(
            format!("{at}.speed"),
            format!("must lie in the speed range [speed_min, speed_max] = [{lo}, {hi}] m/s, got {}", s.speed),
        ));
    }
    Ok(Some((lo, hi)))
}

pub(super) fn finite_positive(field: &str, v: f64) -> Result<f64> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(Error::input(field, format!("must be positive, got {v}")))
    }
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
    let propulsion = super::waves_build::propulsion(s, at)?;
    let speed_range = build_speed_range(s, at)?;
    Ok(Vehicle {
        propulsion,
        speed_range,
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
        let (start, goal) = (self.start.to_array(), self.goal.to_array());
        for (flag, text, point, cell, was) in [
            ("--from", from, &mut m.start, &mut m.start_cell, start),
            ("--to", to, &mut m.goal, &mut m.goal_cell, goal),
        ] {
            let Some(text) = text else { continue };
            // A cell endpoint (`start_cell`) is replaced by a point: the cell's centre, which
            // the flag then moves (a geographic scenario has its metric frame; cells are
            // numbered in metres, so its points are turned back into degrees).
            if cell.take().is_some() {
                *point = Some(match &self.frame {
                    Some(f) => {
                        let (lon, lat) = f.inverse(was[0], was[1]);
                        [lon, lat, was[2]]
                    }
                    None => was,
                });
            }
            let Some(point) = point.as_mut() else { continue };
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
