//! The position resolver as the source of the positions routes and trajectories are made of
//! (OpenSCENARIO 1.3 §7.5 `Waypoint`, §6.9 `Vertex`, `ControlPoint`, `Clothoid`,
//! `ClothoidSplineSegment`: each holds a `Position`): every [`EntityQuery`] is a
//! [`WaypointSource`] and a [`PointSource`] that resolves them with [`resolve`]. So `routing`
//! and `trajectory` never call this module, and a RoutePosition or TrajectoryPosition resolves
//! through them without a cycle between the modules.

use opendrive::{RoadNetwork, RoadPosition};
use scenario::{Position, PositionKind};

use super::resolve::{orientation_of, resolve};
use super::{EntityQuery, PositionError};
use crate::routing::WaypointSource;
use crate::trajectory::{PlacedPoint, PointSource};

impl<Q: EntityQuery + ?Sized> WaypointSource for Q {
    type Error = PositionError;

    fn network(&self) -> &RoadNetwork {
        self.road_network()
    }

    fn road_position(&self, position: &Position) -> Result<Option<RoadPosition>, PositionError> {
        Ok(resolve(position, self)?.road_position)
    }
}

impl<Q: EntityQuery + ?Sized> PointSource for Q {
    type Error = PositionError;

    fn place(&self, position: &Position) -> Result<PlacedPoint, PositionError> {
        let r = resolve(position, self)?;
        Ok(PlacedPoint {
            pose: r.pose,
            oriented: states_heading(position),
        })
    }
}

/// Whether `position` states a heading: an `Orientation` element, or `h` on a WorldPosition.
fn states_heading(position: &Position) -> bool {
    match &position.kind {
        PositionKind::World { h, .. } => h.is_some(),
        kind => orientation_of(kind).is_some(),
    }
}
