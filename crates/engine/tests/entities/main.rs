//! Entities at runtime (OpenSCENARIO 1.3 §7.2.2): adding and deleting, selections, triggering
//! entities, appearance, visibility, external objects, spawned traffic and trailers.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.

#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/runtime/mod.rs"]
mod runtime_support;

mod add_delete;
mod appearance;
mod external;
mod select_triggering;
mod selection;
mod traffic;
mod traffic_roles;
mod trailers;
mod visibility;
