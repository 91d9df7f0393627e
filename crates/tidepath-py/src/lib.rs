//! Python bindings for tidepath: the native module `tidepath._tidepath`, re-exported by the
//! pure-Python package `tidepath` (python/tidepath/__init__.py).
//!
//! Every function here calls the library crates the way the CLI does (tidepath-io's
//! `Scenario::plan`, `evaluate_routes`, `export`; tidepath-experiments' `compare_share` and
//! `shard::merge`; tidepath's registries and optimizers), so a result from Python equals the
//! CLI's for the same seed. Errors of the library (`tidepath::Error`) become `ValueError`
//! with the same one-line message the CLI prints.

use pyo3::prelude::*;

mod compare;
mod convert;
mod fork;
mod optimize;
mod plan;
mod run;
mod scenario;

/// The registry listings: `scenarios()` and `planners()`.
mod listing;

#[pymodule]
fn _tidepath(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<scenario::PyScenario>()?;
    m.add_class::<plan::PyPlan>()?;
    m.add_class::<plan::PyMission>()?;
    m.add_function(wrap_pyfunction!(listing::scenarios, m)?)?;
    m.add_function(wrap_pyfunction!(listing::planners, m)?)?;
    m.add_function(wrap_pyfunction!(compare::compare_json, m)?)?;
    m.add_function(wrap_pyfunction!(compare::compare_share_json, m)?)?;
    m.add_function(wrap_pyfunction!(compare::merge_json, m)?)?;
    m.add_function(wrap_pyfunction!(optimize::optimize, m)?)?;
    m.add_function(wrap_pyfunction!(fork::after_fork_in_child, m)?)?;
    Ok(())
}
