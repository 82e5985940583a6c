//! Building a runnable engine from the loaded scenario and its road network (OpenSCENARIO 1.3
//! §7.1–7.3 and §8.5): one [`Entity`] per ScenarioObject, parameter and variable values, and the
//! storyboard description with a table entry per action and per condition.
//!
//! Names in the event log: storyboard elements keep their names; Init actions, which have none
//! in the file, are named `Init ENTITY ACTIONTYPE` (esmini's form), global Init actions
//! `Init ACTIONTYPE`; ACTIONTYPE is the XSD element name, `scenario::ActionKind::type_name`
//! (the replay names them by it too).

use std::collections::BTreeMap;
use std::sync::Arc;

use opendrive::RoadNetwork;
use scenario::{Action, Actors, Scenario, Trigger};

use crate::actions::ActionTable;
use crate::condition::{ConditionRefs, MarkIds, Names, RefError};
use crate::controller::ControllerTable;
use crate::error::{Error, ErrorKind};
use crate::store::{entity, World};
use crate::storyboard::{
    ActDesc, ActionDesc, ConditionDesc, ConditionEdge, ConditionGroupDesc, ConditionId, EventDesc,
    ManeuverDesc, ManeuverGroupDesc, Priority, StoryDesc, StoryboardDesc, TriggerDesc,
};
use crate::world::entity::EntityId;

/// What [`build`] produces.
pub(crate) struct Built {
    pub world: World,
    /// The user controllers of the scenario's ObjectControllers (engine module `controller`).
    pub controllers: ControllerTable,
    pub desc: StoryboardDesc,
    pub actions: ActionTable,
    pub conditions: Vec<scenario::Condition>,
    /// Per condition: its names resolved in the world (condition/refs.rs).
    pub condition_refs: Vec<ConditionRefs>,
}

/// Builds world, storyboard description and tables from `scenario` on `network`; `seed` is
/// the run's ([`EngineConfig::seed`](crate::EngineConfig::seed)), set on the world before the
/// conditions' entity-free routes are planned with it (condition/refs.rs).
pub(crate) fn build(
    scenario: &Scenario,
    network: Arc<RoadNetwork>,
    seed: u64,
) -> Result<Built, Error> {
    let mut entities = scenario
        .entities
        .scenario_objects
        .iter()
        .enumerate()
        .map(|(i, o)| entity(EntityId(i as u32), o))
        .collect::<Result<Vec<_>, _>>()?;
    let trailers = crate::store::trailer::from_definitions(scenario, &mut entities, entity)?;
    let mut world = World::new(network, entities);
    world.seed = seed;
    world.trailers = trailers;
    crate::store::selection::check_multiplicity(scenario)?;
    crate::store::selection::check_actor_kinds(scenario)?;
    super::external::place_external_objects(scenario, &mut world)?;
    world.selections = crate::store::selection::Selections::new(scenario);
    world.parameters = scenario
        .parameter_declarations
        .iter()
        .map(|p| (p.name.clone(), p.value.clone()))
        .collect::<BTreeMap<_, _>>();
    world.parameter_constraints = scenario
        .parameter_declarations
        .iter()
        .filter(|p| !p.constraint_groups.is_empty())
        .map(|p| (p.name.clone(), p.constraint_groups.clone()))
        .collect();
    world.signals = crate::signals::Signals::new(
        &scenario.road_network.traffic_signal_controllers,
        world.network.controllers(),
    )?;
    world.monitors = scenario
        .monitor_declarations
        .iter()
        .map(|m| (m.name.clone(), m.value))
        .collect();
    world.variables = scenario
        .variable_declarations
        .iter()
        .map(|v| (v.name.clone(), v.value.clone()))
        .collect();
    let mut b = Builder {
        scenario,
        world: &world,
        actions: ActionTable::default(),
        conditions: Vec::new(),
        condition_refs: Vec::new(),
        marks: MarkIds::default(),
        selection_actors: Vec::new(),
    };
    let desc = b.storyboard()?;
    let (actions, conditions, condition_refs) = (b.actions, b.conditions, b.condition_refs);
    let (marks, selection_actors) = (b.marks, b.selection_actors);
    world.marks = marks.store();
    world.mark_ids = marks;
    world.selections.set_actors(selection_actors);
    let controllers = crate::controller::set_up(
        scenario,
        &mut world,
        actions.slots.iter().map(|slot| &slot.action),
    )?;
    Ok(Built {
        world,
        controllers,
        desc,
        actions,
        conditions,
        condition_refs,
    })
}

struct Builder<'a> {
    scenario: &'a Scenario,
    world: &'a World,
    actions: ActionTable,
    conditions: Vec<scenario::Condition>,
    /// Per condition of `conditions`: its names resolved.
    condition_refs: Vec<ConditionRefs>,
    /// The marks' slots, given as checks and conditions name them.
    marks: MarkIds,
    /// Actions whose ManeuverGroup actors name a selection or select triggering entities,
    /// worked out at each start.
    selection_actors: Vec<(
        crate::storyboard::ActionId,
        crate::store::selection::ActorSpec,
    )>,
}

impl Builder<'_> {
    fn storyboard(&mut self) -> Result<StoryboardDesc, Error> {
        let sb = &self.scenario.storyboard;
        let mut init_actions = Vec::new();
        for a in &sb.init.actions {
            let name = format!("Init {}", a.kind.type_name());
            init_actions.push(self.action(name, a, Vec::new())?);
        }
        // The private actions take effect together: each in the order that resolves positions
        // and speeds relative to other entities against those entities' initial ones
        // (scenario::init_order; document order where nothing refers across).
        for step in scenario::init_order(&sb.init)? {
            let p = &sb.init.privates[step.private];
            let actor = self.actor(
                &p.entity_ref,
                &sb.init.actions.first().map_or_else(
                    || scenario::SourcePos::start_of(self.scenario.path.as_path().into()),
                    |a| a.pos.clone(),
                ),
            )?;
            let a = &p.actions[step.action];
            let name = format!("Init {} {}", p.entity_ref, a.kind.type_name());
            init_actions.push(self.action(name, a, vec![actor])?);
        }
        let mut stories = Vec::new();
        for story in &sb.stories {
            let mut acts = Vec::new();
            for act in &story.acts {
                let mut groups = Vec::new();
                // The Act's actions with their ManeuverGroup's actors, noted for runtime
                // actors once the Act's start trigger has its condition ids.
                let mut act_actions = Vec::new();
                for mg in &act.maneuver_groups {
                    let actors = self.actors(&mg.actors, &mg.pos)?;
                    let mut maneuvers = Vec::new();
                    for m in &mg.maneuvers {
                        let mut events = Vec::new();
                        for ev in &m.events {
                            let actions = ev
                                .actions
                                .iter()
                                .map(|a| {
                                    let d = self.action(a.name.clone(), a, actors.clone())?;
                                    act_actions.push((d.id, &mg.actors));
                                    Ok(d)
                                })
                                .collect::<Result<_, Error>>()?;
                            events.push(EventDesc {
                                name: ev.name.clone(),
                                priority: match ev.priority {
                                    scenario::Priority::Skip => Priority::Skip,
                                    scenario::Priority::Parallel => Priority::Parallel,
                                    _ => Priority::Override,
                                },
                                maximum_execution_count: ev.maximum_execution_count,
                                start_trigger: self.trigger(ev.start_trigger.as_ref())?,
                                actions,
                            });
                        }
                        maneuvers.push(ManeuverDesc {
                            name: m.name.clone(),
                            events,
                        });
                    }
                    groups.push(ManeuverGroupDesc {
                        name: mg.name.clone(),
                        maximum_execution_count: mg.maximum_execution_count,
                        maneuvers,
                    });
                }
                let start_trigger = self.trigger(act.start_trigger.as_ref())?;
                for (id, actors) in act_actions {
                    self.note_runtime_actors(id, actors, start_trigger.as_ref());
                }
                acts.push(ActDesc {
                    name: act.name.clone(),
                    start_trigger,
                    stop_trigger: self.trigger(act.stop_trigger.as_ref())?,
                    maneuver_groups: groups,
                });
            }
            stories.push(StoryDesc {
                name: story.name.clone(),
                acts,
            });
        }
        Ok(StoryboardDesc {
            name: "storyBoard".to_owned(),
            init_actions,
            stories,
            stop_trigger: self.trigger(sb.stop_trigger.as_ref())?,
        })
    }

    fn actor(&self, name: &str, pos: &scenario::SourcePos) -> Result<EntityId, Error> {
        self.world
            .id(name)
            .ok_or_else(|| Error::at("a declared entity", format!("entityRef '{name}'"), pos))
    }

    /// The actors of a ManeuverGroup, entity selections expanded, each once, in order.
    fn actors(&self, actors: &Actors, pos: &scenario::SourcePos) -> Result<Vec<EntityId>, Error> {
        let mut out = Vec::new();
        for r in &actors.entity_refs {
            let names = self.scenario.entities.resolve(r);
            if names.is_empty() {
                return Err(Error::at(
                    "a declared entity or selection",
                    format!("entityRef '{r}'"),
                    pos,
                ));
            }
            for n in names {
                let id = self.actor(n, pos)?;
                if !out.contains(&id) {
                    out.push(id);
                }
            }
        }
        Ok(out)
    }

    /// Notes action `id` for actors worked out at its start: when its ManeuverGroup names a
    /// selection, or selects the triggering entities of the Act's `start_trigger` (its
    /// conditions by their ids; store/selection.rs).
    fn note_runtime_actors(
        &mut self,
        id: crate::storyboard::ActionId,
        actors: &Actors,
        start_trigger: Option<&TriggerDesc>,
    ) {
        let selections = &self.scenario.entities.entity_selections;
        let refs = &actors.entity_refs;
        let triggering = actors.select_triggering_entities.then(|| {
            start_trigger
                .iter()
                .flat_map(|t| &t.condition_groups)
                .map(|g| {
                    g.conditions
                        .iter()
                        .map(|c| crate::store::selection::ConditionRef {
                            id: c.id,
                            delay: c.delay,
                        })
                        .collect()
                })
                .collect()
        });
        if triggering.is_some() || refs.iter().any(|r| selections.iter().any(|s| &s.name == r)) {
            let spec = crate::store::selection::ActorSpec {
                refs: refs.to_vec(),
                triggering,
            };
            self.selection_actors.push((id, spec));
        }
    }

    /// An action's description, its table entry added (the entities a state check names
    /// resolved: an undeclared one is an error at the action).
    fn action(
        &mut self,
        name: String,
        action: &Action,
        actors: Vec<EntityId>,
    ) -> Result<ActionDesc, Error> {
        let id = self.actions.push(
            (self.world, &mut self.marks),
            name.clone(),
            action.clone(),
            actors,
        )?;
        Ok(ActionDesc { name, id })
    }

    /// A trigger's description. An empty `<StartTrigger/>` or `<StopTrigger/>` (allowed since
    /// 1.0, and how the ASAM ALKS examples write "start with the parent") is read as no
    /// trigger: a start trigger then starts the element with its parent, as esmini does, and
    /// an absent stop trigger never fires, as an empty one would.
    ///
    /// Each condition's names are resolved in the world now ([`ConditionRefs`]): one that
    /// names no declared entity or selection is an error at the condition (at its Position
    /// element for a relative position's `entityRef`), naming the element it is written in; an
    /// entity-free position the road network does not have is the position's error.
    fn trigger(&mut self, trigger: Option<&Trigger>) -> Result<Option<TriggerDesc>, Error> {
        let Some(trigger) = trigger.filter(|t| !t.condition_groups.is_empty()) else {
            return Ok(None);
        };
        let mut groups = Vec::new();
        for g in &trigger.condition_groups {
            let mut conditions = Vec::new();
            for c in &g.conditions {
                let id = ConditionId(self.conditions.len() as u32);
                let mut names = BuildNames {
                    world: self.world,
                    marks: &mut self.marks,
                };
                let refs = ConditionRefs::resolve(c, &mut names).map_err(|e| match e {
                    RefError::Unresolved(u) => Error::at(
                        format!(
                            "a declared entity for {} of condition '{}'",
                            u.element, c.name
                        ),
                        format!("'{}'", u.name),
                        u.at.as_ref().unwrap_or(&c.pos),
                    ),
                    RefError::Position(p) => Error::new(ErrorKind::Position(p)),
                })?;
                self.conditions.push(c.clone());
                self.condition_refs.push(refs);
                conditions.push(ConditionDesc {
                    name: c.name.clone(),
                    id,
                    edge: match c.condition_edge {
                        scenario::ConditionEdge::Rising => ConditionEdge::Rising,
                        scenario::ConditionEdge::Falling => ConditionEdge::Falling,
                        scenario::ConditionEdge::RisingOrFalling => ConditionEdge::RisingOrFalling,
                        _ => ConditionEdge::None,
                    },
                    delay: c.delay,
                    origin: Some(c.pos.to_string()),
                });
            }
            groups.push(ConditionGroupDesc { conditions });
        }
        Ok(Some(TriggerDesc {
            condition_groups: groups,
        }))
    }
}

/// The world's names as the storyboard is built: entities and selections as declared, marks
/// given their slots as they are met.
struct BuildNames<'a> {
    world: &'a World,
    marks: &'a mut MarkIds,
}

impl Names for BuildNames<'_> {
    fn entity(&self, name: &str) -> Option<EntityId> {
        self.world.id(name)
    }

    fn selection(&self, name: &str) -> Option<crate::condition::SelectionId> {
        self.world.selections.id(name)
    }

    fn mark(&mut self, name: &str) -> Option<crate::condition::MarkId> {
        Some(self.marks.id(name))
    }

    fn network(&self) -> &RoadNetwork {
        &self.world.network
    }

    fn routing_options(&self) -> crate::routing::RoutingOptions {
        crate::position::EntityQuery::routing_options(self.world)
    }
}
