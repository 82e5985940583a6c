//! What a replay needs of the scenario model beyond the frames (OpenSCENARIO 1.3 §7.3
//! storyboard, §7.6 conditions): the entity-to-entity distances and times its conditions
//! measure (TimeHeadwayCondition, TimeToCollisionCondition with an entity target,
//! RelativeDistanceCondition), the actors of each action, and each entity's ObjectControllers.

use scenario::{
    ActionKind, ConditionKind, CoordinateSystem, DistanceMeasure, EntityCondition,
    RelativeDistanceType, Scenario, TimeToCollisionTarget, Trigger,
};

use crate::manifest::{ActionActors, MeasureSpec};

/// Every entity-to-entity quantity a condition of the storyboard measures, one per
/// (condition, triggering entity), in document order (stop trigger of the storyboard last).
pub fn measures(scenario: &Scenario) -> Vec<MeasureSpec> {
    let sb = &scenario.storyboard;
    let mut triggers: Vec<&Trigger> = Vec::new();
    for story in &sb.stories {
        for act in &story.acts {
            triggers.extend(act.start_trigger.iter());
            for group in &act.maneuver_groups {
                for maneuver in &group.maneuvers {
                    for event in &maneuver.events {
                        triggers.extend(event.start_trigger.iter());
                    }
                }
            }
            triggers.extend(act.stop_trigger.iter());
        }
    }
    triggers.extend(sb.stop_trigger.iter());
    let mut out = Vec::new();
    for condition in triggers
        .into_iter()
        .flat_map(|t| &t.condition_groups)
        .flat_map(|g| &g.conditions)
    {
        let ConditionKind::ByEntity {
            triggering_entities,
            entity_condition,
        } = &condition.kind
        else {
            continue;
        };
        let (quantity, reference, rule, value, measure) = match entity_condition {
            EntityCondition::TimeHeadway {
                entity_ref,
                value,
                rule,
                measure,
            } => ("timeHeadway", entity_ref, rule, value, measure),
            EntityCondition::TimeToCollision {
                target: TimeToCollisionTarget::EntityRef(entity_ref),
                value,
                rule,
                measure,
            } => ("timeToCollision", entity_ref, rule, value, measure),
            EntityCondition::RelativeDistance {
                entity_ref,
                value,
                rule,
                measure,
            } => ("relativeDistance", entity_ref, rule, value, measure),
            _ => continue,
        };
        let references = scenario.entities.resolve(reference);
        for entity in triggering_entities
            .entity_refs
            .iter()
            .flat_map(|e| scenario.entities.resolve(e))
        {
            for reference in &references {
                out.push(spec(
                    &condition.name,
                    quantity,
                    entity,
                    reference,
                    measure,
                    *rule,
                    *value,
                ));
            }
        }
    }
    out
}

/// One measure's description.
fn spec(
    condition: &str,
    quantity: &str,
    entity: &str,
    reference: &str,
    measure: &DistanceMeasure,
    rule: scenario::Rule,
    value: f64,
) -> MeasureSpec {
    MeasureSpec {
        condition: condition.to_owned(),
        quantity: quantity.to_owned(),
        entity: entity.to_owned(),
        reference: reference.to_owned(),
        freespace: measure.freespace,
        coordinate_system: measure
            .coordinate_system
            .unwrap_or(CoordinateSystem::Entity)
            .as_str()
            .to_owned(),
        relative_distance_type: measure
            .relative_distance_type
            .unwrap_or(RelativeDistanceType::EuclidianDistance)
            .as_str()
            .to_owned(),
        rule: rule.as_str().to_owned(),
        value,
    }
}

/// Every action with the entities it acts on, named as the event log names it: Init actions
/// `Init ENTITY TYPE` (private) or `Init TYPE` (global), story actions by their name with
/// their ManeuverGroup's actors (selections expanded). A global action has no actors.
pub fn action_actors(scenario: &Scenario) -> Vec<ActionActors> {
    let sb = &scenario.storyboard;
    let mut out = Vec::new();
    for a in &sb.init.actions {
        out.push(ActionActors {
            name: format!("Init {}", a.kind.type_name()),
            kind: a.kind.type_name().to_owned(),
            actors: Vec::new(),
        });
    }
    for p in &sb.init.privates {
        for a in &p.actions {
            out.push(ActionActors {
                name: format!("Init {} {}", p.entity_ref, a.kind.type_name()),
                kind: a.kind.type_name().to_owned(),
                actors: scenario
                    .entities
                    .resolve(&p.entity_ref)
                    .into_iter()
                    .map(str::to_owned)
                    .collect(),
            });
        }
    }
    for group in sb
        .stories
        .iter()
        .flat_map(|s| &s.acts)
        .flat_map(|a| &a.maneuver_groups)
    {
        let actors: Vec<String> = group
            .actors
            .entity_refs
            .iter()
            .flat_map(|e| scenario.entities.resolve(e))
            .map(str::to_owned)
            .collect();
        for a in group
            .maneuvers
            .iter()
            .flat_map(|m| &m.events)
            .flat_map(|e| &e.actions)
        {
            let private = matches!(a.kind, ActionKind::Private(_));
            out.push(ActionActors {
                name: a.name.clone(),
                kind: a.kind.type_name().to_owned(),
                actors: if private { actors.clone() } else { Vec::new() },
            });
        }
    }
    out
}

/// The ObjectControllers of scenario object `name` (their `name`, else the controller's).
pub fn controllers(scenario: &Scenario, name: &str) -> Vec<String> {
    scenario
        .entities
        .object(name)
        .map(|o| {
            o.object_controllers
                .iter()
                .map(|c| c.name.clone().unwrap_or_else(|| c.controller.name.clone()))
                .collect()
        })
        .unwrap_or_default()
}
