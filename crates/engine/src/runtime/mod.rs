//! The scenario runtime (OpenSCENARIO 1.3 §8 "Scenario at runtime"): the world and its entity
//! store, building from the scenario model and the fixed step. The entities' own state is the
//! crate's module `world`. The actions, the controllers
//! and spawned traffic it drives are the crate's top-level modules `actions`, `controller`
//! and `traffic`.
//!
//! | module | job |
//! | --- | --- |
//! | `config` | step length, duration, cap |
//! | `world` | road network + entity store + values; `EntityQuery` / `ConditionContext` |
//! | `frame_view` | a frame's or a kept state's entity as the §8.7 methods see it (`view()`) |
//! | `lane_index` | per-lane index of the entities on the road for gap searches (built once per step) |
//! | `lane_slots` | the lane index's dense lane numbers and lane borders kept per road |
//! | `build` | scenario model → world, storyboard description, action and condition tables |
//! | `conditions` | the storyboard's `ConditionSource` |
//! | `trigger_view` | the step-start world that all triggers of a step see |
//! | `trailer` | trailer connections and the one-axle trailer kinematics |
//! | `external` | ExternalObjectReference entities placed at their OpenDRIVE objects |
//! | `finite` | the step's guard: no non-finite entity state reaches a frame |
//! | `selection` | EntitySelection members at runtime, §7.2.2.5 multiplicity checks |
//! | `targets` | what an action's target asks for now: `entityRef`, SpeedActionTarget, LaneChangeTarget |
//! | `engine` | `Engine`: the built scenario and its API |
//! | `read` | what the engine answers between steps, as plain values (`Engine::entities`, …) |
//! | `step` | the fixed step, one private method per stage |

pub(crate) mod build;
mod conditions;
mod config;
mod engine;
mod external;
mod finite;
mod frame_view;
pub(crate) mod lane_index;
mod lane_slots;
mod read;
pub(crate) mod selection;
mod step;
pub(crate) mod targets;
pub(crate) mod trailer;
pub(crate) mod trigger_view;
pub(crate) mod world;

pub use crate::world::shapes::{shape_value, Span};
pub use crate::world::{ControllerOverrides, Entity, EntityId, EntityKind, Visibility};
pub use config::{EngineConfig, TrafficModel, DEFAULT_DT, DEFAULT_MAX_TIME, DEFAULT_SEED};
pub use engine::{Engine, StageCounters, StopReason};

// For the controllers stage (engine module `controller`).
pub(crate) use world::{place_on_lane, World};
