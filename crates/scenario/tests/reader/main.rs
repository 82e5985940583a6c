//! Reading .xosc into the typed, resolved model: catalogs, every action and condition type,
//! parameter scopes, the corpus, the coverage table, errors with positions, robustness.
//!
//! One test target per area (`tests/<area>/main.rs`); each file below is one module.

mod catalogs;
mod corpus;
mod coverage;
mod errors;
mod every_type;
mod memory_files;
mod model;
mod robustness;
mod with_parameters;
