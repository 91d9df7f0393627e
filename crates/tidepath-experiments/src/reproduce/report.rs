//! REPORT.md: our numbers beside the paper's, the figures, and a verdict per claim.

use std::fmt::Write as _;
use std::path::Path;

use super::{ClaimVerdict, ExperimentOutcome, Paper, ReproduceOptions};
use crate::columns::{render, Column};
use crate::output;
use crate::stats::smallest_p_any;
use crate::table::{num, ALPHA};
use tidepath::error::Result;
use tidepath_io::Outputs;

/// One cell of a paper's table: what the paper reports for a planner on a problem.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PaperCell {
    pub problem: String,
    pub planner: String,
    pub best: Option<f64>,
    pub mean: Option<f64>,
    pub std: Option<f64>,
    /// The paper's "0 times" column.
    pub zeros: Option<u32>,
    /// The worst run, when the paper prints it.
    pub worst: Option<f64>,
    /// The mean wall time per run (s), when the paper prints it (on its own machine).
    pub time_s: Option<f64>,
}

#[derive(Clone, Debug, Default)]
pub struct PaperTable {
    /// Where the numbers are printed, e.g. "amfa2015, Table 2".
    pub source: String,
    /// Runs per cell the paper reports (the denominator of its "0 times" column).
    pub runs: Option<u64>,
    pub cells: Vec<PaperCell>,
}

impl PaperTable {
    pub fn cell(&self, problem: &str, planner: &str) -> Option<&PaperCell> {
        self.cells.iter().find(|c| c.problem == problem && c.planner == planner)
    }
}

/// Does our mean agree with the paper's to within a factor of ten?
pub fn same_magnitude(paper: f64, ours: f64) -> bool {
    if paper == 0.0 || ours == 0.0 {
        return paper.abs() < 1e-300 && ours.abs() < 1e-300;
    }
    if paper.signum() != ours.signum() {
        return false;
    }
    (ours / paper).abs().log10().abs() <= 1.0
}

/// `k/N`, or `k` when the denominator is unknown.
fn of(k: impl std::fmt::Display, n: Option<impl std::fmt::Display>) -> String {
    n.map_or(k.to_string(), |n| format!("{k}/{n}"))
}

/// How many claims got each verdict, in the order the summary lists them.
#[derive(Default)]
struct Tally {
    total: usize,
    reproduced: usize,
    undecidable: usize,
    inconclusive: usize,
    contradicted: usize,
    not_run: usize,
}

impl Tally {
    fn of(outcomes: &[ExperimentOutcome]) -> Self {
        let mut t = Tally::default();
        for (_, v) in outcomes.iter().flat_map(|o| &o.claims) {
            t.total += 1;
            match v {
                ClaimVerdict::Reproduced { .. } => t.reproduced += 1,
                ClaimVerdict::Undecidable { .. } => t.undecidable += 1,
                ClaimVerdict::Inconclusive { .. } => t.inconclusive += 1,
                ClaimVerdict::Contradicted { .. } => t.contradicted += 1,
                ClaimVerdict::NotRun => t.not_run += 1,
            }
        }
        t
    }
}

/// The warning when we made fewer runs than the paper, saying whether any claim can be
/// decided at all with so few; `None` when we made at least as many.
fn fewer_runs_warning(runs: u64, paper_runs: Option<u64>) -> Option<String> {
    let paper = paper_runs.filter(|p| *p > runs)?;
    let n = runs as usize;
    let floor = smallest_p_any(n, n);
    let consequence = if floor >= ALPHA {
        format!(
            "With {runs} runs per planner the rank-sum test cannot reach p < {ALPHA} whatever the costs (the \
             smallest p it can return is {}), so no claim can be decided: every verdict is \"undecidable with \
             {runs} runs\", not a failure to reproduce.",
            num(floor)
        )
    } else {
        "Verdicts rest on fewer runs than the paper's: a real difference may not reach significance, and a claim \
         the test cannot decide at this sample size is marked undecidable."
            .to_string()
    };
    Some(format!(
        "> **Fewer runs than the paper**: {runs} runs per planner and problem; the paper reports {paper}. \
         {consequence} Rerun with `--runs {paper}` for the paper's sample size.\n"
    ))
}

/// The legend of every experiment's table and of the claims.
fn legend() -> String {
    [
        "*paper* columns are the paper's printed values, *ours* this run's, over all runs of each planner.",
        "×10: yes when our mean is within a factor of 10 of the paper's.",
        "\"0\" paper, f = 0 ours, f < 1e-300 ours: runs whose final value is exactly 0 (the paper's \"0 times\"), \
         and below 1e-300, of the runs made (the denominator after the slash).",
        "vs *first planner*: this row's planner against the experiment's first planner, two-sided Wilcoxon \
         rank-sum test at alpha 0.05: better / worse = significantly lower / higher values, ≈ = no significant \
         difference, undecidable = too few runs for any p below 0.05 (the smallest p the test can reach is \
         shown); ref = the first planner itself.",
        "Claims: reproduced = significant in the claimed direction; not reproduced = no significant difference \
         although these run counts could have shown one; NOT reproduced = significant the other way; \
         undecidable with N runs = no p below 0.05 is possible with N runs, whatever the costs.",
    ]
    .iter()
    .map(|l| format!("- {l}\n"))
    .collect()
}

/// Our table beside the paper's for one experiment.
fn experiment_table(o: &ExperimentOutcome) -> String {
    let c = &o.comparison;
    let rows = &c.rows;
    let cells = |f: &dyn Fn(&crate::table::PlannerRow) -> String| rows.iter().map(f).collect::<Vec<_>>();
    let paper = |f: fn(&PaperCell) -> Option<f64>| -> Vec<f64> {
        rows.iter().map(|r| o.paper.cell(&r.problem, &r.planner).and_then(f).unwrap_or(f64::NAN)).collect()
    };
    let ours = |f: fn(&crate::table::PlannerRow) -> f64| rows.iter().map(f).collect::<Vec<f64>>();
    let printed = |f: fn(&PaperCell) -> Option<f64>| o.paper.cells.iter().any(|c| f(c).is_some());
    let reference = c.planners.first().cloned().unwrap_or_default();
    let mut columns = vec![
        Column::new("problem", cells(&|r| r.problem.clone())),
        Column::new("planner", cells(&|r| r.planner.clone())),
        Column::numbers("best paper", paper(|p| p.best), 4),
        Column::numbers("best ours", ours(|r| r.best), 4),
    ];
    // Worst and time only where the paper prints them (amfa2015 does not).
    if printed(|p| p.worst) {
        columns.push(Column::numbers("worst paper", paper(|p| p.worst), 4));
        columns.push(Column::numbers("worst ours", ours(|r| r.worst), 4));
    }
    columns.extend([
        Column::numbers("mean paper", paper(|p| p.mean), 4),
        Column::numbers("mean ours", ours(|r| r.mean), 4),
        Column::new(
            "×10",
            cells(&|r| match o.paper.cell(&r.problem, &r.planner).and_then(|c| c.mean) {
                Some(pm) if same_magnitude(pm, r.mean) => "yes".into(),
                Some(_) => "no".into(),
                None => "—".into(),
            }),
        ),
        Column::numbers("std paper", paper(|p| p.std), 4),
        Column::numbers("std ours", ours(|r| r.std), 4),
    ]);
    if printed(|p| p.time_s) {
        columns.push(Column::numbers("time paper (s)", paper(|p| p.time_s), 4));
        columns.push(Column::numbers("time ours (s)", ours(|r| r.mean_wall_s), 4));
        // Runs that count no evaluations (a whole simulation is one run) have none to show.
        if c.records.iter().any(|r| r.evaluations > 0) {
            columns.push(Column::numbers("evaluations ours (mean)", ours(|r| r.mean_evaluations), 4));
        }
    }
    // The "0" columns count runs at a function's optimum; scenarios have none.
    if c.is_functions() {
        columns.extend([
            Column::new(
                "\"0\" paper",
                cells(&|r| {
                    o.paper
                        .cell(&r.problem, &r.planner)
                        .and_then(|c| c.zeros)
                        .map_or("—".into(), |z| of(z, o.paper.runs))
                }),
            ),
            Column::new("f = 0 ours", cells(&|r| of(r.zeros_exact, Some(r.runs)))),
            Column::new("f < 1e-300 ours", cells(&|r| of(r.zeros_tiny, Some(r.runs)))),
        ]);
    }
    // The marks, worded as in `compare`'s table.
    columns.push(Column::new(format!("vs {reference}"), crate::table::mark_cells(rows)));
    if c.reference.is_some() {
        let g = |v: Option<f64>| v.map_or("—".into(), |v| format!("{v:+.2}"));
        columns.push(Column::new(
            "gap % (best / mean, feasible runs)",
            cells(&|r| match r.feasible_runs {
                0 => crate::table::NO_FEASIBLE_RUN.to_string(),
                _ => format!("{} / {}", g(r.best_gap_percent), g(r.gap_percent)),
            }),
        ));
    }
    render(&columns)
}

/// Stages REPORT.md and each experiment's folder (tables and figures) into `out`.
pub(super) fn stage(
    out: &mut Outputs,
    paper: &Paper,
    opts: &ReproduceOptions,
    outcomes: &[ExperimentOutcome],
    dir: &Path,
    figures: &dyn output::FigureRenderer,
) -> Result<()> {
    let mut md = String::new();
    let _ = writeln!(md, "# Reproduction: {}\n", paper.description);
    let _ = writeln!(
        md,
        "Generated by `tidepath reproduce {} --runs {} --seed {}` (tidepath {}). Every number below was measured \
         by this run; nothing was tuned to match the paper.\n",
        paper.id,
        opts.runs,
        opts.master_seed,
        env!("CARGO_PKG_VERSION")
    );
    let interrupted = opts.stop.as_ref().is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed));
    if interrupted || outcomes.iter().any(|o| !o.comparison.complete) {
        let _ = writeln!(
            md,
            "> **Incomplete**: the run was interrupted (Ctrl-C). {} experiment(s) below have results; each \
             says how many of its runs finished. Claims are judged on the finished runs only.\n",
            outcomes.len()
        );
    }
    let paper_runs = outcomes.iter().filter_map(|o| o.paper.runs).max();
    if let Some(w) = fewer_runs_warning(opts.runs, paper_runs) {
        let _ = writeln!(md, "{w}");
    }
    let t = Tally::of(outcomes);
    let (mut mag_yes, mut mag_total) = (0, 0);
    for o in outcomes {
        for cell in &o.paper.cells {
            if let (Some(pm), Some(row)) =
                (cell.mean, o.comparison.rows.iter().find(|r| r.problem == cell.problem && r.planner == cell.planner))
            {
                mag_total += 1;
                mag_yes += same_magnitude(pm, row.mean) as usize;
            }
        }
    }
    let _ = writeln!(md, "## Summary\n");
    let _ = writeln!(
        md,
        "- Claims reproduced: **{} of {}** (two-sided Wilcoxon rank-sum, alpha {ALPHA}); undecidable with {} runs: \
         {}; not reproduced (no significant difference): {}; NOT reproduced (significantly the other way): {}{}.",
        t.reproduced,
        t.total,
        opts.runs,
        t.undecidable,
        t.inconclusive,
        t.contradicted,
        if t.not_run > 0 { format!("; not checked: {}", t.not_run) } else { String::new() }
    );
    let _ = writeln!(md, "- Means within a factor of 10 of the paper's: **{mag_yes} of {mag_total}** table cells.\n");
    let _ = writeln!(md, "## Legend\n\n{}", legend());

    for o in outcomes {
        let sub = dir.join(&o.id);
        output::stage_results(out, "--out", &sub, &o.comparison, o.scenario.as_ref(), figures)?;
        let _ = writeln!(md, "## {}\n", o.title);
        let _ = writeln!(md, "{}\n", o.setup);
        let paper_runs = o.paper.runs.map_or(String::new(), |n| format!(" ({n} runs per cell)"));
        let fewer = match o.paper.runs {
            Some(n) if n > o.comparison.runs => format!(", fewer than the paper's {n}"),
            _ => String::new(),
        };
        let _ = writeln!(
            md,
            "Paper values from {}{paper_runs}. Ours: {} runs per cell{fewer}.\n",
            o.paper.source, o.comparison.runs
        );
        let _ = writeln!(md, "{}\n", reference_line(&o.comparison));
        if let Some(note) = o.comparison.incomplete_note() {
            let _ = writeln!(md, "**{note}**\n");
        }
        md.push_str(&experiment_table(o));
        for (heading, table) in &o.tables {
            let _ = writeln!(md, "\n### {heading}\n\n{table}");
        }
        if !o.notes.is_empty() {
            let _ = writeln!(md, "\n### Findings\n");
            for n in &o.notes {
                let _ = writeln!(md, "- {n}");
            }
        }
        let _ = writeln!(md, "\n### Claims\n");
        for (claim, verdict) in &o.claims {
            let detail = match verdict {
                ClaimVerdict::Undecidable { p, smallest_p, .. } => format!(
                    " (p = {}; the smallest p the test can reach with these run counts is {}, not below {ALPHA})",
                    num(*p),
                    num(*smallest_p)
                ),
                v => v.p().map_or(String::new(), |p| format!(" (p = {})", num(p))),
            };
            let _ = writeln!(md, "- {}: **{}**{detail}", claim.text, verdict.label());
        }
        // Runs without a convergence history (a whole simulation is one run) have no curve to show.
        if o.comparison.records.iter().any(|r| !r.history.is_empty()) {
            let _ = writeln!(md, "\n![convergence]({}/convergence.svg)", o.id);
        }
        let _ = writeln!(md, "\n![final costs]({}/boxplot.svg)\n", o.id);
        if o.scenario.is_some() {
            let _ = writeln!(md, "![best path of each planner]({}/paths.svg)\n", o.id);
        }
    }
    out.stage_in("--out", dir, "REPORT.md", md.as_bytes())
}

/// One line saying what the gap column measures against, or why there is none.
fn reference_line(c: &crate::compare::Comparison) -> String {
    match (&c.reference, c.kind.as_str()) {
        (Some(r), _) => format!(
            "Gap to a reference: {} ({}, run once with its defaults), cost {}; gap % = 100 (cost - reference) / \
             reference, of the best and the mean cost over feasible runs.",
            r.planner,
            r.status,
            num(r.cost)
        ),
        (None, "functions") => "Gap to a reference: none applies; benchmark functions have a known optimum, f = 0, \
             and the \"0\" columns count the runs that reach it."
            .into(),
        (None, _) => "Gap to a reference: none (no reference was asked for, or it found no feasible plan).".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn magnitude_check() {
        assert!(same_magnitude(4.9e-6, 2.0e-5));
        assert!(!same_magnitude(4.9e-6, 2.0e-4));
        assert!(same_magnitude(0.0, 0.0));
        assert!(!same_magnitude(0.0, 1e-20));
        assert!(!same_magnitude(-1.0, 1.0));
    }

    /// An experiment on a scenario gets the gap column and says what it measures against; a
    /// benchmark-function experiment says why none applies.
    #[test]
    fn scenario_experiments_report_the_gap_to_their_reference() {
        use crate::compare::{compare_scenario, RunBudget};
        let scenario = tidepath_io::scenario::load("headland").unwrap();
        let opts = ReproduceOptions {
            runs: 2,
            master_seed: 3,
            jobs: 1,
            reference: None,
            stop: None,
            time_limit_s: None,
            quick: false,
            only: Vec::new(),
        };
        assert_eq!(opts.reference_for(&scenario).as_deref(), Some("visibility"));
        let none = ReproduceOptions { reference: Some("none".into()), ..opts.clone() };
        assert_eq!(none.reference_for(&scenario), None);
        let reference = opts.reference_for(&scenario);
        let c = compare_scenario(
            &scenario,
            &["astar".to_string(), "theta-star".to_string()],
            2,
            3,
            &RunBudget::default(),
            crate::runner::RunControl::jobs(1),
            reference.as_deref(),
        )
        .unwrap();
        assert!(c.reference.is_some(), "visibility plans headland");
        let outcome = |c: crate::compare::Comparison| ExperimentOutcome {
            id: "headland".into(),
            title: "Grid planners on headland".into(),
            setup: "two runs".into(),
            comparison: c,
            paper: PaperTable::default(),
            claims: Vec::new(),
            notes: Vec::new(),
            tables: Vec::new(),
            scenario: None,
        };
        let paper = Paper { id: "test", description: "test", citation: "", params: &[], build: |_, _| Ok(Vec::new()) };
        let dir = tempfile::tempdir().unwrap();
        let write = |o: ExperimentOutcome| {
            let mut out = Outputs::new();
            stage(&mut out, &paper, &opts, &[o], dir.path(), &output::NoFigures).unwrap();
            out.commit().unwrap();
        };
        write(outcome(c.clone()));
        let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
        assert!(md.contains("Gap to a reference: visibility ("), "{md}");
        assert!(md.contains("gap % (best / mean, feasible runs) |"), "{md}");
        // Grid paths are never shorter than the visibility graph's: A*'s gap is at least 0.
        let astar = md.lines().find(|l| l.starts_with("| headland | astar |")).unwrap();
        let gap = astar.rsplit('|').nth(1).unwrap().trim();
        assert!(!gap.starts_with('-') && gap.contains(" / +"), "{astar}");
        let mut f = c;
        f.kind = "functions".into();
        f.reference = None;
        write(outcome(f));
        let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
        assert!(md.contains("none applies") && !md.contains("gap %"), "{md}");
    }

    /// Two runs against the paper's 30: the report warns, says no claim can be decided, marks
    /// each claim undecidable (not "not reproduced"), and gives every "0" count its denominator.
    #[test]
    fn too_few_runs_make_claims_undecidable_and_the_report_says_why() {
        use crate::compare::from_records;
        use crate::reproduce::Claim;
        use crate::RunRecord;
        let f = |planner: &str, run: u64, cost: f64| RunRecord {
            problem: "sphere-d30-small".into(),
            planner: planner.into(),
            run,
            cost,
            feasible: true,
            ..RunRecord::default()
        };
        let records = vec![f("pso", 0, 0.0), f("pso", 1, 1e-9), f("ga", 0, 2.0), f("ga", 1, 3.0)];
        let c = from_records("functions", &["sphere-d30-small"], &["pso", "ga"], 2, records);
        let claim = Claim::lower("sphere-d30-small", "pso", "ga", "PSO reaches lower costs than GA on sphere".into());
        let verdict = claim.check(&c);
        // Fully separated and untied: exact p = 2 / C(4, 2) = 1/3, the smallest possible.
        assert_eq!(verdict, ClaimVerdict::Undecidable { p: 1.0 / 3.0, smallest_p: 1.0 / 3.0, runs: (2, 2) });
        assert_eq!(verdict.label(), "undecidable with 2 runs");
        let cell = |planner: &str, zeros| PaperCell {
            problem: "sphere-d30-small".into(),
            planner: planner.into(),
            best: Some(0.0),
            mean: Some(1e-3),
            std: Some(1e-3),
            zeros: Some(zeros),
            ..PaperCell::default()
        };
        let outcome = ExperimentOutcome {
            id: "t2".into(),
            title: "Table 2".into(),
            setup: "two runs".into(),
            comparison: c,
            paper: PaperTable {
                source: "amfa2015, Table 2".into(),
                runs: Some(30),
                cells: vec![cell("pso", 7), cell("ga", 0)],
            },
            claims: vec![(claim, verdict)],
            notes: Vec::new(),
            tables: Vec::new(),
            scenario: None,
        };
        let opts = ReproduceOptions {
            runs: 2,
            master_seed: 1,
            jobs: 1,
            reference: None,
            stop: None,
            time_limit_s: None,
            quick: false,
            only: Vec::new(),
        };
        let paper = Paper { id: "test", description: "test", citation: "", params: &[], build: |_, _| Ok(Vec::new()) };
        let dir = tempfile::tempdir().unwrap();
        let mut out = Outputs::new();
        stage(&mut out, &paper, &opts, &[outcome], dir.path(), &output::NoFigures).unwrap();
        out.commit().unwrap();
        let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
        for needle in [
            "**Fewer runs than the paper**: 2 runs per planner and problem; the paper reports 30.",
            // smallest_p_any(2, 2): the normal approximation's bound, 0.1939.
            "cannot reach p < 0.05 whatever the costs (the smallest p it can return is 0.1939)",
            "Claims reproduced: **0 of 1**",
            "undecidable with 2 runs: 1;",
            "Paper values from amfa2015, Table 2 (30 runs per cell). Ours: 2 runs per cell, fewer than the paper's 30.",
            "- PSO reaches lower costs than GA on sphere: **undecidable with 2 runs** (p = 0.3333; the smallest p",
            "## Legend",
            "the denominator after the slash",
        ] {
            assert!(md.contains(needle), "{needle} missing from\n{md}");
        }
        // pso: paper 7 of 30 runs at 0; ours 1 of 2 exactly 0 and 1 of 2 below 1e-300.
        let pso = md.lines().find(|l| l.starts_with("| sphere-d30-small | pso |")).unwrap();
        assert!(pso.contains("| 7/30 | 1/2 | 1/2 | ref |"), "{pso}");
        let ga = md.lines().find(|l| l.starts_with("| sphere-d30-small | ga |")).unwrap();
        assert!(ga.ends_with("| 0/30 | 0/2 | 0/2 | undecidable (p ≥ 0.33) |"), "{ga}");
    }
}
