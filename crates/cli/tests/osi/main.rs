//! `oscsim run --osi`: the OSI ground truth written by the binary (mapping, lights, trailers,
//! visibility, options, trace formats).
//!
//! One test target per area (`tests/<area>/main.rs`); each file below is one module.

#[path = "../osi_common/mod.rs"]
mod osi_common;

mod dsl_actors;
mod environment;
mod lights;
mod mapping;
mod options;
mod trace;
mod traffic_signals;
mod trailer;
mod visibility;
