//! Experiments: many seeded runs of several planners, statistics, tables, plots and logs.
//!
//! `runner` executes problems x planners x runs reproducibly in parallel, `compare` builds the
//! tasks for a scenario or for benchmark functions, `table` computes the per-planner rows the
//! papers report, `output` writes the files, `reproduce` sets our numbers beside a paper's.

pub mod columns;
pub mod compare;
pub mod ompl_log;
pub mod output;
pub mod record;
pub mod reproduce;
pub mod runner;
pub mod shard;
pub mod stats;
pub mod table;

#[cfg(test)]
mod sampling_compare_tests;

pub use record::RunRecord;
