//! `tidepath reproduce acopf2016` at the command line: listed, an unknown part refused before
//! any run, and `--only figures` at the quick budget writing the report with a plan view per
//! environment drawn by the plotting layer. The experiments themselves are tested in the
//! library (`reproduce::acopf2016::tests`).

use std::process::{Command, Output};

fn tidepath(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).output().expect("tidepath runs")
}

#[test]
fn reproduce_list_shows_acopf2016() {
    let o = tidepath(&["reproduce", "list"]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    let line = text.lines().find(|l| l.starts_with("acopf2016 ")).unwrap_or_else(|| panic!("{text}"));
    assert!(line.contains("Figs. 3-5") && line.contains("(acopf2016), section 4"), "{line}");
}

#[test]
fn reproduce_acopf2016_refuses_an_unknown_part() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    let o = tidepath(&["reproduce", "acopf2016", "--only", "maps", "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.starts_with("error: --only: `maps` is not a part of acopf2016 (known: figures, tables, ocean)")
            && err.lines().count() == 1,
        "{err}"
    );
    assert!(!out.exists());
}

/// The figures part at two runs: every environment's plan view is an SVG with the three paths
/// (ACOPF's, ACO's best and A*'s quickest as the reference); the variant's table is left out.
#[test]
fn reproduce_acopf2016_figures_draws_every_environment() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    let o = tidepath(&[
        "reproduce",
        "acopf2016",
        "--quick",
        "--runs",
        "2",
        "--only",
        "figures",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(out.join("REPORT.md")).unwrap();
    assert!(!md.contains("Travel time when the ants reward it"), "{md}");
    for id in ["fig3-glider-1", "fig4-glider-2", "fig5-glider-3", "env4-glider-4"] {
        let svg = std::fs::read_to_string(out.join(id).join("paths.svg")).unwrap();
        for label in ["acopf (best cost", "aco (best cost", "reference: astar"] {
            assert!(svg.contains(label), "{id}: {label}");
        }
    }
    assert!(!out.join("objective-cost").exists());
}
