//! Every registered planner's plans, re-checked by the independent dense sampler of
//! `common/`: on `demo`, `salish`, `headland` (2-D, where `visibility` applies), and two worlds with moving obstacles and time-varying
//! currents. A plan the evaluation calls feasible must pass; the number of feasible plans
//! re-checked is asserted so the test cannot pass by checking nothing.

use crate::common;
/// Fleets' separation re-checked the same way.
#[path = "fleet/mod.rs"]
mod fleet;
/// Simulations re-checked the same way.
#[path = "simulate/mod.rs"]
mod simulate;

use tidepath::planner::PLANNERS;
use tidepath_io::scenario::{PlanRequest, Scenario};

fn scenarios() -> Vec<Scenario> {
    let mut out: Vec<Scenario> =
        ["demo", "salish", "headland"].iter().map(|n| tidepath_io::scenario::load(n).unwrap()).collect();
    out.push(Scenario::from_toml(include_str!("data/moving_jet.toml"), "moving_jet.toml").unwrap());
    out.push(Scenario::from_toml(include_str!("data/tidal_grid.toml"), "tidal_grid.toml").unwrap());
    out
}

#[test]
fn no_disagreement_over_a_thousand_plans_from_every_planner() {
    use rayon::prelude::*;
    // 64 seeds cover every iteration count (6 + seed % 20) with and without the smoother, in
    // each world: about 2,900 feasible plans in all, at least 78 per optimizer (wpa) when written.
    const SEEDS: u64 = 64;
    let worlds = scenarios();
    // The planners run side by side (each plan itself on one thread): the runs are independent
    // and the test's verdicts do not depend on their order.
    let results: Vec<(&str, usize, usize, f64, bool)> = PLANNERS
        .par_iter()
        .map(|entry| {
            // Graph and composite planners vary little with the seed: a few runs each; sampling
            // planners a few more, with short budgets.
            let optimizer = entry.build.is_optimizer();
            let sampling = entry.build.caps.counts_unit(tidepath::planner::Unit::Samples);
            let seeds = if optimizer {
                SEEDS
            } else if sampling {
                6
            } else {
                2
            };
            let mut feasible = 0;
            let clock = std::time::Instant::now();
            for s in &worlds {
                for seed in 0..seeds {
                    // Short runs: many different plans, near the edge of feasibility.
                    let iterations = 6 + seed % 20;
                    let smoother = (seed % 3 == 0).then(|| "shortcut".to_string());
                    let req = PlanRequest {
                        planner: Some(entry.id.into()),
                        seed,
                        // Short runs where the planner counts iterations.
                        iterations: entry
                            .build
                            .caps
                            .counts_unit(tidepath::planner::Unit::Iterations)
                            .then_some(iterations),
                        // And an evaluation cap the population-per-iteration optimizers do not
                        // reach here (populations up to 50): the wolf packs repeat scouting and
                        // raiding up to T_max times per iteration and would take minutes.
                        evaluations: optimizer.then_some(50 * (iterations + 1)),
                        samples: sampling.then_some(300 + 300 * seed),
                        smoother,
                        ..PlanRequest::default()
                    };
                    // A planner may decline a world it does not cover (an input error saying so).
                    let Ok(r) = s.plan(&req, &mut |_| {}) else { break };
                    if r.status.is_success() {
                        feasible += 1;
                        if let Err(e) = common::recheck_plan(s, &r) {
                            panic!("re-check disagrees with a feasible verdict: {e}");
                        }
                    }
                }
            }
            (entry.id, feasible, seeds as usize * worlds.len(), clock.elapsed().as_secs_f64(), optimizer)
        })
        .collect();
    let mut total = 0;
    for (id, feasible, runs, secs, optimizer) in results {
        eprintln!("{id}: {feasible} feasible plans re-checked of {runs} ({secs:.1} s)");
        let wanted = if optimizer { 40 } else { 1 };
        assert!(feasible >= wanted, "{id}: only {feasible} feasible plans");
        total += feasible;
    }
    assert!(total >= 1000, "only {total} feasible plans re-checked");
}

/// The reported defect: `plan demo --planner ga --seed 26 --iterations 20 --smooth shortcut`
/// was called feasible while passing 3.1 m inside the moving sphere. It must now be either
/// infeasible or truly clear of it.
#[test]
fn ga_seed_26_smoothed_plan_is_clear_of_the_moving_sphere_or_infeasible() {
    let s = tidepath_io::scenario::load("demo").unwrap();
    let req = PlanRequest {
        planner: Some("ga".into()),
        seed: 26,
        iterations: Some(20),
        smoother: Some("shortcut".into()),
        ..PlanRequest::default()
    };
    let r = s.plan(&req, &mut |_| {}).unwrap();
    if r.status.is_success() {
        common::recheck_plan(&s, &r).unwrap();
    }
}

/// The re-checker is not vacuous: put a moving sphere where a feasible plan's vehicle is at
/// mid-route, at that time, and it reports the collision; also a wrong clock.
#[test]
fn the_rechecker_finds_what_it_is_shown() {
    use tidepath::geom::Vec3;
    use tidepath::world::{Obstacle, Shape};
    let mut s = Scenario::from_toml(include_str!("data/moving_jet.toml"), "moving_jet.toml").unwrap();
    let r = s.plan(&PlanRequest { seed: 1, ..PlanRequest::default() }, &mut |_| {}).unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    assert!(common::recheck_plan(&s, &r).unwrap() > 1000);
    let m = &r.missions[0];
    let (path, times) = (m.points(), m.times.clone());
    let k = path.len() / 2;
    let (mid, t_mid) = ((path[k] + path[k + 1]) * 0.5, (times[k] + times[k + 1]) * 0.5);
    let velocity = Vec3::new(0.7, -0.4, 0.0);
    s.world.obstacles.push(Obstacle {
        shape: Shape::Sphere { center: mid - velocity * t_mid, radius: 2.0 },
        velocity,
        window: None,
    });
    let e = common::recheck_path(&s.world, &s.missions[0].vehicle, &s.settings, &path, &times, &[]).unwrap_err();
    assert!(e.contains(&format!("obstacle {}", s.world.obstacles.len() - 1)), "{e}");
    s.world.obstacles.pop();
    let mut late = times.clone();
    late[k + 1] += 1.0;
    assert!(common::recheck_path(&s.world, &s.missions[0].vehicle, &s.settings, &path, &late, &[])
        .unwrap_err()
        .contains("arrival"));
}

/// The flown-curve re-checker is not vacuous either: it passes the evaluation's own verdict
/// on a quarter turn, finds a moving sphere placed on the arc at the moment the vehicle is
/// there, a turn flown under the vehicle's radius, and a wrong clock.
#[test]
fn the_flown_rechecker_finds_what_it_is_shown() {
    use tidepath::geom::{Aabb, Vec3};
    use tidepath::mission::Mission;
    use tidepath::path::{ModelSettings, PathModel};
    use tidepath::vehicle::Vehicle;
    use tidepath::world::{Current, Obstacle, Shape, World};
    let mut world = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(300.0, 300.0, 0.0)));
    world.current = Current::Uniform(Vec3::new(0.3, 0.1, 0.0));
    let vehicle = Vehicle { turn_radius: Some(40.0), max_turn: std::f64::consts::PI, ..Vehicle::default() };
    let settings = ModelSettings::default();
    let path = [Vec3::new(10.0, 10.0, -50.0), Vec3::new(200.0, 10.0, -40.0), Vec3::new(200.0, 200.0, -40.0)];
    let mission = Mission::new("m", vehicle.clone(), path[0], path[2], 0.0);
    let model = PathModel::new(&world, &mission, &settings);
    let mut times = Vec::new();
    assert!(model.assess(&path, &mut times).feasible());
    let c = common::flown::recheck_flown(&world, &vehicle, &settings, &path, &times, &[], 40.0).unwrap();
    assert!(c.samples > 500, "{} samples", c.samples);
    assert!((c.min_circumradius - 40.0).abs() < 1e-6, "{c:?}");
    // Halfway round the turn, at the time the vehicle is there.
    let mid = Vec3::new(
        160.0 + 40.0 * (std::f64::consts::FRAC_PI_4).sin(),
        50.0 - 40.0 * (std::f64::consts::FRAC_PI_4).cos(),
        -40.0,
    );
    let velocity = Vec3::new(-0.5, 0.2, 0.0);
    let mut w2 = world.clone();
    w2.obstacles.push(Obstacle {
        shape: Shape::Sphere { center: mid - velocity * times[1], radius: 1.0 },
        velocity,
        window: None,
    });
    let e = common::flown::recheck_flown(&w2, &vehicle, &settings, &path, &times, &[], 40.0).unwrap_err();
    assert!(e.contains("obstacle 0"), "{e}");
    // A corner whose legs allow only 30 m.
    let short = [Vec3::new(170.0, 10.0, -50.0), Vec3::new(200.0, 10.0, -40.0), Vec3::new(200.0, 200.0, -40.0)];
    let e = common::flown::recheck_flown(&world, &vehicle, &settings, &short, &times, &[], 40.0).unwrap_err();
    assert!(e.contains("flown at radius 30.000 m"), "{e}");
    let mut late = times.clone();
    late[1] += 0.5;
    assert!(common::flown::recheck_flown(&world, &vehicle, &settings, &path, &late, &[], 40.0)
        .unwrap_err()
        .contains("halfway"));
}

/// A wave glider's plans, re-checked on the re-checker's own glider clock: every planner on
/// `glider-4` (waves rising to the north-west, an eddy), a few short runs each. The clock is the
/// regression's, so a plan called feasible must agree with it in time and clearance.
#[test]
fn every_planner_agrees_with_the_glider_clock() {
    use rayon::prelude::*;
    let s = tidepath_io::scenario::load("glider-4").unwrap();
    let feasible: usize = PLANNERS
        .par_iter()
        .map(|entry| {
            let mut feasible = 0;
            for seed in 0..3 {
                let req = PlanRequest {
                    planner: Some(entry.id.into()),
                    seed,
                    iterations: entry.build.caps.counts_unit(tidepath::planner::Unit::Iterations).then_some(10),
                    evaluations: entry.build.is_optimizer().then_some(500),
                    samples: entry.build.caps.counts_unit(tidepath::planner::Unit::Samples).then_some(500),
                    ..PlanRequest::default()
                };
                let Ok(r) = s.plan(&req, &mut |_| {}) else { break };
                if r.status.is_success() {
                    feasible += 1;
                    if let Err(e) = common::recheck_plan(&s, &r) {
                        panic!("{}: re-check disagrees with a feasible verdict on glider-4: {e}", entry.id);
                    }
                }
            }
            feasible
        })
        .sum();
    assert!(feasible >= 20, "only {feasible} feasible glider plans re-checked");
}
