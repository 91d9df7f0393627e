//! The run's one clock holds for every registered planner and smoother: on a world heavy
//! enough that any of them would take many seconds (thousands of obstacles and vortices), a
//! wall-time limit of 0.2 s returns within a second, and a stop flag raised from another thread
//! mid-run stops it within a second with stop reason `cancelled`. The planners and smoothers
//! come from the registry tables (extended with this crate's toys), so a new one is covered
//! without editing this file.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

mod common;

use common::toys;
use tidepath::termination::StopReason;
use tidepath_io::scenario::{Components, PlanRequest, Scenario};

/// A 2-D world of 1,500 discs, 1,500 boxes and 1,000 vortices: every path evaluation, raster
/// cell, visibility test and edge check is slow.
fn heavy() -> Scenario {
    let mut text = String::from(
        "name = \"heavy\"\n[world]\ndimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [20000.0, 20000.0, 0.0] }\n",
    );
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for k in 0..3000 {
        let (x, y) = (1000.0 + 18000.0 * next(), 1000.0 + 18000.0 * next());
        if k % 2 == 0 {
            text += &format!("[[world.obstacles]]\nkind = \"cylinder\"\ncenter = [{x}, {y}]\nradius = 30.0\n");
        } else {
            text += &format!(
                "[[world.obstacles]]\nkind = \"box\"\nmin = [{x}, {y}, -1.0]\nmax = [{}, {}, 1.0]\n",
                x + 40.0,
                y + 40.0
            );
        }
    }
    text += "[world.current]\nkind = \"vortices\"\nvortices = [\n";
    for _ in 0..1000 {
        let (x, y) = (20000.0 * next(), 20000.0 * next());
        text += &format!("  {{ x = {x}, y = {y}, strength = 100.0, core_radius = 300.0 }},\n");
    }
    text += "]\n[vehicle]\nspeed = 2.0\nsafety_distance = 5.0\n[mission]\nstart = [200.0, 200.0, 0.0]\ngoal = [19800.0, 19800.0, 0.0]\n";
    text += "[model]\ncurrent_step = 50.0\n";
    Scenario::from_toml(&text, "heavy.toml").unwrap()
}

/// A heavy request for `id`: a large population where the planner has one, no count limit
/// beyond its own defaults.
fn request(c: &Components, id: &str, stop: Option<Arc<AtomicBool>>, time_limit_s: Option<f64>) -> PlanRequest {
    let entry = *c.planners.get(id).unwrap();
    let has_population = entry.has_param("population");
    PlanRequest {
        planner: Some(id.to_string()),
        population: has_population.then_some(5000),
        iterations: None,
        time_limit_s,
        stop,
        parallel: false,
        ..PlanRequest::default()
    }
}

#[test]
fn every_planner_and_smoother_keeps_the_clock_and_the_stop_flag() {
    let s = heavy();
    let c = Components { planners: toys::planners(), smoothers: toys::smoothers() };
    let mut cases: Vec<(String, PlanRequest)> = Vec::new();
    for entry in c.planners.entries() {
        cases.push((entry.id.to_string(), request(&c, entry.id, None, None)));
    }
    // Each smoother after a quick planner, so the smoother is what runs out of time.
    for smoother in c.smoothers.entries() {
        let mut req = request(&c, "pso", None, None);
        req.population = Some(8);
        req.iterations = Some(1);
        req.smoother = Some(smoother.id.to_string());
        cases.push((format!("smoother {}", smoother.id), req));
    }
    let mut failures = Vec::new();
    for (what, req) in &cases {
        // Wall time.
        let timed = PlanRequest { time_limit_s: Some(0.2), ..req.clone() };
        let t = Instant::now();
        let r = s.plan_in(&c, &timed, &mut |_| {});
        let took = t.elapsed();
        eprintln!("{what}: time limit: {took:?}");
        match &r {
            Ok(r) if took > Duration::from_secs(1) => {
                failures.push(format!("{what}: 0.2 s limit took {took:?} (stopped by {})", r.stop_reason.id()))
            }
            Ok(_) => {}
            Err(e) => failures.push(format!("{what}: {e}")),
        }
        // Stop flag from another thread, 0.15 s in, with a long wall-time limit.
        let flag = Arc::new(AtomicBool::new(false));
        let flagged = PlanRequest { stop: Some(flag.clone()), time_limit_s: Some(60.0), ..req.clone() };
        let raiser = {
            let flag = flag.clone();
            std::thread::spawn(move || {
                std::thread::sleep(Duration::from_millis(150));
                flag.store(true, Ordering::Relaxed);
                Instant::now()
            })
        };
        let r = s.plan_in(&c, &flagged, &mut |_| {});
        let returned = Instant::now();
        let raised = raiser.join().unwrap();
        let after = raised.elapsed();
        eprintln!("{what}: stop flag: {after:?} after");
        match r {
            // A planner that finished before the flag went up had nothing to cancel; nor had a
            // run that was judging its finished path when it went up (it returns at once:
            // on this heavy world a planner that ignored the flag would run for seconds).
            Ok(_) if returned < raised + Duration::from_millis(100) => {}
            Ok(r) if r.stop_reason != StopReason::Cancelled => {
                failures.push(format!("{what}: stopped by {} instead of cancelled", r.stop_reason.id()))
            }
            Ok(_) if after > Duration::from_secs(1) => failures.push(format!("{what}: ran {after:?} after the flag")),
            Ok(_) => {}
            Err(e) => failures.push(format!("{what}: {e}")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(cases.len() >= c.planners.entries().len() + c.smoothers.entries().len());
}
