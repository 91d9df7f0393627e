//! `tidepath.Scenario`: loading, start/goal overrides, planning, evaluation and vectorised
//! world queries.

use std::borrow::Cow;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use numpy::PyArrayMethods;
use pyo3::prelude::*;
use pyo3::types::{PyAny, PyTuple};
use serde_json::{json, Value};
use tidepath::geom::Vec3;
use tidepath::Error;
use tidepath_io::scenario::{self, PlanRequest, Scenario};

use crate::convert::{as_array, broadcast, err, json_to_py, points, py_to_table, shaped};
use crate::plan::PyPlan;
use crate::run::interruptible;

/// A checked scenario: world, vehicle, mission(s), cost model and planner settings.
///
/// Build one with `Scenario.builtin(name)`, `Scenario.load(path)` or
/// `Scenario.from_toml(text)`. Scenarios are immutable: `with_mission` returns a new one.
#[pyclass(frozen, name = "Scenario", module = "tidepath")]
pub struct PyScenario {
    pub inner: Scenario,
}

impl PyScenario {
    fn of(r: tidepath::error::Result<Scenario>) -> PyResult<Self> {
        r.map(|inner| Self { inner }).map_err(err)
    }
}

/// `start` / `goal` as the CLI's `--from` / `--to` text: exact shortest float forms.
fn endpoint_text(py: Python<'_>, obj: &Bound<'_, PyAny>) -> PyResult<String> {
    let a = as_array(py, obj)?;
    let ro = a.readonly();
    Ok(ro.as_slice()?.iter().map(|v| v.to_string()).collect::<Vec<_>>().join(","))
}

/// One path or one per mission: an `(n, 3)` array, or a sequence of them.
pub fn paths(py: Python<'_>, obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Vec<Vec<Vec3>>> {
    if let Ok(a) = as_array(py, obj) {
        use numpy::PyUntypedArrayMethods;
        match a.ndim() {
            2 => return Ok(vec![points(py, obj, field)?]),
            3 => {}
            _ => {
                return Err(err(Error::input(
                    field,
                    format!("must be an (n, 3) array or a list of them, got shape {:?}", a.shape()),
                )))
            }
        }
    }
    let mut out = Vec::new();
    for (i, item) in obj.try_iter()?.enumerate() {
        out.push(points(py, &item?, &format!("{field}[{i}]"))?);
    }
    Ok(out)
}

#[pymethods]
impl PyScenario {
    /// A built-in scenario by name (see `tidepath.scenarios()`).
    #[staticmethod]
    fn builtin(name: &str) -> PyResult<Self> {
        match scenario::builtin(name) {
            Some(text) => Self::of(Scenario::from_toml(text, &format!("builtin:{name}"))),
            None => {
                let mut registry = scenario::registry();
                registry.field = "name";
                Err(err(registry
                    .get(name)
                    .err()
                    .unwrap_or_else(|| Error::input("name", format!("'{name}' is unknown")))))
            }
        }
    }

    /// A scenario TOML file (relative data files resolve against its folder, as in the CLI).
    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<Self> {
        if !path.is_file() {
            return Err(err(Error::input("path", format!("'{}' is not an existing file", path.display()))));
        }
        let text = tidepath_io::input::read_text(&path, "path", tidepath_io::input::MAX_SCENARIO_BYTES).map_err(err)?;
        Self::of(Scenario::from_toml(&text, &path.display().to_string()))
    }

    /// A scenario from TOML text; `source` names it in messages (and is where relative data
    /// files are looked up, as for a file of that path).
    #[staticmethod]
    #[pyo3(signature = (text, source = "<string>"))]
    fn from_toml(text: &str, source: &str) -> PyResult<Self> {
        Self::of(Scenario::from_toml(text, source))
    }

    /// A scenario from a dict shaped like its TOML file (`to_dict()` gives one); `source`
    /// names it in messages. Errors name the field as for a file.
    #[staticmethod]
    #[pyo3(signature = (d, source = "<dict>"))]
    fn from_dict(py: Python<'_>, d: &Bound<'_, PyAny>, source: &str) -> PyResult<Self> {
        let text: String = py
            .import("json")?
            .call_method1("dumps", (d,))
            .map_err(|e| err(Error::input("scenario", format!("not JSON-like ({e})"))))?
            .extract()?;
        let mut value: Value = serde_json::from_str(&text).map_err(|e| err(Error::input("scenario", e.to_string())))?;
        if !value.is_object() {
            return Err(err(Error::input("scenario", "must be a dict shaped like a scenario file")));
        }
        // TOML has no null: an absent key is what `None` means.
        without_nulls(&mut value);
        let table: toml::Value =
            serde_json::from_value(value).map_err(|e| err(Error::input("scenario", e.to_string())))?;
        let text = toml::to_string(&table).map_err(|e| err(Error::input("scenario", e.to_string())))?;
        Self::of(Scenario::from_toml(&text, source))
    }

    /// The scenario's spec as a dict shaped like its TOML file (absent keys left out):
    /// `Scenario.from_dict(s.to_dict())` is the same scenario.
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let mut value =
            serde_json::to_value(&self.inner.spec).map_err(|e| err(Error::input("scenario", e.to_string())))?;
        without_nulls(&mut value);
        json_to_py(py, &value)
    }

    /// The scenario as TOML (its spec as loaded: `Scenario.from_toml(s.to_toml())` is the
    /// same scenario).
    fn to_toml(&self) -> PyResult<String> {
        toml::to_string(&self.inner.spec).map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))
    }

    /// A copy with the (single) mission's start and/or goal replaced, as the CLI's
    /// `plan --from/--to`: `(x, y[, z])` metres in a local scenario, `(lon, lat[, depth])` in a
    /// geographic one (depth in metres, positive down); an omitted z or depth keeps the
    /// scenario's.
    #[pyo3(signature = (start = None, goal = None))]
    fn with_mission(
        &self,
        py: Python<'_>,
        start: Option<&Bound<'_, PyAny>>,
        goal: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let from = start.map(|s| endpoint_text(py, s)).transpose()?;
        let to = goal.map(|g| endpoint_text(py, g)).transpose()?;
        let r = self.inner.with_endpoints(from.as_deref(), to.as_deref()).map_err(|e| match &e {
            Error::Input { field, .. } if field == "--from" => e.for_field("start"),
            Error::Input { field, .. } if field == "--to" => e.for_field("goal"),
            _ => e,
        });
        Self::of(r)
    }

    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }

    #[getter]
    fn description(&self) -> &str {
        &self.inner.description
    }

    /// `builtin:NAME`, a file path, or the `source` given to `from_toml`.
    #[getter]
    fn source(&self) -> &str {
        &self.inner.source
    }

    /// 2 or 3.
    #[getter]
    fn dims(&self) -> u8 {
        match self.inner.world.dims {
            tidepath::world::Dims::Two => 2,
            tidepath::world::Dims::Three => 3,
        }
    }

    /// Whether the scenario is in latitude/longitude (plans then have `lonlat`).
    #[getter]
    fn geographic(&self) -> bool {
        self.inner.frame.is_some()
    }

    /// The domain box in metres: `((xmin, ymin, zmin), (xmax, ymax, zmax))`.
    #[getter]
    fn bounds(&self) -> ([f64; 3], [f64; 3]) {
        (self.inner.world.bounds.min.to_array(), self.inner.world.bounds.max.to_array())
    }

    /// The first mission's start, in metres.
    #[getter]
    fn start(&self) -> [f64; 3] {
        self.inner.start.to_array()
    }

    /// The first mission's goal, in metres.
    #[getter]
    fn goal(&self) -> [f64; 3] {
        self.inner.goal.to_array()
    }

    /// The missions' names, in order.
    #[getter]
    fn mission_names(&self) -> Vec<String> {
        self.inner.missions.iter().map(|m| m.name.clone()).collect()
    }

    /// Settings that were accepted but have no effect.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.inner.warnings.clone()
    }

    /// The scenario's own planner (`[planner] id`).
    #[getter]
    fn planner(&self) -> &str {
        &self.inner.planner.id
    }

    /// Plans, as `tidepath plan` does, and returns a `Plan`.
    ///
    /// The GIL is released while planning; Ctrl-C stops the run and raises
    /// KeyboardInterrupt. `params` updates `[planner.params.ID]` of the planner that runs;
    /// `smoother` is a smoother id (or "none") with `smoother_params`; `init` a warm start,
    /// one `(n, 3)` path per mission. With `progress`, a line on `sys.stderr` at most twice a
    /// second: iteration, evaluations, best cost and the share of the budget used.
    #[pyo3(signature = (planner = None, seed = 0, iterations = None, evaluations = None, time_limit = None,
        params = None, smoother = None, smoother_params = None, init = None, population = None, progress = false))]
    #[allow(clippy::too_many_arguments)]
    fn plan(
        &self,
        py: Python<'_>,
        planner: Option<String>,
        seed: u64,
        iterations: Option<u64>,
        evaluations: Option<u64>,
        time_limit: Option<f64>,
        params: Option<&Bound<'_, PyAny>>,
        smoother: Option<String>,
        smoother_params: Option<&Bound<'_, PyAny>>,
        init: Option<&Bound<'_, PyAny>>,
        population: Option<usize>,
        progress: bool,
    ) -> PyResult<PyPlan> {
        let mut scenario = Cow::Borrowed(&self.inner);
        if let Some(p) = params {
            let id = planner.clone().unwrap_or_else(|| scenario.planner.id.clone());
            let table = py_to_table(py, p, "params")?;
            scenario.to_mut().planner.params.entry(id).or_default().extend(table);
        }
        let smoother_params = smoother_params.map(|p| py_to_table(py, p, "smoother_params")).transpose()?;
        let init = init.map(|i| paths(py, i, "init")).transpose()?;
        let stop = Arc::new(AtomicBool::new(false));
        let req = PlanRequest {
            planner,
            seed,
            run: 0,
            iterations,
            evaluations,
            population,
            time_limit_s: time_limit,
            // As `tidepath plan`; not in a forked child (see `fork`): the same results.
            parallel: !crate::fork::forked(),
            smoother,
            smoother_params,
            init,
            stop: Some(stop.clone()),
            ..PlanRequest::default()
        };
        scenario.check_request(&req).map_err(err)?;
        let sc: &Scenario = &scenario;
        let mut last: Option<std::time::Instant> = None;
        let mut observer = |p: &tidepath::optim::Progress| {
            if !progress || last.is_some_and(|t| t.elapsed() < std::time::Duration::from_millis(500)) {
                return;
            }
            last = Some(std::time::Instant::now());
            let line = format!(
                "tidepath: iteration {}, {} evaluations, best cost {:.6} ({:.0} % of the budget, {:.1} s)\n",
                p.iteration,
                p.evaluations,
                p.best_cost,
                100.0 * p.fraction,
                p.elapsed.as_secs_f64()
            );
            // Python's stderr (a notebook shows it), written with the GIL the waiting thread
            // has released.
            Python::attach(|py| {
                if let Ok(e) = py.import("sys").and_then(|sys| sys.getattr("stderr")) {
                    let _ = e.call_method1("write", (line,));
                    let _ = e.call_method0("flush");
                }
            });
        };
        let report = interruptible(py, &stop, || sc.plan(&req, &mut observer))?.map_err(err)?;
        Ok(PyPlan::new(report, sc))
    }

    /// The interactive 3-D view of this scenario and `plans` (each a `Plan` of it), as the
    /// HTML `tidepath view` writes: one self-contained page that opens offline. Written to
    /// `path` when given (all or nothing); returned either way (a notebook shows it with
    /// `IPython.display.HTML`).
    #[pyo3(signature = (plans = Vec::new(), path = None, title = None))]
    fn view(
        &self,
        py: Python<'_>,
        plans: Vec<PyRef<'_, PyPlan>>,
        path: Option<std::path::PathBuf>,
        title: Option<String>,
    ) -> PyResult<String> {
        let mut outputs = tidepath_io::Outputs::new();
        let id =
            path.as_deref().map(|p| tidepath_view::declare_output(&mut outputs, "path", p)).transpose().map_err(err)?;
        let mut routes = Vec::new();
        for p in &plans {
            let r = p.report();
            if r.scenario != self.inner.name || r.missions.len() != self.inner.missions.len() {
                return Err(err(Error::input(
                    "plans",
                    format!(
                        "a plan of `{}` with {} mission(s) cannot be shown on `{}`",
                        r.scenario,
                        r.missions.len(),
                        self.inner.name
                    ),
                )));
            }
            routes.extend(tidepath_view::report_routes(r));
        }
        let title = title.unwrap_or_else(|| self.inner.name.clone());
        let input =
            tidepath_view::ViewInput { scenario: &self.inner, title, routes, simulation: None, simulation_mission: 0 };
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let html = interruptible(py, &stop, move || {
            tidepath_view::render_view(&input, &|| flag.load(std::sync::atomic::Ordering::Relaxed))
        })?
        .map_err(|_| pyo3::exceptions::PyKeyboardInterrupt::new_err("the view was not built"))?;
        if let Some(id) = id {
            outputs.fill(id, html.clone());
            outputs.commit().map_err(err)?;
        }
        Ok(html)
    }

    /// Judges one path per mission (an `(n, 3)` array, or a list of them), start and goal
    /// included, as `tidepath eval` does. Returns a dict: `cost` (all missions, with the
    /// fleet's terms), `feasible`, `status`, `terms` (summed over missions), `violations`
    /// (messages) and `missions` (each with its own cost, terms, feasible, status, violations,
    /// times and metrics).
    fn evaluate(&self, py: Python<'_>, waypoints: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let sc = &self.inner;
        let paths = paths(py, waypoints, "waypoints")?;
        let judged = py.detach(|| sc.evaluate_routes(&paths, &[])).map_err(err)?;
        let rule_below = sc.cost_model().map_err(err)?.feasible_below();
        let mut total = 0.0;
        let mut terms = serde_json::Map::new();
        let mut violations = Vec::new();
        let mut worst = tidepath::planner::Status::Exact;
        let mut missions = Vec::new();
        for m in &judged {
            total += m.cost;
            for (name, v) in &m.terms {
                let sum = terms.get(*name).and_then(Value::as_f64).unwrap_or(0.0) + v;
                terms.insert(name.to_string(), json!(sum));
            }
            violations.extend(m.violations.iter().map(|v| v.message.clone()));
            if m.status.severity() > worst.severity() {
                worst = m.status;
            }
            missions.push(json!({
                "name": m.name,
                "cost": m.cost,
                "terms": m.terms.iter().map(|(k, v)| (k.to_string(), json!(v))).collect::<serde_json::Map<_, _>>(),
                "feasible": m.feasible,
                "status": m.status.id(),
                "reason": m.reason,
                "violations": m.violations.iter().map(|v| v.message.clone()).collect::<Vec<_>>(),
                "times": m.times,
                "metrics": m.metrics,
                "model_rule": rule_below.map(|b| json!({"below": b, "met": m.cost < b})),
            }));
        }
        let fleet = sc.fleet_check(&judged).map(|check| {
            total += check.penalty();
            let names: Vec<String> = judged.iter().map(|m| m.name.clone()).collect();
            tidepath_io::FleetReport::new(&check, &sc.fleet, &names).line()
        });
        let out = json!({
            "scenario": sc.name,
            "cost_model": sc.cost.model,
            "cost": total,
            "terms": terms,
            "feasible": judged.iter().all(|m| m.feasible),
            "status": worst.id(),
            "violations": violations,
            "fleet": fleet,
            "missions": missions,
        });
        json_to_py(py, &out)
    }

    /// Seabed elevation (m, z up) at `x`, `y` (arrays broadcast together); `-inf` where the
    /// world has no seabed.
    fn seabed<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (shape, v) = broadcast(py, &[x, y])?;
        let t = &self.inner.world.terrain;
        let out: Vec<f64> = py.detach(|| v[0].iter().zip(&v[1]).map(|(x, y)| t.elevation(*x, *y)).collect());
        Ok(shaped(py, shape, &[], out))
    }

    /// The current's velocity (m/s) at `x`, `y`, `z` and time `t` (s on the scenario clock),
    /// all broadcast together: an array of shape `(..., 3)`.
    #[pyo3(signature = (x, y, z, t = None))]
    fn current<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
        z: &Bound<'py, PyAny>,
        t: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let zero = 0.0f64.into_pyobject(py)?.into_any();
        let t = t.unwrap_or(&zero);
        let (shape, v) = broadcast(py, &[x, y, z, t])?;
        let c = &self.inner.world.current;
        let out: Vec<f64> = py.detach(|| {
            (0..v[0].len()).flat_map(|i| c.velocity(Vec3::new(v[0][i], v[1][i], v[2][i]), v[3][i]).to_array()).collect()
        });
        Ok(shaped(py, shape, &[3], out))
    }

    /// The clearance (m) of points (an array of shape `(..., 3)`) at time `t`: the smaller of
    /// the height above the seabed (negative below it) and the distance to the nearest
    /// obstacle surface (0 inside one), as the validator measures a motion's clearance;
    /// `inf` in an empty world.
    #[pyo3(signature = (points, t = 0.0))]
    fn clearance<'py>(&self, py: Python<'py>, points: &Bound<'py, PyAny>, t: f64) -> PyResult<Bound<'py, PyAny>> {
        use numpy::PyUntypedArrayMethods;
        let a = as_array(py, points)?;
        let shape = a.shape().to_vec();
        if shape.last() != Some(&3) {
            return Err(err(Error::input("points", format!("must have shape (..., 3), got {shape:?}"))));
        }
        let values = a.readonly().as_slice()?.to_vec();
        let world = &self.inner.world;
        let out: Vec<f64> = py.detach(|| {
            values
                .chunks_exact(3)
                .map(|c| {
                    let p = Vec3::new(c[0], c[1], c[2]);
                    let mut best = world.segment_terrain_clearance(p, p);
                    for o in &world.obstacles {
                        best = best.min(o.segment_clearance(p, p, t, t));
                    }
                    best
                })
                .collect()
        });
        Ok(shaped(py, shape[..shape.len() - 1].to_vec(), &[], out))
    }

    fn __repr__(&self) -> String {
        format!("Scenario({:?}, source={:?})", self.inner.name, self.inner.source)
    }

    /// Pickles as its TOML and source (for process pools and Dask).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let me = slf.get();
        let text = me.to_toml()?;
        let ctor = py.get_type::<PyScenario>().getattr("from_toml")?;
        Ok((ctor, PyTuple::new(py, [text, me.inner.source.clone()])?))
    }
}

/// `value` with every null member of its objects removed, at any depth.
fn without_nulls(value: &mut Value) {
    match value {
        Value::Object(m) => {
            m.retain(|_, v| !v.is_null());
            m.values_mut().for_each(without_nulls);
        }
        Value::Array(a) => a.iter_mut().for_each(without_nulls),
        _ => {}
    }
}
