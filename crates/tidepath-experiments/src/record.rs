//! One run of one planner on one problem, as stored in `results.json` and `runs.csv`.

use serde::{Deserialize, Serialize};

use tidepath::optim::StopReason;
use tidepath::planner::Status;

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
    #[serde(deserialize_with = "null_as_nan")]
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
    /// The path found, start and goal included; empty for function benchmarks. For a fleet,
    /// the first mission's (every mission's is in `missions`).
    pub waypoints: Vec<[f64; 3]>,
    /// The plan's status (`None` for function benchmarks): exact, feasible, infeasible, ...
    #[serde(default)]
    pub status: Option<Status>,
    /// The search's other counts, as the plan reports them.
    #[serde(default)]
    pub expansions: u64,
    #[serde(default)]
    pub samples: u64,
    #[serde(default)]
    pub motion_checks: u64,
    #[serde(default)]
    pub graph_nodes: u64,
    /// Every mission's result (empty for function benchmarks).
    #[serde(default)]
    pub missions: Vec<MissionRecord>,
}

/// One mission of a run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MissionRecord {
    pub name: String,
    pub status: Status,
    /// The final path, start and goal included (empty when nothing was planned).
    pub waypoints: Vec<[f64; 3]>,
    /// Distance from the path's last point to the goal when it stops short (m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_distance_m: Option<f64>,
}

impl RunRecord {
    /// The largest distance left to a goal over the run's missions (m), when a path stopped
    /// short.
    pub fn goal_distance_m(&self) -> Option<f64> {
        self.missions.iter().filter_map(|m| m.goal_distance_m).reduce(f64::max)
    }
}

impl Default for RunRecord {
    fn default() -> Self {
        Self {
            problem: String::new(),
            planner: String::new(),
            run: 0,
            seed: 0,
            cost: f64::INFINITY,
            feasible: false,
            length_m: None,
            travel_time_s: None,
            evaluations: 0,
            iterations: 0,
            elapsed_s: 0.0,
            stop_reason: StopReason::Completed,
            history: Vec::new(),
            waypoints: Vec::new(),
            status: None,
            expansions: 0,
            samples: 0,
            motion_checks: 0,
            graph_nodes: 0,
            missions: Vec::new(),
        }
    }
}

/// Reads a number JSON wrote as `null`: serde_json writes NaN and the infinities as `null`
/// (a planner row with no run, a run without a finite cost), and a results.json read back
/// (`merge`) must take what it wrote. `null` becomes NaN.
pub(crate) fn null_as_nan<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    use serde::Deserialize;
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}
