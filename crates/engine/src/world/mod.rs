//! The world's data (OpenSCENARIO 1.3 §8 "Scenario at runtime", §7.2.2 "Entities"): each
//! entity's state and the plain state the stages keep on it (the lane it tracks, the route it
//! follows and the lane change that route needs, the driver inputs overridden, the domains
//! its controllers are active on), the environment in force, the state each traffic signal
//! shows, and the lane arithmetic and transition shapes that state is computed with. It imports no behaviour module: actions, controllers, traffic, signals and the step
//! read and change it.
//!
//! | module | job |
//! | --- | --- |
//! | `entity` | entity state (pose, road position, speed, …), `EntityId`, `EntityKind`, `ControllerOverrides` |
//! | `lane_track` | `LaneTrack`: the lane the default controller keeps an entity in, its offset and a lateral transition (`Blend`) |
//! | `finite` | whether an entity's state is finite (the step's finite-state guard's test) |
//! | `environment` | the environment in force (§7.7.1 EnvironmentAction) and the scenario's clock |
//! | `date_time` | `xsd:dateTime` to seconds since 1970 (TimeOfDay, TimeOfDayCondition) |
//! | `domains` | `ActiveDomains`: the four domains of §6.6.1 a controller is active on |
//! | `signal_states` | `SignalStates`: the state each traffic signal shows |
//! | `lanes` | reference-line curvature, lane arithmetic, following lanes through links, how much of a lane lies ahead (the lane at an offset is `position::lane_at`) |
//! | `shapes` | transition shapes and dimensions (§7.7.2 TransitionDynamics) |
//! | `route_follow` | `RouteFollow`: the stretch of the assigned route driven, the successor and lane it needs |
//! | `lane_change` | the lane change a route (or `mobil`) needs: cubic, peak lateral acceleration 1 m/s²; none into a lane that ends within it |
//! | `zero_angle` | `sin_cos` and `atan2` at a zero angle (rise) with libm's bits, without the call (ISO C Annex F) |

pub(crate) mod date_time;
mod domains;
pub(crate) mod entity;
mod environment;
pub(crate) mod finite;
pub(crate) mod lane_change;
pub(crate) mod lane_track;
pub(crate) mod lanes;
pub(crate) mod route_follow;
pub(crate) mod shapes;
mod signal_states;
pub(crate) mod zero_angle;

pub use domains::ActiveDomains;
pub use entity::{ControllerOverrides, Entity, EntityId, EntityKind, Visibility};
pub use environment::{Clock, EnvironmentState};
pub use route_follow::RouteFollow;
pub use signal_states::SignalStates;
