//! Condition evaluation (OpenSCENARIO 1.3 §7.6) on a fake runtime (`condition_support::FakeWorld`)
//! over corpus road networks: by-value and by-entity conditions, spacing, motion, road state.
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

mod by_value;
mod clearance_angle;
mod errors;
mod fixtures;
mod motion;
mod road_state;
mod spacing;
