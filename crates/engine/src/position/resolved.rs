//! The result of resolving a position: a world pose of the entity's reference point and where
//! that point lies on the road network (OpenSCENARIO 1.3 §6.3.1 world coordinates, §6.3.3
//! road coordinates, §6.3.4 lane coordinates).

use opendrive::{Pose, RoadNetwork, RoadPosition};

/// A resolved position: the pose the entity's reference point (for a vehicle the centre of the
/// rear axle, on the ground) takes there, and its road position.
#[derive(Debug, Clone, PartialEq)]
pub struct ResolvedPosition {
    /// World pose: x, y, z in m; heading, pitch, roll in rad.
    pub pose: Pose,
    /// The road position of the pose's point; `None` only on an empty road network.
    pub road_position: Option<RoadPosition>,
}

impl ResolvedPosition {
    /// `pose` with its road position looked up anywhere on `network` (its heading choosing
    /// between overlapping roads).
    pub(crate) fn located(network: &RoadNetwork, pose: Pose) -> Self {
        Self {
            road_position: network.locate(pose.x, pose.y, Some(pose.h)),
            pose,
        }
    }

    /// `pose` with its road position projected on road `road_id` (road and lane positions
    /// keep the road they name, also where roads overlap in a junction).
    pub(crate) fn on_road(network: &RoadNetwork, road_id: &str, pose: Pose) -> Self {
        let road_position = network
            .locate_on_road(road_id, pose.x, pose.y)
            .map(|mut rp| {
                if let Ok(road_pose) = network.road_pose(road_id, rp.s, 0.0) {
                    rp.relative_heading = opendrive::angle_difference(pose.h, road_pose.h);
                }
                rp
            });
        Self {
            road_position,
            pose,
        }
    }
}
