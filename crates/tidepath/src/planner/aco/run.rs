//! One mission's colony (acopf2016 steps 1-9): the graph and its tables once, then T
//! iterations of K tours and a pheromone update each, keeping the cheapest tour found.

use super::colony::{Colony, Graph, Walker};
use super::heuristic::{self, Environment};
use super::pheromone::{self, Tours};
use super::{current_speed_bound, time_invariant, Kinematics, Objective, RasterSearch};
use super::{seed_pheromone, simplify, AntColony};
use crate::geom::Vec3;
use crate::planner::{PlannerOutput, Problem};
use crate::rng::Rng;
use crate::termination::{StopReason, Termination};

/// One mission's share of the run: its termination (wall time, stop flag), iterations, ant
/// steps left (expansions) and the run's target cost.
pub struct Budget<'t> {
    pub termination: &'t Termination,
    pub iterations: u64,
    pub steps: Option<u64>,
    pub target: Option<f64>,
}

/// What one mission's colony gave.
pub struct MissionRun {
    /// Start, turning points, goal; empty without a tour to the goal.
    pub path: Vec<Vec3>,
    /// Its summed price (+inf without one).
    pub best: f64,
    pub stopped: Option<StopReason>,
    /// Why no route was found, when the colony ran its course without one.
    pub no_route: Option<String>,
}

impl MissionRun {
    fn empty(stopped: Option<StopReason>, no_route: Option<String>) -> Self {
        Self { path: Vec::new(), best: f64::INFINITY, stopped, no_route }
    }
}

/// Runs the colony on mission `i` within `budget`, adding its counts to `out.stats` and the
/// best cost after each iteration (plus `earlier`) to the history; `report(out, best)` after
/// each iteration.
#[allow(clippy::too_many_arguments)]
pub fn mission(
    colony: &AntColony,
    problem: &Problem<'_>,
    i: usize,
    budget: &Budget<'_>,
    init: Option<&[Vec3]>,
    rng: &mut Rng,
    out: &mut PlannerOutput,
    earlier: f64,
    report: &mut dyn FnMut(&PlannerOutput, f64),
) -> MissionRun {
    let s = &colony.s;
    let (world, m) = (problem.world, &problem.missions[i]);
    let term = budget.termination;
    let stopped = || term.interrupted().or(Some(StopReason::WallTime));
    let stop = || term.interrupted().is_some();
    let rs = match RasterSearch::new(problem, i, colony.cell_size(world), 1.0, s.objective, term) {
        Ok(Some(rs)) if !rs.raster.three_d => rs,
        Ok(Some(_)) => return MissionRun::empty(None, Some(format!("{} plans 2-D worlds only", colony.id))),
        Ok(None) => return MissionRun::empty(stopped(), None),
        Err(e) => return MissionRun::empty(None, Some(e.to_string())),
    };
    let g = Graph::of(&rs);
    out.stats.state_checks += g.len() as u64;
    out.stats.graph_nodes += g.masks.iter().filter(|&&k| k != 0).count() as u64;
    out.stats.graph_edges += g.edge_count();
    let space = format!("the 8-connected {} x {} raster", g.nx, g.ny);
    if g.start == g.goal {
        let cost = rs.price(g.start, g.goal, m.departure_time).map_or(f64::INFINITY, |(c, _)| c);
        return MissionRun { path: vec![g.start_point, g.goal_point], best: cost, stopped: None, no_route: None };
    }
    match g.connected(&stop) {
        None => return MissionRun::empty(stopped(), None),
        Some(false) => {
            let why = format!("no route on {space} (its free cells do not connect start and goal)");
            return MissionRun::empty(None, Some(why));
        }
        Some(true) => {}
    }
    // The environment's maxima (acopf2016 A6) and the least price of one cell (L in cells).
    let bound = current_speed_bound(world);
    let current_max = match bound {
        Some(b) => b,
        None => match world.current.max_speed_hint_within(&world.bounds, m.departure_time, &stop) {
            Some(h) => h,
            None => return MissionRun::empty(stopped(), None),
        },
    };
    let wave_max = world.waves.height_bound();
    let steady = time_invariant(world) && world.waves.is_steady();
    let env = s.field.map(|f| Environment { world, wave_max, current_max, a: f.a, b: f.b });
    let fixed_env = env.as_ref().filter(|_| steady).map(|e| (e, m.departure_time));
    let Some(weights) = heuristic::weights(&g, s.beta, s.field.as_ref(), fixed_env, &stop) else {
        return MissionRun::empty(stopped(), None);
    };
    let unit = {
        let best_speed =
            m.vehicle.best_ground_speed(wave_max, if bound.is_some() { current_max } else { 1.5 * current_max });
        let u = match s.objective {
            Objective::Length => g.unit(),
            Objective::Time => g.unit() / best_speed,
            Objective::Cost => problem.cost.motion_lower_bound(&problem.path_model(i), g.unit(), best_speed),
        };
        if u > 0.0 && u.is_finite() {
            u
        } else {
            1.0
        }
    };
    let mut tau = vec![s.tau0; 8 * g.len()];
    if let Some(path) = init {
        seed_pheromone(&g, &mut tau, path);
    }
    // The environment factor at the ant's clock, where the world changes in time.
    let moving_env = env.filter(|_| !steady);
    let env_gain = s.field.map_or(0.0, |f| s.beta * f.omega);
    let mut weight = |e: usize, t: f64| match &moving_env {
        None => weights[e],
        Some(env) => {
            let (a, b) = (e / 8, g.neighbour(e / 8, e % 8));
            let pb = g.point(b);
            let x = env.exponent(env.sample(pb, t), (pb - g.point(a)).truncate());
            weights[e] * (env_gain * x).exp()
        }
    };
    // Prices: kept per edge where they do not depend on the clock (NaN: not priced yet).
    let (mut cached, mut durations) =
        if steady { (vec![f64::NAN; 8 * g.len()], vec![0.0; 8 * g.len()]) } else { (Vec::new(), Vec::new()) };
    let mut checks = 0u64;
    let mut price = |a: usize, b: usize, e: usize, t: f64| {
        if steady && !cached[e].is_nan() {
            return cached[e].is_finite().then(|| (cached[e], t + durations[e]));
        }
        checks += 1;
        let r = rs.price(a, b, t);
        if steady {
            cached[e] = r.map_or(f64::INFINITY, |(c, _)| c);
            durations[e] = r.map_or(0.0, |(_, arrival)| arrival - t);
        }
        r
    };
    let mut steps = 0u64;
    let mut step = || {
        if budget.steps.is_some_and(|max| steps >= max) {
            return Some(StopReason::MaxExpansions);
        }
        steps += 1;
        term.interrupted()
    };
    let colony_of = Colony {
        graph: &g,
        kinematics: Kinematics::of(&m.vehicle, false),
        alpha: s.alpha,
        departure: m.departure_time,
        unit,
    };
    let mut walker = Walker::new(g.len(), s.lookahead);
    let mut tours = Tours::default();
    let mut best = (f64::INFINITY, Vec::new());
    // The history is in the scenario's cost, as every planner's is (figures draw it against
    // other planners and the reference): with the ants on length or time, the best tour's path
    // is priced by the cost model each time it changes.
    let model = problem.path_model(i);
    let mut scratch = crate::scratch::Scratch::default();
    let (mut shown, mut shown_for) = (f64::INFINITY, f64::INFINITY);
    let (mut stopped_by, mut done) = (None, 0u64);
    while done < budget.iterations {
        if let Some(r) = term.interrupted() {
            stopped_by = Some(r);
            break;
        }
        if budget.target.is_some_and(|t| earlier + best.0 <= t) {
            stopped_by = Some(StopReason::TargetCost);
            break;
        }
        let r = colony_of.iteration(
            s.ants,
            &mut walker,
            &tau,
            &mut tours,
            &mut best,
            &mut weight,
            &mut price,
            &mut step,
            rng,
        );
        if let Err(r) = r {
            stopped_by = Some(r);
            break;
        }
        pheromone::update(&mut tau, &tours, s.rho, s.q, colony.improved());
        done += 1;
        out.stats.iterations += 1;
        if best.0 != shown_for {
            shown_for = best.0;
            shown = match s.objective {
                Objective::Cost => best.0,
                _ => {
                    let points = simplify(best.1.iter().map(|&c| g.point(c)).collect());
                    problem.cost.cost(&model, &points, &mut scratch)
                }
            };
        }
        out.stats.history.push(earlier + shown);
        report(out, best.0);
    }
    out.stats.expansions += steps;
    out.stats.motion_checks += checks;
    if best.0.is_finite() {
        let path = simplify(best.1.iter().map(|&c| g.point(c)).collect());
        return MissionRun { path, best: best.0, stopped: stopped_by, no_route: None };
    }
    let no_route = stopped_by.is_none().then(|| {
        format!("no ant of {} reached the goal on {space} in {done} iterations of {} ants", colony.id, s.ants)
    });
    MissionRun::empty(stopped_by, no_route)
}
