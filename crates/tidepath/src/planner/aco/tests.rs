//! Hand-computed checks of the ant colonies' parts (acopf2016 eqs. 4-6 and 11-13 on a 3 x 3
//! grid, the heuristic of eqs. 7-10 at one cell, the roulette) and of `aco` and `acopf` on
//! small worlds (a wall, a cul-de-sac, budgets, determinism).

use std::f64::consts::PI;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use rand::SeedableRng;

use super::colony::{roulette, Colony, Graph, TourEnd, Walker};
use super::heuristic::{self, Attraction, Environment, Field};
use super::pheromone::{update, Tours, TAU_MAX, TAU_MIN};
use super::*;
use crate::cost::{GeneralCost, GeneralWeights};
use crate::geom::{Aabb, Vec2, Vec3};
use crate::mission::Mission;
use crate::path::{ModelSettings, PathModel};
use crate::planner::{solve, Plan, SolveOptions, Status};
use crate::vehicle::Vehicle;
use crate::world::{Current, Obstacle, Shape, Waves};

fn world_2d(w: f64, h: f64) -> World {
    World {
        waves: Waves::None,
        bounds: Aabb::new(Vec3::ZERO, Vec3::new(w, h, 0.0)),
        dims: Dims::Two,
        terrain: Terrain::None,
        obstacles: Vec::new(),
        current: Current::None,
        frame: None,
    }
}

/// A wall (a box through the plane) from (x0, y0) to (x1, y1).
fn wall(w: &mut World, (x0, y0): (f64, f64), (x1, y1): (f64, f64)) {
    w.obstacles.push(Obstacle::fixed(Shape::Box { min: Vec3::new(x0, y0, -1.0), max: Vec3::new(x1, y1, 1.0) }));
}

fn vehicle(max_turn: f64) -> Vehicle {
    Vehicle {
        propulsion: Default::default(),
        speed: 1.0,
        max_turn,
        max_pitch: 30f64.to_radians(),
        depth_min: 0.0,
        depth_max: 200.0,
        safety_distance: 5.0,
        turn_radius: None,
        speed_range: None,
    }
}

fn colony(id: &str, table: &str) -> AntColony {
    let t: toml::Table = toml::from_str(table).unwrap();
    match id {
        "aco" => AntColony::aco(AcoParams::from_table(&t, "p").unwrap()),
        _ => AntColony::acopf(AcopfParams::from_table(&t, "p").unwrap()),
    }
}

fn run(planner: &mut AntColony, w: &World, m: &Mission, termination: Termination, seed: u64) -> Plan {
    let settings = ModelSettings::default();
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let missions = [m.clone()];
    let problem =
        Problem { world: w, settings: &settings, cost: &cost, missions: &missions, fleet: &crate::fleet::NO_FLEET };
    let mut rng = crate::rng::run_rng(seed, 0);
    solve(planner, &problem, &termination, &mut rng, SolveOptions::default(), &mut |_| {}).unwrap()
}

/// A 3 x 3 grid of unit cells, nothing blocked, from cell 0 to cell 8.
fn grid3() -> Graph {
    let c = |i: f64, j: f64| Vec3::new(i + 0.5, j + 0.5, 0.0);
    Graph::new(3, 3, Vec3::ZERO, (1.0, 1.0), vec![false; 9], (0, 8), c(0.0, 0.0), c(2.0, 2.0))
}

/// Three tours on the 3 x 3 grid (edge = 8 cell + direction; E 0, N 1, NE 4):
/// A 0 -E-> 1 -NE-> 5 -N-> 8 (L 3), B 0 -NE-> 4 -NE-> 8 (L 2), C 0 -N-> 3 -E-> 4 -NE-> 8 (L 4).
fn three_tours() -> Tours {
    let mut t = Tours::default();
    t.push(&[0, 12, 41], 3.0);
    t.push(&[4, 36], 2.0);
    t.push(&[1, 24, 36], 4.0);
    t
}

/// Eqs. 4-6 by hand, rho = 0.85, Q = 6, tau = 1: (1 - rho) tau = 0.15, plus 0.85 sum Q/L_k.
#[test]
fn basic_update_is_eqs_4_to_6() {
    let g = grid3();
    assert_eq!((g.neighbour(0, 0), g.neighbour(1, 4), g.neighbour(5, 1), g.neighbour(4, 4)), (1, 5, 8, 8));
    let mut tau = vec![1.0; 72];
    update(&mut tau, &three_tours(), 0.85, 6.0, false);
    let close = |e: usize, v: f64| assert!((tau[e] - v).abs() < 1e-12, "edge {e}: {} vs {v}", tau[e]);
    for e in [0, 12, 41] {
        close(e, 0.15 + 0.85 * 2.0);
    }
    close(4, 0.15 + 0.85 * 3.0);
    close(36, 0.15 + 0.85 * (3.0 + 1.5)); // 3.975: B's and C's deposits
    for e in [1, 24] {
        close(e, 0.15 + 0.85 * 1.5);
    }
    let touched = [0, 1, 4, 12, 24, 36, 41];
    for e in (0..72).filter(|e| !touched.contains(e)) {
        close(e, 0.15);
    }
}

/// Eqs. 11-13 by hand: B is the best (L 2) and C the worst (L 4). The worst term takes back
/// exactly C's own deposit, so C's edges keep only what the others left.
#[test]
fn elite_update_is_eqs_11_to_13() {
    let mut tau = vec![1.0; 72];
    update(&mut tau, &three_tours(), 0.85, 6.0, true);
    let close = |e: usize, v: f64| assert!((tau[e] - v).abs() < 1e-12, "edge {e}: {} vs {v}", tau[e]);
    close(4, 0.15 + 0.85 * (3.0 + 3.0)); // 5.25
    close(36, 0.15 + 0.85 * (3.0 + 1.5 + 3.0 - 1.5)); // 5.25
    close(1, 0.15 + 0.85 * (1.5 - 1.5)); // 0.15
    close(24, 0.15);
    for e in [0, 12, 41] {
        close(e, 1.85);
    }
    close(2, 0.15);
    // One tour is both best and worst: its extra terms cancel.
    let mut one = Tours::default();
    one.push(&[4, 36], 2.0);
    let mut tau = vec![1.0; 72];
    update(&mut tau, &one, 0.85, 6.0, true);
    assert!((tau[4] - 2.7).abs() < 1e-12 && (tau[36] - 2.7).abs() < 1e-12);
}

/// The clamp [1e-3, 1e3]: evaporation alone stops at 1e-3, a huge deposit at 1e3.
#[test]
fn pheromone_is_clamped() {
    let mut tau = vec![2e-3; 72];
    update(&mut tau, &Tours::default(), 0.85, 6.0, true);
    assert!(tau.iter().all(|&t| t == TAU_MIN), "0.15 x 2e-3 = 3e-4 clamps to 1e-3");
    let mut tau = vec![1.0; 72];
    update(&mut tau, &three_tours(), 0.85, 6000.0, false);
    assert_eq!(tau[36], TAU_MAX); // 0.15 + 0.85 x 4500
    assert_eq!(tau[1], TAU_MAX); // 0.15 + 0.85 x 1500 = 1275.15
    assert_eq!(tau[0], TAU_MAX); // 0.15 + 0.85 x 2000 = 1700.15
    assert_eq!(tau[2], 1.0 - 0.85);
}

/// The heuristic at one cell of a 5 x 5 grid of unit cells, goal at (4.5, 4.5), one blocked
/// cell at (2.5, 3.5), for the move (1,2) -> (2,2) (east). L_g = 2 sqrt 2; printed
/// attraction 2 sqrt 2 + 1/(2 sqrt 2) toward (1, 1)/sqrt 2 = (2.25, 2.25); repulsion
/// mu/1 (1/1 - 1/2) = 5 toward -y; F = (2.25, -2.75), cos = 2.25/sqrt 12.625. Khatib:
/// F = (2, -3), cos = 2/sqrt 13. Waves 2 m of at most 4 m: X_wht = 0.5; current (0.3, -0.4) of
/// at most 1 m/s: X_hfr = 0.5, cos theta_hfr = 0.6; exponent 0.3 sin 0.5 + 0.7 x 0.5 x 0.6.
#[test]
fn heuristic_is_eqs_7_to_10_at_a_cell() {
    let f = Field {
        xi: 1.0,
        mu: 10.0,
        l0: 2.0,
        varsigma: 1.0,
        sigma: 1.0,
        omega: 1.0,
        a: 0.3,
        b: 0.7,
        attraction: Attraction::Printed,
    };
    let lg = 8f64.sqrt();
    assert!((heuristic::attraction(1.0, lg, Attraction::Printed) - (lg + 1.0 / lg)).abs() < 1e-15);
    assert_eq!(heuristic::attraction(2.0, lg, Attraction::Khatib), 2.0 * lg);
    assert_eq!(heuristic::repulsion(10.0, 1.0, 2.0), 5.0);
    assert_eq!(heuristic::repulsion(10.0, 2.0, 2.0), 0.0);
    assert_eq!(heuristic::repulsion(10.0, 2.5, 2.0), 0.0);
    let mut blocked = vec![false; 25];
    blocked[2 + 5 * 3] = true;
    let centre = |i: f64, j: f64| Vec3::new(i + 0.5, j + 0.5, 0.0);
    let g = Graph::new(5, 5, Vec3::ZERO, (1.0, 1.0), blocked, (0, 24), centre(0.0, 0.0), centre(4.0, 4.0));
    let mut world = world_2d(5.0, 5.0);
    world.waves = Waves::Uniform(2.0);
    world.current = Current::Uniform(Vec3::new(0.3, -0.4, 0.0));
    let env = Environment { world: &world, wave_max: 4.0, current_max: 1.0, a: 0.3, b: 0.7 };
    let x = 0.3 * 0.5f64.sin() + 0.7 * 0.5 * 0.6;
    let e = 8 * (1 + 5 * 2); // east out of (1, 2)
    let printed = 2.25 / 12.625f64.sqrt();
    let khatib = 2.0 / 13f64.sqrt();
    for (form, cos) in [(Attraction::Printed, printed), (Attraction::Khatib, khatib)] {
        let f = Field { attraction: form, ..f };
        let w = heuristic::weights(&g, 5.0, Some(&f), Some((&env, 0.0)), &|| false).unwrap();
        let want = (5.0 * (cos - lg.ln() + x)).exp();
        assert!((w[e] / want - 1.0).abs() < 1e-12, "{form:?}: {} vs {want}", w[e]);
        // Without the environment (a world changing in time: it comes in at the ant's clock).
        let w = heuristic::weights(&g, 5.0, Some(&f), None, &|| false).unwrap();
        assert!((w[e] / (5.0 * (cos - lg.ln())).exp() - 1.0).abs() < 1e-12);
    }
    assert!((printed - 0.633_237_790_257_262_7).abs() < 1e-15 && (x - 0.353_827_661_581_260_9).abs() < 1e-15);
    // The basic colony: (1/L)^beta; into the goal L is half a cell.
    let w = heuristic::weights(&g, 5.0, None, None, &|| false).unwrap();
    assert!((w[e] / lg.powi(-5) - 1.0).abs() < 1e-12);
    assert!((w[8 * 23] - 32.0).abs() < 1e-12, "{}", w[8 * 23]); // east into the goal: 0.5^-5
    assert_eq!(w[8 * (2 + 5 * 2) + 1], 0.0, "no move into the blocked cell");
    // Normalisation: heights and speeds above the maxima count as 1, gaps as 0.
    let (xw, xc) = Environment { wave_max: 1.0, current_max: 0.25, ..env }.sample(Vec3::ZERO, 0.0);
    assert_eq!((xw, xc.length()), (1.0, 1.0));
    assert_eq!(heuristic::cos_between(Vec2::ZERO, Vec2::X), 0.0);
}

/// p_k = w_k / sum w: hand-checked thresholds, then 200,000 draws within 0.005 of each p.
#[test]
fn roulette_draws_in_proportion() {
    let w = [1.0, 2.0, 3.0, 4.0];
    assert_eq!(roulette(&w, 10.0, 0.0), 0);
    assert_eq!(roulette(&w, 10.0, 0.0999), 0);
    assert_eq!(roulette(&w, 10.0, 0.1), 1);
    assert_eq!(roulette(&w, 10.0, 0.6), 3);
    assert_eq!(roulette(&w, 10.0, 0.999_999), 3);
    assert_eq!(roulette(&[0.0, 0.0], 0.0, 0.7), 1, "all zero: uniform");
    let mut rng = crate::rng::Rng::seed_from_u64(7);
    let mut n = [0usize; 4];
    let draws = 200_000;
    for _ in 0..draws {
        n[roulette(&w, 10.0, rand::Rng::random::<f64>(&mut rng))] += 1;
    }
    for k in 0..4 {
        let p = n[k] as f64 / draws as f64;
        assert!((p - w[k] / 10.0).abs() < 0.005, "{k}: {p}");
    }
}

/// A corridor of `n` unit cells in a row, from cell `start` to the last cell.
fn corridor(n: usize, start: usize) -> Graph {
    let c = |i: usize| Vec3::new(i as f64 + 0.5, 0.5, 0.0);
    Graph::new(n, 1, Vec3::ZERO, (1.0, 1.0), vec![false; n], (start, n - 1), c(start), c(n - 1))
}

const ANY_TURN: Kinematics = Kinematics { cos_turn: -1.0, tan_pitch: f64::INFINITY, radius: None, three_d: false };

/// A 3 x 1 corridor, the paper's ants (no lookahead) starting in the middle: west is a
/// cul-de-sac (a dead end: the tour is dropped, deposits nothing), east is the goal.
#[test]
fn dead_ends_are_discarded() {
    let g = corridor(3, 1);
    let colony = Colony { graph: &g, kinematics: ANY_TURN, alpha: 1.0, departure: 0.0, unit: 1.0 };
    let mut walker = Walker::new(3, false);
    let mut rng = crate::rng::Rng::seed_from_u64(3);
    let mut price = |a: usize, b: usize, _e: usize, t: f64| {
        let d = g.point(a).distance(g.point(b));
        Some((d, t + d))
    };
    let (mut weight, mut step) = (|_e: usize, _t: f64| 1.0, || None);
    let tau = vec![1.0; 24];
    let (mut tours, mut best) = (Tours::default(), (f64::INFINITY, Vec::new()));
    let dead = colony
        .iteration(200, &mut walker, &tau, &mut tours, &mut best, &mut weight, &mut price, &mut step, &mut rng)
        .unwrap();
    assert_eq!(dead + tours.len(), 200);
    assert!(dead > 70 && tours.len() > 70, "{dead} dead ends");
    assert_eq!(best, (1.0, vec![1, 2]));
    let mut tau = tau;
    update(&mut tau, &tours, 0.85, 6.0, false);
    assert_eq!(tau[8 + 2], 1.0 - 0.85, "the cul-de-sac's edge only evaporates");
    assert!((tau[8] - (0.15 + 0.85 * 6.0 * tours.len() as f64).min(TAU_MAX)).abs() < 1e-9);
    // A dead end ends where it stopped.
    let ends: Vec<TourEnd> = (0..50)
        .map(|_| walker.tour(&g, &tau, 1.0, &ANY_TURN, 0.0, &mut |_, _| 1.0, &mut price, &mut step, &mut rng))
        .collect();
    assert!(ends.contains(&TourEnd::DeadEnd) || walker.cells == vec![1, 2]);
    if walker.cells != vec![1, 2] {
        assert_eq!((walker.cells.clone(), walker.edges.clone()), (vec![1, 0], vec![8 + 2]));
    }
    // With the lookahead no ant enters the one-cell pocket; a pocket two cells deep still
    // traps it one cell in.
    let mut ahead = Walker::new(3, true);
    let d = Colony { graph: &g, ..colony }
        .iteration(100, &mut ahead, &tau, &mut tours, &mut best, &mut weight, &mut price, &mut step, &mut rng)
        .unwrap();
    assert_eq!((d, tours.len()), (0, 100));
    let g4 = corridor(4, 2);
    let mut ahead = Walker::new(4, true);
    let mut price4 = |a: usize, b: usize, _e: usize, t: f64| Some((1.0, t + f64::from(a.abs_diff(b) as u32)));
    let mut trapped = 0;
    for _ in 0..100 {
        let end = ahead.tour(&g4, &[1.0; 32], 1.0, &ANY_TURN, 0.0, &mut weight, &mut price4, &mut step, &mut rng);
        if end == TourEnd::DeadEnd {
            trapped += 1;
            assert_eq!(ahead.cells, vec![2, 1]);
        }
    }
    assert!(trapped > 20, "{trapped}");
}

/// A 2 km x 1 km sea with a wall across most of it: both colonies reach the goal, and every
/// segment of the path passes the shared validator (no blocked cell is entered); the path
/// keeps the vehicle's 60-degree turn limit.
#[test]
fn colonies_go_around_a_wall() {
    let mut w = world_2d(2000.0, 1000.0);
    wall(&mut w, (950.0, 0.0), (1050.0, 750.0));
    for max_turn in [PI, 60f64.to_radians()] {
        let m = Mission::new("m", vehicle(max_turn), Vec3::new(150.0, 150.0, 0.0), Vec3::new(1850.0, 150.0, 0.0), 0.0);
        for id in ["aco", "acopf"] {
            let plan = run(&mut colony(id, "cells = 40"), &w, &m, Termination::iterations(30), 5);
            assert_eq!(plan.status, Status::Feasible, "{id}: {}", plan.reason);
            let path = &plan.missions[0].waypoints;
            assert_eq!((path[0], *path.last().unwrap()), (m.start, m.goal));
            assert!(path.iter().any(|p| p.y > 750.0), "{id} passes the wall's end");
            let settings = ModelSettings::default();
            let model = PathModel::new(&w, &m, &settings);
            let mut t = 0.0;
            for s in path.windows(2) {
                let check = model.validator.motion(s[0], s[1], t);
                assert!(check.valid(), "{id}: {s:?}");
                t = check.arrival;
            }
            let m = plan.missions[0].metrics.as_ref().unwrap();
            assert!(m.max_turn_deg <= max_turn.to_degrees() + 1e-6, "{id}: {}", m.max_turn_deg);
            assert_eq!(plan.stats.iterations, 30);
            assert_eq!(plan.stats.history.len(), 30);
            assert!(plan.stats.history.windows(2).all(|h| h[1] <= h[0]));
            assert!((plan.stats.history[29] - plan.cost).abs() <= 1e-6 * plan.cost);
        }
    }
}

/// With the ants on length (the paper's Q/L) the history is still in the scenario's cost, as
/// every planner's is, so figures can set it beside other planners and a reference: its last
/// entry is the plan's cost, not the path's length.
#[test]
fn the_history_is_in_the_scenarios_cost_whatever_the_ants_reward() {
    let mut w = world_2d(2000.0, 1000.0);
    wall(&mut w, (950.0, 0.0), (1050.0, 750.0));
    let m = Mission::new("m", vehicle(PI), Vec3::new(150.0, 150.0, 0.0), Vec3::new(1850.0, 150.0, 0.0), 0.0);
    for id in ["aco", "acopf"] {
        let plan = run(&mut colony(id, "cells = 40\nobjective = \"length\""), &w, &m, Termination::iterations(20), 3);
        assert_eq!(plan.status, Status::Feasible, "{id}: {}", plan.reason);
        let last = *plan.stats.history.last().unwrap();
        assert!((last - plan.cost).abs() <= 1e-9 * plan.cost, "{id}: history ends at {last}, cost {}", plan.cost);
        let length = plan.missions[0].metrics.as_ref().unwrap().length_m;
        assert!((last - length).abs() > 1.0, "{id}: the history is not the length {length}");
    }
}

/// The same seed gives the same path bit for bit; the run's iteration limit replaces T.
#[test]
fn runs_are_deterministic() {
    let mut w = world_2d(2000.0, 1000.0);
    wall(&mut w, (950.0, 250.0), (1050.0, 1000.0));
    let m = Mission::new("m", vehicle(PI), Vec3::new(150.0, 850.0, 0.0), Vec3::new(1850.0, 850.0, 0.0), 0.0);
    let a = run(&mut colony("acopf", "cells = 40"), &w, &m, Termination::iterations(10), 9);
    let b = run(&mut colony("acopf", "cells = 40"), &w, &m, Termination::iterations(10), 9);
    assert_eq!(a.missions[0].waypoints, b.missions[0].waypoints);
    assert_eq!(a.stats.history, b.stats.history);
    assert_eq!(a.stats.expansions, b.stats.expansions);
    assert_eq!(a.stats.iterations, 10);
    // Without a run limit, T = `iterations`.
    let c = run(&mut colony("aco", "cells = 40\niterations = 4"), &w, &m, Termination::default(), 9);
    assert_eq!((c.stats.iterations, c.stats.stop_reason), (4, StopReason::MaxIterations));
}

/// In a world that changes in time (here only a disc moving far outside the domain) moves
/// are priced at every step and the environment factor is taken at the ant's clock: with
/// uniform waves and current both give what the precomputed tables give, so the same path.
#[test]
fn a_changing_world_is_priced_at_the_ants_clock() {
    let mut w = world_2d(2000.0, 1000.0);
    wall(&mut w, (950.0, 0.0), (1050.0, 700.0));
    w.waves = Waves::Uniform(1.5);
    w.current = Current::Uniform(Vec3::new(0.2, 0.1, 0.0));
    let m = Mission::new("m", vehicle(PI), Vec3::new(150.0, 150.0, 0.0), Vec3::new(1850.0, 150.0, 0.0), 0.0);
    let steady = run(&mut colony("acopf", "cells = 40"), &w, &m, Termination::iterations(8), 4);
    let far = Shape::Circle { center: Vec2::new(-5000.0, -5000.0), radius: 10.0 };
    w.obstacles.push(Obstacle::moving(far, Vec3::new(-1.0, 0.0, 0.0)));
    let moving = run(&mut colony("acopf", "cells = 40"), &w, &m, Termination::iterations(8), 4);
    assert_eq!(steady.status, Status::Feasible, "{}", steady.reason);
    assert_eq!(steady.missions[0].waypoints, moving.missions[0].waypoints);
    assert_eq!(steady.stats.expansions, moving.stats.expansions);
    // Every step priced anew, against each edge once.
    assert!(moving.stats.motion_checks >= moving.stats.expansions - 8 * 30);
    assert!(steady.stats.motion_checks <= steady.stats.graph_edges);
}

/// Budgets: a raised stop flag cancels before any step; an expansion limit bounds the ant
/// steps; a 3-D world is refused with one line.
#[test]
fn budgets_and_refusals() {
    let w = world_2d(1000.0, 1000.0);
    let m = Mission::new("m", vehicle(PI), Vec3::new(100.0, 100.0, 0.0), Vec3::new(900.0, 900.0, 0.0), 0.0);
    let flag = Arc::new(AtomicBool::new(true));
    let t = Termination::iterations(1000).with_stop_flag(flag);
    let plan = run(&mut colony("acopf", "cells = 20"), &w, &m, t, 1);
    assert_eq!(plan.stats.stop_reason, StopReason::Cancelled);
    assert_eq!((plan.stats.iterations, plan.stats.expansions), (0, 0));
    assert_eq!(plan.status, Status::Cancelled);
    let t = Termination { max_expansions: Some(50), ..Termination::iterations(1000) };
    let plan = run(&mut colony("aco", "cells = 20"), &w, &m, t, 1);
    assert_eq!((plan.stats.expansions, plan.stats.stop_reason), (50, StopReason::MaxExpansions));
    // 3-D.
    let mut w3 = world_2d(1000.0, 1000.0);
    w3.dims = Dims::Three;
    w3.bounds.min.z = -100.0;
    let settings = ModelSettings::default();
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let missions = [m.clone()];
    let problem =
        Problem { world: &w3, settings: &settings, cost: &cost, missions: &missions, fleet: &crate::fleet::NO_FLEET };
    let e = colony("acopf", "").check(&problem).unwrap_err().to_string();
    assert_eq!(e, "planner: acopf plans 2-D worlds only (world.dimensions = 2)");
    let e = colony("aco", "cell = 0.5").check(&Problem { world: &w, ..problem }).unwrap_err().to_string();
    assert!(e.starts_with("planner.params.aco: 2000 x 2000 cells exceed"), "{e}");
}

/// A goal walled in on the raster: no route, said without running the colony.
#[test]
fn a_disconnected_raster_is_no_route() {
    let c = |i: f64, j: f64| Vec3::new(i + 0.5, j + 0.5, 0.0);
    let mut blocked = vec![false; 9];
    for k in [2, 5, 6, 7] {
        blocked[k] = true;
    }
    let g = Graph::new(3, 3, Vec3::ZERO, (1.0, 1.0), blocked, (0, 8), c(0.0, 0.0), c(2.0, 2.0));
    assert_eq!(g.connected(&|| false), Some(false));
    // From the centre: west, south and south-west; not north-west past the blocked north.
    assert_eq!(g.masks[4], 0b0100_1100);
    assert_eq!(grid3().connected(&|| false), Some(true));
}

/// A warm start seeds tau_max on the edges between the cells it passes; the history tells
/// the iteration of convergence.
#[test]
fn warm_start_and_convergence() {
    let g = grid3();
    let mut tau = vec![1.0; 72];
    let n =
        seed_pheromone(&g, &mut tau, &[Vec3::new(0.5, 0.5, 0.0), Vec3::new(2.5, 0.5, 0.0), Vec3::new(2.5, 2.5, 0.0)]);
    assert_eq!(n, 4);
    for e in [0, 8, 8 * 2 + 1, 8 * 5 + 1] {
        assert_eq!(tau[e], TAU_MAX, "edge {e}");
    }
    assert_eq!(tau.iter().filter(|&&t| t == TAU_MAX).count(), 4);
    assert_eq!(iterations_to_converge(&[f64::INFINITY, 5.0, 4.0, 4.0]), Some(3));
    assert_eq!(iterations_to_converge(&[f64::INFINITY; 2]), None);
    assert_eq!(iterations_to_converge(&[]), None);
}

/// Rough timing of acopf (T = 60, K = 30) on open 20 x 20 and 200 x 200 rasters:
/// `cargo test --release -p tidepath acopf_timing -- --ignored --nocapture`.
#[test]
#[ignore]
fn acopf_timing() {
    let mut w = world_2d(20000.0, 20000.0);
    wall(&mut w, (9000.0, 0.0), (11000.0, 14000.0));
    w.waves = Waves::Uniform(2.0);
    let m = Mission::new("m", vehicle(PI), Vec3::new(500.0, 500.0, 0.0), Vec3::new(19500.0, 19500.0, 0.0), 0.0);
    // Then in a world that changes in time (a disc moving far away): every step priced.
    for changing in [false, true] {
        if changing {
            let far = Shape::Circle { center: Vec2::new(-5000.0, -5000.0), radius: 10.0 };
            w.obstacles.push(Obstacle::moving(far, Vec3::new(-1.0, 0.0, 0.0)));
        }
        for cells in [20, 200] {
            let t = std::time::Instant::now();
            let plan = run(&mut colony("acopf", &format!("cells = {cells}")), &w, &m, Termination::iterations(60), 1);
            eprintln!(
                "{cells} x {cells} (changing {changing}): {:?}, {} steps, {} priced, {}",
                t.elapsed(),
                plan.stats.expansions,
                plan.stats.motion_checks,
                plan.status
            );
        }
    }
}
