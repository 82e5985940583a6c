//! The oscsim runtime: an OpenSCENARIO 1.3 scenario on an ASAM OpenDRIVE road network, run
//! headless in fixed steps; entity state, storyboard, conditions, actions, controllers, and the
//! physical-object domain model of OpenSCENARIO 2.0 §8.7.
//!
//! The front door: load a [`scenario::Scenario`] and its road network once
//! ([`load::road_network`], an `Arc` that engines share), build an [`Engine`] with
//! [`Engine::new`] (or [`Engine::load`] for one run from a path), and step it:
//! [`Engine::step`] advances one fixed step and pushes a [`Frame`] to a [`FrameSink`] and the
//! step's [`EventRecord`]s to an [`EventSink`]. Between steps, [`Engine::entities`] gives each
//! entity's state as plain values ([`EntityState`]). Variants of a scenario for a batch come
//! from [`scenario::Scenario::with_parameters`], which reads no file its first load read.
//!
//! ```
//! use std::path::Path;
//! use std::sync::Arc;
//! use engine::{load, output::CsvWriter, Engine, EngineConfig, EventRecord};
//!
//! let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenarios/cut_in_highway.xosc");
//! let scenario = scenario::Scenario::load(Path::new(path))?;
//! let network = load::road_network(&scenario)?; // read once, shared
//! let config = EngineConfig { duration: Some(2.0), ..EngineConfig::default() };
//!
//! let mut engine = Engine::new(&scenario, Arc::clone(&network), config)?;
//! let mut csv = CsvWriter::new(Vec::new());
//! let mut events: Vec<EventRecord> = Vec::new();
//! engine.run(&mut csv, &mut events)?;
//!
//! // 2 s at the default 0.05 s step: 40 steps; Ego drives at its $EgoSpeed (25 m/s).
//! assert_eq!(engine.steps(), 40);
//! let ego = engine.entity("Ego").expect("in the scene");
//! assert_eq!(ego.speed, 25.0);
//!
//! // A variant with another parameter value, on the same road network.
//! let slower = scenario.with_parameters(&[("EgoSpeed".into(), "20".into())])?;
//! let mut engine = Engine::new(&slower, network, config)?;
//! engine.run(&mut (), &mut ())?;
//! assert_eq!(engine.entity("Ego").expect("in the scene").speed, 20.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! | module | implements |
//! | --- | --- |
//! | `controller` | OpenSCENARIO 1.3 §7.5 controllers and §6.6 user controllers: the default controller, route following, the `Controller` trait, `idm`, `mobil`, `acc`, `vehicle_dynamics`, `external`, the controllers stage |
//! | `domain` | OpenSCENARIO 2.0 §8.7 physical-object actors and their measurement methods |
//! | `storyboard` | OpenSCENARIO 1.3 §7.2.1 / §8.3–8.4 storyboard state machine and triggers |
//! | `position` | OpenSCENARIO 1.3 §7.4 positions resolved to world poses and road positions |
//! | `condition` | OpenSCENARIO 1.3 §7.6 condition evaluation |
//! | `trajectory` | OpenSCENARIO 1.3 trajectory shapes (Polyline, Clothoid, ClothoidSpline, Nurbs) by arc length and time |
//! | `models` | driver and vehicle models of the built-in controllers: IDM, MOBIL, ACC, single-track vehicle |
//! | `routing` | OpenSCENARIO 1.3 routes: waypoints and routeStrategy planned on the OpenDRIVE lane graph |
//! | `signals` | OpenSCENARIO 1.3 traffic signal controllers: phases cycling, reference and delay, signal states |
//! | `user_values` | values from outside for UserDefinedValueCondition: typed text, time series, CSV file |
//! | `world` | the world's data: entity state and the plain state the stages keep on entities, lane look-ups, transition shapes |
//! | `store` | OpenSCENARIO 1.3 §8 the world store of a run: `World` (road network, entities, values), the lane index, selections, trailer connections, action targets |
//! | `runtime` | OpenSCENARIO 1.3 §8 scenario at runtime: building, the `Engine`, the step; the stages' tables |
//! | `actions` | OpenSCENARIO 1.3 §7.7 actions at runtime: one file per action kind, the action table |
//! | `traffic` | OpenSCENARIO 1.3 §7.2.2.3 spawned traffic: sources, sinks, swarms, areas |
//! | `output` | trajectory CSV, event log and the per-step frame seam for OSI |
//! | `error` | `Error`, the one error of the public API: `kind()` an `ErrorKind`, `pos()` the scenario's file:line:col |
//! | `load` | the loading layer: road networks read once and shared, `Engine::load` |
//! | `tolerance` | the named numeric tolerances (time, speed, length, turn, value, step fraction) |
//! | `snapshot` | entity and environment state as plain values (`Engine::entities`) |
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod actions;
pub mod condition;
pub mod controller;
pub mod domain;
mod error;
pub mod load;
pub mod models;
pub mod output;
pub mod position;
pub mod routing;
pub mod runtime;
pub mod signals;
mod snapshot;
mod store;
pub mod storyboard;
pub mod tolerance;
mod traffic;
pub mod trajectory;
pub mod user_values;
mod world;

pub use error::{Error, ErrorKind};
pub use load::RoadNetworks;
pub use output::{CsvWriter, EntityFrame, JsonlWriter};
pub use output::{EventRecord, EventSink, Frame, FrameSink, SinkError, SinkErrorKind};
pub use runtime::{Engine, EngineConfig, StageCounters, StopReason};
pub use snapshot::{Clock, EntityState, EnvironmentState, ScenarioSource};
pub use world::{EntityId, EntityKind, Visibility};
