//! End-to-end tests of `compare`, `bench functions` and `reproduce` (issue #3); `reproduce`'s
//! report is checked in `numbers.rs`, with its verdicts at too few runs.

use std::path::Path;
use std::process::{Command, Output};

fn tidepath(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).output().expect("tidepath runs")
}

/// results.json without the fields that measure time.
fn untimed(path: &Path) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                for k in ["elapsed_s", "mean_wall_s", "total_wall_s"] {
                    m.remove(k);
                }
                m.values_mut().for_each(strip);
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    strip(&mut v);
    v
}

#[test]
fn compare_writes_all_files_and_is_independent_of_jobs() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    let log = dir.path().join("demo.log");
    let base = ["compare", "demo", "--planners", "pso,ga,de", "--runs", "4", "--iterations", "30"];
    let mut args: Vec<&str> = base.to_vec();
    args.extend(["--jobs", "2", "--out", a.to_str().unwrap(), "--ompl-log", log.to_str().unwrap()]);
    let o = tidepath(&args);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    for p in ["| pso |", "| ga |", "| de |", "vs pso", "ref"] {
        assert!(stdout.contains(p), "missing {p} in\n{stdout}");
    }
    for f in ["results.json", "runs.csv", "table.md", "convergence.svg", "boxplot.svg", "paths.svg"] {
        assert!(a.join(f).is_file(), "{f} missing");
    }
    let csv = std::fs::read_to_string(a.join("runs.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 12);
    // The default reference (theta-star in 3-D) is a dashed line on the convergence figure, and
    // every planner's legend entry gives its final gap or its feasible runs.
    let conv = std::fs::read_to_string(a.join("convergence.svg")).unwrap();
    assert!(conv.contains("\nreference theta-star ("), "no reference line in convergence.svg");
    assert!(conv.contains("\niteration\n"), "optimizers' axis is not in iterations");
    for p in ["pso", "ga", "de"] {
        let gap = conv.contains(&format!("\n{p} (final gap "));
        let few = (0..=2).any(|k| conv.contains(&format!("\n{p} ({k}/4 runs feasible)")));
        assert!(gap || few, "{p}: neither a gap nor its feasible runs in the legend");
    }
    let ompl = std::fs::read_to_string(&log).unwrap();
    assert!(ompl.contains("3 planners") && ompl.contains("tidepath_pso"), "{ompl}");

    let mut args: Vec<&str> = base.to_vec();
    args.extend(["--jobs", "1", "--out", b.to_str().unwrap()]);
    assert_eq!(tidepath(&args).status.code(), Some(0));
    assert_eq!(untimed(&a.join("results.json")), untimed(&b.join("results.json")));
}

#[test]
fn compare_rejects_unknown_planner_before_running() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    let o = tidepath(&["compare", "demo", "--planners", "pso,nope", "--runs", "2", "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("nope"));
    assert!(!out.exists());
}

/// An unknown reference planner is named against the flag, in one line, before any run.
#[test]
fn unknown_reference_planners_are_refused_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    for args in [
        vec!["compare", "demo", "--planners", "pso", "--reference", "nope", "--out", out.to_str().unwrap()],
        vec!["reproduce", "amfa2015", "--reference", "nope", "--out", out.to_str().unwrap()],
    ] {
        let o = tidepath(&args);
        assert_eq!(o.status.code(), Some(2));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.starts_with("error: --reference: unknown planner 'nope'") && err.lines().count() == 1, "{err}");
        assert!(!out.exists());
    }
}

/// `bench functions --help` names every optimizer of the planner table, so a new one cannot
/// be left out of the list; and each runs there.
#[test]
fn bench_functions_lists_and_runs_every_optimizer() {
    let help = String::from_utf8_lossy(&tidepath(&["bench", "functions", "--help"]).stdout).to_string();
    let flat = help.split_whitespace().collect::<Vec<_>>().join(" ");
    let optimizers: Vec<&str> =
        tidepath::planner::registry().entries().iter().filter(|e| e.build.is_optimizer()).map(|e| e.id).collect();
    for id in &optimizers {
        assert!(flat.contains(&format!(" {id},")) || flat.contains(&format!(" {id} (")), "{id} missing from: {flat}");
    }
    for id in ["js", "ijs", "qpso", "hho", "mpa"] {
        assert!(optimizers.contains(&id), "{id}");
    }
    let algos = optimizers.join(",");
    let o = tidepath(&[
        "bench",
        "functions",
        "--algos",
        &algos,
        "--funcs",
        "sphere",
        "--dim",
        "5",
        "--runs",
        "2",
        "--evaluations",
        "500",
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(stdout.lines().filter(|l| l.starts_with("| sphere-d5-standard")).count(), optimizers.len(), "{stdout}");
}

#[test]
fn bench_functions_reports_sphere_near_zero() {
    let o = tidepath(&[
        "bench",
        "functions",
        "--algos",
        "pso,de",
        "--funcs",
        "sphere,rastrigin",
        "--dim",
        "10",
        "--runs",
        "5",
        "--evaluations",
        "20000",
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let sphere: Vec<&str> = stdout.lines().filter(|l| l.starts_with("| sphere-d10-standard")).collect();
    assert_eq!(sphere.len(), 2, "{stdout}");
    for line in sphere {
        let mean: f64 = line.split('|').nth(4).unwrap().trim().parse().unwrap();
        assert!(mean < 1e-6, "sphere mean {mean} in {line}");
    }
}
