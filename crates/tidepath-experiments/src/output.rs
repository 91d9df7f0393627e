//! The files `compare` and `bench functions` write into their output folder.

use std::path::Path;

use super::compare::Comparison;
use tidepath::error::Result;
use tidepath_io::scenario::Scenario;
use tidepath_io::{write_atomic, Outputs};

/// Fields that measure time and so differ between otherwise identical reruns.
pub const TIMING_FIELDS: &[&str] = &["elapsed_s", "mean_wall_s", "total_wall_s"];

pub fn results_json(c: &Comparison) -> String {
    serde_json::to_string_pretty(c).expect("comparison serialises") + "\n"
}

/// One row per run, through the one CSV writer.
pub fn runs_csv(c: &Comparison) -> Result<String> {
    use tidepath_io::csv_table::{row, text, writer};
    let mut w = writer();
    let header = [
        "problem",
        "planner",
        "run",
        "seed",
        "cost",
        "feasible",
        "length_m",
        "travel_time_s",
        "evaluations",
        "iterations",
        "elapsed_s",
        "stop_reason",
        "status",
        "expansions",
        "samples",
        "motion_checks",
        "goal_distance_m",
    ];
    row(&mut w, "runs.csv", header)?;
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v}"));
    for r in &c.records {
        let fields = [
            r.problem.clone(),
            r.planner.clone(),
            r.run.to_string(),
            r.seed.to_string(),
            r.cost.to_string(),
            r.feasible.to_string(),
            opt(r.length_m),
            opt(r.travel_time_s),
            r.evaluations.to_string(),
            r.iterations.to_string(),
            r.elapsed_s.to_string(),
            r.stop_reason.id().to_string(),
            r.status.map_or("", |s| s.id()).to_string(),
            r.expansions.to_string(),
            r.samples.to_string(),
            r.motion_checks.to_string(),
            opt(r.goal_distance_m()),
        ];
        row(&mut w, "runs.csv", fields)?;
    }
    text(w, "runs.csv")
}

/// Draws a comparison's figures. The plotting layer implements it and the command line passes
/// it in, so the experiments never import plotting.
pub trait FigureRenderer: Sync {
    /// The file names [`FigureRenderer::render`] gives, known before any run so that every
    /// output target is checked before the work starts; `scenario` says whether a map is drawn.
    fn names(&self, scenario: bool) -> Vec<&'static str>;
    /// (file name, SVG text) of every figure of `c`; `scenario` adds its map.
    fn render(&self, c: &Comparison, scenario: Option<&Scenario>) -> Result<Vec<(String, String)>>;
}

/// No figures (tables only).
pub struct NoFigures;

impl FigureRenderer for NoFigures {
    fn names(&self, _: bool) -> Vec<&'static str> {
        Vec::new()
    }

    fn render(&self, _: &Comparison, _: Option<&Scenario>) -> Result<Vec<(String, String)>> {
        Ok(Vec::new())
    }
}

/// The table files' names, in the order [`table_files`] gives them.
pub const TABLE_FILES: [&str; 3] = ["results.json", "runs.csv", "table.md"];

/// results.json, runs.csv and table.md (the Markdown table printed on stdout).
pub fn table_files(c: &Comparison) -> Result<Vec<(String, String)>> {
    let texts = [results_json(c), runs_csv(c)?, table_md(c)];
    Ok(TABLE_FILES.iter().zip(texts).map(|(n, t)| (n.to_string(), t)).collect())
}

/// The Markdown table with everything needed to read it, as `compare` and `bench functions`
/// print it: a note when the experiment is incomplete, the reference of the gap column, the
/// smoother, the table, and the legend.
pub fn table_md(c: &Comparison) -> String {
    use super::table::{legend, markdown, reference_line};
    let mut out = String::new();
    if let Some(note) = c.incomplete_note() {
        out.push_str(&format!("> **{note}**\n\n"));
    }
    if let Some(line) = reference_line(c) {
        out.push_str(&format!("{line}\n\n"));
    }
    if let Some(s) = &c.smoother {
        out.push_str(&format!("Smoother: every compared run's path went through {}.\n\n", s.describe()));
    }
    out.push_str(&markdown(c));
    out.push('\n');
    out.push_str(&legend(c));
    out
}

/// Declares every file of a results folder `dir` in `out`, so that a bad target is refused
/// before any run (the folder is created only when `out` is committed).
pub fn declare_results(
    out: &mut Outputs,
    flag: &str,
    dir: &Path,
    figures: &dyn FigureRenderer,
    scenario: bool,
) -> Result<()> {
    for name in TABLE_FILES.iter().copied().chain(figures.names(scenario)) {
        out.declare_in(flag, dir, name)?;
    }
    Ok(())
}

/// Fills the results folder `dir` in `out`: the tables and `figures` of `c`.
pub fn stage_results(
    out: &mut Outputs,
    flag: &str,
    dir: &Path,
    c: &Comparison,
    scenario: Option<&Scenario>,
    figures: &dyn FigureRenderer,
) -> Result<()> {
    stage_files(out, flag, dir, &table_files(c)?)?;
    stage_files(out, flag, dir, &figures.render(c, scenario)?)
}

/// Stages `files` (name, contents) into `dir` through `out`.
pub fn stage_files(out: &mut Outputs, flag: &str, dir: &Path, files: &[(String, String)]) -> Result<()> {
    for (name, text) in files {
        out.stage_in(flag, dir, name, text.as_bytes())?;
    }
    Ok(())
}

/// The tables and `figures` of `c` in `dir`: all files or none (the library entry point; the
/// command line declares its targets before running, then stages as here).
pub fn write_all(c: &Comparison, dir: &Path, scenario: Option<&Scenario>, figures: &dyn FigureRenderer) -> Result<()> {
    let mut out = Outputs::new();
    stage_results(&mut out, "--out", dir, c, scenario, figures)?;
    out.commit()
}

/// An OMPL benchmark log of the comparison, written safely.
pub fn write_ompl(c: &Comparison, path: &Path) -> Result<()> {
    write_atomic(path, ompl_log_text(c).as_bytes())
}

/// The text of an OMPL benchmark log of the comparison (one experiment per problem;
/// concatenated logs are not allowed by the format, so only the first problem is written;
/// `compare` has one).
pub fn ompl_log_text(c: &Comparison) -> String {
    use super::ompl_log::{write_ompl_log, OmplLogInfo};
    let problem = c.problems.first().cloned().unwrap_or_default();
    let host =
        std::fs::read_to_string("/etc/hostname").map(|h| h.trim().to_string()).unwrap_or_else(|_| "unknown".into());
    let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let setup = format!(
        "tidepath {} compare; planners {}; {} runs per planner; master seed {}; budget: {}",
        c.tidepath_version,
        c.planners.join(","),
        c.runs,
        c.master_seed,
        c.budget.describe()
    );
    let info = OmplLogInfo {
        experiment: &problem,
        host: &host,
        start_unix_s: now.saturating_sub(c.total_wall_s as u64),
        setup: &setup,
        cpu_info: None,
        master_seed: c.master_seed,
        time_limit_s: c.budget.time_limit_s,
        total_time_s: c.total_wall_s,
    };
    let planners: Vec<(&str, Vec<&super::RunRecord>)> =
        c.planners.iter().map(|p| (p.as_str(), c.records_of(&problem, p).collect())).collect();
    write_ompl_log(&info, &planners)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::{from_records, RunBudget, Smoothing};

    /// The OMPL log's setup states the budget in words, not as a Rust debug print.
    #[test]
    fn the_ompl_log_states_the_budget_readably() {
        let mut c = from_records("scenario", &["bay"], &["pso"], 1, Vec::new());
        c.budget = RunBudget {
            iterations: Some(20),
            time_limit_s: Some(5.0),
            smoother: Some(Smoothing { id: "shortcut".into(), params: Some(toml::toml! { passes = 2 }) }),
            ..RunBudget::default()
        };
        let log = ompl_log_text(&c);
        assert!(log.contains("budget: 20 iterations, time limit 5 s per run; smoother shortcut:passes=2\n"), "{log}");
        assert!(!log.contains("RunBudget") && !log.contains("Some("), "{log}");
        c.budget = RunBudget::default();
        assert!(ompl_log_text(&c).contains("budget: the scenario's and planners' defaults\n"));
    }
}
