//! Whole-corpus sweeps: every corpus scenario runs without a panic (the two broken ones fail
//! naming the missing file), runs are byte-identical, and damaged inputs never panic, hang or
//! reach a frame with a non-finite value.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.

#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/runtime/mod.rs"]
mod runtime_support;

mod determinism;
mod every_scenario;
mod robustness;
mod robustness_cases;
