//! Regression tests for the defects a hostile and a careless user found: each named after it.
//! Contract: bad input gives exit 2 and one line on stderr naming the field, and no file is
//! created, replaced or truncated; no panic, no hang.

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn tidepath(args: &[&str]) -> (Output, Duration) {
    let t = Instant::now();
    let o = Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).output().expect("tidepath runs");
    (o, t.elapsed())
}

fn demo() -> String {
    String::from_utf8(tidepath(&["scenario", "demo"]).0.stdout).unwrap()
}

fn edited(old: &str, new: &str) -> String {
    let d = demo();
    assert!(d.contains(old), "demo lacks {old}");
    d.replacen(old, new, 1)
}

/// Exit 2, one line naming `field` (and `value`), nothing written into the folder.
fn rejects(scenario: &str, extra: &[&str], field: &str, value: &str) {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("s.toml");
    std::fs::write(&f, scenario).unwrap();
    let out = dir.path().join("p.json");
    let mut args = vec!["plan", f.to_str().unwrap(), "--out", out.to_str().unwrap()];
    args.extend_from_slice(extra);
    let (o, _) = tidepath(&args);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{field}: stderr {stderr}");
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.contains(field) && stderr.contains(value), "expected {field} / {value}: {stderr}");
    assert!(!stderr.contains("panicked"));
    assert!(!out.exists());
}

#[test]
fn huge_waypoint_count_is_refused_before_allocating() {
    rejects(&edited("waypoints = 10", "waypoints = 1000000000"), &[], "encoding.waypoints", "1000000000");
}

#[test]
fn huge_population_is_refused_before_allocating() {
    rejects(&demo(), &["--population", "1000000000000"], "planner.params.pso.population", "1000000000000");
    rejects(&edited("waypoints = 10", "waypoints = 9000"), &["--population", "90000"], "population", "20000000");
}

#[test]
fn grid_shape_that_overflows_is_refused() {
    let text = r#"
name = "g"
[world]
dimensions = 2
bounds = { min = [0.0, 0.0, 0.0], max = [100.0, 100.0, 0.0] }
[world.current]
kind = "grid"
origin = [0.0, 0.0]
spacing = [1.0, 1.0]
shape = [4294967296, 4294967296]
times = [0.0]
u = [[0.0]]
v = [[0.0]]
[mission]
start = [1.0, 1.0, 0.0]
goal = [90.0, 90.0, 0.0]
"#;
    rejects(text, &[], "world.current.shape", "4294967296");
}

#[test]
fn time_limit_1e20_is_an_input_error() {
    rejects(&demo(), &["--time-limit", "1e20"], "--time-limit", "1e20");
}

#[test]
fn bench_dimension_of_a_hundred_million_is_refused() {
    let (o, _) = tidepath(&["bench", "functions", "--algos", "pso", "--funcs", "sphere", "--dim", "100000000"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("error: --dim"));
}

#[test]
fn tiny_current_step_is_refused() {
    rejects(&edited("current_step = 250.0", "current_step = 1e-9"), &[], "model.current_step", "1e-9");
}

#[test]
fn iterations_near_u64_max_are_refused() {
    rejects(&demo(), &["--iterations", "18446744073709551615"], "--iterations", "at most");
}

#[test]
fn compare_with_ten_thousand_jobs_is_refused() {
    let (o, _) = tidepath(&["compare", "demo", "--planners", "pso", "--runs", "1", "--jobs", "10000"]);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--jobs"));
}

#[test]
fn eval_of_a_waypoint_at_1e12_m_ends_quickly() {
    let dir = tempfile::tempdir().unwrap();
    let plan = dir.path().join("far.json");
    std::fs::write(&plan, r#"{"waypoints": [[1000, 6000, -400], [1e12, 6000, -400], [19000, 6500, -300]]}"#).unwrap();
    let (o, took) = tidepath(&["eval", "demo", plan.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("outside the domain"));
    assert!(took < Duration::from_secs(60), "took {took:?}");
}

#[test]
fn max_pitch_above_90_degrees_is_refused() {
    rejects(&edited("max_pitch_deg = 30.0", "max_pitch_deg = 180.0"), &[], "vehicle.max_pitch_deg", "180");
}

#[test]
fn departure_time_1e20_is_refused() {
    rejects(&edited("departure_time = 0.0", "departure_time = 1e20"), &[], "mission.departure_time", "1e20");
}

#[test]
fn zero_iterations_in_the_scenario_are_refused() {
    rejects(&edited("iterations = 200", "iterations = 0"), &[], "planner.iterations", "0");
}

#[test]
fn bounds_of_1e15_give_the_right_reason() {
    rejects(&edited("max = [20000.0, 12000.0, 0.0]", "max = [1e15, 12000.0, 0.0]"), &[], "world.bounds", "1e15");
}

#[test]
fn type_error_inside_an_obstacle_names_the_field() {
    let text = edited("center = [17000.0, 4500.0]\nradius = 600.0", "center = [17000.0, 4500.0]\nradius = \"wide\"");
    rejects(&text, &[], "world.obstacles[2].radius", "wide");
}

#[test]
fn usage_errors_take_one_line() {
    for args in [&["plan"][..], &["plan", "demo", "--bogus"], &["frobnicate"], &["plan", "demo", "--seed", "x"]] {
        let (o, _) = tidepath(args);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr.trim_end().lines().count(), 1, "{args:?}: {stderr}");
    }
}

#[test]
fn eval_does_not_call_a_path_that_misses_the_goal_feasible() {
    let dir = tempfile::tempdir().unwrap();
    let plan = dir.path().join("short.json");
    std::fs::write(&plan, r#"{"waypoints": [[1000, 6000, -400], [1500, 6000, -400]]}"#).unwrap();
    let (o, _) = tidepath(&["eval", "demo", plan.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains("is not the mission goal"), "{stdout}");
}

fn plan_to(out: &Path, plot: Option<&Path>) -> Output {
    let mut args = vec!["plan", "demo", "--iterations", "3", "--out", out.to_str().unwrap()];
    if let Some(p) = plot {
        args.extend_from_slice(&["--plot", p.to_str().unwrap()]);
    }
    tidepath(&args).0
}

#[cfg(unix)]
#[test]
fn symlink_fifo_and_device_outputs_are_refused_and_left_alone() {
    let dir = tempfile::tempdir().unwrap();
    let victim = dir.path().join("victim.txt");
    std::fs::write(&victim, "keep me").unwrap();
    let link = dir.path().join("plan.json");
    std::os::unix::fs::symlink(&victim, &link).unwrap();
    let o = plan_to(&link, None);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("symbolic link"));
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me");
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
    let fifo = dir.path().join("fifo.json");
    if Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success()) {
        let o = plan_to(&fifo, None);
        assert_eq!(o.status.code(), Some(2));
        assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo_like());
    }
    let o = plan_to(Path::new("/dev/null"), None);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("device"));
}

trait FifoLike {
    fn is_fifo_like(&self) -> bool;
}

impl FifoLike for std::fs::FileType {
    fn is_fifo_like(&self) -> bool {
        use std::os::unix::fs::FileTypeExt;
        self.is_fifo()
    }
}

#[cfg(unix)]
#[test]
fn a_plot_into_a_read_only_folder_leaves_no_json_behind() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let ro = dir.path().join("ro");
    std::fs::create_dir(&ro).unwrap();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    let out = dir.path().join("out.json");
    let o = plan_to(&out, Some(&ro.join("p.svg")));
    // Root ignores folder permissions; then both files are written, which is also all-or-none.
    if o.status.code() == Some(2) {
        assert!(!out.exists(), "out.json left behind");
    } else {
        assert!(out.exists() && ro.join("p.svg").exists());
    }
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
}

#[test]
fn a_missing_plot_folder_leaves_no_json_behind() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    std::fs::write(&out, "old").unwrap();
    let o = plan_to(&out, Some(&dir.path().join("nope/p.svg")));
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "old", "out.json replaced");
}

#[test]
fn compare_with_table_md_as_a_directory_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir_all(out.join("table.md")).unwrap();
    let (o, _) = tidepath(&[
        "compare",
        "demo",
        "--planners",
        "pso,de",
        "--runs",
        "2",
        "--iterations",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("table.md"));
    let left: Vec<_> = std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left, vec![std::ffi::OsString::from("table.md")], "files left behind");
}

#[test]
fn compare_into_a_new_folder_writes_every_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("new/out");
    let (o, _) = tidepath(&[
        "compare",
        "demo",
        "--planners",
        "pso",
        "--runs",
        "2",
        "--iterations",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    // The parent `new` does not exist: created with the output folder, as before.
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["results.json", "runs.csv", "table.md", "convergence.svg", "boxplot.svg", "paths.svg"] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
}
