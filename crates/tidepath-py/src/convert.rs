//! Conversions between Python objects and the library's values.

use numpy::ndarray::{Array1, Array2, ArrayD, IxDyn};
use numpy::{IntoPyArray, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyAny;
use tidepath::geom::Vec3;

/// A library error as Python's `ValueError`, with the CLI's one-line message.
pub fn err(e: tidepath::Error) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// A JSON value as plain Python objects (dict, list, float, int, str, bool, None).
pub fn json_to_py(py: Python<'_>, value: &serde_json::Value) -> PyResult<Py<PyAny>> {
    let text = serde_json::to_string(value).map_err(|e| PyValueError::new_err(e.to_string()))?;
    json_text_to_py(py, &text)
}

/// JSON text parsed by Python's `json` module.
pub fn json_text_to_py(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
    Ok(py.import("json")?.call_method1("loads", (text,))?.unbind())
}

/// A Python value (a dict of parameters) as a TOML table, through JSON; `field` names it in
/// errors.
pub fn py_to_table(py: Python<'_>, obj: &Bound<'_, PyAny>, field: &str) -> PyResult<toml::Table> {
    let text: String = py
        .import("json")?
        .call_method1("dumps", (obj,))
        .map_err(|e| PyValueError::new_err(format!("{field}: not JSON-like ({e})")))?
        .extract()?;
    let value: toml::Value = serde_json::from_str(&text)
        .map_err(|e| err(tidepath::Error::input(field, format!("cannot be a TOML table: {e}"))))?;
    match value {
        toml::Value::Table(t) => Ok(t),
        other => Err(err(tidepath::Error::input(field, format!("must be a dict, got {}", other.type_str())))),
    }
}

/// Any array-like of float64 (numpy asarray) as a C-contiguous numpy array.
pub fn as_array<'py>(py: Python<'py>, obj: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let np = py.import("numpy")?;
    let kwargs = pyo3::types::PyDict::new(py);
    kwargs.set_item("dtype", np.getattr("float64")?)?;
    let a = np.call_method("ascontiguousarray", (obj,), Some(&kwargs))?;
    Ok(a.cast_into::<PyArrayDyn<f64>>()?)
}

/// Points as an `(n, 3)` array; `field` names it in errors.
pub fn points(py: Python<'_>, obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Vec<Vec3>> {
    let a = as_array(py, obj)?;
    let shape = a.shape().to_vec();
    if shape.len() != 2 || shape[1] != 3 {
        return Err(err(tidepath::Error::input(field, format!("must be an (n, 3) array, got shape {shape:?}"))));
    }
    let ro = a.readonly();
    let s = ro.as_slice()?;
    Ok(s.chunks_exact(3).map(|c| Vec3::new(c[0], c[1], c[2])).collect())
}

/// `(n, 3)` float64 array of points.
pub fn points_array<'py>(py: Python<'py>, pts: &[[f64; 3]]) -> Bound<'py, PyAny> {
    let flat: Vec<f64> = pts.iter().flatten().copied().collect();
    Array2::from_shape_vec((pts.len(), 3), flat).expect("n x 3").into_pyarray(py).into_any()
}

/// 1-D float64 array.
pub fn vector<'py>(py: Python<'py>, v: Vec<f64>) -> Bound<'py, PyAny> {
    Array1::from_vec(v).into_pyarray(py).into_any()
}

/// The arguments broadcast against each other (numpy's rules): their common shape and each
/// one's values in C order.
pub fn broadcast(py: Python<'_>, args: &[&Bound<'_, PyAny>]) -> PyResult<(Vec<usize>, Vec<Vec<f64>>)> {
    let np = py.import("numpy")?;
    let arrays: Vec<Bound<'_, PyAny>> =
        args.iter().map(|a| as_array(py, a).map(|x| x.into_any())).collect::<PyResult<_>>()?;
    let tuple = pyo3::types::PyTuple::new(py, &arrays)?;
    let out = np.call_method1("broadcast_arrays", tuple)?;
    let mut shape = Vec::new();
    let mut values = Vec::new();
    for item in out.try_iter()? {
        let a = as_array(py, &item?)?;
        shape = a.shape().to_vec();
        values.push(a.readonly().as_slice()?.to_vec());
    }
    Ok((shape, values))
}

/// An array of `shape` (plus `extra` trailing axes) from values in C order.
pub fn shaped<'py>(py: Python<'py>, mut shape: Vec<usize>, extra: &[usize], values: Vec<f64>) -> Bound<'py, PyAny> {
    shape.extend_from_slice(extra);
    ArrayD::from_shape_vec(IxDyn(&shape), values).expect("shape matches").into_pyarray(py).into_any()
}
