//! Where OpenSCENARIO 1.3 §7.2.2.5 "Generalization of entities" restricts entity selections
//! and entity types, checked when the engine is built.
//!
//! References that need one position, lane or box must name a ScenarioObject, not an
//! EntitySelection: a RelativeTargetLane, RelativeTargetLaneOffset, RelativeTargetSpeed,
//! Longitudinal/LateralDistanceAction or SpeedProfileAction reference, and the reference entity
//! of TimeHeadway, TimeToCollision, RelativeSpeed, RelativeDistance and RelativeAngle
//! conditions ([`check_multiplicity`]). Motion and trailer actions must act on entity types
//! that can do them ([`check_actor_kinds`]).

use std::collections::HashMap;

use scenario::{
    Action, ActionKind, Condition, ConditionKind, EntityCondition, EntityObject, LateralAction,
    LongitudinalAction, PrivateAction, Scenario, ScenarioObject, SourcePos, SpeedTarget,
    TimeToCollisionTarget, Trigger,
};

use crate::error::Error;

/// Rejects an EntitySelection where §7.2.2.5 requires a single ScenarioObject (module doc).
pub(crate) fn check_multiplicity(scenario: &Scenario) -> Result<(), Error> {
    let selections = &scenario.entities.entity_selections;
    let check = |name: &str, what: &str, pos: &SourcePos| {
        if selections.iter().any(|s| s.name == name) {
            return Err(Error::at(
                format!("a ScenarioObject as the reference of {what} (§7.2.2.5)"),
                format!("EntitySelection '{name}'"),
                pos,
            ));
        }
        Ok(())
    };
    let sb = &scenario.storyboard;
    let mut actions: Vec<&Action> = sb.init.actions.iter().collect();
    actions.extend(sb.init.privates.iter().flat_map(|p| p.actions.iter()));
    let mut triggers: Vec<&Trigger> = sb.stop_trigger.iter().collect();
    for act in sb.stories.iter().flat_map(|s| &s.acts) {
        triggers.extend(act.start_trigger.iter().chain(act.stop_trigger.iter()));
        for ev in act
            .maneuver_groups
            .iter()
            .flat_map(|g| &g.maneuvers)
            .flat_map(|m| &m.events)
        {
            actions.extend(ev.actions.iter());
            triggers.extend(ev.start_trigger.iter());
        }
    }
    for a in actions {
        if let Some((name, what)) = action_reference(a) {
            check(name, what, &a.pos)?;
        }
    }
    for c in triggers
        .iter()
        .flat_map(|t| &t.condition_groups)
        .flat_map(|g| &g.conditions)
    {
        if let Some((name, what)) = condition_reference(c) {
            check(name, what, &c.pos)?;
        }
    }
    Ok(())
}

/// Rejects private actions on entities they cannot apply to (§7.2.2.5, first restriction):
/// motion (Longitudinal, Lateral, Synchronize) on an ExternalObjectReference (an object of the
/// road network; §7.2.2 lets Vehicle, Pedestrian and MiscObject instances move), and
/// TrailerAction on anything but a Vehicle. Actors are the Init `Private` entity and the
/// ManeuverGroup actors with selections expanded to their declared members.
pub(crate) fn check_actor_kinds<'s>(scenario: &'s Scenario) -> Result<(), Error> {
    let entities = &scenario.entities;
    // The scenario objects by name, the first of a name as `Entities::object` finds it: one
    // look-up per actor instead of a scan of every object (issue 31: 4,000 vehicles).
    let mut objects: HashMap<&str, &ScenarioObject> = HashMap::new();
    for o in &entities.scenario_objects {
        objects.entry(o.name.as_str()).or_insert(o);
    }
    // `Entities::resolve` with the objects' look-up above.
    let resolve = |name: &'s str| -> Vec<&'s str> {
        if objects.contains_key(name) {
            return vec![name];
        }
        entities.resolve(name)
    };
    let check = |actor_refs: &'s [String], a: &Action| {
        let ActionKind::Private(p) = &a.kind else {
            return Ok(());
        };
        let (what, vehicle_only) = match p {
            PrivateAction::Longitudinal(_) => ("a LongitudinalAction", false),
            PrivateAction::Lateral(_) => ("a LateralAction", false),
            PrivateAction::Synchronize(_) => ("a SynchronizeAction", false),
            PrivateAction::Trailer(_) => ("a TrailerAction", true),
            _ => return Ok(()),
        };
        for name in actor_refs.iter().flat_map(|r| resolve(r)) {
            let Some(&object) = objects.get(name) else {
                continue;
            };
            let (kind, allowed) = match &object.entity_object {
                EntityObject::Vehicle(_) => ("Vehicle", true),
                EntityObject::Pedestrian(_) => ("Pedestrian", !vehicle_only),
                EntityObject::MiscObject(_) => ("MiscObject", !vehicle_only),
                _ => ("ExternalObjectReference", false),
            };
            if !allowed {
                let expected = if vehicle_only {
                    format!("a Vehicle as the actor of {what} (§7.2.2.5)")
                } else {
                    format!("a Vehicle, Pedestrian or MiscObject as the actor of {what} (§7.2.2.5)")
                };
                return Err(Error::at(expected, format!("{kind} '{name}'"), &a.pos));
            }
        }
        Ok(())
    };
    let sb = &scenario.storyboard;
    for p in &sb.init.privates {
        for a in &p.actions {
            check(std::slice::from_ref(&p.entity_ref), a)?;
        }
    }
    for act in sb.stories.iter().flat_map(|s| &s.acts) {
        for g in &act.maneuver_groups {
            for a in g
                .maneuvers
                .iter()
                .flat_map(|m| &m.events)
                .flat_map(|e| &e.actions)
            {
                check(&g.actors.entity_refs, a)?;
            }
        }
    }
    Ok(())
}

/// The single-entity reference of a private action, with the element's name.
fn action_reference(a: &Action) -> Option<(&str, &'static str)> {
    let ActionKind::Private(p) = &a.kind else {
        return None;
    };
    match p {
        PrivateAction::Longitudinal(l) => match l {
            LongitudinalAction::Speed {
                target:
                    SpeedTarget::Relative { entity_ref, .. }
                    | SpeedTarget::RelativeAtStart { entity_ref, .. },
                ..
            } => Some((entity_ref, "a RelativeTargetSpeed")),
            LongitudinalAction::LongitudinalDistance { entity_ref, .. } => {
                Some((entity_ref, "a LongitudinalDistanceAction"))
            }
            LongitudinalAction::RelativeAcceleration { entity_ref, .. } => {
                Some((entity_ref, "a RelativeAccelerationAction"))
            }
            LongitudinalAction::ModelAcceleration { target: Some(t) } => match t {
                scenario::ModelAcceleration::Relative { entity_ref, .. } => {
                    Some((entity_ref, "a driver model's free-road acceleration"))
                }
                scenario::ModelAcceleration::Toward {
                    of: Some(scenario::SpeedOf { entity_ref, .. }),
                    ..
                } => Some((entity_ref, "a driver model's desired speed")),
                scenario::ModelAcceleration::Toward { rate, .. } => match &**rate {
                    scenario::ModelAcceleration::Relative { entity_ref, .. } => {
                        Some((entity_ref, "a driver model's free-road acceleration"))
                    }
                    _ => None,
                },
                _ => None,
            },
            LongitudinalAction::SpeedProfile {
                entity_ref: Some(entity_ref),
                ..
            } => Some((entity_ref, "a SpeedProfileAction")),
            _ => None,
        },
        PrivateAction::Lateral(l) => match l {
            LateralAction::LaneChange {
                target: scenario::LaneChangeTarget::Relative { entity_ref, .. },
                ..
            } => Some((entity_ref, "a RelativeTargetLane")),
            LateralAction::LaneChange {
                target: scenario::LaneChangeTarget::Beside { entity_ref, .. },
                ..
            } => Some((entity_ref, "a lane change beside an entity")),
            LateralAction::LaneChange {
                target: scenario::LaneChangeTarget::Numbered { entity_ref, .. },
                ..
            } => Some((entity_ref, "a lane numbered across an entity's road")),
            LateralAction::MandatoryLane {
                target: Some(scenario::LaneChangeTarget::Relative { entity_ref, .. }),
            } => Some((entity_ref, "a RelativeTargetLane")),
            LateralAction::LaneOffset {
                target: scenario::LaneOffsetTarget::Relative { entity_ref, .. },
                ..
            } => Some((entity_ref, "a RelativeTargetLaneOffset")),
            LateralAction::LateralDistance { entity_ref, .. } => {
                Some((entity_ref, "a LateralDistanceAction"))
            }
            _ => None,
        },
        _ => None,
    }
}

/// The reference entity of an EntityCondition, with the element's name.
fn condition_reference(c: &Condition) -> Option<(&str, &'static str)> {
    let ConditionKind::ByEntity {
        entity_condition, ..
    } = &c.kind
    else {
        return None;
    };
    match entity_condition {
        EntityCondition::TimeHeadway { entity_ref, .. } => {
            Some((entity_ref, "a TimeHeadwayCondition"))
        }
        EntityCondition::TimeToCollision {
            target: TimeToCollisionTarget::EntityRef(entity_ref),
            ..
        } => Some((entity_ref, "a TimeToCollisionCondition")),
        EntityCondition::RelativeSpeed { entity_ref, .. } => {
            Some((entity_ref, "a RelativeSpeedCondition"))
        }
        EntityCondition::RelativeDistance { entity_ref, .. } => {
            Some((entity_ref, "a RelativeDistanceCondition"))
        }
        EntityCondition::RelativeAngle { entity_ref, .. } => {
            Some((entity_ref, "a RelativeAngleCondition"))
        }
        _ => None,
    }
}
