//! Versions that go into every message and trace file: the OSI interface version the
//! messages follow (ASAM OSI 3.8.0, `osi3.InterfaceVersion`) and the protobuf
//! implementation that encodes them (prost), as the OSI trace file naming convention
//! (OSI 3.8 §2.2.6.2) and the MCAP channel metadata (§2.2.6.1.2) ask for.

use crate::osi3::InterfaceVersion;

/// OSI major version of the messages in `proto/`.
pub const OSI_VERSION_MAJOR: u32 = 3;
/// OSI minor version of the messages in `proto/`.
pub const OSI_VERSION_MINOR: u32 = 8;
/// OSI patch version of the messages in `proto/`.
pub const OSI_VERSION_PATCH: u32 = 0;
/// The OSI version as `major.minor.patch`.
pub const OSI_VERSION: &str = "3.8.0";
/// Version of the protobuf implementation (the `prost` crate) that encodes the messages,
/// as `major.minor.patch`. A test checks it against `Cargo.lock`.
pub const PROTOBUF_VERSION: &str = "0.13.5";

/// The `osi3.InterfaceVersion` of the messages in `proto/`: 3.8.0.
pub fn interface_version() -> InterfaceVersion {
    InterfaceVersion {
        version_major: Some(OSI_VERSION_MAJOR),
        version_minor: Some(OSI_VERSION_MINOR),
        version_patch: Some(OSI_VERSION_PATCH),
    }
}
