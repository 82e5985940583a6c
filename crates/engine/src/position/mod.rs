//! Positions at runtime: OpenSCENARIO 1.3 §6.3 coordinate systems and the ten `Position`
//! forms of §7.4, resolved to a world pose of the entity's reference point and a road
//! position, over the OpenDRIVE road model. Written by hand: the rules are the standard's own
//! and the geometry is the `opendrive` crate's.
//!
//! | module | implements |
//! | --- | --- |
//! | `query` | `EntityQuery` / `EntityView`: the runtime's read-only answers about entities |
//! | `error` | `PositionError`, `PositionErrorKind` |
//! | `resolved` | `ResolvedPosition`: world pose + road position |
//! | `orientation` | absolute / relative Orientation rules, surface pitch and roll, object axes |
//! | `world` | WorldPosition, RelativeWorldPosition, RelativeObjectPosition |
//! | `road` | RoadPosition, RelativeRoadPosition |
//! | `lane` | LanePosition, RelativeLanePosition (ds and dsLane) |
//! | `lane_at` | the lane that holds a lateral offset at s (the look-up behind every entity's lane) |
//! | `lane_length` | arc length along a lane centre line; s after a distance along it |
//! | `road_chain` | the plan's measure over a DSL plan's roads: its s, or u = L − s along an oncoming actor's direction of travel; lane lengths and walks across their joints |
//! | `lane_walk` | ds along a lane across sections and connecting roads (1.3 continuation rule) |
//! | `beyond` | s past a road's ends: the same continuation for every road-based form |
//! | `check` | entity-free positions of a scenario resolved at load (actions' Road/Lane positions; conditions' positions of every entity-free form, and the entity-free route of a RoutePosition FromCurrentEntity planned) |
//! | `route` | RoutePosition (FromCurrentEntity, FromRoadCoordinates, FromLaneCoordinates) on the path of `routing::plan_route`, or FromCurrentEntity on a path planned before |
//! | `trajectory` | TrajectoryPosition on a polyline |
//! | `resolve` | `resolve`: the dispatcher (and `resolve_with`, the reference entity given); what each form needs (`needs`); GeoPosition |
//! | `sources` | every `EntityQuery` as routing's `WaypointSource` and trajectory's `PointSource` (resolving through `resolve`) |

mod beyond;
mod check;
mod error;
mod lane;
mod lane_at;
mod lane_length;
mod lane_walk;
mod orientation;
mod query;
mod resolve;
mod resolved;
mod road;
mod road_chain;
mod route;
mod sources;
mod trajectory;
mod world;

pub use check::check_positions;
pub(crate) use check::{plan_entity_free, resolve_entity_free};
pub use error::{PositionError, PositionErrorKind};
pub use query::{EntityQuery, EntityView};
pub use resolve::resolve;
pub(crate) use resolve::{needs, resolve_with, Needs};
pub use resolved::ResolvedPosition;
pub(crate) use route::on_planned_route;

pub(crate) use lane::{add_lanes, driving_heading as lane_driving_heading};
pub(crate) use lane_at::lane_at;
pub(crate) use lane_length::lane_arc_length;
pub use lane_length::SIMPSON_STEP;
pub(crate) use lane_walk::walk as lane_walk;
pub(crate) use orientation::local_to_world;
pub(crate) use road_chain::RoadChain;
