//! Expressions (OpenSCENARIO 1.3 §9.2): operators, functions, values and their errors.
//!
//! One test target per area (`tests/<area>/main.rs`); each file below is one module.

mod errors;
mod functions;
mod operators;
mod values;
