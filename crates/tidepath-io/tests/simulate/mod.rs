//! Simulations re-checked by the independent dense sampler of `common/`: each segment of the
//! flown track against the true world in force when the vehicle flew it (moving ships where
//! they were, each forecast from its arrival), at the vehicle's own clock; and every planner
//! of the table in the loop.

use tidepath::planner::{Unit, PLANNERS};
use tidepath::simulate::Simulation;
use tidepath_io::scenario::Scenario;
use tidepath_io::simulation::SimRequest;

use crate::common::recheck_path;

/// Re-checks the flown track segment by segment; returns the samples taken.
fn recheck_track(s: &Scenario, sim: &Simulation) -> Result<usize, String> {
    let t = &sim.track;
    let mut samples = 0;
    for (i, (w, tt)) in t.points.windows(2).zip(t.times.windows(2)).enumerate() {
        let e = sim.epochs.iter().rposition(|e| e.from <= tt[0]).unwrap_or(0);
        let truth = sim.truth(&s.world, e);
        let m = &s.missions[0];
        samples +=
            recheck_path(&truth, &m.vehicle, &s.settings, w, tt, &[]).map_err(|x| format!("track segment {i}: {x}"))?;
    }
    Ok(samples)
}

/// A per-replan budget in whatever the planner counts, small enough for a test.
fn tiny(id: &str) -> SimRequest {
    let caps = tidepath::planner::registry().get(id).unwrap().build.caps;
    let mut req =
        SimRequest { planner: Some(id.to_string()), seed: 3, time_limit_s: Some(20.0), ..SimRequest::default() };
    match caps.counts.first() {
        Some(Unit::Iterations) => req.iterations = Some(15),
        Some(Unit::Evaluations) => req.evaluations = Some(600),
        Some(Unit::Samples) => req.samples = Some(600),
        Some(Unit::Expansions) | None => {}
    }
    req
}

#[test]
fn every_planner_runs_in_the_loop() {
    use rayon::prelude::*;
    let s = Scenario::from_toml(include_str!("../data/channel_changes.toml"), "channel_changes.toml").unwrap();
    let results: Vec<(&str, bool, usize)> = PLANNERS
        .par_iter()
        .map(|e| {
            let r = s.simulate(&tiny(e.id)).unwrap_or_else(|err| panic!("{}: {err}", e.id));
            let sim = &r.sim;
            assert!(sim.complete, "{}: {}", e.id, sim.reason);
            assert!(sim.phases.len() >= 2 || !sim.reached, "{}: the change is a phase", e.id);
            // Never a jump: each phase starts where the track is at its time.
            for p in &sim.phases[1..] {
                let k = sim.track.times.iter().rposition(|&x| x <= p.time).unwrap();
                assert_eq!(sim.track.points[k], p.position, "{}", e.id);
            }
            let samples = if sim.reached {
                recheck_track(&s, sim).unwrap_or_else(|x| panic!("{}: {x}", e.id))
            } else {
                assert!(sim.reason.contains("phase"), "{}: {}", e.id, sim.reason);
                0
            };
            (e.id, sim.reached, samples)
        })
        .collect();
    let reached: Vec<&str> = results.iter().filter(|r| r.1).map(|r| r.0).collect();
    // The exact planners cannot miss on an open channel; optimizers on 15 iterations may.
    for id in ["astar", "theta-star", "visibility", "hybrid"] {
        assert!(reached.contains(&id), "{id} did not reach: {results:?}");
    }
    assert!(reached.len() * 2 > results.len(), "most planners reach the goal: {results:?}");
    assert!(results.iter().all(|r| !r.1 || r.2 > 100), "{results:?}");
}

#[test]
fn coastal_traffic_reaches_the_goal_and_passes_the_independent_recheck() {
    let s = tidepath_io::scenario::load("coastal-traffic").unwrap();
    let r = s.simulate(&SimRequest { seed: 1, ..SimRequest::default() }).unwrap();
    let sim = &r.sim;
    assert!(sim.reached, "{}", sim.reason);
    assert!(sim.track_violations.is_empty(), "{:?}", sim.track_violations);
    assert!(recheck_track(&s, sim).unwrap() > 1000);
    // Ships were sighted and the route re-planned around something.
    assert!(sim.phases.iter().any(|p| p.sighted.is_some()), "a ship is sighted");
    assert!(sim.phases.iter().any(|p| p.replan.is_some() && p.route_problem.is_some()), "a re-plan dodges");
}

#[test]
fn forecast_update_replans_on_the_new_forecast() {
    let s = tidepath_io::scenario::load("forecast-update").unwrap();
    let r = s.simulate(&SimRequest { seed: 1, ..SimRequest::default() }).unwrap();
    let sim = &r.sim;
    assert!(sim.reached, "{}", sim.reason);
    assert_eq!(sim.currents.len(), 2, "the new forecast arrived");
    let p = sim.phases.iter().find(|p| !p.changes.is_empty()).expect("the forecast phase");
    assert!(p.event.contains("forecast"), "{}", p.event);
    assert!(p.replan.as_ref().is_some_and(|x| x.status.is_success()), "re-planned on it");
    assert_ne!(p.route_before, p.route_after, "the route after the new forecast differs");
    // The re-checker's clock, on each forecast from its arrival, agrees with the reported
    // times: the travel time is the one on the forecasts as they arrived.
    recheck_track(&s, sim).unwrap();
    // And it is not the time the departure plan promised on the old forecast alone.
    let planned = s.evaluate(&sim.phases[0].route_after).unwrap();
    let promised = *planned.times.last().unwrap();
    assert!((sim.arrival().unwrap() - promised).abs() > 1.0, "{} vs {promised}", sim.arrival().unwrap());
}
