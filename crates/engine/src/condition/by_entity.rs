//! ByEntityCondition (OpenSCENARIO 1.3 §7.6.3, XSD `ByEntityCondition`,
//! `TriggeringEntities`): an EntityCondition tested for each triggering entity, combined by
//! `triggeringEntitiesRule` — `any`: true when it holds for at least one, `all`: when it holds
//! for every one. An EntityRef naming an EntitySelection stands for all its members. Every
//! triggering entity is evaluated each time (no short cut), so that the duration conditions
//! keep their memory of each. The entities for which it held are reported to the context
//! ([`ConditionContext::note_triggering`]) for `selectTriggeringEntities` (§7.3.1).

use opendrive::Real;
use scenario::{
    CollisionTarget, EntityCondition, SourcePos, TimeToCollisionTarget, TriggeringEntities,
    TriggeringEntitiesRule,
};

use super::angle::{own_angle, relative_angle, within};
use super::clearance::{clear, Clearance};
use super::mark::{gap_reached_since, traveled_since};
use super::motion::{acceleration, relative_speed, speed, stands_still, DURATION_TOLERANCE};
use super::place::place_reached;
use super::road_state::{at_end_of_road, off_road};
use super::rule::compare;
use super::spacing::{distance_holds, time_headway, time_to_collision};
use super::target::Target;
use super::{ConditionContext, ConditionError, ConditionErrorKind, ConditionState};
use crate::position::{resolve, EntityView};

/// The raw value of a ByEntityCondition.
pub(crate) fn evaluate<C: ConditionContext + ?Sized>(
    triggering: &TriggeringEntities,
    condition: &EntityCondition,
    ctx: &C,
    state: &mut ConditionState,
    pos: &SourcePos,
) -> Result<bool, ConditionError> {
    let mut any = false;
    let mut all = !triggering.entity_refs.is_empty();
    let mut held = Vec::new();
    for name in &triggering.entity_refs {
        // An EntityRef may name an EntitySelection: each member is a triggering entity.
        let members = match ctx.entity(name) {
            Some(_) => vec![name.clone()],
            None => ctx.entity_selection(name).ok_or_else(|| {
                ConditionError::new(ConditionErrorKind::UnknownEntity(name.clone()), pos)
            })?,
        };
        for member in &members {
            let e = ctx.entity(member).ok_or_else(|| {
                ConditionError::new(ConditionErrorKind::UnknownEntity(member.clone()), pos)
            })?;
            let holds =
                holds(condition, ctx, &e, state).map_err(|k| ConditionError::new(k, pos))?;
            any |= holds;
            all &= holds;
            if holds {
                held.push(member.clone());
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

/// The reference entity `name`.
fn reference<'c, C: ConditionContext + ?Sized>(
    ctx: &'c C,
    name: &str,
) -> Result<EntityView<'c>, ConditionErrorKind> {
    ctx.entity(name)
        .ok_or_else(|| ConditionErrorKind::UnknownEntity(name.to_string()))
}

/// True when `duration` s have passed since `holds` became true for `e` without a break.
fn held(
    state: &mut ConditionState,
    e: &EntityView<'_>,
    holds: bool,
    now: Real,
    duration: Real,
) -> bool {
    state
        .held_for(e.name, holds, now)
        .is_some_and(|d| d + DURATION_TOLERANCE >= duration)
}

/// Whether `condition` holds for the triggering entity `e`.
fn holds<C: ConditionContext + ?Sized>(
    condition: &EntityCondition,
    ctx: &C,
    e: &EntityView<'_>,
    state: &mut ConditionState,
) -> Result<bool, ConditionErrorKind> {
    let network = ctx.road_network();
    let now = ctx.simulation_time();
    let position_target = |p: &scenario::Position| {
        resolve(p, ctx)
            .map(|r| Target::Point(r.pose))
            .map_err(ConditionErrorKind::Position)
    };
    Ok(match condition {
        EntityCondition::EndOfRoad { duration } => {
            held(state, e, at_end_of_road(network, e), now, *duration)
        }
        EntityCondition::Offroad { duration } => {
            held(state, e, off_road(network, e), now, *duration)
        }
        EntityCondition::StandStill { duration } => held(state, e, stands_still(e), now, *duration),
        EntityCondition::Collision(CollisionTarget::EntityRef(name)) => {
            reference(ctx, name)?;
            ctx.collided(e.name, name)
        }
        EntityCondition::Collision(CollisionTarget::ByType(object_type)) => ctx
            .entities()
            .filter(|o| o.name != e.name && o.object_type == *object_type)
            .any(|o| ctx.collided(e.name, o.name)),
        EntityCondition::Collision(_) => false,
        EntityCondition::TimeHeadway {
            entity_ref,
            value,
            rule,
            measure,
        } => {
            let r = reference(ctx, entity_ref)?;
            time_headway(ctx, e, &r, measure)?.is_some_and(|t| compare(t, *rule, *value))
        }
        EntityCondition::TimeToCollision {
            target,
            value,
            rule,
            measure,
        } => {
            let target = match target {
                TimeToCollisionTarget::EntityRef(name) => Target::Entity(reference(ctx, name)?),
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
            entity_ref,
            value,
            rule,
            direction,
        } => {
            let r = reference(ctx, entity_ref)?;
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
            entity_ref,
            value,
            rule,
            measure,
        } => {
            let target = Target::Entity(reference(ctx, entity_ref)?);
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
            for name in entity_refs {
                reference(ctx, name)?;
            }
            let c = Clearance {
                opposite_lanes: *opposite_lanes,
                distance_forward: *distance_forward,
                distance_backward: *distance_backward,
                free_space: *free_space,
                relative_lane_ranges,
                entity_refs,
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
            entity_ref,
            angle_type,
            angle,
            angle_tolerance,
            // Every frame gives the same difference (see `angle`).
            coordinate_system: _,
        } => {
            let r = reference(ctx, entity_ref)?;
            within(relative_angle(e, &r, *angle_type), *angle, *angle_tolerance)
        }
        EntityCondition::TraveledSinceMark { mark, value } => {
            traveled_since(e, ctx.mark(mark).as_ref(), *value)
        }
        EntityCondition::PlaceReached { value, roads } => place_reached(network, e, *value, roads),
        EntityCondition::GapReachedSinceMark { mark, gap } => {
            let r = reference(ctx, &gap.entity_ref)?;
            gap_reached_since(network, now, e, &r, ctx.mark(mark).as_ref(), gap)
        }
        _ => {
            return Err(ConditionErrorKind::Unsupported {
                expected: "an EntityCondition of OpenSCENARIO 1.3",
                found: "another kind",
            })
        }
    })
}
