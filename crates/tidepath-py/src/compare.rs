//! `tidepath.compare`: the CLI's `compare` through tidepath-experiments, whole
//! (`compare_json`) or one share of its runs (`compare_share_json`, a task an executor runs
//! anywhere), the shares joined by the library's `shard::merge` (`merge_json`).

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use pyo3::prelude::*;
use tidepath::Error;
use tidepath_experiments::compare::{compare_share, default_reference, request, RunBudget};
use tidepath_experiments::output;
use tidepath_experiments::runner::RunControl;
use tidepath_experiments::shard::{self, ShardFile, ShardInfo, ShardResults, Share};
use tidepath_io::scenario::Scenario;

use crate::convert::err;
use crate::run::interruptible;
use crate::scenario::PyScenario;

/// Most worker threads (as the CLI's `--jobs`).
const MAX_JOBS: usize = 1024;

fn jobs(requested: Option<usize>) -> Result<usize, Error> {
    match requested {
        Some(0) => Err(Error::input("jobs", "must be at least 1, got 0")),
        Some(j) if j > MAX_JOBS => Err(Error::input("jobs", format!("must be at most {MAX_JOBS}, got {j}"))),
        Some(j) => Ok(j),
        None => Ok(std::thread::available_parallelism().map_or(1, |n| n.get())),
    }
}

/// The budget from its JSON form (`RunBudget`'s fields; Python builds it).
fn budget(json: &str) -> Result<RunBudget, Error> {
    serde_json::from_str(json).map_err(|e| Error::input("budget", e.to_string()))
}

/// The checks `tidepath compare` makes before the first run, naming Python's arguments; the
/// reference planner resolved (`"default"`: the CLI's default, `None`: none).
fn prepare(
    scenario: &Scenario,
    planners: &[String],
    runs: u64,
    seed: u64,
    budget: &RunBudget,
    reference: Option<&str>,
) -> Result<Option<String>, Error> {
    tidepath_experiments::compare::check_runs(runs).map_err(|e| e.for_field("runs"))?;
    if let Some(id) = budget.smoother.as_ref().map(|s| s.id.as_str()).filter(|id| *id != "none") {
        tidepath::smoothing::registry().get(id).map_err(|e| e.for_field("smoother"))?;
    }
    let reference = match reference {
        None | Some("none") => None,
        Some("default") => Some(default_reference(scenario).to_string()),
        Some(id) => Some(id.to_string()),
    };
    for p in planners {
        tidepath::planner::registry().get(p).map_err(|e| e.for_field("planners"))?;
        scenario.check_request(&request(budget, p, seed))?;
    }
    if let Some(id) = &reference {
        let r = RunBudget { time_limit_s: budget.time_limit_s, ..RunBudget::default() };
        scenario.check_request(&request(&r, id, seed)).map_err(|e| e.for_field("reference"))?;
    }
    Ok(reference)
}

/// Runs `compare` (or one share of it) on `jobs` threads, interruptible.
#[allow(clippy::too_many_arguments)]
fn run(
    py: Python<'_>,
    scenario: &Scenario,
    planners: &[String],
    runs: u64,
    seed: u64,
    budget: &RunBudget,
    reference: Option<&str>,
    jobs_requested: Option<usize>,
    share: Option<Share>,
) -> PyResult<tidepath_experiments::compare::Comparison> {
    let reference = prepare(scenario, planners, runs, seed, budget, reference).map_err(err)?;
    let jobs = crate::fork::pool_jobs(jobs(jobs_requested).map_err(err)?);
    let stop = Arc::new(AtomicBool::new(false));
    let c = interruptible(py, &stop, || {
        let control = RunControl { jobs, stop: Some(&stop), on_done: &|_| {} };
        compare_share(scenario, planners, runs, seed, budget, control, reference.as_deref(), share)
    })?;
    c.map_err(err)
}

/// A whole comparison, as `tidepath compare ... --out DIR` writes `DIR/results.json`.
#[pyfunction]
#[pyo3(signature = (scenario, planners, runs, seed, budget, reference, jobs = None))]
#[allow(clippy::too_many_arguments)]
pub fn compare_json(
    py: Python<'_>,
    scenario: &Bound<'_, PyScenario>,
    planners: Vec<String>,
    runs: u64,
    seed: u64,
    budget: &str,
    reference: Option<String>,
    jobs: Option<usize>,
) -> PyResult<String> {
    let b = self::budget(budget).map_err(err)?;
    let c = run(py, &scenario.get().inner, &planners, runs, seed, &b, reference.as_deref(), jobs, None)?;
    Ok(output::results_json(&c))
}

/// Share `k` of `n` of a comparison (`compare --shard K/N`), on a scenario given as TOML text
/// and its source, on one thread: its shard `results.json` text. An executor's task.
#[pyfunction]
#[pyo3(signature = (toml, source, planners, runs, seed, budget, reference, k, n))]
#[allow(clippy::too_many_arguments)]
pub fn compare_share_json(
    py: Python<'_>,
    toml: &str,
    source: &str,
    planners: Vec<String>,
    runs: u64,
    seed: u64,
    budget: &str,
    reference: Option<String>,
    k: u64,
    n: u64,
) -> PyResult<String> {
    let scenario = Scenario::from_toml(toml, source).map_err(err)?;
    let b = self::budget(budget).map_err(err)?;
    let share = Share::parse(&format!("{k}/{n}")).map_err(err)?;
    let c = run(py, &scenario, &planners, runs, seed, &b, reference.as_deref(), Some(1), Some(share))?;
    let file = ShardFile { shard: Some(ShardInfo::new(share, &c, &scenario)), comparison: c };
    Ok(file.json())
}

/// Joins shard `results.json` texts into the comparison one run makes (the library's
/// `shard::merge`, as `tidepath merge`): its `results.json` text.
#[pyfunction]
pub fn merge_json(shards: Vec<String>) -> PyResult<String> {
    let parts = shards
        .iter()
        .enumerate()
        .map(|(i, text)| {
            let file: ShardFile = serde_json::from_str(text)
                .map_err(|e| Error::input("shards", format!("task {} returned no shard results.json: {e}", i + 1)))?;
            Ok(ShardResults { dir: format!("task {}", i + 1), file })
        })
        .collect::<Result<Vec<_>, Error>>()
        .map_err(err)?;
    let (c, _) = shard::merge(&parts).map_err(err)?;
    Ok(output::results_json(&c))
}
