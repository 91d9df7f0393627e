//! An independent feasibility re-checker for plans: dense sampling of every segment at the
//! vehicle's own clock, written separately from the `validity` module. It re-derives the clock
//! from the documented travel model (pieces of at most `current_step` metres, each at the crab
//! ground speed for the current at its midpoint when the vehicle enters it), checks that the
//! plan's reported arrival times agree, and samples every piece at the times the vehicle is
//! there: seabed clearance (vertical) and obstacle clearance (Euclidean, own distance
//! formulas, obstacles moved to the sample's time) must both be at least the safety distance.

#![allow(dead_code)]

use tidepath::geom::Vec3;
use tidepath::path::{ModelSettings, TravelModel};
use tidepath::vehicle::Vehicle;
use tidepath::world::{Current, Obstacle, Shape, World};
use tidepath_io::scenario::Scenario;
use tidepath_io::PlanReport;

/// Samples per piece, at least; pieces longer than `MAX_SPACING` metres get more.
const MIN_SAMPLES: usize = 24;
const MAX_SPACING: f64 = 5.0;
/// Rounding allowance (m) on clearances.
const TOL: f64 = 1e-6;

/// (start point, end point, start time, end time) of each piece of segment a -> b.
pub fn clock(
    world: &World,
    settings: &ModelSettings,
    v: f64,
    a: Vec3,
    b: Vec3,
    t0: f64,
) -> Option<Vec<(Vec3, Vec3, f64, f64)>> {
    let len = a.distance(b);
    if len == 0.0 {
        return Some(vec![(a, b, t0, t0)]);
    }
    let d = (b - a) / len;
    if settings.travel == TravelModel::VectorSum {
        // One piece at the model's mean speed (documented in the validity module).
        let floor = 0.05 * v;
        let va = (d * v + world.current.velocity(a, t0)).length().max(floor);
        let vb = (d * v + world.current.velocity(b, t0 + len / va)).length().max(floor);
        return Some(vec![(a, b, t0, t0 + len / (2.0 * va) + len / (2.0 * vb))]);
    }
    let n = match world.current {
        Current::None | Current::Uniform(_) => 1,
        _ => (len / settings.current_step).ceil().clamp(1.0, 100_000.0) as usize,
    };
    let piece = len / n as f64;
    let mut out = Vec::with_capacity(n);
    let mut t = t0;
    for k in 0..n {
        let p0 = a + d * (piece * k as f64);
        let p1 = if k + 1 == n { b } else { a + d * (piece * (k + 1) as f64) };
        let c = world.current.velocity(a + d * (piece * (k as f64 + 0.5)), t);
        let along = c.dot(d);
        let cross = c - d * along;
        let disc = v * v - cross.dot(cross);
        if disc < 0.0 || along + disc.sqrt() <= 0.0 {
            return None;
        }
        let t1 = t + piece / (along + disc.sqrt());
        out.push((p0, p1, t, t1));
        t = t1;
    }
    Some(out)
}

/// [`clock`] for `vehicle`: a wave glider's pieces follow its documented speed model instead
/// (acopf2016 eqs. 1-2 as tidepath reads them: speed over ground = max(min_speed,
/// wave_gain H + current_gain c.d), H and c at the piece's midpoint when the glider enters it,
/// pieces of at most `current_step` where waves or current vary; `None` where a head current
/// drives it backwards). Written here from the formula, not from the validator.
pub fn vehicle_clock(
    world: &World,
    settings: &ModelSettings,
    vehicle: &Vehicle,
    v: f64,
    a: Vec3,
    b: Vec3,
    t0: f64,
) -> Option<Vec<(Vec3, Vec3, f64, f64)>> {
    let Some(g) = vehicle.glider() else { return clock(world, settings, v, a, b, t0) };
    let len = a.distance(b);
    if len == 0.0 {
        return Some(vec![(a, b, t0, t0)]);
    }
    let d = (b - a) / len;
    let steady_field = matches!(world.current, Current::None | Current::Uniform(_))
        && matches!(world.waves, tidepath::world::Waves::None | tidepath::world::Waves::Uniform(_));
    let n = if steady_field { 1 } else { (len / settings.current_step).ceil().clamp(1.0, 100_000.0) as usize };
    let piece = len / n as f64;
    let mut out = Vec::with_capacity(n);
    let mut t = t0;
    for k in 0..n {
        let mid = a + d * (piece * (k as f64 + 0.5));
        let along = world.current.velocity(mid, t).dot(d);
        let speed = g.wave_gain * world.waves.height(mid, t) + g.current_gain * along;
        if along < 0.0 && speed <= 0.0 {
            return None;
        }
        let p0 = a + d * (piece * k as f64);
        let p1 = if k + 1 == n { b } else { a + d * (piece * (k + 1) as f64) };
        let t1 = t + piece / speed.max(g.min_speed);
        out.push((p0, p1, t, t1));
        t = t1;
    }
    Some(out)
}

/// Distance from `p` to the surface of `o` at time `t` (0 inside), by its own formulas.
pub fn distance(o: &Obstacle, p: Vec3, t: f64) -> f64 {
    let q = p - o.velocity * t;
    match o.shape {
        Shape::Sphere { center, radius } => ((q - center).length() - radius).max(0.0),
        Shape::Circle { center, radius } => {
            (((q.x - center.x).powi(2) + (q.y - center.y).powi(2)).sqrt() - radius).max(0.0)
        }
        Shape::Cylinder { center, radius, z_min, z_max } => {
            let radial = (((q.x - center.x).powi(2) + (q.y - center.y).powi(2)).sqrt() - radius).max(0.0);
            let vertical = if q.z < z_min {
                z_min - q.z
            } else if q.z > z_max {
                q.z - z_max
            } else {
                0.0
            };
            (radial * radial + vertical * vertical).sqrt()
        }
        Shape::Box { min, max } => {
            let dx = (min.x - q.x).max(0.0).max(q.x - max.x);
            let dy = (min.y - q.y).max(0.0).max(q.y - max.y);
            let dz = (min.z - q.z).max(0.0).max(q.z - max.z);
            (dx * dx + dy * dy + dz * dz).sqrt()
        }
    }
}

/// The through-water speed at time `t` of a plan flown at `speeds` (one per segment; empty:
/// the cruise speed) with `times` at its waypoints: the speed of the last waypoint reached.
/// With a turning radius a waypoint's time is halfway round its turn, where the speed changes.
pub fn speed_at(vehicle: &Vehicle, speeds: &[f64], times: &[f64], t: f64) -> f64 {
    if speeds.is_empty() {
        return vehicle.speed;
    }
    let i = times.iter().rposition(|&x| x <= t).unwrap_or(0);
    speeds[i.min(speeds.len() - 1)]
}

/// Re-checks one path (start and goal included) with its reported arrival times, segment i
/// flown at `speeds[i]` (empty: the cruise speed). Returns the number of samples taken, or
/// what is wrong.
pub fn recheck_path(
    world: &World,
    vehicle: &Vehicle,
    settings: &ModelSettings,
    path: &[Vec3],
    times: &[f64],
    speeds: &[f64],
) -> Result<usize, String> {
    if path.len() != times.len() {
        return Err(format!("{} points but {} times", path.len(), times.len()));
    }
    let safety = vehicle.safety_distance;
    let mut samples = 0;
    let mut t0 = times[0];
    for (i, w) in path.windows(2).enumerate() {
        let v = if speeds.is_empty() { vehicle.speed } else { speeds[i] };
        let pieces = vehicle_clock(world, settings, vehicle, v, w[0], w[1], t0)
            .ok_or_else(|| format!("segment {i}: the current blocks the vehicle"))?;
        for &(p0, p1, ta, tb) in &pieces {
            let n = MIN_SAMPLES.max((p0.distance(p1) / MAX_SPACING).ceil() as usize);
            for k in 0..=n {
                let s = k as f64 / n as f64;
                let (p, t) = (p0 + (p1 - p0) * s, ta + (tb - ta) * s);
                samples += 1;
                let ground = world.terrain.elevation(p.x, p.y);
                if p.z - ground < safety - TOL {
                    return Err(format!(
                        "segment {i}: {p:?} is {:.3} m above the seabed (safety {safety})",
                        p.z - ground
                    ));
                }
                for (j, o) in world.obstacles.iter().enumerate() {
                    let d = distance(o, p, t);
                    if d < safety - TOL {
                        return Err(format!(
                            "segment {i}: {p:?} at t = {t:.3} s is {d:.3} m from obstacle {j} (safety {safety})"
                        ));
                    }
                }
            }
        }
        let t1 = pieces.last().map_or(t0, |p| p.3);
        let reported = times[i + 1];
        if (t1 - reported).abs() > 1e-9 * t1.abs().max(1.0) {
            return Err(format!("segment {i}: arrival {t1} by the re-checker's clock, {reported} reported"));
        }
        t0 = reported;
    }
    Ok(samples)
}

/// Re-checks every mission of a plan the scenario's evaluation called feasible.
pub fn recheck_plan(s: &Scenario, r: &PlanReport) -> Result<usize, String> {
    let mut samples = 0;
    for (m, mission) in r.missions.iter().zip(&s.missions) {
        if !m.feasible {
            continue;
        }
        let path = m.points();
        let speeds = m.speeds.as_deref().unwrap_or(&[]);
        if let (Some(v), Some((lo, hi))) = (m.speeds.as_ref(), mission.vehicle.speed_range) {
            if v.len() + 1 != path.len() || v.iter().any(|x| !(lo..=hi).contains(x)) {
                return Err(format!("mission {}: speeds {v:?} not one per segment within [{lo}, {hi}]", m.name));
            }
        }
        let checked = match mission.vehicle.turn_radius {
            Some(radius) => {
                flown::recheck_flown(&s.world, &mission.vehicle, &s.settings, &path, &m.times, speeds, radius)
                    .map(|c| c.samples)
            }
            None => recheck_path(&s.world, &mission.vehicle, &s.settings, &path, &m.times, speeds),
        };
        samples +=
            checked.map_err(|e| format!("{} / {} seed {} mission {}: {e}", s.name, r.planner, r.seed, m.name))?;
    }
    if r.missions.iter().all(|m| m.feasible) && s.fleet.active(r.missions.len()) {
        samples += recheck_separation(s, r)?;
        recheck_arrivals(s, r)?;
    }
    Ok(samples)
}

/// Re-checks a fleet's separation by sampling every pair of vehicles on a common time grid
/// (every 0.25 s, from the first departure to the last arrival), each vehicle on the
/// re-checker's own clock, waiting at its start before departure and at its goal after
/// arrival (or absent, with `presence = "leaves"`). Every sample of a pair must be at least
/// its separation apart. Returns the samples taken.
pub fn recheck_separation(s: &Scenario, r: &PlanReport) -> Result<usize, String> {
    use tidepath::fleet::Presence;
    let rules = &s.fleet;
    if !rules.active(r.missions.len()) {
        return Ok(0);
    }
    // Each vehicle's pieces, on the flown curve's points when it has one.
    let mut timed: Vec<Vec<(Vec3, Vec3, f64, f64)>> = Vec::new();
    for (m, mission) in r.missions.iter().zip(&s.missions) {
        let (pts, times): (Vec<Vec3>, Vec<f64>) = match &m.flown {
            Some(f) => (f.vectors(), f.times.clone()),
            None => (m.points(), m.times.clone()),
        };
        let mut pieces = Vec::new();
        let speeds = m.speeds.as_deref().unwrap_or(&[]);
        for (w, &t0) in pts.windows(2).zip(&times) {
            let v = speed_at(&mission.vehicle, speeds, &m.times, t0);
            let p = vehicle_clock(&s.world, &s.settings, &mission.vehicle, v, w[0], w[1], t0)
                .ok_or_else(|| format!("mission {}: the current blocks the vehicle", m.name))?;
            pieces.extend(p);
        }
        timed.push(pieces);
    }
    let at = |pieces: &[(Vec3, Vec3, f64, f64)], t: f64| -> Option<Vec3> {
        let (first, last) = (pieces.first()?, pieces.last()?);
        if t < first.2 || t > last.3 {
            return (rules.presence == Presence::Stays).then_some(if t < first.2 { first.0 } else { last.1 });
        }
        let &(p0, p1, t0, t1) = pieces.iter().find(|p| t <= p.3)?;
        Some(if t1 > t0 { p0.lerp(p1, (t - t0) / (t1 - t0)) } else { p1 })
    };
    let t_lo = timed.iter().filter_map(|p| p.first().map(|x| x.2)).fold(f64::INFINITY, f64::min);
    let t_hi = timed.iter().filter_map(|p| p.last().map(|x| x.3)).fold(f64::NEG_INFINITY, f64::max);
    let steps = ((t_hi - t_lo) / 0.25).ceil().max(1.0) as usize;
    let mut samples = 0;
    for k in 0..=steps {
        let t = t_lo + (t_hi - t_lo) * k as f64 / steps as f64;
        for i in 0..timed.len() {
            for j in i + 1..timed.len() {
                let (Some(a), Some(b)) = (at(&timed[i], t), at(&timed[j], t)) else { continue };
                samples += 1;
                let need = rules.separation(i, j);
                if a.distance(b) < need - TOL {
                    return Err(format!(
                        "{} / {} seed {}: missions {} and {} are {:.3} m apart at t = {t:.3} s (separation {need})",
                        s.name,
                        r.planner,
                        r.seed,
                        r.missions[i].name,
                        r.missions[j].name,
                        a.distance(b)
                    ));
                }
            }
        }
    }
    Ok(samples)
}

/// Re-checks a fleet's arrival rule on the re-checker's own clock: each vehicle's arrival is
/// the end of its last piece (the flown curve's, with a turning radius).
pub fn recheck_arrivals(s: &Scenario, r: &PlanReport) -> Result<(), String> {
    use tidepath::fleet::Arrival;
    let mut arrivals = Vec::new();
    for (m, mission) in r.missions.iter().zip(&s.missions) {
        let (pts, times): (Vec<Vec3>, Vec<f64>) = match &m.flown {
            Some(f) => (f.vectors(), f.times.clone()),
            None => (m.points(), m.times.clone()),
        };
        let mut t = times.first().copied().ok_or_else(|| format!("mission {}: no times", m.name))?;
        let speeds = m.speeds.as_deref().unwrap_or(&[]);
        for (w, &t0) in pts.windows(2).zip(&times) {
            let v = speed_at(&mission.vehicle, speeds, &m.times, t0);
            let p = vehicle_clock(&s.world, &s.settings, &mission.vehicle, v, w[0], w[1], t0)
                .ok_or_else(|| format!("mission {}: the current blocks the vehicle", m.name))?;
            t = p.last().map_or(t0, |x| x.3);
        }
        arrivals.push(t);
    }
    let spread = arrivals.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - arrivals.iter().cloned().fold(f64::INFINITY, f64::min);
    match &s.fleet.arrival {
        Arrival::Together { tolerance_s } if spread > tolerance_s + 1e-6 => {
            Err(format!("{} / {}: arrivals spread over {spread:.3} s, more than {tolerance_s}", s.name, r.planner))
        }
        Arrival::Order(order) => {
            for w in order.windows(2) {
                if arrivals[w[1]] < arrivals[w[0]] - 1e-6 {
                    return Err(format!(
                        "{} / {}: mission {} arrives before mission {}",
                        s.name, r.planner, w[1], w[0]
                    ));
                }
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// A one-thread and a four-thread rayon pool, for runs that must not depend on the thread count.
pub fn one_and_four_threads() -> Vec<rayon::ThreadPool> {
    [1, 4].iter().map(|&n| rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap()).collect()
}

/// `run` once in each pool, the pools side by side (the results are compared, not ordered),
/// in pool order.
pub fn in_each_pool<T: Send>(pools: &[rayon::ThreadPool], run: impl Fn() -> T + Sync) -> Vec<T> {
    std::thread::scope(|scope| {
        let handles: Vec<_> = pools.iter().map(|p| scope.spawn(|| p.install(&run))).collect();
        handles.into_iter().map(|h| h.join().expect("run thread")).collect()
    })
}

/// The re-checker for vehicles with a turning radius (the flown fillet curve).
pub mod flown;

/// A toy planner and a toy smoother in extended registries.
#[allow(dead_code)]
pub mod toys;

/// A writer of crafted NetCDF headers (size bombs).
#[allow(dead_code)]
pub mod cdf1;
