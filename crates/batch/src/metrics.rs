//! What a batch measures in each variant's run: the host against every other entity, frame by
//! frame, with the OpenSCENARIO 2.0 §8.7 methods of the engine's domain model.
//!
//! | column | definition |
//! | --- | --- |
//! | `collision` | at some frame the host's bounding box touched or overlapped another entity's: §8.7.5.1.1 `time_to_collision` is 0 (the ground-plane footprints intersect and the vertical extents overlap), whether or not the scenario has a CollisionCondition |
//! | `first_collision_time` | the time of the first such frame |
//! | `min_ttc` | the smallest §8.7.5.1.1 `time_to_collision(other)` of the host over all frames and other entities, where defined (both keep their velocities; receding pairs have none) |
//! | `min_headway` | the smallest positive §8.7.5.1.2 `time_headway(other)` of the host (a vehicle) over frames and others: the time the host needs at its speed to reach where the other is, along the road; others behind (negative headway) do not count |
//! | `min_gap` | the smallest bumper-to-bumper distance to an entity in the host's path: §8.7.2.1.1 `object_distance(other, longitudinal, bounding_boxes)` (absolute value) over the others whose boxes overlap the host's lateral extent (`object_distance(other, lateral, bounding_boxes)` is 0) |
//!
//! Trailers the host tows are part of the host, not others (they would touch it always). An
//! entity that is not placed, or not visible to traffic (VisibilityAction `traffic="false"`),
//! is not measured. `min_gap` uses the host's own axes, which on a curve of radius R over a
//! gap g deviates from the distance along the lane by about g³/(24R²) (1 mm for 30 m at
//! R = 300 m): the gap is meant for car-following situations, where that is negligible, and it
//! costs a few hundred nanoseconds where the road-aligned `space_gap` costs tens of
//! microseconds per pair and frame.

use opendrive::RoadNetwork;

use engine::domain::{time_headway_between, DistanceDirection, DistanceMode};
use engine::output::{EntityFrame, Frame, FrameSink};
use engine::runtime::EntityKind;

/// The running minima and the collision record of one run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Measures {
    /// A collision happened.
    pub collision: bool,
    /// Time of the first frame with one (s).
    pub first_collision_time: Option<f64>,
    /// Smallest time to collision (s).
    pub min_ttc: Option<f64>,
    /// Smallest positive time headway (s).
    pub min_headway: Option<f64>,
    /// Smallest in-path gap (m).
    pub min_gap: Option<f64>,
}

/// A frame sink that measures the host against the others (module doc).
pub struct Observer<'n> {
    network: &'n RoadNetwork,
    host: String,
    /// What was measured so far.
    pub measures: Measures,
}

/// Keeps the smaller of `slot` and a finite `value`.
fn min_into(slot: &mut Option<f64>, value: f64) {
    if value.is_finite() && slot.is_none_or(|old| value < old) {
        *slot = Some(value);
    }
}

impl<'n> Observer<'n> {
    /// An observer of `host` on `network`.
    pub fn new(network: &'n RoadNetwork, host: &str) -> Self {
        Observer {
            network,
            host: host.to_owned(),
            measures: Measures::default(),
        }
    }

    fn measure(&mut self, time: f64, host: &EntityFrame<'_>, other: &EntityFrame<'_>) {
        let (h, o) = (host.view(), other.view());
        let (hp, op) = (h.physical_object(), o.physical_object());
        let m = &mut self.measures;
        if let Some(ttc) = h
            .traffic_participant()
            .time_to_collision(&o.traffic_participant())
        {
            min_into(&mut m.min_ttc, ttc);
            if ttc <= 0.0 && !m.collision {
                m.collision = true;
                m.first_collision_time = Some(time);
            }
        }
        let lateral =
            hp.object_distance(&op, DistanceDirection::Lateral, DistanceMode::BoundingBoxes);
        if lateral == 0.0 {
            let longitudinal = hp.object_distance(
                &op,
                DistanceDirection::Longitudinal,
                DistanceMode::BoundingBoxes,
            );
            min_into(&mut m.min_gap, longitudinal.abs());
        }
        if host.kind == EntityKind::Vehicle {
            if let (Some(a), Some(b)) = (host.road_position, other.road_position) {
                if let Ok(Some(headway)) = time_headway_between(self.network, a, host.speed, b) {
                    if headway > 0.0 {
                        min_into(&mut m.min_headway, headway);
                    }
                }
            }
        }
    }
}

impl FrameSink for Observer<'_> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        let objects: Vec<EntityFrame<'_>> = frame.objects().collect();
        let Some(host) = objects.iter().find(|e| e.name == self.host) else {
            return Ok(());
        };
        // The host's trailer chain.
        let mut towed = Vec::new();
        let mut next = host.trailer;
        while let Some(t) = next.filter(|t| !towed.contains(t)) {
            towed.push(t);
            next = objects.iter().find(|e| e.id == t).and_then(|e| e.trailer);
        }
        for other in &objects {
            if other.id == host.id || towed.contains(&other.id) || !other.visibility.traffic {
                continue;
            }
            self.measure(frame.time, host, other);
        }
        Ok(())
    }
}
