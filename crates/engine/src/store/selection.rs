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
//!   current member and combined by `any`/`all` (§7.2.2.2); the condition holds the
//!   selection's handle ([`Selections::id`], resolved when the storyboard is built) and reads
//!   its members by it ([`Selections::members_of`]);
//! * as ManeuverGroup actors: each private action runs per member, the members taken when the
//!   action starts.
//!
//! * with `Actors/@selectTriggeringEntities` (§7.3.1): the entities that made the parent Act's
//!   start trigger fire join the actors when each action starts (`triggering`); an Act without
//!   a start trigger starts with its Story and selects no one.
//!
//! The §7.2.2.5 restrictions on where a selection may stand and which entity types an action
//! applies to are checked when the engine is built (`restrictions`, [`check_multiplicity`],
//! [`check_actor_kinds`]). Selection cycles are rejected by the scenario loader.

use std::collections::BTreeMap;

use scenario::{EntitySelection, Scenario, SelectionMember};

use crate::condition::SelectionId;
use crate::storyboard::{ActionId, ConditionId};
use crate::world::entity::{Entity, EntityId};

mod restrictions;
mod triggering;

pub(crate) use restrictions::{check_actor_kinds, check_multiplicity};
pub(crate) use triggering::ConditionRef;
use triggering::TriggerReports;

/// What a selection reads of the world store: its entities and their names (the store's
/// `World` implements it; the seam keeps this module below the `World` that holds the
/// selections).
pub(crate) trait Entities {
    /// All entities in declaration order.
    fn entities(&self) -> &[Entity];
    /// The entity with handle `id`.
    fn entity(&self, id: EntityId) -> &Entity;
    /// The handle of the entity called `name`.
    fn id(&self, name: &str) -> Option<EntityId>;
}

/// The actors of the actions of one ManeuverGroup, worked out when each action starts.
#[derive(Debug, Clone, Default)]
pub(crate) struct ActorSpec {
    /// The EntityRefs of `Actors` (objects or selections).
    pub refs: Vec<String>,
    /// With `selectTriggeringEntities`: the conditions of the parent Act's start trigger, per
    /// condition group.
    pub triggering: Option<Vec<Vec<ConditionRef>>>,
}

/// The scenario's entity selections, as declared.
#[derive(Debug, Clone, Default)]
pub(crate) struct Selections {
    defs: Vec<EntitySelection>,
    /// Actions whose actors name a selection or select triggering entities.
    actors: BTreeMap<ActionId, ActorSpec>,
    /// What the conditions of those Acts' start triggers reported.
    reports: TriggerReports,
}

impl Selections {
    /// The selections of `scenario`.
    pub(crate) fn new(scenario: &Scenario) -> Self {
        Selections {
            defs: scenario.entities.entity_selections.clone(),
            actors: BTreeMap::new(),
            reports: TriggerReports::default(),
        }
    }

    /// Records the actions whose ManeuverGroup actors name a selection or select triggering
    /// entities.
    pub(crate) fn set_actors(&mut self, actors: Vec<(ActionId, ActorSpec)>) {
        for c in actors
            .iter()
            .filter_map(|(_, spec)| spec.triggering.as_ref())
            .flatten()
            .flatten()
        {
            self.reports.watch(c);
        }
        self.actors = actors.into_iter().collect();
    }

    /// Records an evaluation of condition `id` at `time`: its raw value and the triggering
    /// entities it held for (`triggering`).
    pub(crate) fn note_triggering(
        &self,
        id: ConditionId,
        time: f64,
        value: bool,
        held: &[EntityId],
    ) {
        self.reports.note(id, time, value, held);
    }

    /// The actors of action `id` now, if its ManeuverGroup names a selection or selects
    /// triggering entities: objects as named, selections by their current members, then the
    /// triggering entities, each once, in that order.
    pub(crate) fn actors_now(&self, id: ActionId, world: &dyn Entities) -> Option<Vec<EntityId>> {
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
            let ids = self.reports.entities(groups);
            add(ids
                .into_iter()
                .filter(|&id| world.entity(id).placed)
                .collect());
        }
        Some(out)
    }

    fn find(&self, name: &str) -> Option<&EntitySelection> {
        self.defs.iter().find(|s| s.name == name)
    }

    /// The handle of selection `name` (its index in declaration order), `None` if `name` is
    /// not a selection: what a condition's triggering entities are resolved to when the
    /// storyboard is built (condition/refs.rs).
    pub(crate) fn id(&self, name: &str) -> Option<SelectionId> {
        self.defs
            .iter()
            .position(|s| s.name == name)
            .map(|i| SelectionId(i as u32))
    }

    /// The placed members of selection `id` now, in id order (none for a handle not from
    /// [`Selections::id`]).
    pub(crate) fn members_of(&self, world: &dyn Entities, id: SelectionId) -> Vec<EntityId> {
        self.defs
            .get(id.0 as usize)
            .map(|s| self.placed_members(world, s))
            .unwrap_or_default()
    }

    /// The placed members of selection `name` now, in id order; `None` if `name` is not a
    /// selection.
    pub(crate) fn members(&self, world: &dyn Entities, name: &str) -> Option<Vec<EntityId>> {
        Some(self.placed_members(world, self.find(name)?))
    }

    /// The placed members of `selection` now, in id order.
    fn placed_members(&self, world: &dyn Entities, selection: &EntitySelection) -> Vec<EntityId> {
        let mut flags = vec![false; world.entities().len()];
        let mut visiting = Vec::new();
        self.collect(world, selection, &mut visiting, &mut flags);
        world
            .entities()
            .iter()
            .zip(flags)
            .filter(|(e, f)| *f && e.placed)
            .map(|(e, _)| e.id)
            .collect()
    }

    fn collect<'s>(
        &'s self,
        world: &dyn Entities,
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
}
