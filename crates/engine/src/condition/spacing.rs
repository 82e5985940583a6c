//! Entity conditions on spacing (OpenSCENARIO 1.3 §7.6.3; XSD `DistanceCondition`,
//! `RelativeDistanceCondition`, `ReachPositionCondition`, `TimeHeadwayCondition`,
//! `TimeToCollisionCondition`), measured by `measure`.
//!
//! * DistanceCondition / RelativeDistanceCondition: |distance| from the triggering entity to
//!   the position / reference entity, `rule` value.
//! * ReachPositionCondition (deprecated since 1.2): the Euclidean distance between the
//!   reference point and the position is at most `tolerance`.
//! * TimeHeadwayCondition, 1.3: "the reference entity is assumed to be leading/ahead, so the
//!   triggering entity is trailing … For the relative speed only the speed of the triggering
//!   entity is considered". oscsim: headway = |distance| / speed of the triggering entity,
//!   where the reference must be ahead (its reference point's longitudinal coordinate in the
//!   chosen system is > 0) and the speed > 0; otherwise there is no headway and the condition
//!   is false (pitfall 12, esmini #23: the triggering entity measures; a reference behind never
//!   gives a headway).
//! * TimeToCollisionCondition, 1.3: "distance divided by the relative speed … for the relative
//!   speed calculation the same coordinate system and relative distance type applies as for
//!   the distance calculation. If the relative speed is negative … the condition evaluates to
//!   false." oscsim: with the default measure and `freespace` (entity system, Euclidean) the
//!   exact box time of §8.7.5.1.1 time_to_collision() (boxes moving on their velocities);
//!   otherwise |distance| / closing speed, the closing speed being minus the rate of
//!   |distance| under the same measure (`measure::distance_rate`); boxes already touching
//!   (freespace distance 0) have TTC 0. Objects not closing have no TTC (pitfall 11):
//!   oncoming traffic in the next lane closes in Euclidean distance but not in lateral
//!   distance, and its boxes never meet, so choose the measure accordingly.

use opendrive::Real;
use scenario::{CoordinateSystem, DistanceMeasure, RelativeDistanceType, Rule};

use super::measure::{box_time_to_collision, distance, distance_rate};
use super::rule::compare;
use super::target::Target;
use super::ConditionErrorKind;
use crate::position::{EntityQuery, EntityView};

/// `|distance| rule value`; false when the measure has no answer now.
pub(crate) fn distance_holds<Q: EntityQuery + ?Sized>(
    ctx: &Q,
    e: &EntityView<'_>,
    target: &Target<'_>,
    measure: &DistanceMeasure,
    rule: Rule,
    value: Real,
) -> Result<bool, ConditionErrorKind> {
    Ok(distance(ctx.road_network(), e, target, measure)?
        .is_some_and(|d| compare(d.abs(), rule, value)))
}

/// The time headway of `e` behind `reference`, s; `None` when there is none.
pub(crate) fn time_headway<Q: EntityQuery + ?Sized>(
    ctx: &Q,
    e: &EntityView<'_>,
    reference: &EntityView<'_>,
    measure: &DistanceMeasure,
) -> Result<Option<Real>, ConditionErrorKind> {
    if e.speed <= 0.0 {
        return Ok(None);
    }
    let network = ctx.road_network();
    let target = Target::Entity(*reference);
    let ahead_measure = DistanceMeasure {
        freespace: false,
        relative_distance_type: Some(RelativeDistanceType::Longitudinal),
        coordinate_system: Some(match measure.coordinate_system {
            Some(CoordinateSystem::Road) | Some(CoordinateSystem::Lane) => CoordinateSystem::Road,
            _ => CoordinateSystem::Entity,
        }),
        ..*measure
    };
    let ahead = distance(network, e, &target, &ahead_measure)?;
    if !ahead.is_some_and(|a| a > 0.0) {
        return Ok(None);
    }
    Ok(distance(network, e, &target, measure)?.map(|d| d.abs() / e.speed))
}

/// The time to collision of `e` with `target`, s; `None` when they are not closing.
pub(crate) fn time_to_collision<Q: EntityQuery + ?Sized>(
    ctx: &Q,
    e: &EntityView<'_>,
    target: &Target<'_>,
    measure: &DistanceMeasure,
) -> Result<Option<Real>, ConditionErrorKind> {
    let entity_system = matches!(
        measure.coordinate_system,
        None | Some(CoordinateSystem::Entity)
    );
    let euclidean = matches!(
        measure.relative_distance_type,
        None | Some(RelativeDistanceType::EuclidianDistance)
    );
    if measure.freespace && entity_system && euclidean {
        return Ok(box_time_to_collision(e, target));
    }
    let network = ctx.road_network();
    let Some(d) = distance(network, e, target, measure)? else {
        return Ok(None);
    };
    if measure.freespace && d == 0.0 {
        // Boxes that touch or overlap have collided: no time is left.
        return Ok(Some(0.0));
    }
    let Some(rate) = distance_rate(network, e, target, measure)? else {
        return Ok(None);
    };
    let closing = -rate;
    Ok((closing > 0.0 && closing.is_finite()).then(|| d.abs() / closing))
}
