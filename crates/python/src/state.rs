//! Plain value classes of entity state, all immutable: `Pose` (OpenSCENARIO 1.3 §6.3 world
//! coordinates: x, y, z, heading, pitch, roll of the reference point), `Vector3`,
//! `RoadPosition` (OpenDRIVE road, lane, s, t) and `BoundingBox` (§8.7.9).

use pyo3::prelude::*;

/// Position and orientation of an entity's reference point in world coordinates (m, rad).
#[pyclass(frozen, eq, module = "oscsim")]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// x (m).
    #[pyo3(get)]
    pub x: f64,
    /// y (m).
    #[pyo3(get)]
    pub y: f64,
    /// z (m).
    #[pyo3(get)]
    pub z: f64,
    /// Heading (rad, counter-clockwise from +x).
    #[pyo3(get)]
    pub h: f64,
    /// Pitch (rad).
    #[pyo3(get)]
    pub p: f64,
    /// Roll (rad).
    #[pyo3(get)]
    pub r: f64,
}

#[pymethods]
impl Pose {
    #[new]
    #[pyo3(signature = (x, y, z = 0.0, h = 0.0, p = 0.0, r = 0.0))]
    fn new(x: f64, y: f64, z: f64, h: f64, p: f64, r: f64) -> Self {
        Pose { x, y, z, h, p, r }
    }

    /// (x, y, z, h, p, r).
    fn as_tuple(&self) -> (f64, f64, f64, f64, f64, f64) {
        (self.x, self.y, self.z, self.h, self.p, self.r)
    }

    fn __repr__(&self) -> String {
        format!(
            "Pose(x={}, y={}, z={}, h={}, p={}, r={})",
            self.x, self.y, self.z, self.h, self.p, self.r
        )
    }
}

impl From<opendrive::Pose> for Pose {
    fn from(p: opendrive::Pose) -> Self {
        Pose {
            x: p.x,
            y: p.y,
            z: p.z,
            h: p.h,
            p: p.p,
            r: p.r,
        }
    }
}

impl From<Pose> for opendrive::Pose {
    fn from(p: Pose) -> Self {
        opendrive::Pose {
            x: p.x,
            y: p.y,
            z: p.z,
            h: p.h,
            p: p.p,
            r: p.r,
        }
    }
}

/// A 3-vector: a velocity (m/s), an acceleration (m/s²) or a point (m).
#[pyclass(frozen, eq, module = "oscsim")]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vector3 {
    /// x.
    #[pyo3(get)]
    pub x: f64,
    /// y.
    #[pyo3(get)]
    pub y: f64,
    /// z.
    #[pyo3(get)]
    pub z: f64,
}

#[pymethods]
impl Vector3 {
    #[new]
    #[pyo3(signature = (x, y, z = 0.0))]
    fn new(x: f64, y: f64, z: f64) -> Self {
        Vector3 { x, y, z }
    }

    /// (x, y, z).
    fn as_tuple(&self) -> (f64, f64, f64) {
        (self.x, self.y, self.z)
    }

    fn __repr__(&self) -> String {
        format!("Vector3(x={}, y={}, z={})", self.x, self.y, self.z)
    }
}

impl From<engine::domain::Vector3> for Vector3 {
    fn from(v: engine::domain::Vector3) -> Self {
        Vector3 {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    }
}

/// Where an entity's reference point is on the road network (OpenDRIVE 1.8 reference line
/// coordinates and lane).
#[pyclass(frozen, eq, module = "oscsim")]
#[derive(Debug, Clone, PartialEq)]
pub struct RoadPosition {
    /// OpenDRIVE road id.
    #[pyo3(get)]
    pub road_id: String,
    /// Lane id (negative right of the reference line, positive left).
    #[pyo3(get)]
    pub lane_id: i32,
    /// s along the road's reference line (m).
    #[pyo3(get)]
    pub s: f64,
    /// t from the reference line (m, positive left).
    #[pyo3(get)]
    pub t: f64,
    /// Offset from the lane's centre (m, positive left).
    #[pyo3(get)]
    pub offset: f64,
    /// The junction the road belongs to, if it is a connecting road.
    #[pyo3(get)]
    pub junction_id: Option<String>,
}

#[pymethods]
impl RoadPosition {
    fn __repr__(&self) -> String {
        format!(
            "RoadPosition(road_id={:?}, lane_id={}, s={}, t={}, offset={})",
            self.road_id, self.lane_id, self.s, self.t, self.offset
        )
    }
}

impl From<&opendrive::RoadPosition> for RoadPosition {
    fn from(p: &opendrive::RoadPosition) -> Self {
        RoadPosition {
            road_id: p.road_id.clone(),
            lane_id: p.lane_id,
            s: p.s,
            t: p.t,
            offset: p.offset,
            junction_id: p.junction_id.clone(),
        }
    }
}

/// An entity's bounding box (OpenSCENARIO 2.0 §8.7.9): centre relative to the reference point
/// in the entity's axes (m), and its dimensions (m).
#[pyclass(frozen, eq, module = "oscsim")]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingBox {
    /// Centre relative to the reference point (x forward, y left, z up).
    #[pyo3(get)]
    pub center: Vector3,
    /// Length along x.
    #[pyo3(get)]
    pub length: f64,
    /// Width along y.
    #[pyo3(get)]
    pub width: f64,
    /// Height along z.
    #[pyo3(get)]
    pub height: f64,
}

#[pymethods]
impl BoundingBox {
    fn __repr__(&self) -> String {
        format!(
            "BoundingBox(center={}, length={}, width={}, height={})",
            self.center.__repr__(),
            self.length,
            self.width,
            self.height
        )
    }
}

impl From<&engine::domain::BoundingBox> for BoundingBox {
    fn from(b: &engine::domain::BoundingBox) -> Self {
        let c = b.center();
        BoundingBox {
            center: Vector3 {
                x: c.x,
                y: c.y,
                z: c.z,
            },
            length: b.length(),
            width: b.width(),
            height: b.height(),
        }
    }
}
