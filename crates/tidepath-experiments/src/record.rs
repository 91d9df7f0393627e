//! One run of one planner on one problem, as stored in `results.json` and `runs.csv`.

use serde::{Deserialize, Serialize};

use tidepath::optim::StopReason;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunRecord {
    /// Scenario name, or the benchmark problem (e.g. `sphere-d30-small`).
    pub problem: String,
    pub planner: String,
    /// Run index i (0-based) within this (problem, planner) pair.
    pub run: u64,
    /// The seed this run used: derived from (master seed, problem, planner, i), so
    /// `tidepath plan PROBLEM --planner PLANNER --seed SEED` repeats it.
    pub seed: u64,
    /// Best cost found (for function benchmarks, the function value).
    pub cost: f64,
    /// The path is feasible (always true for function benchmarks).
    pub feasible: bool,
    /// Path length and travel time; `None` for function benchmarks.
    pub length_m: Option<f64>,
    pub travel_time_s: Option<f64>,
    pub evaluations: u64,
    pub iterations: u64,
    /// Wall time of the run (s). Timing fields are the only ones that differ between reruns.
    pub elapsed_s: f64,
    pub stop_reason: StopReason,
    /// Best cost after initialisation and after each iteration (`None` while still infinite).
    pub history: Vec<Option<f64>>,
    /// The path found, start and goal included; empty for function benchmarks.
    pub waypoints: Vec<[f64; 3]>,
}
