//! The files `compare` and `bench functions` write into their output folder.

use std::fmt::Write as _;
use std::path::Path;

use super::compare::Comparison;
use crate::error::{Error, Result};
use crate::io::write_atomic;

/// Fields that measure time and so differ between otherwise identical reruns.
pub const TIMING_FIELDS: &[&str] = &["elapsed_s", "mean_wall_s", "total_wall_s"];

pub fn results_json(c: &Comparison) -> String {
    serde_json::to_string_pretty(c).expect("comparison serialises") + "\n"
}

/// One row per run.
pub fn runs_csv(c: &Comparison) -> String {
    let mut out = String::from(
        "problem,planner,run,seed,cost,feasible,length_m,travel_time_s,evaluations,iterations,elapsed_s,stop_reason\n",
    );
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v}"));
    for r in &c.records {
        let stop =
            serde_json::to_value(r.stop_reason).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default();
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{},{}",
            csv_field(&r.problem),
            csv_field(&r.planner),
            r.run,
            r.seed,
            r.cost,
            r.feasible,
            opt(r.length_m),
            opt(r.travel_time_s),
            r.evaluations,
            r.iterations,
            r.elapsed_s,
            stop
        );
    }
    out
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Creates `dir` (and parents) if needed.
pub fn ensure_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))
}

/// Writes results.json, runs.csv and table.md (the Markdown table printed on stdout) into `dir`.
pub fn write_tables(c: &Comparison, dir: &Path) -> Result<()> {
    ensure_dir(dir)?;
    write_atomic(&dir.join("results.json"), results_json(c).as_bytes())?;
    write_atomic(&dir.join("runs.csv"), runs_csv(c).as_bytes())?;
    write_atomic(&dir.join("table.md"), super::table::markdown(&c.rows, c.is_functions()).as_bytes())?;
    Ok(())
}

/// results.json, runs.csv, convergence.svg and boxplot.svg, plus paths.svg when the problem is
/// a scenario (its best path per planner over the map).
pub fn write_all(c: &Comparison, dir: &Path, scenario: Option<&crate::scenario::Scenario>) -> Result<()> {
    use crate::plot::experiment::{
        write_boxplot_figure, write_convergence_figure, write_paths_figure, PlannerRuns, ProblemRuns,
    };
    use crate::plot::PlotPath;
    write_tables(c, dir)?;
    let problems: Vec<ProblemRuns> = c
        .problems
        .iter()
        .map(|p| ProblemRuns {
            problem: p,
            planners: c
                .planners
                .iter()
                .map(|pl| PlannerRuns {
                    planner: pl,
                    costs: c.records_of(p, pl).map(|r| r.cost).collect(),
                    histories: c
                        .records_of(p, pl)
                        .map(|r| r.history.iter().map(|h| h.unwrap_or(f64::INFINITY)).collect())
                        .collect(),
                })
                .collect(),
        })
        .collect();
    let what = if c.is_functions() { "benchmark functions".to_string() } else { c.problems.join(", ") };
    let title = format!("{what}: {} runs per planner", c.runs);
    write_convergence_figure(
        &format!("Convergence — {title} (median and interquartile band)"),
        &problems,
        &dir.join("convergence.svg"),
    )?;
    write_boxplot_figure(&format!("Final cost — {title}"), &problems, &dir.join("boxplot.svg"))?;
    if let Some(s) = scenario {
        let best: Vec<(String, Vec<crate::geom::Vec3>)> = c
            .planners
            .iter()
            .filter_map(|pl| {
                c.records_of(&s.name, pl).min_by(|a, b| a.cost.total_cmp(&b.cost)).map(|r| {
                    let ok = if r.feasible { "feasible" } else { "infeasible" };
                    (
                        format!("{pl} (best cost {}, {ok})", super::table::num(r.cost)),
                        r.waypoints.iter().map(|p| crate::geom::Vec3::from_array(*p)).collect(),
                    )
                })
            })
            .collect();
        let paths: Vec<PlotPath> = best.iter().map(|(l, pts)| PlotPath::new(l.clone(), pts)).collect();
        write_paths_figure(
            &format!("{} — best path of each planner over {} runs", s.name, c.runs),
            &s.world,
            s.start,
            s.goal,
            s.departure_time,
            &paths,
            &dir.join("paths.svg"),
        )?;
    }
    Ok(())
}

/// An OMPL benchmark log of the comparison (one experiment per problem, concatenated logs are
/// not allowed by the format, so only the first problem is written; `compare` has one).
pub fn write_ompl(c: &Comparison, path: &Path) -> Result<()> {
    use super::ompl_log::{write_ompl_log, OmplLogInfo};
    let problem = c.problems.first().cloned().unwrap_or_default();
    let host =
        std::fs::read_to_string("/etc/hostname").map(|h| h.trim().to_string()).unwrap_or_else(|_| "unknown".into());
    let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let setup = format!(
        "tidepath {} compare; planners {}; {} runs per planner; master seed {}; budget {:?}",
        c.tidepath_version,
        c.planners.join(","),
        c.runs,
        c.master_seed,
        c.budget
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
    write_atomic(path, write_ompl_log(&info, &planners).as_bytes())
}
