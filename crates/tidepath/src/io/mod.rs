//! Files tidepath reads and writes: the plan JSON, and safe output files (all or none, never
//! over a symlink, FIFO or device).

pub mod export;
pub mod geodata;
pub mod input;
pub mod output;
pub mod plan_json;

pub use output::{write_atomic, OutputId, Outputs};
pub use plan_json::{MissionReport, PlanAbout, PlanFile, PlanReport, PLAN_FORMAT_VERSION};
