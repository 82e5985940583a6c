//! Python values ↔ the typed values of OpenSCENARIO 1.3 §9.1 parameters
//! ([`scenario::expr::Value`]): bool ↔ boolean, int ↔ int / unsignedInt, float ↔ double,
//! str ↔ string and dateTime.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyString};
use scenario::expr::Value;

/// The [`Value`] of a Python bool, int, float or str.
pub fn from_py(value: &Bound<'_, PyAny>) -> PyResult<Value> {
    // bool before int: Python's bool is a subclass of int.
    if let Ok(b) = value.cast::<PyBool>() {
        return Ok(Value::Bool(b.is_true()));
    }
    if value.is_instance_of::<PyInt>() {
        if let Ok(i) = value.extract::<i64>() {
            return Ok(Value::Int(i));
        }
        return Ok(Value::UnsignedInt(value.extract::<u64>()?));
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(Value::Double(value.extract::<f64>()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(Value::String(value.extract::<String>()?));
    }
    Err(PyTypeError::new_err(format!(
        "expected a bool, int, float or str, found {}",
        value.get_type().name()?
    )))
}

/// The text of a Python value as a `--param NAME=VALUE` override takes it (parsed as the
/// declared type by the scenario reader): booleans as `true` / `false`, floats in their
/// shortest round-trip decimal form (no exponent).
pub fn override_text(value: &Bound<'_, PyAny>) -> PyResult<String> {
    Ok(from_py(value)?.to_string())
}

/// The Python object of `value`.
pub fn to_py<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Int(i) => i.into_pyobject(py)?.into_any(),
        Value::UnsignedInt(u) => u.into_pyobject(py)?.into_any(),
        Value::Double(x) => x.into_pyobject(py)?.into_any(),
        Value::String(s) | Value::DateTime(s) => PyString::new(py, s).into_any(),
    })
}
