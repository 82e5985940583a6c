//! Entity states as plain C values: [`OscsimEntityState`] for each entity in the scene after a
//! step (OpenSCENARIO 1.3 §7.2.2 entities; world coordinates of §6.3; road coordinates of
//! ASAM OpenDRIVE 1.8), copied from the engine's frame of that step, with the names and road
//! ids as C strings that live until the next step.

use std::ffi::CString;

use engine::output::{EntityFrame, Frame, FrameSink};
use engine::runtime::EntityKind;

/// What an entity is (OpenSCENARIO 1.3 `EntityObject`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OscsimEntityKind {
    /// `Vehicle`.
    Vehicle = 0,
    /// `Pedestrian`.
    Pedestrian = 1,
    /// `MiscObject`.
    MiscObject = 2,
    /// `ExternalObjectReference`.
    External = 3,
}

/// The state of one entity at the time of the latest step.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OscsimEntityState {
    /// Index in declaration order (spawned entities after): the `id` column of the trajectory
    /// CSV. Stable through the run.
    pub id: u32,
    /// What the entity is.
    pub kind: OscsimEntityKind,
    /// Reference point (a vehicle's rear-axle centre on the ground), world x (m).
    pub x: f64,
    /// World y (m).
    pub y: f64,
    /// World z (m).
    pub z: f64,
    /// Heading (rad, counter-clockwise from +x).
    pub h: f64,
    /// Pitch (rad).
    pub p: f64,
    /// Roll (rad).
    pub r: f64,
    /// Signed longitudinal speed (m/s).
    pub speed: f64,
    /// Velocity of the reference point, world x (m/s).
    pub vx: f64,
    /// World y (m/s).
    pub vy: f64,
    /// World z (m/s).
    pub vz: f64,
    /// Acceleration of the reference point, world x (m/s²).
    pub ax: f64,
    /// World y (m/s²).
    pub ay: f64,
    /// World z (m/s²).
    pub az: f64,
    /// Yaw rate (rad/s, counter-clockwise).
    pub yaw_rate: f64,
    /// 1 when the reference point is on a road (then `lane_id`, `s`, `t`, `offset` and the
    /// road id are set), else 0.
    pub on_road: i32,
    /// Lane id (negative right of the reference line); 0 off the roads.
    pub lane_id: i32,
    /// s along the road's reference line (m); NaN off the roads.
    pub s: f64,
    /// t from the reference line (m, positive left); NaN off the roads.
    pub t: f64,
    /// Offset from the lane centre (m, positive left); NaN off the roads.
    pub offset: f64,
    /// Bounding-box centre relative to the reference point, entity x axis (m).
    pub bbox_center_x: f64,
    /// Entity y axis (m).
    pub bbox_center_y: f64,
    /// Entity z axis (m).
    pub bbox_center_z: f64,
    /// Bounding-box length (m).
    pub length: f64,
    /// Bounding-box width (m).
    pub width: f64,
    /// Bounding-box height (m).
    pub height: f64,
}

impl From<&EntityFrame<'_>> for OscsimEntityState {
    fn from(e: &EntityFrame<'_>) -> Self {
        let kind = match e.kind {
            EntityKind::Vehicle => OscsimEntityKind::Vehicle,
            EntityKind::Pedestrian => OscsimEntityKind::Pedestrian,
            EntityKind::MiscObject => OscsimEntityKind::MiscObject,
            _ => OscsimEntityKind::External,
        };
        let (on_road, lane_id, s, t, offset) = match e.road_position {
            Some(rp) => (1, rp.lane_id, rp.s, rp.t, rp.offset),
            None => (0, 0, f64::NAN, f64::NAN, f64::NAN),
        };
        let (p, b) = (e.pose, &e.bounding_box);
        let c = b.center();
        OscsimEntityState {
            id: e.id,
            kind,
            x: p.x,
            y: p.y,
            z: p.z,
            h: p.h,
            p: p.p,
            r: p.r,
            speed: e.speed,
            vx: e.velocity.x,
            vy: e.velocity.y,
            vz: e.velocity.z,
            ax: e.acceleration.x,
            ay: e.acceleration.y,
            az: e.acceleration.z,
            yaw_rate: e.yaw_rate,
            on_road,
            lane_id,
            s,
            t,
            offset,
            bbox_center_x: c.x,
            bbox_center_y: c.y,
            bbox_center_z: c.z,
            length: b.length(),
            width: b.width(),
            height: b.height(),
        }
    }
}

/// The entities of the latest frame: states, names and road ids (a frame sink).
#[derive(Debug, Default)]
pub struct Scene {
    /// States in frame order.
    pub states: Vec<OscsimEntityState>,
    /// Names, same order.
    pub names: Vec<CString>,
    /// Road ids, same order (empty off the roads).
    pub road_ids: Vec<CString>,
}

/// `text` as a C string (interior NULs, which OpenSCENARIO names cannot sensibly hold, become
/// spaces).
pub fn c_string(text: &str) -> CString {
    CString::new(text.replace('\0', " ")).unwrap_or_default()
}

impl Scene {
    /// The index of entity `name` in the latest frame.
    pub fn find(&self, name: &str) -> Option<usize> {
        self.names
            .iter()
            .position(|n| n.as_bytes() == name.as_bytes())
    }
}

impl FrameSink for Scene {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        self.states.clear();
        self.names.clear();
        self.road_ids.clear();
        for e in frame.objects() {
            self.states.push(OscsimEntityState::from(&e));
            self.names.push(c_string(e.name));
            let road = e.road_position.map_or("", |rp| rp.road_id.as_str());
            self.road_ids.push(c_string(road));
        }
        Ok(())
    }
}
