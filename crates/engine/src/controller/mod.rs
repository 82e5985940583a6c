//! User controllers (OpenSCENARIO 1.3 §6.6 "Controllers", §7.2.2.1 "Motion control for
//! entities", §7.7.2.5 "ControllerAction"): the built-in models an entity can be given with a
//! `Controller` whose `<Property name="model">` names one (`properties`), the
//! [`Controller`] trait they implement, the world view they read and the stage that applies
//! their commands.
//!
//! # Motion domains
//!
//! An entity's longitudinal and lateral domains each belong to at most one active user
//! controller; the default controller takes every domain no user controller holds (§7.2.2.1:
//! "the default controller is assigned to an entity's motion domain if no user assigned
//! controller is running, or a user assigned controller is running but only controls one
//! motion domain"), and a controller that is not one of oscsim's models (esmini's) holds none.
//! Activating a controller on a domain stops the action running there: that action's control
//! strategy belonged to the default controller, which loses the domain (§7.5.1: the newer
//! control of a domain overrides the running one).
//!
//! # A motion action on a domain a user controller holds
//!
//! §6.6.1: "the default controller enforces control strategies exactly as they are described
//! by the actions; a user-defined controller may have custom interpretations of control
//! strategies", and "the default controller is expected to enforce control strategies along the
//! entity domains that do not have a user defined controller". oscsim's rule: a
//! MotionControlAction (LongitudinalAction, LateralAction, SynchronizeAction,
//! FollowTrajectoryAction) that starts on a domain a user controller holds is handed to that
//! controller instead of the default controller, and completes at once: it assigns no control
//! strategy to the default controller, so none remains to be completed (§7.5.2). What each
//! model makes of it, written to the event log:
//!
//! - `idm`, `mobil`, `acc`, `vehicle_dynamics`: a SpeedAction's target speed (a relative one as
//!   it is at the start), or a SpeedProfileAction's last entry, becomes the desired speed (set
//!   speed, the speed the driver keeps); the transition shape is not followed, the model's own
//!   dynamics are;
//! - `mobil`: a LaneChangeAction's target lane becomes its next lane change, made with its own
//!   lateral shape; a target that is no drivable lane of the entity's road where it is, or one
//!   driven the other way (a relative target counted across the centre line), is not taken:
//!   the entity keeps its lane, and the log says why;
//! - `mobil`, and `idm` where no user controller holds the lateral domain: oscsim's mandatory
//!   lane (`scenario::LateralAction::MandatoryLane`, no XML form) is reached lane by lane into
//!   gaps MOBIL's safety criterion accepts and kept until released (module `mobil`, "A
//!   mandatory lane");
//! - `idm`, `mobil`: oscsim's free-road acceleration
//!   (`scenario::LongitudinalAction::ModelAcceleration`, no XML form) takes the place of the
//!   IDM's free-road term, its interaction term toward the leader kept, until released (module
//!   `car_following`); as the rate toward a speed (`scenario::ModelAcceleration::Toward`), that
//!   speed is the desired speed and the rate's magnitude toward it the free-road term until
//!   the speed is reached, then the model's own term (module `car_following`, "A rate toward a
//!   speed");
//! - every other motion action, and every one given to `external`, is not taken (the log says
//!   "ignored").
//!
//! In the Init a SpeedAction on such a domain also sets the entity's speed at once: the Init
//! gives initial states (§7.2.1). A TeleportAction is no motion control: it always places the
//! entity. A domain handed back (deactivation) continues under the default controller from the
//! entity's speed and lane offset then.
//!
//! | module | job |
//! | --- | --- |
//! | `default` | the default controller's step: along the lane, through junctions |
//! | `command` | the [`Controller`] trait, [`Command`], [`Strategy`] |
//! | `view` | [`ControllerView`]: the entity, its neighbours and gaps along the lanes |
//! | `lane_beside` | the lanes beside as the road decides them (drivable, direction, road mark), kept over the stretch they hold |
//! | `car_following` | `idm` and `acc` |
//! | `mobil` | `mobil` (IDM + MOBIL lane changes) |
//! | `vehicle_dynamics` | `vehicle_dynamics`: driver + single-track vehicle, overrides |
//! | `external_input` | [`ExternalInput`]: what the host asks of an `external` entity, and its check |
//! | `external` | `external`: driven by the host program ([`ExternalInput`]) |
//! | `table` | controllers per entity, active domains |
//! | `drivers` | the `idm` and `mobil` models by value, and the controllers holding a domain, as the stage walks them |
//! | `assign` | AssignControllerAction, ActivateControllerAction, ObjectController |
//! | `properties` | a `Controller`'s `model` property and settings → the model to run, or the default controller |
//! | `load` | every controller read when the engine is built; ObjectControllers assigned |
//! | `strategy` | motion actions handed to the controller holding their domain |
//! | `parallel` | the driver models' commands of a step on several threads (the same bits) |
//! | `one_gap` | two lane changes into one gap: the one behind yields (SUMO's order) |
//! | `stage` | the controllers stage: commands, then moves |

mod assign;
mod car_following;
mod command;
mod default;
mod drivers;
mod external;
mod external_input;
mod lane_beside;
mod load;
mod mobil;
mod one_gap;
mod parallel;
pub mod properties;
pub(crate) mod stage;
mod strategy;
mod table;
#[cfg(test)]
mod test_world;
mod vehicle_dynamics;
mod view;

pub use crate::world::ActiveDomains;
pub use crate::world::RouteFollow;
pub(crate) use assign::{activate, assign, Origin, Taken};
pub use car_following::{AccController, IdmController};
pub use command::{Command, Controller, FreeAcceleration, Lateral, Longitudinal, Strategy};
pub(crate) use default::place_on_track;
pub use external::ExternalController;
pub use external_input::{ExternalInput, InputError};
pub(crate) use load::set_up;
pub use mobil::MobilController;
pub use properties::TrafficModel;
pub(crate) use strategy::hand_over;
pub(crate) use table::ControllerTable;
pub use vehicle_dynamics::VehicleDynamicsController;
pub use view::{ControllerView, Gap, NeighbourLane, Side};
