//! `--repair` (plan and compare) and `[encoding] repair`: amfa2015's excluding and contracting
//! operators applied inside an optimizer's search.

use super::tidepath;

fn run(args: &[&str]) -> std::process::Output {
    tidepath(args, &[])
}

fn stdout(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The plan's cost and length lines (the wall time varies between runs).
fn numbers(text: &str) -> String {
    let lines: Vec<&str> =
        text.lines().filter(|l| l.trim_start().starts_with("cost") || l.trim_start().starts_with("length")).collect();
    assert_eq!(lines.len(), 2, "{text}");
    lines.join("\n")
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `plan --repair` changes the search (the same seed gives another plan) and keeps it
/// deterministic; a bad id or parameter is refused with one line naming it.
#[test]
fn plan_takes_a_repair_and_refuses_bad_ones() {
    let plan = |extra: &[&str]| {
        let mut args = vec!["plan", "demo", "--planner", "pso", "--evaluations", "1500"];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        numbers(&stdout(&o))
    };
    let plain = plan(&[]);
    let repaired = plan(&["--repair", "exclude-contract:margin=5"]);
    assert_eq!(repaired, plan(&["--repair", "exclude-contract:margin=5"]));
    assert_ne!(plain, repaired);
    assert_eq!(plain, plan(&["--repair", "none"]));
    for (flag, want) in [
        ("nope", "error: --repair: unknown repair 'nope' (known: exclude, contract, exclude-contract"),
        ("exclude:margin=-1", "error: encoding.repair_params.exclude.margin: must be in [0, inf), got -1"),
        ("contract:k", "error: --repair: `k` is not KEY=VALUE"),
    ] {
        let o = run(&["plan", "demo", "--planner", "pso", "--repair", flag]);
        assert_eq!(o.status.code(), Some(2), "{flag}");
        let e = stderr(&o);
        assert!(e.starts_with(want), "{flag}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
    }
}

/// `[encoding] repair` in a scenario file: a bad id fails before planning, naming the field.
#[test]
fn scenario_repair_field_is_checked() {
    let dir = tempfile::tempdir().unwrap();
    let demo =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../tidepath-io/scenarios/demo.toml")).unwrap();
    let write = |name: &str, extra: &str| {
        let text = demo.replacen("[encoding]\n", &format!("[encoding]\n{extra}\n"), 1);
        assert_ne!(text, demo);
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path
    };
    let good = write("good.toml", "repair = \"exclude\"\nrepair_params.exclude = { margin = 2.0 }");
    // Planned (exit 0 feasible, 1 infeasible), not refused (2).
    let o = run(&["plan", good.to_str().unwrap(), "--planner", "pso", "--evaluations", "500"]);
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", stderr(&o));
    assert!(stdout(&o).contains("pso (seed 1)"), "{}", stdout(&o));
    let bad = write("bad.toml", "repair = \"zz\"");
    let o = run(&["plan", bad.to_str().unwrap(), "--planner", "pso"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).starts_with("error: encoding.repair: unknown repair 'zz'"), "{}", stderr(&o));
}

/// `compare --repair` checks the id before any run; `planners` lists the repairs.
#[test]
fn compare_checks_the_repair_and_planners_lists_them() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad");
    let o = run(&["compare", "demo", "--planners", "pso", "--repair", "nope", "--out", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).starts_with("error: --repair: unknown repair 'nope'"), "{}", stderr(&o));
    assert!(!bad.exists());
    let o = run(&[
        "compare",
        "demo",
        "--planners",
        "pso",
        "--runs",
        "2",
        "--iterations",
        "5",
        "--reference",
        "none",
        "--repair",
        "exclude-contract",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = run(&["planners"]);
    let text = stdout(&o);
    let repairs = text.split("Repairs inside the search").nth(1).expect("a Repairs section");
    for id in ["exclude", "contract", "exclude-contract"] {
        assert!(repairs.lines().any(|l| l.trim_start().starts_with(&format!("{id} "))), "{id}: {repairs}");
    }
    // And the same ids as smoothers, applied after a planner.
    let smoothers = text.split("Smoothers").nth(1).unwrap().split("Repairs").next().unwrap();
    assert!(smoothers.contains("exclude-contract"), "{smoothers}");
}
