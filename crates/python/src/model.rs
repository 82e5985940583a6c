//! `oscsim.Scenario` (a scenario loaded through the front door, the `load` crate: an
//! OpenSCENARIO XML 1.x file with its catalogs and parameter overrides, OpenSCENARIO 1.3 §9.1,
//! or an OpenSCENARIO DSL 2.x file with its road network and seed) and `oscsim.RoadNetwork`
//! (an OpenDRIVE file, loaded once and shared by the simulations built on it).

use std::path::PathBuf;
use std::sync::Arc;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{front_door_error, guard, positioned, ScenarioError};
use crate::value;

/// A scenario ready to run, in either language: an OpenSCENARIO XML file with its parameters
/// resolved (with the overrides given) and catalogs read, or an OpenSCENARIO DSL file checked,
/// resolved with a seed, planned and lowered; with its road network, read once. Immutable; any
/// number of simulations can be built from one.
#[pyclass(frozen, module = "oscsim")]
pub struct Scenario {
    pub(crate) inner: Arc<load::Loaded>,
    path: PathBuf,
}

impl Scenario {
    /// Loads `path` through the front door (either language) with `options` and the XML
    /// parameter overrides `params`.
    pub(crate) fn open(
        py: Python<'_>,
        path: PathBuf,
        params: Option<&Bound<'_, PyDict>>,
        options: load::Options,
    ) -> PyResult<Self> {
        let options = load::Options {
            params: overrides(params)?,
            ..options
        };
        load::load(&path, &options)
            .map(|l| Scenario {
                inner: Arc::new(l),
                path,
            })
            .map_err(|e| front_door_error(py, &e))
    }
}

#[pymethods]
impl Scenario {
    /// Loads `path`: a .xosc file (OpenSCENARIO XML), whose global parameters `params`
    /// overrides by name (a leading `$` is allowed; values parsed as the declared types), or a
    /// .osc file (OpenSCENARIO DSL) on the road network `road` (a .xodr; default: the file its
    /// `map.set_map_file(…)` names), its constraints solved with `seed` (same seed, same
    /// scenario). `road` for an XML scenario (it names its own) and `params` for a DSL one (it
    /// varies by seed) are errors. Raises `ScenarioError` with `file`, `line`, `column` when
    /// the file, a catalog, a parameter value, the road network or the DSL scenario's plan is
    /// invalid.
    #[staticmethod]
    #[pyo3(signature = (path, params = None, *, road = None, seed = engine::runtime::DEFAULT_SEED))]
    fn load(
        py: Python<'_>,
        path: PathBuf,
        params: Option<&Bound<'_, PyDict>>,
        road: Option<PathBuf>,
        seed: u64,
    ) -> PyResult<Self> {
        guard(|| {
            let options = load::Options {
                road,
                seed,
                ..load::Options::default()
            };
            Scenario::open(py, path, params, options)
        })
    }

    /// The scenario file.
    #[getter]
    fn path(&self) -> String {
        self.path.display().to_string()
    }

    /// `"xml"` (OpenSCENARIO XML 1.x) or `"dsl"` (OpenSCENARIO DSL 2.x).
    #[getter]
    fn language(&self) -> &'static str {
        match self.inner.language {
            load::Language::Xml => "xml",
            load::Language::Dsl => "dsl",
        }
    }

    /// A DSL scenario's phases by path (`do`, `do.cut_in`, …: the names of their Acts in the
    /// event log), children before their composition; empty for XML.
    #[getter]
    fn phases(&self) -> Vec<String> {
        self.inner.phases.iter().map(|p| p.path.clone()).collect()
    }

    /// The road network file the scenario names (RoadNetwork/LogicFile), if any.
    #[getter]
    fn road_network_path(&self) -> Option<String> {
        let file = self.inner.scenario.road_network.logic_file.as_ref()?;
        Some(file.display().to_string())
    }

    /// The global parameters and their values after the overrides, by name.
    #[getter]
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for p in &self.inner.scenario.parameter_declarations {
            d.set_item(&p.name, value::to_py(py, &p.value)?)?;
        }
        Ok(d)
    }

    /// The names of the scenario's entities (ScenarioObjects), in declaration order.
    #[getter]
    fn entity_names(&self) -> Vec<String> {
        let objects = &self.inner.scenario.entities.scenario_objects;
        objects.iter().map(|o| o.name.clone()).collect()
    }

    fn __repr__(&self) -> String {
        format!("Scenario.load({:?})", self.path.display().to_string())
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
