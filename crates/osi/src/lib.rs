//! ASAM OSI 3.8.0 ground truth for oscsim: the `osi3` messages, the mapping helpers that
//! fill them from scenario entities, and `.osi` / `.mcap` trace files.
//!
//! - [`osi3`]: the messages (GroundTruth, MovingObject, StationaryObject, Lane,
//!   LaneBoundary, …), generated from `proto/` with the standard's field numbers.
//! - [`ground_truth::GroundTruthBuilder`]: one `GroundTruth` per step, lanes first or every
//!   frame, host vehicle by name; the entry point for the engine.
//! - [`ids::IdAllocator`]: globally unique, stable ids across objects, lanes, boundaries.
//! - [`rigid_body::RigidBodyState`]: reference point → bounding-box centre, velocity,
//!   acceleration (`MovingObject.base`).
//! - [`lanes::from_network`]: `Lane` / `LaneBoundary` from an OpenDRIVE road network,
//!   polylines sampled from the exact road model by [`polyline`].
//! - [`classification`], [`color`]: OpenSCENARIO categories and colours → OSI.
//! - [`entity`]: a scenario entity → `MovingObject` / `StationaryObject` with the OSI rules.
//! - [`trace`]: the [`trace::TraceWriter`] seam, `.osi` and `.mcap` writers and readers,
//!   the OSI file naming convention, and [`trace::TraceFile`] for `--osi PATH`.
//!
//! ```
//! use osi::trace::{read_osi_bytes, OsiFileWriter, TraceWriter};
//! let mut gt = osi::osi3::GroundTruth::default();
//! gt.version = Some(osi::version::interface_version());
//! let mut writer = OsiFileWriter::new(Vec::new(), "mem.osi".as_ref());
//! writer.write(&gt)?;
//! let bytes = writer.into_inner()?.unwrap_or_default();
//! let back = read_osi_bytes(&bytes, "mem.osi".as_ref())?;
//! assert_eq!(back, vec![gt]);
//! # Ok::<(), osi::Error>(())
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod classification;
pub mod color;
pub mod entity;
mod error;
pub mod ground_truth;
pub mod ids;
pub mod lanes;
pub mod osi3;
pub mod polyline;
pub mod rigid_body;
pub mod schema;
pub mod trace;
pub mod version;

pub use error::{Error, ErrorKind};
