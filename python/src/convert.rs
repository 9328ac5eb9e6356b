//! Rust values to Python objects: numpy arrays from vectors, and JSON values (the rows,
//! claims and answers the library writes) to dicts, lists, strings and numbers.

use numpy::ndarray::{Array1, Array2, Array3};
use numpy::IntoPyArray;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;

/// A 1-d array owning `v` (no copy).
pub fn array1<T: numpy::Element>(py: Python<'_>, v: Vec<T>) -> Bound<'_, PyAny> {
    Array1::from_vec(v).into_pyarray(py).into_any()
}

/// A (len / cols, cols) array owning the row-major `v` (no copy).
pub fn array2<T: numpy::Element>(
    py: Python<'_>,
    v: Vec<T>,
    cols: usize,
) -> PyResult<Bound<'_, PyAny>> {
    let rows = v.len() / cols;
    let a = Array2::from_shape_vec((rows, cols), v)
        .map_err(|e| PyRuntimeError::new_err(format!("penner: array shape: {e}")))?;
    Ok(a.into_pyarray(py).into_any())
}

/// A (len / (b·c), b, c) array owning the row-major `v` (no copy).
pub fn array3<T: numpy::Element>(
    py: Python<'_>,
    v: Vec<T>,
    b: usize,
    c: usize,
) -> PyResult<Bound<'_, PyAny>> {
    let a = v.len() / (b * c);
    let arr = Array3::from_shape_vec((a, b, c), v)
        .map_err(|e| PyRuntimeError::new_err(format!("penner: array shape: {e}")))?;
    Ok(arr.into_pyarray(py).into_any())
}

/// A JSON value as Python objects: objects as dicts (keys in the library's order), arrays
/// as lists, integers as int, other numbers as float, null as None.
pub fn json_to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any()
            } else if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any()
            } else {
                n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any()
            }
        }
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(a) => {
            let l = PyList::empty(py);
            for x in a {
                l.append(json_to_py(py, x)?)?;
            }
            l.into_any()
        }
        Value::Object(o) => {
            let d = PyDict::new(py);
            for (k, x) in o {
                d.set_item(k, json_to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}
