//! The protobuf schema of the OSI messages, for self-describing traces: the MCAP schema
//! record of an OSI channel holds the binary `FileDescriptorSet` of the top-level message
//! type, with all imports (OSI 3.8 §2.2.6.1.2, "OSI message schema").

/// Fully qualified name of the ground-truth message, the MCAP schema name of its channel.
pub const GROUND_TRUTH_SCHEMA_NAME: &str = "osi3.GroundTruth";

/// Binary `FileDescriptorSet` of `osi_groundtruth.proto` and everything it imports, as
/// `protoc --include_imports --descriptor_set_out` writes it; compiled by `build.rs`.
pub const GROUND_TRUTH_FILE_DESCRIPTOR_SET: &[u8] =
    include_bytes!(concat!(env!("OUT_DIR"), "/osi3_descriptor_set.bin"));
