//! `tidepath plan` and `tidepath eval` print a cost model's own feasibility rule (lfhh2019:
//! F < 2) beside tidepath's verdict, and only for a model that has one.

use std::process::Command;

fn tidepath(dir: &std::path::Path, args: &[&str]) -> String {
    let o = Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(dir).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout).unwrap()
}

/// Plans the one-disc world with the given `[cost]` section into `plan.json`; the printout.
fn plan(dir: &std::path::Path, cost: &str) -> String {
    let text = format!(
        "name = \"one-disc\"\n[world]\ndimensions = 2\nbounds = {{ min = [0.0, 0.0, 0.0], max = [700.0, 500.0, 0.0] }}\n\
        [[world.obstacles]]\nkind = \"cylinder\"\ncenter = [350.0, 250.0]\nradius = 80.0\n\
        [vehicle]\nspeed = 1.5\nsafety_distance = 5.0\nmax_turn_deg = 180.0\n\
        [mission]\nstart = [50.0, 240.0, 0.0]\ngoal = [650.0, 260.0, 0.0]\n{cost}"
    );
    let file = dir.join("one-disc.toml");
    std::fs::write(&file, text).unwrap();
    tidepath(dir, &["plan", "one-disc.toml", "--planner", "visibility", "--out", "plan.json"])
}

fn rule_line(out: &str) -> Option<&str> {
    out.lines().find(|l| l.trim_start().starts_with("lfhh2019 rule"))
}

#[test]
fn plan_prints_the_papers_rule_beside_the_status() {
    let dir = tempfile::tempdir().unwrap();
    let out = plan(dir.path(), "[cost]\nmodel = \"lfhh2019\"\n");
    let line = rule_line(&out).unwrap_or_else(|| panic!("no rule line in:\n{out}"));
    assert!(line.contains("F < 2: met (F = 0.5"), "{line}");
    let out = tidepath(dir.path(), &["eval", "one-disc.toml", "plan.json"]);
    assert!(out.contains("lfhh2019 rule: F < 2: met (F = 0.5"), "{out}");
    let out = plan(dir.path(), "[cost]\nmodel = \"lfhh2019\"\nweights = { min_interior_angle_deg = 180.0 }\n");
    let line = rule_line(&out).unwrap_or_else(|| panic!("no rule line in:\n{out}"));
    assert!(line.contains("F < 2: not met (F = "), "{line}");
    let f: f64 = line.rsplit("F = ").next().unwrap().trim_end_matches(')').parse().unwrap();
    assert!(f >= 2.0, "{line}");
    // eval judges the written plan again and applies the same rule.
    let out = tidepath(dir.path(), &["eval", "one-disc.toml", "plan.json"]);
    let line = out.lines().find(|l| l.contains("lfhh2019 rule")).unwrap_or_else(|| panic!("{out}"));
    assert!(line.contains("F < 2: not met (F = "), "{line}");
    let out = plan(dir.path(), "");
    assert!(rule_line(&out).is_none() && !out.contains("F < 2"), "{out}");
    let out = tidepath(dir.path(), &["eval", "one-disc.toml", "plan.json"]);
    assert!(!out.contains("F < 2"), "{out}");
}
