//! The scenario runtime (OpenSCENARIO 1.3 §8 "Scenario at runtime"): building from the scenario
//! model, the `Engine` and the fixed step. The data the step changes is the crate's module
//! `store` (the `World`) and `world` (the entities' own state); the stages it runs are the
//! crate's top-level modules `actions`, `controller` and `traffic`, each handed its own table
//! (`ActionTable`, `ControllerTable`, `Traffic`), which the `Engine` keeps.
//!
//! | module | job |
//! | --- | --- |
//! | `config` | step length, duration, cap |
//! | `frame_view` | a frame's or a kept state's entity as the §8.7 methods see it (`view()`) |
//! | `build` | scenario model → world, storyboard description, action and condition tables |
//! | `conditions` | the storyboard's `ConditionSource` |
//! | `trigger_view` | the step-start world that all triggers of a step see |
//! | `external` | ExternalObjectReference entities placed at their OpenDRIVE objects |
//! | `finite` | the step's guard: no non-finite entity state reaches a frame (the moves test what they move) |
//! | `engine` | `Engine`: the built scenario and its API |
//! | `read` | what the engine answers between steps, as plain values (`Engine::entities`, …) |
//! | `step` | the fixed step, one private method per stage |
//! | `trailer_stage` | the trailer stage: each connected trailer placed behind its tow |

mod build;
mod conditions;
mod config;
mod engine;
mod external;
mod finite;
mod frame_view;
mod read;
mod step;
mod trailer_stage;
pub(crate) mod trigger_view;

pub use crate::world::shapes::{shape_value, Span};
pub use crate::world::{ControllerOverrides, Entity, EntityId, EntityKind, Visibility};
pub use config::{EngineConfig, TrafficModel, DEFAULT_DT, DEFAULT_MAX_TIME, DEFAULT_SEED};
pub use engine::{Engine, StageCounters, StopReason};
