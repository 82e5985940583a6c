//! Positions (OpenSCENARIO 1.3 §7.4) resolved to world poses and road positions: world, road,
//! lane, relative and route positions, continuation across roads, the Init placement esmini
//! reports, and their errors.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

#[path = "../support/condition.rs"]
mod condition_support;
#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/runtime/mod.rs"]
mod runtime_support;
#[path = "../support/trajectory.rs"]
mod trajectory_support;

mod continuation;
mod errors;
mod esmini_init;
mod geo;
mod road_lane;
mod route_planned;
mod route_seed;
mod route_trajectory;
mod teleport_heading;
mod world;
