//! Not in the paper: ACOPF and ACO with the ants depositing Q/C for C the scenario's cost of
//! their path (the glider's travel time) instead of the paper's Q/L, on all four environments,
//! beside A*'s quickest path. The paper's heuristic already steers by waves and current
//! (eq. 10); this asks what rewarding time itself adds.

use super::super::{ExperimentOutcome, PaperTable, ReproduceOptions};
use super::paper::{COST_OBJECTIVE, CURRENT_ENV, ENVIRONMENTS, PLANNERS, WAVES_ENV};
use super::runs::{astar_optimum, budget, measures, run_setting};
use super::tables::{gaps, iters, median_iqr, median_iqr_with, pct, versus, LEGEND};
use super::verdicts::{follows_waves, of, quicker, ranked, successful, uses_current};
use tidepath::error::Result;

/// The experiment's id in the report.
pub const ID: &str = "objective-cost";

pub fn experiment(opts: &ReproduceOptions, progress: &(dyn Fn(usize) + Sync)) -> Result<ExperimentOutcome> {
    let scenarios = ENVIRONMENTS.iter().map(|e| tidepath_io::scenario::load(e.scenario)).collect::<Result<Vec<_>>>()?;
    let budget = budget(opts);
    let c = run_setting(&scenarios, COST_OBJECTIVE, &budget, opts, progress)?;
    let mut table = String::from(
        "| environment | planner | success | travel time (s) | gap to A* time (%) | length (m) | iterations to \
         converge | mean wave height along the path (m) | share of length in the current band |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    let mut notes = Vec::new();
    for (index, s) in scenarios.iter().enumerate() {
        let ms = measures(&c, &s.name, &s.world);
        let optimum = if c.complete { astar_optimum(s, "time", opts)? } else { None };
        let t_star = optimum.as_ref().and_then(|o| o.reference.travel_time_s);
        for p in PLANNERS {
            let time = successful(&ms, p, |m| m.time);
            let len = successful(&ms, p, |m| m.length);
            let conv: Vec<f64> = of(&ms, p).map(|m| m.converged).collect();
            let mark = |values: &[f64], against: &[f64]| {
                if p == "acopf" {
                    String::new()
                } else {
                    format!("; {}", versus(values, against))
                }
            };
            let (rt, rt0) = (ranked(&ms, p, |m| m.time), ranked(&ms, "acopf", |m| m.time));
            let (rl, rl0) = (ranked(&ms, p, |m| m.length), ranked(&ms, "acopf", |m| m.length));
            let conv0: Vec<f64> = of(&ms, "acopf").map(|m| m.converged).collect();
            let (w, w0) = (successful(&ms, p, |m| m.wave_mean), successful(&ms, "acopf", |m| m.wave_mean));
            let band = |p: &str| successful(&ms, p, |m| m.band_share.unwrap_or(f64::NAN));
            let (b, b0) = (band(p), band("acopf"));
            let band_cell =
                if index == CURRENT_ENV { format!("{}{}", median_iqr(&b), mark(&b, &b0)) } else { "—".into() };
            let k = of(&ms, p).filter(|m| m.success).count();
            table += &format!(
                "| {} | {p} | {k} of {} | {}{} | {}{} | {}{} | {}{} | {}{} | {band_cell} |\n",
                s.name,
                of(&ms, p).count(),
                median_iqr(&time),
                mark(&rt, &rt0),
                median_iqr_with(&gaps(&time, t_star), pct),
                mark(&rt, &rt0),
                median_iqr(&len),
                mark(&rl, &rl0),
                median_iqr_with(&conv, iters),
                mark(&conv, &conv0),
                median_iqr(&w),
                mark(&w, &w0),
            );
        }
        if let Some(o) = &optimum {
            notes.push(format!(
                "{}: A*'s quickest path on the same cells takes {} s ({}).",
                s.name,
                o.reference.travel_time_s.map_or("—".into(), crate::table::num),
                if o.optimal {
                    "optimal on the cells".to_string()
                } else {
                    format!("{}, not proven optimal", o.reference.status)
                }
            ));
        }
        // The paper's claims 3, 5 and 6 in this setting, for comparison with the main tables.
        let problem = s.name.as_str();
        let mut judged = vec![quicker(problem, &ms)];
        if index == WAVES_ENV {
            judged.push(follows_waves(problem, &ms));
        }
        if index == CURRENT_ENV {
            judged.push(uses_current(problem, &ms));
        }
        for (claim, v) in judged {
            let p = v.p().map_or(String::new(), |p| format!(" (p = {})", crate::table::num(p)));
            notes.push(format!("{}, with the ants rewarding travel time: {}: {}{p}.", s.name, claim.text, v.label()));
        }
    }
    Ok(ExperimentOutcome {
        id: ID.into(),
        title: "Not in the paper: the ants rewarding travel time (objective = cost), all four environments".into(),
        setup: format!(
            "The four environments above with one change: ACOPF and ACO deposit Q/C with C the scenario's cost of the \
             ant's path (the glider's travel time) in eqs. 6 and 11-13 instead of Q/L (`objective = cost`); \
             everything else as above, {} runs per planner and environment, the same run seeds. The paper's \
             setting (objective = length) is the main table of each environment; this one is the variant.",
            opts.runs
        ),
        comparison: c,
        paper: PaperTable { source: "none (tidepath's variant)".into(), runs: None, cells: Vec::new() },
        claims: Vec::new(),
        notes,
        tables: vec![(format!("Travel time when the ants reward it\n\n{LEGEND}"), table)],
        scenario: None,
    })
}
