//! The plan JSON written by `tidepath plan --out` and read by `tidepath eval`.
//! Field meanings are documented in README.md ("Plan JSON"); keep the two in step.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::optim::StopReason;
use crate::path::{Metrics, Violation};

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PlanReport {
    pub tidepath_version: String,
    pub planner: String,
    pub seed: u64,
    pub scenario: String,
    pub scenario_source: String,
    pub cost_model: String,
    /// "crab" or "vector-sum": which travel-time model the cost and metrics used.
    pub travel_time_model: String,
    /// The path, start and goal included, [x, y, z] in metres.
    pub waypoints: Vec<[f64; 3]>,
    /// The path after the smoother, when one ran. `cost`, `cost_terms`, `feasible`,
    /// `violations` and `metrics` then describe this path.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smoothed: Option<Vec<[f64; 3]>>,
    /// Cost of `waypoints` before smoothing, when a smoother ran.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub raw_cost: Option<f64>,
    /// Cost of the final path (`smoothed` if present, else `waypoints`).
    pub cost: f64,
    /// The weighted terms of the cost model, in the model's order; they sum to `cost`.
    pub cost_terms: serde_json::Map<String, serde_json::Value>,
    pub feasible: bool,
    pub violations: Vec<Violation>,
    pub metrics: Metrics,
    pub evaluations: u64,
    pub iterations: u64,
    pub stop_reason: StopReason,
    pub elapsed_s: f64,
    /// Best cost after initialisation and after each iteration (null where still infinite).
    pub history: Vec<Option<f64>>,
}

impl PlanReport {
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("plan report serialises") + "\n"
    }

    /// The final path: `smoothed` when present, else `waypoints`.
    pub fn points(&self) -> Vec<Vec3> {
        self.smoothed.as_ref().unwrap_or(&self.waypoints).iter().map(|p| Vec3::from_array(*p)).collect()
    }
}

/// The part of a plan file `eval` needs; other fields are optional so hand-written files work.
#[derive(Clone, Debug, Deserialize)]
pub struct PlanFile {
    pub waypoints: Vec<[f64; 3]>,
    #[serde(default)]
    pub smoothed: Option<Vec<[f64; 3]>>,
    #[serde(default)]
    pub cost: Option<f64>,
    #[serde(default)]
    pub planner: Option<String>,
    #[serde(default)]
    pub scenario: Option<String>,
}

impl PlanFile {
    pub fn read(path: &std::path::Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        Self::parse(&text, &path.display().to_string())
    }

    pub fn parse(text: &str, source: &str) -> Result<Self> {
        let de = &mut serde_json::Deserializer::from_str(text);
        let file: PlanFile = serde_path_to_error::deserialize(de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            let field = if path == "." { source.to_string() } else { format!("{source}: {path}") };
            Error::input(
                field,
                format!("{} (line {}, column {})", strip_position(&inner.to_string()), inner.line(), inner.column()),
            )
        })?;
        let lists = [("waypoints", Some(&file.waypoints)), ("smoothed", file.smoothed.as_ref())];
        for (name, list) in lists.into_iter().filter_map(|(n, l)| l.map(|l| (n, l))) {
            if list.len() < 2 {
                return Err(Error::input(
                    format!("{source}: {name}"),
                    format!("a path needs at least 2 points, got {}", list.len()),
                ));
            }
            for (i, p) in list.iter().enumerate() {
                if p.iter().any(|v| !v.is_finite()) {
                    return Err(Error::input(
                        format!("{source}: {name}[{i}]"),
                        format!("{p:?}: numbers must be finite"),
                    ));
                }
            }
        }
        Ok(file)
    }

    /// The final path: `smoothed` when present, else `waypoints`.
    pub fn points(&self) -> Vec<Vec3> {
        self.smoothed.as_ref().unwrap_or(&self.waypoints).iter().map(|p| Vec3::from_array(*p)).collect()
    }
}

/// serde_json appends " at line L column C"; we print the position once, our way.
fn strip_position(msg: &str) -> &str {
    msg.rfind(" at line ").map_or(msg, |i| &msg[..i])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_file_errors_name_the_field() {
        let e = PlanFile::parse(r#"{"waypoints": [[0,0,0],[1,"a",0]]}"#, "p.json").unwrap_err().to_string();
        assert!(e.starts_with("p.json: waypoints[1][1]: invalid type"), "{e}");
        let e = PlanFile::parse(r#"{"waypoints": [[0,0,0]]}"#, "p.json").unwrap_err().to_string();
        assert!(e.contains("at least 2 points"), "{e}");
        let e = PlanFile::parse("{not json", "p.json").unwrap_err().to_string();
        assert!(e.starts_with("p.json"), "{e}");
    }
}
