//! wpa2017 (Zhang, Zhang, Liu, Zhou & Papavassiliou 2017), section IV: MWPA against PSO and GA
//! (WPA beside them) on Table 2's functions (Table 4), once at each planner's own budget and
//! once at equal evaluations; and WPA against MWPA on the path problem (Table 5, Figs. 8-9).
//! Readings: docs/papers/wpa2017.md (experiments, A12, A13).

mod paper;
mod path;
#[cfg(test)]
mod tests;

use std::time::Instant;

use super::{Claim, ExperimentOutcome, ReproduceOptions};
use crate::compare::{compare_functions, comparison_of, Comparison, FunctionProblem, RunBudget};
use crate::runner::RunControl;
use crate::table::num;
use crate::RunRecord;
use tidepath::error::{Error, Result};
use tidepath::optim::ga::{Ga, GaParams};
use tidepath::optim::mwpa::{Mwpa, MwpaParams};
use tidepath::optim::pso::{Pso, PsoParams};
use tidepath::optim::wpa::{Wpa, WpaParams};
use tidepath::optim::{Optimizer, StopReason};

/// Table 4's planners, in report order (the first is the one the others are marked against);
/// WPA is ours, shown for reference and never in a claim.
const PLANNERS: [&str; 4] = ["mwpa", "pso", "ga", "wpa"];

/// Longest convergence history kept per run in the equal-evaluation experiment, where PSO and
/// GA run tens of thousands of generations.
const MAX_HISTORY: usize = 1000;

/// The experiments' budgets: the paper's by default ([`Scale::PAPER`]); tests pass a small one.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Scale {
    /// MWPA's and WPA's iterations K_max and wolves N on the functions.
    pub wolf_iterations: u64,
    pub wolf_population: usize,
    /// PSO's iterations and particles, GA's generations and individuals.
    pub baseline_iterations: u64,
    pub baseline_population: usize,
    /// Iterations and wolves on the path problem; `None`: the scenario's (300 and 300).
    pub path_iterations: Option<u64>,
    pub path_population: Option<usize>,
}

impl Scale {
    /// The paper's values and our readings of what it leaves out (docs/papers/wpa2017.md
    /// A12-A13): N = 100 and K_max = 500 for the wolf packs, 50 and 1000
    /// for PSO and GA, and the path scenario's own 300 and 300.
    pub const PAPER: Scale = Scale {
        wolf_iterations: 500,
        wolf_population: 100,
        baseline_iterations: 1000,
        baseline_population: 50,
        path_iterations: None,
        path_population: None,
    };
}

pub(super) fn run(opts: &ReproduceOptions, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<ExperimentOutcome>> {
    run_scaled(opts, progress, &Scale::PAPER)
}

fn stopped(opts: &ReproduceOptions) -> bool {
    opts.stop.as_ref().is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed))
}

pub(super) fn run_scaled(
    opts: &ReproduceOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
    scale: &Scale,
) -> Result<Vec<ExperimentOutcome>> {
    let runs = opts.runs as usize;
    let per_functions = paper::FUNCTIONS.len() * PLANNERS.len() * runs;
    let total = 2 * per_functions + path::PLANNERS.len() * runs;
    let mut outcomes = Vec::new();
    let own = functions_at_own_budgets(opts, scale, &|n| progress(n, total))?;
    let budgets = equal_budgets(&own.comparison);
    outcomes.push(own);
    if !stopped(opts) && budgets.len() == paper::FUNCTIONS.len() {
        outcomes.push(functions_at_equal_evaluations(opts, scale, &budgets, &|n| progress(per_functions + n, total))?);
    }
    if !stopped(opts) {
        outcomes.push(path::experiment(opts, scale, &|n| progress(2 * per_functions + n, total))?);
    }
    Ok(outcomes)
}

/// Table 2's problems: each function with its own dimension and range.
fn problems() -> Vec<FunctionProblem> {
    paper::FUNCTIONS
        .iter()
        .map(|&function| {
            let (dim, lower, upper) = function.wpa2017_setting().expect("a Table 2 function");
            FunctionProblem { function, dim, lower, upper, label: format!("{}-d{dim}", function.id()) }
        })
        .collect()
}

/// Table 3's settings (docs/papers/wpa2017.md, parameters and baselines), the populations from
/// `scale`.
fn factory(scale: &Scale) -> impl Fn(&str) -> Result<Box<dyn Optimizer>> + Sync + '_ {
    move |id: &str| -> Result<Box<dyn Optimizer>> {
        let prefix = format!("wpa2017.{id}");
        Ok(match id {
            "mwpa" => Box::new(Mwpa::new(
                MwpaParams { population: scale.wolf_population, ..MwpaParams::wpa2017() }.checked(&prefix)?,
            )),
            "wpa" => Box::new(Wpa::new(
                WpaParams { population: scale.wolf_population, ..WpaParams::wpa2017() }.checked(&prefix)?,
            )),
            "pso" => Box::new(Pso::new(
                PsoParams { population: scale.baseline_population, ..PsoParams::wpa2017() }.checked(&prefix)?,
            )),
            "ga" => Box::new(Ga::new(
                GaParams { population: scale.baseline_population, ..GaParams::wpa2017() }.checked(&prefix)?,
            )),
            other => return Err(Error::input("planner", format!("wpa2017 has no planner '{other}'"))),
        })
    }
}

fn strings(ids: &[&str]) -> Vec<String> {
    ids.iter().map(|s| s.to_string()).collect()
}

/// One comparison of several parts run under different budgets: their records in task order
/// (problem, planner, run) and the rows recomputed over all planners, the first the reference
/// of the marks. Incomplete when any planned run is missing.
fn assemble(
    kind: &str,
    problems: Vec<String>,
    planners: &[String],
    opts: &ReproduceOptions,
    budget: RunBudget,
    mut records: Vec<RunRecord>,
    total_wall_s: f64,
) -> Comparison {
    let index = |list: &[String], x: &str| list.iter().position(|p| p == x).unwrap_or(usize::MAX);
    records.retain(|r| r.stop_reason != StopReason::Cancelled);
    records.sort_by_key(|r| (index(&problems, &r.problem), index(planners, &r.planner), r.run));
    let planned = problems.len() * planners.len() * opts.runs as usize;
    comparison_of(kind, problems, planners, (opts.runs, opts.master_seed), budget, records, planned, total_wall_s)
}

/// Table 4 at each planner's own budget: MWPA and WPA N = 100 for K_max = 500 iterations, PSO
/// and GA 50 for 1000 iterations.
fn functions_at_own_budgets(
    opts: &ReproduceOptions,
    scale: &Scale,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<ExperimentOutcome> {
    let problems = problems();
    let labels: Vec<String> = problems.iter().map(|p| p.label.clone()).collect();
    let factory = factory(scale);
    let start = Instant::now();
    let mut records = Vec::new();
    let mut done = 0;
    for (group, iterations) in [(["mwpa", "wpa"], scale.wolf_iterations), (["pso", "ga"], scale.baseline_iterations)] {
        if stopped(opts) {
            break;
        }
        let budget =
            RunBudget { iterations: Some(iterations), time_limit_s: opts.time_limit_s, ..RunBudget::default() };
        let on_done = |n| progress(done + n);
        let control = RunControl { jobs: opts.jobs, stop: opts.stop.as_ref(), on_done: &on_done };
        let c = compare_functions(
            &problems,
            &strings(&group),
            opts.runs,
            opts.master_seed,
            &budget,
            control,
            Some(&factory),
        )?;
        done += c.planned_runs();
        records.extend(c.records);
    }
    let budget = RunBudget { time_limit_s: opts.time_limit_s, ..RunBudget::default() };
    let c = assemble("functions", labels.clone(), &strings(&PLANNERS), opts, budget, records, secs(start));
    let claims = checked(&c, &claims(&labels));
    let mut notes = vec![evaluations_note(&c, &labels), optimum_note(&c, &problems)];
    notes.extend(wpa_note(&c, &labels));
    notes.push(time_note());
    Ok(ExperimentOutcome {
        id: "table4-functions".into(),
        title: "Table 4: benchmark functions, each planner at its own budget".into(),
        setup: format!(
            "{} runs per planner and function. Functions and ranges of Table 2: {}. Table 3's settings with our \
             readings (docs/papers/wpa2017.md, A12-A13): MWPA N = {wn}, K_max = {wk} iterations, T_max = 20, ω = 500, \
             α = 4 (printed 0.8, impossible), β = 6, step_a/b/c = range/1000, /500, /2000, h = 4, adaptive raid \
             weight in [0.4, 1], siege decay c = 0.99; WPA (ours, not in Table 4) the same without the paper's \
             modifications. PSO w = 0.7, c1 = c2 = 2, {bn} particles, {bk} iterations (printed 10, read as 1000), \
             v_max = range; GA real-coded, {bn} individuals, {bk} generations, pc = 0.8, roulette, two-point \
             crossover, per-gene mutation 1/D with σ = 0.1 × range, elitism 1. The iteration counts give very \
             different numbers of evaluations (column \"evaluations ours\"): the next experiment gives every \
             planner the same number. Claims on cost; WPA takes part in none.",
            opts.runs,
            ranges(&problems),
            wn = scale.wolf_population,
            wk = scale.wolf_iterations,
            bn = scale.baseline_population,
            bk = scale.baseline_iterations,
        ),
        comparison: c,
        paper: paper::table4("wpa2017, Table 4", &labels),
        claims,
        notes,
        tables: Vec::new(),
        scenario: None,
    })
}

/// Per function, MWPA's mean evaluations per run at its own budget, rounded up: the equal
/// budget of every planner in the second experiment. Empty unless MWPA ran on every function.
fn equal_budgets(c: &Comparison) -> Vec<(String, u64)> {
    c.rows
        .iter()
        .filter(|r| r.planner == "mwpa" && r.runs > 0 && r.mean_evaluations.is_finite())
        .map(|r| (r.problem.clone(), r.mean_evaluations.ceil() as u64))
        .collect()
}

/// Table 4 at equal evaluations: on each function every planner stops at MWPA's mean count.
fn functions_at_equal_evaluations(
    opts: &ReproduceOptions,
    scale: &Scale,
    budgets: &[(String, u64)],
    progress: &(dyn Fn(usize) + Sync),
) -> Result<ExperimentOutcome> {
    let problems = problems();
    let labels: Vec<String> = problems.iter().map(|p| p.label.clone()).collect();
    let factory = factory(scale);
    let planners = strings(&PLANNERS);
    let start = Instant::now();
    let mut records = Vec::new();
    let mut done = 0;
    for (problem, (label, evaluations)) in problems.iter().zip(budgets) {
        debug_assert_eq!(&problem.label, label);
        if stopped(opts) {
            break;
        }
        let budget =
            RunBudget { evaluations: Some(*evaluations), time_limit_s: opts.time_limit_s, ..RunBudget::default() };
        let on_done = |n| progress(done + n);
        let control = RunControl { jobs: opts.jobs, stop: opts.stop.as_ref(), on_done: &on_done };
        let one = std::slice::from_ref(problem);
        let c = compare_functions(one, &planners, opts.runs, opts.master_seed, &budget, control, Some(&factory))?;
        done += c.planned_runs();
        records.extend(c.records);
    }
    let thinned = thin_histories(&mut records);
    let budget = RunBudget { time_limit_s: opts.time_limit_s, ..RunBudget::default() };
    let c = assemble("functions", labels.clone(), &planners, opts, budget, records, secs(start));
    let claims = checked(&c, &claims(&labels));
    let mut notes = vec![evaluations_note(&c, &labels), optimum_note(&c, &problems)];
    notes.extend(wpa_note(&c, &labels));
    if thinned {
        notes.push(format!(
            "Convergence figure: PSO and GA run far more generations here than MWPA runs iterations; every \
             history longer than {MAX_HISTORY} entries is thinned to {MAX_HISTORY} evenly spaced ones (the last \
             kept), so its x axis is progress through the run, not the iteration number."
        ));
    }
    let budget_list: Vec<String> = budgets.iter().map(|(l, e)| format!("{l} {e}")).collect();
    Ok(ExperimentOutcome {
        id: "table4-equal-evaluations".into(),
        title: "Table 4 again: every planner at MWPA's number of evaluations".into(),
        setup: format!(
            "The previous experiment's problems and settings, {} runs, but every planner stops at the same number \
             of evaluations on a function: MWPA's mean count per run at its own budget in the previous experiment, \
             rounded up ({}). MWPA therefore runs about its own K_max, and PSO and GA many more generations than \
             their 1000. This asks whether MWPA's lead comes from its search or from spending more evaluations. \
             The paper's columns are Table 4's, measured at the paper's own budgets. Claims on cost, as before.",
            opts.runs,
            budget_list.join(", ")
        ),
        comparison: c,
        paper: paper::table4("wpa2017, Table 4 (at the paper's own budgets)", &labels),
        claims,
        notes,
        tables: Vec::new(),
        scenario: None,
    })
}

/// Keeps at most [`MAX_HISTORY`] evenly spaced entries of each history (the last included);
/// true when any history was thinned.
fn thin_histories(records: &mut [RunRecord]) -> bool {
    let mut any = false;
    for r in records {
        let n = r.history.len();
        if n > MAX_HISTORY {
            r.history = (0..MAX_HISTORY).map(|j| r.history[j * (n - 1) / (MAX_HISTORY - 1)]).collect();
            any = true;
        }
    }
    any
}

fn secs(start: Instant) -> f64 {
    start.elapsed().as_secs_f64()
}

fn ranges(problems: &[FunctionProblem]) -> String {
    problems
        .iter()
        .map(|p| format!("{} D = {} [{}, {}]", p.function.id(), p.dim, p.lower, p.upper))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Table 4's orderings: MWPA below PSO and GA from D = 30 up, as the paper states; at D <= 6
/// the paper's means put PSO and GA at or below MWPA ("the relative effect of PSO is the best
/// for the single peak and low dimension function"), and the claim takes that side.
fn claims(labels: &[String]) -> Vec<Claim> {
    let mut out = Vec::new();
    for (i, label) in labels.iter().enumerate() {
        let f = paper::FUNCTIONS[i];
        let dim = f.wpa2017_setting().map_or(0, |s| s.0);
        for (planner, name) in [("pso", "PSO"), ("ga", "GA")] {
            let theirs = paper::table4_rows(planner).expect("Table 4 planner")[i].2;
            let mwpa = paper::TABLE4_MWPA[i].2;
            out.push(if dim >= 30 {
                Claim::lower(label, "mwpa", planner, format!("MWPA reaches lower costs than {name} on {f} (D = {dim})"))
            } else {
                Claim::lower(
                    label,
                    planner,
                    "mwpa",
                    format!(
                        "{name} reaches lower costs than MWPA on {f} (D = {dim}; the paper's means {theirs} against \
                         {mwpa}, the low-dimension converse)"
                    ),
                )
            });
        }
    }
    out
}

fn checked(c: &Comparison, claims: &[Claim]) -> Vec<(Claim, super::ClaimVerdict)> {
    claims.iter().map(|claim| (claim.clone(), claim.check(c))).collect()
}

/// Mean evaluations per run of each planner, and how many times MWPA's that is.
fn evaluations_note(c: &Comparison, labels: &[String]) -> String {
    let per: Vec<String> = labels
        .iter()
        .map(|l| {
            let of = |p: &str| c.rows.iter().find(|r| &r.problem == l && r.planner == p).map(|r| r.mean_evaluations);
            let list: Vec<String> = PLANNERS
                .iter()
                .filter_map(|p| of(p).filter(|e| e.is_finite()).map(|e| format!("{p} {e:.0}")))
                .collect();
            format!("{l}: {}", list.join(", "))
        })
        .collect();
    format!("Mean evaluations per run: {}.", per.join("; "))
}

/// On the functions whose optimum is not 0 (Easom, Trid), the mean distance of each planner's
/// final value to it, which the table's four digits hide.
fn optimum_note(c: &Comparison, problems: &[FunctionProblem]) -> String {
    let per: Vec<String> = problems
        .iter()
        .filter(|p| p.function.optimum(p.dim) != 0.0)
        .map(|p| {
            let list: Vec<String> = PLANNERS
                .iter()
                .filter_map(|pl| {
                    let r = c.rows.iter().find(|r| r.problem == p.label && r.planner == *pl)?;
                    r.mean.is_finite().then(|| format!("{pl} {}", num(r.mean - p.function.optimum(p.dim))))
                })
                .collect();
            format!("{} (f* = {}): {}", p.label, p.function.optimum(p.dim), list.join(", "))
        })
        .collect();
    format!("Mean distance to the optimum, f - f*, where f* is not 0: {}.", per.join("; "))
}

/// How WPA (not in Table 4) compares with MWPA, by the rank-sum marks of its rows.
fn wpa_note(c: &Comparison, labels: &[String]) -> Option<String> {
    let marks: Vec<String> = labels
        .iter()
        .filter_map(|l| {
            let r = c.rows.iter().find(|r| &r.problem == l && r.planner == "wpa")?;
            let m = r.mark.map_or("—", |m| m.word());
            Some(format!("{l} {m} (mean {})", num(r.mean)))
        })
        .collect();
    (!marks.is_empty()).then(|| {
        format!(
            "WPA against MWPA (not in the paper's Table 4; the \"vs mwpa\" column, from WPA's side): {}.",
            marks.join(", ")
        )
    })
}

fn time_note() -> String {
    "Times are wall-clock seconds per run on this machine (the paper's: MATLAB 2013b on a 2.2 GHz Core i3); \
     they depend on the machine, the language and the load, so only their ratios between planners mean \
     anything, and no claim rests on them."
        .into()
}
