//! Assembling one ASAM OSI 3.8 `GroundTruth` per output step: the seam the engine feeds.
//!
//! A [`GroundTruthBuilder`] lives for a whole run. It owns the [`IdAllocator`] (so ids are
//! unique across objects, lanes and boundaries, and stable from frame to frame), the lanes
//! of the road network (built once, sent in the first frame or in every frame, as
//! `--osi-static first|every` asks), the map and projection strings, and the host
//! vehicle rule (`--osi-host NAME`; by default the entity named `Ego`, else none).
//! Each step opens a [`FrameBuilder`], adds entities, and finishes it into a message that
//! carries the interface version (3.8.0) in every frame.
//!
//! The builder keeps one `GroundTruth` for the whole run and writes each frame over the last
//! (module `reuse`): the k-th object added in a frame overwrites the k-th object of the
//! last one, lists are cut back or extended only where the frame has fewer or more objects,
//! and the map strings are set once. A frame is byte for byte the message a fresh build
//! would give; a run whose entity set does not change allocates nothing per frame.

use crate::entity::{fill_moving_object, fill_stationary_object, EntityInfo, MiscObjectInfo};
use crate::error::Error;
use crate::ids::IdAllocator;
use crate::lanes::{from_network, RoadLanes};
use crate::osi3::ground_truth::ProjFrameOffset;
use crate::osi3::{
    EnvironmentalConditions, GroundTruth, Identifier, Timestamp, TrafficLight, TrafficSign,
    Vector3d,
};
use crate::polyline::Sampling;
use crate::reuse::slot;
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
    /// The message of the last frame, written over by the next (module doc); the map and
    /// projection fields are set here once.
    gt: GroundTruth,
    /// How many of each list the open frame has written so far.
    filled: Filled,
    frames: u64,
}

/// The number of objects of each list written in the open frame.
#[derive(Debug, Clone, Copy, Default)]
struct Filled {
    moving: usize,
    stationary: usize,
    lights: usize,
    signs: usize,
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
        self.gt.map_reference = map_reference.map(str::to_string);
        self.gt.proj_string = network
            .header()
            .geo_reference
            .as_ref()
            .map(|g| g.0.trim().to_string())
            .filter(|s| !s.is_empty());
        self.gt.proj_frame_offset = network.header().offset.as_ref().map(|o| ProjFrameOffset {
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
        self.gt.model_reference = model_reference.map(str::to_string);
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
        let gt = &mut self.gt;
        gt.version = Some(interface_version());
        gt.timestamp = Some(Timestamp {
            seconds: Some(seconds),
            nanos: Some(nanos),
        });
        gt.environmental_conditions = None;
        self.filled = Filled::default();
        FrameBuilder { owner: self }
    }
}

/// One frame being filled; [`FrameBuilder::finish`] hands out the message.
#[derive(Debug)]
pub struct FrameBuilder<'a> {
    owner: &'a mut GroundTruthBuilder,
}

impl<'a> FrameBuilder<'a> {
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
        let owner = &mut *self.owner;
        let object = slot(&mut owner.gt.moving_object, owner.filled.moving);
        fill_moving_object(object, &mut owner.ids, info, state, lanes)?;
        owner.filled.moving += 1;
        // `fill_moving_object` always sets the id.
        Ok(object.id.unwrap_or_default())
    }

    /// Adds a MiscObject as a stationary object; returns its id.
    pub fn add_misc_object(
        &mut self,
        info: &MiscObjectInfo<'_>,
        lanes: &[Identifier],
    ) -> Result<Identifier, Error> {
        let owner = &mut *self.owner;
        let object = slot(&mut owner.gt.stationary_object, owner.filled.stationary);
        fill_stationary_object(object, &mut owner.ids, info, lanes)?;
        owner.filled.stationary += 1;
        // `fill_stationary_object` always sets the id.
        Ok(object.id.unwrap_or_default())
    }

    /// The next traffic light of this frame, to be written in place (last frame's light at
    /// this place, or a new default one), and the run's id allocator for its id.
    pub fn next_traffic_light(&mut self) -> (&mut TrafficLight, &mut IdAllocator) {
        let owner = &mut *self.owner;
        let light = slot(&mut owner.gt.traffic_light, owner.filled.lights);
        owner.filled.lights += 1;
        (light, &mut owner.ids)
    }

    /// The next traffic sign of this frame, to be written in place, as
    /// [`Self::next_traffic_light`].
    pub fn next_traffic_sign(&mut self) -> (&mut TrafficSign, &mut IdAllocator) {
        let owner = &mut *self.owner;
        let sign = slot(&mut owner.gt.traffic_sign, owner.filled.signs);
        owner.filled.signs += 1;
        (sign, &mut owner.ids)
    }

    /// Sets the frame's `environmental_conditions` (none unless set).
    pub fn set_environmental_conditions(&mut self, conditions: Option<EnvironmentalConditions>) {
        self.owner.gt.environmental_conditions = conditions;
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
    /// as `--osi-static` asks, the lanes. Objects of the last frame beyond this frame's count
    /// are dropped here.
    pub fn finish(self) -> &'a GroundTruth {
        let carries_static_data = self.carries_static_data();
        let owner = self.owner;
        let gt = &mut owner.gt;
        gt.moving_object.truncate(owner.filled.moving);
        gt.stationary_object.truncate(owner.filled.stationary);
        gt.traffic_light.truncate(owner.filled.lights);
        gt.traffic_sign.truncate(owner.filled.signs);
        let host_name = owner.host.as_deref().unwrap_or(DEFAULT_HOST);
        let host = owner.ids.get_moving_object(host_name);
        gt.host_vehicle_id = host.filter(|h| gt.moving_object.iter().any(|m| m.id == Some(*h)));
        // The lanes do not change during a run: put in by the first frame, they stay there for
        // `Every` and are taken out again for `First`.
        match (carries_static_data, owner.frames) {
            (true, 0) => {
                gt.lane.clone_from(&owner.lanes.lanes);
                gt.lane_boundary.clone_from(&owner.lanes.lane_boundaries);
            }
            (true, _) => {}
            (false, _) => {
                gt.lane.clear();
                gt.lane_boundary.clear();
            }
        }
        owner.frames += 1;
        &owner.gt
    }
}
