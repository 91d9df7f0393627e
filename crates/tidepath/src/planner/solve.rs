//! The one way every planner is run: check the termination, the planner's settings and the
//! missions' start and goal; plan; smooth; judge every path with the shared evaluation; set
//! the status from those direct checks.

use super::{Claim, Planner, Problem, RunOptions, SearchStats, Status};
use crate::error::Result;
use crate::geom::Vec3;
use crate::optim::Progress;
use crate::path::{Metrics, PathModel, Violation};
use crate::rng::Rng;
use crate::smoothing::Smoother;
use crate::termination::{StopReason, Termination};

#[derive(Clone, Copy, Default)]
pub struct SolveOptions<'a> {
    pub run: RunOptions<'a>,
    /// Every path goes through it before it is judged.
    pub smoother: Option<&'a dyn Smoother>,
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
    /// Arrival time at each point of the final path (s on the scenario clock).
    pub times: Vec<f64>,
    pub cost: f64,
    pub terms: Vec<(&'static str, f64)>,
    pub feasible: bool,
    pub violations: Vec<Violation>,
    pub metrics: Option<Metrics>,
}

impl MissionPlan {
    /// The final path: smoothed when a smoother ran.
    pub fn path(&self) -> &[Vec3] {
        self.smoothed.as_deref().unwrap_or(&self.waypoints)
    }

    fn unplanned(name: &str) -> Self {
        Self {
            name: name.to_string(),
            waypoints: Vec::new(),
            smoothed: None,
            raw_cost: None,
            times: Vec::new(),
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
}

impl Plan {
    pub fn feasible(&self) -> bool {
        self.status.is_success()
    }
}

/// Cost, terms, violations, metrics and arrival times of one path of one mission.
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
        cost: total,
        terms,
        feasible: violations.is_empty(),
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
pub fn solve(
    planner: &mut dyn Planner,
    problem: &Problem<'_>,
    termination: &Termination,
    rng: &mut Rng,
    options: SolveOptions<'_>,
    observer: &mut dyn FnMut(&Progress),
) -> Result<Plan> {
    termination.check()?;
    // The run's one clock starts here: every stage below draws on the same deadline.
    let termination = &termination.started_now();
    let id = planner.id().to_string();
    let models: Vec<PathModel<'_>> = (0..problem.missions.len()).map(|i| problem.path_model(i)).collect();
    let unplanned = |status, reason| Plan {
        planner: id.clone(),
        status,
        reason,
        missions: problem.missions.iter().map(|m| MissionPlan::unplanned(&m.name)).collect(),
        cost: f64::INFINITY,
        stats: SearchStats::default(),
    };
    for (i, (m, model)) in problem.missions.iter().zip(&models).enumerate() {
        if let Err(issue) = model.validator.state(m.start, m.departure_time) {
            let why = model.validator.describe(m.start, issue);
            return Ok(unplanned(Status::InvalidStart, format!("{}: {why}", mission_field(problem, i, "start"))));
        }
        if let Err(issue) = model.validator.fixed_state(m.goal) {
            let why = model.validator.describe(m.goal, issue);
            return Ok(unplanned(Status::InvalidGoal, format!("{}: {why}", mission_field(problem, i, "goal"))));
        }
    }

    for i in 0..problem.missions.len() {
        if let Some(reason) = super::reachability::unreachable(problem, i, termination) {
            return Ok(unplanned(Status::Unreachable, reason));
        }
    }
    // Whether this planner takes this problem (a setting, or a world it does not cover).
    planner.check(problem)?;

    let mut out = planner.plan(problem, termination, rng, options.run, observer);
    if let Some(Claim::Unreachable(reason)) = &out.claim {
        return Ok(Plan { stats: out.stats, ..unplanned(Status::Unreachable, reason.clone()) });
    }
    let mut missions = Vec::with_capacity(problem.missions.len());
    for (i, m) in problem.missions.iter().enumerate() {
        let raw = out.paths.get(i).cloned().unwrap_or_default();
        if raw.len() < 2 {
            missions.push(MissionPlan::unplanned(&m.name));
            continue;
        }
        let model = &models[i];
        let mission = match options.smoother {
            None => judge(model, problem.cost, &raw, &m.name),
            Some(s) => {
                let smoothed = s.smooth(model, problem.cost, &raw, termination);
                // A smoother cut by the clock or the stop flag is what stopped the run.
                if let (Some(r), false) = (termination.interrupted(), is_interruption(out.stats.stop_reason)) {
                    out.stats.stop_reason = r;
                }
                let raw_cost = problem.cost.breakdown(model, &raw).0;
                let mut j = judge(model, problem.cost, &smoothed, &m.name);
                j.waypoints = raw;
                j.smoothed = Some(smoothed);
                j.raw_cost = Some(raw_cost);
                j
            }
        };
        missions.push(mission);
    }
    let cost = missions.iter().map(|m| m.cost).sum();
    let all_feasible = missions.iter().all(|m| m.feasible);
    let (status, reason) = if all_feasible {
        match &out.claim {
            Some(Claim::Optimal { space, scenario_cost: true, .. }) => {
                (Status::Exact, optimal_reason(problem.cost, "the scenario's cost model", space))
            }
            Some(Claim::Optimal { space, objective, .. }) => (
                Status::Feasible,
                format!("no constraint violated; optimal for {objective} {space}, not for the scenario's cost model"),
            ),
            _ => (Status::Feasible, "no constraint violated".to_string()),
        }
    } else {
        let first = first_problem(&missions);
        match out.stats.stop_reason {
            StopReason::WallTime => (
                Status::Timeout,
                format!(
                    "the wall-time limit of {:.3} s stopped the run before a feasible path was found; {first}",
                    termination.wall_time.map_or(0.0, |d| d.as_secs_f64())
                ),
            ),
            _ => (Status::Infeasible, first),
        }
    };
    let reason = match (&out.claim, status) {
        (Some(Claim::Hint(h)), Status::Infeasible | Status::Timeout) => format!("{reason}; {h}"),
        _ => reason,
    };
    Ok(Plan { planner: id, status, reason, missions, cost, stats: out.stats })
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

fn is_interruption(r: StopReason) -> bool {
    matches!(r, StopReason::WallTime | StopReason::Cancelled)
}

/// The first violation of the first infeasible mission, and how many more there are.
fn first_problem(missions: &[MissionPlan]) -> String {
    let several = missions.len() > 1;
    let total: usize = missions.iter().map(|m| m.violations.len()).sum();
    let Some(m) = missions.iter().find(|m| !m.feasible) else {
        return String::new();
    };
    let prefix = if several { format!("{}: ", m.name) } else { String::new() };
    let Some(v) = m.violations.first() else {
        return format!("{prefix}the planner returned no path");
    };
    let more = if total > 1 { format!(" (and {} more violations)", total - 1) } else { String::new() };
    format!("{prefix}{}{more}", v.message)
}
