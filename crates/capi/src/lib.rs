//! C API of oscsim: a `cdylib` (`liboscsim.so`) and the header `include/oscsim.h` that
//! cbindgen generates from this crate. A thin layer over the engine's library API: opaque
//! handles, plain C structs and status codes; no Rust type crosses the boundary, and no panic
//! either (each call catches it and returns [`OscsimStatus::Panic`]).
//!
//! | module | job |
//! | --- | --- |
//! | `control` | inputs of entities under an `external` controller (the system under test) |
//! | `error` | status codes, the last error message, the panic guard |
//! | `scenario` | the scenario handle: either language loaded through the front door (a DSL file with its road network and seed) |
//! | `simulation` | the simulation handle: load, step, run, time, entities by index or name, OSI bytes |
//! | `state` | entity states as C values, copied from each step's frame |
//!
//! `examples/c/run_scenario.c` shows the calls; `tests/it/c_example.rs` compiles and runs it.
//! The crate's job is FFI, hence `unsafe`: each use says why it holds. It is the one crate
//! where the workspace lint `unsafe_code` is allowed (the C ABI: `#[no_mangle]` functions
//! taking raw pointers).
#![allow(unsafe_code)]

mod control;
mod error;
mod scenario;
mod simulation;
mod state;

pub use control::{
    oscsim_simulation_attach_external, oscsim_simulation_set_acceleration,
    oscsim_simulation_set_pedals, oscsim_simulation_set_pose,
};
pub use error::{oscsim_last_error_message, oscsim_test_panic, OscsimStatus};
pub use scenario::{
    oscsim_load_options_default, oscsim_scenario_free, oscsim_scenario_load,
    oscsim_simulation_from_scenario, OscsimLoadOptions, OscsimScenario,
};
pub use simulation::{
    oscsim_config_default, oscsim_simulation_entity_count, oscsim_simulation_entity_name,
    oscsim_simulation_entity_road_id, oscsim_simulation_entity_state,
    oscsim_simulation_find_entity, oscsim_simulation_free, oscsim_simulation_new,
    oscsim_simulation_osi_frame_count, oscsim_simulation_osi_ground_truth, oscsim_simulation_run,
    oscsim_simulation_step, oscsim_simulation_test_panic, oscsim_simulation_time, OscsimConfig,
    OscsimParameter, OscsimSimulation, OscsimStopReason,
};
pub use state::{OscsimEntityKind, OscsimEntityState};
