//! Scenarios: world, vehicle, mission, cost model and planner settings in one TOML file.
//!
//! Loading runs in three steps, each with one-line errors that name the field and value:
//! TOML syntax, a walk that rejects NaN and infinities anywhere (TOML allows `nan` and `inf`),
//! then typed decoding and semantic checks (`build.rs`).

mod build;
mod builtin;
mod cell_endpoints;
mod cells;
mod changes_build;
mod changes_spec;
#[cfg(test)]
mod changes_tests;
mod fleet_spec;
mod forecast;
mod geo_cover;
pub mod geographic;
mod jet;
mod plan;
mod resample;
mod route_frame;
pub mod spec;
mod waves_build;
mod waves_spec;
mod world_build;

pub use build::Scenario;
pub use builtin::{builtin, builtin_names, registry, BUILTIN};
pub use changes_build::{MAX_CHANGES, MAX_RANDOM_DRAWS};
pub use fleet_spec::{FleetSpec, PairSpec, PresenceId};
pub use plan::{default_time_limit_s, Components, LimitSource, PlanRequest, DEFAULT_TIME_LIMIT_S};
pub use spec::ScenarioSpec;

pub use tidepath::config::{from_value, parse_toml};

use std::path::Path;

use tidepath::error::{Error, Result};

/// Loads a built-in scenario by name, or else a scenario file by path.
pub fn load(name_or_path: &str) -> Result<Scenario> {
    if let Some(text) = builtin(name_or_path) {
        return Scenario::from_toml(text, &format!("builtin:{name_or_path}"));
    }
    let path = Path::new(name_or_path);
    if !path.exists() {
        return Err(Error::input(
            "SCENARIO",
            format!(
                "'{name_or_path}' is neither a built-in scenario ({}) nor an existing file",
                builtin_names().collect::<Vec<_>>().join(", ")
            ),
        ));
    }
    let text = crate::input::read_text(path, "SCENARIO", crate::input::MAX_SCENARIO_BYTES)?;
    Scenario::from_toml(&text, &path.display().to_string())
}
