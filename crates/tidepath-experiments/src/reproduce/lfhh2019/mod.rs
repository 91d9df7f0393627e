//! lfhh2019 (Liu, Chen, Wang & Zhan 2019): LFHH against FHH, FHH with LTS, EDA-G, adaptive DE,
//! RRT* and PRM* in the dynamic 2-D (Table 2) and 3-D (Table 3) worlds, the ablation of LTS,
//! smoothing and the planning window (Tables 4-5), and the sweeps of λ, T and the population
//! (Figs. 15-16). One run is one `simulate` of six phases (the departure plan and a re-plan at
//! each of the five changes); its F is the mean F of the five re-planned paths (A6) and its time
//! the wall time of the whole loop. Readings: docs/papers/lfhh2019.md (experiments, A6, A8, A11).

mod paper;
mod score;
mod tables;
#[cfg(test)]
mod tests;
mod verdicts;

use std::collections::BTreeMap;
use std::sync::Mutex;
use std::time::Instant;

use super::{Claim, ClaimVerdict, ExperimentOutcome, ReproduceOptions};
use crate::compare::{comparison_of, Comparison, RunBudget};
use crate::runner::{execute, tasks, RunControl, Task};
use crate::RunRecord;
use paper::Case;
use score::{RunScore, Scoring};
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::optim::StopReason;
use tidepath::simulate::SimParams;
use tidepath_io::scenario::Scenario;
use tidepath_io::simulation::SimRequest;

/// The paper's cost F (eqs. 6-10).
const COST_MODEL: &str = "lfhh2019";
/// LFHH's learning factor λ (eq. 14) and smoothing period T (eq. 15) as the planner names them.
const LAMBDA: &str = "lambda";
const PERIOD: &str = "period";
/// The period that turns smoothing off: generations are counted from 1 and a generation
/// smooths when it is a multiple of T, so with T = 10^12 (the largest count) none does.
const NO_SMOOTHING: i64 = tidepath::termination::MAX_COUNT as i64;

/// The budgets: the paper's by default ([`Scale::PAPER`]); `--quick` and tests pass smaller ones.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Scale {
    /// What the report calls this budget.
    pub name: &'static str,
    /// Generations per (re-)planning in 2-D and 3-D, and the population NP.
    pub generations_2d: u64,
    pub generations_3d: u64,
    pub population: usize,
    /// RRT*'s iterations and PRM*'s nodes per (re-)planning.
    pub samples: u64,
    /// How many of Table 2's three pairs and Table 3's six cases run (in the paper's order).
    pub cases_2d: usize,
    pub cases_3d: usize,
    /// The sweeps' values (the paper's choice, λ = 0.08, T = 5, NP = 200, first when present).
    pub lambdas: &'static [f64],
    pub periods: &'static [u64],
    pub populations: &'static [usize],
}

impl Scale {
    /// The paper's budgets and sweeps.
    pub const PAPER: Scale = Scale {
        name: "the paper's",
        generations_2d: paper::GENERATIONS_2D,
        generations_3d: paper::GENERATIONS_3D,
        population: paper::POPULATION,
        samples: paper::SAMPLES,
        cases_2d: 3,
        cases_3d: 6,
        lambdas: &paper::LAMBDAS,
        periods: &paper::PERIODS,
        populations: &paper::POPULATIONS,
    };

    /// `--quick`: every table and case, a fifth of the generations and coarser sweeps, for a
    /// look at the pipeline and the orders of magnitude, not for the paper's numbers.
    pub const QUICK: Scale = Scale {
        name: "the quick (--quick)",
        generations_2d: 20,
        generations_3d: 60,
        population: paper::POPULATION,
        samples: paper::SAMPLES,
        cases_2d: 3,
        cases_3d: 6,
        lambdas: &[0.0, 0.04, 0.08, 0.2, 0.5, 1.0],
        periods: &[5, 10, 20],
        populations: &[100, 200, 400],
    };

    fn generations(&self, case: &Case) -> u64 {
        if case.three_d {
            self.generations_3d
        } else {
            self.generations_2d
        }
    }
}

pub(super) fn run(opts: &ReproduceOptions, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<ExperimentOutcome>> {
    run_scaled(opts, progress, if opts.quick { &Scale::QUICK } else { &Scale::PAPER })
}

fn stopped(opts: &ReproduceOptions) -> bool {
    opts.stop.as_ref().is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed))
}

/// One row of a table: a planner with parameter overrides and loop settings.
#[derive(Clone, Debug)]
pub(super) struct Variant {
    /// The row's label (a planner id, or e.g. `lfhh-no-lts`, `λ = 0.2`).
    pub label: String,
    pub planner: &'static str,
    pub params: Vec<(&'static str, toml::Value)>,
    /// The first window (waypoints ahead); `None`: the paper's W = 20.
    pub window: Option<usize>,
    /// NP; `None`: the scale's.
    pub population: Option<usize>,
}

impl Variant {
    fn plain(planner: &'static str) -> Self {
        Variant { label: planner.to_string(), planner, params: Vec::new(), window: None, population: None }
    }

    fn lfhh(label: String, params: Vec<(&'static str, toml::Value)>) -> Self {
        Variant { label, planner: "lfhh", params, window: None, population: None }
    }

    fn sampling(&self) -> bool {
        matches!(self.planner, "rrt-star" | "prm-star")
    }
}

/// Table 2's and 3's rows.
fn algorithms() -> Vec<Variant> {
    paper::ALGORITHMS.iter().map(|(id, _)| Variant::plain(id)).collect()
}

const NO_LTS: &str = "lfhh-no-lts";
const NO_SMOOTH: &str = "lfhh-no-smooth";
const NO_WINDOW: &str = "lfhh-no-window";

/// The ablation's rows after LFHH: λ = 0, smoothing off, every re-plan to the goal.
fn ablations() -> Vec<Variant> {
    vec![
        Variant::lfhh(NO_LTS.into(), vec![(LAMBDA, toml::Value::Float(0.0))]),
        Variant::lfhh(NO_SMOOTH.into(), vec![(PERIOD, toml::Value::Integer(NO_SMOOTHING))]),
        Variant { window: Some(tidepath_io::simulation::MAX_WINDOW), ..Variant::plain("lfhh") }.labelled(NO_WINDOW),
    ]
}

impl Variant {
    fn labelled(self, label: &str) -> Self {
        Variant { label: label.to_string(), ..self }
    }
}

/// What a run's record does not keep.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct RunDetail {
    pub problem: String,
    pub planner: String,
    pub run: u64,
    pub score: RunScore,
    /// The loop reached the goal along a track the true world allows.
    pub reached: bool,
    /// Windows tried over the run's re-plans at changes (20 to 39 each).
    pub windows: usize,
    /// Stopped by the wall-time cap (not by Ctrl-C).
    pub timed_out: bool,
}

/// The runs of `variants` on `cases`: the comparison (kind "scenario", the first variant the
/// reference of the marks) and each run's details.
pub(super) struct Runs {
    pub comparison: Comparison,
    pub details: Vec<RunDetail>,
}

impl Runs {
    pub fn detail(&self, problem: &str, planner: &str, run: u64) -> Option<&RunDetail> {
        self.details.iter().find(|d| d.problem == problem && d.planner == planner && d.run == run)
    }

    /// `f` of the finished runs of `planner` on `problem`, in run order.
    pub fn values(&self, problem: &str, planner: &str, f: impl Fn(&RunRecord) -> f64) -> Vec<f64> {
        self.comparison.records_of(problem, planner).map(f).collect()
    }

    pub fn costs(&self, problem: &str, planner: &str) -> Vec<f64> {
        self.values(problem, planner, |r| r.cost)
    }
}

/// The scenario of `case` with its pair as the mission.
fn scenario_of(case: &Case, cache: &mut BTreeMap<&'static str, Scenario>) -> Result<Scenario> {
    if !cache.contains_key(case.scenario) {
        cache.insert(case.scenario, tidepath_io::scenario::load(case.scenario)?);
    }
    let mut s = cache[case.scenario].clone();
    if s.missions.len() != 1 {
        return Err(Error::input("SCENARIO", format!("{} must have one mission", case.scenario)));
    }
    // The paper's F is what every planner minimises and every run is scored on.
    if s.cost.model != COST_MODEL {
        s.cost = tidepath_io::scenario::spec::CostSpec { model: COST_MODEL.into(), weights: toml::Table::new() };
    }
    let z2d = s.missions[0].start.z;
    let start = Vec3::from_array(case.world_point(case.pair.start, z2d));
    let goal = Vec3::from_array(case.world_point(case.pair.target, z2d));
    s.missions[0].start = start;
    s.missions[0].goal = goal;
    s.start = start;
    s.goal = goal;
    Ok(s)
}

/// The scenario a variant flies: `base` with its parameter overrides.
fn with_params(base: &Scenario, v: &Variant) -> Scenario {
    let mut s = base.clone();
    if !v.params.is_empty() {
        let table = s.planner.params.entry(v.planner.to_string()).or_default();
        for (k, value) in &v.params {
            table.insert(k.to_string(), value.clone());
        }
    }
    s
}

/// The loop's request for one run: the paper's window rule (W = 20, W + 1 while the window's
/// piece is infeasible, a re-plan at every change, a fresh population), the variant's window,
/// the scale's budget.
fn request(opts: &ReproduceOptions, scale: &Scale, case: &Case, v: &Variant, seed: u64) -> SimRequest {
    let p = SimParams::LFHH2019;
    let sampling = v.sampling();
    SimRequest {
        planner: Some(v.planner.to_string()),
        seed,
        iterations: (!sampling).then(|| scale.generations(case)),
        samples: sampling.then_some(scale.samples),
        population: (!sampling).then(|| v.population.unwrap_or(scale.population)),
        total_time_limit_s: opts.time_limit_s,
        window: Some(v.window.unwrap_or(p.window)),
        growth: Some(p.growth),
        policy: Some(p.policy),
        warm_start: Some(p.warm_start),
        accept: Some(p.accept),
        parallel: false,
        stop: opts.stop.clone(),
        ..SimRequest::default()
    }
}

/// One simulation, scored.
fn one_run(
    opts: &ReproduceOptions,
    scale: &Scale,
    s: &Scenario,
    case: &Case,
    v: &Variant,
    t: &Task,
) -> Result<(RunRecord, RunDetail)> {
    let report = s.simulate(&request(opts, scale, case, v, t.seed))?;
    let cost = s.cost_model()?;
    let scoring = if v.sampling() { Scoring::Resampled } else { Scoring::Own };
    let sim = &report.sim;
    let score = RunScore::of(sim, scoring, (cost.as_ref(), &s.world, &s.missions[0], &s.settings));
    let f = score.run_f();
    let timed_out = !sim.complete && !stopped(opts);
    let stop_reason = match (sim.complete, timed_out) {
        (true, _) => StopReason::Completed,
        (false, true) => StopReason::WallTime,
        (false, false) => StopReason::Cancelled,
    };
    let windows = sim.phases.iter().skip(1).filter_map(|p| p.replan.as_ref()).map(|r| r.windows.len()).sum();
    let record = RunRecord {
        problem: t.problem.clone(),
        planner: t.planner.clone(),
        run: t.run,
        seed: t.seed,
        cost: f,
        feasible: f < paper::FEASIBLE_BELOW,
        length_m: Some(sim.track.travelled),
        travel_time_s: sim.arrival(),
        elapsed_s: report.elapsed_s,
        stop_reason,
        waypoints: sim.track.points.iter().map(|p| p.to_array()).collect(),
        ..RunRecord::default()
    };
    let detail = RunDetail {
        problem: t.problem.clone(),
        planner: t.planner.clone(),
        run: t.run,
        score,
        reached: sim.reached,
        windows,
        timed_out,
    };
    Ok((record, detail))
}

/// Runs every variant on every case, `opts.runs` times each; `progress` gets the runs finished.
pub(super) fn run_cases(
    opts: &ReproduceOptions,
    scale: &Scale,
    cases: &[Case],
    variants: &[Variant],
    progress: &(dyn Fn(usize) + Sync),
) -> Result<Runs> {
    let mut cache = BTreeMap::new();
    let scenarios: Vec<Scenario> = cases.iter().map(|c| scenario_of(c, &mut cache)).collect::<Result<_>>()?;
    let labels: Vec<String> = cases.iter().map(Case::label).collect();
    let planners: Vec<String> = variants.iter().map(|v| v.label.clone()).collect();
    // Every (case, variant) scenario built once, before any run, so a bad setting fails early.
    let mut setups = BTreeMap::new();
    for (k, case) in cases.iter().enumerate() {
        for v in variants {
            let s = with_params(&scenarios[k], v);
            s.check_sim_request(&request(opts, scale, case, v, 0))?;
            setups.insert((labels[k].clone(), v.label.clone()), (s, *case, v.clone()));
        }
    }
    let all = tasks(opts.master_seed, &labels, &planners, opts.runs);
    let details = Mutex::new(Vec::new());
    let start = Instant::now();
    let control = RunControl { jobs: opts.jobs, stop: opts.stop.as_ref(), on_done: progress };
    let records = execute(&all, control, |t| {
        let (s, case, v) = &setups[&(t.problem.clone(), t.planner.clone())];
        let (record, detail) = one_run(opts, scale, s, case, v, t)?;
        details.lock().unwrap_or_else(|e| e.into_inner()).push(detail);
        Ok(record)
    })?;
    let mut records: Vec<RunRecord> = records.into_iter().flatten().collect();
    records.retain(|r| r.stop_reason != StopReason::Cancelled);
    let mut details = details.into_inner().unwrap_or_else(|e| e.into_inner());
    details.retain(|d| records.iter().any(|r| r.problem == d.problem && r.planner == d.planner && r.run == d.run));
    Ok(Runs { comparison: assemble(labels, &planners, opts, scale, records, start.elapsed().as_secs_f64()), details })
}

/// The comparison of `records` (any order) over `problems` x `planners`.
fn assemble(
    problems: Vec<String>,
    planners: &[String],
    opts: &ReproduceOptions,
    scale: &Scale,
    mut records: Vec<RunRecord>,
    total_wall_s: f64,
) -> Comparison {
    let index = |list: &[String], x: &str| list.iter().position(|p| p == x).unwrap_or(usize::MAX);
    records.sort_by_key(|r| (index(&problems, &r.problem), index(planners, &r.planner), r.run));
    let planned = problems.len() * planners.len() * opts.runs as usize;
    let budget = RunBudget {
        iterations: Some(scale.generations_2d),
        population: Some(scale.population),
        samples: Some(scale.samples),
        time_limit_s: opts.time_limit_s,
        ..RunBudget::default()
    };
    comparison_of("scenario", problems, planners, (opts.runs, opts.master_seed), budget, records, planned, total_wall_s)
}

/// `runs` with the rows of `more` (the same problems) appended after its own planners.
fn merged(a: Runs, b: Runs, opts: &ReproduceOptions, scale: &Scale) -> Runs {
    let problems = a.comparison.problems.clone();
    let mut planners = a.comparison.planners.clone();
    planners.extend(b.comparison.planners.iter().cloned());
    let records = [a.comparison.records, b.comparison.records].concat();
    let wall = a.comparison.total_wall_s + b.comparison.total_wall_s;
    let details = [a.details, b.details].concat();
    Runs { comparison: assemble(problems, &planners, opts, scale, records, wall), details }
}

/// Only the rows of `planners`, in that order.
fn only(runs: &Runs, planners: &[&str], opts: &ReproduceOptions, scale: &Scale) -> Runs {
    let keep = |p: &str| planners.contains(&p);
    let records = runs.comparison.records.iter().filter(|r| keep(&r.planner)).cloned().collect();
    let names: Vec<String> = planners.iter().map(|p| p.to_string()).collect();
    Runs {
        comparison: assemble(
            runs.comparison.problems.clone(),
            &names,
            opts,
            scale,
            records,
            runs.comparison.total_wall_s,
        ),
        details: runs.details.iter().filter(|d| keep(&d.planner)).cloned().collect(),
    }
}

/// The parts `--only` picks: Table 2, Table 3, the ablation (Tables 4-5; with LFHH's own runs
/// when its table is not run) and the parameter sweeps (Figs. 15-16).
pub const PARTS: &[&str] = &["table2", "table3", "ablation", "sweeps"];

pub(super) fn run_scaled(
    opts: &ReproduceOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
    scale: &Scale,
) -> Result<Vec<ExperimentOutcome>> {
    let runs = opts.runs as usize;
    let cases_2d = &paper::CASES_2D[..scale.cases_2d.min(3)];
    let cases_3d = &paper::CASES_3D[..scale.cases_3d.min(6)];
    let (table2, table3, ablation, sweeping) =
        (opts.wants("table2"), opts.wants("table3"), opts.wants("ablation"), opts.wants("sweeps"));
    // A table's runs when it is wanted; LFHH's alone when only the ablation needs them.
    let first = |table: bool| match (table, ablation) {
        (true, _) => Some(algorithms()),
        (false, true) => Some(vec![Variant::plain("lfhh")]),
        (false, false) => None,
    };
    let (first_2d, first_3d) = (first(table2), first(table3));
    let n = |v: &Option<Vec<Variant>>| v.as_ref().map_or(0, Vec::len);
    let sweep_points = if sweeping { scale.lambdas.len() + scale.periods.len() + scale.populations.len() } else { 0 };
    let counts = [
        cases_2d.len() * n(&first_2d) * runs,
        cases_3d.len() * n(&first_3d) * runs,
        cases_2d.len() * 3 * runs * usize::from(ablation),
        cases_3d.len() * 3 * runs * usize::from(ablation),
        sweep_points * runs,
    ];
    let total: usize = counts.iter().sum();
    let offset = |k: usize| counts[..k].iter().sum::<usize>();
    let step = |k: usize| move |n: usize| progress(offset(k) + n, total);
    let mut outcomes = Vec::new();

    let mut t2 = None;
    if let Some(v) = &first_2d {
        t2 = Some(run_cases(opts, scale, cases_2d, v, &step(0))?);
    }
    let mut t3 = None;
    if let (false, false, Some(v)) = (stopped(opts), cases_3d.is_empty(), &first_3d) {
        t3 = Some(run_cases(opts, scale, cases_3d, v, &step(1))?);
    }
    let mut ablation_2d = None;
    if let (false, true, Some(t2)) = (stopped(opts), ablation, &t2) {
        let rest = run_cases(opts, scale, cases_2d, &ablations(), &step(2))?;
        ablation_2d = Some(merged(only(t2, &["lfhh"], opts, scale), rest, opts, scale));
    }
    let mut ablation_3d = None;
    if let (false, true, Some(t3)) = (stopped(opts), ablation, &t3) {
        let rest = run_cases(opts, scale, cases_3d, &ablations(), &step(3))?;
        ablation_3d = Some(merged(only(t3, &["lfhh"], opts, scale), rest, opts, scale));
    }
    if let (true, Some(t2)) = (table2, t2) {
        outcomes.push(tables::table2(opts, scale, t2));
    }
    if let (true, Some(t3)) = (table3, t3) {
        outcomes.push(tables::table3(opts, scale, t3));
    }
    if let Some(a) = ablation_2d {
        outcomes.push(tables::ablation(opts, scale, a, false));
    }
    if let Some(a) = ablation_3d {
        outcomes.push(tables::ablation(opts, scale, a, true));
    }
    let mut done = offset(4);
    for sweep in sweeps(scale) {
        if stopped(opts) || !sweeping {
            break;
        }
        let base = done;
        let on_done = move |n: usize| progress(base + n, total);
        let r = run_cases(opts, scale, &paper::CASES_2D[..1], &sweep.variants, &on_done)?;
        done += sweep.variants.len() * runs;
        outcomes.push(tables::sweep(opts, scale, &sweep, r));
    }
    Ok(outcomes)
}

/// One parameter sweep of LFHH on Table 2's first pair.
pub(super) struct Sweep {
    pub id: &'static str,
    /// The parameter's symbol and what it is.
    pub symbol: &'static str,
    pub what: &'static str,
    pub variants: Vec<Variant>,
    /// The values, in the variants' order.
    pub values: Vec<f64>,
    /// The paper's value (λ = 0.08, T = 5, NP = 200), which the other values are compared with.
    pub paper_value: f64,
}

impl Sweep {
    /// The row of the paper's value, else (a sweep without it) the first.
    pub fn reference(&self) -> &str {
        let k = self.values.iter().position(|v| *v == self.paper_value).unwrap_or(0);
        &self.variants[k].label
    }
}

/// The sweeps of Figs. 15-16, each in increasing order of its parameter (the figure's x axis).
fn sweeps(scale: &Scale) -> Vec<Sweep> {
    fn ordered<T: Copy + PartialOrd>(values: &[T]) -> Vec<T> {
        let mut v = values.to_vec();
        v.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
        v
    }
    let lambdas = ordered(scale.lambdas);
    let periods = ordered(scale.periods);
    let populations = ordered(scale.populations);
    vec![
        Sweep {
            id: "sweep-lambda",
            symbol: "λ",
            what: "the learning factor of LTS (eq. 14)",
            variants: lambdas
                .iter()
                .map(|&l| Variant::lfhh(format!("λ = {l}"), vec![(LAMBDA, toml::Value::Float(l))]))
                .collect(),
            values: lambdas,
            paper_value: paper::BEST_LAMBDA,
        },
        Sweep {
            id: "sweep-period",
            symbol: "T",
            what: "the smoothing period (eq. 15)",
            variants: periods
                .iter()
                .map(|&t| Variant::lfhh(format!("T = {t}"), vec![(PERIOD, toml::Value::Integer(t as i64))]))
                .collect(),
            values: periods.iter().map(|&t| t as f64).collect(),
            paper_value: paper::BEST_PERIOD as f64,
        },
        Sweep {
            id: "sweep-population",
            symbol: "NP",
            what: "the population",
            variants: populations
                .iter()
                .map(|&n| Variant { population: Some(n), ..Variant::plain("lfhh") }.labelled(&format!("NP = {n}")))
                .collect(),
            values: populations.iter().map(|&n| n as f64).collect(),
            paper_value: paper::POPULATION as f64,
        },
    ]
}

/// The verdicts of `claims` on `c` (rank-sum).
fn checked(c: &Comparison, claims: Vec<Claim>) -> Vec<(Claim, ClaimVerdict)> {
    claims
        .into_iter()
        .map(|claim| {
            let v = claim.check(c);
            (claim, v)
        })
        .collect()
}

/// The budget in words, for the setups.
fn budget_words(scale: &Scale, three_d: bool) -> String {
    format!(
        "Budget ({}): NP = {}, {} generations per (re-)planning; RRT* {} iterations and PRM* {} nodes per \
         (re-)planning",
        scale.name,
        scale.population,
        if three_d { scale.generations_3d } else { scale.generations_2d },
        scale.samples,
        scale.samples
    )
}
