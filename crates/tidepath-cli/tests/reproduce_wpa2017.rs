//! `tidepath reproduce wpa2017` at the command line: listed, and bad input refused before any
//! run. Its experiments at a small budget are tested in the library
//! (`reproduce::wpa2017::tests`); the paper's budgets take minutes, too long for a test.

use std::process::{Command, Output};

fn tidepath(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).output().expect("tidepath runs")
}

#[test]
fn reproduce_list_shows_wpa2017() {
    let o = tidepath(&["reproduce", "list"]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    let line = text.lines().find(|l| l.starts_with("wpa2017 ")).unwrap_or_else(|| panic!("{text}"));
    assert!(line.contains("Table 5") && line.contains("[Zhang et al. 2017 (wpa2017)"), "{line}");
}

/// Too few runs, an unknown reference planner: refused in one line naming the flag, and no
/// output folder is made.
#[test]
fn reproduce_wpa2017_refuses_bad_input_before_running() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    let out_s = out.to_str().unwrap();
    for (args, expect) in [
        (vec!["reproduce", "wpa2017", "--runs", "1", "--out", out_s], "error: --runs: needs at least 2 runs"),
        (
            vec!["reproduce", "wpa2017", "--reference", "nope", "--out", out_s],
            "error: --reference: unknown planner 'nope'",
        ),
    ] {
        let o = tidepath(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.starts_with(expect) && err.lines().count() == 1, "{args:?}: {err}");
        assert!(!out.exists());
    }
}
