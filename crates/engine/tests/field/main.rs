//! Scenarios from the field (issues 16 and 34): the semantics the visible corpus does not exercise,
//! one module per class, each with the standard's rule in its doc and hand-computed
//! expectations in its comments. Fixtures in `tests/files/field/`.

#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/runtime/mod.rs"]
mod runtime_support;

mod support;

mod against_s;
mod asam_examples;
mod asam_lane_changes;
mod asam_sync_nurbs;
mod asam_traffic_jams;
mod clearance;
mod empty_elements;
mod group_state;
mod init_together;
mod jerk;
mod other_suites;
mod past_road_end;
mod pedestrian_sync;
mod qualified_names;
mod trailers;
