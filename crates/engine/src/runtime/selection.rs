//! EntitySelection at runtime (OpenSCENARIO 1.3 §7.2.2.2 "Entity selections", §7.2.2.3
//! "Spawned objects", §7.2.2.4, §7.2.2.5 "Generalization of entities").
//!
//! A selection's members are worked out against the world when they are used, not once at
//! load: EntityRef members (objects, or nested selections recursively) and ByType members,
//! which take every entity of that type in the store, spawned vehicles included. Only placed
//! entities are members, so a deleted or sunk vehicle drops out, and a vehicle spawned in a
//! step counts from the next step's triggers on. Members come once each, in id order.
//!
//! Where a selection is used:
//! * as `TriggeringEntities` (each condition evaluation): the condition is evaluated for every
//!   current member and combined by `any`/`all` (§7.2.2.2);
//! * as ManeuverGroup actors: each private action runs per member, the members taken when the
//!   action starts.
//!
//! `Actors/@selectTriggeringEntities` (§7.3.1 "ManeuverGroups and Actors"): when true, the
//! entities that made the parent Act's start trigger fire are actors too, in addition to (the
//! union with) the EntityRefs. "Entities become actors if … their states are used by the
//! logical expressions in Conditions, the Conditions using the states evaluate to true, [and
//! are] contained in ConditionGroups that evaluate to true", the condition groups being those
//! of the parent Act. oscsim reads this as: the TriggeringEntities of the Act's
//! ByEntityConditions for which the EntityCondition held when the Act started, over the
//! condition groups whose conditions were all true then. Each condition reports its raw value
//! (and a ByEntityCondition those entities) at every evaluation
//! ([`Selections::note_triggering`]); an Act's start trigger is evaluated only until the Act
//! starts, so its last report is the one of the firing step.
//! When a condition's `delay` or edge makes the group fire although no group holds at that
//! moment, every group's entities are taken (the per-entity history a delay shifts is not
//! kept). An Act without a start trigger starts with its Story and selects no one.
//!
//! §7.2.2.5 restricts references that need one position, lane or box: a RelativeTargetLane,
//! RelativeTargetLaneOffset, RelativeTargetSpeed, Longitudinal/LateralDistanceAction or
//! SpeedProfileAction reference, and the reference entity of TimeHeadway, TimeToCollision,
//! RelativeSpeed, RelativeDistance and RelativeAngle conditions must be a ScenarioObject;
//! [`check_multiplicity`] rejects a selection there when the engine is built, and
//! [`check_actor_kinds`] actions on entity types they cannot apply to. Selection cycles are
//! rejected by the scenario loader.

use std::borrow::Cow;
use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap};

use scenario::{
    Action, ActionKind, Condition, ConditionKind, EntityCondition, EntityObject, EntitySelection,
    LateralAction, LongitudinalAction, PrivateAction, Scenario, SelectionMember, SourcePos,
    SpeedTarget, TimeToCollisionTarget, Trigger,
};

use super::entity::EntityId;
use super::error::RuntimeError;
use super::world::World;
use crate::storyboard::ActionId;

/// The actors of the actions of one ManeuverGroup, worked out when each action starts.
#[derive(Debug, Clone, Default)]
pub(crate) struct ActorSpec {
    /// The EntityRefs of `Actors` (objects or selections).
    pub refs: Vec<String>,
    /// With `selectTriggeringEntities`: the positions of the conditions of the parent Act's
    /// start trigger, per condition group.
    pub triggering: Option<Vec<Vec<SourcePos>>>,
}

/// The last report of one ByEntityCondition: its raw value and the entities it held for.
type Report = (bool, Vec<String>);

/// The scenario's entity selections, as declared.
#[derive(Debug, Clone, Default)]
pub(crate) struct Selections {
    defs: Vec<EntitySelection>,
    /// Actions whose actors name a selection or select triggering entities.
    actors: BTreeMap<ActionId, ActorSpec>,
    /// The last report of each condition, by its position in the file. Written while
    /// conditions are evaluated (they see the world read-only).
    reports: RefCell<HashMap<SourcePos, Report>>,
}

impl Selections {
    /// The selections of `scenario`.
    pub(crate) fn new(scenario: &Scenario) -> Self {
        Selections {
            defs: scenario.entities.entity_selections.clone(),
            actors: BTreeMap::new(),
            reports: RefCell::new(HashMap::new()),
        }
    }

    /// Records the actions whose ManeuverGroup actors name a selection or select triggering
    /// entities.
    pub(crate) fn set_actors(&mut self, actors: Vec<(ActionId, ActorSpec)>) {
        self.actors = actors.into_iter().collect();
    }

    /// Keeps the raw value of the condition at `pos` and the triggering entities it held for
    /// (module doc).
    pub(crate) fn note_triggering(&self, pos: &SourcePos, value: bool, held: &[String]) {
        self.reports
            .borrow_mut()
            .insert(pos.clone(), (value, held.to_vec()));
    }

    /// The actors of action `id` now, if its ManeuverGroup names a selection or selects
    /// triggering entities: objects as named, selections by their current members, then the
    /// triggering entities, each once, in that order.
    pub(crate) fn actors_now(&self, id: ActionId, world: &World) -> Option<Vec<EntityId>> {
        let spec = self.actors.get(&id)?;
        let mut out: Vec<EntityId> = Vec::new();
        let mut add = |ids: Vec<EntityId>| {
            for id in ids {
                if !out.contains(&id) {
                    out.push(id);
                }
            }
        };
        for r in &spec.refs {
            add(self
                .members(world, r)
                .unwrap_or_else(|| world.id(r).into_iter().collect()));
        }
        if let Some(groups) = &spec.triggering {
            let names = self.triggering_entities(groups);
            add(names
                .iter()
                .filter_map(|n| world.id(n))
                .filter(|&id| world.entity(id).placed)
                .collect());
        }
        Some(out)
    }

    /// The triggering entities of a start trigger with these condition `groups` as last
    /// reported (module doc): over the groups whose conditions all held, else over all.
    fn triggering_entities(&self, groups: &[Vec<SourcePos>]) -> Vec<String> {
        let reports = self.reports.borrow();
        let holds = |g: &Vec<SourcePos>| g.iter().all(|p| reports.get(p).is_some_and(|r| r.0));
        let firing: Vec<&Vec<SourcePos>> = groups.iter().filter(|g| holds(g)).collect();
        let chosen = if firing.is_empty() {
            groups.iter().collect()
        } else {
            firing
        };
        let mut names: Vec<String> = Vec::new();
        for pos in chosen.into_iter().flatten() {
            for n in reports.get(pos).map_or(&[][..], |r| &r.1[..]) {
                if !names.contains(n) {
                    names.push(n.clone());
                }
            }
        }
        names
    }

    fn find(&self, name: &str) -> Option<&EntitySelection> {
        self.defs.iter().find(|s| s.name == name)
    }

    /// The placed members of selection `name` now, in id order; `None` if `name` is not a
    /// selection.
    pub(crate) fn members(&self, world: &World, name: &str) -> Option<Vec<EntityId>> {
        let selection = self.find(name)?;
        let mut flags = vec![false; world.entities().len()];
        let mut visiting = Vec::new();
        self.collect(world, selection, &mut visiting, &mut flags);
        Some(
            world
                .entities()
                .iter()
                .zip(flags)
                .filter(|(e, f)| *f && e.placed)
                .map(|(e, _)| e.id)
                .collect(),
        )
    }

    fn collect<'s>(
        &'s self,
        world: &World,
        selection: &'s EntitySelection,
        visiting: &mut Vec<&'s str>,
        flags: &mut [bool],
    ) {
        // The loader rejects cycles; a revisit is skipped all the same.
        if visiting.contains(&selection.name.as_str()) {
            return;
        }
        visiting.push(&selection.name);
        for m in &selection.members {
            match m {
                SelectionMember::EntityRef(name) => {
                    if let Some(nested) = self.find(name) {
                        self.collect(world, nested, visiting, flags);
                    } else if let Some(id) = world.id(name) {
                        flags[id.index()] = true;
                    }
                }
                SelectionMember::ByType(t) => {
                    for e in world.entities() {
                        if e.kind.object_type() == *t {
                            flags[e.id.index()] = true;
                        }
                    }
                }
                _ => {}
            }
        }
        visiting.pop();
    }

    /// `condition` with every selection among its triggering entities replaced by the names
    /// of its current members (unchanged when it names none).
    pub(crate) fn expand_condition<'c>(
        &self,
        world: &World,
        condition: &'c Condition,
    ) -> Cow<'c, Condition> {
        let ConditionKind::ByEntity {
            triggering_entities,
            ..
        } = &condition.kind
        else {
            return Cow::Borrowed(condition);
        };
        if !triggering_entities
            .entity_refs
            .iter()
            .any(|n| self.find(n).is_some())
        {
            return Cow::Borrowed(condition);
        }
        let mut names: Vec<String> = Vec::new();
        for n in &triggering_entities.entity_refs {
            match self.members(world, n) {
                Some(ids) => names.extend(ids.iter().map(|&id| world.entity(id).name.clone())),
                None => names.push(n.clone()),
            }
        }
        names.dedup();
        let mut expanded = condition.clone();
        if let ConditionKind::ByEntity {
            triggering_entities,
            ..
        } = &mut expanded.kind
        {
            triggering_entities.entity_refs = names;
        }
        Cow::Owned(expanded)
    }
}

/// Rejects an EntitySelection where §7.2.2.5 requires a single ScenarioObject (module doc).
pub(crate) fn check_multiplicity(scenario: &Scenario) -> Result<(), RuntimeError> {
    let selections = &scenario.entities.entity_selections;
    let check = |name: &str, what: &str, pos: &SourcePos| {
        if selections.iter().any(|s| s.name == name) {
            return Err(RuntimeError::at(
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
pub(crate) fn check_actor_kinds(scenario: &Scenario) -> Result<(), RuntimeError> {
    let entities = &scenario.entities;
    let check = |actor_refs: &[String], a: &Action| {
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
        for name in actor_refs.iter().flat_map(|r| entities.resolve(r)) {
            let Some(object) = entities.object(name) else {
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
                return Err(RuntimeError::at(
                    expected,
                    format!("{kind} '{name}'"),
                    &a.pos,
                ));
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
                target: SpeedTarget::Relative { entity_ref, .. },
                ..
            } => Some((entity_ref, "a RelativeTargetSpeed")),
            LongitudinalAction::LongitudinalDistance { entity_ref, .. } => {
                Some((entity_ref, "a LongitudinalDistanceAction"))
            }
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
