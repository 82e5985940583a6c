//! `oscsim.Entity`: the state of one entity at one simulation time (a snapshot; it does not
//! change when the simulation steps on), with the OpenSCENARIO 2.0 §8.7 measurement methods
//! of physical objects: `object_distance` (§8.7.2.1.1), `get_s_coord`, `get_t_coord`,
//! `get_route_point` (§8.7.2.1.2–8.7.2.1.4), `distance_along_route` (§8.7.4.1.1),
//! `time_to_collision`, `time_headway`, `space_gap` (§8.7.5.1.1–8.7.5.1.3). The methods are
//! the engine's (`engine::domain`); this module only builds their arguments and names the
//! enums by the standard's values.

use std::sync::Arc;

use engine::domain::{
    Acceleration6d, DistanceDirection, DistanceMode, MovableObject, OnRouteType, PhysicalObject,
    Route, RouteDistanceEnum, RouteElement, RouteStretch, TrafficParticipant, Vector3 as Vector3d,
    Vehicle, VehicleCategory, Velocity6d,
};
use engine::runtime::EntityKind;
use pyo3::create_exception;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::error::{guard, OscsimError};
use crate::state::{BoundingBox, Pose, RoadPosition, Vector3};

create_exception!(
    oscsim,
    DomainError,
    OscsimError,
    "A §8.7 method has no answer for these objects: off the roads, not on the route, roads \
     not joined. The message names the case and the point."
);

/// A route stretch as Python gives it: `(road_id, s_start, s_end, lane_id or None)`.
type Stretch = (String, f64, f64, Option<i32>);

/// The state of one entity at one simulation time.
#[pyclass(frozen, module = "oscsim")]
pub struct Entity {
    pub(crate) state: engine::EntityState,
    pub(crate) time: f64,
    pub(crate) network: Arc<opendrive::RoadNetwork>,
}

impl Entity {
    fn physical(&self) -> PhysicalObject {
        PhysicalObject::new(self.state.bounding_box, self.state.pose)
    }

    /// `v` (world axes, as the snapshot gives velocity and acceleration) in the entity's own
    /// axes, as §8.7.4 defines them: the inverse of the snapshot's rotation by the heading.
    fn local(&self, v: Vector3d) -> Vector3d {
        let (c, s) = (self.state.pose.h.cos(), self.state.pose.h.sin());
        Vector3d::new(c * v.x + s * v.y, -s * v.x + c * v.y, v.z)
    }

    fn participant(&self) -> TrafficParticipant {
        let mut movable = MovableObject::new(self.physical());
        movable.velocity = Velocity6d {
            translational: self.local(self.state.velocity),
            rotational: Vector3d::new(0.0, 0.0, self.state.yaw_rate),
        };
        movable.acceleration = Acceleration6d {
            translational: self.local(self.state.acceleration),
            rotational: Vector3d::ZERO,
        };
        TrafficParticipant::new(movable, Vec::new())
    }
}

fn domain_error(e: engine::domain::DomainError) -> PyErr {
    DomainError::new_err(e.to_string())
}

fn direction(text: &str) -> PyResult<DistanceDirection> {
    match text {
        "longitudinal" => Ok(DistanceDirection::Longitudinal),
        "lateral" => Ok(DistanceDirection::Lateral),
        _ => Err(PyValueError::new_err(format!(
            "expected a distance_direction (longitudinal, lateral), found {text:?}"
        ))),
    }
}

fn mode(text: &str) -> PyResult<DistanceMode> {
    match text {
        "reference_points" => Ok(DistanceMode::ReferencePoints),
        "bounding_boxes" => Ok(DistanceMode::BoundingBoxes),
        _ => Err(PyValueError::new_err(format!(
            "expected a distance_mode (reference_points, bounding_boxes), found {text:?}"
        ))),
    }
}

fn route_type(text: &str) -> PyResult<OnRouteType> {
    match text {
        "on_road" => Ok(OnRouteType::OnRoad),
        "on_lane_section" => Ok(OnRouteType::OnLaneSection),
        "on_lane" => Ok(OnRouteType::OnLane),
        "on_crossing" => Ok(OnRouteType::OnCrossing),
        _ => Err(PyValueError::new_err(format!(
            "expected an on_route_type (on_road, on_lane_section, on_lane, on_crossing), \
             found {text:?}"
        ))),
    }
}

fn route_distance(text: &str) -> PyResult<RouteDistanceEnum> {
    match text {
        "from_start" => Ok(RouteDistanceEnum::FromStart),
        "from_end" => Ok(RouteDistanceEnum::FromEnd),
        _ => Err(PyValueError::new_err(format!(
            "expected a route_distance_enum (from_start, from_end), found {text:?}"
        ))),
    }
}

/// A point on a route element (§8.7.2.1.4 route_point): the element and s, t in its system.
#[pyclass(frozen, module = "oscsim")]
pub struct RoutePoint {
    /// `road`, `lane_section`, `lane` or `crossing`.
    #[pyo3(get)]
    kind: &'static str,
    /// The road (for a crossing: the junction's connecting road).
    #[pyo3(get)]
    road_id: String,
    /// Index of the lane section in the road (lane_section and lane).
    #[pyo3(get)]
    lane_section: Option<usize>,
    /// The lane (lane).
    #[pyo3(get)]
    lane_id: Option<i32>,
    /// The junction (crossing).
    #[pyo3(get)]
    junction_id: Option<String>,
    /// s in the element's system (m).
    #[pyo3(get)]
    s: f64,
    /// t in the element's system (m, positive left).
    #[pyo3(get)]
    t: f64,
}

#[pymethods]
impl RoutePoint {
    fn __repr__(&self) -> String {
        let none = |v: Option<String>| v.unwrap_or_else(|| "None".to_owned());
        format!(
            "RoutePoint(kind={:?}, road_id={:?}, lane_section={}, lane_id={}, s={}, t={})",
            self.kind,
            self.road_id,
            none(self.lane_section.map(|v| v.to_string())),
            none(self.lane_id.map(|v| v.to_string())),
            self.s,
            self.t
        )
    }
}

impl From<engine::domain::RoutePoint> for RoutePoint {
    fn from(p: engine::domain::RoutePoint) -> Self {
        let (kind, road_id, lane_section, lane_id, junction_id) = match p.element {
            RouteElement::Road { road_id } => ("road", road_id, None, None, None),
            RouteElement::LaneSection { road_id, index } => {
                ("lane_section", road_id, Some(index), None, None)
            }
            RouteElement::Lane {
                road_id,
                lane_section,
                lane_id,
            } => ("lane", road_id, Some(lane_section), Some(lane_id), None),
            RouteElement::Crossing {
                junction_id,
                road_id,
            } => ("crossing", road_id, None, None, Some(junction_id)),
        };
        RoutePoint {
            kind,
            road_id,
            lane_section,
            lane_id,
            junction_id,
            s: p.s,
            t: p.t,
        }
    }
}

#[pymethods]
impl Entity {
    /// `ScenarioObject/@name`.
    #[getter]
    fn name(&self) -> &str {
        &self.state.name
    }

    /// Index in declaration order (the `id` column of the trajectory CSV, the OSI object id).
    #[getter]
    fn id(&self) -> u32 {
        self.state.id.0
    }

    /// `vehicle`, `pedestrian`, `misc_object` or `external`.
    #[getter]
    fn kind(&self) -> &'static str {
        match self.state.kind {
            EntityKind::Vehicle => "vehicle",
            EntityKind::Pedestrian => "pedestrian",
            EntityKind::MiscObject => "misc_object",
            _ => "external",
        }
    }

    /// The vehicle category as the scenario writes it (`car`, `truck`, …), None for
    /// non-vehicles.
    #[getter]
    fn vehicle_category(&self) -> Option<&'static str> {
        self.state.vehicle_category.map(|c| c.as_str())
    }

    /// The traffic role as the scenario writes it (`Vehicle/@role`, `Pedestrian/@role`, or drawn
    /// from a TrafficDefinition's VehicleRoleDistribution: `civil`, `police`, `ambulance`, …),
    /// None when none is given.
    #[getter]
    fn role(&self) -> Option<&'static str> {
        self.state.role.map(|r| r.as_str())
    }

    /// Simulation time of this state (s).
    #[getter]
    fn time(&self) -> f64 {
        self.time
    }

    /// Pose of the reference point (rear-axle centre on the ground for vehicles), world
    /// coordinates.
    #[getter]
    fn pose(&self) -> Pose {
        self.state.pose.into()
    }

    /// Signed longitudinal speed (m/s).
    #[getter]
    fn speed(&self) -> f64 {
        self.state.speed
    }

    /// Translational velocity in the entity's own axes (x forward, y left, z up; m/s), as
    /// §8.7.4 defines `velocity`.
    #[getter]
    fn velocity(&self) -> Vector3 {
        self.local(self.state.velocity).into()
    }

    /// Translational acceleration in the entity's own axes (m/s²), §8.7.4 `acceleration`.
    #[getter]
    fn acceleration(&self) -> Vector3 {
        self.local(self.state.acceleration).into()
    }

    /// Yaw rate (rad/s, positive counter-clockwise).
    #[getter]
    fn yaw_rate(&self) -> f64 {
        self.state.yaw_rate
    }

    /// Distance travelled since the start (m).
    #[getter]
    fn odometer(&self) -> f64 {
        self.state.odometer
    }

    /// Road and lane of the reference point, None off the roads.
    #[getter]
    fn road_position(&self) -> Option<RoadPosition> {
        self.state.road_position.as_ref().map(RoadPosition::from)
    }

    /// The bounding box.
    #[getter]
    fn bounding_box(&self) -> BoundingBox {
        (&self.state.bounding_box).into()
    }

    /// §8.7.2.1.1 `object_distance(reference, direction, mode)`: the distance to `reference`
    /// along this entity's x axis (`longitudinal`) or y axis (`lateral`), between the
    /// reference points (`reference_points`, the standard's default) or the bounding boxes
    /// (`bounding_boxes`; 0 when they overlap on that axis); positive when `reference` is
    /// ahead / to the left (m).
    #[pyo3(signature = (reference, direction = "longitudinal", mode = "reference_points"))]
    fn object_distance(&self, reference: &Entity, direction: &str, mode: &str) -> PyResult<f64> {
        let (d, m) = (self::direction(direction)?, self::mode(mode)?);
        guard(|| Ok(self.physical().object_distance(&reference.physical(), d, m)))
    }

    /// §8.7.2.1.2 `get_s_coord(route_type)`: s of the reference point in the system of the
    /// route element of `route_type` (`on_road`, `on_lane_section`, `on_lane`, `on_crossing`)
    /// it stands on (m). Raises `DomainError` when it is on no such element.
    #[pyo3(signature = (route_type = "on_road"))]
    fn get_s_coord(&self, route_type: &str) -> PyResult<f64> {
        let rt = self::route_type(route_type)?;
        guard(|| {
            let object = self.physical();
            object.get_s_coord(&self.network, rt).map_err(domain_error)
        })
    }

    /// §8.7.2.1.3 `get_t_coord(route_type)`: t likewise (m, positive left).
    #[pyo3(signature = (route_type = "on_road"))]
    fn get_t_coord(&self, route_type: &str) -> PyResult<f64> {
        let rt = self::route_type(route_type)?;
        guard(|| {
            let object = self.physical();
            object.get_t_coord(&self.network, rt).map_err(domain_error)
        })
    }

    /// §8.7.2.1.4 `get_route_point(route_type)`: the route element and s, t.
    #[pyo3(signature = (route_type = "on_road"))]
    fn get_route_point(&self, route_type: &str) -> PyResult<RoutePoint> {
        let rt = self::route_type(route_type)?;
        guard(|| {
            let object = self.physical();
            let point = object.get_route_point(&self.network, rt);
            point.map(RoutePoint::from).map_err(domain_error)
        })
    }

    /// §8.7.4.1.1 `distance_along_route(route, from)`: the distance along `route` from its
    /// start (`from_start`, the default) or to its end (`from_end`) (m). `route` is a list of
    /// stretches `(road_id, s_start, s_end, lane_id)` (`lane_id` None: the whole road) in travel
    /// order (`s_end < s_start` runs towards −s). Raises `DomainError` when the entity is not
    /// on it.
    #[pyo3(signature = (route, from_ = "from_start"))]
    fn distance_along_route(&self, route: Vec<Stretch>, from_: &str) -> PyResult<f64> {
        let from = route_distance(from_)?;
        guard(|| {
            let stretches = route
                .into_iter()
                .map(|(road_id, s_start, s_end, lane_id)| RouteStretch {
                    road_id,
                    lane_id,
                    s_start,
                    s_end,
                })
                .collect();
            let route = Route::new(&self.network, stretches).map_err(domain_error)?;
            let participant = self.participant();
            (participant.distance_along_route(&self.network, &route, from)).map_err(domain_error)
        })
    }

    /// §8.7.5.1.1 `time_to_collision(reference)`: the time until this entity's bounding box
    /// touches `reference`'s, both keeping their current velocities (s); 0 when they overlap,
    /// None when they never touch.
    fn time_to_collision(&self, reference: &Entity) -> PyResult<Option<f64>> {
        guard(|| {
            Ok(self
                .participant()
                .time_to_collision(&reference.participant()))
        })
    }

    /// §8.7.5.1.2 `time_headway(reference)` (a vehicle method): the distance along s from this
    /// vehicle's reference point to `reference`'s, in its direction of travel, divided by its
    /// speed (s); negative when `reference` is behind, None at rest. Raises `TypeError` for
    /// non-vehicles, `DomainError` off the roads or on roads not joined.
    fn time_headway(&self, reference: &Entity) -> PyResult<Option<f64>> {
        let Some(category) = self.state.vehicle_category else {
            return Err(PyTypeError::new_err(format!(
                "time_headway is a method of vehicles (§8.7.5.1.2); '{}' is a {}",
                self.state.name,
                self.kind()
            )));
        };
        guard(|| {
            let category = VehicleCategory::from_scenario(category);
            let vehicle =
                Vehicle::new(self.participant(), category, Vec::new()).map_err(domain_error)?;
            (vehicle.time_headway(&self.network, &reference.participant())).map_err(domain_error)
        })
    }

    /// §8.7.5.1.3 `space_gap(reference, direction)`: the gap between the bounding boxes along
    /// the road (`longitudinal`, in s) or across it (`lateral`, in t) (m), signed as the
    /// engine signs it: positive when this entity is ahead of (left of) `reference`, negative
    /// when behind (right); overlapping boxes give the overlap with that sign.
    #[pyo3(signature = (reference, direction = "longitudinal"))]
    fn space_gap(&self, reference: &Entity, direction: &str) -> PyResult<f64> {
        let d = self::direction(direction)?;
        guard(|| {
            let participant = self.participant();
            (participant.space_gap(&self.network, &reference.participant(), d))
                .map_err(domain_error)
        })
    }

    fn __repr__(&self) -> String {
        let p = self.state.pose;
        format!(
            "Entity(name={:?}, time={}, x={}, y={}, h={}, speed={})",
            self.state.name, self.time, p.x, p.y, p.h, self.state.speed
        )
    }
}
