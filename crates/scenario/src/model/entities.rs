//! Entities (OpenSCENARIO 1.3 §7.2.2 "Entities", XSD `Entities`, `ScenarioObject`, `Vehicle`,
//! `Pedestrian`, `MiscObject`, `ExternalObjectReference`, `EntitySelection`, `Controller`).
//! Lengths in m, mass in kg, speeds in m/s, accelerations in m/s², angles in rad.

use crate::model::{
    CatalogOrigin, ControllerType, MiscObjectCategory, ObjectType, PedestrianCategory, Properties,
    Role, VehicleCategory,
};
use crate::source::SourcePos;

/// The Entities section (XSD `Entities`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Entities {
    /// Scenario objects in declaration order.
    pub scenario_objects: Vec<ScenarioObject>,
    /// Entity selections, with members expanded.
    pub entity_selections: Vec<EntitySelection>,
}

impl Entities {
    /// The scenario object called `name`.
    pub fn object(&self, name: &str) -> Option<&ScenarioObject> {
        self.scenario_objects.iter().find(|o| o.name == name)
    }

    /// The scenario objects `name` stands for: itself if an object, its expanded members if
    /// a selection.
    pub fn resolve<'s>(&'s self, name: &'s str) -> Vec<&'s str> {
        if self.object(name).is_some() {
            return vec![name];
        }
        self.entity_selections
            .iter()
            .find(|s| s.name == name)
            .map(|s| s.objects.iter().map(String::as_str).collect())
            .unwrap_or_default()
    }
}

/// A scenario object (XSD `ScenarioObject`).
#[derive(Debug, Clone, PartialEq)]
pub struct ScenarioObject {
    /// `name`, unique among entities.
    pub name: String,
    /// What it is (XSD group `EntityObject`).
    pub entity_object: EntityObject,
    /// Controllers assigned to it (several from 1.2).
    pub object_controllers: Vec<ObjectController>,
    /// Where the ScenarioObject element starts.
    pub pos: SourcePos,
}

/// The kind of a scenario object (XSD group `EntityObject`; catalog references are resolved).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum EntityObject {
    /// A vehicle.
    Vehicle(Box<Vehicle>),
    /// A pedestrian.
    Pedestrian(Box<Pedestrian>),
    /// A miscellaneous object.
    MiscObject(Box<MiscObject>),
    /// An object of the road network (XSD `ExternalObjectReference`, 1.1+): its name there.
    ExternalObjectReference(String),
}

/// A bounding box (XSD `BoundingBox`): centre relative to the reference point, dimensions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingBox {
    /// Centre x, y, z in the entity's frame, m.
    pub center: [f64; 3],
    /// Width (y), m.
    pub width: f64,
    /// Length (x), m.
    pub length: f64,
    /// Height (z), m.
    pub height: f64,
}

/// A vehicle (XSD `Vehicle`).
#[derive(Debug, Clone, PartialEq)]
pub struct Vehicle {
    /// `name`.
    pub name: String,
    /// `vehicleCategory`.
    pub vehicle_category: VehicleCategory,
    /// `role` (1.2+).
    pub role: Option<Role>,
    /// `mass`, kg (1.2+).
    pub mass: Option<f64>,
    /// `model3d` path as written (1.1+).
    pub model3d: Option<String>,
    /// BoundingBox.
    pub bounding_box: BoundingBox,
    /// Performance.
    pub performance: Performance,
    /// Axles.
    pub axles: Axles,
    /// Properties.
    pub properties: Properties,
    /// TrailerHitch (1.3): where a trailer attaches.
    pub trailer_hitch: Option<TrailerJoint>,
    /// TrailerCoupler (1.3): where this vehicle attaches to a tractor.
    pub trailer_coupler: Option<TrailerJoint>,
    /// Trailer (1.3): the trailer connected at the start.
    pub trailer: Option<Trailer>,
    /// Set when the vehicle came from a catalog.
    pub catalog: Option<CatalogOrigin>,
}

/// Performance limits (XSD `Performance`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Performance {
    /// m/s.
    pub max_speed: f64,
    /// m/s².
    pub max_acceleration: f64,
    /// m/s², positive.
    pub max_deceleration: f64,
    /// m/s³ (1.2+).
    pub max_acceleration_rate: Option<f64>,
    /// m/s³ (1.2+).
    pub max_deceleration_rate: Option<f64>,
}

/// Axles (XSD `Axles`).
#[derive(Debug, Clone, PartialEq)]
pub struct Axles {
    /// FrontAxle (optional from 1.1).
    pub front_axle: Option<Axle>,
    /// RearAxle.
    pub rear_axle: Axle,
    /// AdditionalAxle entries.
    pub additional_axles: Vec<Axle>,
}

/// An axle (XSD `Axle`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axle {
    /// Maximum steering angle, rad.
    pub max_steering: f64,
    /// Wheel diameter, m.
    pub wheel_diameter: f64,
    /// Track width, m.
    pub track_width: f64,
    /// x of the axle in the vehicle frame, m.
    pub position_x: f64,
    /// z of the axle, m.
    pub position_z: f64,
}

/// TrailerHitch or TrailerCoupler (XSD `TrailerHitch`, `TrailerCoupler`): dx, dz in m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrailerJoint {
    /// dx from the reference point, m.
    pub dx: f64,
    /// dz, m.
    pub dz: Option<f64>,
}

/// A vehicle's trailer (XSD `Trailer`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Trailer {
    /// An inline trailer object.
    Trailer(Box<ScenarioObject>),
    /// A reference to another entity (TrailerRef).
    TrailerRef(String),
}

/// A pedestrian (XSD `Pedestrian`).
#[derive(Debug, Clone, PartialEq)]
pub struct Pedestrian {
    /// `name`.
    pub name: String,
    /// `pedestrianCategory`.
    pub pedestrian_category: PedestrianCategory,
    /// `mass`, kg.
    pub mass: f64,
    /// `model3d` (or the deprecated `model`).
    pub model3d: Option<String>,
    /// `role` (1.2+).
    pub role: Option<Role>,
    /// BoundingBox.
    pub bounding_box: BoundingBox,
    /// Properties.
    pub properties: Properties,
    /// Set when it came from a catalog.
    pub catalog: Option<CatalogOrigin>,
}

/// A miscellaneous object (XSD `MiscObject`).
#[derive(Debug, Clone, PartialEq)]
pub struct MiscObject {
    /// `name`.
    pub name: String,
    /// `miscObjectCategory`.
    pub misc_object_category: MiscObjectCategory,
    /// `mass`, kg.
    pub mass: f64,
    /// `model3d`.
    pub model3d: Option<String>,
    /// BoundingBox.
    pub bounding_box: BoundingBox,
    /// Properties.
    pub properties: Properties,
    /// Set when it came from a catalog.
    pub catalog: Option<CatalogOrigin>,
}

/// A controller (XSD `Controller`).
#[derive(Debug, Clone, PartialEq)]
pub struct Controller {
    /// `name`.
    pub name: String,
    /// `controllerType` (1.2+).
    pub controller_type: Option<ControllerType>,
    /// Properties (controller-specific settings).
    pub properties: Properties,
    /// Set when it came from a catalog.
    pub catalog: Option<CatalogOrigin>,
    /// Where the `Controller` element was written (in the catalog file for a catalog entry).
    pub pos: SourcePos,
}

/// A controller assigned to an object (XSD `ObjectController`).
#[derive(Debug, Clone, PartialEq)]
pub struct ObjectController {
    /// `name` (1.3), used by ActivateControllerAction@objectControllerRef.
    pub name: Option<String>,
    /// The controller.
    pub controller: Controller,
}

/// An entity selection (XSD `EntitySelection`).
#[derive(Debug, Clone, PartialEq)]
pub struct EntitySelection {
    /// `name`.
    pub name: String,
    /// Members as written (XSD `SelectedEntities`).
    pub members: Vec<SelectionMember>,
    /// The scenario objects the selection stands for, nested selections and ByType expanded,
    /// each once, in declaration order of the objects.
    pub objects: Vec<String>,
    /// Where the selection starts.
    pub pos: SourcePos,
}

/// A member of an entity selection (XSD `SelectedEntities` choice).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SelectionMember {
    /// EntityRef: an object or another selection.
    EntityRef(String),
    /// ByType: every object of a type.
    ByType(ObjectType),
}
