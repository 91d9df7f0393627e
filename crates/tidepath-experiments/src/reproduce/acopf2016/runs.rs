//! The runs behind every table and figure of acopf2016: `acopf` and `aco` on the environments'
//! built-in scenarios, with the ants' objective set in their parameters (the paper's path
//! length, or the scenario's cost model: the glider's travel time), each run seeded by (master
//! seed, scenario, planner, run index) whatever `--jobs`; `astar` on the same raster for the
//! optima; and what we measure on each run's path beyond its record.

use std::time::Instant;

use super::super::ReproduceOptions;
use super::paper::{ANTS, ITERATIONS, PLANNERS, QUICK_ANTS, QUICK_ITERATIONS};
use crate::compare::{comparison_of, record_of, request, Comparison, Reference, RunBudget};
use crate::runner::{execute, tasks, RunControl, Task};
use crate::RunRecord;
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::optim::StopReason;
use tidepath::world::{Current, Terrain, World};
use tidepath_io::scenario::Scenario;

/// The run budget: the paper's T = 60 iterations, or `--quick`'s (the ants K are a planner
/// parameter: [`ants`]).
pub fn budget(opts: &ReproduceOptions) -> RunBudget {
    let iterations = if opts.quick { QUICK_ITERATIONS } else { ITERATIONS };
    RunBudget { iterations: Some(iterations), time_limit_s: opts.time_limit_s, ..RunBudget::default() }
}

/// Ants K per iteration: the paper's 30, or `--quick`'s.
pub fn ants(opts: &ReproduceOptions) -> usize {
    if opts.quick {
        QUICK_ANTS
    } else {
        ANTS
    }
}

/// `scenario` with `planner`'s `objective` parameter set.
pub fn with_objective(scenario: &Scenario, planner: &str, objective: &str) -> Scenario {
    let mut s = scenario.clone();
    s.planner.params.entry(planner.to_string()).or_default().insert("objective".into(), objective.into());
    s
}

/// Runs [`PLANNERS`] on every scenario with the ants' `objective`, `opts.runs` runs each; runs
/// cut short by Ctrl-C are left out (the comparison says how many finished).
pub fn run_setting(
    scenarios: &[Scenario],
    objective: &str,
    budget: &RunBudget,
    opts: &ReproduceOptions,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<Comparison> {
    let planners: Vec<String> = PLANNERS.iter().map(|p| p.to_string()).collect();
    // Every (scenario, planner) setting built and checked before any run.
    let mut set: Vec<(String, String, Scenario)> = Vec::new();
    for s in scenarios {
        for p in &planners {
            let mut s = with_objective(s, p, objective);
            let k = i64::try_from(ants(opts)).unwrap_or(i64::MAX);
            s.planner.params.entry(p.clone()).or_default().insert("ants".into(), k.into());
            s.check_request(&request(budget, p, 0))?;
            set.push((s.name.clone(), p.clone(), s));
        }
    }
    let problems: Vec<String> = scenarios.iter().map(|s| s.name.clone()).collect();
    let all = tasks(opts.master_seed, &problems, &planners, opts.runs);
    let run_one = |t: &Task| -> Result<RunRecord> {
        let (_, _, s) = set
            .iter()
            .find(|(n, p, _)| *n == t.problem && *p == t.planner)
            .ok_or_else(|| Error::input("scenario", format!("`{}` was not set up", t.problem)))?;
        let mut req = request(budget, &t.planner, t.seed);
        req.stop = opts.stop.clone();
        Ok(record_of(t, s.plan(&req, &mut |_| {})?))
    };
    let start = Instant::now();
    let control = RunControl { jobs: opts.jobs, stop: opts.stop.as_ref(), on_done: progress };
    let records = execute(&all, control, run_one)?;
    let planned = records.len();
    let records: Vec<_> = records.into_iter().flatten().filter(|r| r.stop_reason != StopReason::Cancelled).collect();
    Ok(comparison_of(
        "scenario",
        problems,
        &planners,
        (opts.runs, opts.master_seed),
        budget.clone(),
        records,
        planned,
        start.elapsed().as_secs_f64(),
    ))
}

/// A*'s optimum: its path as a reference, and whether A* says it is optimal for the objective
/// on its graph (with `objective = time` its status is `feasible`, since it optimises time,
/// not the scenario's cost; its reason says "optimal for travel time on ... raster").
#[derive(Clone, Debug, PartialEq)]
pub struct Optimum {
    pub reference: Reference,
    pub optimal: bool,
    pub reason: String,
}

impl Optimum {
    /// `astar, objective = OBJ (optimal on the cells)`, or with its status when not optimal.
    pub fn label(&self, objective: &str) -> String {
        let how = if self.optimal { "optimal on the cells".to_string() } else { self.reference.status.clone() };
        format!("astar, objective = {objective} ({how})")
    }
}

/// A* on the scenario's own cells with `objective` (`time` or `length`), run once (master
/// seed); `None` when it plans nothing or is stopped.
pub fn astar_optimum(scenario: &Scenario, objective: &str, opts: &ReproduceOptions) -> Result<Option<Optimum>> {
    let s = with_objective(scenario, "astar", objective);
    let budget = RunBudget { time_limit_s: opts.time_limit_s, ..RunBudget::default() };
    let mut req = request(&budget, "astar", opts.master_seed);
    req.stop = opts.stop.clone();
    let r = s.plan(&req, &mut |_| {})?;
    if !r.status.is_success() || r.stop_reason == StopReason::Cancelled {
        return Ok(None);
    }
    let reason = r.missions.first().map(|m| m.reason.clone()).unwrap_or_default();
    let what = if objective == "time" { "travel time" } else { objective };
    Ok(Some(Optimum {
        optimal: r.status.id() == "exact" || reason.contains(&format!("optimal for {what}")),
        reason,
        reference: Reference {
            planner: "astar".into(),
            status: r.status.id().to_string(),
            cost: r.cost_value(),
            length_m: r.length_m(),
            travel_time_s: r.travel_time_s(),
            waypoints: r
                .missions
                .first()
                .map(|m| m.points().iter().map(|p| p.to_array()).collect())
                .unwrap_or_default(),
        },
    }))
}

/// What one run gives the tables and the claims.
#[derive(Clone, Debug, PartialEq)]
pub struct Measure {
    pub planner: String,
    pub run: u64,
    /// Reached the goal on a feasible path.
    pub success: bool,
    /// Path length (m) and the glider's travel time (s) of the final path, from the plan's
    /// evaluation; NaN without a path.
    pub length: f64,
    pub time: f64,
    /// The iteration at which the run's final best was first found; NaN without a history.
    pub converged: f64,
    /// Along the path (by length): the mean wave height (m), the share in the grid's western
    /// half (x <= 10 cells), and the share inside the current band (`None` without a current).
    pub wave_mean: f64,
    pub west_share: f64,
    pub band_share: Option<f64>,
    /// The path's points, rounded to micrometres: equal keys are the same path.
    pub key: Vec<[i64; 2]>,
}

/// The iteration at which `history`'s last value was first reached: `history[i]` is the best
/// after iteration i + 1, or after initialisation then iteration i when it holds one value
/// more than `iterations`. `None` when nothing was ever found.
pub fn converged_at(history: &[Option<f64>], iterations: u64) -> Option<u64> {
    let last = history.iter().rev().find_map(|h| *h)?;
    let first = history.iter().position(|h| *h == Some(last))?;
    let offset = u64::from(history.len() as u64 > iterations);
    Some(first as u64 + 1 - offset)
}

/// The measures of run `r` on `world`.
pub fn measure(r: &RunRecord, world: &World) -> Measure {
    let success = r.feasible && r.status.is_some_and(|s| s.is_success()) && r.goal_distance_m().is_none();
    let points: Vec<Vec3> = r.waypoints.iter().map(|p| Vec3::from_array(*p)).collect();
    let along = along_path(&points, world);
    Measure {
        planner: r.planner.clone(),
        run: r.run,
        success,
        length: r.length_m.unwrap_or(f64::NAN),
        time: r.travel_time_s.unwrap_or(f64::NAN),
        converged: converged_at(&r.history, r.iterations).map_or(f64::NAN, |i| i as f64),
        wave_mean: along.wave_mean,
        west_share: along.west_share,
        band_share: along.band_share,
        key: key_of(&points),
    }
}

pub fn key_of(points: &[Vec3]) -> Vec<[i64; 2]> {
    points.iter().map(|p| [(p.x * 1e6).round() as i64, (p.y * 1e6).round() as i64]).collect()
}

/// Length-weighted means along a path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Along {
    pub wave_mean: f64,
    pub west_share: f64,
    pub band_share: Option<f64>,
}

/// Pieces per segment for [`along_path`]: a step between two cell centres is at most one
/// diagonal, so 64 pieces put the share's error below 2 % of a cell.
const PIECES: usize = 64;

/// The mean wave height (at time 0: the environments are steady), the share of length west of
/// the grid's middle, and the share in the current band along `points`. The band is the set
/// of cells whose centre has a current (a point belongs to the cell that holds it); on a world
/// not given cell by cell, the current at the point itself decides.
pub fn along_path(points: &[Vec3], world: &World) -> Along {
    let has_current = |p: Vec3| world.current.velocity(p, 0.0).length() > 1e-12;
    let cells = match &world.terrain {
        Terrain::Cells(c) => Some(c),
        _ => None,
    };
    let middle = cells.map_or((world.bounds.min.x + world.bounds.max.x) / 2.0, |c| c.x0 + c.dx * c.nx as f64 / 2.0);
    let in_band = |p: Vec3| match cells {
        Some(c) => {
            let i = (((p.x - c.x0) / c.dx).floor().max(0.0) as usize).min(c.nx - 1);
            let j = (((p.y - c.y0) / c.dy).floor().max(0.0) as usize).min(c.ny - 1);
            has_current(Vec3::new(c.x0 + c.dx * (i as f64 + 0.5), c.y0 + c.dy * (j as f64 + 0.5), p.z))
        }
        None => has_current(p),
    };
    let banded = !matches!(world.current, Current::None);
    let (mut total, mut wave, mut west, mut band) = (0.0, 0.0, 0.0, 0.0);
    for w in points.windows(2) {
        let ds = w[0].distance(w[1]) / PIECES as f64;
        for k in 0..PIECES {
            let p = w[0].lerp(w[1], (k as f64 + 0.5) / PIECES as f64);
            total += ds;
            wave += ds * world.waves.height(p, 0.0);
            if p.x <= middle {
                west += ds;
            }
            if banded && in_band(p) {
                band += ds;
            }
        }
    }
    if total == 0.0 {
        return Along { wave_mean: f64::NAN, west_share: f64::NAN, band_share: banded.then_some(f64::NAN) };
    }
    Along { wave_mean: wave / total, west_share: west / total, band_share: banded.then_some(band / total) }
}

/// The measures of a reference path (A*'s), labelled `planner`.
pub fn measure_reference(r: &Reference, planner: &str, world: &World) -> Measure {
    let points: Vec<Vec3> = r.waypoints.iter().map(|p| Vec3::from_array(*p)).collect();
    let along = along_path(&points, world);
    Measure {
        planner: planner.to_string(),
        run: 0,
        success: true,
        length: r.length_m.unwrap_or(f64::NAN),
        time: r.travel_time_s.unwrap_or(f64::NAN),
        converged: f64::NAN,
        wave_mean: along.wave_mean,
        west_share: along.west_share,
        band_share: along.band_share,
        key: key_of(&points),
    }
}

/// Every run's measures in `c` on `problem`, in record order (planner, then run).
pub fn measures(c: &Comparison, problem: &str, world: &World) -> Vec<Measure> {
    c.records.iter().filter(|r| r.problem == problem).map(|r| measure(r, world)).collect()
}
