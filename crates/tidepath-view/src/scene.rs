//! The scene as JSON: everything the page draws, in the scenario's metres (x east, y north,
//! z up), with the clock the playback runs on.
//!
//! The page (`assets/viewer.js`) reads exactly these keys: `title`, `subtitle`, `dims`,
//! `bounds`, `z_range`, `exaggeration`, `geo_ticks`, `time`, `seabed`, `waves`, `currents`,
//! `obstacles`, `routes`, `markers`, `phases`.

use serde_json::{json, Value};
use tidepath::geom::Vec3;
use tidepath::world::{Current, Dims, Obstacle, Terrain};

use crate::flow::{currents_json, sample_times, waves_json};
use crate::obstacles::{obstacles_json, EpochObstacles};
use crate::routes::{route_json, RouteContext};
use crate::seabed::seabed_json;
use crate::{Stopped, ViewInput};

/// The clock the slider runs over: from the first departure to the last arrival (of routes
/// and of a simulated track). A view with nothing timed but something moving (a ship, a
/// tidal current) gets the time a vehicle needs for the first mission's straight line, half as
/// long again; a view where nothing moves has a single instant.
fn time_range(input: &ViewInput<'_>, moves: bool) -> (f64, f64) {
    let s = input.scenario;
    let t0 = s.missions.iter().map(|m| m.departure_time).fold(s.departure_time, f64::min);
    let mut t1 = t0;
    for r in &input.routes {
        t1 = r
            .times
            .iter()
            .chain(r.flown.iter().flat_map(|f| f.1.iter()))
            .copied()
            .filter(|t| t.is_finite())
            .fold(t1, f64::max);
    }
    if let Some(sim) = input.simulation {
        t1 = sim.track.times.iter().copied().filter(|t| t.is_finite()).fold(t1, f64::max);
    }
    if t1 <= t0 && moves {
        let straight = s.missions.first().map_or(0.0, |m| m.start.distance(m.goal) / m.vehicle.speed.max(1e-6));
        t1 = t0 + 1.5 * straight.max(60.0);
    }
    (t0, t1)
}

/// The vertical range the scene shows: the domain and the seabed within it; a 2-D world
/// without a seabed gets a thin slab about its travel plane so obstacles show as walls.
fn z_range(input: &ViewInput<'_>, seabed: Option<&Value>) -> (f64, f64) {
    let b = &input.scenario.world.bounds;
    let (mut lo, mut hi) = (b.min.z, b.max.z);
    if let Some(s) = seabed {
        lo = lo.min(s["cmin"].as_f64().unwrap_or(lo));
        hi = hi.max(s["zmax_drawn"].as_f64().unwrap_or(hi));
    }
    if hi - lo < 1e-6 {
        let pad = 0.03 * (b.max.x - b.min.x).max(b.max.y - b.min.y).max(1.0);
        lo -= pad;
        hi += pad;
    } else {
        // A flat seabed on the box's floor flickers against the floor's pane (both drawn at
        // one depth): keep a little water under the deepest node and air over the land.
        let pad = 0.02 * (hi - lo);
        lo -= pad;
        hi += pad;
    }
    (lo, hi)
}

fn point(p: Vec3) -> Value {
    let m = crate::lattice::m;
    json!([m(p.x), m(p.y), m(p.z)])
}

/// The whole scene.
pub fn scene_json(input: &ViewInput<'_>, stop: &dyn Fn() -> bool) -> Result<Value, Stopped> {
    let s = input.scenario;
    let world = &s.world;
    let b = &world.bounds;
    // The true world over time: a simulation's epochs, else the scenario's world throughout.
    let epochs: Vec<EpochObstacles<'_>> = match input.simulation {
        Some(sim) if !sim.epochs.is_empty() => sim
            .epochs
            .iter()
            .enumerate()
            .map(|(k, e)| EpochObstacles {
                from: (k > 0).then_some(e.from),
                to: sim.epochs.get(k + 1).map(|n| n.from),
                obstacles: &e.obstacles,
            })
            .collect(),
        _ => vec![EpochObstacles { from: None, to: None, obstacles: &world.obstacles }],
    };
    let pieces: Vec<(f64, &Current)> = match input.simulation {
        Some(sim) if !sim.epochs.is_empty() => {
            sim.epochs.iter().map(|e| (e.from, &sim.currents[e.current.min(sim.currents.len() - 1)])).collect()
        }
        _ => vec![(f64::NEG_INFINITY, &world.current)],
    };
    let any_moving = epochs.iter().flat_map(|e| e.obstacles.iter()).any(|o: &Obstacle| !o.is_fixed());
    let flows = pieces.len() > 1 || !matches!(world.current, Current::None | Current::Uniform(_));
    let (t0, t1) = time_range(input, any_moving || flows || world.waves.varies());
    let times = sample_times(t0, t1, &pieces);

    let seabed = seabed_json(world, s.frame.as_ref(), stop)?;
    let (z_lo, z_hi) = z_range(input, seabed.as_ref());
    let obstacles = obstacles_json(&epochs, z_lo, z_hi, stop)?;
    let currents = currents_json(world, &pieces, &times, stop)?;
    let waves = waves_json(world, &times, stop)?;

    let cost = s.cost_model().ok();
    let cx = RouteContext { scenario: s, world, epochs: &epochs, cost: cost.as_deref() };
    let mut routes = Vec::with_capacity(input.routes.len());
    for r in &input.routes {
        routes.push(route_json(&cx, r, stop)?);
    }
    let phases: Vec<Value> = input
        .simulation
        .map(|sim| {
            sim.phases
                .iter()
                .map(|p| {
                    json!({
                        "t": p.time,
                        "event": p.event,
                        "status": p.replan.as_ref().map(|r| r.status.to_string()),
                        "route": p.route_after.iter().map(|q| point(*q)).collect::<Vec<_>>(),
                    })
                })
                .collect()
        })
        .unwrap_or_default();
    let starts: Vec<Value> = s.missions.iter().map(|m| json!({ "name": m.name, "at": point(m.start) })).collect();
    let goals: Vec<Value> = s.missions.iter().map(|m| json!({ "name": m.name, "at": point(m.goal) })).collect();
    let width = (b.max.x - b.min.x).max(b.max.y - b.min.y);
    let flat = world.dims == Dims::Two && matches!(world.terrain, Terrain::None);
    Ok(json!({
        "title": input.title,
        "subtitle": s.description,
        "dims": if world.dims == Dims::Three { 3 } else { 2 },
        "bounds": { "x": [b.min.x, b.max.x], "y": [b.min.y, b.max.y] },
        "z_range": [z_lo, z_hi],
        "exaggeration": {
            "default": if flat { 1.0 } else { crate::axes::default_exaggeration(width, z_hi - z_lo) },
            "max": crate::axes::MAX_EXAGGERATION,
        },
        "geo_ticks": s.frame.as_ref().map(|f| crate::axes::geo_ticks(f, b)),
        "time": { "start": t0, "end": t1, "epoch": s.epoch.map(|e| e.to_rfc3339()) },
        "seabed": seabed,
        "waves": waves,
        "currents": currents,
        "obstacles": obstacles,
        "routes": routes,
        "markers": { "starts": starts, "goals": goals },
        "phases": phases,
    }))
}
