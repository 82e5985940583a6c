//! The osi crate's integration tests but the allocation count, one binary (issue 33); each
//! module is one former test file, `common` their shared helpers. `tests/allocations.rs` stays
//! a binary of its own: its counting global allocator would count every test of a shared one.

mod common;
mod engine_sink;
mod ground_truth_builder;
mod lanes_reference;
mod trace_errors;
mod trace_roundtrip;
mod wire_format;
