//! Python bindings of oscsim (PyO3, abi3 for CPython ≥ 3.9): the native module
//! `oscsim._oscsim`, wrapped by the Python package in `python/oscsim`. A thin layer over the
//! engine's library API: loading, stepping, entity snapshots and the OpenSCENARIO 2.0 §8.7
//! methods are the engine's; this crate converts arguments and results, and turns errors and
//! panics into Python exceptions.
//!
//! | module | job |
//! | --- | --- |
//! | `error` | the exception classes, the panic guard every call runs in, error positions |
//! | `value` | Python values ↔ OpenSCENARIO parameter values |
//! | `model` | `Scenario` and `RoadNetwork` |
//! | `state` | `Pose`, `Vector3`, `RoadPosition`, `BoundingBox` |
//! | `entity` | `Entity` snapshots and the §8.7 methods, `RoutePoint`, `DomainError` |
//! | `record` | the trajectories and event log a simulation keeps |
//! | `control` | inputs of entities under an `external` controller (the system under test) |
//! | `external` | the names of Python functions bound to a DSL scenario's external methods at load, checked by the front door |
//! | `simulation` | `Simulation`: step, run, state, values from outside, control, OSI bytes |
//! | `batch` | `BatchPlan`, `BatchJournal`, `merge_results`, `summary`: the variants of a distribution (`oscsim batch`), durable into a folder |
#![deny(missing_docs)]

use pyo3::prelude::*;

mod batch;
mod control;
mod entity;
mod error;
mod external;
mod model;
mod record;
mod simulation;
mod state;
mod value;

/// Panics inside oscsim, for tests of the boundary: raises `InternalError` (the interpreter
/// lives on).
#[pyfunction]
fn _debug_panic(message: &str) -> PyResult<()> {
    error::guard(|| panic!("{message}"))
}

/// The native module `oscsim._oscsim`.
#[pymodule]
fn _oscsim(m: &Bound<'_, PyModule>) -> PyResult<()> {
    error::register(m)?;
    m.add("DomainError", m.py().get_type::<entity::DomainError>())?;
    m.add_class::<model::Scenario>()?;
    m.add_class::<model::RoadNetwork>()?;
    m.add_class::<simulation::Simulation>()?;
    m.add_class::<entity::Entity>()?;
    m.add_class::<entity::RoutePoint>()?;
    m.add_class::<state::Pose>()?;
    m.add_class::<state::Vector3>()?;
    m.add_class::<state::RoadPosition>()?;
    m.add_class::<state::BoundingBox>()?;
    m.add_class::<batch::BatchPlan>()?;
    m.add_class::<batch::BatchJournal>()?;
    m.add_function(wrap_pyfunction!(batch::merge_results, m)?)?;
    m.add_function(wrap_pyfunction!(batch::summary, m)?)?;
    m.add_function(wrap_pyfunction!(_debug_panic, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
