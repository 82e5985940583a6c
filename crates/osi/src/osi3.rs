//! The ASAM OSI 3.8.0 messages oscsim writes, generated at build time by `prost-build`
//! from the definitions in `crates/osi/proto/` (see the README there): package `osi3`,
//! `GroundTruth` and everything it reaches through the fields oscsim fills.
//!
//! Field names, numbers and types are those of OSI 3.8.0, so the bytes that
//! [`prost::Message::encode`] produces are the standard's wire format. Optional scalar
//! fields are `Option<_>` (proto2 presence), enums are `Option<i32>` with typed accessors.
#![allow(missing_docs)] // generated code: each message and field carries the proto comment, enum values do not

include!(concat!(env!("OUT_DIR"), "/osi3.rs"));
