//! Spawned traffic (OpenSCENARIO 1.3 §7.2.2.3 "Spawned objects", XSD `TrafficAction`):
//! TrafficSourceAction, TrafficSinkAction, TrafficSwarmAction, TrafficAreaAction,
//! TrafficStopAction.
//!
//! Uses point one way: `state` (the running table) → the kinds (`area` and `source_sink`,
//! which take `swarm`'s constants, and `swarm`) → `spawn` → `controllers` → `spawning` and
//! `random`, which use no sibling.
//!
//! | module | job |
//! | --- | --- |
//! | `area` | TrafficAreaAction: a number of vehicles in a polygon or road ranges |
//! | `controllers` | the controller a spawned vehicle gets: ControllerDistribution, template ObjectControllers, run option; run option `vehicle_model` for the scenario's vehicles |
//! | `random` | the per-action random streams, split from the run's seed |
//! | `spawn` | vehicle templates, free lane points, adding and removing spawned vehicles |
//! | `state` | the running traffic actions, their start and the traffic stage of the step |
//! | `swarm` | TrafficSwarmAction: a ring of traffic around a central object |
//! | `source_sink` | TrafficSourceAction and TrafficSinkAction |

mod area;
mod controllers;
mod random;
mod source_sink;
mod spawn;
mod spawning;
mod state;
mod swarm;

pub(crate) use controllers::equip_scenario_vehicles;
pub(crate) use spawn::leave;
pub(crate) use state::{start, step, supports, Traffic};
