//! Assembling one ASAM OSI 3.8 `GroundTruth` per output step: the seam the engine feeds.
//!
//! A [`GroundTruthBuilder`] lives for a whole run. It owns the [`IdAllocator`] (so ids are
//! unique across objects, lanes and boundaries, and stable from frame to frame), the lanes
//! of the road network (built once, sent in the first frame or in every frame, as
//! `--osi-static first|every` asks), the map and projection strings, and the host
//! vehicle rule (`--osi-host NAME`; by default the entity named `Ego`, else none).
//! Each step opens a [`FrameBuilder`], adds entities, and finishes it into a message that
//! carries the interface version (3.8.0) in every frame.

use crate::entity::{moving_object, stationary_object, EntityInfo, MiscObjectInfo};
use crate::error::Error;
use crate::ids::{IdAllocator, IdKey};
use crate::lanes::{from_network, RoadLanes};
use crate::osi3::ground_truth::ProjFrameOffset;
use crate::osi3::{GroundTruth, Identifier, Timestamp, TrafficLight, TrafficSign, Vector3d};
use crate::polyline::Sampling;
use crate::rigid_body::RigidBodyState;
use crate::version::interface_version;

/// Name of the entity that is the host vehicle when none is named.
pub const DEFAULT_HOST: &str = "Ego";

/// In which frames the lanes and lane boundaries go (`--osi-static`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StaticData {
    /// Only in the first frame (the default: they do not change).
    #[default]
    First,
    /// In every frame.
    Every,
}

/// Builds the GroundTruth of each step of a run (see the module doc).
#[derive(Debug, Clone, Default)]
pub struct GroundTruthBuilder {
    ids: IdAllocator,
    lanes: RoadLanes,
    static_data: StaticData,
    host: Option<String>,
    map_reference: Option<String>,
    model_reference: Option<String>,
    proj_string: Option<String>,
    proj_frame_offset: Option<ProjFrameOffset>,
    frames: u64,
}

impl GroundTruthBuilder {
    /// A builder without road network; lanes go out as `static_data` says.
    pub fn new(static_data: StaticData) -> Self {
        GroundTruthBuilder {
            ids: IdAllocator::new(),
            static_data,
            ..Default::default()
        }
    }

    /// Builds the lanes of `network` (ids first, so lane ids are the same whatever the
    /// entities), takes `proj_string` from its `geoReference`, `proj_frame_offset` from
    /// its header `<offset>` (OpenDRIVE 1.8 §6.4: translate by x, y, z, then rotate by hdg
    /// about the new origin, which is OSI's x_proj = R(yaw)·x_osi + position with
    /// yaw = hdg), and `map_reference` as given.
    pub fn set_road_network(
        &mut self,
        network: &opendrive::RoadNetwork,
        map_reference: Option<&str>,
        sampling: &Sampling,
    ) -> Result<(), Error> {
        self.lanes = from_network(network, &mut self.ids, sampling, map_reference)?;
        self.map_reference = map_reference.map(str::to_string);
        self.proj_string = network
            .header()
            .geo_reference
            .as_ref()
            .map(|g| g.0.trim().to_string())
            .filter(|s| !s.is_empty());
        self.proj_frame_offset = network.header().offset.as_ref().map(|o| ProjFrameOffset {
            position: Some(Vector3d {
                x: Some(o.x),
                y: Some(o.y),
                z: Some(o.z),
            }),
            yaw: Some(o.hdg),
        });
        Ok(())
    }

    /// Sets `model_reference`, the 3D model of the environment (e.g. the scenario's
    /// `SceneGraphFile`).
    pub fn set_model_reference(&mut self, model_reference: Option<&str>) {
        self.model_reference = model_reference.map(str::to_string);
    }

    /// Names the host vehicle (`--osi-host`); `None` returns to the default
    /// ([`DEFAULT_HOST`] if such an entity exists).
    pub fn set_host(&mut self, name: Option<&str>) {
        self.host = name.map(str::to_string);
    }

    /// The run's id allocator, e.g. to look up lane ids with
    /// [`crate::lanes::assigned_lane`].
    pub fn ids(&self) -> &IdAllocator {
        &self.ids
    }

    /// The lanes and boundaries built by [`Self::set_road_network`].
    pub fn lanes(&self) -> &RoadLanes {
        &self.lanes
    }

    /// Starts the frame at simulation time `timestamp_nanos` (ns since the start).
    pub fn begin_frame(&mut self, timestamp_nanos: u64) -> FrameBuilder<'_> {
        let seconds = i64::try_from(timestamp_nanos / 1_000_000_000).unwrap_or(i64::MAX);
        // The remainder is below 10⁹ and fits in u32.
        let nanos = (timestamp_nanos % 1_000_000_000) as u32;
        let gt = GroundTruth {
            version: Some(interface_version()),
            timestamp: Some(Timestamp {
                seconds: Some(seconds),
                nanos: Some(nanos),
            }),
            map_reference: self.map_reference.clone(),
            model_reference: self.model_reference.clone(),
            proj_string: self.proj_string.clone(),
            proj_frame_offset: self.proj_frame_offset,
            ..Default::default()
        };
        FrameBuilder { owner: self, gt }
    }
}

/// One frame being filled; [`FrameBuilder::finish`] hands out the message.
#[derive(Debug)]
pub struct FrameBuilder<'a> {
    owner: &'a mut GroundTruthBuilder,
    gt: GroundTruth,
}

impl FrameBuilder<'_> {
    /// The run's id allocator, for lane look-ups while the frame is open
    /// ([`crate::lanes::assigned_lane_at`]).
    pub fn ids(&self) -> &IdAllocator {
        &self.owner.ids
    }

    /// Adds a vehicle or pedestrian in `state`, on OSI lanes `lanes`; returns its id.
    pub fn add_entity(
        &mut self,
        info: &EntityInfo<'_>,
        state: &RigidBodyState,
        lanes: &[Identifier],
    ) -> Result<Identifier, Error> {
        let object = moving_object(&mut self.owner.ids, info, state, lanes)?;
        // `moving_object` always sets the id.
        let id = object.id.unwrap_or_default();
        self.gt.moving_object.push(object);
        Ok(id)
    }

    /// Adds a MiscObject as a stationary object; returns its id.
    pub fn add_misc_object(
        &mut self,
        info: &MiscObjectInfo<'_>,
        lanes: &[Identifier],
    ) -> Result<Identifier, Error> {
        let object = stationary_object(&mut self.owner.ids, info, lanes)?;
        // `stationary_object` always sets the id.
        let id = object.id.unwrap_or_default();
        self.gt.stationary_object.push(object);
        Ok(id)
    }

    /// Adds a traffic light bulb under the id of `key`; returns the id.
    pub fn add_traffic_light(&mut self, key: IdKey, mut light: TrafficLight) -> Identifier {
        let id = self.owner.ids.id(key);
        light.id = Some(id);
        self.gt.traffic_light.push(light);
        id
    }

    /// Adds a traffic sign under the id of `key`; returns the id.
    pub fn add_traffic_sign(&mut self, key: IdKey, mut sign: TrafficSign) -> Identifier {
        let id = self.owner.ids.id(key);
        sign.id = Some(id);
        self.gt.traffic_sign.push(sign);
        id
    }

    /// Whether this frame carries the static data (lanes, static traffic signs), as
    /// `--osi-static` asks: the first frame only, or every frame.
    pub fn carries_static_data(&self) -> bool {
        match self.owner.static_data {
            StaticData::First => self.owner.frames == 0,
            StaticData::Every => true,
        }
    }

    /// The finished message: host vehicle id (if the host entity is in the frame) and,
    /// as `--osi-static` asks, the lanes.
    pub fn finish(mut self) -> GroundTruth {
        let host_name = self.owner.host.as_deref().unwrap_or(DEFAULT_HOST);
        let host = self
            .owner
            .ids
            .get(&IdKey::MovingObject(host_name.to_string()));
        self.gt.host_vehicle_id =
            host.filter(|h| self.gt.moving_object.iter().any(|m| m.id == Some(*h)));
        if self.carries_static_data() {
            self.gt.lane = self.owner.lanes.lanes.clone();
            self.gt.lane_boundary = self.owner.lanes.lane_boundaries.clone();
        }
        self.owner.frames += 1;
        self.gt
    }
}
