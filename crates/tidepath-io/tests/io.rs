//! tidepath-io's integration tests, one test binary: each file of `tests/` is a module here
//! (`cargo test -p tidepath-io --test io planners::` runs one file's tests). One binary instead
//! of one per file: a fresh `cargo test --workspace` links and compiles the shared code once,
//! and the files' tests share the cores instead of running one binary after another.
//! `budgets.rs` stays a binary of its own: it times planners against their wall-clock budget,
//! which other tests running beside it would disturb.

mod common;

mod amfa_scenarios;
mod cells;
mod contract;
mod export;
mod feasibility_property;
mod fuzz;
mod fuzz_readers;
mod geodata;
mod geographic;
mod glider_scenarios;
mod ijs_scenarios;
mod jet_ratio;
mod kinematics;
mod lfhh2019_scenarios;
mod model_rule;
mod params_boundary;
mod planners;
mod posture;
mod reader_edges;
mod recheck_plans;
mod references;
mod sampling;
mod scenario_validation;
mod seabed_envelope;
mod waves;

/// With `autotests = false`, a file added to `tests/` runs only once declared above: this
/// fails naming any `tests/*.rs` that is neither declared here nor a binary of its own.
#[test]
fn every_test_file_is_declared() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let root = std::fs::read_to_string(dir.join("io.rs")).unwrap();
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        let Some(module) = name.strip_suffix(".rs") else { continue };
        if !["io", "budgets"].contains(&module) && !root.contains(&format!("\nmod {module};")) {
            missing.push(name);
        }
    }
    missing.sort();
    assert!(missing.is_empty(), "tests/ files not declared in tests/io.rs: {missing:?}");
}
