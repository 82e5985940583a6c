//! OpenSCENARIO 2.0 §8.7 physical-object actors and their measurement methods.
//!
//! | module | implements |
//! | --- | --- |
//! | `error` | `DomainError`, the error cases the §8.7 methods name |
//! | `enums` | §8.7.12–8.7.17 vehicle_category, intended_infrastructure, distance_direction, distance_mode, on_route_type, route_distance_enum |
//! | `color` | §8.7.11 color and its RGB table (W3C values for fuchsia and purple) |
//! | `kinematics` | position_3d, velocity_6d, acceleration_6d |
//! | `frame` | the object coordinate system placed by a pose_3d |
//! | `bounding_box` | §8.7.9 bounding_box |
//! | `footprint` | the bounding box's ground-plane rectangle |
//! | `object` | §8.7.2–8.7.5, 8.7.7, 8.7.8 physical_object … person, animal |
//! | `vehicle` | §8.7.6 vehicle, §8.7.10 axle |
//! | `actor` | `Actor`: one of the instantiable §8.7 actors, for stores holding every kind |
//! | `object_distance` | §8.7.2.1.1 object_distance() |
//! | `time_to_collision` | §8.7.5.1.1 time_to_collision() |
//! | `road_locate` | an object's road position; one road's s/t on another's axes |
//! | `road_path` | shortest distance along roads between two road positions |
//! | `route_coords` | §8.7.2.1.2–8.7.2.1.4 get_s_coord(), get_t_coord(), get_route_point() |
//! | `route` | the route / compound_route argument of §8.7.4.1.1 |
//! | `distance_along_route` | §8.7.4.1.1 distance_along_route() |
//! | `time_headway` | §8.7.5.1.2 time_headway() |
//! | `space_gap` | §8.7.5.1.3 space_gap() |
//! | `from_scenario` | OpenSCENARIO 1.x Vehicle, Pedestrian, MiscObject → §8.7 actors |
//! | `vehicle_group` | §8.7.18.1 vehicle_group (non-normative): a single-lane formation |

mod actor;
mod bounding_box;
mod color;
mod distance_along_route;
mod enums;
mod error;
mod footprint;
mod frame;
mod from_scenario;
mod kinematics;
mod object;
mod object_distance;
mod road_locate;
mod road_path;
mod route;
mod route_coords;
mod space_gap;
mod time_headway;
mod time_to_collision;
mod vehicle;
mod vehicle_group;

pub use actor::Actor;
pub use bounding_box::BoundingBox;
pub use color::Color;
pub use enums::{
    DistanceDirection, DistanceMode, IntendedInfrastructure, OnRouteType, RouteDistanceEnum,
    VehicleCategory,
};
pub use error::{DomainError, DomainErrorKind};
pub use kinematics::{Acceleration6d, Position3d, Vector3, Velocity6d};
pub use object::{
    Animal, MovableObject, Person, Physical, PhysicalObject, StationaryObject, TrafficParticipant,
};
pub(crate) use road_path::shortest_road_path;
pub use route::{Route, RouteStretch};
pub use route_coords::{RouteElement, RoutePoint};
pub(crate) use space_gap::{signed_gap, Interval, RoadPair};
pub use time_headway::time_headway_between;
pub use vehicle::{Axle, Vehicle};
pub use vehicle_group::VehicleGroup;
