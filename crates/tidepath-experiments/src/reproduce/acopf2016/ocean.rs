//! Not in the paper: ACOPF and ACO where an engineer would use them, `glider-ocean` (200 x 200
//! cells of 0.02 degrees off Nihoa, waves and currents from a synthetic forecast file), beside
//! A*'s quickest and shortest paths on the same cells. The ants run at the paper's setting
//! (Q/L, objective = length) and rewarding travel time (objective = cost); the table gives each
//! one's gap to the optimum and its time per run.

use super::super::{ExperimentOutcome, PaperTable, ReproduceOptions};
use super::paper::{COST_OBJECTIVE, PAPER_OBJECTIVE, PLANNERS};
use super::runs::{astar_optimum, budget, measures, run_setting};
use super::tables::{gaps, median_iqr, median_iqr_with, pct, LEGEND};
use super::verdicts::{of, successful};
use crate::compare::{comparison_of, Comparison};
use tidepath::error::Result;

/// The experiment's id in the report.
pub const ID: &str = "ocean-glider-ocean";
/// The scenario.
pub const SCENARIO: &str = "glider-ocean";

pub fn experiment(opts: &ReproduceOptions, progress: &(dyn Fn(usize) + Sync)) -> Result<ExperimentOutcome> {
    let s = tidepath_io::scenario::load(SCENARIO)?;
    let budget = budget(opts);
    let half = PLANNERS.len() * opts.runs as usize;
    let paper = run_setting(std::slice::from_ref(&s), PAPER_OBJECTIVE, &budget, opts, progress)?;
    let cost = run_setting(std::slice::from_ref(&s), COST_OBJECTIVE, &budget, opts, &|n| progress(half + n))?;
    let complete = paper.complete && cost.complete;
    let time = if complete { astar_optimum(&s, "time", opts)? } else { None };
    let length = if complete { astar_optimum(&s, "length", opts)? } else { None };
    let (t_star, l_star) =
        (time.as_ref().and_then(|o| o.reference.travel_time_s), length.as_ref().and_then(|o| o.reference.length_m));
    let mut table = String::from(
        "| planner | ants' objective | success | travel time (s) | gap to A* time (%) | length (m) | gap to A* \
         length (%) | time per run (s) |\n|---|---|---|---|---|---|---|---|\n",
    );
    for (objective, c) in [(PAPER_OBJECTIVE, &paper), (COST_OBJECTIVE, &cost)] {
        let ms = measures(c, &s.name, &s.world);
        for p in PLANNERS {
            let t = successful(&ms, p, |m| m.time);
            let l = successful(&ms, p, |m| m.length);
            let secs: Vec<f64> = c.records.iter().filter(|r| r.planner == p).map(|r| r.elapsed_s).collect();
            table += &format!(
                "| {p} | {objective} | {} of {} | {} | {} | {} | {} | {} |\n",
                of(&ms, p).filter(|m| m.success).count(),
                of(&ms, p).count(),
                median_iqr(&t),
                median_iqr_with(&gaps(&t, t_star), pct),
                median_iqr(&l),
                median_iqr_with(&gaps(&l, l_star), pct),
                median_iqr(&secs),
            );
        }
    }
    let mut notes = Vec::new();
    for (what, o) in [("quickest", &time), ("shortest", &length)] {
        if let Some(o) = o {
            notes.push(format!(
                "A*'s {what} path on the same cells: {} s, {} m ({}).",
                o.reference.travel_time_s.map_or("—".into(), crate::table::num),
                o.reference.length_m.map_or("—".into(), crate::table::num),
                if o.optimal { "optimal on the cells".to_string() } else { o.reference.status.clone() }
            ));
        }
    }
    Ok(ExperimentOutcome {
        id: ID.into(),
        title: format!("Not in the paper: a forecast-driven ocean (`{SCENARIO}`), gap to A*'s optimum"),
        setup: format!(
            "`{SCENARIO}`: 200 x 200 cells of 0.02 degrees off Nihoa; significant wave height and surface current \
             from a synthetic NetCDF forecast (scripts/make_acopf2016_scenarios.py); the glider's travel time is \
             the scenario's cost. ACOPF and ACO at the paper's T and K, {} runs each, once with the paper's Q/L \
             (objective = length) and once rewarding travel time (objective = cost); A* on the same cells for \
             the optima. Time per run is wall time on this machine, runs side by side with --jobs.",
            opts.runs
        ),
        comparison: {
            // A*'s quickest path is the gap column's reference and the plan view's dashed line.
            let mut c = merged(paper, cost);
            super::environment::set_reference(&mut c, &s, time.as_ref(), opts)?;
            c
        },
        paper: PaperTable { source: "none (tidepath's experiment)".into(), runs: None, cells: Vec::new() },
        claims: Vec::new(),
        notes,
        tables: vec![(format!("Gap to the optimum on a forecast\n\n{LEGEND}"), table)],
        scenario: Some(s),
    })
}

/// The two settings' runs as one comparison for results.json: the cost setting's planners
/// renamed `acopf (objective = cost)` and so on, so the summary rows keep them apart.
fn merged(paper: Comparison, cost: Comparison) -> Comparison {
    let renamed = |p: &str| format!("{p} (objective = cost)");
    let mut planners = paper.planners.clone();
    planners.extend(cost.planners.iter().map(|p| renamed(p)));
    let mut records = paper.records;
    records.extend(cost.records.into_iter().map(|mut r| {
        r.planner = renamed(&r.planner);
        r
    }));
    let planned = planners.len() * paper.problems.len() * paper.runs as usize;
    let mut c = comparison_of(
        "scenario",
        paper.problems,
        &planners,
        (paper.runs, paper.master_seed),
        paper.budget,
        records,
        planned,
        paper.total_wall_s + cost.total_wall_s,
    );
    c.complete &= paper.complete && cost.complete;
    c
}
