//! The world store of a run (OpenSCENARIO 1.3 §8 "Scenario at runtime"): the data the stages
//! of the step read and change, importing none of the modules of those stages (`actions`,
//! `controller`, `traffic`, `runtime`). The entities' own state is the crate's module `world`;
//! the tables of the stages (the actions, the user controllers, running traffic) belong to
//! the stage that owns them and are handed to it by `runtime`.
//!
//! | module | job |
//! | --- | --- |
//! | `world` | `World`: road network + entity store + values; `EntityQuery` / `ConditionContext` |
//! | `object` | an `Entity` from its ScenarioObject (also the template of spawned vehicles) |
//! | `driver_inputs` | the driver models' per-step inputs per entity, a compact copy filled with the lane index |
//! | `lane_index` | per-lane index of the entities on the road for gap searches (built once per step) |
//! | `lane_kept` | what the lane index keeps of each entity's entries from step to step, its order repair and check |
//! | `lane_refresh` | the lane index's entries made in the moves' walk, made anew at the step's start only for entities written since |
//! | `lane_slots` | the lane index's dense lane numbers and lane borders kept per road |
//! | `selection` | EntitySelection members at runtime, §7.2.2.5 multiplicity checks |
//! | `targets` | what an action's target asks for now: `entityRef`, SpeedActionTarget, LaneChangeTarget |
//! | `trailer` | trailer connections and the one-axle trailer kinematics |

pub(crate) mod driver_inputs;
pub(crate) mod lane_index;
mod lane_kept;
#[cfg(test)]
pub(crate) use lane_kept::tests::generator;
#[cfg(test)]
mod lane_kept_tests;
mod lane_refresh;
#[cfg(test)]
mod lane_search_tests;
mod lane_slots;
mod object;
pub(crate) mod selection;
pub(crate) mod targets;
pub(crate) mod trailer;
mod world;

pub(crate) use object::entity;
pub(crate) use world::{place_on_lane, ConditionWorld, World};
