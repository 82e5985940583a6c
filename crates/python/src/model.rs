//! `oscsim.Scenario` (an OpenSCENARIO 1.x file loaded with its catalogs and parameter
//! overrides, OpenSCENARIO 1.3 §9.1) and `oscsim.RoadNetwork` (an OpenDRIVE file, loaded once
//! and shared by the simulations built on it).

use std::path::PathBuf;
use std::sync::Arc;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{guard, load_error, positioned, ScenarioError};
use crate::value;

/// A scenario loaded from an OpenSCENARIO 1.x file: parameters resolved (with the overrides
/// given), catalogs read. Immutable; any number of simulations can be built from one.
#[pyclass(frozen, module = "oscsim")]
pub struct Scenario {
    pub(crate) inner: Arc<scenario::Scenario>,
}

#[pymethods]
impl Scenario {
    /// Loads `path` (a .xosc file). `params` overrides global parameters by name (a leading
    /// `$` is allowed); values are parsed as the declared types. Raises `ScenarioError` with
    /// `file`, `line`, `column` when the file, a catalog or a parameter value is invalid.
    #[staticmethod]
    #[pyo3(signature = (path, params = None))]
    fn load(py: Python<'_>, path: PathBuf, params: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        guard(|| {
            let overrides = overrides(params)?;
            scenario::Scenario::load_with_parameters(&path, &overrides)
                .map(|s| Scenario { inner: Arc::new(s) })
                .map_err(|e| load_error(py, &e.into()))
        })
    }

    /// The scenario file.
    #[getter]
    fn path(&self) -> String {
        self.inner.path.display().to_string()
    }

    /// The road network file the scenario names (RoadNetwork/LogicFile), if any.
    #[getter]
    fn road_network_path(&self) -> Option<String> {
        let file = self.inner.road_network.logic_file.as_ref()?;
        Some(file.display().to_string())
    }

    /// The global parameters and their values after the overrides, by name.
    #[getter]
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for p in &self.inner.parameter_declarations {
            d.set_item(&p.name, value::to_py(py, &p.value)?)?;
        }
        Ok(d)
    }

    /// The names of the scenario's entities (ScenarioObjects), in declaration order.
    #[getter]
    fn entity_names(&self) -> Vec<String> {
        let objects = &self.inner.entities.scenario_objects;
        objects.iter().map(|o| o.name.clone()).collect()
    }

    fn __repr__(&self) -> String {
        format!("Scenario.load({:?})", self.inner.path.display().to_string())
    }
}

/// `params` as (name, text) overrides.
pub fn overrides(params: Option<&Bound<'_, PyDict>>) -> PyResult<Vec<(String, String)>> {
    let Some(params) = params else {
        return Ok(Vec::new());
    };
    params
        .iter()
        .map(|(k, v)| {
            let name: String = k.extract()?;
            Ok((
                name.trim_start_matches('$').to_owned(),
                value::override_text(&v)?,
            ))
        })
        .collect()
}

/// An OpenDRIVE road network, loaded once: pass it to every `Simulation` that runs on it so
/// that the file is not parsed again.
#[pyclass(frozen, module = "oscsim")]
pub struct RoadNetwork {
    pub(crate) inner: Arc<opendrive::RoadNetwork>,
    path: PathBuf,
}

#[pymethods]
impl RoadNetwork {
    /// Loads `path` (a .xodr file). Raises `ScenarioError` with `file`, `line`, `column` when
    /// it is not valid OpenDRIVE.
    #[staticmethod]
    fn load(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        guard(|| {
            opendrive::RoadNetwork::from_file(&path)
                .map(|n| RoadNetwork {
                    inner: Arc::new(n),
                    path: path.clone(),
                })
                .map_err(|e| {
                    let message = format!("cannot load the road network: {e}");
                    positioned::<ScenarioError>(py, message, (&e).into())
                })
        })
    }

    /// The file it was loaded from.
    #[getter]
    fn path(&self) -> String {
        self.path.display().to_string()
    }

    /// The ids of its roads, in file order.
    #[getter]
    fn road_ids(&self) -> Vec<String> {
        self.inner.roads().iter().map(|r| r.id.clone()).collect()
    }

    /// The length of road `road_id` along its reference line (m), None if there is no such road.
    fn road_length(&self, road_id: &str) -> Option<f64> {
        self.inner.road(road_id).map(|r| r.length)
    }

    fn __repr__(&self) -> String {
        format!("RoadNetwork.load({:?})", self.path.display().to_string())
    }
}
