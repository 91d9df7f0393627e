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
