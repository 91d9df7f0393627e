//! `tidepath reproduce lfhh2019` at the command line: listed, and bad input refused before any
//! run. Its experiments at a tiny budget are tested in the library
//! (`reproduce::lfhh2019::tests`); even `--quick` takes many minutes, too long for a test.

use std::process::{Command, Output};

fn tidepath(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).output().expect("tidepath runs")
}

#[test]
fn reproduce_list_shows_lfhh2019() {
    let o = tidepath(&["reproduce", "list"]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    let line = text.lines().find(|l| l.starts_with("lfhh2019 ")).unwrap_or_else(|| panic!("{text}"));
    assert!(line.contains("Tables 2-3") && line.contains("[Liu et al. 2019 (lfhh2019)"), "{line}");
}

/// Too few runs, with or without `--quick`: refused in one line naming the flag, and no output
/// folder is made.
#[test]
fn reproduce_lfhh2019_refuses_bad_input_before_running() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    let out_s = out.to_str().unwrap();
    for args in [
        vec!["reproduce", "lfhh2019", "--runs", "1", "--out", out_s],
        vec!["reproduce", "lfhh2019", "--quick", "--runs", "0", "--out", out_s],
    ] {
        let o = tidepath(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.starts_with("error: --runs: needs at least 2 runs") && err.lines().count() == 1, "{args:?}: {err}");
        assert!(!out.exists());
    }
}
