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
//! - [`lights`]: OpenSCENARIO vehicle light states → `VehicleClassification.LightState`.
//! - [`traffic_signals`]: OpenDRIVE signals → `TrafficLight` (one per bulb, state from the
//!   engine's signal controllers) and `TrafficSign`; [`signal_types`] the type tables.
//! - [`environment`]: the scenario's Environment (weather, sun, fog, time of day) →
//!   `EnvironmentalConditions`, OSI's bands.
//! - [`entity`]: a scenario entity → `MovingObject` / `StationaryObject` with the OSI rules.
//! - `reuse`: each frame written over the last one's message (no allocation per frame).
//! - [`sink`]: the engine→OSI mapping, one GroundTruth per engine frame
//!   ([`sink::GroundTruthSink`]), and the engine frame sinks built on it: [`sink::OsiSink`]
//!   (a trace file) and [`sink::StepFrames`] (the bindings).
//! - [`trace`]: the [`trace::TraceWriter`] seam, `.osi` and `.mcap` writers and readers,
//!   the OSI file naming convention, and [`trace::TraceFile`] for `--osi PATH`.
//!
//! ```
//! use osi::entity::{EntityInfo, EntityKind};
//! use osi::ground_truth::{GroundTruthBuilder, StaticData};
//! use osi::rigid_body::RigidBodyState;
//! use osi::trace::{read_osi_bytes, OsiFileWriter, TraceWriter};
//!
//! let mut builder = GroundTruthBuilder::new(StaticData::First);
//! let mut writer = OsiFileWriter::new(Vec::new(), "mem.osi".as_ref());
//! let ego = EntityInfo {
//!     name: "Ego",
//!     kind: EntityKind::Vehicle { category: "car" },
//!     scenario_file: Some("cut-in.xosc"),
//!     model3d: None,
//!     color: None,
//!     trailer: None,
//!     lights: None,
//!     role: None,
//! };
//! for step in 0..3u64 {
//!     let state = RigidBodyState {
//!         reference_point: [20.0 * 0.05 * step as f64, 0.0, 0.0],
//!         velocity: [20.0, 0.0, 0.0],
//!         bbox_centre: [1.4, 0.0, 0.75],
//!         dimension: [4.5, 1.8, 1.5],
//!         ..Default::default()
//!     };
//!     let mut frame = builder.begin_frame(step * 50_000_000);
//!     frame.add_entity(&ego, &state, &[])?;
//!     writer.write(frame.finish())?;
//! }
//! let bytes = writer.into_inner()?.unwrap_or_default();
//! let back = read_osi_bytes(&bytes, "mem.osi".as_ref())?;
//! // Step 2: reference point at x = 2 m, bounding-box centre 1.4 m ahead of it.
//! let x = back[2].moving_object[0].base.as_ref().and_then(|b| b.position?.x);
//! assert!((x.unwrap() - 3.4).abs() < 1e-12);
//! assert_eq!(back[2].host_vehicle_id, back[2].moving_object[0].id);
//! # Ok::<(), osi::Error>(())
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod classification;
pub mod color;
pub mod entity;
pub mod environment;
mod error;
pub mod ground_truth;
pub mod ids;
pub mod lanes;
pub mod lights;
pub mod osi3;
pub mod polyline;
mod reuse;
pub mod rigid_body;
pub mod schema;
pub mod signal_types;
pub mod sink;
pub mod trace;
pub mod traffic_signals;
pub mod version;

pub use error::{Error, ErrorKind};
