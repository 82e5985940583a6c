//! `oscsim.Simulation` (the native part; `python/oscsim/__init__.py` adds the Python-side
//! conveniences): one run of a scenario by the engine's fixed step (OpenSCENARIO 1.3 §8
//! "Scenario at runtime"), with its trajectories and event log kept for Python.
//!
//! The engine sits behind a mutex so that the class is `Sync` as PyO3 requires; the GIL is
//! held throughout (no call releases it), so the lock is never contended. A panic inside a
//! call that holds the lock poisons it: the call raises `InternalError`, and so does every
//! later call on that simulation, whose state can no longer be trusted.

use std::fs::File;
use std::io::BufWriter;
use std::path::PathBuf;
use std::sync::{Arc, Mutex, MutexGuard};

use engine::output::CsvWriter;
use engine::{Engine, EngineConfig, FrameSink, StopReason};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

use crate::control::Control;
use crate::entity::Entity;
use crate::error::{
    guard, load_error, step_error, InternalError, OscsimError, ScenarioError, SimulationError,
};
use crate::model::{RoadNetwork, Scenario};
use crate::record::{Events, Recorders, Trajectories};
use crate::state::Pose;
use crate::value;

/// The engine and what the simulation keeps for Python.
struct Inner {
    engine: Engine,
    trajectories: Trajectories,
    /// The trajectory CSV file, when the simulation was made with `csv=PATH`.
    csv: Option<CsvWriter<BufWriter<File>>>,
    /// The OSI ground truth, when the simulation was made with `osi=True`.
    osi: Option<osi::sink::StepFrames>,
    events: Events,
    /// The error a step failed with: the run cannot go on.
    failed: Option<String>,
}

/// One run of a scenario, stepped from Python.
#[pyclass(subclass, module = "oscsim")]
pub struct Simulation {
    inner: Mutex<Inner>,
    network: Arc<opendrive::RoadNetwork>,
    scenario_path: String,
    config: EngineConfig,
    /// The external methods a DSL scenario calls or reads: method and `file:line:col`.
    calls: Vec<(String, String)>,
    /// The external methods it reads in conditions: method and the value's name (`m(args)`).
    reads: Vec<(String, String)>,
}

/// `values` as a NumPy float64 array (copied once through a bytes buffer).
fn float_array<'py>(
    py: Python<'py>,
    numpy: &Bound<'py, PyModule>,
    values: &[f64],
) -> PyResult<Bound<'py, PyAny>> {
    let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
    let buffer = PyBytes::new(py, &bytes);
    numpy
        .call_method1("frombuffer", (buffer, "<f8"))?
        .call_method0("copy")
}

/// `values` as a NumPy int64 array.
fn int_array<'py>(
    py: Python<'py>,
    numpy: &Bound<'py, PyModule>,
    values: &[i64],
) -> PyResult<Bound<'py, PyAny>> {
    let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
    let buffer = PyBytes::new(py, &bytes);
    numpy
        .call_method1("frombuffer", (buffer, "<i8"))?
        .call_method0("copy")
}

/// `values` as a NumPy object array of str.
fn str_array<'py>(
    py: Python<'py>,
    numpy: &Bound<'py, PyModule>,
    values: &[String],
) -> PyResult<Bound<'py, PyAny>> {
    let list = PyList::new(py, values)?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", "object")?;
    numpy.call_method("array", (list,), Some(&kwargs))
}

impl Simulation {
    fn lock(&self) -> PyResult<MutexGuard<'_, Inner>> {
        self.inner.lock().map_err(|_| {
            InternalError::new_err(
                "this simulation is unusable: an earlier call panicked inside oscsim \
                 (InternalError); build a new Simulation",
            )
        })
    }

    /// One step on a locked simulation.
    fn step_locked(py: Python<'_>, inner: &mut Inner) -> PyResult<Option<StopReason>> {
        if let Some(message) = &inner.failed {
            return Err(SimulationError::new_err(format!(
                "the simulation stopped after an error: {message}"
            )));
        }
        let Inner {
            engine,
            trajectories,
            csv,
            osi,
            events,
            failed,
        } = inner;
        if let Some(osi) = osi.as_mut() {
            osi.begin_step();
        }
        let was_running = engine.stop_reason().is_none();
        let mut recorders = Recorders {
            trajectories,
            csv: csv.as_mut(),
            osi: osi.as_mut(),
        };
        let reason = engine.step(&mut recorders, events).map_err(|e| {
            *failed = Some(e.to_string());
            step_error(py, &e)
        })?;
        // The run ended in this step: the CSV file is complete.
        if let (Some(csv), true, Some(_)) = (csv.as_mut(), was_running, reason) {
            csv.finish().map_err(|e| {
                OscsimError::new_err(format!("cannot write the trajectory CSV: {e}"))
            })?;
        }
        Ok(reason)
    }

    fn osi(inner: &Inner) -> PyResult<&osi::sink::StepFrames> {
        let osi = inner.osi.as_ref().ok_or_else(|| {
            OscsimError::new_err(
                "expected a simulation made with osi=True, found one without OSI output",
            )
        })?;
        Ok(osi)
    }

    fn snapshot(&self, state: engine::EntityState, time: f64) -> Entity {
        Entity {
            state,
            time,
            network: Arc::clone(&self.network),
        }
    }
}

#[pymethods]
impl Simulation {
    /// A simulation of `scenario` (a `Scenario`, or the path of a .xosc file loaded with
    /// `params`, or of a .osc file on `road`, solved with `seed`: `Scenario.load`) stepped every
    /// `dt` seconds; `seed` fixes the random streams (spawned traffic, random routes). The run ends at the storyboard's end, after `duration` seconds if
    /// given, at the latest at `max_time`. `record=False` keeps no trajectories. `osi=True`
    /// makes the OSI GroundTruth of every step (`osi_ground_truth()`), with `osi_host` as the
    /// host vehicle (default `Ego`) and lanes in the first frame only, as `oscsim run --osi`
    /// does, or in every frame with `osi_static="every"`. `road_network` (a `RoadNetwork`) is
    /// the road network to run on, shared with every simulation given the same; by default
    /// the one the scenario was loaded with. `scenario` may also be an OpenSCENARIO DSL `.osc`
    /// file, loaded through the front door: planned with `seed` and `dt` on `road` (the path of
    /// an OpenDRIVE file; default: the file the scenario names with `map.set_map_file`), its
    /// entry scenario `entry` (default: the one no other invokes), with `duration` bounding a
    /// last phase that has no end. `csv` (a path) writes the trajectory CSV there as the run
    /// goes, the file `oscsim run --csv` writes, complete when the run ends. Raises
    /// `ScenarioError` (with `file`, `line`, `column`) when the scenario does not load or the
    /// engine cannot be built from it.
    #[new]
    #[pyo3(signature = (scenario, dt = engine::runtime::DEFAULT_DT, seed = engine::runtime::DEFAULT_SEED, duration = None, max_time = engine::runtime::DEFAULT_MAX_TIME, record = true, params = None, osi = false, osi_host = None, osi_static = "first", road_network = None, road = None, entry = None, csv = None, bindings = None))]
    #[allow(clippy::too_many_arguments)] // Python keyword arguments
    fn new(
        py: Python<'_>,
        scenario: &Bound<'_, PyAny>,
        dt: f64,
        seed: u64,
        duration: Option<f64>,
        max_time: f64,
        record: bool,
        params: Option<&Bound<'_, PyDict>>,
        osi: bool,
        osi_host: Option<String>,
        osi_static: &str,
        road_network: Option<PyRef<'_, RoadNetwork>>,
        road: Option<PathBuf>,
        entry: Option<String>,
        csv: Option<PathBuf>,
        bindings: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let static_data = match osi_static {
            "first" => osi::ground_truth::StaticData::First,
            "every" => osi::ground_truth::StaticData::Every,
            _ => {
                return Err(PyValueError::new_err(format!(
                    "expected osi_static 'first' or 'every', found {osi_static:?}"
                )))
            }
        };
        guard(|| {
            let loaded: Arc<load::Loaded> = if let Ok(s) = scenario.cast::<Scenario>() {
                if params.is_some() || road.is_some() || entry.is_some() || bindings.is_some() {
                    return Err(PyValueError::new_err(
                        "params, road, entry and bindings apply when loading: pass params, road and entry to Scenario.load, bindings with the scenario's path",
                    ));
                }
                Arc::clone(&s.get().inner)
            } else {
                let path: PathBuf = scenario.extract()?;
                let options = load::Options {
                    road,
                    seed,
                    dt,
                    open_end: duration.is_some(),
                    scenario: entry,
                    bindings: bindings.map(crate::external::bindings).transpose()?,
                    ..load::Options::default()
                };
                Arc::clone(&Scenario::open(py, path, params, options)?.inner)
            };
            let calls = loaded
                .calls
                .iter()
                .map(|c| (c.method.clone(), c.pos.to_string()))
                .collect();
            let reads = loaded
                .calls
                .iter()
                .filter_map(|c| Some((c.method.clone(), c.value.clone()?)))
                .collect();

            let scenario = &loaded.scenario;
            let config = EngineConfig {
                dt,
                duration,
                max_time,
                seed,
                ..EngineConfig::default()
            };
            let network = match road_network {
                Some(n) => Arc::clone(&n.inner),
                None => Arc::clone(&loaded.network),
            };
            let csv = csv
                .map(|path| {
                    File::create(&path)
                        .map(|f| CsvWriter::new(BufWriter::new(f)))
                        .map_err(|e| {
                            OscsimError::new_err(format!("cannot create {}: {e}", path.display()))
                        })
                })
                .transpose()?;
            let engine = Engine::new(scenario, Arc::clone(&network), config)
                .map_err(|e| load_error(py, &e))?;
            let osi = osi
                .then(|| {
                    let options = osi::sink::SinkOptions {
                        host: osi_host,
                        static_data,
                    };
                    osi::sink::GroundTruthSink::new(&engine, &options).map_err(|e| {
                        ScenarioError::new_err(format!("cannot make the OSI ground truth: {e}"))
                    })
                })
                .transpose()?
                .map(osi::sink::StepFrames::new);
            Ok(Simulation {
                inner: Mutex::new(Inner {
                    engine,
                    trajectories: Trajectories {
                        enabled: record,
                        ..Trajectories::default()
                    },
                    csv,
                    osi,
                    events: Events::default(),
                    failed: None,
                }),
                network,
                scenario_path: scenario.path.display().to_string(),
                config,
                calls,
                reads,
            })
        })
    }

    /// Runs one step of `dt`: triggers, actions, controllers, measurements, output. The first
    /// step runs the Init actions and records the frame at t = 0 too. Returns None while the
    /// run goes on, then why it ended (`stop_trigger`, `stories_complete`, `duration`,
    /// `time_cap`); a step after the end does nothing. Raises `SimulationError` when the step
    /// fails (the simulation then refuses further steps).
    fn step(&self, py: Python<'_>) -> PyResult<Option<&'static str>> {
        guard(|| {
            let mut inner = self.lock()?;
            Ok(Self::step_locked(py, &mut inner)?.map(StopReason::name))
        })
    }

    /// Steps until the run ends; returns why (see `step`).
    fn run(&self, py: Python<'_>) -> PyResult<&'static str> {
        guard(|| {
            let mut inner = self.lock()?;
            loop {
                if let Some(reason) = Self::step_locked(py, &mut inner)? {
                    return Ok(reason.name());
                }
            }
        })
    }

    /// Simulation time (s): that of the latest frame (0 before the first step).
    #[getter]
    fn time(&self) -> PyResult<f64> {
        guard(|| Ok(self.lock()?.engine.time()))
    }

    /// Steps run so far.
    #[getter]
    fn steps(&self) -> PyResult<u64> {
        guard(|| Ok(self.lock()?.engine.steps()))
    }

    /// The step length (s).
    #[getter]
    fn dt(&self) -> f64 {
        self.config.dt
    }

    /// The seed of the random streams.
    #[getter]
    fn seed(&self) -> u64 {
        self.config.seed
    }

    /// The scenario file.
    #[getter]
    fn scenario_path(&self) -> &str {
        &self.scenario_path
    }

    /// The external methods a DSL scenario calls (`call m(…)`, in the order they are
    /// written) and then reads in conditions (`until m(…) > 3`): `(method, "file:line:col")`.
    /// Each method needs a function bound to its name, at load (`bindings=`) or with `bind`
    /// before the first step.
    #[getter]
    fn external_calls(&self) -> Vec<(String, String)> {
        self.calls.clone()
    }

    /// The external methods a DSL scenario reads in conditions: `(method, value)`, the value
    /// being the user-defined value the condition compares, named by the call's text
    /// (`m(args as JSON values)`), set from the bound function before each step.
    #[getter]
    fn _external_reads(&self) -> Vec<(String, String)> {
        self.reads.clone()
    }

    /// Why the run ended, None while it goes on.
    #[getter]
    fn stop_reason(&self) -> PyResult<Option<&'static str>> {
        guard(|| Ok(self.lock()?.engine.stop_reason().map(StopReason::name)))
    }

    /// True until the run ends (or a step fails).
    #[getter]
    fn running(&self) -> PyResult<bool> {
        guard(|| {
            let inner = self.lock()?;
            Ok(inner.engine.stop_reason().is_none() && inner.failed.is_none())
        })
    }

    /// The entities in the scenario now (placed or spawned), in declaration order: snapshots
    /// at the current time. Empty before the first step, which runs the Init actions.
    #[getter]
    fn entities(&self) -> PyResult<Vec<Entity>> {
        guard(|| {
            let inner = self.lock()?;
            let time = inner.engine.time();
            let states = inner.engine.entities().into_iter();
            Ok(states.map(|e| self.snapshot(e, time)).collect())
        })
    }

    /// The entity called `name` now. Raises `KeyError` when no entity of that name is in the
    /// scene (before the first step, which places the entities, none is).
    fn entity(&self, name: &str) -> PyResult<Entity> {
        guard(|| {
            let inner = self.lock()?;
            let state = inner.engine.entity(name).ok_or_else(|| {
                PyKeyError::new_err(format!("expected an entity in the scene, found '{name}'"))
            })?;
            Ok(self.snapshot(state, inner.engine.time()))
        })
    }

    /// Whether an entity called `name` is in the scene now.
    fn in_scene(&self, name: &str) -> PyResult<bool> {
        guard(|| Ok(self.lock()?.engine.entity(name).is_some()))
    }

    /// The event log so far as JSON text lines, one storyboard transition (or other record)
    /// per line: the lines `oscsim run --events` writes. `Simulation.events()` parses them.
    fn event_lines(&self) -> PyResult<Vec<String>> {
        guard(|| Ok(self.lock()?.events.lines.clone()))
    }

    /// The event log's lines from line `start` on (0-based): what the steps since added.
    fn _event_lines_since(&self, start: usize) -> PyResult<Vec<String>> {
        guard(|| {
            let inner = self.lock()?;
            Ok(inner.events.lines.get(start..).unwrap_or_default().to_vec())
        })
    }

    /// The recorded trajectories as NumPy arrays by column, one row per placed entity per
    /// frame (the trajectory CSV's rows): `time`, `id` (int64), `name` (object), `x`, `y`,
    /// `z`, `h`, `p`, `r`, `road_id` (object, '' off the roads), `lane_id` (int64, 0 off the
    /// roads), `offset`, `t`, `s` (NaN off the roads), `speed`, then world-axes `vx`, `vy`,
    /// `vz`, `ax`, `ay`, `az` and `yaw_rate`.
    fn trajectories<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        guard(|| {
            let inner = self.lock()?;
            let t = &inner.trajectories;
            let numpy = py.import("numpy")?;
            let d = PyDict::new(py);
            d.set_item("time", float_array(py, &numpy, &t.time)?)?;
            d.set_item("id", int_array(py, &numpy, &t.id)?)?;
            d.set_item("name", str_array(py, &numpy, &t.name)?)?;
            let numeric = Trajectories::NUMERIC.iter().zip(&t.values);
            for (name, column) in numeric.clone().take(6) {
                d.set_item(name, float_array(py, &numpy, column)?)?;
            }
            d.set_item("road_id", str_array(py, &numpy, &t.road_id)?)?;
            d.set_item("lane_id", int_array(py, &numpy, &t.lane_id)?)?;
            for (name, column) in numeric.skip(6) {
                d.set_item(name, float_array(py, &numpy, column)?)?;
            }
            Ok(d)
        })
    }

    /// The ASAM OSI 3.8 GroundTruth of the latest step as protobuf bytes (decode with the
    /// official bindings: `osi3.osi_groundtruth_pb2.GroundTruth.FromString(b)`), the message
    /// `oscsim run --osi` writes for that frame; empty before the first step. Raises
    /// `OscsimError` unless the simulation was made with `osi=True`.
    fn osi_ground_truth<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        guard(|| {
            let inner = self.lock()?;
            Ok(PyBytes::new(py, Self::osi(&inner)?.latest()))
        })
    }

    /// Every GroundTruth the latest `step()` made, in time order: after the first step two
    /// (t = 0, which carries the lanes and lane boundaries, and t = dt), after later steps one,
    /// after a step past the end none.
    fn osi_ground_truths<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyBytes>>> {
        guard(|| {
            let inner = self.lock()?;
            let frames = Self::osi(&inner)?.frames();
            Ok(frames.iter().map(|f| PyBytes::new(py, f)).collect())
        })
    }

    /// Rows of trajectory recorded so far.
    #[getter]
    fn trajectory_rows(&self) -> PyResult<usize> {
        guard(|| Ok(self.lock()?.trajectories.len()))
    }

    /// Forgets the recorded trajectories (recording goes on).
    fn clear_trajectories(&self) -> PyResult<()> {
        guard(|| {
            self.lock()?.trajectories.clear();
            Ok(())
        })
    }

    /// Sets the value of a UserDefinedValueCondition's `name` (bool, int, float or str) from
    /// the next step on.
    fn set_user_value(&self, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let value = value::from_py(value)?;
        guard(|| {
            self.lock()?.engine.set_user_value(name, value);
            Ok(())
        })
    }

    /// Sets global parameter `name` from the next step on, as a ParameterSetAction would; the
    /// value is converted to the declared type without loss and must meet the parameter's
    /// ConstraintGroups. Raises `KeyError` for an undeclared parameter, `ValueError` when the
    /// value does not convert or breaks the constraints (the parameter keeps its value).
    fn set_parameter(&self, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let value = value::from_py(value)?;
        let name = name.trim_start_matches('$');
        guard(|| {
            let set = self.lock()?.engine.set_parameter(name, &value);
            match set {
                Ok(true) => Ok(()),
                Ok(false) => Err(PyKeyError::new_err(format!(
                    "expected a declared global parameter, found '{name}'"
                ))),
                Err(e) => Err(PyValueError::new_err(format!("parameter '{name}': {e}"))),
            }
        })
    }

    /// Hands entity `name` to Python: assigns it an `external` controller active on the
    /// longitudinal and lateral domains and stops the motion actions running on it; until the
    /// first `control` it drives as under the default controller. Call it after the first
    /// step (which places the entities); an entity the scenario already gives an active
    /// `external` controller needs no call. Raises `SimulationError` for an unknown entity.
    fn attach_external(&self, name: &str) -> PyResult<()> {
        guard(|| {
            let attached = self.lock()?.engine.attach_external(name);
            attached.map_err(|e| SimulationError::new_err(e.to_string()))
        })
    }

    /// The input of entity `name`'s `external` controller from the next step on, in one of
    /// three forms: `acceleration` (m/s², along the direction of travel) with an optional front
    /// wheel angle `steering` (rad, positive left; None keeps the lane); pedals `throttle` and
    /// `brake` (0..1) with a `steering_wheel` angle (rad) through the engine's vehicle model;
    /// or the `pose` at the end of the step. It holds until the next call. Raises
    /// `SimulationError` unless an `external` controller holds the entity, `ValueError` for
    /// inputs out of range or of more than one form.
    #[pyo3(signature = (name, *, acceleration = None, steering = None, throttle = None, brake = None, steering_wheel = None, pose = None))]
    #[allow(clippy::too_many_arguments)] // Python keyword arguments
    fn control(
        &self,
        name: &str,
        acceleration: Option<f64>,
        steering: Option<f64>,
        throttle: Option<f64>,
        brake: Option<f64>,
        steering_wheel: Option<f64>,
        pose: Option<PyRef<'_, Pose>>,
    ) -> PyResult<()> {
        let input = Control {
            acceleration,
            steering,
            throttle,
            brake,
            steering_wheel,
            pose: pose.map(|p| *p),
        }
        .input()?;
        guard(|| {
            let set = self.lock()?.engine.set_external_input(name, input);
            set.map_err(|e| match e.kind() {
                engine::ErrorKind::ExternalInput { .. } => PyValueError::new_err(e.to_string()),
                _ => SimulationError::new_err(e.to_string()),
            })
        })
    }

    /// The value of global parameter `name` now. Raises `KeyError` for an undeclared one.
    fn parameter<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let name = name.trim_start_matches('$');
        guard(|| {
            let v = self.lock()?.engine.parameter(name).ok_or_else(|| {
                PyKeyError::new_err(format!(
                    "expected a declared global parameter, found '{name}'"
                ))
            })?;
            value::to_py(py, &v)
        })
    }

    /// The value of every monitor (MonitorDeclaration), by name.
    fn monitors(&self) -> PyResult<Vec<(String, bool)>> {
        guard(|| Ok(self.lock()?.engine.monitors()))
    }

    /// The state of every traffic signal that has one, by signal id.
    fn signal_states(&self) -> PyResult<Vec<(String, String)>> {
        guard(|| Ok(self.lock()?.engine.signal_states()))
    }

    /// Panics inside oscsim while holding the simulation, for tests of the boundary: raises
    /// `InternalError`, and the simulation refuses every later call.
    fn _debug_panic(&self) -> PyResult<()> {
        guard(|| {
            let _inner = self.lock()?;
            panic!("Simulation._debug_panic was called");
        })
    }

    fn __repr__(&self) -> PyResult<String> {
        Ok(format!(
            "Simulation({:?}, dt={}, seed={}, time={})",
            self.scenario_path,
            self.config.dt,
            self.config.seed,
            self.time()?
        ))
    }
}
