//! Tables 1-3: IJS against JS, QPSO, PSO, HHO and MPA on the same encoding and cost (45
//! individuals, 38 interior points, T = 500 iterations), static and in the jet at 0.5, 0.8 and
//! 1.2 x the AUV's speed; the travel times of the successful runs beside the paper's, the
//! success rates, the time per run, and the current penalty F_p2 of Figs. 14-16.

use std::collections::BTreeMap;
use std::sync::Mutex;
use std::time::Instant;

use super::super::{Claim, ClaimVerdict, ExperimentOutcome, PaperTable, ReproduceOptions};
use super::paper::{Row, Setting, IJS_CURRENT_PENALTY, PLANNERS, PRINTED_SHORTEST};
use crate::compare::{comparison_of, gap_percent, record_of, request, run_reference, RunBudget};
use crate::runner::{execute, tasks, RunControl, Task};
use crate::stats::Summary;
use crate::table::num;
use tidepath::error::Result;
use tidepath::optim::pso::PsoParams;
use tidepath::optim::StopReason;
use tidepath_io::plan_json::PlanReport;
use tidepath_io::scenario::Scenario;

/// The paper's iterations per run, and `--quick`'s.
pub const ITERATIONS: u64 = 500;
pub const QUICK_ITERATIONS: u64 = 50;
pub const POPULATION: usize = 45;

/// What a run gives beyond its record: the paper's success test and its two measures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// F_p1 = 1 and the target reached (the ijs2023 cost's `safety` and `target` terms are 0),
    /// on every mission.
    pub success: bool,
    /// Travel time (s), eq. 17 (the scenarios' `vector-sum` model): the latest arrival.
    pub time_s: f64,
    /// The current penalty F_p2 (the `current` term over its weight c2), summed over the
    /// missions; `None` without a current.
    pub current_penalty: Option<f64>,
}

fn term(terms: &serde_json::Map<String, serde_json::Value>, name: &str) -> f64 {
    terms.get(name).and_then(|v| v.as_f64()).unwrap_or(f64::NAN)
}

/// The weight c2 of `scenario`'s ijs2023 cost (0 when not given).
pub(super) fn current_weight(scenario: &Scenario) -> f64 {
    scenario.cost.weights.get("w_current").and_then(|v| v.as_float()).unwrap_or(0.0)
}

/// The cost terms and the arrival time (s) of each mission of a plan.
pub(super) type MissionTerms<'a> = (&'a serde_json::Map<String, serde_json::Value>, f64);

/// The paper's measures of plan `r`.
pub(super) fn outcome_of(r: &PlanReport, c2: f64) -> Outcome {
    let missions: Vec<MissionTerms> =
        r.missions.iter().map(|m| (&m.cost_terms, m.times.last().copied().unwrap_or(f64::NAN))).collect();
    outcome_from(&missions, c2)
}

/// The paper's measures of a plan's missions.
pub(super) fn outcome_from(missions: &[MissionTerms], c2: f64) -> Outcome {
    let success =
        !missions.is_empty() && missions.iter().all(|(t, _)| term(t, "safety") == 0.0 && term(t, "target") == 0.0);
    let time_s = missions.iter().map(|m| m.1).fold(f64::NAN, f64::max);
    let current_penalty = (c2 > 0.0).then(|| missions.iter().map(|(t, _)| term(t, "current") / c2).sum());
    Outcome { success, time_s, current_penalty }
}

/// `scenario` with ijs2023's PSO setting (w 0.9 -> 0.4 over the run's iterations, c = 2,
/// v_max = 0.2 x the box width); the other planners keep their published defaults.
pub(super) fn with_pso_setting(scenario: &Scenario, iterations: u64) -> Scenario {
    let mut s = scenario.clone();
    s.planner.params.insert("pso".into(), PsoParams::ijs2023(iterations).to_table());
    s
}

/// Each run's [`Outcome`] by (planner, run index).
pub(super) type Outcomes = BTreeMap<(String, u64), Outcome>;

/// Runs every task of `planners` on `scenario` and keeps each run's [`Outcome`].
pub(super) fn run_all(
    scenario: &Scenario,
    planners: &[String],
    budget: &RunBudget,
    opts: &ReproduceOptions,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<(crate::compare::Comparison, Outcomes)> {
    for p in planners {
        scenario.check_request(&request(budget, p, 0))?;
    }
    let problems = vec![scenario.name.clone()];
    let all = tasks(opts.master_seed, &problems, planners, opts.runs);
    let c2 = current_weight(scenario);
    let outcomes = Mutex::new(BTreeMap::new());
    let run_one = |t: &Task| -> Result<crate::RunRecord> {
        let mut req = request(budget, &t.planner, t.seed);
        req.stop = opts.stop.clone();
        let r = scenario.plan(&req, &mut |_| {})?;
        outcomes.lock().expect("no run panics").insert((t.planner.clone(), t.run), outcome_of(&r, c2));
        Ok(record_of(t, r))
    };
    let start = Instant::now();
    let control = RunControl { jobs: opts.jobs, stop: opts.stop.as_ref(), on_done: progress };
    let records = execute(&all, control, run_one)?;
    let planned = records.len();
    let records: Vec<_> = records.into_iter().flatten().filter(|r| r.stop_reason != StopReason::Cancelled).collect();
    let c = comparison_of(
        "scenario",
        problems,
        planners,
        (opts.runs, opts.master_seed),
        budget.clone(),
        records,
        planned,
        start.elapsed().as_secs_f64(),
    );
    Ok((c, outcomes.into_inner().expect("no run panics")))
}

/// A planner's outcomes, in run order.
pub(super) fn of<'a>(outcomes: &'a Outcomes, planner: &str) -> Vec<&'a Outcome> {
    outcomes.iter().filter(|((p, _), _)| p == planner).map(|(_, o)| o).collect()
}

/// Mean and sample standard deviation (none for fewer than two values).
fn mean_std(v: &[f64]) -> (Option<f64>, Option<f64>) {
    let s = Summary::of(v);
    (s.map(|s| s.mean), s.filter(|s| s.n > 1).map(|s| s.std))
}

fn opt(v: Option<f64>) -> String {
    v.map_or("—".into(), num)
}

fn pct(x: f64) -> String {
    format!("{:.0} %", 100.0 * x)
}

/// Travel time with failed runs ranked after every successful one, for the rank-sum test
/// (a failure is worse than any success, whatever its time).
fn ranked_time(o: &Outcome) -> f64 {
    if o.success {
        o.time_s
    } else {
        1e12 + o.time_s
    }
}

/// One setting of Tables 1-3.
pub fn experiment(
    setting: &Setting,
    opts: &ReproduceOptions,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<ExperimentOutcome> {
    let iterations = if opts.quick { QUICK_ITERATIONS } else { ITERATIONS };
    let scenario = with_pso_setting(&tidepath_io::scenario::load(setting.scenario)?, iterations);
    let budget = RunBudget {
        iterations: Some(iterations),
        population: Some(POPULATION),
        time_limit_s: opts.time_limit_s,
        ..RunBudget::default()
    };
    let planners: Vec<String> = PLANNERS.iter().map(|s| s.to_string()).collect();
    let (mut c, outcomes) = run_all(&scenario, &planners, &budget, opts, progress)?;
    let reference = opts.reference.clone().map_or(Some("astar".to_string()), |r| (r != "none").then_some(r));
    c.reference_planner = reference.clone();
    if let (Some(r), true) = (reference.as_deref(), c.complete) {
        c.reference = run_reference(&scenario, r, opts.master_seed, &budget, opts.stop.clone())?;
        if let Some(r) = &c.reference {
            for row in &mut c.rows {
                row.gap_percent = row.feasible_mean.map(|m| gap_percent(m, r.cost));
                row.best_gap_percent = row.feasible_best.map(|b| gap_percent(b, r.cost));
            }
        }
    }
    let problem = c.problems[0].clone();
    let m = &scenario.missions[0];
    let straight_s = m.start.distance(m.goal) / m.vehicle.speed;

    // The side-by-side table of travel times.
    let mut table = String::from(
        "| planner | T_best (s) | paper | T_mean (s) | paper | STD (s) | paper | success | paper | T_best against the \
         straight line at still-water speed | s per run | paper (s) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for p in PLANNERS {
        let runs = of(&outcomes, p);
        let times: Vec<f64> = runs.iter().filter(|o| o.success).map(|o| o.time_s).collect();
        let best = times.iter().copied().fold(None, |b: Option<f64>, t| Some(b.map_or(t, |b| b.min(t))));
        let (mean, std) = mean_std(&times);
        let success = if runs.is_empty() { f64::NAN } else { times.len() as f64 / runs.len() as f64 };
        let wall: Vec<f64> = c.records_of(&problem, p).map(|r| r.elapsed_s).collect();
        let paper =
            setting.row_of(p).unwrap_or(Row { t_best: None, t_mean: None, std: None, success: 0.0, run_time_s: None });
        table += &format!(
            "| {p} | {} | {} | {} | {} | {} | {} | {} ({} of {}) | {} | {} | {} | {} |\n",
            opt(best),
            opt(paper.t_best),
            opt(mean),
            opt(paper.t_mean),
            opt(std),
            opt(paper.std),
            pct(success),
            times.len(),
            runs.len(),
            pct(paper.success),
            best.map_or("—".into(), |b| format!("{:+.1} %", 100.0 * (b / straight_s - 1.0))),
            opt(mean_std(&wall).0),
            opt(paper.run_time_s),
        );
    }
    let mut tables = vec![("Travel time of the successful runs, beside the paper's".to_string(), table)];

    // Figs. 14-16: the current penalty of the successful paths.
    let mut penalty: BTreeMap<&str, Vec<f64>> = BTreeMap::new();
    if setting.current {
        let mut t = String::from(
            "| planner | runs | min | 25 % | median | 75 % | max | mean |\n|---|---|---|---|---|---|---|---|\n",
        );
        for p in PLANNERS {
            let v: Vec<f64> = of(&outcomes, p).iter().filter(|o| o.success).filter_map(|o| o.current_penalty).collect();
            match Summary::of(&v) {
                Some(q) => {
                    t += &format!(
                        "| {p} | {} | {} | {} | {} | {} | {} | {} |\n",
                        q.n,
                        num(q.best),
                        num(q.q1),
                        num(q.median),
                        num(q.q3),
                        num(q.worst),
                        num(q.mean)
                    )
                }
                None => t += &format!("| {p} | 0 | — | — | — | — | — | — |\n"),
            }
            penalty.insert(p, v);
        }
        tables.push(("Current penalty F_p2 of the successful paths (the paper's box plots, Figs. 14-16)".into(), t));
    }

    // Claims: IJS's travel times below each baseline's, failures ranked last (the paper's
    // "lowest T_best and T_mean" and its success rates in one test).
    let ranked = |p: &str| of(&outcomes, p).iter().map(|o| ranked_time(o)).collect::<Vec<_>>();
    let mut claims: Vec<(Claim, ClaimVerdict)> = PLANNERS[1..]
        .iter()
        .map(|b| {
            let claim = Claim::lower(
                &problem,
                "ijs",
                b,
                format!("IJS finds quicker paths than {} ({}: lower T_best and T_mean, more successes; failed runs ranked last)", b.to_uppercase(), setting.source),
            );
            let v = claim.judge(&ranked("ijs"), &ranked(b));
            (claim, v)
        })
        .collect();
    if setting.current {
        let claim = Claim::lower(
            &problem,
            "ijs",
            "mpa",
            format!(
                "IJS's paths cross the current less than MPA's (lower F_p2 of the successful paths; {})",
                setting.source
            ),
        );
        let v = claim.judge(&penalty["ijs"], &penalty["mpa"]);
        claims.push((claim, v));
    }

    let mut notes = Vec::new();
    let successes = |p: &str| of(&outcomes, p).iter().filter(|o| o.success).count();
    let (ijs_ok, n) = (successes("ijs"), of(&outcomes, "ijs").len());
    notes.push(format!(
        "The paper: IJS succeeds in every run (100 %). Ours: {ijs_ok} of {n} — {}.",
        if ijs_ok == n && n > 0 { "reproduced" } else { "NOT reproduced" }
    ));
    let best_planner = |f: &dyn Fn(&[f64]) -> Option<f64>| {
        PLANNERS
            .iter()
            .filter_map(|p| {
                let t: Vec<f64> = of(&outcomes, p).iter().filter(|o| o.success).map(|o| o.time_s).collect();
                f(&t).map(|v| (*p, v))
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
    };
    let min = |t: &[f64]| t.iter().copied().reduce(f64::min);
    if let Some((p, v)) = best_planner(&min) {
        notes.push(format!(
            "The paper: IJS has the lowest T_best. Ours: {} has it ({} s) — {}.",
            p.to_uppercase(),
            num(v),
            if p == "ijs" { "reproduced" } else { "NOT reproduced" }
        ));
    }
    if let Some((p, v)) = best_planner(&|t: &[f64]| mean_std(t).0) {
        notes.push(format!(
            "The paper: IJS has the lowest T_mean. Ours: {} has it ({} s) — {}.",
            p.to_uppercase(),
            num(v),
            if p == "ijs" { "reproduced" } else { "NOT reproduced" }
        ));
    }
    if setting.id == "table3-strong-1.2" {
        let (h, mp) = (successes("hho"), successes("mpa"));
        notes.push(format!(
            "The paper: HHO and MPA never succeed at 1.2 x the AUV's speed. Ours: HHO {h} and MPA {mp} of {n} — {}.",
            if h == 0 && mp == 0 { "reproduced" } else { "NOT reproduced" }
        ));
    }
    if setting.id == "table2-current" {
        let v = &penalty["ijs"];
        let (lo, hi) = IJS_CURRENT_PENALTY;
        if let (Some(a), Some(b)) = (v.iter().copied().reduce(f64::min), v.iter().copied().reduce(f64::max)) {
            notes.push(format!(
                "The paper's IJS current penalty lies in [{lo}, {hi}] (Fig. 14); ours in [{}, {}].",
                num(a),
                num(b)
            ));
        }
    }
    if setting.id == "table1-static" {
        let (d, t) = PRINTED_SHORTEST;
        notes.push(format!(
            "The paper's printed shortest time is its printed distance over 1.542 m/s ({} s = {} m / 1.542 m/s: \
             reproduced). Its distance cannot come from its coordinates (A14): the straight line from start to goal \
             is {} m here, {} s at 1.542 m/s, the bound the gap column measures against (it ignores the seabed, the \
             threats and eq. 14).",
            num(t),
            num(d),
            num(m.start.distance(m.goal)),
            num(straight_s)
        ));
    }
    if let Some(r) = &c.reference {
        notes.push(format!(
            "The cost gap column is against {} on the world's raster (cost {}, travel time {} s): {}; it does not \
             keep eq. 14's window, so its last move to the goal usually pays the target penalty.",
            r.planner,
            num(r.cost),
            opt(r.travel_time_s),
            if setting.current {
                "the jet changes in time, so it is a reference, not an optimum"
            } else {
                "exact on its 26-connected graph for the time term"
            }
        ));
    }
    Ok(ExperimentOutcome {
        id: setting.id.into(),
        title: format!("{} (`{}`)", setting.title, setting.scenario),
        setup: format!(
            "The built-in scenario `{}`: the paper's area and start and goal over a synthetic seamount field with two \
             radar cylinders, two spheres and two boxes (the paper's DEM and threat values are not available; \
             docs/papers/ijs2023.md A10). 38 interior points on planes across x with eq. 14's window (1665 m sideways, \
             325 m vertically between planes), the ijs2023 cost (eqs. 15-24; c1 = {}, c2 = {}), eq. 17's travel \
             time. {POPULATION} individuals, {iterations} iterations per run{}, {} runs per planner. IJS and JS as \
             in docs/papers/ijs2023.md; PSO with w 0.9 -> 0.4, c1 = c2 = 2, v_max = 0.2 x the box width; QPSO, HHO \
             and MPA with their published defaults (the paper prints none, A13). A run succeeds when its path is \
             safe (F_p1 = 1) and its last move reaches the goal within the window (F_p3 = 0).",
            setting.scenario,
            1.0 - current_weight(&scenario),
            current_weight(&scenario),
            if opts.quick { " (--quick: a tenth of the paper's 500)" } else { "" },
            opts.runs
        ),
        comparison: c,
        paper: PaperTable { source: setting.source.into(), runs: Some(20), cells: Vec::new() },
        claims,
        notes,
        tables,
        scenario: Some(scenario),
    })
}
