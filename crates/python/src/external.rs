//! Python functions bound to a DSL scenario's external methods at load
//! (`Simulation(path, bindings={"name": function})`, ASAM OpenSCENARIO DSL 2.1 §7.3.6
//! `is external`): the names given to the front door (`load::Options::bindings`), which
//! refuses a scenario calling or reading an unbound method at its place. The Python package
//! runs the functions itself, between steps (`python/oscsim/__init__.py`), where they may read
//! the simulation (the native step holds the simulation's lock, so a function run inside it
//! could not): the front door's functions here only stand for them.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `bindings` (a dict of method name to callable) as the front door's bindings (module doc).
pub(crate) fn bindings(bindings: &Bound<'_, PyDict>) -> PyResult<load::Bindings> {
    let mut out = load::Bindings::default();
    for (name, function) in bindings.iter() {
        let name: String = name.extract()?;
        if !function.is_callable() {
            return Err(PyTypeError::new_err(format!(
                "expected a callable for external method {name:?}, found {function}"
            )));
        }
        out.bind(name, |_| {
            Err("a Python function, run by the Python package between steps".to_string())
        });
    }
    Ok(out)
}
