//! The oscsim runtime: entity state, storyboard, actions, conditions, controllers and the
//! physical-object domain model of OpenSCENARIO 2.0 §8.7.
//!
//! [`Engine::build`] turns a loaded [`scenario::Scenario`] and its road network into a runnable
//! engine; [`Engine::step`] advances it by one fixed step and pushes a [`Frame`] to a
//! [`FrameSink`] and the step's [`EventRecord`]s to an [`EventSink`].
//!
//! | module | implements |
//! | --- | --- |
//! | `controller` | OpenSCENARIO 1.3 §6.6 user controllers: the `Controller` trait, `idm`, `mobil`, `acc`, `vehicle_dynamics`, `external`, the controllers stage |
//! | `domain` | OpenSCENARIO 2.0 §8.7 physical-object actors and their measurement methods |
//! | `storyboard` | OpenSCENARIO 1.3 §7.2.1 / §8.3–8.4 storyboard state machine and triggers |
//! | `position` | OpenSCENARIO 1.3 §7.4 positions resolved to world poses and road positions |
//! | `condition` | OpenSCENARIO 1.3 §7.6 condition evaluation |
//! | `trajectory` | OpenSCENARIO 1.3 trajectory shapes (Polyline, Clothoid, ClothoidSpline, Nurbs) by arc length and time |
//! | `models` | driver and vehicle models of the built-in controllers: IDM, MOBIL, ACC, single-track vehicle |
//! | `routing` | OpenSCENARIO 1.3 routes: waypoints and routeStrategy planned on the OpenDRIVE lane graph |
//! | `signals` | OpenSCENARIO 1.3 traffic signal controllers: phases cycling, reference and delay, signal states |
//! | `user_values` | values from outside for UserDefinedValueCondition: typed text, time series, CSV file |
//! | `runtime` | OpenSCENARIO 1.3 §8 scenario at runtime: world, entities, building, the step |
//! | `actions` | OpenSCENARIO 1.3 §7.7 actions at runtime: one file per action kind, the action table |
//! | `controller` | OpenSCENARIO 1.3 §7.5 controllers: the default controller, route following |
//! | `traffic` | OpenSCENARIO 1.3 §7.2.2.3 spawned traffic: sources, sinks, swarms, areas |
//! | `output` | trajectory CSV, event log and the per-step frame seam for OSI |
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod actions;
pub mod condition;
pub mod controller;
pub mod domain;
pub mod models;
pub mod output;
pub mod position;
pub mod routing;
pub mod runtime;
pub mod signals;
pub mod storyboard;
mod traffic;
pub mod trajectory;
pub mod user_values;

pub use output::{EventRecord, EventSink, Frame, FrameSink};
pub use runtime::{
    Engine, EngineConfig, EntityId, LoadError, RuntimeError, RuntimeErrorKind, StopReason,
};
