//! The scenario handle: a scenario loaded through the front door (the `load` crate), in either
//! language — OpenSCENARIO XML 1.x (`.xosc`, with parameter overrides, OpenSCENARIO 1.3 §9.1)
//! or OpenSCENARIO DSL 2.x (`.osc`, with its road network and the seed its constraints are
//! solved with) — from which any number of simulations are built, sharing its road network.

use std::ffi::c_char;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::error::{guard, Failure};
use crate::simulation::{
    load_failure, overrides, text, write, OscsimConfig, OscsimParameter, OscsimSimulation,
};

/// How [`oscsim_scenario_load`] loads a scenario: the options of `oscsim run`.
/// [`oscsim_load_options_default`] gives none.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct OscsimLoadOptions {
    /// The OpenDRIVE road network of an OpenSCENARIO DSL scenario (`--road`), UTF-8; null: the
    /// file its `map.set_map_file(…)` names. Must be null for an XML scenario (it names its
    /// own).
    pub road: *const c_char,
    /// The seed of a DSL scenario's constraint solver (`--seed`; same seed, same scenario).
    pub seed: u64,
    /// Global parameter overrides of an XML scenario (`--param`); null when `n_params` is 0.
    /// Must be none for a DSL scenario (it varies by seed).
    pub params: *const OscsimParameter,
    /// How many overrides `params` points to.
    pub n_params: usize,
}

/// A loaded scenario: opaque to C.
pub struct OscsimScenario {
    loaded: Arc<load::Loaded>,
}

/// No road network, seed 1 (the engine's default seed), no overrides.
#[no_mangle]
pub extern "C" fn oscsim_load_options_default() -> OscsimLoadOptions {
    OscsimLoadOptions {
        road: std::ptr::null(),
        seed: engine::runtime::DEFAULT_SEED,
        params: std::ptr::null(),
        n_params: 0,
    }
}

/// Loads the scenario at `path` (`.xosc` or `.osc`) with `options` (null:
/// [`oscsim_load_options_default`]). On success writes the handle to `*out` (free it with
/// [`oscsim_scenario_free`]); on failure writes null and returns
/// [`crate::OscsimStatus::Load`] with the message naming file:line:col (the XML element, the
/// DSL construct, the road file), or [`crate::OscsimStatus::Argument`].
///
/// # Safety
/// `path` is a NUL-terminated string; `options` is null or readable, its strings
/// NUL-terminated and `params` pointing to `n_params` overrides; `out` is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_scenario_load(
    path: *const c_char,
    options: *const OscsimLoadOptions,
    out: *mut *mut OscsimScenario,
) -> crate::OscsimStatus {
    guard(|| {
        // SAFETY: the caller's contract, pointer by pointer.
        unsafe { write(out, std::ptr::null_mut())? };
        let path = unsafe { text(path, "a scenario path") }?;
        let o = unsafe { options.as_ref() }
            .copied()
            .unwrap_or_else(|| oscsim_load_options_default());
        let road = if o.road.is_null() {
            None
        } else {
            Some(PathBuf::from(unsafe {
                text(o.road, "a road network path")
            }?))
        };
        let options = load::Options {
            road,
            seed: o.seed,
            params: unsafe { overrides(o.params, o.n_params) }?,
            ..load::Options::default()
        };
        let loaded = load::load(Path::new(path), &options).map_err(|e| load_failure(&e))?;
        let scenario = Box::new(OscsimScenario {
            loaded: Arc::new(loaded),
        });
        // SAFETY: checked writable above.
        unsafe { write(out, Box::into_raw(scenario)) }
    })
}

/// Frees a scenario (null does nothing); simulations built from it live on.
///
/// # Safety
/// `scenario` is null or a handle of [`oscsim_scenario_load`] not freed before; it is not used
/// after.
#[no_mangle]
pub unsafe extern "C" fn oscsim_scenario_free(scenario: *mut OscsimScenario) {
    if !scenario.is_null() {
        // SAFETY: a handle of Box::into_raw, freed once by the caller's contract.
        let _ = guard(|| {
            drop(unsafe { Box::from_raw(scenario) });
            Ok(())
        });
    }
}

/// Builds a simulation of `scenario` with `config` (null: [`crate::oscsim_config_default`]),
/// on the scenario's road network. On success writes the handle to `*out` (free it with
/// [`crate::oscsim_simulation_free`]); on failure writes null and returns
/// [`crate::OscsimStatus::Load`] or [`crate::OscsimStatus::Argument`].
///
/// # Safety
/// `scenario` is a live handle of [`oscsim_scenario_load`]; `config` is null or readable; `out`
/// is writable.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_from_scenario(
    scenario: *const OscsimScenario,
    config: *const OscsimConfig,
    out: *mut *mut OscsimSimulation,
) -> crate::OscsimStatus {
    guard(|| {
        // SAFETY: the caller's contract, pointer by pointer.
        unsafe { write(out, std::ptr::null_mut())? };
        let scenario = unsafe { scenario.as_ref() }
            .ok_or_else(|| Failure::argument("expected a scenario, found a null pointer"))?;
        let config = unsafe { config.as_ref() };
        let sim = Box::new(OscsimSimulation::build(&scenario.loaded, config)?);
        // SAFETY: checked writable above.
        unsafe { write(out, Box::into_raw(sim)) }
    })
}
