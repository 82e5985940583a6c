//! User controllers (OpenSCENARIO 1.3 §6.6, §7.2.2.1, §7.7.2.5; engine module `controller`):
//! the built-in models in whole runs with hand-computed expectations, load errors, the external
//! API, spawned traffic with controllers, and the example examples/aeb_cut_in.rs.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module.

#[path = "../../../../examples/aeb_cut_in.rs"]
mod aeb;

#[path = "../support/scale.rs"]
mod scale;

mod aeb_example;
mod external_driver;
mod idm_junction;
mod threads;
mod user_controllers;
