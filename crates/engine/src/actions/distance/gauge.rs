//! How the distance actions measure (OpenSCENARIO 1.3 §6.4 "Distances"; the attributes
//! `coordinateSystem` and `freespace` of LongitudinalDistanceAction and LateralDistanceAction).
//!
//! The reference-point distance from the actor to the reference entity along the action's axis
//! is measured as the conditions measure it (`condition::measure`: entity, road, lane, world or
//! trajectory frame; signed, positive when the reference lies ahead of / left of the actor's
//! travel). The standard's default frame is `entity`, "the actor's local coordinate system".
//!
//! The actions keep a *clearance*: the reference-point distance on the side where the reference
//! should be, less, with `freespace`, the extents of the two bounding boxes towards each other
//! (box centre offset ± half length or width). For boxes aligned with the axis this is the
//! §6.4 freespace distance; unlike that distance (0 for overlapping boxes) it goes negative when
//! the boxes overlap along the axis or the reference is on the wrong side, so the controller
//! still knows which way and how far to move.

use scenario::{CoordinateSystem, DistanceMeasure, RelativeDistanceType, SourcePos};

use crate::condition::{measured_distance, MeasureTarget};
use crate::domain::BoundingBox;
use crate::error::Error;
use crate::store::World;
use crate::world::entity::EntityId;

/// The axis a distance action keeps its distance along.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Axis {
    /// Along the actor's travel (x of the entity frame, s of the road).
    Longitudinal,
    /// Across it (y of the entity frame, t of the road), positive to the left.
    Lateral,
}

/// How one distance action measures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Gauge {
    /// Along which axis.
    pub axis: Axis,
    /// The frame (`coordinateSystem`; absent: entity).
    pub coordinate_system: CoordinateSystem,
    /// Between bounding boxes (true) or reference points.
    pub freespace: bool,
}

impl Gauge {
    /// The gauge of an action starting now (`coordinate_system` absent: entity) and its first
    /// reading ([`Gauge::points`]); an error at `pos` when the frame cannot measure between the
    /// two entities.
    pub fn at_start(
        world: &World,
        (actor, reference): (EntityId, EntityId),
        axis: Axis,
        coordinate_system: Option<CoordinateSystem>,
        freespace: bool,
        pos: &SourcePos,
    ) -> Result<(Gauge, f64), Error> {
        let gauge = Gauge {
            axis,
            coordinate_system: coordinate_system.unwrap_or(CoordinateSystem::Entity),
            freespace,
        };
        match gauge.points(world, actor, reference) {
            Some(now) => Ok((gauge, now)),
            None => Err(Error::at(
                format!("a {axis:?} distance the coordinateSystem can measure").to_lowercase(),
                format!(
                    "none between '{}' and '{}'",
                    world.entity(actor).name,
                    world.entity(reference).name
                ),
                pos,
            )),
        }
    }

    /// Signed reference-point distance from `actor` to `reference` along the axis: positive
    /// when the reference lies ahead of / left of the actor. `None` when the frame has no
    /// answer now (a road frame off the roads, a trajectory frame without a trajectory).
    pub fn points(&self, world: &World, actor: EntityId, reference: EntityId) -> Option<f64> {
        let measure = DistanceMeasure {
            freespace: false,
            coordinate_system: Some(self.coordinate_system),
            relative_distance_type: Some(match self.axis {
                Axis::Longitudinal => RelativeDistanceType::Longitudinal,
                Axis::Lateral => RelativeDistanceType::Lateral,
            }),
            routing_algorithm: None,
        };
        let (a, r) = (world.entity(actor), world.entity(reference));
        measured_distance(
            &world.network,
            &world.view(a),
            &MeasureTarget::Entity(world.view(r)),
            &measure,
        )
        .ok()
        .flatten()
    }

    /// The clearance from `actor` to `reference` when the reference should lie on side
    /// `toward` of the actor (+1: ahead / left, −1: behind / right), in metres (see the module
    /// doc); `None` as [`Gauge::points`].
    pub fn clearance(
        &self,
        world: &World,
        actor: EntityId,
        reference: EntityId,
        toward: f64,
    ) -> Option<f64> {
        let points = toward * self.points(world, actor, reference)?;
        if !self.freespace {
            return Some(points);
        }
        let (a, r) = (world.entity(actor), world.entity(reference));
        Some(
            points
                - extent(&a.bounding_box, self.axis, toward)
                - extent(&r.bounding_box, self.axis, -toward),
        )
    }
}

/// How far box `b` reaches from its reference point along `axis` towards side `dir` (+1:
/// front / left, −1: rear / right).
pub(crate) fn extent(b: &BoundingBox, axis: Axis, dir: f64) -> f64 {
    let c = b.center();
    match axis {
        Axis::Longitudinal => b.length() / 2.0 + dir * c.x,
        Axis::Lateral => b.width() / 2.0 + dir * c.y,
    }
}
