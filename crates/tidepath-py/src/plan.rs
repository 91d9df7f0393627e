//! `tidepath.Plan` and `tidepath.Mission`: a plan's report with numpy arrays.

use chrono::{DateTime, Utc};
use pyo3::prelude::*;
use pyo3::types::PyAny;
use serde_json::{json, Value};
use tidepath_io::export::{export, ExportFormat, Georef};
use tidepath_io::scenario::Scenario;
use tidepath_io::{MissionReport, Outputs, PlanReport};

use crate::convert::{err, json_text_to_py, json_to_py, points_array, vector};

/// The result of `Scenario.plan`: the report `tidepath plan --out plan.json` writes.
#[pyclass(frozen, name = "Plan", module = "tidepath")]
pub struct PyPlan {
    report: PlanReport,
    frame: Option<tidepath::geo::GeoFrame>,
    epoch: Option<DateTime<Utc>>,
}

impl PyPlan {
    pub fn new(report: PlanReport, scenario: &Scenario) -> Self {
        Self { report, frame: scenario.frame.clone(), epoch: scenario.epoch }
    }

    /// The report, for the viewer.
    pub fn report(&self) -> &PlanReport {
        &self.report
    }

    fn georef(&self) -> Georef<'_> {
        Georef { frame: self.frame.as_ref(), epoch: self.epoch }
    }
}

/// The cost terms of a mission report as a JSON object (name -> value).
fn terms_of(m: &MissionReport) -> Value {
    Value::Object(m.cost_terms.clone())
}

#[pymethods]
impl PyPlan {
    /// The plan's status: "exact", "feasible", "infeasible", "timeout", "invalid-start",
    /// "invalid-goal", "unreachable" or "cancelled" (the worst of its missions').
    #[getter]
    fn status(&self) -> &'static str {
        self.report.status.id()
    }

    /// Why, in one line.
    #[getter]
    fn reason(&self) -> &str {
        &self.report.reason
    }

    /// The plan's cost (all missions, with a fleet's terms); None when nothing was planned.
    #[getter]
    fn cost(&self) -> Option<f64> {
        self.report.cost
    }

    #[getter]
    fn feasible(&self) -> bool {
        self.report.feasible
    }

    #[getter]
    fn planner(&self) -> &str {
        &self.report.planner
    }

    #[getter]
    fn seed(&self) -> u64 {
        self.report.seed
    }

    /// The weighted cost terms, summed over the missions (one mission: its terms).
    #[getter]
    fn terms(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let mut sum = serde_json::Map::new();
        for m in &self.report.missions {
            for (k, v) in &m.cost_terms {
                let total = sum.get(k).and_then(Value::as_f64).unwrap_or(0.0) + v.as_f64().unwrap_or(f64::NAN);
                sum.insert(k.clone(), json!(total));
            }
        }
        json_to_py(py, &Value::Object(sum))
    }

    /// The best cost after initialisation and after each iteration (NaN where the run had
    /// none), a 1-D float64 array.
    #[getter]
    fn history<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vector(py, self.report.history.iter().map(|h| h.unwrap_or(f64::NAN)).collect())
    }

    /// One `Mission` per mission of the scenario, in order.
    #[getter]
    fn missions(&self) -> Vec<PyMission> {
        let lonlat = self.report.geographic.as_ref().map(|g| &g.paths);
        self.report
            .missions
            .iter()
            .enumerate()
            .map(|(i, m)| PyMission {
                report: m.clone(),
                lonlat: lonlat.and_then(|p| p.get(i)).map(|p| p.iter().map(|q| [q[0], q[1]]).collect()),
            })
            .collect()
    }

    #[getter]
    fn evaluations(&self) -> u64 {
        self.report.evaluations
    }

    #[getter]
    fn iterations(&self) -> u64 {
        self.report.iterations
    }

    #[getter]
    fn expansions(&self) -> u64 {
        self.report.expansions
    }

    #[getter]
    fn samples(&self) -> u64 {
        self.report.samples
    }

    /// What ended the run: "iterations", "evaluations", "wall-time", "cancelled", ...
    #[getter]
    fn stop_reason(&self) -> &'static str {
        self.report.stop_reason.id()
    }

    /// Wall time of the run, in seconds.
    #[getter]
    fn elapsed_s(&self) -> f64 {
        self.report.elapsed_s
    }

    /// The plan JSON `tidepath plan --out plan.json` writes.
    fn to_json(&self) -> String {
        self.report.to_json()
    }

    /// The plan JSON parsed into plain Python objects.
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        json_text_to_py(py, &self.report.to_json())
    }

    /// Writes the plan in the format of the path's extension, as `tidepath plan --out`:
    /// .json (tidepath's plan), .csv, and in a geographic scenario .geojson, .kml, .gpx.
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        let format = ExportFormat::of(&path, "path").map_err(err)?;
        format.check(self.frame.as_ref(), "path").map_err(err)?;
        let mut outputs = Outputs::new();
        let id = outputs.declare("path", &path).map_err(err)?;
        outputs.fill(id, export(&self.report, format, self.georef()).map_err(err)?);
        outputs.commit().map_err(err)
    }

    fn __repr__(&self) -> String {
        let cost = self.report.cost.map_or("None".to_string(), |c| format!("{c:.6}"));
        format!(
            "Plan(planner={:?}, seed={}, status={:?}, cost={cost}, missions={})",
            self.report.planner,
            self.report.seed,
            self.report.status.id(),
            self.report.missions.len()
        )
    }
}

/// One mission of a plan.
#[pyclass(frozen, name = "Mission", module = "tidepath")]
pub struct PyMission {
    report: MissionReport,
    lonlat: Option<Vec<[f64; 2]>>,
}

#[pymethods]
impl PyMission {
    #[getter]
    fn name(&self) -> &str {
        &self.report.name
    }

    /// The planner's path, start and goal included: an `(n, 3)` float64 array in metres (the
    /// `waypoints` of the plan JSON).
    #[getter]
    fn waypoints<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        points_array(py, &self.report.waypoints)
    }

    /// The path after the smoother, when one ran (`(m, 3)`), else None.
    #[getter]
    fn smoothed<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyAny>> {
        self.report.smoothed.as_ref().map(|s| points_array(py, s))
    }

    /// The final path: the smoothed one when a smoother ran, else the waypoints.
    #[getter]
    fn path<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        points_array(py, self.report.smoothed.as_ref().unwrap_or(&self.report.waypoints))
    }

    /// Arrival time (s, scenario clock) at each point of the final path, a 1-D array.
    #[getter]
    fn times<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vector(py, self.report.times.clone())
    }

    /// The final path's (longitude, latitude) in degrees, `(n, 2)`, in a geographic
    /// scenario; None in a local one.
    #[getter]
    fn lonlat<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyAny>> {
        use numpy::IntoPyArray;
        self.lonlat.as_ref().map(|ll| {
            let flat: Vec<f64> = ll.iter().flatten().copied().collect();
            numpy::ndarray::Array2::from_shape_vec((ll.len(), 2), flat).expect("n x 2").into_pyarray(py).into_any()
        })
    }

    #[getter]
    fn cost(&self) -> Option<f64> {
        self.report.cost
    }

    #[getter]
    fn terms(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        json_to_py(py, &terms_of(&self.report))
    }

    #[getter]
    fn feasible(&self) -> bool {
        self.report.feasible
    }

    #[getter]
    fn status(&self) -> &'static str {
        self.report.status.id()
    }

    #[getter]
    fn reason(&self) -> &str {
        &self.report.reason
    }

    /// Each violated constraint's one-line message.
    #[getter]
    fn violations(&self) -> Vec<String> {
        self.report.violations.iter().map(|v| v.message.clone()).collect()
    }

    /// Length, travel time, clearance, turns, ... as a dict (None when nothing was planned).
    #[getter]
    fn metrics(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        json_to_py(py, &serde_json::to_value(self.report.metrics).unwrap_or(Value::Null))
    }

    fn __repr__(&self) -> String {
        format!(
            "Mission({:?}, {} waypoints, status={:?})",
            self.report.name,
            self.report.waypoints.len(),
            self.report.status.id()
        )
    }
}
