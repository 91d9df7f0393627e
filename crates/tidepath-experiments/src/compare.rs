//! `compare` and `bench functions`: build the tasks, run them, summarise.

use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Instant;

use serde::{Deserialize, Serialize};

use super::record::MissionRecord;
use super::runner::{execute, tasks, RunControl, Task};
use super::shard::Share;
use super::table::{rows_for, PlannerRow};
use super::RunRecord;
use tidepath::error::{Error, Result};
use tidepath::optim::functions::{Function, FunctionObjective};
use tidepath::optim::{self, Optimizer};
use tidepath::planner::build_optimizer;
use tidepath::rng::run_rng;
use tidepath::termination::{check_count, check_wall_time, StopReason, Termination};
use tidepath_io::scenario::{PlanRequest, Scenario};

/// What every run of an experiment is given: budget overrides and the smoother.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct RunBudget {
    pub iterations: Option<u64>,
    pub evaluations: Option<u64>,
    #[serde(default)]
    pub expansions: Option<u64>,
    #[serde(default)]
    pub samples: Option<u64>,
    #[serde(default)]
    pub target_cost: Option<f64>,
    pub population: Option<usize>,
    /// Wall-time safety net (s); runs stopped by it are marked `wall_time`.
    pub time_limit_s: Option<f64>,
    /// The smoother asked for (`compare --smooth`); `None`: the scenario's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smoother: Option<Smoothing>,
}

/// A smoother and its parameters, as `--smooth ID[:KEY=VALUE,...]` gives them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Smoothing {
    /// Smoother id; `none` turns the scenario's smoother off.
    pub id: String,
    /// Its parameters; `None`: the scenario's `[planner.smoother_params.ID]`, else its defaults.
    #[serde(default)]
    pub params: Option<toml::Table>,
}

impl RunBudget {
    /// The budget in words, for logs (`20 iterations, time limit 5 s per run; smoother
    /// shortcut:passes=2`).
    pub fn describe(&self) -> String {
        let mut parts: Vec<String> = [
            (self.iterations, "iterations"),
            (self.evaluations, "evaluations"),
            (self.expansions, "expansions"),
            (self.samples, "samples"),
        ]
        .iter()
        .filter_map(|(n, unit)| n.map(|n| format!("{n} {unit}")))
        .collect();
        if let Some(t) = self.target_cost {
            parts.push(format!("stop at cost {t}"));
        }
        if let Some(p) = self.population {
            parts.push(format!("population {p}"));
        }
        if let Some(t) = self.time_limit_s {
            parts.push(format!("time limit {t} s"));
        }
        let limits = if parts.is_empty() {
            "the scenario's and planners' defaults".into()
        } else {
            parts.join(", ") + " per run"
        };
        match &self.smoother {
            Some(s) => format!("{limits}; smoother {}", s.describe()),
            None => limits,
        }
    }
}

impl Smoothing {
    /// `ID` or `ID:KEY=VALUE,...`, the flag's own syntax (keys in order).
    pub fn describe(&self) -> String {
        match &self.params {
            Some(p) if !p.is_empty() => {
                let kv: Vec<String> = p.iter().map(|(k, v)| format!("{k}={v}")).collect();
                format!("{}:{}", self.id, kv.join(","))
            }
            _ => self.id.clone(),
        }
    }
}

/// Everything `results.json` holds.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Comparison {
    pub tidepath_version: String,
    /// "scenario" or "functions".
    pub kind: String,
    pub problems: Vec<String>,
    pub planners: Vec<String>,
    pub runs: u64,
    pub master_seed: u64,
    pub budget: RunBudget,
    pub rows: Vec<PlannerRow>,
    pub records: Vec<RunRecord>,
    /// Timing field: wall time of the whole experiment (s).
    pub total_wall_s: f64,
    /// The reference plan the gaps are measured against, when one was run.
    #[serde(default)]
    pub reference: Option<Reference>,
    /// False when the experiment was interrupted (Ctrl-C): the statistics then use the runs
    /// that finished, and every output says so.
    #[serde(default = "finished")]
    pub complete: bool,
    /// Runs that finished, of `problems x planners x runs`.
    #[serde(default)]
    pub finished_runs: usize,
    /// The planner asked for as the reference, also when it found no feasible plan.
    #[serde(default)]
    pub reference_planner: Option<String>,
    /// The smoother every compared run's path went through (`--smooth`, else the scenario's);
    /// `None`: no smoothing.
    #[serde(default)]
    pub smoother: Option<Smoothing>,
}

fn finished() -> bool {
    true
}

/// A reference planner's result on the scenario: what "the optimum" means for the gap column.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Reference {
    pub planner: String,
    /// Its plan's status (`exact` when the reference is provably optimal on its model).
    pub status: String,
    pub cost: f64,
    pub length_m: Option<f64>,
    pub travel_time_s: Option<f64>,
    /// Its path (the first mission's final path), for the paths figure.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub waypoints: Vec<[f64; 3]>,
}

/// The reference planner for a scenario when none is named: for vehicles with a turning
/// radius, Hybrid-A* (its paths are flyable; polyline references are not, and the vehicle
/// flies them on another curve); else the exact visibility graph where it applies (2-D discs
/// and boxes), else Theta* on the world's raster (any-angle, never longer than A* on the same
/// raster).
pub fn default_reference(scenario: &Scenario) -> &'static str {
    if scenario.missions.iter().any(|m| m.vehicle.turn_radius.is_some()) {
        return "hybrid-astar";
    }
    let cost = scenario.cost_model();
    let applies = cost.as_ref().is_ok_and(|c| {
        let p = scenario.problem(c.as_ref());
        (0..p.missions.len()).all(|i| tidepath::planner::visibility::scene(&p, i, true).is_ok())
    });
    if applies {
        "visibility"
    } else {
        "theta-star"
    }
}

/// Runs `planner` once (master seed, run 0) as the reference; `None` if it finds no feasible
/// plan (then no gap is reported).
pub fn run_reference(
    scenario: &Scenario,
    planner: &str,
    seed: u64,
    budget: &RunBudget,
    stop: Option<Arc<AtomicBool>>,
) -> Result<Option<Reference>> {
    let mut req = request(budget, planner, seed);
    req.stop = stop;
    // The reference runs with its own defaults, not the compared planners' budget or smoother.
    req.smoother = None;
    req.smoother_params = None;
    req.iterations = None;
    req.evaluations = None;
    req.expansions = None;
    req.samples = None;
    req.target_cost = None;
    req.population = None;
    let r = scenario.plan(&req, &mut |_| {})?;
    Ok((r.status.is_success() && r.stop_reason != StopReason::Cancelled).then(|| Reference {
        planner: planner.to_string(),
        status: r.status.id().to_string(),
        cost: r.cost_value(),
        length_m: r.length_m(),
        travel_time_s: r.travel_time_s(),
        waypoints: r.missions.first().map(|m| m.points().iter().map(|p| p.to_array()).collect()).unwrap_or_default(),
    }))
}

/// The gap of `cost` to the reference cost, in percent.
pub fn gap_percent(cost: f64, reference: f64) -> f64 {
    100.0 * (cost - reference) / reference.abs().max(f64::MIN_POSITIVE)
}

impl Comparison {
    pub fn is_functions(&self) -> bool {
        self.kind == "functions"
    }

    /// Every run the experiment asked for.
    pub fn planned_runs(&self) -> usize {
        self.problems.len() * self.planners.len() * self.runs as usize
    }

    /// One line saying the output is incomplete and why, or `None` when it is complete.
    pub fn incomplete_note(&self) -> Option<String> {
        (!self.complete).then(|| {
            format!(
                "Incomplete: interrupted after {} of {} runs; the statistics use the finished runs only.",
                self.finished_runs,
                self.planned_runs()
            )
        })
    }

    pub fn records_of<'a>(&'a self, problem: &'a str, planner: &'a str) -> impl Iterator<Item = &'a RunRecord> + 'a {
        self.records.iter().filter(move |r| r.problem == problem && r.planner == planner)
    }
}

/// Most runs per planner and problem (`--runs`): far beyond any statistical need, few enough
/// that the run records fit in memory.
pub const MAX_RUNS: u64 = 100_000;

/// Most runs of one experiment in all (problems x planners x runs).
pub const MAX_TASKS: u64 = 1_000_000;

/// `--runs` must be from 1 to [`MAX_RUNS`].
pub fn check_runs(runs: u64) -> Result<()> {
    if runs == 0 || runs > MAX_RUNS {
        return Err(Error::input("--runs", format!("must be from 1 to {MAX_RUNS}, got {runs}")));
    }
    Ok(())
}

/// The experiment's size: `runs` checked, and problems x planners x runs at most [`MAX_TASKS`].
fn check_size(problems: usize, planners: usize, runs: u64) -> Result<()> {
    check_runs(runs)?;
    let total = (problems as u64).saturating_mul(planners as u64).saturating_mul(runs);
    if total > MAX_TASKS {
        return Err(Error::input(
            "--runs",
            format!("{problems} problems x {planners} planners x {runs} runs = {total} runs, more than the limit of {MAX_TASKS}"),
        ));
    }
    Ok(())
}

fn check_planners(planners: &[String]) -> Result<()> {
    if planners.is_empty() {
        return Err(Error::input("--planners", "name at least one planner"));
    }
    for (i, p) in planners.iter().enumerate() {
        if planners[..i].contains(p) {
            return Err(Error::input("--planners", format!("'{p}' is listed twice")));
        }
    }
    Ok(())
}

/// Runs every planner `runs` times on a scenario, and `reference` once (its gap column).
#[allow(clippy::too_many_arguments)]
pub fn compare_scenario(
    scenario: &Scenario,
    planners: &[String],
    runs: u64,
    master_seed: u64,
    budget: &RunBudget,
    control: RunControl<'_>,
    reference: Option<&str>,
) -> Result<Comparison> {
    compare_share(scenario, planners, runs, master_seed, budget, control, reference, None)
}

/// [`compare_scenario`], or with `share` only that share of its runs (`compare --shard`, see
/// [`crate::shard`]): the comparison of those runs; share 1 runs the reference.
#[allow(clippy::too_many_arguments)]
pub fn compare_share(
    scenario: &Scenario,
    planners: &[String],
    runs: u64,
    master_seed: u64,
    budget: &RunBudget,
    control: RunControl<'_>,
    reference: Option<&str>,
    share: Option<Share>,
) -> Result<Comparison> {
    check_planners(planners)?;
    check_size(1, planners.len(), runs)?;
    // Fail on a bad planner id or parameter before any run starts.
    let registry = tidepath::planner::registry();
    for p in planners {
        let population = budget.population.or(scenario.planner.population);
        registry.build(p, scenario.planner.params.get(p), population, &scenario.encoding)?;
    }
    scenario.termination(&request(budget, "", 0))?;
    let problems = vec![scenario.name.clone()];
    let mut all = tasks(master_seed, &problems, planners, runs);
    if let Some(s) = share {
        if s.n > all.len() as u64 {
            return Err(Error::input("--shard", format!("'{s}' asks for more shares than the {} runs", all.len())));
        }
        all = s.select(all);
    }
    let start = Instant::now();
    let stop = control.stop.cloned();
    let records = execute(&all, control, |t| scenario_run(scenario, budget, t, stop.clone()))?;
    let mut c = finish("scenario", problems, planners, runs, master_seed, budget, records, start);
    c.smoother = effective_smoother(scenario, budget);
    c.reference_planner = reference.map(str::to_string);
    if let (Some(id), true, true) = (reference, c.complete, share.is_none_or(|s| s.k == 1)) {
        let r = run_reference(scenario, id, master_seed, budget, stop)?;
        set_reference(&mut c, r);
    }
    Ok(c)
}

/// Sets the comparison's reference and the rows' gaps to it.
pub(crate) fn set_reference(c: &mut Comparison, reference: Option<Reference>) {
    c.reference = reference;
    if let Some(r) = &c.reference {
        // Over feasible runs only: an infeasible path's cost is mostly penalty.
        for row in &mut c.rows {
            row.gap_percent = row.feasible_mean.map(|m| gap_percent(m, r.cost));
            row.best_gap_percent = row.feasible_best.map(|b| gap_percent(b, r.cost));
        }
    }
}

/// The smoother the compared runs use: the one asked for, else the scenario's (with its
/// parameters); `None` for none.
fn effective_smoother(scenario: &Scenario, budget: &RunBudget) -> Option<Smoothing> {
    let s = match &budget.smoother {
        Some(s) => s.clone(),
        None => {
            let id = scenario.planner.smoother.clone()?;
            Smoothing { params: scenario.planner.smoother_params.get(&id).cloned(), id }
        }
    };
    (s.id != "none").then_some(s)
}

/// The request of one compared run (`planner` empty: the scenario's): the budget and smoother
/// of every run; commands check it for each planner before any run starts.
pub fn request(budget: &RunBudget, planner: &str, seed: u64) -> PlanRequest {
    PlanRequest {
        planner: (!planner.is_empty()).then(|| planner.to_string()),
        seed,
        run: 0,
        iterations: budget.iterations,
        evaluations: budget.evaluations,
        expansions: budget.expansions,
        samples: budget.samples,
        target_cost: budget.target_cost,
        population: budget.population,
        time_limit_s: budget.time_limit_s,
        parallel: false,
        smoother: budget.smoother.as_ref().map(|s| s.id.clone()),
        smoother_params: budget.smoother.as_ref().and_then(|s| s.params.clone()),
        ..PlanRequest::default()
    }
}

fn scenario_run(scenario: &Scenario, budget: &RunBudget, t: &Task, stop: Option<Arc<AtomicBool>>) -> Result<RunRecord> {
    let mut req = request(budget, &t.planner, t.seed);
    req.stop = stop;
    Ok(record_of(t, scenario.plan(&req, &mut |_| {})?))
}

/// The record an experiment keeps of task `t`'s plan.
pub fn record_of(t: &Task, r: tidepath_io::plan_json::PlanReport) -> RunRecord {
    RunRecord {
        problem: t.problem.clone(),
        planner: t.planner.clone(),
        run: t.run,
        seed: t.seed,
        cost: r.cost_value(),
        feasible: r.feasible,
        length_m: r.length_m(),
        travel_time_s: r.travel_time_s(),
        evaluations: r.evaluations,
        iterations: r.iterations,
        elapsed_s: r.elapsed_s,
        stop_reason: r.stop_reason,
        waypoints: r.paths().first().map(|p| p.iter().map(|q| q.to_array()).collect()).unwrap_or_default(),
        status: Some(r.status),
        expansions: r.expansions,
        samples: r.samples,
        motion_checks: r.motion_checks,
        graph_nodes: r.graph_nodes,
        missions: r
            .missions
            .iter()
            .map(|m| MissionRecord {
                name: m.name.clone(),
                status: m.status,
                waypoints: m.points().iter().map(|q| q.to_array()).collect(),
                goal_distance_m: m.goal_distance_m,
            })
            .collect(),
        history: r.history,
    }
}

/// One benchmark-function problem: a function, its dimension and its box.
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionProblem {
    pub function: Function,
    pub dim: usize,
    pub lower: f64,
    pub upper: f64,
    /// Label used in tables, e.g. `sphere-d30-small`.
    pub label: String,
}

/// Builds an optimizer for a planner id; the default uses each optimizer's default parameters.
pub type OptimizerFactory<'a> = dyn Fn(&str) -> Result<Box<dyn Optimizer>> + Sync + 'a;

/// Runs every optimizer `runs` times on each function problem.
#[allow(clippy::too_many_arguments)]
pub fn compare_functions(
    problems: &[FunctionProblem],
    planners: &[String],
    runs: u64,
    master_seed: u64,
    budget: &RunBudget,
    control: RunControl<'_>,
    factory: Option<&OptimizerFactory<'_>>,
) -> Result<Comparison> {
    check_planners(planners)?;
    check_size(problems.len(), planners.len(), runs)?;
    let default_factory = |id: &str| build_optimizer(id, None, budget.population);
    let factory: &OptimizerFactory<'_> = factory.unwrap_or(&default_factory);
    for p in planners {
        factory(p)?;
    }
    let labels: Vec<String> = problems.iter().map(|p| p.label.clone()).collect();
    let all = tasks(master_seed, &labels, planners, runs);
    let b = Termination {
        max_iterations: budget.iterations.map(|n| check_count("--iterations", n)).transpose()?,
        max_evaluations: budget.evaluations.map(|n| check_count("--evaluations", n)).transpose()?,
        wall_time: Some(match budget.time_limit_s {
            Some(t) => check_wall_time("--time-limit", t)?,
            None => check_wall_time("default time limit", tidepath_io::scenario::default_time_limit_s()?)?,
        }),
        stop: control.stop.cloned(),
        ..Termination::default()
    };
    let start = Instant::now();
    let records = execute(&all, control, |t| {
        let problem = problems.iter().find(|p| p.label == t.problem).expect("task problem exists");
        let objective = FunctionObjective::new(problem.function, problem.dim, problem.lower, problem.upper);
        let mut opt = factory(&t.planner)?;
        let r = optim::run(opt.as_mut(), &objective, &b, &mut run_rng(t.seed, 0), false, &[], &mut |_| {});
        Ok(RunRecord {
            problem: t.problem.clone(),
            planner: t.planner.clone(),
            run: t.run,
            seed: t.seed,
            cost: r.best_cost,
            feasible: true,
            length_m: None,
            travel_time_s: None,
            evaluations: r.evaluations,
            iterations: r.iterations,
            elapsed_s: r.elapsed.as_secs_f64(),
            stop_reason: r.stop_reason,
            history: r.history.iter().map(|h| h.is_finite().then_some(*h)).collect(),
            ..RunRecord::default()
        })
    })?;
    Ok(finish("functions", labels, planners, runs, master_seed, budget, records, start))
}

#[allow(clippy::too_many_arguments)]
fn finish(
    kind: &str,
    problems: Vec<String>,
    planners: &[String],
    runs: u64,
    master_seed: u64,
    budget: &RunBudget,
    records: Vec<Option<RunRecord>>,
    start: Instant,
) -> Comparison {
    // Runs skipped after a stop, and runs the stop cut short, are not finished runs.
    let planned = records.len();
    let records: Vec<RunRecord> =
        records.into_iter().flatten().filter(|r| r.stop_reason != StopReason::Cancelled).collect();
    let total_wall_s = start.elapsed().as_secs_f64();
    comparison_of(kind, problems, planners, (runs, master_seed), budget.clone(), records, planned, total_wall_s)
}

/// The comparison of finished `records` (none cancelled) out of `planned` runs: its rows per
/// problem and planner, the first planner the reference of the marks; incomplete when runs are
/// missing. `seeding` is (runs per pair, master seed).
#[allow(clippy::too_many_arguments)]
pub(crate) fn comparison_of(
    kind: &str,
    problems: Vec<String>,
    planners: &[String],
    seeding: (u64, u64),
    budget: RunBudget,
    records: Vec<RunRecord>,
    planned: usize,
    total_wall_s: f64,
) -> Comparison {
    let rows = problems.iter().flat_map(|p| rows_for(p, planners, &records)).collect();
    Comparison {
        tidepath_version: env!("CARGO_PKG_VERSION").to_string(),
        kind: kind.to_string(),
        problems,
        planners: planners.to_vec(),
        runs: seeding.0,
        master_seed: seeding.1,
        budget,
        rows,
        complete: records.len() == planned,
        finished_runs: records.len(),
        records,
        total_wall_s,
        reference: None,
        reference_planner: None,
        smoother: None,
    }
}

/// A finished comparison of `records` (tests build tables from hand-made runs).
#[cfg(test)]
pub(crate) fn from_records(
    kind: &str,
    problems: &[&str],
    planners: &[&str],
    runs: u64,
    records: Vec<RunRecord>,
) -> Comparison {
    let planners: Vec<String> = planners.iter().map(|p| p.to_string()).collect();
    let problems = problems.iter().map(|p| p.to_string()).collect();
    let records = records.into_iter().map(Some).collect();
    finish(kind, problems, &planners, runs, 0, &RunBudget::default(), records, Instant::now())
}
