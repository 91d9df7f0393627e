//! `compare --shard K/N` and `merge` (issue #36): three shards joined write what one compare
//! writes, timings aside; shards that do not make one compare are refused, nothing written.

use std::path::{Path, PathBuf};
use std::process::Output;

use super::tidepath;

/// 2 planners x 3 runs on the 2-D `headland`, 10 iterations each: six runs, a fraction of a
/// second.
const COMPARE: [&str; 10] =
    ["compare", "headland", "--planners", "pso,de", "--runs", "3", "--iterations", "10", "--seed", "5"];

fn run(extra: &[&str]) -> Output {
    let args: Vec<&str> = COMPARE.iter().copied().chain(extra.iter().copied()).collect();
    tidepath(&args, &[])
}

fn text(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The shards K/3 of [`COMPARE`] (with `extra` flags) in `dir/part-K`.
fn shards(dir: &Path, extra: &[&str]) -> Vec<PathBuf> {
    (1..=3)
        .map(|k| {
            let part = dir.join(format!("part-{k}"));
            let share = format!("{k}/3");
            let mut args = vec!["--shard", share.as_str(), "--out", part.to_str().unwrap(), "--jobs", "1"];
            args.extend(extra);
            let o = run(&args);
            assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
            part
        })
        .collect()
}

fn merge(dirs: &[&Path], out: &Path) -> Output {
    let mut args = vec!["merge"];
    args.extend(dirs.iter().map(|d| d.to_str().unwrap()));
    args.extend(["--out", out.to_str().unwrap()]);
    tidepath(&args, &[])
}

/// results.json without its timing fields.
fn untimed(path: &Path) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                for k in tidepath_experiments::output::TIMING_FIELDS {
                    m.remove(*k);
                }
                m.values_mut().for_each(strip);
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v: serde_json::Value = serde_json::from_str(&text(path)).unwrap();
    strip(&mut v);
    v
}

/// `text`'s table without the column headed `name`, columns split at `sep` (lines without a
/// separator kept as they are).
fn without_column(text: &str, sep: char, name: &str) -> String {
    let header = text.lines().find(|l| l.split(sep).any(|c| c.trim() == name)).expect("the column is there");
    let at = header.split(sep).position(|c| c.trim() == name).unwrap();
    let cut = |l: &str| {
        if !l.contains(sep) {
            return l.to_string();
        }
        l.split(sep).enumerate().filter(|(i, _)| *i != at).map(|(_, c)| c).collect::<Vec<_>>().join(&sep.to_string())
    };
    text.lines().map(cut).collect::<Vec<_>>().join("\n")
}

#[test]
fn three_shards_merged_write_what_one_compare_writes() {
    let dir = tempfile::tempdir().unwrap();
    let whole = dir.path().join("whole");
    let o = run(&["--out", whole.to_str().unwrap(), "--jobs", "2"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let parts = shards(dir.path(), &[]);
    // A shard writes its share's records and the block merge checks, nothing else.
    let names: Vec<String> =
        std::fs::read_dir(&parts[1]).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
    assert_eq!(names, ["results.json"]);
    let part: serde_json::Value = serde_json::from_str(&text(&parts[1].join("results.json"))).unwrap();
    let runs: Vec<(&str, u64)> = part["records"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| (r["planner"].as_str().unwrap(), r["run"].as_u64().unwrap()))
        .collect();
    assert_eq!(runs, [("pso", 1), ("de", 1)], "share 2 of 3 holds runs 1 and 4 of the six");
    assert_eq!((part["shard"]["k"].as_u64(), part["shard"]["n"].as_u64()), (Some(2), Some(3)));
    assert_eq!(part["shard"]["scenario"], "builtin:headland");

    let all = dir.path().join("all");
    let o = merge(&[&parts[2], &parts[0], &parts[1]], &all);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("| pso |"));
    assert_eq!(untimed(&all.join("results.json")), untimed(&whole.join("results.json")));
    for (file, sep, timing) in [("runs.csv", ',', "elapsed_s"), ("table.md", '|', "wall s/run")] {
        let (a, b) = (text(&all.join(file)), text(&whole.join(file)));
        assert_eq!(without_column(&a, sep, timing), without_column(&b, sep, timing), "{file}");
    }
    for figure in ["convergence.svg", "boxplot.svg", "paths.svg"] {
        assert_eq!(text(&all.join(figure)), text(&whole.join(figure)), "{figure}");
    }
}

/// Exit 2 with one line naming the problem, and `out` never created.
fn refused(dirs: &[&Path], out: &Path, message: &str) {
    let o = merge(dirs, out);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(e.contains(message), "{e} lacks {message}");
    assert!(!out.exists(), "{} was created", out.display());
}

#[test]
fn shards_that_are_not_one_whole_compare_are_refused_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let parts = shards(dir.path(), &[]);
    let (one, two, three) = (parts[0].as_path(), parts[1].as_path(), parts[2].as_path());
    let out = dir.path().join("out");
    refused(&[one, three], &out, "shard 2/3 is missing");
    refused(&[one, two, two, three], &out, "shard 2/3 is given twice");
    let other = dir.path().join("seed-6");
    let o =
        tidepath(&[&COMPARE[..8], &["--seed", "6", "--shard", "2/3", "--out", other.to_str().unwrap()]].concat(), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    refused(&[one, &other, three], &out, "shard 2/3 ('");
    refused(&[one, &other, three], &out, "differs in master seed: 6; shard 1/3 (");
    // An existing results folder is left as it was.
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("results.json"), "mine").unwrap();
    assert_eq!(merge(&[one, three], &out).status.code(), Some(2));
    assert_eq!(text(&out.join("results.json")), "mine");
    assert_eq!(std::fs::read_dir(&out).unwrap().count(), 1);
}

#[test]
fn bad_shards_are_refused_naming_the_flag_and_value() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    for bad in ["0/3", "4/3", "a/b", "7/7"] {
        let o = run(&["--shard", bad, "--out", out.to_str().unwrap()]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{bad}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(e.contains("--shard") && e.contains(&format!("'{bad}'")), "{e}");
        assert!(!out.exists());
    }
}

/// More shares than runs of a planner: a share holding no run of one planner writes that row's
/// statistics as `null` (NaN in JSON), and merge reads them back: six shares of the six runs
/// join into the unsharded comparison.
#[test]
fn shares_without_a_run_of_some_planner_still_merge() {
    let dir = tempfile::tempdir().unwrap();
    let whole = dir.path().join("whole");
    let o = run(&["--out", whole.to_str().unwrap(), "--jobs", "1"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let parts: Vec<PathBuf> = (1..=6)
        .map(|k| {
            let part = dir.path().join(format!("six-{k}"));
            let share = format!("{k}/6");
            let o = run(&["--shard", share.as_str(), "--out", part.to_str().unwrap(), "--jobs", "1"]);
            assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
            part
        })
        .collect();
    let out = dir.path().join("merged");
    let refs: Vec<&Path> = parts.iter().map(|p| p.as_path()).collect();
    let o = merge(&refs, &out);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(untimed(&out.join("results.json")), untimed(&whole.join("results.json")));
}
