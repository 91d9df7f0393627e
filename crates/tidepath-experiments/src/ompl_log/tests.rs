use super::format::{real, utc_date_time};
use super::writer::run_values;
use super::*;
use crate::RunRecord;
use tidepath::optim::StopReason;

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
        ..RunRecord::default()
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
stop_reason|max iterations|max evaluations|wall time|max expansions|max samples|target cost|cancelled|completed
2 planners
tidepath_pso
0 common properties
18 properties for each run
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
solution difference REAL
expansions INTEGER
samples INTEGER
motion checks INTEGER
graph states INTEGER
2 runs
0.5; 0; 1; 0; 6; 1000.25; 2; 12.5; 800.5; 120; 2; 0; 11; ; 0; 0; 0; 0; 
0.25; 0; 0; 1; 5; 1500; 3; 30; 1300; 120; 2; 1; 18446744073709551615; 0; 0; 0; 0; 0; 
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
18 properties for each run
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
solution difference REAL
expansions INTEGER
samples INTEGER
motion checks INTEGER
graph states INTEGER
1 runs
0.5; 0; 0; ; 4; ; ; ; ; 0; 0; 0; 8; ; 0; 0; 0; 0; 
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

/// The plan's own status decides OMPL's: a path that stops short is an approximate solution
/// with its distance left; proofs, bad endpoints and cancellations keep their own values.
#[test]
fn plan_statuses_map_to_ompl_statuses() {
    use tidepath::planner::Status;
    let mut r = fixture().remove(0);
    r.status = Some(Status::Timeout);
    r.missions = vec![crate::record::MissionRecord {
        name: "m".into(),
        status: Status::Timeout,
        waypoints: r.waypoints.clone(),
        goal_distance_m: Some(42.5),
    }];
    let v = run_values(&r);
    assert_eq!((v[2].as_str(), v[3].as_str(), v[4].as_str(), v[13].as_str()), ("0", "1", "5", "42.5"));
    for (status, value) in [
        (Status::Exact, "6"),
        (Status::InvalidStart, "1"),
        (Status::InvalidGoal, "2"),
        (Status::Unreachable, "9"),
        (Status::Cancelled, "8"),
    ] {
        r.status = Some(status);
        assert_eq!(run_values(&r)[4], value, "{status}");
    }
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
