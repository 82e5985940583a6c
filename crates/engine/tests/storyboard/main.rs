//! Storyboard state machine and triggers (OpenSCENARIO 1.3 §7.2.1, §8.3–8.4): element states and
//! transitions, edges, delays, priorities, execution counts, stop triggers, and esmini's
//! reference transition logs.
//!
//! One test target per area (crates/engine/tests/<area>/main.rs); each file below is one
//! module, the helpers are shared from `tests/support/`.

#[path = "../support/corpus.rs"]
mod corpus;
#[path = "../support/storyboard.rs"]
mod storyboard_support;

mod condition_groups;
mod delay;
mod edges;
mod errors;
mod esmini_acc_test;
mod esmini_follow_reference;
mod execution_count;
mod init;
mod log;
mod priority;
mod properties;
mod stages;
mod start_with_parent;
mod state_condition;
mod stop;
