//! OMPL benchmark logs (`compare --ompl-log`), so tidepath runs load into the SQLite database that
//! Planner Arena reads, beside OMPL's own planners.
//!
//! Verified with the `ompl` wheel 2.0.1 from PyPI (Python 3.11, SQLite 3.40), whose console
//! script `ompl_benchmark_statistics` parses logs in `ompl/_benchmark_statistics.py`:
//!
//! ```text
//! pip install ompl==2.0.1
//! TIDEPATH_OMPL_LOG=/tmp/tidepath_ompl.log \
//!     cargo test -p tidepath --lib experiments::ompl_log -- --ignored
//! ompl_benchmark_statistics /tmp/tidepath_ompl.log -d /tmp/tidepath_ompl.db
//! python3 crates/tidepath/tests/ompl_check_db.py /tmp/tidepath_ompl.db
//! ```
//!
//! The layout follows a log written by OMPL 2.0.1's own `Benchmark::saveResultsToFile`. What the
//! parser does, and so what this writer guards against:
//! * it keeps only the last word of the `Experiment` and `Running on` lines, so words are joined
//!   with `_` instead of being silently cut;
//! * the setup block ends at the first line starting with `|>>>` (and the parser loops forever if
//!   none comes), so such lines in the setup text are indented;
//! * every run value is followed by `"; "`, the last one included; an empty value, `nan` and
//!   `inf` become NULL, but `-inf` would be stored as text, so no non-finite number is written;
//! * it stores INTEGER columns with SQLite's numeric affinity, which turns integers beyond `i64`
//!   into lossy REALs: derived seeds use all 64 bits, so the seed is a TEXT column;
//! * `(runid, time)` is the key of the progress table, so progress times must differ in a run;
//! * it always creates the `bestPlannerConfigs` views, which fail to query without the `time`
//!   and `solved` columns;
//! * enum descriptions are stored by enum name, first log wins: the `status` enum is copied
//!   verbatim from OMPL 2.0.1 so mixed databases agree.
//!
//! And what Planner Arena needs: the progress page reads the `best_cost` column, enums are drawn
//! as bar charts only when the enum and the column share a name (`stop_reason`), and the
//! performance page shows one version at a time (tidepath's runs carry version `tidepath X.Y.Z`,
//! so they meet OMPL's runs of the same experiment on the regression page).

use std::fmt::{self, Write as _};

use super::RunRecord;
use crate::optim::StopReason;

/// The experiment-level facts of an OMPL log: one log holds one experiment (one problem).
#[derive(Clone, Debug)]
pub struct OmplLogInfo<'a> {
    /// Problem name, Planner Arena's "motion planning problem"; whitespace becomes `_`.
    pub experiment: &'a str,
    /// Machine name; whitespace becomes `_`.
    pub host: &'a str,
    /// Start of the experiment (UNIX seconds), written in UTC as OMPL 2.0.1 does:
    /// `YYYY-MM-DD HH:MM:SS`.
    pub start_unix_s: u64,
    /// Free text shown by Planner Arena as the experiment's setup (scenario, budget, planner
    /// parameters): OMPL keeps per-planner settings in the same place.
    pub setup: &'a str,
    /// Optional CPU description, as OMPL's `lscpu` block.
    pub cpu_info: Option<&'a str>,
    pub master_seed: u64,
    /// The wall-time safety net (s); `None` is written as 0 because the format has no "no limit".
    pub time_limit_s: Option<f64>,
    /// Wall time of the whole experiment (s).
    pub total_time_s: f64,
}

/// Run properties, in the order their values are written. Names match OMPL's where the meaning
/// matches (so the columns are shared in a mixed database); `memory` is left out on purpose:
/// tidepath does not measure it and a 0 would be plotted as a measurement.
const RUN_PROPERTIES: [&str; 13] = [
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
];

/// The same progress columns as OMPL's RRT*, so Planner Arena's progress page overlays them.
const PROGRESS_PROPERTIES: [&str; 3] = ["time REAL", "iterations INTEGER", "best cost REAL"];

/// OMPL 2.0.1's `PlannerStatus` enum line, verbatim (its ABORT and INFEASIBLE print as
/// "Unknown status").
const STATUS_ENUM: &str = "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|\
                           Approximate solution|Exact solution|Crash|Unknown status|Unknown status";
const STATUS_TIMEOUT: u8 = 4;
const STATUS_APPROXIMATE: u8 = 5;
const STATUS_EXACT: u8 = 6;

const STOP_REASON_ENUM: &str = "stop_reason|max iterations|max evaluations|wall time";

fn stop_reason_value(reason: StopReason) -> u8 {
    // Indices into STOP_REASON_ENUM; a new variant must be added there too.
    match reason {
        StopReason::MaxIterations => 0,
        StopReason::MaxEvaluations => 1,
        StopReason::WallTime => 2,
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

fn run_values(r: &RunRecord) -> [String; RUN_PROPERTIES.len()] {
    // A run whose best cost never became finite found nothing, not even a best-effort path.
    let found = r.cost.is_finite();
    let (solved, approximate, status) = match (found, r.feasible) {
        (true, true) => (true, Some(false), STATUS_EXACT),
        // OMPL's meaning of an approximate solution: a path came back but does not solve the
        // problem (here: it violates a constraint).
        (true, false) => (false, Some(true), STATUS_APPROXIMATE),
        (false, _) => (false, None, STATUS_TIMEOUT),
    };
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

fn boolean(b: bool) -> String {
    // The `bestPlannerConfigs` views average `solved`, which needs numbers, not words.
    if b { "1" } else { "0" }.to_string()
}

/// Shortest round-trip text; exponent form only where plain digits would run long. Empty (NULL)
/// for non-finite values, see the module docs.
fn real(x: f64) -> String {
    if !x.is_finite() {
        return String::new();
    }
    let a = x.abs();
    if a != 0.0 && !(1e-5..1e16).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// Header numbers go through Python's `float()` and cannot be empty.
fn header_real(x: f64) -> String {
    if x.is_finite() {
        real(x)
    } else {
        "0".to_string()
    }
}

fn token(s: &str, fallback: &str) -> String {
    let t = s.split_whitespace().collect::<Vec<_>>().join("_");
    if t.is_empty() {
        fallback.to_string()
    } else {
        t
    }
}

fn block(text: &str) -> String {
    // Python reads with universal newlines, so a lone '\r' also ends a line.
    let text = text.replace("\r\n", "\n").replace('\r', "\n");
    let mut out = String::new();
    for line in text.lines() {
        if line.starts_with("|>>>") {
            out.push(' ');
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

fn utc_date_time(unix_s: u64) -> String {
    let secs = unix_s % 86_400;
    let (y, m, d) = civil_from_days((unix_s / 86_400) as i64);
    format!("{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02}", secs / 3600, secs / 60 % 60, secs % 60)
}

/// Days since 1970-01-01 to a proleptic Gregorian date (H. Hinnant's `civil_from_days`); the
/// crate has no date dependency and needs only this.
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = (if mp < 10 { mp + 3 } else { mp - 9 }) as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[allow(clippy::too_many_arguments)]
    fn record(
        planner: &str,
        run: u64,
        seed: u64,
        cost: f64,
        feasible: bool,
        path: Option<(f64, f64, usize)>,
        elapsed_s: f64,
        stop_reason: StopReason,
        history: Vec<Option<f64>>,
    ) -> RunRecord {
        RunRecord {
            problem: "harbour".into(),
            planner: planner.into(),
            run,
            seed,
            cost,
            feasible,
            length_m: path.map(|p| p.0),
            travel_time_s: path.map(|p| p.1),
            evaluations: 40 * history.len() as u64,
            iterations: history.len().saturating_sub(1) as u64,
            elapsed_s,
            stop_reason,
            history,
            waypoints: path.map(|p| vec![[0.0, 0.0, -5.0]; p.2]).unwrap_or_default(),
        }
    }

    /// Two planners x 3 runs: an infeasible run, a run whose seed needs all 64 bits, runs
    /// without a path (function-benchmark style), one without history and one too fast to time.
    /// `tests/ompl_check_db.py` checks these values after the real OMPL script loaded them.
    fn fixture() -> Vec<RunRecord> {
        use StopReason::*;
        vec![
            record(
                "pso",
                0,
                11,
                12.5,
                true,
                Some((1000.25, 800.5, 3)),
                0.5,
                MaxIterations,
                vec![Some(20.0), Some(15.0), Some(12.5)],
            ),
            record(
                "pso",
                1,
                u64::MAX,
                30.0,
                false,
                Some((1500.0, 1300.0, 4)),
                0.25,
                MaxEvaluations,
                vec![None, Some(40.0), Some(30.0)],
            ),
            record("pso", 2, 1 << 63, 11.0, true, Some((990.0, 790.0, 5)), 2.0, WallTime, vec![Some(19.0), Some(11.0)]),
            record("ga", 0, 7, 0.75, true, None, 0.125, MaxIterations, vec![Some(3.0), Some(1.5), Some(0.75)]),
            record("ga", 1, 8, f64::INFINITY, true, None, 0.5, MaxIterations, vec![]),
            record("ga", 2, 9, 2.5e-7, true, None, 0.0, MaxEvaluations, vec![Some(1e20), Some(2.5e-7)]),
        ]
    }

    fn grouped(records: &[RunRecord]) -> Vec<(&str, Vec<&RunRecord>)> {
        ["pso", "ga"].iter().map(|&p| (p, records.iter().filter(|r| r.planner == p).collect())).collect()
    }

    fn info() -> OmplLogInfo<'static> {
        OmplLogInfo {
            experiment: "harbour",
            host: "vm",
            start_unix_s: 1_782_000_000,
            setup: "scenario harbour\nbudget: 2 iterations\n",
            cpu_info: None,
            master_seed: 42,
            time_limit_s: Some(60.0),
            total_time_s: 3.375,
        }
    }

    #[test]
    fn golden_small_log() {
        let records = fixture();
        let planners = vec![("pso", vec![&records[0], &records[1]]), ("ga", vec![&records[4]])];
        let expected = format!(
            "tidepath version {}\n{}",
            env!("CARGO_PKG_VERSION"),
            "Experiment harbour
0 experiment properties
Running on vm
Starting at 2026-06-21 00:00:00
<<<|
scenario harbour
budget: 2 iterations
|>>>
42 is the random seed
60 seconds per run
0 MB per run
3.375 seconds spent to collect the data
2 enum types
status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|Approximate solution|Exact solution|Crash|Unknown status|Unknown status
stop_reason|max iterations|max evaluations|wall time
2 planners
tidepath_pso
0 common properties
13 properties for each run
time REAL
simplification time REAL
solved BOOLEAN
approximate solution BOOLEAN
status ENUM
solution length REAL
solution segments INTEGER
best cost REAL
travel time REAL
evaluations INTEGER
iterations INTEGER
stop_reason ENUM
seed TEXT
2 runs
0.5; 0; 1; 0; 6; 1000.25; 2; 12.5; 800.5; 120; 2; 0; 11; 
0.25; 0; 0; 1; 5; 1500; 3; 30; 1300; 120; 2; 1; 18446744073709551615; 
3 progress properties for each run
time REAL
iterations INTEGER
best cost REAL
2 runs
0.16666666666666666,0,20,;0.3333333333333333,1,15,;0.5,2,12.5,;
0.08333333333333333,0,,;0.16666666666666666,1,40,;0.25,2,30,;
.
tidepath_ga
0 common properties
13 properties for each run
time REAL
simplification time REAL
solved BOOLEAN
approximate solution BOOLEAN
status ENUM
solution length REAL
solution segments INTEGER
best cost REAL
travel time REAL
evaluations INTEGER
iterations INTEGER
stop_reason ENUM
seed TEXT
1 runs
0.5; 0; 0; ; 4; ; ; ; ; 0; 0; 0; 8; 
.
"
        );
        assert_eq!(write_ompl_log(&info(), &planners), expected);
    }

    /// Reads a log the way `ompl/_benchmark_statistics.py` does (positional lines, `"; "`-ended
    /// run values, `,`-ended progress samples) and returns, per planner, its name, run rows and
    /// progress rows.
    #[allow(clippy::type_complexity)]
    fn parse_like_ompl(log: &str) -> Vec<(String, Vec<Vec<String>>, Vec<Vec<Vec<String>>>)> {
        let mut lines = log.lines();
        let mut line = || lines.next().expect("log ends early");
        let count = |l: &str| l.split_whitespace().next().unwrap().parse::<usize>().unwrap();
        let n_planners = loop {
            let l = line();
            if l.ends_with(" planners") {
                break count(l);
            }
        };
        let mut out = Vec::new();
        for _ in 0..n_planners {
            let name = line().to_string();
            let common = count(line());
            for _ in 0..common {
                line();
            }
            let n_props = count(line());
            let props: Vec<&str> = (0..n_props).map(|_| line()).collect();
            let n_runs = count(line());
            let rows: Vec<Vec<String>> = (0..n_runs)
                .map(|_| {
                    let l = format!("{}\n", line());
                    let parts: Vec<&str> = l.split("; ").collect();
                    parts[..parts.len() - 1].iter().map(|s| s.to_string()).collect()
                })
                .collect();
            assert!(rows.iter().all(|r| r.len() == props.len()), "{name}: value count != property count");
            let mut progress = Vec::new();
            let next = line();
            if next != "." {
                let n_prog = count(next);
                for _ in 0..n_prog {
                    line();
                }
                assert_eq!(count(line()), n_runs);
                for _ in 0..n_runs {
                    let l = format!("{}\n", line());
                    let samples: Vec<&str> = l.split(';').collect();
                    let samples: Vec<Vec<String>> = samples[..samples.len() - 1]
                        .iter()
                        .map(|s| {
                            let v: Vec<&str> = s.split(',').collect();
                            v[..v.len() - 1].iter().map(|x| x.to_string()).collect()
                        })
                        .collect();
                    assert!(samples.iter().all(|s| s.len() == n_prog));
                    progress.push(samples);
                }
                assert_eq!(line(), ".");
            }
            out.push((name, rows, progress));
        }
        assert!(lines.next().is_none(), "trailing text after the last planner");
        out
    }

    #[test]
    fn every_run_and_sample_lines_up_with_its_properties() {
        let records = fixture();
        let log = write_ompl_log(&info(), &grouped(&records));
        let parsed = parse_like_ompl(&log);
        assert_eq!(parsed.len(), 2);
        let (name, rows, progress) = &parsed[0];
        assert_eq!(name, "tidepath_pso");
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[2][0], "2");
        assert_eq!(rows[2][12], "9223372036854775808");
        assert_eq!(progress.len(), 3);
        assert_eq!(progress[2].len(), 2);

        let (name, rows, progress) = &parsed[1];
        assert_eq!(name, "tidepath_ga");
        // Path-less runs: no length, segments or travel time; the infinite cost is NULL.
        assert_eq!(rows[0][5..9], ["".to_string(), "".into(), "0.75".into(), "".into()]);
        assert_eq!(rows[1][7], "");
        assert_eq!(rows[2][7], "2.5e-7");
        // No history, and a zero elapsed time, both give an empty progress line.
        assert_eq!(progress.iter().map(Vec::len).collect::<Vec<_>>(), [3, 0, 0]);
        assert!(log.contains("\n3 runs per planner\n"));
    }

    #[test]
    fn progress_times_increase_and_end_at_the_run_time() {
        let records = fixture();
        let parsed = parse_like_ompl(&write_ompl_log(&info(), &grouped(&records)));
        for samples in parsed.iter().flat_map(|p| &p.2) {
            let times: Vec<f64> = samples.iter().map(|s| s[0].parse().unwrap()).collect();
            assert!(times.iter().all(|&t| t > 0.0), "{times:?}");
            assert!(times.windows(2).all(|w| w[0] < w[1]), "{times:?}");
        }
        let pso = &parsed[0].2;
        assert_eq!(pso[2].last().unwrap()[0], "2");
        assert_eq!(pso[2].iter().map(|s| s[1].as_str()).collect::<Vec<_>>(), ["0", "1"]);
    }

    #[test]
    fn unequal_run_counts_leave_out_the_runs_per_planner_line() {
        let records = fixture();
        let planners = vec![("pso", vec![&records[0]]), ("ga", vec![&records[3], &records[4]])];
        let log = write_ompl_log(&info(), &planners);
        assert!(!log.contains("runs per planner"));
        assert_eq!(parse_like_ompl(&log).len(), 2);
    }

    #[test]
    fn free_text_cannot_break_the_layout() {
        let records = fixture();
        let info = OmplLogInfo {
            experiment: "two words",
            host: " ",
            setup: "a\r\n|>>> not the end\rb",
            cpu_info: Some("x86_64"),
            time_limit_s: None,
            total_time_s: f64::NAN,
            ..info()
        };
        let log = write_ompl_log(&info, &[("p s\no", vec![&records[0]])]);
        assert!(log.contains("\nExperiment two_words\n"));
        assert!(log.contains("\nRunning on UNKNOWN\n"));
        assert!(log.contains("\n<<<|\na\n |>>> not the end\nb\n|>>>\n<<<|\nx86_64\n|>>>\n"));
        assert!(log.contains("\n0 seconds per run\n"));
        assert!(log.contains("\n0 seconds spent to collect the data\n"));
        assert_eq!(parse_like_ompl(&log)[0].0, "tidepath_p_s_o");
    }

    #[test]
    fn numbers_stay_short_and_exact() {
        assert_eq!(real(0.1), "0.1");
        assert_eq!(real(3.0), "3");
        assert_eq!(real(-0.0), "-0");
        assert_eq!(real(1e-7), "1e-7");
        assert_eq!(real(1.5e300), "1.5e300");
        assert_eq!(real(123456.789), "123456.789");
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert_eq!(real(x), "");
        }
        for x in [1e-7, 0.1 + 0.2, 1.5e300, 5e-324, f64::MAX] {
            assert_eq!(real(x).parse::<f64>().unwrap(), x);
        }
    }

    #[test]
    fn dates_are_utc_calendar_dates() {
        assert_eq!(utc_date_time(0), "1970-01-01 00:00:00");
        assert_eq!(utc_date_time(951_782_400), "2000-02-29 00:00:00");
        assert_eq!(utc_date_time(1_700_000_000), "2023-11-14 22:13:20");
        assert_eq!(utc_date_time(4_102_444_799), "2099-12-31 23:59:59");
    }

    /// Writes the fixture log to `$TIDEPATH_OMPL_LOG` for the real OMPL script (see the module
    /// docs); ignored because CI machines need not have the `ompl` wheel.
    #[test]
    #[ignore = "writes a file for ompl_benchmark_statistics; set TIDEPATH_OMPL_LOG"]
    fn write_fixture_log_for_ompl_script() {
        let path = std::env::var("TIDEPATH_OMPL_LOG").expect("set TIDEPATH_OMPL_LOG to the log path to write");
        let records = fixture();
        let info = OmplLogInfo { cpu_info: Some("fixture cpu"), ..info() };
        std::fs::write(&path, write_ompl_log(&info, &grouped(&records))).unwrap();
    }
}
