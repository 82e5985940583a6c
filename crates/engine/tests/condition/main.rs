//! Condition evaluation (OpenSCENARIO 1.3 §7.6) on a fake runtime (`condition_support::FakeWorld`)
//! over corpus road networks: by-value and by-entity conditions, spacing, motion, road state.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.

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
