//! The one way every planner is run: check the termination, the planner's settings and the
//! missions' start and goal; plan; smooth; judge every path with the shared evaluation; set
//! the status from those direct checks.

use super::reachability::{self, Bottleneck, Reachability};
use super::{Claim, Planner, Problem, RunOptions, SearchGraph, SearchStats, Status};
use crate::error::Result;
use crate::geom::Vec3;
use crate::mission::Mission;
use crate::optim::Progress;
use crate::path::{Flown, Metrics, PathModel, Violation};
use crate::rng::Rng;
use crate::smoothing::Smoother;
use crate::termination::{StopReason, Termination};

#[derive(Clone, Copy, Default)]
pub struct SolveOptions<'a> {
    pub run: RunOptions<'a>,
    /// Every path goes through it before it is judged.
    pub smoother: Option<&'a dyn Smoother>,
    /// How a fleet is planned (`--fleet sequential`).
    pub fleet: super::fleet_sequential::FleetMode,
}

/// One mission's path, judged.
#[derive(Clone, Debug, PartialEq)]
pub struct MissionPlan {
    pub name: String,
    /// The planner's path, start and goal included (empty when nothing was planned).
    pub waypoints: Vec<Vec3>,
    /// The path after the smoother, when one ran; everything below then describes it.
    pub smoothed: Option<Vec<Vec3>>,
    /// Cost of `waypoints` before smoothing, when a smoother ran.
    pub raw_cost: Option<f64>,
    /// Arrival time at each point of the final path (s on the scenario clock); with a turning
    /// radius, at an interior waypoint the time halfway round its turn.
    pub times: Vec<f64>,
    /// The through-water speed of each segment of the final path (m/s), for a vehicle with a
    /// speed range; `None` when every segment is flown at the cruise speed.
    pub speeds: Option<Vec<f64>>,
    /// With a turning radius: the curve the vehicle flies along the final path (fillets at
    /// its waypoints), sampled where the evaluation checked it, with arrival times.
    pub flown: Option<Flown>,
    pub cost: f64,
    pub terms: Vec<(&'static str, f64)>,
    pub feasible: bool,
    pub violations: Vec<Violation>,
    pub metrics: Option<Metrics>,
    /// This mission's own status and its one-line reason.
    pub status: Status,
    pub reason: String,
    /// When the final path stops short of the goal (a planner that ran out of time on the
    /// way), the straight distance left from its last point to the goal (m).
    pub goal_distance_m: Option<f64>,
    /// The place a failure is about, for figures and messages: the start or goal that is
    /// invalid, or the bottleneck of the reachability check (where the deepest water any route
    /// must cross is too shallow, or where a passage narrower than the raster may exist).
    pub focus: Option<Focus>,
}

/// A marked place: where a mission's failure is, and a short label for it.
#[derive(Clone, Debug, PartialEq)]
pub struct Focus {
    pub at: Vec3,
    pub label: String,
}

impl MissionPlan {
    /// The final path: smoothed when a smoother ran.
    pub fn path(&self) -> &[Vec3] {
        self.smoothed.as_deref().unwrap_or(&self.waypoints)
    }

    pub(super) fn unplanned(name: &str, status: Status, reason: String) -> Self {
        Self {
            status,
            reason,
            goal_distance_m: None,
            focus: None,
            name: name.to_string(),
            waypoints: Vec::new(),
            smoothed: None,
            raw_cost: None,
            times: Vec::new(),
            speeds: None,
            flown: None,
            cost: f64::INFINITY,
            terms: Vec::new(),
            feasible: false,
            violations: Vec::new(),
            metrics: None,
        }
    }
}

/// A plan: one judged path per mission, the status with a one-line reason, and the search
/// statistics.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    pub planner: String,
    pub status: Status,
    pub reason: String,
    pub missions: Vec<MissionPlan>,
    /// Sum of the missions' costs.
    pub cost: f64,
    pub stats: SearchStats,
    /// The search graphs the planner kept ([`RunOptions::record_graph`]), each naming its
    /// mission by its index in the problem.
    pub graphs: Vec<SearchGraph>,
    /// The fleet's closest pair and separation conflicts, when the problem has a separation
    /// to keep.
    pub fleet: Option<crate::fleet::FleetCheck>,
}

impl Plan {
    pub fn feasible(&self) -> bool {
        self.status.is_success()
    }
}

/// Cost, terms, violations, metrics and arrival times of one path of one mission, flown at
/// `model`'s segment speeds.
pub fn judge(model: &PathModel<'_>, cost: &dyn crate::cost::CostModel, points: &[Vec3], name: &str) -> MissionPlan {
    let (total, terms) = cost.breakdown(model, points);
    let violations = model.violations(points);
    let mut times = Vec::with_capacity(points.len());
    model.assess(points, &mut times);
    MissionPlan {
        name: name.to_string(),
        waypoints: points.to_vec(),
        smoothed: None,
        raw_cost: None,
        times,
        speeds: model.speeds.map(|_| (0..points.len().saturating_sub(1)).map(|i| model.segment_speed(i)).collect()),
        flown: model.flown(points),
        cost: total,
        terms,
        feasible: violations.is_empty(),
        status: if violations.is_empty() { Status::Feasible } else { Status::Infeasible },
        reason: violations.first().map_or_else(|| "no constraint violated".to_string(), |v| v.message.clone()),
        goal_distance_m: points.last().map(|p| p.distance(model.goal)).filter(|&d| d > 0.0),
        focus: None,
        violations,
        metrics: Some(model.metrics(points)),
    }
}

/// The field a mission's start or goal comes from, for messages.
pub fn mission_field(problem: &Problem<'_>, i: usize, what: &str) -> String {
    if problem.missions.len() == 1 {
        format!("mission.{what}")
    } else {
        format!("missions[{i}].{what}")
    }
}

/// Runs `planner` on `problem` and judges the result. Errors are bad input (termination,
/// planner settings); everything the planning finds is in the plan's status.
///
/// Each mission gets its own status: a mission whose start or goal is invalid, or whose goal
/// is provably unreachable, is reported so and left out; the planner plans the others (jointly
/// when it plans fleets jointly). The plan's status is the worst of its missions', and its
/// reason names that mission.
pub fn solve(
    planner: &mut dyn Planner,
    problem: &Problem<'_>,
    termination: &Termination,
    rng: &mut Rng,
    options: SolveOptions<'_>,
    observer: &mut dyn FnMut(&Progress),
) -> Result<Plan> {
    if options.fleet == super::fleet_sequential::FleetMode::Sequential && problem.missions.len() > 1 {
        return super::fleet_sequential::solve_sequential(planner, problem, termination, rng, options, observer);
    }
    termination.check()?;
    // The run's one clock starts here: every stage below draws on the same deadline.
    let termination = &termination.started_now();
    let id = planner.id().to_string();
    let n = problem.missions.len();
    let models: Vec<PathModel<'_>> = (0..n).map(|i| problem.path_model(i)).collect();
    // Missions that cannot be planned, with their status, reason and the place it is about.
    let mut refused: Vec<Option<(Status, String, Option<Focus>)>> = vec![None; n];
    let focus = |at: Vec3, label: &str| Some(Focus { at, label: label.to_string() });
    for (i, (m, model)) in problem.missions.iter().zip(&models).enumerate() {
        if let Err(issue) = model.validator.state(m.start, m.departure_time) {
            let why = model.validator.describe(m.start, issue);
            let reason = format!("{}: {why}", mission_field(problem, i, "start"));
            refused[i] = Some((Status::InvalidStart, reason, focus(m.start, "invalid start")));
        } else if let Err(issue) = model.validator.fixed_state(m.goal) {
            let why = model.validator.describe(m.goal, issue);
            let reason = format!("{}: {why}", mission_field(problem, i, "goal"));
            refused[i] = Some((Status::InvalidGoal, reason, focus(m.goal, "invalid goal")));
        }
    }
    for (i, r) in refused.iter_mut().enumerate() {
        if r.is_none() {
            if let Reachability::Unreachable { reason, at } = reachability::check(problem, i, termination) {
                *r = Some((Status::Unreachable, reason, at.and_then(|a| focus(a, "bottleneck"))));
            }
        }
    }
    let planned: Vec<usize> = (0..n).filter(|&i| refused[i].is_none()).collect();
    let mut stats = SearchStats::default();
    let mut graphs = Vec::new();
    let mut missions: Vec<MissionPlan> = problem
        .missions
        .iter()
        .zip(&refused)
        .map(|(m, r)| {
            let (status, reason, focus) =
                r.clone().unwrap_or((Status::Infeasible, "the planner returned no path".into(), None));
            MissionPlan { focus, ..MissionPlan::unplanned(&m.name, status, reason) }
        })
        .collect();
    let mut claim = None;
    if !planned.is_empty() {
        // The planner sees only the missions it can plan, in their order.
        let subset: Vec<Mission> = planned.iter().map(|&i| problem.missions[i].clone()).collect();
        let sub_fleet = problem.fleet.subset(&planned);
        let sub = Problem { missions: &subset, fleet: &sub_fleet, ..*problem };
        // Whether this planner takes this problem (a setting, or a world it does not cover).
        planner.check(&sub)?;
        let init: Option<Vec<Vec<Vec3>>> =
            options.run.init.map(|all| planned.iter().map(|&i| all.get(i).cloned().unwrap_or_default()).collect());
        let run = RunOptions { init: init.as_deref(), ..options.run };
        let mut out = planner.plan(&sub, termination, rng, run, observer);
        for (k, &i) in planned.iter().enumerate() {
            let m = &problem.missions[i];
            if let Some(Claim::Unreachable(reason)) = &out.claim {
                missions[i] = MissionPlan::unplanned(&m.name, Status::Unreachable, reason.clone());
                continue;
            }
            let raw = out.paths.get(k).cloned().unwrap_or_default();
            if raw.len() < 2 {
                continue;
            }
            // The planner's speeds, else the cheapest speed level per segment (vehicles with a
            // speed range only).
            let speeds = match out.speeds.get_mut(k).and_then(Option::take) {
                Some(s) if m.vehicle.speed_range.is_some() => Some(s),
                _ => crate::cost::edge_speeds(problem.cost, &models[i], &raw),
            };
            let model = &models[i].with_speeds(speeds.as_deref());
            missions[i] = match options.smoother {
                None => judge(model, problem.cost, &raw, &m.name),
                Some(s) => {
                    let smoothed = s.smooth(model, problem.cost, &raw, termination);
                    // A smoother cut by the clock or the stop flag is what stopped the run.
                    if let (Some(r), false) = (termination.interrupted(), is_interruption(out.stats.stop_reason)) {
                        out.stats.stop_reason = r;
                    }
                    let raw_cost = problem.cost.breakdown(model, &raw).0;
                    // The speeds follow the route onto the smoothed path.
                    let moved = speeds.as_deref().map(|v| crate::path::resample_speeds(&raw, v, &smoothed));
                    let model = &models[i].with_speeds(moved.as_deref());
                    let mut j = judge(model, problem.cost, &smoothed, &m.name);
                    j.waypoints = raw;
                    j.smoothed = Some(smoothed);
                    j.raw_cost = Some(raw_cost);
                    j
                }
            };
        }
        stats = out.stats;
        claim = out.claim;
        // The planner numbered its missions within the subset it saw.
        graphs = out.graphs;
        for g in &mut graphs {
            g.mission = planned.get(g.mission).copied().unwrap_or(g.mission);
        }
    }
    // The fleet's separation, on the vehicles' own clocks: a conflict makes both infeasible.
    let fleet = super::fleet_judge::judge_fleet(&models, &mut missions, problem.fleet);
    // Each planned mission's status from its own direct checks and why the run stopped.
    for (k, &i) in planned.iter().enumerate() {
        let m = &mut missions[i];
        if matches!(m.status, Status::Unreachable) {
            continue;
        }
        let no_route = match &claim {
            Some(Claim::NoRoute(v)) => v.get(k).cloned().flatten(),
            _ => None,
        };
        let left = m.goal_distance_m.map_or(String::new(), |d| format!("; it stops {d:.1} m short of the goal"));
        (m.status, m.reason) = if m.feasible {
            match &claim {
                // A search over polylines is optimal for the polyline; a vehicle with a turning
                // radius flies another curve (its fillets), whose cost the search never saw.
                Some(Claim::Optimal { space, .. }) if problem.missions[i].vehicle.turn_radius.is_some() => (
                    Status::Feasible,
                    format!(
                        "no constraint violated; the search's optimum {space} is a polyline, and this vehicle flies it with turns of radius {} m, so no optimality is claimed",
                        problem.missions[i].vehicle.turn_radius.unwrap_or_default()
                    ),
                ),
                Some(Claim::Optimal { space, scenario_cost: true, .. }) => {
                    (Status::Exact, optimal_reason(problem.cost, "the scenario's cost model", space))
                }
                Some(Claim::Optimal { space, objective, .. }) => (
                    Status::Feasible,
                    format!(
                        "no constraint violated; optimal for {objective} {space}, not for the scenario's cost model"
                    ),
                ),
                _ => (Status::Feasible, "no constraint violated".to_string()),
            }
        } else {
            let mut first = first_problem(m);
            let mut hint = match &claim {
                Some(Claim::Hint(h)) => format!("; {h}"),
                _ => String::new(),
            };
            // No route found by a search that is not a proof: say what was searched, then
            // where the optimistic check connects start and goal (the place to look).
            if no_route.is_some() || m.waypoints.len() < 2 {
                // On the run's clock: a run out of time gets the reason without the place.
                let bottleneck = reachability::explain(problem, i, termination);
                let (text, at) = not_proved(problem, bottleneck.as_ref(), no_route.is_some());
                hint = format!("; {text}");
                m.focus = at.map(|at| Focus { at, label: "narrowest passage".into() });
            }
            if let Some(why) = &no_route {
                first = if m.waypoints.len() >= 2 { format!("{why}; its fallback path: {first}") } else { why.clone() };
            }
            match stats.stop_reason {
                StopReason::WallTime => (
                    Status::Timeout,
                    format!(
                        "the wall-time limit of {:.3} s stopped the run before a feasible path was found; {first}{left}{hint}",
                        termination.wall_time.map_or(0.0, |d| d.as_secs_f64())
                    ),
                ),
                StopReason::Cancelled => (
                    Status::Cancelled,
                    format!("the run was cancelled before a feasible path was found; {first}{left}"),
                ),
                _ => (Status::Infeasible, format!("{first}{left}{hint}")),
            }
        };
    }
    // The missions' costs plus the fleet's terms: what a joint optimizer minimised.
    let cost = missions.iter().map(|m| m.cost).sum::<f64>() + fleet.as_ref().map_or(0.0, |f| f.penalty());
    let (status, reason) = overall(&missions);
    Ok(Plan { planner: id, status, reason, missions, cost, stats, graphs, fleet })
}

/// The plan's status: the worst of its missions'; the reason is that mission's, named when
/// there are several.
pub(super) fn overall(missions: &[MissionPlan]) -> (Status, String) {
    let Some(worst) = missions.iter().max_by_key(|m| m.status.severity()) else {
        return (Status::Infeasible, "no mission".into());
    };
    if missions.len() == 1 {
        return (worst.status, worst.reason.clone());
    }
    let failing = missions.iter().filter(|m| !m.status.is_success()).count();
    if failing == 0 {
        let all_exact = missions.iter().all(|m| m.status == Status::Exact);
        let what = if all_exact { &worst.reason } else { "no constraint violated" };
        return (worst.status, format!("all {} missions: {what}", missions.len()));
    }
    let more =
        if failing > 1 { format!(" ({} of {} missions not flyable)", failing, missions.len()) } else { String::new() };
    (worst.status, format!("mission {}: {}{more}", worst.name, worst.reason))
}

/// "optimal for the scenario's cost model on SPACE", saying which terms the optimality covers
/// when the model has path-level terms too.
fn optimal_reason(cost: &dyn crate::cost::CostModel, what: &str, space: &str) -> String {
    let additive = cost.additive_terms();
    let path_level: Vec<&str> = cost.term_names().iter().filter(|t| !additive.contains(t)).copied().collect();
    if path_level.is_empty() {
        format!("optimal for {what} {space}")
    } else {
        format!(
            "optimal for {what} {space} (its additive terms: {}; the path-level terms {} are checked, not optimised)",
            additive.join(", "),
            path_level.join(", ")
        )
    }
}

/// "not proved unreachable: ..." for a mission whose planner found no route, naming where the
/// optimistic check's deepest connection pinches, and that place.
fn not_proved(problem: &Problem<'_>, bn: Option<&Bottleneck>, raster: bool) -> (String, Option<Vec3>) {
    let finer = if raster { ": try a finer raster" } else { "" };
    let Some(b) = bn else {
        return ("not proved unreachable: the optimistic check connects start and goal".to_string(), None);
    };
    let place = problem.world.place(b.at.x, b.at.y);
    let text = if b.pinch {
        format!(
            "not proved unreachable: the optimistic check connects start and goal through ({place}) with {:.1} m of water (this vehicle needs {:.1} m); a passage narrower than {:.0} m may exist there{finer}",
            b.water_m, b.needed_m, b.cell_m
        )
    } else {
        format!(
            "not proved unreachable: the optimistic check connects start and goal with {:.0} m cells, its shallowest place ({place}) with {:.1} m of water (this vehicle needs {:.1} m); a passage narrower than the planner's cells may exist along it{finer}",
            b.cell_m, b.water_m, b.needed_m
        )
    };
    (text, Some(b.at))
}

fn is_interruption(r: StopReason) -> bool {
    matches!(r, StopReason::WallTime | StopReason::Cancelled)
}

/// The first violation of a mission's path, and how many more there are.
fn first_problem(m: &MissionPlan) -> String {
    let Some(v) = m.violations.first() else {
        return "the planner returned no path".to_string();
    };
    let more = if m.violations.len() > 1 {
        format!(" (and {} more violations)", m.violations.len() - 1)
    } else {
        String::new()
    };
    format!("{}{more}", v.message)
}
