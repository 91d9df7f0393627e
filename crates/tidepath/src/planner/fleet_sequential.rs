//! Planning a fleet one vehicle after another (prioritized planning): each vehicle is planned
//! by the chosen planner alone, with the vehicles planned before it in the world as moving
//! obstacles. A planner that checks moving obstacles at the vehicle's clock (time-dependent
//! A*, Theta*, RRT*, the optimizers) thus keeps the fleet's separation without fleet code.
//!
//! * **Traffic.** An earlier vehicle becomes one obstacle per leg of its timed path (legs of
//!   constant ground speed, [`crate::fleet::timed_legs`]), each present only during its leg
//!   (an obstacle time window), a disc in 2-D or a ball in 3-D of radius `separation -
//!   safety` (the later vehicle's safety distance is the margin every obstacle gets, so the
//!   centres stay `separation` apart). With `presence = stays` the earlier vehicle also waits
//!   at its start before departing and at its goal after arriving.
//! * **Priority.** The longest transit (start to goal, straight) first: it has the fewest
//!   ways around the others; ties by scenario order. When a vehicle cannot be planned, it
//!   moves to the front and the fleet is planned again, at most once per vehicle.
//! * **Budgets.** Each vehicle gets the run's count limits; the wall-time limit and the stop
//!   flag are the whole run's (one clock).

use super::solve::{judge, solve, MissionPlan, Plan, SolveOptions};
use super::{Planner, Problem, SearchStats, Status};
use crate::error::Result;
use crate::fleet::{timed_legs, FleetRules, Presence, NO_FLEET};
use crate::geom::{Vec2, Vec3};
use crate::optim::Progress;
use crate::path::PathModel;
use crate::rng::Rng;
use crate::termination::Termination;
use crate::world::{Dims, Obstacle, Shape, World};

/// Least radius of a traffic obstacle (m), when the separation is not above the safety
/// distance: the vehicles must then only not touch.
const MIN_TRAFFIC_RADIUS: f64 = 1e-3;

/// How `solve` plans several missions.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FleetMode {
    /// As the planner does (jointly or one after another, each alone).
    #[default]
    AsPlanner,
    /// One after another, each around the vehicles planned before it.
    Sequential,
}

/// The default priority order: longest straight transit first, ties by index.
pub fn priority(problem: &Problem<'_>) -> Vec<usize> {
    let mut order: Vec<usize> = (0..problem.missions.len()).collect();
    let length = |i: usize| problem.missions[i].start.distance(problem.missions[i].goal);
    order.sort_by(|&a, &b| length(b).total_cmp(&length(a)).then(a.cmp(&b)));
    order
}

/// The obstacles vehicle `j` (flying `path` with `model`) is for vehicle `k`.
fn traffic(
    model: &PathModel<'_>,
    path: &[Vec3],
    rules: &FleetRules,
    j: usize,
    k: usize,
    safety: f64,
    dims: Dims,
) -> Vec<Obstacle> {
    let radius = (rules.separation(j, k) - safety).max(MIN_TRAFFIC_RADIUS);
    let shape = |c: Vec3| match dims {
        Dims::Two => Shape::Circle { center: Vec2::new(c.x, c.y), radius },
        Dims::Three => Shape::Sphere { center: c, radius },
    };
    let mut legs = Vec::new();
    timed_legs(model, path, &mut legs);
    let mut out = Vec::with_capacity(legs.len() + 2);
    let (Some(first), Some(last)) = (legs.first().copied(), legs.last().copied()) else { return out };
    if rules.presence == Presence::Stays {
        out.push(Obstacle { shape: shape(first.0), velocity: Vec3::ZERO, window: Some((f64::NEG_INFINITY, first.2)) });
        out.push(Obstacle { shape: shape(last.1), velocity: Vec3::ZERO, window: Some((last.3, f64::INFINITY)) });
    }
    for (p0, p1, t0, t1) in legs {
        if t1 > t0 {
            // Placed at time 0 so that it is at p0 at t0.
            let v = (p1 - p0) / (t1 - t0);
            out.push(Obstacle { shape: shape(p0 - v * t0), velocity: v, window: Some((t0, t1)) });
        }
    }
    out
}

fn add_stats(total: &mut SearchStats, s: &SearchStats) {
    total.iterations += s.iterations;
    total.evaluations += s.evaluations;
    total.expansions += s.expansions;
    total.samples += s.samples;
    total.state_checks += s.state_checks;
    total.motion_checks += s.motion_checks;
    total.graph_nodes += s.graph_nodes;
    total.graph_edges += s.graph_edges;
    total.history.extend_from_slice(&s.history);
    total.stop_reason = s.stop_reason;
    total.elapsed += s.elapsed;
}

/// Plans the missions of `problem` one after another (see the module's notes), then judges
/// them together on the problem's own world, separation included.
pub(super) fn solve_sequential(
    planner: &mut dyn Planner,
    problem: &Problem<'_>,
    termination: &Termination,
    rng: &mut Rng,
    options: SolveOptions<'_>,
    observer: &mut dyn FnMut(&Progress),
) -> Result<Plan> {
    termination.check()?;
    let termination = &termination.started_now();
    let n = problem.missions.len();
    let models: Vec<PathModel<'_>> = (0..n).map(|i| problem.path_model(i)).collect();
    let inner = SolveOptions { fleet: FleetMode::AsPlanner, ..options };
    let mut order = priority(problem);
    let mut stats = SearchStats::default();
    let mut graphs = Vec::new();
    let mut results: Vec<Option<MissionPlan>>;
    let mut tried: Vec<Vec<usize>> = Vec::new();
    loop {
        results = vec![None; n];
        let mut failed = None;
        for (rank, &k) in order.iter().enumerate() {
            if termination.interrupted().is_some() {
                break;
            }
            let mut world: World = problem.world.clone();
            for &j in &order[..rank] {
                if let Some(m) = &results[j] {
                    let safety = problem.missions[k].vehicle.safety_distance;
                    let flown = models[j].with_speeds(m.speeds.as_deref());
                    world.obstacles.extend(traffic(&flown, m.path(), problem.fleet, j, k, safety, world.dims));
                }
            }
            let one = [problem.missions[k].clone()];
            let sub = Problem { world: &world, missions: &one, fleet: &NO_FLEET, ..*problem };
            let init = options.run.init.map(|all| vec![all.get(k).cloned().unwrap_or_default()]);
            let run = super::RunOptions { init: init.as_deref(), ..inner.run };
            let plan = solve(planner, &sub, termination, rng, SolveOptions { run, ..inner }, observer)?;
            add_stats(&mut stats, &plan.stats);
            graphs.extend(plan.graphs.into_iter().map(|mut g| {
                g.mission = k;
                g
            }));
            let m = plan.missions.into_iter().next().expect("one mission");
            let ok = m.status.is_success();
            results[k] = Some(m);
            if !ok {
                failed = Some(k);
                break;
            }
        }
        tried.push(order.clone());
        let Some(k) = failed else { break };
        let mut next = order.clone();
        next.retain(|&x| x != k);
        next.insert(0, k);
        if tried.contains(&next) || tried.len() >= n || termination.interrupted().is_some() {
            break;
        }
        order = next;
    }
    // Judged together on the problem's own world; the vehicles' own reasons for any that failed.
    let mut missions: Vec<MissionPlan> = Vec::with_capacity(n);
    for (i, r) in results.into_iter().enumerate() {
        let name = &problem.missions[i].name;
        missions.push(match r {
            Some(m) if m.status.is_success() => {
                let mut j = judge(&models[i].with_speeds(m.speeds.as_deref()), problem.cost, m.path(), name);
                if m.smoothed.is_some() {
                    (j.waypoints, j.smoothed, j.raw_cost) = (m.waypoints.clone(), m.smoothed.clone(), m.raw_cost);
                }
                if j.feasible {
                    j.reason = format!(
                        "no constraint violated; planned after the vehicles before it in the order {}",
                        names(problem, &order)
                    );
                }
                j
            }
            Some(m) => m,
            None => {
                let reason = format!(
                    "not planned: planning one after another (order {}) stopped before it",
                    names(problem, &order)
                );
                MissionPlan::unplanned(name, Status::Infeasible, reason)
            }
        });
    }
    let fleet = super::fleet_judge::judge_fleet(&models, &mut missions, problem.fleet);
    for m in &mut missions {
        if !m.feasible && m.status.is_success() {
            m.status = Status::Infeasible;
        }
    }
    // The missions' costs plus the fleet's terms: what a joint optimizer minimised.
    let cost = missions.iter().map(|m| m.cost).sum::<f64>() + fleet.as_ref().map_or(0.0, |f| f.penalty());
    let (status, reason) = super::solve::overall(&missions);
    Ok(Plan { planner: planner.id().to_string(), status, reason, missions, cost, stats, graphs, fleet })
}

fn names(problem: &Problem<'_>, order: &[usize]) -> String {
    order.iter().map(|&i| problem.missions[i].name.as_str()).collect::<Vec<_>>().join(", ")
}
