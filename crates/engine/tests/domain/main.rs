//! The OpenSCENARIO 2.0 §8.7 physical-object actors and their measurement methods (distances,
//! gaps, headway, time to collision, route coordinates) against closed forms.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.

#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/domain.rs"]
mod domain_support;

mod distance_along_route;
mod from_scenario;
mod object_distance;
mod properties;
mod route_coords;
mod space_gap;
mod time_headway;
mod time_to_collision;
mod types;
mod vehicle_group;
