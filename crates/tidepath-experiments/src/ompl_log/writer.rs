//! Renders runs as OMPL log text: the header, the per-planner blocks and the run / progress values.

use std::fmt::{self, Write as _};

use super::format::{block, boolean, header_real, real, token, utc_date_time};
use super::OmplLogInfo;
use crate::RunRecord;
use tidepath::optim::StopReason;

/// Run properties, in the order their values are written. Names match OMPL's where the meaning
/// matches (so the columns are shared in a mixed database); `memory` is left out on purpose:
/// tidepath does not measure it and a 0 would be plotted as a measurement.
const RUN_PROPERTIES: [&str; 18] = [
    "time REAL",
    // Truly 0 (tidepath does not simplify paths), and needed: once an OMPL log has added this
    // column, the script's views compute `time + simplification_time`, NULL for a NULL here.
    "simplification time REAL",
    "solved BOOLEAN",
    "approximate solution BOOLEAN",
    "status ENUM",
    "solution length REAL",
    "solution segments INTEGER",
    "best cost REAL",
    "travel time REAL",
    "evaluations INTEGER",
    "iterations INTEGER",
    "stop_reason ENUM",
    "seed TEXT",
    // OMPL's name for an approximate solution's distance to the goal.
    "solution difference REAL",
    "expansions INTEGER",
    "samples INTEGER",
    // OMPL's "valid segment" checks: motions judged by the validator.
    "motion checks INTEGER",
    "graph states INTEGER",
];

/// The same progress columns as OMPL's RRT*, so Planner Arena's progress page overlays them.
const PROGRESS_PROPERTIES: [&str; 3] = ["time REAL", "iterations INTEGER", "best cost REAL"];

/// OMPL 2.0.1's `PlannerStatus` enum line, verbatim (its ABORT and INFEASIBLE print as
/// "Unknown status").
const STATUS_ENUM: &str = "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|\
                           Approximate solution|Exact solution|Crash|Unknown status|Unknown status";
const STATUS_INVALID_START: u8 = 1;
const STATUS_INVALID_GOAL: u8 = 2;
const STATUS_TIMEOUT: u8 = 4;
const STATUS_APPROXIMATE: u8 = 5;
const STATUS_EXACT: u8 = 6;
/// OMPL's ABORT (a run stopped by the caller) and INFEASIBLE (proved: no solution exist):
/// their names print as "Unknown status" in OMPL 2.0.1's enum line, but the values stay apart.
const STATUS_ABORT: u8 = 8;
const STATUS_INFEASIBLE: u8 = 9;

const STOP_REASON_ENUM: &str =
    "stop_reason|max iterations|max evaluations|wall time|max expansions|max samples|target cost|cancelled|completed";

fn stop_reason_value(reason: StopReason) -> u8 {
    // Indices into STOP_REASON_ENUM; a new variant must be added there too.
    match reason {
        StopReason::MaxIterations => 0,
        StopReason::MaxEvaluations => 1,
        StopReason::WallTime => 2,
        StopReason::MaxExpansions => 3,
        StopReason::MaxSamples => 4,
        StopReason::TargetCost => 5,
        StopReason::Cancelled => 6,
        StopReason::Completed => 7,
    }
}

/// Renders one experiment as an OMPL benchmark log.
///
/// Planner names get a `tidepath_` prefix, as OMPL's get `geometric_`, so they cannot collide
/// with OMPL planners in a shared database. A comparison over several problems needs one log
/// per problem; `ompl_benchmark_statistics` accepts many logs at once.
pub fn write_ompl_log(info: &OmplLogInfo, planners: &[(&str, Vec<&RunRecord>)]) -> String {
    let mut out = String::new();
    write_log(&mut out, info, planners).expect("formatting into a String cannot fail");
    out
}

fn write_log(out: &mut String, info: &OmplLogInfo, planners: &[(&str, Vec<&RunRecord>)]) -> fmt::Result {
    writeln!(out, "tidepath version {}", env!("CARGO_PKG_VERSION"))?;
    writeln!(out, "Experiment {}", token(info.experiment, "NO_NAME"))?;
    writeln!(out, "0 experiment properties")?;
    writeln!(out, "Running on {}", token(info.host, "UNKNOWN"))?;
    writeln!(out, "Starting at {}", utc_date_time(info.start_unix_s))?;
    write!(out, "<<<|\n{}|>>>\n", block(info.setup))?;
    if let Some(cpu) = info.cpu_info {
        write!(out, "<<<|\n{}|>>>\n", block(cpu))?;
    }
    writeln!(out, "{} is the random seed", info.master_seed)?;
    writeln!(out, "{} seconds per run", header_real(info.time_limit_s.unwrap_or(0.0)))?;
    // tidepath sets no memory limit; 0 is what the parser itself stores for MoveIt logs.
    writeln!(out, "0 MB per run")?;
    // Optional in the format; a single count is only true when every planner ran equally often.
    if let Some((_, first)) = planners.first() {
        if planners.iter().all(|(_, runs)| runs.len() == first.len()) {
            writeln!(out, "{} runs per planner", first.len())?;
        }
    }
    writeln!(out, "{} seconds spent to collect the data", header_real(info.total_time_s))?;
    writeln!(out, "2 enum types")?;
    writeln!(out, "{STATUS_ENUM}")?;
    writeln!(out, "{STOP_REASON_ENUM}")?;
    writeln!(out, "{} planners", planners.len())?;
    for (name, runs) in planners {
        write_planner(out, name, runs)?;
    }
    Ok(())
}

fn write_planner(out: &mut String, name: &str, runs: &[&RunRecord]) -> fmt::Result {
    writeln!(out, "tidepath_{}", token(name, "unnamed"))?;
    writeln!(out, "0 common properties")?;
    writeln!(out, "{} properties for each run", RUN_PROPERTIES.len())?;
    for p in RUN_PROPERTIES {
        writeln!(out, "{p}")?;
    }
    writeln!(out, "{} runs", runs.len())?;
    for r in runs {
        for value in run_values(r) {
            write!(out, "{value}; ")?;
        }
        writeln!(out)?;
    }
    if runs.iter().any(|r| has_progress(r)) {
        writeln!(out, "{} progress properties for each run", PROGRESS_PROPERTIES.len())?;
        for p in PROGRESS_PROPERTIES {
            writeln!(out, "{p}")?;
        }
        // One line per run, in run order: the parser pairs them with the runs by position.
        writeln!(out, "{} runs", runs.len())?;
        for r in runs {
            write_progress(out, r)?;
            writeln!(out)?;
        }
    }
    writeln!(out, ".")
}

/// OMPL's (solved, approximate solution, status) for a run: from the plan's own status when
/// the run has one, else (function benchmarks, older records) from its cost and feasibility.
fn ompl_status(r: &RunRecord) -> (bool, Option<bool>, u8) {
    use tidepath::planner::Status;
    match r.status {
        Some(Status::Exact | Status::Feasible) => (true, Some(false), STATUS_EXACT),
        // OMPL's approximate solution: a path came back but does not solve the problem (it
        // stops short of the goal, or violates a constraint).
        Some(Status::Infeasible) if !r.waypoints.is_empty() => (false, Some(true), STATUS_APPROXIMATE),
        Some(Status::Timeout) if !r.waypoints.is_empty() => (false, Some(true), STATUS_APPROXIMATE),
        Some(Status::Infeasible | Status::Timeout) => (false, None, STATUS_TIMEOUT),
        Some(Status::InvalidStart) => (false, None, STATUS_INVALID_START),
        Some(Status::InvalidGoal) => (false, None, STATUS_INVALID_GOAL),
        Some(Status::Unreachable) => (false, None, STATUS_INFEASIBLE),
        Some(Status::Cancelled) => (false, None, STATUS_ABORT),
        // A run whose best cost never became finite found nothing, not even a best-effort path.
        None => match (r.cost.is_finite(), r.feasible) {
            (true, true) => (true, Some(false), STATUS_EXACT),
            (true, false) => (false, Some(true), STATUS_APPROXIMATE),
            (false, _) => (false, None, STATUS_TIMEOUT),
        },
    }
}

pub(super) fn run_values(r: &RunRecord) -> [String; RUN_PROPERTIES.len()] {
    let (solved, approximate, status) = ompl_status(r);
    // The distance left to the goal, for approximate solutions (0 when the path reaches it).
    let difference = (approximate == Some(true)).then(|| r.goal_distance_m().unwrap_or(0.0));
    let segments = (!r.waypoints.is_empty()).then(|| r.waypoints.len() - 1);
    [
        real(r.elapsed_s),
        "0".to_string(),
        boolean(solved),
        approximate.map(boolean).unwrap_or_default(),
        status.to_string(),
        r.length_m.map(real).unwrap_or_default(),
        segments.map(|s| s.to_string()).unwrap_or_default(),
        real(r.cost),
        r.travel_time_s.map(real).unwrap_or_default(),
        r.evaluations.to_string(),
        r.iterations.to_string(),
        stop_reason_value(r.stop_reason).to_string(),
        r.seed.to_string(),
        difference.map(real).unwrap_or_default(),
        r.expansions.to_string(),
        r.samples.to_string(),
        r.motion_checks.to_string(),
        r.graph_nodes.to_string(),
    ]
}

fn has_progress(r: &RunRecord) -> bool {
    // Without a positive run time all samples share one time, which the progress table's key
    // rejects (the script then drops them with a warning).
    !r.history.is_empty() && r.elapsed_s.is_finite() && r.elapsed_s > 0.0
}

/// Planner Arena plots progress against time, but tidepath records the best cost per iteration,
/// not per instant: the time of entry k is interpolated as if the initialisation and each
/// iteration took equal wall time. The `iterations` column stays exact.
fn write_progress(out: &mut String, r: &RunRecord) -> fmt::Result {
    if !has_progress(r) {
        return Ok(());
    }
    let n = r.history.len() as f64;
    for (k, best) in r.history.iter().enumerate() {
        let time = r.elapsed_s * (k as f64 + 1.0) / n;
        write!(out, "{},{},{},;", real(time), k, best.map(real).unwrap_or_default())?;
    }
    Ok(())
}
