use pyo3::prelude::*;
use serde_json::{json, Value};
use tidepath::planner::capabilities::{Dimensions, Fleets};
use tidepath::registry::Entry;

use crate::convert::json_to_py;

/// The built-in scenarios: a list of dicts with `id`, `description` and `citation`, read from
/// the scenario table (as `tidepath scenarios` prints it).
#[pyfunction]
pub fn scenarios(py: Python<'_>) -> PyResult<Py<PyAny>> {
    let list: Vec<Value> = tidepath_io::scenario::BUILTIN
        .iter()
        .map(|e| json!({"id": e.id, "description": e.description, "citation": e.citation}))
        .collect();
    json_to_py(py, &Value::Array(list))
}

/// The planners: a list of dicts with `id`, `description`, `citation`, `capabilities` and
/// `parameters` (each with `name`, `range`, `default`, `help`, `source`, `optional`), read from
/// the planner table (as `tidepath planners --params` prints it).
#[pyfunction]
pub fn planners(py: Python<'_>) -> PyResult<Py<PyAny>> {
    let list: Vec<Value> = tidepath::planner::registry()
        .entries()
        .iter()
        .map(|e| {
            let c = e.build.caps;
            let mut v = entry(e);
            v["capabilities"] = json!({
                "summary": c.to_string(),
                "dimensions": match c.dimensions { Dimensions::Both => "2d-and-3d", Dimensions::TwoOnly => "2d-only" },
                "fleets": match c.fleets { Fleets::Jointly => "jointly", Fleets::OneAfterAnother => "one-after-another" },
                "warm_start": c.warm_start,
                "counts": c.counts.iter().map(|u| u.name()).collect::<Vec<_>>(),
                "optimal": c.optimal,
                "randomised": c.randomised,
                "graph": c.graph,
            });
            v
        })
        .collect();
    json_to_py(py, &Value::Array(list))
}

/// An entry's id, description, citation and parameters.
fn entry<B: Copy>(e: &Entry<B>) -> Value {
    let params: Vec<Value> = e
        .params
        .iter()
        .map(|p| {
            json!({
                "name": p.name,
                "range": p.range.to_string(),
                "default": (p.default)().and_then(|d| serde_json::to_value(d).ok()),
                "default_text": p.default_text(),
                "optional": p.optional,
                "help": p.help(),
                "source": p.source,
            })
        })
        .collect();
    json!({"id": e.id, "description": e.description, "citation": e.citation, "parameters": params})
}
