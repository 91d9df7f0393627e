//! From `[[changes]]` and `[simulate]` to `tidepath::world::changes::Change` and
//! `tidepath::simulate::SimParams`, checking every value with one-line errors that name the
//! field and the value, so a bad change is refused when the scenario loads, not mid-run.
//!
//! Obstacle and vortex indices are checked against a static bound: the world's list plus
//! what the changes listed before add (the mission loop re-checks them when a change
//! applies, since triggers may fire in another order and removals shift indices).
//! In a geographic scenario positions are projected exactly as the world's are: a
//! move-obstacle centre like `world.obstacles`' centres, an added obstacle like a world
//! obstacle, a velocity from east/north into the frame's x/y, a forecast file through the
//! world's forecast reader on the scenario clock; an `at` instant becomes seconds after the
//! epoch.

use chrono::{DateTime, Utc};
use tidepath::error::{Error, Result};
use tidepath::geo::GeoFrame;
use tidepath::geom::{Vec2, Vec3};
use tidepath::simulate::{Acceptance, Growth, ReplanPolicy, SimParams};
use tidepath::world::changes::{center as shape_center, Change, ChangeKind, Law, RandomShift, Trigger};
use tidepath::world::{Current, Dims, World};

use super::build::{build_current, build_obstacle, MAX_COORDINATE, MAX_OBSTACLES, MAX_SPEED, MAX_TIME_S};
use super::geographic::{east_north_to_frame, forecast_grid, parse_instant, project_obstacle};
use super::spec::*;

/// Most changes a scenario may hold: each is checked, and applied once, in a mission.
pub const MAX_CHANGES: usize = 4096;
/// Most random draws a change may take before it is skipped (each one tries the change on a
/// copy of the world).
pub const MAX_RANDOM_DRAWS: u64 = 10_000;
/// Largest window and growth step (waypoints): the encodings' limit.
pub const MAX_WINDOW: usize = tidepath::encoding::MAX_WAYPOINTS;

/// What the changes are built against.
pub(super) struct ChangeContext<'a> {
    /// The world as built (metres): dimensions, obstacles, current, bounds.
    pub world: &'a World,
    /// The world spec in metres (a geographic one localised, its terrain resampled), for
    /// forecast files.
    pub metric: &'a WorldSpec,
    pub frame: Option<&'a GeoFrame>,
    /// The scenario clock's zero, when the scenario has one.
    pub epoch: Option<DateTime<Utc>>,
    /// The scenario's file path or `builtin:NAME`, for data file paths.
    pub source: &'a str,
    /// The scenario's `[vehicle] speed` (m/s), for a jet's `speed_ratio`.
    pub vehicle_speed: f64,
}

/// Every change of `specs`, checked; warnings (a data file found built in) go to `warnings`.
pub(super) fn build_changes(
    specs: &[ChangeSpec],
    cx: &ChangeContext<'_>,
    warnings: &mut Vec<String>,
) -> Result<Vec<Change>> {
    if specs.len() > MAX_CHANGES {
        return Err(Error::input("changes", format!("at most {MAX_CHANGES} changes, got {}", specs.len())));
    }
    let mut list = StaticLists::new(cx.world);
    specs.iter().enumerate().map(|(i, spec)| build_change(i, spec, cx, &mut list, warnings)).collect()
}

/// What the changes listed so far can have made of the world's lists: the obstacles' charted
/// centres (time 0, metres; world's first, then added ones) and the most vortices a current
/// has had.
struct StaticLists {
    world_obstacles: usize,
    centres: Vec<Vec3>,
    world_vortices: Option<usize>,
    vortices: usize,
}

impl StaticLists {
    fn new(world: &World) -> Self {
        let vortices = vortex_count(&world.current);
        Self {
            world_obstacles: world.obstacles.len(),
            centres: world.obstacles.iter().map(|o| shape_center(&o.shape)).collect(),
            world_vortices: vortices,
            vortices: vortices.unwrap_or(0),
        }
    }

    fn obstacle(&self, field: &str, index: usize) -> Result<usize> {
        let (n, added) = (self.world_obstacles, self.centres.len() - self.world_obstacles);
        if index < self.centres.len() {
            return Ok(index);
        }
        let has = if n == 1 { "1 obstacle".to_string() } else { format!("{n} obstacles") };
        let add = if added == 0 { "none".to_string() } else { added.to_string() };
        Err(Error::input(
            field,
            format!("{index} does not exist (the world has {has} and the changes before this one add {add})"),
        ))
    }

    fn vortex(&self, field: &str, index: usize) -> Result<usize> {
        if self.vortices == 0 {
            return Err(Error::input(
                field,
                "needs a current made of vortices: world.current has none, nor does a current change before this one",
            ));
        }
        if index < self.vortices {
            return Ok(index);
        }
        let world = match self.world_vortices {
            Some(n) => format!("world.current has {n}"),
            None => "world.current has none".to_string(),
        };
        Err(Error::input(
            field,
            format!("{index} does not exist ({world}, and no current before this one has more than {})", self.vortices),
        ))
    }
}

fn vortex_count(c: &Current) -> Option<usize> {
    match c {
        Current::Vortices(v) => Some(v.len()),
        _ => None,
    }
}

fn build_change(
    i: usize,
    spec: &ChangeSpec,
    cx: &ChangeContext<'_>,
    list: &mut StaticLists,
    warnings: &mut Vec<String>,
) -> Result<Change> {
    let at = format!("changes[{i}]");
    let field = |name: &str| format!("{at}.{name}");
    let trigger = build_trigger(&at, spec, cx.epoch)?;
    check_fields(&at, spec)?;
    // `check_fields` made sure every field a kind needs is there.
    let kind = match spec.kind {
        ChangeKindId::MoveObstacle => {
            let index = list.obstacle(&field("obstacle"), spec.obstacle.unwrap_or_default())?;
            // Without a centre (only with `random`, see `check_fields`) the draw displaces the
            // obstacle's centre at the change's time, and the written one is never read.
            let center = match spec.center.as_deref() {
                Some(c) => obstacle_center(&field("center"), c, cx)?,
                None => list.centres[index],
            };
            ChangeKind::MoveObstacle { index, center }
        }
        ChangeKindId::ObstacleVelocity => {
            let index = list.obstacle(&field("obstacle"), spec.obstacle.unwrap_or_default())?;
            let v = spec.velocity.as_deref().unwrap_or_default();
            if !(2..=3).contains(&v.len()) {
                return Err(Error::input(
                    field("velocity"),
                    format!("needs 2 or 3 components [vx, vy(, vz)], got {}", v.len()),
                ));
            }
            let mut velocity = Vec3::new(v[0], v[1], v.get(2).copied().unwrap_or(0.0));
            if velocity.length() > MAX_SPEED {
                return Err(Error::input(field("velocity"), format!("must be at most {MAX_SPEED} m/s, got {v:?}")));
            }
            if let Some(frame) = cx.frame {
                // East and north at the obstacle's charted centre, as a world obstacle's.
                let c = list.centres[index];
                let (vx, vy) = east_north_to_frame(frame, c.x, c.y, velocity.x, velocity.y);
                velocity = Vec3::new(vx, vy, velocity.z);
            }
            ChangeKind::ObstacleVelocity { index, velocity }
        }
        ChangeKindId::AddObstacle => {
            if list.centres.len() >= MAX_OBSTACLES {
                return Err(Error::input(
                    field("add"),
                    format!("the world and the changes before this one already hold {MAX_OBSTACLES} obstacles, the most a world may hold"),
                ));
            }
            let mut o = spec.add.clone().unwrap_or_else(|| unreachable!("checked"));
            if let Some(frame) = cx.frame {
                project_obstacle(frame, &mut o, &field("add"), warnings)?;
            }
            let obstacle = build_obstacle(&field("add"), &o)?;
            list.centres.push(shape_center(&obstacle.shape));
            ChangeKind::AddObstacle(obstacle)
        }
        ChangeKindId::RemoveObstacle => {
            ChangeKind::RemoveObstacle { index: list.obstacle(&field("obstacle"), spec.obstacle.unwrap_or_default())? }
        }
        ChangeKindId::MoveVortex => {
            let index = list.vortex(&field("vortex"), spec.vortex.unwrap_or_default())?;
            // Without a centre (only with `random`) the draw displaces the vortex's centre at
            // the change's time; [0, 0] is never read.
            let c = spec.center.as_deref().unwrap_or(&[0.0, 0.0]);
            if c.len() != 2 {
                return Err(Error::input(
                    field("center"),
                    format!("a vortex centre needs 2 coordinates [x, y] (metres), got {}", c.len()),
                ));
            }
            check_coordinates(&field("center"), c)?;
            ChangeKind::MoveVortex { index, center: Vec2::new(c[0], c[1]) }
        }
        ChangeKindId::VortexStrength => {
            let index = list.vortex(&field("vortex"), spec.vortex.unwrap_or_default())?;
            ChangeKind::VortexStrength { index, strength: spec.strength.unwrap_or_default() }
        }
        ChangeKindId::Current => {
            let mut c = spec.current.clone().unwrap_or_else(|| unreachable!("checked"));
            if let CurrentSpec::File { .. } = c {
                let Some(frame) = cx.frame else {
                    return Err(Error::input(
                        field("current.kind"),
                        "\"file\" reads longitude/latitude data: set world.frame = \"geographic\"",
                    ));
                };
                let Some(epoch) = cx.epoch else {
                    return Err(Error::input(
                        field("current"),
                        "a forecast file's times are read on the scenario clock, which has no zero here: give world.epoch",
                    ));
                };
                c = forecast_grid(&c, &field("current"), frame, cx.metric, cx.source, Some(epoch), warnings)?.0;
            }
            let current = build_current(&c, &cx.world.bounds, &field("current"), cx.vehicle_speed)?;
            if let Some(n) = vortex_count(&current) {
                list.vortices = list.vortices.max(n);
            }
            ChangeKind::ReplaceCurrent(current)
        }
    };
    let stepping = matches!(spec.kind, ChangeKindId::MoveObstacle | ChangeKindId::MoveVortex) && spec.center.is_none();
    let random = spec.random.as_ref().map(|r| build_random(&field("random"), r, stepping)).transpose()?;
    Ok(Change { trigger, kind, random })
}

/// The one trigger a change gives.
fn build_trigger(at: &str, spec: &ChangeSpec, epoch: Option<DateTime<Utc>>) -> Result<Trigger> {
    let given: Vec<&str> = [
        ("at_time", spec.at_time.is_some()),
        ("at", spec.at.is_some()),
        ("after_distance", spec.after_distance.is_some()),
    ]
    .into_iter()
    .filter_map(|(name, present)| present.then_some(name))
    .collect();
    if given.len() != 1 {
        let got = match given.as_slice() {
            [] => "none".to_string(),
            [a, b] => format!("{a} and {b}"),
            _ => given.join(", "),
        };
        return Err(Error::input(at, format!("give exactly one trigger (at_time, at or after_distance), got {got}")));
    }
    let clock = |field: String, t: f64| -> Result<Trigger> {
        if !(t >= 0.0 && t.is_finite()) {
            return Err(Error::input(field, format!("must be finite and >= 0, got {t}")));
        }
        if t > MAX_TIME_S {
            return Err(Error::input(field, format!("must be at most {MAX_TIME_S} s (about a century), got {t}")));
        }
        Ok(Trigger::AtTime(t))
    };
    if let Some(t) = spec.at_time {
        return clock(format!("{at}.at_time"), t);
    }
    if let Some(text) = &spec.at {
        let field = format!("{at}.at");
        let instant = parse_instant(&field, text)?;
        let Some(epoch) = epoch else {
            return Err(Error::input(
                field,
                format!("`{text}` needs the scenario clock's zero: give world.epoch or an ISO mission departure"),
            ));
        };
        let t = (instant - epoch).num_milliseconds() as f64 / 1e3;
        if t < 0.0 {
            return Err(Error::input(
                field,
                format!(
                    "`{text}` is before the scenario clock's zero {} (world.epoch, else the earliest ISO departure)",
                    epoch.to_rfc3339_opts(chrono::SecondsFormat::Secs, true)
                ),
            ));
        }
        return clock(field, t);
    }
    let d = spec.after_distance.unwrap_or_default();
    if !(d >= 0.0 && d.is_finite()) {
        return Err(Error::input(format!("{at}.after_distance"), format!("must be finite and >= 0, got {d}")));
    }
    Ok(Trigger::AfterDistance(d))
}

/// Refuses a field `kind` does not use, then a field it needs that is missing.
fn check_fields(at: &str, spec: &ChangeSpec) -> Result<()> {
    use ChangeKindId::*;
    let kind = spec.kind;
    let (needs, may): (&[&str], &[&str]) = match kind {
        MoveObstacle => (&["obstacle", "center"], &["random"]),
        ObstacleVelocity => (&["obstacle", "velocity"], &[]),
        AddObstacle => (&["add"], &["random"]),
        RemoveObstacle => (&["obstacle"], &[]),
        MoveVortex => (&["vortex", "center"], &["random"]),
        VortexStrength => (&["vortex", "strength"], &[]),
        Current => (&["current"], &[]),
    };
    // A random move may leave out its centre: it then steps from where the obstacle or vortex
    // is when the change applies.
    let stepping: [&str; 2] = [needs[0], "random"];
    let (needs, may) = match kind {
        MoveObstacle | MoveVortex if spec.random.is_some() && spec.center.is_none() => (&stepping[..1], &stepping[1..]),
        _ => (needs, may),
    };
    let present = [
        ("obstacle", spec.obstacle.is_some()),
        ("vortex", spec.vortex.is_some()),
        ("center", spec.center.is_some()),
        ("velocity", spec.velocity.is_some()),
        ("strength", spec.strength.is_some()),
        ("add", spec.add.is_some()),
        ("current", spec.current.is_some()),
        ("random", spec.random.is_some()),
    ];
    for (name, given) in present {
        if given && !needs.contains(&name) && !may.contains(&name) {
            let why =
                if name == "random" { " (only move-obstacle, add-obstacle and move-vortex set a centre)" } else { "" };
            return Err(Error::input(
                format!("{at}.{name}"),
                format!("is not a field of kind = \"{}\"{why}", kind.id()),
            ));
        }
    }
    for (name, given) in present {
        if !given && needs.contains(&name) {
            return Err(Error::input(format!("{at}.{name}"), format!("missing: kind = \"{}\" needs it", kind.id())));
        }
    }
    Ok(())
}

/// A move-obstacle centre: [x, y] (or [x, y, z]) in a 2-D world, [x, y, z] in a 3-D one; in a
/// geographic scenario x, y are longitude and latitude, projected.
fn obstacle_center(field: &str, c: &[f64], cx: &ChangeContext<'_>) -> Result<Vec3> {
    let three = cx.world.dims == Dims::Three;
    let names = match (cx.frame.is_some(), three) {
        (true, true) => "[longitude, latitude, z]",
        (true, false) => "[longitude, latitude]",
        (false, true) => "[x, y, z]",
        (false, false) => "[x, y]",
    };
    let ok = if three { c.len() == 3 } else { (2..=3).contains(&c.len()) };
    if !ok {
        let dims = if three { "3-D" } else { "2-D" };
        return Err(Error::input(field, format!("needs {names} in a {dims} world, got {} coordinates", c.len())));
    }
    let z = c.get(2).copied().unwrap_or(0.0);
    match cx.frame {
        Some(frame) => {
            let (x, y) = frame.forward(c[0], c[1], field)?;
            check_coordinates(field, &[z])?;
            Ok(Vec3::new(x, y, z))
        }
        None => {
            check_coordinates(field, c)?;
            Ok(Vec3::new(c[0], c[1], z))
        }
    }
}

fn check_coordinates(field: &str, c: &[f64]) -> Result<()> {
    match c.iter().find(|v| v.abs() > MAX_COORDINATE) {
        Some(v) => Err(Error::input(field, format!("coordinates must be within +-{MAX_COORDINATE:e} m, got {v:e}"))),
        None => Ok(()),
    }
}

/// `from_current`: the change gives no centre, so the draw displaces the current one.
fn build_random(field: &str, r: &RandomSpec, from_current: bool) -> Result<RandomShift> {
    if !(r.scale >= 0.0 && r.scale.is_finite()) {
        return Err(Error::input(format!("{field}.scale"), format!("must be finite and >= 0 (m), got {}", r.scale)));
    }
    let draws = r.max_draws.unwrap_or(RandomShift::LFHH2019_MAX_DRAWS as u64);
    if !(1..=MAX_RANDOM_DRAWS).contains(&draws) {
        return Err(Error::input(
            format!("{field}.max_draws"),
            format!("must be from 1 to {MAX_RANDOM_DRAWS}, got {draws}"),
        ));
    }
    let law = match r.law {
        LawId::Gaussian => Law::Gaussian,
        LawId::Uniform => Law::Uniform,
    };
    Ok(RandomShift { law, scale: r.scale, max_draws: draws as u32, from_current })
}

/// The mission loop's settings: `SimParams::default()` without a `[simulate]` section, else
/// the preset (or the defaults) with the fields given on top.
pub(super) fn build_simulate(spec: Option<&SimulateSpec>) -> Result<SimParams> {
    let Some(s) = spec else { return Ok(SimParams::default()) };
    let mut p = match s.preset {
        Some(PresetId::Lfhh2019) => SimParams::LFHH2019,
        None => SimParams::default(),
    };
    let waypoints = |field: &str, n: usize| -> Result<usize> {
        if (1..=MAX_WINDOW).contains(&n) {
            Ok(n)
        } else {
            Err(Error::input(field, format!("must be from 1 to {MAX_WINDOW} waypoints, got {n}")))
        }
    };
    if let Some(w) = s.window {
        p.window = waypoints("simulate.window", w)?;
    }
    match (s.growth, s.growth_step) {
        (Some(GrowthId::Double), Some(_)) => {
            return Err(Error::input("simulate.growth_step", "only with growth = \"add\" (growth is \"double\")"));
        }
        (Some(GrowthId::Double), None) => p.growth = Growth::Double,
        (Some(GrowthId::Add), step) => p.growth = Growth::Add(waypoints("simulate.growth_step", step.unwrap_or(1))?),
        (None, Some(step)) => match p.growth {
            Growth::Add(_) => p.growth = Growth::Add(waypoints("simulate.growth_step", step)?),
            Growth::Double => {
                return Err(Error::input(
                    "simulate.growth_step",
                    "only with growth = \"add\" (the default growth is \"double\")",
                ));
            }
        },
        (None, None) => {}
    }
    if let Some(policy) = s.policy {
        p.policy = match policy {
            PolicyId::WhenInfeasible => ReplanPolicy::WhenInfeasible,
            PolicyId::Always => ReplanPolicy::Always,
        };
    }
    if let Some(w) = s.warm_start {
        p.warm_start = w;
    }
    if let Some(a) = s.accept {
        p.accept = match a {
            AcceptId::Route => Acceptance::Route,
            AcceptId::Window => Acceptance::Window,
        };
    }
    if let Some(r) = s.sensor_range {
        if !(r > 0.0 && r.is_finite()) {
            return Err(Error::input("simulate.sensor_range", format!("must be finite and > 0 (m), got {r}")));
        }
        if r > MAX_COORDINATE {
            return Err(Error::input(
                "simulate.sensor_range",
                format!("must be at most {MAX_COORDINATE:e} m, got {r:e}"),
            ));
        }
        p.sensor_range = Some(r);
    }
    Ok(p)
}
