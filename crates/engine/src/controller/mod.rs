//! Controllers (OpenSCENARIO 1.3 §7.5 "Controllers"): what moves an entity each step. Only the
//! default controller exists; other controllers are rejected by the controller actions.
//!
//! | module | implements |
//! | --- | --- |
//! | `default` | the default controller's step: along the lane, through junctions |
//! | `route` | `RouteFollow`: the stretch of the assigned route driven, the successor and lane it needs |
//! | `lane_change` | the lane change a route needs: cubic, peak lateral acceleration 1 m/s² |

mod default;
mod lane_change;
mod route;

pub(crate) use default::{move_entity, place_on_track};
pub use route::RouteFollow;
