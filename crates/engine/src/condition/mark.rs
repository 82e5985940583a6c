//! oscsim's marks (no XML form): what a state check (`scenario::StateCheck::mark`, written by
//! the OpenSCENARIO DSL runtime at the start of a phase that starts on a run-time condition,
//! ASAM OpenSCENARIO DSL 2.1 §8.9) notes on its actor, and the two conditions that measure from
//! it: `TraveledSinceMark` (the odometer's advance since the mark: `distance(d)` without a
//! duration) and `GapReachedSinceMark` (the actor has reached its place relative to another
//! entity from the side it was on at the mark: `position(time: t / neither, ahead_of/behind:
//! x, at: end)` without a duration). Both are false before the mark is noted, so they may
//! stand in any trigger.

use opendrive::{Real, RoadPosition};
use scenario::SpeedGap;

use crate::position::EntityView;

/// What a state check noted on its actor.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Mark {
    /// The actor's odometer then (m).
    pub odometer: Real,
    /// With a gap: the actor's place error relative to the gap's entity then
    /// ([`place_error`], m).
    pub gap_error: Option<Real>,
}

/// The actor's s minus the gap's entity's, less [`SpeedGap::offset`] at that entity's speed
/// `speed` (m): 0 where the gap asks the actor to be, positive beyond. `None` when the two are
/// on different roads (s is not comparable).
pub(crate) fn place_error(
    actor: &RoadPosition,
    other: &RoadPosition,
    speed: Real,
    gap: &SpeedGap,
) -> Option<Real> {
    (actor.road_id == other.road_id).then(|| actor.s - other.s - gap.offset(speed))
}

/// TraveledSinceMark: `e`'s odometer has advanced `value` m or more since `mark`.
pub(super) fn traveled_since(e: &EntityView<'_>, mark: Option<Mark>, value: Real) -> bool {
    mark.is_some_and(|m| e.odometer - m.odometer >= value)
}

/// GapReachedSinceMark: `e`'s place error relative to `other` is 0 or of the sign opposite to
/// the one noted at `mark`.
pub(super) fn gap_reached_since(
    e: &EntityView<'_>,
    other: &EntityView<'_>,
    mark: Option<Mark>,
    gap: &SpeedGap,
) -> bool {
    let (Some(m0), Some(a), Some(x)) = (
        mark.and_then(|m| m.gap_error),
        e.road_position,
        other.road_position,
    ) else {
        return false;
    };
    place_error(a, x, other.speed, gap).is_some_and(|now| now == 0.0 || (now > 0.0) != (m0 > 0.0))
}
