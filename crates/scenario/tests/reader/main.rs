//! Reading .xosc into the typed, resolved model: catalogs, every action and condition type,
//! parameter scopes, the corpus, the coverage table, errors with positions, robustness.
//!
//! One test target per area (`tests/<area>/main.rs`); each file below is one module.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

mod catalogs;
mod corpus;
mod coverage;
mod errors;
mod every_type;
mod memory_files;
mod model;
mod robustness;
mod with_parameters;
