//! Identifiers for a GroundTruth: ASAM OSI 3.8 requires every `id` of a moving object,
//! stationary object, lane, lane boundary, traffic light and traffic sign to be unique within a GroundTruth
//! (rule `is_globally_unique`), and a tool reading a trace expects an object to keep its
//! id from frame to frame.
//!
//! [`IdAllocator`] hands out ids from one counter shared by all kinds, so two items
//! never share an id whatever their kind, and remembers each key's id, so the same
//! entity, lane or boundary gets the same id in every frame of a run. Ids start at 1
//! (some OSI consumers read 0 as "unset") and follow the order of first request, so a
//! run that asks in a fixed order gets the same ids every time.

use std::collections::HashMap;

use crate::osi3::Identifier;

/// What an id is for; equal keys get equal ids.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum IdKey {
    /// A scenario entity shown as a `MovingObject` (by entity name).
    MovingObject(String),
    /// A scenario entity or road object shown as a `StationaryObject` (by name).
    StationaryObject(String),
    /// An OpenDRIVE lane: road id, index of the lane_section in the road, lane id.
    Lane {
        /// OpenDRIVE road id.
        road: String,
        /// 0-based index of the lane_section along the road.
        lane_section: usize,
        /// OpenDRIVE lane id (positive left, negative right).
        lane: i32,
    },
    /// The outer boundary of an OpenDRIVE lane (lane 0: the centre line).
    LaneBoundary {
        /// OpenDRIVE road id.
        road: String,
        /// 0-based index of the lane_section along the road.
        lane_section: usize,
        /// OpenDRIVE lane id whose outer border this is; 0 for the centre lane.
        lane: i32,
    },
    /// One bulb of an OpenDRIVE signal shown as `TrafficLight`s.
    TrafficLight {
        /// OpenDRIVE road id.
        road: String,
        /// 0-based index of the signal in the road's `<signals>`.
        signal: usize,
        /// 0-based index of the bulb, from the top.
        bulb: usize,
    },
    /// An OpenDRIVE signal shown as a `TrafficSign`.
    TrafficSign {
        /// OpenDRIVE road id.
        road: String,
        /// 0-based index of the signal in the road's `<signals>`.
        signal: usize,
    },
}

/// Hands out globally unique, stable OSI ids (see the module doc).
#[derive(Debug, Clone, Default)]
pub struct IdAllocator {
    ids: HashMap<IdKey, u64>,
    next: u64,
}

impl IdAllocator {
    /// An allocator whose first id is 1.
    pub fn new() -> Self {
        IdAllocator {
            ids: HashMap::new(),
            next: 1,
        }
    }

    /// The id of `key`: the one it got before, or the next free one.
    pub fn id(&mut self, key: IdKey) -> Identifier {
        let next = &mut self.next;
        let value = *self.ids.entry(key).or_insert_with(|| {
            let v = (*next).max(1);
            *next = v + 1;
            v
        });
        Identifier { value: Some(value) }
    }

    /// The id `key` already has, without allocating one.
    pub fn get(&self, key: &IdKey) -> Option<Identifier> {
        self.ids.get(key).map(|&v| Identifier { value: Some(v) })
    }

    /// Number of ids handed out.
    pub fn len(&self) -> usize {
        self.ids.len()
    }

    /// Whether no id was handed out yet.
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_across_kinds_and_stable() {
        let mut ids = IdAllocator::new();
        let ego = ids.id(IdKey::MovingObject("Ego".into()));
        let lane = ids.id(IdKey::Lane {
            road: "0".into(),
            lane_section: 0,
            lane: -1,
        });
        // Same name, other kind: must not share the id (pitfall #16).
        let ego_static = ids.id(IdKey::StationaryObject("Ego".into()));
        assert_eq!(ego.value, Some(1));
        assert_eq!(lane.value, Some(2));
        assert_eq!(ego_static.value, Some(3));
        // Asked again in a later frame: the same id.
        assert_eq!(ids.id(IdKey::MovingObject("Ego".into())), ego);
        assert_eq!(ids.len(), 3);
        assert_eq!(ids.get(&IdKey::MovingObject("Target".into())), None);
    }
}
