//! The lanes a signal is valid for (OpenDRIVE 1.8 §14.2 "Lane validity for signals"): "by
//! default, signals are valid for all lanes of a road, for traffic traveling in the direction
//! indicated by @orientation"; `<validity>` elements restrict them to the lanes in their
//! ranges.

use super::graph::{driving_direction, Direction};
use crate::model::{Road, Signal};

impl Road {
    /// The ids of the lanes of the lane section at `signal`'s s that it is valid for, left to
    /// right: with `<validity>` elements, the lanes whose ids lie in their ranges; without,
    /// the drivable lanes driven in the direction its `orientation` names ("+" towards +s,
    /// "-" towards −s, anything else both; the driving direction from the road's traffic
    /// rule). Never the centre lane.
    pub fn signal_lanes(&self, signal: &Signal) -> Vec<i32> {
        let direction = match signal.orientation.trim() {
            "+" => Some(Direction::Forward),
            "-" => Some(Direction::Backward),
            _ => None,
        };
        self.lane_section_at(signal.s)
            .lanes()
            .filter(|lane| lane.id != 0)
            .filter(|lane| {
                if signal.validity.is_empty() {
                    lane.lane_type.is_drivable()
                        && direction.is_none_or(|d| driving_direction(self, lane.id) == d)
                } else {
                    signal.valid_for_lane(lane.id)
                }
            })
            .map(|lane| lane.id)
            .collect()
    }
}
