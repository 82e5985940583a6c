//! The fixed-step runtime (OpenSCENARIO 1.3 §8): actions (speed, lateral, distance, synchronize),
//! the default controller, the trigger view, action order, end of the run, global values, and
//! esmini's reference runs and the reader of them.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.

#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/runtime/mod.rs"]
mod runtime_support;

mod acceleration_action;
mod action_order;
mod actions;
mod batch_variants;
mod clothoid_spline_start;
mod condition_positions;
mod controller;
mod distance;
mod distance_esmini;
mod end_time;
mod esmini_reference_reader;
mod global;
mod held_check_time;
mod init_names;
mod lane_follow;
mod lateral;
mod lateral_esmini;
mod lateral_follow_rate;
mod override_values;
mod random_traffic_create;
mod red_light;
mod relative_acceleration_shape;
mod signals_controllers;
mod speed_action;
mod speed_limits;
mod speed_profile;
mod sync_arrival;
mod sync_esmini;
mod time_of_day;
mod travel_action;
mod trigger_view;
mod user_values;
