//! Ctrl-C everywhere: the first SIGINT stops `compare`, `bench functions`, `reproduce` and
//! `plan` and `simulate` within a second, keeps and writes what finished (marked incomplete) and exits 130.

#![cfg(unix)]

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Starts `tidepath args` in `dir`, sends SIGINT after `after`, and returns (exit code, time
/// from the signal to the exit, stdout).
fn interrupt(dir: &std::path::Path, args: &[&str], after: Duration) -> (Option<i32>, Duration, String) {
    interrupt_n(dir, args, after, 1)
}

/// As [`interrupt`], with `signals` SIGINTs sent back to back (as `timeout -s INT` sends one
/// to the process and one to its group).
fn interrupt_n(
    dir: &std::path::Path,
    args: &[&str],
    after: Duration,
    signals: usize,
) -> (Option<i32>, Duration, String) {
    let child = Command::new(env!("CARGO_BIN_EXE_tidepath"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(after);
    // SAFETY: sending a signal to our own child.
    for _ in 0..signals {
        unsafe {
            libc::kill(child.id() as libc::pid_t, libc::SIGINT);
        }
    }
    let sent = Instant::now();
    let out = child.wait_with_output().unwrap();
    (out.status.code(), sent.elapsed(), String::from_utf8_lossy(&out.stdout).into_owned())
}

#[test]
fn an_interrupted_compare_writes_the_finished_runs_marked_incomplete() {
    let dir = tempfile::tempdir().unwrap();
    let (code, took, stdout) = interrupt(
        dir.path(),
        &["compare", "demo", "--planners", "pso,de", "--runs", "200", "--jobs", "2", "--out", "res"],
        Duration::from_secs(2),
    );
    assert_eq!(code, Some(130), "{stdout}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    let results: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("res/results.json")).unwrap()).unwrap();
    assert_eq!(results["complete"], false);
    let finished = results["finished_runs"].as_u64().unwrap();
    assert!(finished > 0 && finished < 400, "{finished}");
    assert_eq!(results["records"].as_array().unwrap().len() as u64, finished);
    assert!(results["records"].as_array().unwrap().iter().all(|r| r["stop_reason"] != "cancelled"));
    let table = std::fs::read_to_string(dir.path().join("res/table.md")).unwrap();
    assert!(table.starts_with("> **Incomplete: interrupted after"), "{table}");
    assert!(stdout.contains("Incomplete"));
    // Every declared file is there, and no temporary.
    let names: Vec<String> = std::fs::read_dir(dir.path().join("res"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(names.len(), 6, "{names:?}");
}

#[test]
fn an_interrupted_bench_and_plan_exit_130_with_what_they_have() {
    let dir = tempfile::tempdir().unwrap();
    let (code, took, stdout) = interrupt(
        dir.path(),
        &["bench", "functions", "--algos", "pso,de", "--funcs", "rastrigin", "--runs", "5000", "--out", "b"],
        Duration::from_millis(1500),
    );
    assert_eq!(code, Some(130), "{stdout}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert!(std::fs::read_to_string(dir.path().join("b/table.md")).unwrap().contains("Incomplete"));
    let (code, took, stdout) = interrupt(
        dir.path(),
        &["plan", "demo", "--planner", "pso", "--iterations", "100000000", "--out", "p.json"],
        Duration::from_millis(1500),
    );
    assert_eq!(code, Some(130), "{stdout}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert!(stdout.contains("stopped by cancelled"), "{stdout}");
    let plan: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("p.json")).unwrap()).unwrap();
    assert_eq!(plan["stop_reason"], "cancelled");
}

#[test]
fn an_interrupted_reproduction_marks_its_report_incomplete() {
    let dir = tempfile::tempdir().unwrap();
    let (code, took, stdout) = interrupt(
        dir.path(),
        &["reproduce", "amfa2015", "--only", "tables", "--runs", "30", "--out", "r"],
        Duration::from_secs(2),
    );
    assert_eq!(code, Some(130), "{stdout}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    let report = std::fs::read_to_string(dir.path().join("r/REPORT.md")).unwrap();
    assert!(report.contains("**Incomplete**"), "{report}");
}

/// A cancelled plan exits 130 even when its best path so far is feasible, and writes it; one
/// interrupt delivered twice at once (process and group) is one Ctrl-C, not two.
#[test]
fn a_cancelled_plan_with_a_feasible_best_exits_130_and_writes_it() {
    let dir = tempfile::tempdir().unwrap();
    let (code, took, stdout) = interrupt_n(
        dir.path(),
        &["plan", "headland", "--planner", "hybrid", "--iterations", "100000000", "--out", "p.json"],
        Duration::from_millis(1500),
        2,
    );
    assert_eq!(code, Some(130), "{stdout}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    let plan: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("p.json")).unwrap()).unwrap();
    assert_eq!(plan["stop_reason"], "cancelled");
    assert_eq!(plan["missions"][0]["feasible"], true, "{stdout}");
}

/// An interrupted simulation writes the phases done, marked incomplete, and exits 130.
#[test]
fn an_interrupted_simulation_writes_its_phases_marked_incomplete() {
    let dir = tempfile::tempdir().unwrap();
    let (code, took, stdout) = interrupt(
        dir.path(),
        &["simulate", "coastal-traffic", "--planner", "pso", "--iterations", "100000000", "--out", "s.json"],
        Duration::from_millis(1500),
    );
    assert_eq!(code, Some(130), "{stdout}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert!(stdout.contains("incomplete"), "{stdout}");
    let sim: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("s.json")).unwrap()).unwrap();
    assert_eq!(sim["outcome"]["complete"], false);
    assert!(sim["outcome"]["reason"].as_str().unwrap().starts_with("stopped"), "{}", sim["outcome"]["reason"]);
}
