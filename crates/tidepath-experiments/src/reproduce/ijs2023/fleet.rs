//! Section IV-C (Fig. 17): three AUVs planned together by IJS, each choosing its speeds in
//! 0.5-4 knots, in the jet at 0.2 x the AUV's speed, to one goal; they must arrive together
//! and never meet. The paper gives no model for either rule (A15); tidepath's fleet rules
//! (`[fleet]`: arrival within 60 s, 100 m apart at every instant) stand in.

use super::super::{ExperimentOutcome, PaperTable, ReproduceOptions};
use super::paper::FLEET;
use super::tables::{of, run_all, with_pso_setting, ITERATIONS, POPULATION, QUICK_ITERATIONS};

/// IJS, as in the paper, and MPA beside it (ours: the baseline that did best in Tables 1-3
/// here), so a reader sees what the same budget reaches on this fleet.
pub const PLANNERS: [&str; 2] = ["ijs", "mpa"];
use crate::compare::RunBudget;
use crate::stats::Summary;
use crate::table::num;
use tidepath::error::Result;

pub const SCENARIO: &str = "ijs-fleet";

pub fn experiment(opts: &ReproduceOptions, progress: &(dyn Fn(usize) + Sync)) -> Result<ExperimentOutcome> {
    let iterations = if opts.quick { QUICK_ITERATIONS } else { ITERATIONS };
    let scenario = with_pso_setting(&tidepath_io::scenario::load(SCENARIO)?, iterations);
    let budget = RunBudget {
        iterations: Some(iterations),
        population: Some(POPULATION),
        time_limit_s: opts.time_limit_s,
        ..RunBudget::default()
    };
    let planners: Vec<String> = PLANNERS.iter().map(|p| p.to_string()).collect();
    let (c, outcomes) = run_all(&scenario, &planners, &budget, opts, progress)?;
    let problem = c.problems[0].clone();
    let (pa, ps, pp) = FLEET;
    let show = |s: Option<Summary>| {
        s.map_or("—".to_string(), |s| format!("{} (best {}, std {})", num(s.mean), num(s.best), num(s.std)))
    };
    let mut table = String::from("| measure | ijs | mpa (not in the paper) | paper (IJS) |\n|---|---|---|---|\n");
    let mut rows: Vec<Vec<String>> = vec![Vec::new(); 5];
    let mut notes = Vec::new();
    for p in PLANNERS {
        let runs = of(&outcomes, p);
        let records: Vec<_> = c.records_of(&problem, p).collect();
        // A fleet run succeeds when every vehicle's path is safe and reaches its goal (the
        // paper's test per vehicle) and the fleet keeps its rules (tidepath's verdict).
        let ok: Vec<bool> = runs.iter().zip(&records).map(|(o, r)| o.success && r.feasible).collect();
        let n = ok.len();
        let k = ok.iter().filter(|b| **b).count();
        let arrival: Vec<f64> = runs.iter().zip(&ok).filter(|(_, ok)| **ok).map(|(o, _)| o.time_s).collect();
        let penalty: Vec<f64> =
            runs.iter().zip(&ok).filter(|(_, ok)| **ok).filter_map(|(o, _)| o.current_penalty).collect();
        rows[0].push(format!("{:.0} % ({k} of {n})", 100.0 * k as f64 / n.max(1) as f64));
        rows[1].push(show(Summary::of(&arrival)));
        rows[2].push(show(Summary::of(&penalty)));
        rows[3].push(format!("{} of {n}", runs.iter().filter(|o| o.success).count()));
        rows[4].push(format!("{} of {n}", records.iter().filter(|r| r.feasible).count()));
        if p == "ijs" {
            notes.push(format!(
                "The paper: 65 % of IJS's fleet runs succeed. Ours: {k} of {n} ({:.0} %) — {}.",
                100.0 * k as f64 / n.max(1) as f64,
                if n > 0 && (k as f64 / n as f64 - ps).abs() <= 0.15 {
                    "close to it (within 15 points)"
                } else {
                    "not the paper's rate"
                }
            ));
            if let Some(s) = Summary::of(&arrival) {
                notes.push(format!(
                    "Common arrival: ours {} s on average, the paper {} s; the worlds differ (our seamounts and threats \
                     are synthetic), so only the order of magnitude can be compared.",
                    num(s.mean),
                    num(pa)
                ));
            }
        }
    }
    let paper = [format!("{:.0} %", 100.0 * ps), num(pa), num(pp), "—".into(), "—".into()];
    let names = [
        "success",
        "common arrival (s), successful runs",
        "total current penalty, successful runs",
        "safe and at the goal, every vehicle",
        "fleet rules kept (arrival, separation)",
    ];
    for ((name, ours), paper) in names.iter().zip(&rows).zip(&paper) {
        table += &format!("| {name} | {} | {paper} |\n", ours.join(" | "));
    }
    Ok(ExperimentOutcome {
        id: "fleet".into(),
        title: format!("Section IV-C: three AUVs arriving together (`{SCENARIO}`)"),
        setup: format!(
            "The built-in scenario `{SCENARIO}`: Fig. 17's three starts (3309 m deep) to goals 250 m apart \
             around the paper's common goal (one point would break any separation on arrival), each AUV choosing its segment speeds in 0.5-4 knots, the jet at 0.2 x 1.542 m/s, \
             the ijs2023 cost on each vehicle (c1 = 0.7, c2 = 0.3) and tidepath's fleet rules: arrival within 60 s, \
             100 m apart at every instant (the paper gives neither value, A15). IJS (and MPA, which the paper does not \
             run here) plans the three paths as one vector, {POPULATION} individuals, {iterations} iterations, {} \
             runs each.",
            opts.runs
        ),
        comparison: c,
        paper: PaperTable { source: "ijs2023, section IV-C and Fig. 17".into(), runs: Some(20), cells: Vec::new() },
        claims: Vec::new(),
        notes,
        tables: vec![("The fleet beside the paper".into(), table)],
        scenario: Some(scenario),
    })
}
