//! The read-only seam between positions/conditions and the runtime: what the runtime knows
//! about each entity at the current moment of a step (OpenSCENARIO 1.3 §6.3 "Coordinate
//! systems", §7.2.2 "Entities", §6.4 "Distances").
//!
//! The runtime implements [`EntityQuery`]; position resolution and condition evaluation read
//! entities only through it, so they never see the runtime's stores. An [`EntityView`] is a
//! small value built on demand: the pose of the entity's reference point (for a vehicle the
//! centre of the rear axle, on the ground), its road position, its motion and its bounding box.

use opendrive::{Pose, Real, RoadNetwork, RoadPosition};
use scenario::ObjectType;

use crate::domain::{
    Acceleration6d, BoundingBox, MovableObject, PhysicalObject, Route, TrafficParticipant,
    Velocity6d,
};
use crate::routing::RoutingOptions;
use crate::trajectory::Trajectory;

/// One entity as positions and conditions see it at the current moment.
///
/// Build one with [`EntityView::new`] and fill the rest with struct-update syntax
/// (`EntityView { speed: 3.0, ..EntityView::new(…) }`), so that fields added later do not
/// break existing code.
#[derive(Debug, Clone, Copy)]
pub struct EntityView<'a> {
    /// The entity's name (XSD `ScenarioObject/@name`).
    pub name: &'a str,
    /// What the entity is: vehicle, pedestrian, miscellaneous object or external object
    /// (XSD `ObjectType`, the categories of `CollisionCondition/ByType`).
    pub object_type: ObjectType,
    /// Pose of the reference point in world coordinates (x, y, z in m; h, p, r in rad).
    pub pose: Pose,
    /// Where the reference point lies on the road network (`RoadNetwork::locate` of the
    /// pose); `None` when the runtime found no road at all.
    pub road_position: Option<&'a RoadPosition>,
    /// Signed speed along the entity's heading, m/s (negative when reversing): what
    /// SpeedCondition and RelativeSpeedCondition compare when they have no `direction`, what
    /// TimeHeadwayCondition divides by, and what StandStillCondition tests (|speed|).
    pub speed: Real,
    /// Velocity in the entity's own axes (x forward, y left, z up), world as reference: the
    /// components of directional speed conditions, and the motion that TimeToCollision
    /// extrapolates.
    pub velocity: Velocity6d,
    /// Acceleration in the entity's own axes, world as reference (AccelerationCondition; x
    /// when it has no `direction`).
    pub acceleration: Acceleration6d,
    /// Distance travelled since the start of the simulation along the path (odometer), m:
    /// what TraveledDistanceCondition compares.
    pub odometer: Real,
    /// The bounding box, centre relative to the reference point (XSD `BoundingBox`).
    pub bounding_box: BoundingBox,
    /// The route assigned by an AssignRouteAction, if any: the path of
    /// `routingAlgorithm="assignedRoute"` distances.
    pub route: Option<&'a Route>,
    /// The trajectory the entity follows (FollowTrajectoryAction), if any: the frame of
    /// `coordinateSystem="trajectory"` distances.
    pub trajectory: Option<&'a Trajectory>,
}

impl<'a> EntityView<'a> {
    /// An entity named `name` of `object_type` at `pose`, at rest, with no road position, no
    /// route and a zero odometer.
    pub fn new(
        name: &'a str,
        object_type: ObjectType,
        pose: Pose,
        bounding_box: BoundingBox,
    ) -> Self {
        Self {
            name,
            object_type,
            pose,
            road_position: None,
            speed: 0.0,
            velocity: Velocity6d::ZERO,
            acceleration: Acceleration6d::ZERO,
            odometer: 0.0,
            bounding_box,
            route: None,
            trajectory: None,
        }
    }

    /// The OpenSCENARIO 2.0 §8.7.2 physical_object of this entity (pose and box), for the
    /// domain methods.
    pub fn physical_object(&self) -> PhysicalObject {
        PhysicalObject::new(self.bounding_box, self.pose)
    }

    /// The OpenSCENARIO 2.0 §8.7.5 traffic_participant of this entity (pose, box, velocity,
    /// acceleration), for time_to_collision and the road-based methods.
    pub fn traffic_participant(&self) -> TrafficParticipant {
        let mut movable = MovableObject::new(self.physical_object());
        movable.velocity = self.velocity;
        movable.acceleration = self.acceleration;
        TrafficParticipant::new(movable, Vec::new())
    }
}

/// Read access to the entities of a running scenario and to its road network.
///
/// Implemented by the runtime; every method answers for the current moment of the step.
pub trait EntityQuery {
    /// The entity called `name`, or `None` if there is no such entity (or it is not placed
    /// yet).
    fn entity(&self, name: &str) -> Option<EntityView<'_>>;

    /// All entities that are placed, in declaration order (for CollisionCondition by type and
    /// RelativeClearanceCondition, which look at every other entity).
    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_>;

    /// The road network the scenario runs on.
    fn road_network(&self) -> &RoadNetwork;

    /// The settings routes are planned with (RoutePosition, AssignRouteAction): the runtime
    /// gives its run's seed for routeStrategy `random`, so that one route plans one path for
    /// positions, the controller and conditions. Default: [`RoutingOptions::default`].
    fn routing_options(&self) -> RoutingOptions {
        RoutingOptions::default()
    }
}
