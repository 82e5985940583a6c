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
///
/// The ids live in one map per kind, so that the ids asked for in every frame (an entity's by
/// its name, a lane's by road id, lane_section and lane) are found from borrowed keys
/// ([`IdAllocator::moving_object`], [`IdAllocator::lane`]) without building an owned
/// [`IdKey`]: no allocation per object and frame once the key has its id.
#[derive(Debug, Clone, Default)]
pub struct IdAllocator {
    moving: HashMap<String, u64>,
    stationary: HashMap<String, u64>,
    /// Lanes and lane boundaries by road id, then (lane_section, lane, boundary?).
    lanes: HashMap<String, HashMap<(usize, i32, bool), u64>>,
    /// Traffic lights and signs.
    signals: HashMap<IdKey, u64>,
    next: u64,
    len: usize,
}

impl IdAllocator {
    /// An allocator whose first id is 1.
    pub fn new() -> Self {
        IdAllocator {
            next: 1,
            ..Default::default()
        }
    }

    /// The next free value (from 1).
    fn fresh(next: &mut u64, len: &mut usize) -> u64 {
        let v = (*next).max(1);
        *next = v + 1;
        *len += 1;
        v
    }

    /// The id of `key`: the one it got before, or the next free one.
    pub fn id(&mut self, key: IdKey) -> Identifier {
        let (next, len) = (&mut self.next, &mut self.len);
        let value = match key {
            IdKey::MovingObject(name) => *self
                .moving
                .entry(name)
                .or_insert_with(|| Self::fresh(next, len)),
            IdKey::StationaryObject(name) => *self
                .stationary
                .entry(name)
                .or_insert_with(|| Self::fresh(next, len)),
            IdKey::Lane {
                road,
                lane_section,
                lane,
            } => Self::lane_entry(
                &mut self.lanes,
                road,
                (lane_section, lane, false),
                next,
                len,
            ),
            IdKey::LaneBoundary {
                road,
                lane_section,
                lane,
            } => Self::lane_entry(&mut self.lanes, road, (lane_section, lane, true), next, len),
            key @ (IdKey::TrafficLight { .. } | IdKey::TrafficSign { .. }) => *self
                .signals
                .entry(key)
                .or_insert_with(|| Self::fresh(next, len)),
        };
        Identifier { value: Some(value) }
    }

    /// The value of a lane or boundary `key` of `road`, handed out if new.
    fn lane_entry(
        lanes: &mut HashMap<String, HashMap<(usize, i32, bool), u64>>,
        road: String,
        key: (usize, i32, bool),
        next: &mut u64,
        len: &mut usize,
    ) -> u64 {
        *lanes
            .entry(road)
            .or_default()
            .entry(key)
            .or_insert_with(|| Self::fresh(next, len))
    }

    /// The id of the `MovingObject` of entity `name`, as `id(IdKey::MovingObject(name))`
    /// gives it; the name is copied only the first time.
    pub fn moving_object(&mut self, name: &str) -> Identifier {
        match self.moving.get(name) {
            Some(&value) => Identifier { value: Some(value) },
            None => self.id(IdKey::MovingObject(name.to_owned())),
        }
    }

    /// The id of the `StationaryObject` of `name`, as `id(IdKey::StationaryObject(name))`
    /// gives it; the name is copied only the first time.
    pub fn stationary_object(&mut self, name: &str) -> Identifier {
        match self.stationary.get(name) {
            Some(&value) => Identifier { value: Some(value) },
            None => self.id(IdKey::StationaryObject(name.to_owned())),
        }
    }

    /// The id the lane `lane` of lane_section `lane_section` of road `road` already has
    /// ([`IdKey::Lane`]), without allocating.
    pub fn lane(&self, road: &str, lane_section: usize, lane: i32) -> Option<Identifier> {
        let value = self.lanes.get(road)?.get(&(lane_section, lane, false))?;
        Some(Identifier {
            value: Some(*value),
        })
    }

    /// The id `key` already has, without allocating one.
    pub fn get(&self, key: &IdKey) -> Option<Identifier> {
        let value = match key {
            IdKey::MovingObject(name) => self.moving.get(name),
            IdKey::StationaryObject(name) => self.stationary.get(name),
            IdKey::Lane {
                road,
                lane_section,
                lane,
            } => self.lanes.get(road)?.get(&(*lane_section, *lane, false)),
            IdKey::LaneBoundary {
                road,
                lane_section,
                lane,
            } => self.lanes.get(road)?.get(&(*lane_section, *lane, true)),
            IdKey::TrafficLight { .. } | IdKey::TrafficSign { .. } => self.signals.get(key),
        };
        value.map(|&v| Identifier { value: Some(v) })
    }

    /// The id the `MovingObject` of entity `name` already has, without allocating.
    pub fn get_moving_object(&self, name: &str) -> Option<Identifier> {
        self.moving
            .get(name)
            .map(|&v| Identifier { value: Some(v) })
    }

    /// Number of ids handed out.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no id was handed out yet.
    pub fn is_empty(&self) -> bool {
        self.len == 0
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
        // The borrowed look-ups give the same ids as the keys.
        assert_eq!(ids.moving_object("Ego"), ego);
        assert_eq!(ids.lane("0", 0, -1), Some(lane));
        assert_eq!(ids.lane("0", 0, 1), None);
        assert_eq!(ids.get_moving_object("Ego"), Some(ego));
        // A new name through the borrowed path takes the next value, 4.
        assert_eq!(ids.moving_object("Target").value, Some(4));
        assert_eq!(ids.len(), 4);
    }
}
