//! The simulation handle: load a scenario (through the front door: OpenSCENARIO 1.3 XML with
//! its catalogs and road network, or OpenSCENARIO DSL 2.x; `scenario.rs` takes a DSL file's
//! road network and seed), step it in the engine's fixed steps (OpenSCENARIO 1.3 §8 "Scenario at runtime"),
//! read the entities after each step.
//!
//! Pointers: every function checks its pointers for null and returns
//! [`OscsimStatus::Argument`]; otherwise a pointer must be what the header says (a handle from
//! [`oscsim_simulation_new`] not yet freed, a NUL-terminated string, writable output). Strings
//! and states the library hands out stay valid until the next step or free of that handle.
//! A handle is not thread-safe: use it from one thread at a time.

use std::ffi::{c_char, CStr};
use std::path::Path;
use std::sync::Arc;

use engine::output::{Frame, FrameSink};
use engine::{Engine, EngineConfig, StopReason};
use osi::sink::{GroundTruthSink, SinkOptions, StepFrames};

use crate::error::{guard, Failure, OscsimStatus};
use crate::state::{OscsimEntityState, Scene};

/// Why a run ended, or that it goes on.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OscsimStopReason {
    /// The run goes on.
    Running = 0,
    /// The storyboard's StopTrigger fired.
    StopTrigger = 1,
    /// Every Story completed and the storyboard has no StopTrigger.
    StoriesComplete = 2,
    /// The configured duration elapsed.
    Duration = 3,
    /// The hard cap on simulated time (`max_time`) was reached.
    TimeCap = 4,
}

impl From<Option<StopReason>> for OscsimStopReason {
    fn from(reason: Option<StopReason>) -> Self {
        match reason {
            None => OscsimStopReason::Running,
            Some(StopReason::StopTrigger) => OscsimStopReason::StopTrigger,
            Some(StopReason::StoriesComplete) => OscsimStopReason::StoriesComplete,
            Some(StopReason::Duration) => OscsimStopReason::Duration,
            Some(StopReason::TimeCap) => OscsimStopReason::TimeCap,
        }
    }
}

/// How a simulation runs. [`oscsim_config_default`] gives the engine's defaults.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OscsimConfig {
    /// Step length (s), > 0.
    pub dt: f64,
    /// Seed of the random streams (spawned traffic, random routes).
    pub seed: u64,
    /// Stop after this much simulated time (s); 0 or less: no limit but the storyboard's.
    pub duration: f64,
    /// Hard cap on simulated time (s).
    pub max_time: f64,
    /// 1: make the ASAM OSI GroundTruth of every frame, as `oscsim run --osi` does (host
    /// vehicle `Ego`, lanes in the first frame), read with
    /// [`oscsim_simulation_osi_ground_truth`]; 0: none.
    pub osi: i32,
}

/// One global parameter override at load time, as `oscsim run --param NAME=VALUE`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct OscsimParameter {
    /// Parameter name (a leading `$` is allowed), UTF-8.
    pub name: *const c_char,
    /// Value as text, parsed as the declared type, UTF-8.
    pub value: *const c_char,
}

/// A simulation: opaque to C.
pub struct OscsimSimulation {
    pub(crate) engine: Engine,
    pub(crate) scene: Scene,
    /// The OSI GroundTruths of the latest step, when asked for.
    osi: Option<StepFrames>,
    /// The error a step failed with: the run cannot go on.
    failed: Option<String>,
    /// Set while a call works on the simulation; still set on entry when an earlier call
    /// panicked half-way, whose state can no longer be trusted.
    busy: bool,
}

/// The engine's defaults: dt 0.05 s, seed 1, no duration, max_time 3600 s; no OSI.
#[no_mangle]
pub extern "C" fn oscsim_config_default() -> OscsimConfig {
    let d = EngineConfig::default();
    OscsimConfig {
        dt: d.dt,
        seed: d.seed,
        duration: d.duration.unwrap_or(0.0),
        max_time: d.max_time,
        osi: 0,
    }
}

/// `text` as UTF-8, or an argument failure naming `what`.
///
/// # Safety
/// `text` is null or a NUL-terminated string.
pub(crate) unsafe fn text<'a>(text: *const c_char, what: &str) -> Result<&'a str, Failure> {
    if text.is_null() {
        return Err(Failure::argument(format!(
            "expected {what}, found a null pointer"
        )));
    }
    // SAFETY: non-null, and NUL-terminated by the caller's contract.
    let c = unsafe { CStr::from_ptr(text) };
    c.to_str()
        .map_err(|_| Failure::argument(format!("expected {what} in UTF-8, found other bytes")))
}

/// The simulation behind `sim`, refused when an earlier call panicked on it.
///
/// # Safety
/// `sim` is null or a live handle of [`oscsim_simulation_new`], used by no other thread.
pub(crate) unsafe fn handle<'a>(
    sim: *mut OscsimSimulation,
) -> Result<&'a mut OscsimSimulation, Failure> {
    // SAFETY: null or a live, exclusively used handle by the caller's contract.
    let sim = unsafe { sim.as_mut() }
        .ok_or_else(|| Failure::argument("expected a simulation, found a null pointer"))?;
    if sim.busy {
        return Err(Failure::new(
            OscsimStatus::Panic,
            "this simulation is unusable: an earlier call panicked inside oscsim; free it and \
             load a new one",
        ));
    }
    Ok(sim)
}

/// Runs `f` on the simulation behind `sim`, marking it busy meanwhile (see [`handle`]).
///
/// # Safety
/// As [`handle`].
pub(crate) unsafe fn with_sim(
    sim: *mut OscsimSimulation,
    f: impl FnOnce(&mut OscsimSimulation) -> Result<(), Failure>,
) -> OscsimStatus {
    guard(|| {
        // SAFETY: passed on from the caller.
        let sim = unsafe { handle(sim) }?;
        sim.busy = true;
        let result = f(sim);
        sim.busy = false;
        result
    })
}

/// Entity `index` of `items`, or an argument failure.
fn at<T>(items: &[T], index: usize) -> Result<&T, Failure> {
    items.get(index).ok_or_else(|| {
        Failure::argument(format!(
            "expected an entity index below {}, found {index}",
            items.len()
        ))
    })
}

/// Writes `value` to `out`.
///
/// # Safety
/// `out` is null or writable.
pub(crate) unsafe fn write<T>(out: *mut T, value: T) -> Result<(), Failure> {
    if out.is_null() {
        return Err(Failure::argument("expected an output pointer, found null"));
    }
    // SAFETY: non-null and writable by the caller's contract.
    unsafe { out.write(value) };
    Ok(())
}

/// `n_params` overrides from `params` (null when 0) as (name, value).
///
/// # Safety
/// `params` points to `n_params` overrides whose strings are NUL-terminated.
pub(crate) unsafe fn overrides(
    params: *const OscsimParameter,
    n_params: usize,
) -> Result<Vec<(String, String)>, Failure> {
    if n_params == 0 {
        return Ok(Vec::new());
    }
    if params.is_null() {
        return Err(Failure::argument(
            "expected parameters, found a null pointer",
        ));
    }
    // SAFETY: `params` points to `n_params` overrides.
    let params = unsafe { std::slice::from_raw_parts(params, n_params) };
    params
        .iter()
        .map(|p| {
            // SAFETY: NUL-terminated strings by the caller's contract.
            let name = unsafe { text(p.name, "a parameter name") }?;
            let value = unsafe { text(p.value, "a parameter value") }?;
            Ok((name.trim_start_matches('$').to_owned(), value.to_owned()))
        })
        .collect()
}

/// A load failure with the front door's message (file:line:col).
pub(crate) fn load_failure(e: &dyn std::fmt::Display) -> Failure {
    Failure::new(OscsimStatus::Load, e.to_string())
}

impl OscsimSimulation {
    /// A simulation of `loaded` with `config` (null: [`oscsim_config_default`]).
    pub(crate) fn build(
        loaded: &load::Loaded,
        config: Option<&OscsimConfig>,
    ) -> Result<Self, Failure> {
        let c = config.copied().unwrap_or_else(|| oscsim_config_default());
        // Settings the C struct does not have keep the engine's defaults.
        let config = EngineConfig {
            dt: c.dt,
            seed: c.seed,
            duration: (c.duration > 0.0).then_some(c.duration),
            max_time: c.max_time,
            ..EngineConfig::default()
        };
        let engine = Engine::new(&loaded.scenario, Arc::clone(&loaded.network), config)
            .map_err(|e| load_failure(&e))?;
        let osi = if c.osi != 0 {
            let sink = GroundTruthSink::new(&engine, &SinkOptions::default())
                .map_err(|e| load_failure(&format!("cannot make the OSI ground truth: {e}")))?;
            Some(StepFrames::new(sink))
        } else {
            None
        };
        Ok(OscsimSimulation {
            engine,
            scene: Scene::default(),
            osi,
            failed: None,
            busy: false,
        })
    }
}

/// Loads the scenario at `path` with `n_params` overrides from `params` (may be null when 0)
/// and builds a simulation with `config` (null: [`oscsim_config_default`]): the front door of
/// [`crate::oscsim_scenario_load`] with the default road network (an OpenSCENARIO DSL file's
/// `map.set_map_file(…)`) and `config`'s seed. On success writes the handle to `*out` (free it
/// with [`oscsim_simulation_free`]); on failure writes null and returns
/// [`OscsimStatus::Load`] (message with file:line:col) or [`OscsimStatus::Argument`].
/// Nothing has run yet: the first step runs the Init actions.
///
/// # Safety
/// `path` is a NUL-terminated string; `params` points to `n_params` overrides whose strings
/// are NUL-terminated; `config` is null or readable; `out` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_new(
    path: *const c_char,
    params: *const OscsimParameter,
    n_params: usize,
    config: *const OscsimConfig,
    out: *mut *mut OscsimSimulation,
) -> OscsimStatus {
    guard(|| {
        // SAFETY: the caller's contract, pointer by pointer.
        unsafe { write(out, std::ptr::null_mut())? };
        let path = unsafe { text(path, "a scenario path") }?;
        let params = unsafe { overrides(params, n_params) }?;
        // SAFETY: null or readable.
        let config = unsafe { config.as_ref() };
        let options = load::Options {
            seed: config.map_or(engine::runtime::DEFAULT_SEED, |c| c.seed),
            params,
            dt: config.map_or(engine::runtime::DEFAULT_DT, |c| c.dt),
            ..load::Options::default()
        };
        let loaded = load::load(Path::new(path), &options).map_err(|e| load_failure(&e))?;
        let sim = Box::new(OscsimSimulation::build(&loaded, config)?);
        // SAFETY: checked writable above.
        unsafe { write(out, Box::into_raw(sim)) }
    })
}

/// Frees a simulation (null does nothing).
///
/// # Safety
/// `sim` is null or a handle of [`oscsim_simulation_new`] not freed before; it is not used
/// after.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_free(sim: *mut OscsimSimulation) {
    if !sim.is_null() {
        // SAFETY: a handle of Box::into_raw, freed once by the caller's contract. Dropping an
        // engine does not panic (plain data); the guard is for the unforeseen.
        let _ = guard(|| {
            drop(unsafe { Box::from_raw(sim) });
            Ok(())
        });
    }
}

/// What a step reports to: the scene, and the OSI frames when asked for.
struct Sinks<'a> {
    scene: &'a mut Scene,
    osi: Option<&'a mut StepFrames>,
}

impl FrameSink for Sinks<'_> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        self.scene.frame(frame)?;
        match &mut self.osi {
            Some(osi) => osi.frame(frame),
            None => Ok(()),
        }
    }
}

impl OscsimSimulation {
    fn step(&mut self) -> Result<OscsimStopReason, Failure> {
        if let Some(message) = &self.failed {
            return Err(Failure::new(
                OscsimStatus::Step,
                format!("the simulation stopped after an error: {message}"),
            ));
        }
        if let Some(osi) = self.osi.as_mut() {
            osi.begin_step();
        }
        let mut sinks = Sinks {
            scene: &mut self.scene,
            osi: self.osi.as_mut(),
        };
        let reason = self.engine.step(&mut sinks, &mut ()).map_err(|e| {
            self.failed = Some(e.to_string());
            Failure::new(OscsimStatus::Step, e.to_string())
        })?;
        Ok(reason.into())
    }
}

/// Runs one step of dt (the first also runs the Init actions and reports the frame at t = 0
/// as well). Writes why the run ended to `*reason` ([`OscsimStopReason::Running`] while it goes
/// on; `reason` may be null); a step after the end does nothing.
///
/// # Safety
/// `sim` is a live handle; `reason` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_step(
    sim: *mut OscsimSimulation,
    reason: *mut OscsimStopReason,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| {
            let r = sim.step()?;
            if !reason.is_null() {
                write(reason, r)?;
            }
            Ok(())
        })
    }
}

/// Steps until the run ends; writes why to `*reason` (may be null).
///
/// # Safety
/// As [`oscsim_simulation_step`].
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_run(
    sim: *mut OscsimSimulation,
    reason: *mut OscsimStopReason,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| loop {
            let r = sim.step()?;
            if r != OscsimStopReason::Running {
                if !reason.is_null() {
                    write(reason, r)?;
                }
                return Ok(());
            }
        })
    }
}

/// Writes the simulation time of the latest step (s; 0 before the first) to `*time`.
///
/// # Safety
/// `sim` is a live handle; `time` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_time(
    sim: *mut OscsimSimulation,
    time: *mut f64,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe { with_sim(sim, |sim| write(time, sim.engine.time())) }
}

/// Writes the number of entities in the scene after the latest step to `*count` (0 before the
/// first step, which places them).
///
/// # Safety
/// `sim` is a live handle; `count` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_entity_count(
    sim: *mut OscsimSimulation,
    count: *mut usize,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe { with_sim(sim, |sim| write(count, sim.scene.states.len())) }
}

/// Writes the state of entity `index` (0 ≤ index < count) to `*state`.
///
/// # Safety
/// `sim` is a live handle; `state` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_entity_state(
    sim: *mut OscsimSimulation,
    index: usize,
    state: *mut OscsimEntityState,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| {
            let s = at(&sim.scene.states, index)?;
            write(state, *s)
        })
    }
}

/// Writes the name of entity `index` to `*name` (UTF-8, valid until the next step or free).
///
/// # Safety
/// `sim` is a live handle; `name` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_entity_name(
    sim: *mut OscsimSimulation,
    index: usize,
    name: *mut *const c_char,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| {
            let n = at(&sim.scene.names, index)?;
            write(name, n.as_ptr())
        })
    }
}

/// Writes the OpenDRIVE road id of entity `index` to `*road_id` ("" off the roads; valid
/// until the next step or free).
///
/// # Safety
/// `sim` is a live handle; `road_id` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_entity_road_id(
    sim: *mut OscsimSimulation,
    index: usize,
    road_id: *mut *const c_char,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| {
            let r = at(&sim.scene.road_ids, index)?;
            write(road_id, r.as_ptr())
        })
    }
}

/// Writes the index of the entity called `name` in the scene to `*index`;
/// [`OscsimStatus::NotFound`] when no entity of that name is in the scene now.
///
/// # Safety
/// `sim` is a live handle; `name` is a NUL-terminated string; `index` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_find_entity(
    sim: *mut OscsimSimulation,
    name: *const c_char,
    index: *mut usize,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| {
            let name = text(name, "an entity name")?;
            let i = sim.scene.find(name).ok_or_else(|| {
                Failure::new(
                    OscsimStatus::NotFound,
                    format!("expected an entity in the scene, found '{name}'"),
                )
            })?;
            write(index, i)
        })
    }
}

/// Panics inside oscsim while working on `sim`, for tests of the boundary: returns
/// [`OscsimStatus::Panic`], and every later call on `sim` but [`oscsim_simulation_free`]
/// returns [`OscsimStatus::Panic`] too; other simulations go on.
///
/// # Safety
/// `sim` is a live handle.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_test_panic(sim: *mut OscsimSimulation) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe { with_sim(sim, |_| panic!("oscsim_simulation_test_panic was called")) }
}

/// Writes the number of OSI GroundTruths the latest step made to `*count`: 2 after the first
/// step (t = 0, which carries the lanes, and t = dt), 1 after later ones, 0 before the first
/// and after a step past the end.
/// [`OscsimStatus::Argument`] unless the simulation was made with `osi` = 1.
///
/// # Safety
/// `sim` is a live handle; `count` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_osi_frame_count(
    sim: *mut OscsimSimulation,
    count: *mut usize,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe { with_sim(sim, |sim| write(count, osi_frames(sim)?.len())) }
}

/// Writes GroundTruth `index` of the latest step (0 ≤ index < the frame count; the last is
/// the current state) as protobuf bytes (ASAM OSI 3.8 osi_groundtruth.proto, the message
/// `oscsim run --osi` writes for that frame) to `*data` and its length to `*len`. The bytes
/// are the library's, valid until the next step or free.
///
/// # Safety
/// `sim` is a live handle; `data` and `len` are writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_osi_ground_truth(
    sim: *mut OscsimSimulation,
    index: usize,
    data: *mut *const u8,
    len: *mut usize,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| {
            let frames = osi_frames(sim)?;
            let frame = frames.get(index).ok_or_else(|| {
                Failure::argument(format!(
                    "expected a frame index below {}, found {index}",
                    frames.len()
                ))
            })?;
            write(data, frame.as_ptr())?;
            write(len, frame.len())
        })
    }
}

fn osi_frames(sim: &OscsimSimulation) -> Result<&[Vec<u8>], Failure> {
    let osi = sim.osi.as_ref().ok_or_else(|| {
        Failure::argument("expected a simulation made with osi = 1, found one without OSI output")
    })?;
    Ok(osi.frames())
}
