//! `tidepath.optimize`: any optimizer of the planner table on a benchmark function (at full
//! speed, as `tidepath bench functions` runs it) or on a Python callable (slower: every
//! evaluation takes the GIL and calls back into Python).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use numpy::{PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyAny, PyDict};
use tidepath::optim::functions::{Function, FunctionObjective};
use tidepath::optim::{self, Objective, Scratch};
use tidepath::rng::run_rng;
use tidepath::termination::{check_count, check_wall_time, Termination};
use tidepath::Error;

use crate::convert::{as_array, err, py_to_table, vector};
use crate::run::interruptible;

/// A Python callable `f(x) -> float` over a box.
struct Callback {
    fun: Py<PyAny>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    /// The first exception the callable raised; the run is stopped on it.
    error: Arc<Mutex<Option<PyErr>>>,
    stop: Arc<AtomicBool>,
}

impl Objective for Callback {
    fn dim(&self) -> usize {
        self.lower.len()
    }
    fn lower(&self) -> &[f64] {
        &self.lower
    }
    fn upper(&self) -> &[f64] {
        &self.upper
    }
    fn evaluate(&self, x: &[f64], _scratch: &mut Scratch) -> f64 {
        Python::attach(|py| {
            let r = self.fun.call1(py, (vector(py, x.to_vec()),)).and_then(|v| v.extract::<f64>(py));
            r.unwrap_or_else(|e| {
                let mut slot = self.error.lock().unwrap_or_else(|p| p.into_inner());
                slot.get_or_insert(e);
                self.stop.store(true, Ordering::Relaxed);
                f64::INFINITY
            })
        })
    }
}

/// The box of a callable: `bounds` as a sequence of (low, high) pairs.
fn bounds_of(py: Python<'_>, bounds: &Bound<'_, PyAny>) -> PyResult<(Vec<f64>, Vec<f64>)> {
    let a = as_array(py, bounds)?;
    let shape = a.shape().to_vec();
    if shape.len() != 2 || shape[1] != 2 || shape[0] == 0 {
        return Err(err(Error::input(
            "bounds",
            format!("must be a sequence of (low, high) pairs, got shape {shape:?}"),
        )));
    }
    let v = a.readonly().as_slice()?.to_vec();
    let (lo, hi): (Vec<f64>, Vec<f64>) = v.chunks_exact(2).map(|c| (c[0], c[1])).unzip();
    for (i, (l, h)) in lo.iter().zip(&hi).enumerate() {
        if !(l.is_finite() && h.is_finite() && l < h) {
            return Err(err(Error::input(
                format!("bounds[{i}]"),
                format!("must be finite with low < high, got ({l}, {h})"),
            )));
        }
    }
    Ok((lo, hi))
}

/// Runs optimizer `algo` on `fun`: a benchmark function's id ("rastrigin", ...; `dim` and
/// optional `bounds=(low, high)`, default the function's standard box) or a Python callable
/// `f(x: ndarray) -> float` with `bounds` one (low, high) pair per dimension. Returns a dict
/// with `x`, `cost`, `evaluations`, `iterations`, `history`, `stop_reason`, `elapsed_s`.
#[pyfunction]
#[pyo3(signature = (fun, bounds = None, algo = "de", iterations = None, evaluations = None, population = None,
    seed = 0, dim = None, params = None, time_limit = None))]
#[allow(clippy::too_many_arguments)]
pub fn optimize(
    py: Python<'_>,
    fun: &Bound<'_, PyAny>,
    bounds: Option<&Bound<'_, PyAny>>,
    algo: &str,
    iterations: Option<u64>,
    evaluations: Option<u64>,
    population: Option<usize>,
    seed: u64,
    dim: Option<usize>,
    params: Option<&Bound<'_, PyAny>>,
    time_limit: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let params = params.map(|p| py_to_table(py, p, "params")).transpose()?;
    let mut opt =
        tidepath::planner::build_optimizer(algo, params.as_ref(), population).map_err(|e| err(e.for_field("algo")))?;
    let stop = Arc::new(AtomicBool::new(false));
    let error = Arc::new(Mutex::new(None));
    let termination = Termination {
        max_iterations: iterations.map(|n| check_count("iterations", n)).transpose().map_err(err)?,
        max_evaluations: evaluations.map(|n| check_count("evaluations", n)).transpose().map_err(err)?,
        wall_time: Some(
            match time_limit {
                Some(t) => check_wall_time("time_limit", t),
                None => {
                    tidepath_io::scenario::default_time_limit_s().and_then(|t| check_wall_time("default time limit", t))
                }
            }
            .map_err(err)?,
        ),
        stop: Some(stop.clone()),
        ..Termination::default()
    };
    let objective: Box<dyn Objective> = if let Ok(id) = fun.extract::<String>() {
        let function = Function::from_id(&id).ok_or_else(|| {
            let known: Vec<&str> = Function::ALL.iter().map(|f| f.id()).collect();
            err(Error::input("fun", format!("unknown function '{id}' (known: {})", known.join(", "))))
        })?;
        let d = function.fixed_dim().unwrap_or(dim.unwrap_or(30));
        if d == 0 || d > 100_000 {
            return Err(err(Error::input("dim", format!("must be in [1, 100000], got {d}"))));
        }
        let (lo, hi) = match bounds {
            None => function.default_range(d),
            Some(b) => b.extract::<(f64, f64)>().map_err(|_| {
                err(Error::input("bounds", "for a benchmark function, one (low, high) pair for every dimension"))
            })?,
        };
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            return Err(err(Error::input("bounds", format!("must be finite with low < high, got ({lo}, {hi})"))));
        }
        Box::new(FunctionObjective::new(function, d, lo, hi))
    } else if fun.is_callable() {
        let b = bounds.ok_or_else(|| {
            err(Error::input("bounds", "a callable needs bounds: one (low, high) pair per dimension"))
        })?;
        let (lower, upper) = bounds_of(py, b)?;
        if dim.is_some_and(|d| d != lower.len()) {
            return Err(err(Error::input(
                "dim",
                format!("is {} but bounds give {} dimensions", dim.unwrap_or(0), lower.len()),
            )));
        }
        Box::new(Callback { fun: fun.clone().unbind(), lower, upper, error: error.clone(), stop: stop.clone() })
    } else {
        return Err(err(Error::input("fun", "must be a benchmark function's id or a callable")));
    };
    optim::check_memory(opt.population(), objective.dim()).map_err(err)?;
    let obj = objective.as_ref();
    let r = interruptible(py, &stop, || {
        optim::run(opt.as_mut(), obj, &termination, &mut run_rng(seed, 0), false, &[], &mut |_| {})
    });
    // A callback's own exception comes first: it is why the run stopped.
    if let Some(e) = error.lock().unwrap_or_else(|p| p.into_inner()).take() {
        return Err(e);
    }
    let r = r?;
    let out = PyDict::new(py);
    out.set_item("x", vector(py, r.best_x))?;
    out.set_item("cost", r.best_cost)?;
    out.set_item("evaluations", r.evaluations)?;
    out.set_item("iterations", r.iterations)?;
    out.set_item("history", vector(py, r.history))?;
    out.set_item("stop_reason", r.stop_reason.id())?;
    out.set_item("elapsed_s", r.elapsed.as_secs_f64())?;
    Ok(out.into_any().unbind())
}
