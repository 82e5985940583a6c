//! ASAM OpenSCENARIO 1.0–1.3 (XML) scenario model for oscsim.
//!
//! Parses `.xosc` files into typed, resolved data with source positions.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod distribution;
pub mod expr;
