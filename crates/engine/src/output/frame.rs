//! The per-step snapshot of every entity and the seam that receives it.
//!
//! A [`Frame`] borrows the world's entity store: nothing is copied per step. An
//! [`EntityFrame`] carries what an OSI GroundTruth needs (ASAM OSI 3.x `MovingObject` /
//! `StationaryObject`): name, kind, the pose of the reference point (OpenSCENARIO: rear-axle
//! centre on the ground; OSI's base.position is the bounding-box centre, the box centre is given
//! relative to the reference point so the OSI side can convert), bounding box, velocity,
//! acceleration, yaw rate, road and lane position, vehicle, pedestrian or misc-object category,
//! colour, model3d, the VisibilityAction flags, the LightStateAction light states and the towed
//! trailer; the frame names the scenario and road files ([`ScenarioSource`]) and carries the
//! environment in force ([`crate::EnvironmentState`]).

use std::collections::BTreeMap;

use opendrive::{Pose, Real, RoadPosition};
use scenario::{LightState, MiscObjectCategory, PedestrianCategory, Role, VehicleCategory};

use super::SinkError;
use crate::domain::{BoundingBox, Color, Vector3};
use crate::snapshot::{EntityState, ScenarioSource};
use crate::world::{ControllerOverrides, Entity, EntityId, EntityKind, Visibility};

/// The state of every entity at one simulation time.
#[derive(Debug, Clone, Copy)]
pub struct Frame<'a> {
    /// Simulation time (s).
    pub time: f64,
    /// Index of the step that produced the frame (the initial frame is 0).
    pub step: u64,
    /// The entities in declaration order: the world's store, read through [`Frame::objects`]
    /// and [`Frame::entity`] (views, so the store's layout stays the engine's).
    pub(crate) entities: &'a [Entity],
    /// Traffic signal controllers' phases and signal states (crate::signals).
    pub signals: &'a crate::world::SignalStates,
    /// The environment in force (EnvironmentAction: time of day, weather, road condition).
    pub environment: &'a crate::world::EnvironmentState,
    /// The scenario and road files of the run (for source references).
    pub source: &'a ScenarioSource,
}

impl<'a> Frame<'a> {
    /// The snapshot of each placed entity, in declaration order.
    pub fn objects(&self) -> impl Iterator<Item = EntityFrame<'a>> + 'a {
        self.entities
            .iter()
            .filter(|e| e.placed)
            .map(EntityFrame::of)
    }

    /// The snapshot of the entity with index `id` ([`EntityFrame::id`], e.g. a trailer's),
    /// placed or not; `None` for an index no entity has.
    pub fn entity(&self, id: u32) -> Option<EntityFrame<'a>> {
        let i = usize::try_from(id).ok()?;
        self.entities.get(i).map(EntityFrame::of)
    }
}

/// One entity in a frame.
#[derive(Debug, Clone, Copy)]
pub struct EntityFrame<'a> {
    /// Index in declaration order (stable through the run).
    pub id: u32,
    /// Name.
    pub name: &'a str,
    /// Vehicle, pedestrian, misc object or external object.
    pub kind: EntityKind,
    /// Pose of the reference point (world frame).
    pub pose: Pose,
    /// Bounding box, centre relative to the reference point.
    pub bounding_box: BoundingBox,
    /// Velocity in world axes (m/s).
    pub velocity: Vector3,
    /// Acceleration in world axes (m/s²).
    pub acceleration: Vector3,
    /// Yaw rate (rad/s).
    pub yaw_rate: Real,
    /// Signed speed (m/s).
    pub speed: Real,
    /// Distance travelled since the start (m).
    pub odometer: Real,
    /// Road and lane position, if on a road.
    pub road_position: Option<&'a RoadPosition>,
    /// Vehicle category (vehicles only).
    pub vehicle_category: Option<VehicleCategory>,
    /// Pedestrian category (pedestrians declared in the scenario only).
    pub pedestrian_category: Option<PedestrianCategory>,
    /// Misc object category (misc objects only).
    pub misc_object_category: Option<MiscObjectCategory>,
    /// Role in traffic (vehicles and pedestrians with a `role`, spawned vehicles with a drawn
    /// one).
    pub role: Option<Role>,
    /// Colour, if known.
    pub color: Option<Color>,
    /// `model3d`, if given.
    pub model3d: Option<&'a str>,
    /// Seen by image generators, sensors and other traffic (VisibilityAction, OpenSCENARIO
    /// 1.3 XSD `VisibilityAction`; all true unless an action changed them).
    pub visibility: Visibility,
    /// The state LightStateAction last gave each light, by light: an XSD `VehicleLightType`
    /// (e.g. `lowBeam`) or a user-defined light's type. Lights no action touched are absent.
    pub lights: &'a BTreeMap<String, LightState>,
    /// Id of the trailer this vehicle tows (OSI `vehicle_classification.trailer_id`); the
    /// trailer's snapshot is [`Frame::entity`]`(id)`.
    pub trailer: Option<u32>,
    /// Driver inputs overridden by OverrideControllerValueAction (OpenSCENARIO 1.3 §7.7.2.5).
    pub overrides: &'a ControllerOverrides,
}

impl<'a> EntityFrame<'a> {
    /// The snapshot of `e`.
    pub(crate) fn of(e: &'a Entity) -> Self {
        let (c, s) = (e.pose.h.cos(), e.pose.h.sin());
        let to_world = |v: Vector3| Vector3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z);
        EntityFrame {
            id: e.id.0,
            name: &e.name,
            kind: e.kind,
            pose: e.pose,
            bounding_box: e.bounding_box,
            velocity: to_world(e.velocity.translational),
            acceleration: to_world(e.acceleration.translational),
            yaw_rate: e.velocity.rotational.z,
            speed: e.speed,
            odometer: e.odometer,
            road_position: e.road_position.as_ref(),
            vehicle_category: e.vehicle_category,
            pedestrian_category: e.pedestrian_category,
            misc_object_category: e.misc_object_category,
            role: e.role,
            color: e.color,
            model3d: e.model3d.as_deref(),
            visibility: e.visibility,
            lights: &e.lights,
            trailer: e.trailer.map(|t| t.0),
            overrides: &e.overrides,
        }
    }

    /// The same state as owned values, e.g. to keep it past the step.
    pub fn to_state(&self) -> EntityState {
        EntityState {
            id: EntityId(self.id),
            name: self.name.to_owned(),
            kind: self.kind,
            pose: self.pose,
            bounding_box: self.bounding_box,
            velocity: self.velocity,
            acceleration: self.acceleration,
            yaw_rate: self.yaw_rate,
            speed: self.speed,
            odometer: self.odometer,
            road_position: self.road_position.cloned(),
            vehicle_category: self.vehicle_category,
            pedestrian_category: self.pedestrian_category,
            misc_object_category: self.misc_object_category,
            role: self.role,
            color: self.color,
            model3d: self.model3d.map(str::to_owned),
            visibility: self.visibility,
            lights: self.lights.clone(),
            trailer: self.trailer.map(EntityId),
            overrides: self.overrides.clone(),
        }
    }
}

/// Receives one frame per step (the initial state, then after each step's movement).
pub trait FrameSink {
    /// Takes a frame. An error ends the run.
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError>;

    /// Called once after the last frame (flush files, close streams).
    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }
}

/// Discards frames.
impl FrameSink for () {
    fn frame(&mut self, _frame: &Frame<'_>) -> Result<(), SinkError> {
        Ok(())
    }
}

/// Feeds every sink of the list, in order.
impl FrameSink for Vec<Box<dyn FrameSink>> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        self.iter_mut().try_for_each(|s| s.frame(frame))
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.iter_mut().try_for_each(|s| s.finish())
    }
}

/// Feeds the sink if there is one.
impl<S: FrameSink> FrameSink for Option<S> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        self.as_mut().map_or(Ok(()), |s| s.frame(frame))
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.as_mut().map_or(Ok(()), FrameSink::finish)
    }
}

/// Feeds both sinks, the first first.
impl<A: FrameSink, B: FrameSink> FrameSink for (A, B) {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        self.0.frame(frame)?;
        self.1.frame(frame)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.0.finish()?;
        self.1.finish()
    }
}
