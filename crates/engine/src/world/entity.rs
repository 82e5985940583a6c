//! Entity state at runtime (OpenSCENARIO 1.3 §7.2.2 "Entities", §6.3 coordinate systems):
//! the pose of the reference point (a vehicle's rear-axle centre, on the ground), its road
//! position, speed, velocity, acceleration, odometer, the bounding box and the
//! OpenSCENARIO 2.0 §8.7 physical-object view of it.
//!
//! Entities live in the [`World`](crate::store::World)'s store, addressed by [`EntityId`].

use std::collections::BTreeMap;

use opendrive::{Pose, Real, RoadPosition};
use scenario::{
    LightState, MiscObjectCategory, ObjectType, PedestrianCategory, Performance, VehicleCategory,
};

use super::lane_track::LaneTrack;
use crate::domain::{Acceleration6d, BoundingBox, Color, Route, Vector3, Velocity6d};
use crate::storyboard::ActionId;

/// The driver inputs overridden on one entity (OverrideControllerValueAction, OpenSCENARIO 1.3
/// §7.7.2.5): per input, the last override an action gave (active, or released with
/// `active = false`); `None` where no action has named the input.
/// It has the shape of the action itself, which is kept as the state.
pub type ControllerOverrides = scenario::OverrideControllerValueAction;

/// Handle of an entity in the world's store: its index in declaration order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct EntityId(pub u32);

impl EntityId {
    /// The entity's index in declaration order (also its `id` column in the CSV).
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// What kind of object an entity is (XSD `EntityObject` choice).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EntityKind {
    /// `Vehicle`.
    Vehicle,
    /// `Pedestrian`.
    Pedestrian,
    /// `MiscObject`.
    MiscObject,
    /// `ExternalObjectReference`: an object of the road network file.
    External,
}

impl EntityKind {
    /// The XSD `ObjectType` of this kind.
    pub fn object_type(self) -> ObjectType {
        match self {
            EntityKind::Vehicle => ObjectType::Vehicle,
            EntityKind::Pedestrian => ObjectType::Pedestrian,
            EntityKind::MiscObject => ObjectType::Miscellaneous,
            EntityKind::External => ObjectType::External,
        }
    }
}

/// Visibility flags of VisibilityAction (OpenSCENARIO 1.3 §7.7.2.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Visibility {
    /// Visible in image generators.
    pub graphics: bool,
    /// Visible to sensors.
    pub sensors: bool,
    /// Visible to other traffic participants.
    pub traffic: bool,
}

impl Default for Visibility {
    fn default() -> Self {
        Visibility {
            graphics: true,
            sensors: true,
            traffic: true,
        }
    }
}

/// One entity: static description and the state of the current step. What the default
/// controller keeps between steps (the lane it follows, the route it drives, the actions that
/// hold each control domain) is crate-private; library users read entities as
/// [`EntityState`](crate::EntityState) values or in frames.
#[derive(Debug, Clone)]
pub struct Entity {
    /// Handle.
    pub id: EntityId,
    /// `ScenarioObject/@name`.
    pub name: String,
    /// Kind.
    pub kind: EntityKind,
    /// Bounding box, centre relative to the reference point.
    pub bounding_box: BoundingBox,
    /// Vehicle category (vehicles only).
    pub vehicle_category: Option<VehicleCategory>,
    /// Pedestrian category (pedestrians declared in the scenario only).
    pub pedestrian_category: Option<PedestrianCategory>,
    /// Misc object category (misc objects only).
    pub misc_object_category: Option<MiscObjectCategory>,
    /// Role in traffic (`role` of a Vehicle or Pedestrian, OpenSCENARIO 1.2+; spawned
    /// vehicles: drawn from the VehicleRoleDistribution, traffic/spawn.rs).
    pub role: Option<scenario::Role>,
    /// Performance limits (vehicles only).
    pub performance: Option<Performance>,
    /// Colour, from a `Property name="color"` when one names a §8.7.11 colour.
    pub color: Option<Color>,
    /// The largest curvature a vehicle can drive (1/m), from its axles (trajectory::max_curvature).
    pub max_curvature: Option<Real>,
    /// Axles (vehicles only): the wheelbase and steering of the `vehicle_dynamics` model.
    pub axles: Option<scenario::Axles>,
    /// `mass` (kg, vehicles of 1.2+).
    pub mass: Option<Real>,
    /// `model3d`, as written.
    pub model3d: Option<String>,
    /// True once a TeleportAction (or AddEntityAction) placed the entity.
    pub placed: bool,
    /// True once the entity has left the scenario (DeleteEntityAction, a traffic sink); while
    /// it is not placed, `pose` is where it left.
    pub departed: bool,
    /// Pose of the reference point in world coordinates.
    pub pose: Pose,
    /// Road position of the reference point (`RoadNetwork::locate` of the pose), if on a road.
    pub road_position: Option<RoadPosition>,
    /// The lane the default controller follows; `None` moves the entity straight along its
    /// heading.
    pub(crate) track: Option<LaneTrack>,
    /// Signed longitudinal speed (m/s).
    pub speed: Real,
    /// Velocity in the entity's axes (x forward, y left, z up).
    pub velocity: Velocity6d,
    /// Acceleration in the entity's axes.
    pub acceleration: Acceleration6d,
    /// Distance travelled since the start (m).
    pub odometer: Real,
    /// Visibility flags.
    pub visibility: Visibility,
    /// The state LightStateAction last gave each light (actions/appearance.rs).
    pub lights: BTreeMap<String, LightState>,
    /// Route assigned by AssignRouteAction.
    pub route: Option<Route>,
    /// The planned route the default controller follows, with the entity's progress along it
    /// (AssignRouteAction, AcquirePositionAction; controller/route.rs).
    pub(crate) route_follow: Option<super::route_follow::RouteFollow>,
    /// The action controlling the longitudinal domain, if any (§7.5.1 control domains).
    pub(crate) longitudinal_action: Option<ActionId>,
    /// The action controlling the lateral domain, if any.
    pub(crate) lateral_action: Option<ActionId>,
    /// The last step could not move the entity: its lane ends with no successor.
    pub(crate) at_lane_end: bool,
    /// The running lateral action comes before the running longitudinal one in the storyboard
    /// (or there is none): the lateral motion of this step uses the speed of the step's start.
    pub(crate) lateral_first: bool,
    /// Speed at the start of the step, before stage 2 (m/s).
    pub(crate) start_speed: Real,
    /// The pose was set by an action for this step (FollowTrajectoryAction): the controller
    /// takes measurements without moving the entity.
    pub(crate) held: bool,
    /// Lateral speed of the running lateral transition as a share of the speed (m of lateral
    /// motion per m travelled), at the end of the last step.
    pub(crate) lateral_slope: Real,
    /// The trailer this vehicle tows now (§7.2.2.6; store/trailer.rs keeps it).
    pub trailer: Option<EntityId>,
    /// Driver inputs overridden by OverrideControllerValueAction (§7.7.2.5), recorded only.
    pub overrides: ControllerOverrides,
}

impl Entity {
    /// A new, unplaced entity at the origin, at rest.
    pub fn new(id: EntityId, name: &str, kind: EntityKind, bounding_box: BoundingBox) -> Self {
        Entity {
            id,
            name: name.to_owned(),
            kind,
            bounding_box,
            vehicle_category: None,
            pedestrian_category: None,
            misc_object_category: None,
            role: None,
            performance: None,
            color: None,
            model3d: None,
            placed: false,
            departed: false,
            pose: Pose::default(),
            max_curvature: None,
            axles: None,
            mass: None,
            road_position: None,
            track: None,
            speed: 0.0,
            velocity: Velocity6d::ZERO,
            acceleration: Acceleration6d::ZERO,
            odometer: 0.0,
            visibility: Visibility::default(),
            lights: BTreeMap::new(),
            route: None,
            route_follow: None,
            longitudinal_action: None,
            lateral_action: None,
            lateral_slope: 0.0,
            held: false,
            start_speed: 0.0,
            at_lane_end: false,
            lateral_first: false,
            trailer: None,
            overrides: ControllerOverrides::default(),
        }
    }

    /// Translational velocity in the entity's axes (x forward, y left) of travel at its speed:
    /// along the heading, or, on a lane track whose heading is turned by `relative_heading`
    /// from the direction of travel, along the lane: speed·(cos rel, −sin rel, 0).
    pub fn travel_velocity(&self) -> Vector3 {
        self.along_travel(self.speed)
    }

    /// The vector of length `value` along the direction of travel, in the entity's axes (see
    /// [`Entity::travel_velocity`]).
    pub fn along_travel(&self, value: Real) -> Vector3 {
        along(value, self.travel_cos_sin())
    }

    /// Component of `v` (entity axes) along the direction of travel.
    pub fn travel_component(&self, v: Vector3) -> Real {
        component_along(v, self.travel_cos_sin())
    }

    /// Cosine and sine of the heading relative to the direction of travel; for the common 0
    /// (±0) without calling them, with the same values (cos ±0 = 1, sin ±0 = ±0). A caller
    /// that asks several times while neither the track nor its relative heading changes (the
    /// default controller's move, controller/default.rs) asks once and passes them to
    /// [`along`] and [`component_along`].
    #[inline]
    pub(crate) fn travel_cos_sin(&self) -> (Real, Real) {
        let rel = self.track.as_ref().map_or(0.0, |t| t.relative_heading);
        if rel == 0.0 {
            (1.0, rel)
        } else {
            (rel.cos(), rel.sin())
        }
    }

    /// Maximum speed (m/s): the performance limit, unlimited for non-vehicles.
    pub fn max_speed(&self) -> Real {
        self.performance.map_or(Real::INFINITY, |p| p.max_speed)
    }
}

/// The vector of length `value` along the direction of travel whose cosine and sine
/// ([`Entity::travel_cos_sin`]) are `(cos, sin)`, in the entity's axes: [`Entity::along_travel`].
#[inline]
pub(crate) fn along(value: Real, (cos, sin): (Real, Real)) -> Vector3 {
    Vector3::new(value * cos, -value * sin, 0.0)
}

/// Component of `v` (entity axes) along the direction of travel whose cosine and sine are
/// `(cos, sin)`: [`Entity::travel_component`].
#[inline]
pub(crate) fn component_along(v: Vector3, (cos, sin): (Real, Real)) -> Real {
    v.x * cos - v.y * sin
}
