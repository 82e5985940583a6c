//! ByEntityCondition (OpenSCENARIO 1.3 §7.6.3, XSD `ByEntityCondition`,
//! `TriggeringEntities`): an EntityCondition tested for each triggering entity, combined by
//! `triggeringEntitiesRule` — `any`: true when it holds for at least one, `all`: when it holds
//! for every one. An EntityRef naming an EntitySelection stands for all its members. Every
//! triggering entity is evaluated each time (no short cut), so that the duration conditions
//! keep their memory of each. The entities for which it held are reported to the context
//! ([`ConditionContext::note_triggering`]) for `selectTriggeringEntities` (§7.3.1). The
//! condition's position (ReachPosition, Distance, TimeToCollision's Position target) depends
//! on no triggering entity, so an evaluation works it out once, for the first triggering entity
//! that is measured, and measures the others to the same point.

use std::cell::Cell;

use opendrive::{Pose, Real};
use scenario::{
    CollisionTarget, EntityCondition, SourcePos, TimeToCollisionTarget, TriggeringEntities,
    TriggeringEntitiesRule,
};

use super::angle::{own_angle, relative_angle, within};
use super::clearance::{clear, Clearance};
use super::mark::{gap_reached_since, traveled_since};
use super::motion::{acceleration, relative_speed, speed, stands_still, DURATION_TOLERANCE};
use super::place::place_reached;
use super::refs::{reference_names, ConditionRefs, PositionRef, Triggering};
use super::road_state::{at_end_of_road, off_road};
use super::rule::compare;
use super::spacing::{distance_holds, time_headway, time_to_collision};
use super::target::Target;
use super::{ConditionContext, ConditionError, ConditionErrorKind, ConditionState};
use crate::position::{
    on_planned_route, resolve, resolve_with, EntityView, PositionError, PositionErrorKind,
};
use crate::world::EntityId;

/// The raw value of a ByEntityCondition (`refs`: its names resolved, condition/refs.rs).
pub(crate) fn evaluate<C: ConditionContext + ?Sized>(
    triggering: &TriggeringEntities,
    condition: &EntityCondition,
    refs: &ConditionRefs,
    ctx: &C,
    state: &mut ConditionState,
    pos: &SourcePos,
) -> Result<bool, ConditionError> {
    let mut any = false;
    let mut all = !triggering.entity_refs.is_empty();
    let mut held = Vec::new();
    // Each member once where the same one would follow itself (a selection's member after the
    // object itself, say).
    let mut last = None;
    // The condition's position, once worked out in this evaluation.
    let point = Cell::new(None);
    let mut visit = |id: EntityId, name: &str| -> Result<(), ConditionError> {
        if last == Some(id) {
            return Ok(());
        }
        last = Some(id);
        let e = ctx.entity_at(id).ok_or_else(|| {
            ConditionError::new(ConditionErrorKind::UnknownEntity(name.to_owned()), pos)
        })?;
        let holds = holds(condition, refs, ctx, (id, &e), state, &point)
            .map_err(|k| ConditionError::new(k, pos))?;
        any |= holds;
        all &= holds;
        if holds {
            held.push(id);
        }
        Ok(())
    };
    for (name, t) in triggering.entity_refs.iter().zip(&refs.triggering) {
        match *t {
            Triggering::Entity(id) => visit(id, name)?,
            // An EntityRef may name an EntitySelection: each member is a triggering entity.
            Triggering::Selection(s) => {
                for id in ctx.selection_members(s) {
                    visit(id, name)?;
                }
            }
        }
    }
    let value = match triggering.rule {
        TriggeringEntitiesRule::All => all,
        _ => any,
    };
    ctx.note_triggering(pos, value, &held);
    Ok(value)
}

/// The `i`-th reference entity of the condition (`refs.references`, in the order of
/// `refs::reference_names`), as it stands now.
fn reference<'c, C: ConditionContext + ?Sized>(
    ctx: &'c C,
    condition: &EntityCondition,
    refs: &ConditionRefs,
    i: usize,
) -> Result<(EntityId, EntityView<'c>), ConditionErrorKind> {
    let unknown = || {
        let name = reference_names(condition)
            .get(i)
            .map_or_else(String::new, |(n, _)| (*n).to_owned());
        ConditionErrorKind::UnknownEntity(name)
    };
    let id = *refs.references.get(i).ok_or_else(unknown)?;
    Ok((id, ctx.entity_at(id).ok_or_else(unknown)?))
}

/// The condition's position `p` as a point to measure to, as it is now: resolved before when
/// it depends on no entity, from its entity's pose by id when it is relative to one, placed on
/// its route planned before for FromCurrentEntity on an entity-free route, planned from its
/// names when it is a route or trajectory position relative to an entity (`refs.position`,
/// condition/refs.rs). `point` keeps it for the rest of the evaluation (module doc).
fn position_target<'c, C: ConditionContext + ?Sized>(
    ctx: &'c C,
    p: &scenario::Position,
    refs: &ConditionRefs,
    point: &Cell<Option<Pose>>,
) -> Result<Target<'c>, ConditionErrorKind> {
    if let Some(pose) = point.get() {
        return Ok(Target::Point(pose));
    }
    let by_id = |id: EntityId| {
        move |name: &str| {
            ctx.entity_at(id).ok_or_else(|| {
                PositionError::new(PositionErrorKind::UnknownEntity(name.into()), &p.pos)
            })
        }
    };
    let resolved = match &refs.position {
        Some(PositionRef::Fixed(pose)) => return Ok(Target::Point(*pose)),
        Some(PositionRef::Relative(id)) => resolve_with(p, ctx, by_id(*id)),
        Some(PositionRef::OnRoute(route, id)) => {
            on_planned_route(p, route, ctx.road_network(), by_id(*id))
        }
        // Refs from `ConditionRefs::resolve` hold the position of a condition that has one.
        Some(PositionRef::Planned) | None => resolve(p, ctx),
    };
    let pose = resolved.map_err(ConditionErrorKind::Position)?.pose;
    point.set(Some(pose));
    Ok(Target::Point(pose))
}

/// True when `duration` s have passed since `holds` became true for entity `id` without a
/// break.
fn held(state: &mut ConditionState, id: EntityId, holds: bool, now: Real, duration: Real) -> bool {
    state
        .held_for(id, holds, now)
        .is_some_and(|d| d + DURATION_TOLERANCE >= duration)
}

/// Whether `condition` holds for the triggering entity `e`.
fn holds<C: ConditionContext + ?Sized>(
    condition: &EntityCondition,
    refs: &ConditionRefs,
    ctx: &C,
    (id, e): (EntityId, &EntityView<'_>),
    state: &mut ConditionState,
    point: &Cell<Option<Pose>>,
) -> Result<bool, ConditionErrorKind> {
    let reference = |i| reference(ctx, condition, refs, i);
    let network = ctx.road_network();
    let now = ctx.simulation_time();
    let position_target = |p: &scenario::Position| position_target(ctx, p, refs, point);
    Ok(match condition {
        EntityCondition::EndOfRoad { duration } => {
            held(state, id, at_end_of_road(network, e), now, *duration)
        }
        EntityCondition::Offroad { duration } => {
            held(state, id, off_road(network, e), now, *duration)
        }
        EntityCondition::StandStill { duration } => {
            held(state, id, stands_still(e), now, *duration)
        }
        EntityCondition::Collision(CollisionTarget::EntityRef(_)) => {
            let (other, o) = reference(0)?;
            other != id && ctx.collided(e, &o)
        }
        EntityCondition::Collision(CollisionTarget::ByType(object_type)) => ctx
            .entities()
            .filter(|o| o.name != e.name && o.object_type == *object_type)
            .any(|o| ctx.collided(e, &o)),
        EntityCondition::Collision(_) => false,
        EntityCondition::TimeHeadway {
            entity_ref: _,
            value,
            rule,
            measure,
        } => {
            let (_, r) = reference(0)?;
            time_headway(ctx, e, &r, measure)?.is_some_and(|t| compare(t, *rule, *value))
        }
        EntityCondition::TimeToCollision {
            target,
            value,
            rule,
            measure,
        } => {
            let target = match target {
                TimeToCollisionTarget::EntityRef(_) => Target::Entity(reference(0)?.1),
                TimeToCollisionTarget::Position(p) => position_target(p)?,
                _ => return Ok(false),
            };
            time_to_collision(ctx, e, &target, measure)?.is_some_and(|t| compare(t, *rule, *value))
        }
        EntityCondition::Acceleration {
            value,
            rule,
            direction,
        } => compare(acceleration(e, *direction), *rule, *value),
        EntityCondition::Speed {
            value,
            rule,
            direction,
        } => compare(speed(e, *direction), *rule, *value),
        EntityCondition::RelativeSpeed {
            entity_ref: _,
            value,
            rule,
            direction,
        } => {
            let (_, r) = reference(0)?;
            compare(relative_speed(e, &r, *direction), *rule, *value)
        }
        EntityCondition::TraveledDistance { value } => {
            compare(e.odometer, scenario::Rule::GreaterOrEqual, *value)
        }
        EntityCondition::ReachPosition {
            position,
            tolerance,
        } => {
            let target = position_target(position)?;
            let measure = scenario::DistanceMeasure {
                freespace: false,
                coordinate_system: None,
                relative_distance_type: None,
                routing_algorithm: None,
            };
            distance_holds(
                ctx,
                e,
                &target,
                &measure,
                scenario::Rule::LessOrEqual,
                *tolerance,
            )?
        }
        EntityCondition::Distance {
            position,
            value,
            rule,
            measure,
        } => {
            let target = position_target(position)?;
            distance_holds(ctx, e, &target, measure, *rule, *value)?
        }
        EntityCondition::RelativeDistance {
            entity_ref: _,
            value,
            rule,
            measure,
        } => {
            let target = Target::Entity(reference(0)?.1);
            distance_holds(ctx, e, &target, measure, *rule, *value)?
        }
        EntityCondition::RelativeClearance {
            opposite_lanes,
            distance_forward,
            distance_backward,
            free_space,
            relative_lane_ranges,
            entity_refs,
        } => {
            // Only these entities count, each once, in the store's order (as the scene's).
            let mut only = (0..entity_refs.len())
                .map(reference)
                .collect::<Result<Vec<_>, _>>()?;
            only.sort_by_key(|(id, _)| *id);
            only.dedup_by_key(|(id, _)| *id);
            let only: Vec<EntityView<'_>> = only.into_iter().map(|(_, v)| v).collect();
            let c = Clearance {
                opposite_lanes: *opposite_lanes,
                distance_forward: *distance_forward,
                distance_backward: *distance_backward,
                free_space: *free_space,
                relative_lane_ranges,
                only: (!entity_refs.is_empty()).then_some(&only[..]),
            };
            clear(ctx, e, &c)?
        }
        EntityCondition::Angle {
            angle_type,
            angle,
            angle_tolerance,
            coordinate_system,
        } => own_angle(network, e, *angle_type, *coordinate_system)?
            .is_some_and(|a| within(a, *angle, *angle_tolerance)),
        EntityCondition::RelativeAngle {
            entity_ref: _,
            angle_type,
            angle,
            angle_tolerance,
            // Every frame gives the same difference (see `angle`).
            coordinate_system: _,
        } => {
            let (_, r) = reference(0)?;
            within(relative_angle(e, &r, *angle_type), *angle, *angle_tolerance)
        }
        EntityCondition::TraveledSinceMark { value, .. } => {
            traveled_since(e, refs.mark.and_then(|m| ctx.mark(m)), *value)
        }
        EntityCondition::PlaceReached { value, roads } => place_reached(network, e, *value, roads),
        EntityCondition::GapReachedSinceMark { gap, .. } => {
            let (_, r) = reference(0)?;
            let mark = refs.mark.and_then(|m| ctx.mark(m));
            gap_reached_since(network, now, e, &r, mark, gap)
        }
        _ => {
            return Err(ConditionErrorKind::Unsupported {
                expected: "an EntityCondition of OpenSCENARIO 1.3",
                found: "another kind",
            })
        }
    })
}
