//! Trajectories and routes (OpenSCENARIO 1.3 §7.5 routes, §7.7 FollowTrajectoryAction): shapes
//! by arc length and time, route planning on the OpenDRIVE lane graph, driving along both, and
//! esmini's reference runs.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/runtime/mod.rs"]
mod runtime_support;
#[path = "../support/trajectory.rs"]
mod trajectory_support;

mod errors;
mod esmini;
mod esmini_nurbs;
mod esmini_polyline;
mod properties;
mod routing_corpus;
mod routing_drive;
mod routing_esmini;
mod routing_properties;
mod routing_random_route;
mod routing_strategies;
mod runtime;
mod shapes;
mod timing;
