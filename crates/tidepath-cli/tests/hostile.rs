//! Hostile input, as an attacker or a careless user would give it: output paths that step
//! through folders that do not exist, special files as inputs, size bombs, counts at the edge
//! of the integers, dates at the edge of the calendar, values with newlines. Every case runs
//! the real binary under a memory limit and a time limit and must end with exit 2 (or 0/1 for
//! a legal run), one line on stderr, no panic, and, on exit 2, no file created and every file
//! of the user's intact. Special files and crafted data files are made here, by the test.

#![cfg(unix)]

use std::os::unix::process::CommandExt as _;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[path = "../../tidepath-io/tests/common/cdf1.rs"]
mod cdf1;
use cdf1::forecast_bomb;

/// Address space each run may use: far below what the size bombs asked for (7 to 22 GB).
const MEMORY_LIMIT: u64 = 3 << 30;

struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    took: Duration,
}

/// Runs `tidepath args` in `cwd` under the memory limit; kills it after `limit`.
fn run_in(cwd: &Path, args: &[&str], limit: Duration) -> Run {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_tidepath"));
    cmd.args(args).current_dir(cwd).stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped());
    // SAFETY: setrlimit is async-signal-safe and touches nothing of the parent's.
    unsafe {
        cmd.pre_exec(|| {
            let lim = libc::rlimit { rlim_cur: MEMORY_LIMIT, rlim_max: MEMORY_LIMIT };
            if libc::setrlimit(libc::RLIMIT_AS, &lim) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let t = Instant::now();
    let mut child = cmd.spawn().expect("tidepath starts");
    let (mut out, mut err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut out, &mut s).ok();
        s
    });
    let err_reader = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut err, &mut s).ok();
        s
    });
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if t.elapsed() > limit {
            child.kill().ok();
            child.wait().ok();
            panic!("tidepath {args:?} ran past {limit:?}: a hang");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Run { code: status.code(), stdout: reader.join().unwrap(), stderr: err_reader.join().unwrap(), took: t.elapsed() }
}

fn run(cwd: &Path, args: &[&str]) -> Run {
    run_in(cwd, args, Duration::from_secs(60))
}

/// Every file under `dir` with its contents (folders as `name/`), sorted.
fn tree(dir: &Path) -> Vec<(String, String)> {
    fn walk(base: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            let rel = p.strip_prefix(base).unwrap().display().to_string();
            let meta = std::fs::symlink_metadata(&p).unwrap();
            if meta.is_dir() {
                out.push((format!("{rel}/"), String::new()));
                walk(base, &p, out);
            } else if meta.is_file() && meta.len() < 1 << 20 {
                out.push((rel, std::fs::read_to_string(&p).unwrap_or_else(|_| format!("{} bytes", meta.len()))));
            } else {
                out.push((rel, format!("{:?} {}", meta.file_type(), meta.len())));
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, dir, &mut out);
    out.sort();
    out
}

/// Exit 2 with one line on stderr that contains every one of `words`, no panic.
fn refused(r: &Run, words: &[&str]) {
    assert_eq!(r.code, Some(2), "stderr: {}", r.stderr);
    assert_eq!(r.stderr.trim_end().lines().count(), 1, "not one line: {:?}", r.stderr);
    assert!(r.stderr.starts_with("error: "), "{:?}", r.stderr);
    for w in words {
        assert!(r.stderr.contains(w), "expected `{w}` in {:?}", r.stderr);
    }
    assert!(!r.stderr.contains("panicked") && !r.stderr.contains("memory allocation"), "{}", r.stderr);
}

/// Runs `args` in a fresh folder holding the user's files; it must be refused (`words` in
/// the message) and leave the folder exactly as it was.
fn refused_leaving_all(setup: impl Fn(&Path), args: &[&str], words: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("thesis.tex"), "my thesis").unwrap();
    setup(dir.path());
    let before = tree(dir.path());
    let r = run(dir.path(), args);
    refused(&r, words);
    assert_eq!(tree(dir.path()), before, "{args:?} changed the folder");
}

fn demo_text() -> String {
    let dir = tempfile::tempdir().unwrap();
    run(dir.path(), &["scenario", "demo"]).stdout
}

// ---------------------------------------------------------------------------------------------
// Data loss

#[test]
fn a_failed_compare_never_removes_a_folder_it_did_not_create() {
    let compare = |out: &str| -> Vec<String> {
        ["compare", "demo", "--planners", "pso", "--runs", "2", "--iterations", "3", "--out", out]
            .iter()
            .map(|s| s.to_string())
            .collect()
    };
    let keep = |d: &Path| {
        std::fs::create_dir(d.join("keep")).unwrap();
        std::fs::write(d.join("keep/thesis.tex"), "text").unwrap();
        std::fs::create_dir(d.join("keep/results.json")).unwrap();
    };
    for out in ["new/../keep", "a/b/../../keep", "./new/../keep/", "keep/../keep"] {
        let args = compare(out);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        refused_leaving_all(keep, &args, &["--out", "results.json", "is a directory"]);
    }
    // `--out new/..` is the current folder: the user's files there survive.
    let cwd = |d: &Path| {
        std::fs::write(d.join("data.csv"), "1,2").unwrap();
        std::fs::write(d.join("table.md"), "| mine |").unwrap();
        std::fs::create_dir(d.join("results.json")).unwrap();
    };
    let args = compare("new/..");
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    refused_leaving_all(cwd, &args, &["is a directory"]);
    // The blocking output a symlink; and a symlinked parent folder.
    let link = |d: &Path| {
        std::fs::create_dir(d.join("keep")).unwrap();
        std::fs::write(d.join("keep/thesis.tex"), "text").unwrap();
        std::os::unix::fs::symlink(d.join("thesis.tex"), d.join("keep/results.json")).unwrap();
        std::os::unix::fs::symlink(d.join("keep"), d.join("via")).unwrap();
    };
    for out in ["new/../keep", "via", "via/../keep", "new/../via/"] {
        let args = compare(out);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        refused_leaving_all(link, &args, &["symbolic link"]);
    }
}

#[test]
fn a_compare_through_missing_folders_writes_where_the_path_resolves() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("keep")).unwrap();
    std::fs::write(dir.path().join("keep/thesis.tex"), "text").unwrap();
    let r = run(
        dir.path(),
        &["compare", "demo", "--planners", "pso", "--runs", "2", "--iterations", "3", "--out", "new/../keep"],
    );
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert_eq!(std::fs::read_to_string(dir.path().join("keep/thesis.tex")).unwrap(), "text");
    assert!(dir.path().join("keep/results.json").is_file());
    assert!(!dir.path().join("new").exists(), "a folder nobody asked for was left");
}

// ---------------------------------------------------------------------------------------------
// Special files and size bombs as inputs

fn mkfifo(p: &Path) -> bool {
    Command::new("mkfifo").arg(p).status().is_ok_and(|s| s.success())
}

/// A geographic scenario over 1 x 1 degree reading `terrain` and/or `current` files.
fn geo_scenario(terrain: Option<&str>, current: Option<&str>) -> String {
    let mut s = String::from(
        "name = \"hostile\"\n[world]\ndimensions = 2\nframe = \"geographic\"\n\
         bounds = { min = [-125.0, 48.0, 0.0], max = [-124.0, 49.0, 0.0] }\nepoch = \"2025-01-01T00:00:00Z\"\n",
    );
    if let Some(t) = terrain {
        s += &format!("[world.terrain]\nkind = \"file\"\npath = \"{t}\"\n");
    }
    if let Some(c) = current {
        s += &format!("[world.current]\nkind = \"file\"\npath = \"{c}\"\n");
    }
    s + "[vehicle]\nspeed = 2.0\n[mission]\nstart = [-124.9, 48.1, 0.0]\ngoal = [-124.1, 48.9, 0.0]\n"
}

#[test]
fn fifos_as_inputs_are_refused_not_waited_on() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for name in ["t.asc", "t.nc", "t.tif", "c.nc", "s.toml", "p.json"] {
        if !mkfifo(&d.join(name)) {
            return; // no mkfifo here
        }
    }
    for (i, (terrain, current)) in
        [(Some("t.asc"), None), (Some("t.nc"), None), (Some("t.tif"), None), (None, Some("c.nc"))].iter().enumerate()
    {
        let f = d.join(format!("s{i}.toml"));
        std::fs::write(&f, geo_scenario(*terrain, *current)).unwrap();
        let r = run_in(d, &["plan", f.to_str().unwrap()], Duration::from_secs(20));
        refused(&r, &["not a regular file"]);
    }
    refused(&run_in(d, &["plan", "s.toml"], Duration::from_secs(20)), &["SCENARIO", "not a regular file"]);
    refused(&run_in(d, &["eval", "demo", "p.json"], Duration::from_secs(20)), &["not a regular file"]);
    refused(&run_in(d, &["plan", "demo", "--init", "p.json"], Duration::from_secs(20)), &["not a regular file"]);
}

#[test]
fn size_bombs_as_data_files_are_refused_before_allocating() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::os::unix::fs::symlink("/dev/zero", d.join("zero.asc")).unwrap();
    // 20 GB of nothing, sparse: no disk is used.
    std::fs::File::create(d.join("sparse.asc")).unwrap().set_len(20_000_000_000).unwrap();
    let header = |nx: u64, ny: u64| format!("ncols {nx}\nnrows {ny}\nxllcorner -125\nyllcorner 48\ncellsize 0.0001\n");
    std::fs::write(d.join("h1.asc"), header(46_340, 46_340)).unwrap();
    std::fs::write(d.join("h2.asc"), header(2, 1_000_000_000)).unwrap();
    std::fs::write(d.join("h3.asc"), header(1_000_000_000, 2)).unwrap();
    std::fs::write(d.join("h4.asc"), header(10_000, 10_000)).unwrap();
    for (file, words) in [
        ("zero.asc", &["not a regular file"][..]),
        ("sparse.asc", &["header line 1 is longer"]),
        ("h1.asc", &["46340 x 46340", "exceed"]),
        ("h2.asc", &["nrows", "1048576"]),
        ("h3.asc", &["ncols", "1048576"]),
        ("h4.asc", &["need at least", "the file has"]),
    ] {
        let f = d.join(format!("{file}.toml"));
        std::fs::write(&f, geo_scenario(Some(file), None)).unwrap();
        let r = run(d, &["plan", f.to_str().unwrap()]);
        refused(&r, words);
        assert!(r.took < Duration::from_secs(10), "{file}: {:?}", r.took);
    }
}

#[test]
fn forecasts_declaring_more_than_memory_are_refused_from_the_header() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (steps, nlat, nlon) in [(9000, 1001, 1001), (200, 1001, 1001), (9000, 201, 201)] {
        let bytes = forecast_bomb(steps, nlat, nlon);
        assert!(bytes.len() < 100_000, "{} bytes", bytes.len());
        std::fs::write(d.join("bomb.nc"), bytes).unwrap();
        std::fs::write(d.join("s.toml"), geo_scenario(None, Some("bomb.nc"))).unwrap();
        let r = run(d, &["plan", "s.toml"]);
        refused(&r, &["bomb.nc", "more than the limit of 67108864"]);
        assert!(r.took < Duration::from_secs(10), "{:?}", r.took);
    }
    std::fs::write(d.join("bomb.nc"), forecast_bomb(10_000, 3, 3)).unwrap();
    refused(&run(d, &["plan", "s.toml"]), &["10000 time steps", "9000"]);
}

#[test]
fn scenario_and_plan_files_beyond_their_size_limit_are_refused_unread() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::File::create(d.join("big.toml")).unwrap().set_len(1 << 30).unwrap();
    std::fs::File::create(d.join("big.json")).unwrap().set_len(3 << 30).unwrap();
    let r = run(d, &["plan", "big.toml"]);
    refused(&r, &["SCENARIO", "1073741824 bytes", "limit"]);
    assert!(r.took < Duration::from_secs(5));
    refused(&run(d, &["eval", "demo", "big.json"]), &["3221225472 bytes", "limit"]);
    refused(&run(d, &["plan", "/dev/zero"]), &["not a regular file"]);
}

// ---------------------------------------------------------------------------------------------
// Counts and dates at the edge

#[test]
fn run_counts_at_the_edge_of_the_integers_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    for runs in ["18446744073709551615", "9223372036854775808", "0", "100001"] {
        for args in [
            &["compare", "demo", "--planners", "pso", "--runs", runs][..],
            &["reproduce", "amfa2015", "--only", "tables", "--runs", runs, "--out", "r"],
            &["bench", "functions", "--algos", "pso", "--funcs", "sphere", "--runs", runs],
        ] {
            let r = run(dir.path(), args);
            let expect = if runs == "0" && args[0] == "reproduce" { "at least 2" } else { "--runs" };
            refused(&r, &[expect, runs]);
        }
    }
    let r = run(dir.path(), &["bench", "functions", "--algos", "pso", "--funcs", "sphere", "--evaluations", "0"]);
    refused(&r, &["--evaluations", "at least 1"]);
    let r = run(dir.path(), &["bench", "functions", "--algos", "pso", "--funcs", "sphere", "--preset", "wpa2071"]);
    refused(&r, &["--preset", "unknown preset 'wpa2071'", "known: wpa2017"]);
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none(), "files left behind");
}

#[test]
fn dates_at_the_edge_of_the_calendar_are_refused_when_the_scenario_loads() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let base = geo_scenario(None, None);
    for (epoch, departure, words) in [
        ("-262143-01-01T00:00:00Z", "-262143-01-01T00:00:00Z", "-262143"),
        ("+262142-12-31T23:00:00", "2025-01-01T00:00:00Z", "outside the years 1800 to 2300"),
        ("1799-12-31T23:59:59Z", "2025-01-01T00:00:00Z", "outside the years 1800 to 2300"),
        ("2025-01-01T00:00:00Z", "2301-01-01T00:00:00Z", "outside the years 1800 to 2300"),
    ] {
        let text = base
            .replace("epoch = \"2025-01-01T00:00:00Z\"", &format!("epoch = \"{epoch}\""))
            .replace("goal = [-124.1, 48.9, 0.0]", &format!("goal = [-124.1, 48.9, 0.0]\ndeparture = \"{departure}\""));
        std::fs::write(d.join("s.toml"), text).unwrap();
        for out in ["p.gpx", "p.csv", "p.geojson"] {
            let r = run(d, &["plan", "s.toml", "--planner", "visibility", "--out", out]);
            assert_eq!(r.code, Some(2), "{epoch} / {departure}: {}", r.stderr);
            refused(&r, &[words]);
            assert!(!d.join(out).exists());
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Bounded work

#[test]
fn eval_of_a_hundred_thousand_far_away_waypoints_ends_quickly() {
    let dir = tempfile::tempdir().unwrap();
    let mut pts = vec!["[1000, 6000, -400]".to_string()];
    for i in 0..99_998 {
        let x = if i % 2 == 0 { "1e15" } else { "-1e15" };
        let y = if i % 3 == 0 { "1e15" } else { "-1e15" };
        pts.push(format!("[{x}, {y}, -400]"));
    }
    pts.push("[19000, 6500, -300]".into());
    std::fs::write(dir.path().join("zig.json"), format!("{{\"waypoints\": [{}]}}", pts.join(","))).unwrap();
    let r = run(dir.path(), &["eval", "demo", "zig.json"]);
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    assert!(r.stdout.contains("outside the domain") && r.stdout.contains("more"), "violations listed in part");
    assert!(r.stdout.lines().count() < 200, "{} lines", r.stdout.lines().count());
    assert!(r.took < Duration::from_secs(30), "{:?}", r.took);
}

/// With a turning radius every turn is judged on chords: a plan of 100,000 quarter turns at a
/// 400 m radius with a millimetre arc tolerance asks for more chords than the evaluation's limit, and is refused
/// in one line before any is flown.
#[test]
fn eval_of_a_hundred_thousand_finely_judged_turns_is_refused_before_flying_them() {
    let dir = tempfile::tempdir().unwrap();
    let toml = demo_text()
        .replace("safety_distance = 25.0", "safety_distance = 25.0\nturn_radius = 400.0")
        .replace("[model]", "[model]\narc_tolerance = 0.001");
    assert!(toml.contains("turn_radius") && toml.contains("arc_tolerance"), "the demo's text changed");
    std::fs::write(dir.path().join("turns.toml"), toml).unwrap();
    // Round and round a 900 m square: every quarter turn fits the 400 m radius.
    let corners = ["[5000, 5000, -400]", "[5900, 5000, -400]", "[5900, 5900, -400]", "[5000, 5900, -400]"];
    let mut pts = vec!["[1000, 6000, -400]".to_string()];
    pts.extend((0..99_998).map(|i| corners[i % 4].to_string()));
    pts.push("[19000, 6500, -300]".into());
    std::fs::write(dir.path().join("zig.json"), format!("{{\"waypoints\": [{}]}}", pts.join(","))).unwrap();
    let r = run(dir.path(), &["eval", "turns.toml", "zig.json"]);
    refused(&r, &["judging these paths", "arc_tolerance"]);
    assert!(r.took < Duration::from_secs(10), "{:?}", r.took);
}

#[test]
fn feature_counts_beyond_their_limit_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let peaks: Vec<String> = (0..10_000)
        .map(|i| format!("{{ x = {}.0, y = 10.0, height = 5.0, sigma_x = 3.0, sigma_y = 3.0 }}", i % 90))
        .collect();
    let text = format!(
        "name = \"peaks\"\n[world]\ndimensions = 2\nbounds = {{ min = [0.0, 0.0, 0.0], max = [100.0, 100.0, 0.0] }}\n\
         [world.terrain]\nkind = \"peaks\"\nbase = -50.0\npeaks = [{}]\n[vehicle]\nspeed = 2.0\n\
         [mission]\nstart = [1.0, 1.0, 0.0]\ngoal = [99.0, 99.0, 0.0]\n",
        peaks.join(", ")
    );
    std::fs::write(d.join("peaks.toml"), text).unwrap();
    refused(&run(d, &["plan", "peaks.toml", "--planner", "astar"]), &["world.terrain.peaks", "4096", "10000"]);
}

// ---------------------------------------------------------------------------------------------
// Outputs on a late refusal

#[test]
fn no_output_is_written_when_a_later_flag_is_refused() {
    for reference in ["bogus", "visibility", ""] {
        refused_leaving_all(
            |_| {},
            &["plan", "demo", "--iterations", "3", "--out", "c.json", "--plot", "c.svg", "--reference", reference],
            &["--reference"],
        );
    }
    // A plot target that cannot be written: the JSON is not written either.
    refused_leaving_all(
        |d| std::fs::create_dir(d.join("y.svg")).unwrap(),
        &["plan", "demo", "--iterations", "3", "--out", "x.json", "--plot", "y.svg"],
        &["--plot", "is a directory"],
    );
    // A missing OMPL log folder: no result folder either.
    refused_leaving_all(
        |_| {},
        &[
            "compare",
            "demo",
            "--planners",
            "pso",
            "--runs",
            "2",
            "--iterations",
            "3",
            "--out",
            "res",
            "--ompl-log",
            "missing/x.log",
        ],
        &["--ompl-log", "does not exist"],
    );
    // A bad planner among the compared ones, or a bad reference: nothing runs, nothing is written.
    refused_leaving_all(
        |_| {},
        &["compare", "demo", "--planners", "pso,nope", "--runs", "2", "--out", "res"],
        &["--planners", "nope"],
    );
    refused_leaving_all(
        |_| {},
        &["compare", "demo", "--planners", "pso", "--runs", "2", "--out", "res", "--reference", "visibility"],
        &["--reference", "2-D"],
    );
}

#[test]
fn two_outputs_naming_one_file_are_an_input_error() {
    refused_leaving_all(
        |_| {},
        &["plan", "demo", "--iterations", "3", "--out", "x.json", "--plot", "./x.json"],
        &["--plot", "also the --out file"],
    );
    refused_leaving_all(
        |d| std::fs::create_dir(d.join("sub")).unwrap(),
        &["plan", "demo", "--iterations", "3", "--out", "x.json", "--plot", "sub/../x.json"],
        &["also the --out file"],
    );
    refused_leaving_all(
        |_| {},
        &["compare", "demo", "--planners", "pso", "--runs", "2", "--out", "res", "--ompl-log", "res/table.md"],
        &["--ompl-log", "also the --out file"],
    );
}

#[test]
fn damaged_plan_files_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("tail.json"), r#"{"waypoints": [[1000, 6000, -400], [19000, 6500, -300]]} trailing"#)
        .unwrap();
    std::fs::write(d.join("v0.json"), r#"{"version": 0, "waypoints": [[1000, 6000, -400], [19000, 6500, -300]]}"#)
        .unwrap();
    refused(&run(d, &["eval", "demo", "tail.json"]), &["tail.json", "unexpected text after"]);
    refused(&run(d, &["eval", "demo", "v0.json"]), &["v0.json: version", "got 0"]);
}

// ---------------------------------------------------------------------------------------------
// Messages

#[test]
fn values_with_newlines_stay_on_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let demo = demo_text();
    refused(&run(d, &["plan", "demo", "--planner", "ps\no"]), &["ps\\no"]);
    refused(&run(d, &["plan", "no\nsuch\rscenario"]), &["no\\nsuch\\rscenario"]);
    let geo = geo_scenario(Some("a\\nb.asc"), None);
    std::fs::write(d.join("g.toml"), geo).unwrap();
    refused(&run(d, &["plan", "g.toml"]), &["a\\nb.asc"]);
    let text = geo_scenario(None, None).replace("2025-01-01T00:00:00Z", "2025-01-01\\nT00:00");
    std::fs::write(d.join("t.toml"), text).unwrap();
    refused(&run(d, &["plan", "t.toml"]), &["world.epoch", "2025-01-01\\nT00:00"]);
    std::fs::write(d.join("n.toml"), demo.replacen("name = \"demo\"", "name = \"de\\nmo\"", 1)).unwrap();
    refused(&run(d, &["plan", "n.toml", "--reference", "nope"]), &["--reference"]);
}

#[test]
fn messages_name_the_value_the_user_gave() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    refused(&run(d, &["plan", "demo", "--time-limit", "1e-300"]), &["--time-limit", "1e-300"]);
    let salish = run(d, &["scenario", "salish"]).stdout;
    let fine = salish.replace("path = \"salish_topobathy.nc\"", "path = \"salish_topobathy.nc\"\nresolution = 1e-300");
    std::fs::write(d.join("r.toml"), fine).unwrap();
    refused(&run(d, &["plan", "r.toml"]), &["world.terrain.resolution", "1e-300"]);
    let coarse = salish.replace("path = \"salish_topobathy.nc\"", "path = \"salish_topobathy.nc\"\ndecimate = 10000");
    std::fs::write(d.join("c.toml"), coarse).unwrap();
    refused(&run(d, &["plan", "c.toml"]), &["world.terrain.decimate", "10000"]);
}

#[test]
fn no_subcommand_prints_the_usage_and_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let r = run(dir.path(), &[]);
    assert_eq!(r.code, Some(2));
    assert!(r.stderr.contains("Usage: tidepath"), "{}", r.stderr);
}

/// Where this test's binary writes nothing unasked: a folder argument that is a file.
#[test]
fn an_output_folder_that_is_a_file_is_refused() {
    refused_leaving_all(
        |d| std::fs::write(d.join("res"), "a file").unwrap(),
        &["compare", "demo", "--planners", "pso", "--runs", "2", "--out", "res"],
        &["--out", "not a folder"],
    );
    refused_leaving_all(
        |d| std::fs::write(d.join("r"), "a file").unwrap(),
        &["reproduce", "amfa2015", "--only", "tables", "--runs", "2", "--out", "r/sub"],
        &["--out", "not a folder"],
    );
}

/// Work that grows with the input stays inside the run's clock: a fine raster over thousands
/// of peaks, thousands of vortices under the composite planner.
#[test]
fn rasters_and_references_keep_the_time_limit() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let peaks: Vec<String> = (0..4096)
        .map(|i| {
            format!(
                "{{ x = {}.0, y = {}.0, height = 5.0, sigma_x = 30.0, sigma_y = 30.0 }}",
                i % 64 * 150,
                i / 64 * 150
            )
        })
        .collect();
    let text = format!(
        "name = \"peaks\"\n[world]\ndimensions = 2\nbounds = {{ min = [0.0, 0.0, 0.0], max = [10000.0, 10000.0, 0.0] }}\n\
         [world.terrain]\nkind = \"peaks\"\nbase = -50.0\npeaks = [{}]\n[vehicle]\nspeed = 2.0\n\
         [mission]\nstart = [10.0, 10.0, 0.0]\ngoal = [9990.0, 9990.0, 0.0]\n[planner.params.astar]\ncells = 4096\n",
        peaks.join(", ")
    );
    std::fs::write(d.join("peaks.toml"), text).unwrap();
    let r = run(d, &["plan", "peaks.toml", "--planner", "astar", "--time-limit", "1"]);
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    assert!(r.stdout.contains("stopped by wall_time"), "{}", r.stdout);
    assert!(r.took < Duration::from_secs(5), "{:?}", r.took);
    let vortices: Vec<String> = (0..4096)
        .map(|i| format!("{{ x = {}.0, y = {}.0, strength = 50.0, core_radius = 200.0 }}", i % 64 * 150, i / 64 * 150))
        .collect();
    let text = format!(
        "name = \"eddies\"\n[world]\ndimensions = 2\nbounds = {{ min = [0.0, 0.0, 0.0], max = [10000.0, 10000.0, 0.0] }}\n\
         [world.current]\nkind = \"vortices\"\nvortices = [{}]\n[vehicle]\nspeed = 2.0\n\
         [mission]\nstart = [10.0, 10.0, 0.0]\ngoal = [9990.0, 9990.0, 0.0]\n",
        vortices.join(", ")
    );
    std::fs::write(d.join("eddies.toml"), text).unwrap();
    let r = run(d, &["plan", "eddies.toml", "--planner", "hybrid", "--time-limit", "1"]);
    assert!(matches!(r.code, Some(0) | Some(1)), "{}", r.stderr);
    assert!(r.took < Duration::from_secs(5), "{:?}", r.took);
}

/// A GeoTIFF whose no-data text tag declares 2 GB: one error line, not the `tiff` crate's
/// stray debug print beside it.
#[test]
fn a_geotiff_text_tag_longer_than_its_file_is_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fixture = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tidepath-io/tests/data/geo/bathy_area.tif");
    let mut b = std::fs::read(fixture).unwrap();
    // Classic little-endian TIFF: the first IFD's entries are (tag, type, count, value).
    assert_eq!(&b[..4], b"II*\0");
    let ifd = u32::from_le_bytes(b[4..8].try_into().unwrap()) as usize;
    let n = u16::from_le_bytes(b[ifd..ifd + 2].try_into().unwrap()) as usize;
    let entry = (0..n).map(|k| ifd + 2 + 12 * k).find(|&e| u16::from_le_bytes([b[e], b[e + 1]]) == 42113).unwrap();
    b[entry + 4..entry + 8].copy_from_slice(&0x7fff_ffffu32.to_le_bytes());
    std::fs::write(d.join("nodata.tif"), b).unwrap();
    std::fs::write(d.join("s.toml"), geo_scenario(Some("nodata.tif"), None)).unwrap();
    refused(&run(d, &["plan", "s.toml"]), &["nodata.tif", "text tag 42113 declares 2147483647 bytes"]);
}
