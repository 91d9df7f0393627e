//! The simulation file `simulate --out` writes: every phase (its trigger, the changes, the
//! world the vehicle knew, the re-planned piece with its status, cost and planning time, the
//! route ahead after it) and the executed track with its times. Positions are metres in the
//! scenario's local frame; a geographic scenario adds longitude/latitude beside them and UTC
//! instants beside the clock's seconds.
//!
//! Everything but the wall times (`planning_s`, `elapsed_s`) repeats bit for bit for the same
//! seed.

use serde_json::{json, Value};

use super::SimReport;
use crate::export::utc;
use crate::scenario::Scenario;
use tidepath::geom::Vec3;
use tidepath::simulate::{Acceptance, Growth, Phase, Replan, ReplanPolicy};
use tidepath::world::changes::Trigger;

/// Bumped when a field changes meaning or goes away (2: a phase's `change` became `changes`,
/// every change of one event).
pub const SIMULATION_FORMAT_VERSION: u32 = 2;

/// The simulation as pretty-printed JSON.
pub fn simulation_json(scenario: &Scenario, r: &SimReport) -> String {
    let sim = &r.sim;
    let points = |ps: &[Vec3]| -> Value { ps.iter().map(|p| json!([p.x, p.y, p.z])).collect() };
    let lonlat = |ps: &[Vec3]| -> Option<Value> {
        scenario.frame.as_ref().map(|f| {
            ps.iter()
                .map(|p| {
                    let (lon, lat) = f.inverse(p.x, p.y);
                    json!([lon, lat, p.z])
                })
                .collect()
        })
    };
    let instant = |t: f64| utc(scenario.epoch, t);
    let phases: Vec<Value> =
        sim.phases.iter().enumerate().map(|(k, p)| phase_json(scenario, r, k, p, &points, &lonlat, &instant)).collect();
    let p = &r.params;
    let doc = json!({
        "tidepath_simulation": SIMULATION_FORMAT_VERSION,
        "scenario": scenario.name,
        "scenario_source": scenario.source,
        "planner": r.planner,
        "seed": r.seed,
        "epoch": scenario.epoch.map(|e| e.to_rfc3339()),
        "loop": {
            "window": p.window,
            "growth": match p.growth { Growth::Double => "double".to_string(), Growth::Add(n) => format!("add {n}") },
            "policy": policy_id(p.policy),
            "accept": accept_id(p.accept),
            "warm_start": p.warm_start,
            "sensor_range_m": p.sensor_range,
            "replan_time_limit_s": r.replan_time_limit_s,
            "total_time_limit_s": r.total_time_limit_s,
        },
        "outcome": {
            "reached": sim.reached,
            "complete": sim.complete,
            "reason": sim.reason,
            "arrival_s": sim.arrival(),
            "arrival_utc": sim.arrival().and_then(instant),
            "travelled_m": sim.track.travelled,
            "track_violations": sim.track_violations,
            "elapsed_s": r.elapsed_s,
        },
        "phases": phases,
        "track": {
            "points": points(&sim.track.points),
            "lonlat": lonlat(&sim.track.points),
            "times_s": sim.track.times,
        },
        "route_left": points(&sim.route),
    });
    let mut text = serde_json::to_string_pretty(&doc).expect("JSON of numbers and strings");
    text.push('\n');
    text
}

/// The `[simulate] accept` word for `a`.
pub fn accept_id(a: Acceptance) -> &'static str {
    match a {
        Acceptance::Route => "route",
        Acceptance::Window => "window",
    }
}

pub fn policy_id(p: ReplanPolicy) -> &'static str {
    match p {
        ReplanPolicy::WhenInfeasible => "when-infeasible",
        ReplanPolicy::Always => "always",
    }
}

fn phase_json(
    scenario: &Scenario,
    r: &SimReport,
    k: usize,
    p: &Phase,
    points: &dyn Fn(&[Vec3]) -> Value,
    lonlat: &dyn Fn(&[Vec3]) -> Option<Value>,
    instant: &dyn Fn(f64) -> Option<String>,
) -> Value {
    let sim = &r.sim;
    let (known, unseen) = sim.known(&scenario.world, k);
    let epoch = &sim.epochs[p.epoch];
    let trigger = p.trigger.map(|t| match t {
        Trigger::AtTime(s) => json!({ "at_time_s": s }),
        Trigger::AfterDistance(m) => json!({ "after_distance_m": m }),
    });
    let changes: Vec<Value> = p
        .changes
        .iter()
        .map(|c| json!({ "description": c.description, "random_draws": c.draws, "skipped": c.skipped }))
        .collect();
    let obstacles: Vec<Value> = known
        .obstacles
        .iter()
        .map(|o| {
            let c = tidepath::world::changes::center(&o.shape_at(p.time));
            json!({ "center_now": [c.x, c.y, c.z], "velocity": [o.velocity.x, o.velocity.y, o.velocity.z] })
        })
        .collect();
    json!({
        "phase": k,
        "event": p.event,
        "time_s": p.time,
        "time_utc": instant(p.time),
        "position": [p.position.x, p.position.y, p.position.z],
        "position_lonlat": lonlat(&[p.position]).map(|v| v[0].clone()),
        "trigger": trigger,
        "changes": changes,
        "sighted_obstacle": p.sighted,
        "known_world": {
            "obstacles": obstacles,
            "unseen_obstacles": unseen.len(),
            "current_forecast": epoch.current,
            "current_forecasts_received": epoch.current + 1,
        },
        "route_problem": p.route_problem,
        "replan": p.replan.as_ref().map(|x| replan_json(x, points)),
        "route_after": points(&p.route_after),
    })
}

fn replan_json(x: &Replan, points: &dyn Fn(&[Vec3]) -> Value) -> Value {
    json!({
        "windows_tried": x.windows,
        "target": [x.target.x, x.target.y, x.target.z],
        "status": x.status.id(),
        "reason": x.reason,
        "cost": x.cost.is_finite().then_some(x.cost),
        "planning_s": x.planning_s,
        "warm_start": x.warm,
        "piece": points(&x.piece),
        "focus": x.focus.as_ref().map(|f| json!({ "at": [f.at.x, f.at.y, f.at.z], "label": f.label })),
    })
}
