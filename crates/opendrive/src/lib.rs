//! ASAM OpenDRIVE 1.4–1.8 road model for oscsim.
//!
//! Parses `.xodr` files into typed data and evaluates the road geometry exactly (f64, analytic
//! reference-line geometry, no pre-sampled polylines).
#![forbid(unsafe_code)]
#![deny(missing_docs)]
