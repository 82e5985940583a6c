//! Parameter value distributions (OpenSCENARIO 1.3 §9.5): deterministic, stochastic, errors.
//!
//! One test target per area (`tests/<area>/main.rs`); each file below is one module.

mod deterministic;
mod errors;
mod stochastic;
