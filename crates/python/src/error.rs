//! The package's exceptions and the boundary guard: every call from Python runs inside
//! [`guard`], which turns a Rust panic into [`InternalError`] (never an abort, never PyO3's
//! `PanicException`, which derives from `BaseException` and escapes `except Exception`).
//!
//! | exception | raised for |
//! | --- | --- |
//! | `OscsimError(Exception)` | base of the others |
//! | `ScenarioError` | a scenario or road network that does not load or build; `file`, `line`, `column` |
//! | `SimulationError` | a step that fails (an action that cannot start, a non-finite state) |
//! | `InternalError` | a panic inside oscsim (a bug): the call failed, the interpreter lives |

use std::panic::{catch_unwind, AssertUnwindSafe};

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use scenario::SourcePos;

create_exception!(
    oscsim,
    OscsimError,
    PyException,
    "Base class of the exceptions oscsim raises."
);
create_exception!(
    oscsim,
    ScenarioError,
    OscsimError,
    "A scenario, catalog or road network did not load, or the engine could not be built from it. \
     The attributes `file`, `line` and `column` name the place (None when the error has none)."
);
create_exception!(
    oscsim,
    SimulationError,
    OscsimError,
    "A step failed: an action that could not start, a state that became non-finite. The \
     simulation stops; `file`, `line`, `column` name the scenario element when known."
);
create_exception!(
    oscsim,
    InternalError,
    OscsimError,
    "oscsim panicked (a bug; please report it with the scenario). The call failed, the \
     interpreter is unharmed; a simulation that panicked mid-step refuses further use."
);

/// Runs `f`, turning a panic into [`InternalError`] with the panic's message.
pub fn guard<T>(f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without message".to_owned());
        Err(InternalError::new_err(format!(
            "internal error in oscsim (please report it): {message}"
        )))
    })
}

/// Where an error is: file, 1-based line and column, each known or not.
#[derive(Debug, Clone, Default)]
pub struct Place {
    /// The file.
    pub file: Option<String>,
    /// Line.
    pub line: Option<u32>,
    /// Column (characters).
    pub column: Option<u32>,
}

impl From<Option<&SourcePos>> for Place {
    fn from(pos: Option<&SourcePos>) -> Self {
        pos.map_or_else(Place::default, |p| Place {
            file: Some(p.file.display().to_string()),
            line: Some(p.line),
            column: Some(p.col),
        })
    }
}

impl From<&opendrive::Error> for Place {
    fn from(e: &opendrive::Error) -> Self {
        match e.pos() {
            Some(pos) => Some(pos).into(),
            None => Place {
                file: e.file().map(|f| f.display().to_string()),
                ..Place::default()
            },
        }
    }
}

/// An exception of type `T` with `message` whose `file`, `line` and `column` attributes are
/// those of `place`.
pub fn positioned<T: pyo3::PyTypeInfo>(py: Python<'_>, message: String, place: Place) -> PyErr {
    let err = PyErr::new::<T, _>(message);
    let value = err.value(py);
    let Place { file, line, column } = place;
    // Setting attributes on a fresh exception instance does not fail; if it ever did, the
    // exception is still raised with its message.
    let _ = value.setattr("file", file);
    let _ = value.setattr("line", line);
    let _ = value.setattr("column", column);
    err
}

/// A load or build error as [`ScenarioError`].
pub fn load_error(py: Python<'_>, e: &engine::Error) -> PyErr {
    let place = match e.kind() {
        engine::ErrorKind::RoadNetwork(e) => e.into(),
        _ => e.pos().into(),
    };
    positioned::<ScenarioError>(py, e.to_string(), place)
}

/// A scenario that did not load through the front door as [`ScenarioError`], placed where
/// the error is (the XML element, the DSL construct, the road file).
pub fn front_door_error(py: Python<'_>, e: &load::Error) -> PyErr {
    let place = match e.kind() {
        load::ErrorKind::RoadNetwork(r) => r.into(),
        _ => e.pos().as_ref().into(),
    };
    positioned::<ScenarioError>(py, e.to_string(), place)
}

/// A failed step as [`SimulationError`].
pub fn step_error(py: Python<'_>, e: &engine::Error) -> PyErr {
    positioned::<SimulationError>(py, e.to_string(), e.pos().into())
}

/// Registers the exception classes on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("OscsimError", py.get_type::<OscsimError>())?;
    m.add("ScenarioError", py.get_type::<ScenarioError>())?;
    m.add("SimulationError", py.get_type::<SimulationError>())?;
    m.add("InternalError", py.get_type::<InternalError>())?;
    Ok(())
}
