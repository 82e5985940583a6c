//! The plan as an OpenSCENARIO 1.x scenario model (`scenario::Scenario`), which the engine runs
//! as it runs an XML scenario (OpenSCENARIO 1.3 §7.2.1 Storyboard, §7.3.1 ManeuverGroups).
//!
//! | plan | OpenSCENARIO 1.x |
//! | --- | --- |
//! | the scenario | one Story named after it |
//! | a phase | an Act named by the phase's path; StartTrigger: its start (none at 0 s); StopTrigger: its end |
//! | a phase lasting until its end | a ManeuverGroup `PATH/hold` whose Event waits on a condition that is never true, so only the StopTrigger ends the Act (its `stopTransition` is the phase's end line) |
//! | an actor's actions in a phase | a ManeuverGroup `PATH/ACTOR` with one Event per action (starting with the Act, or at an absolute time) |
//! | `emit e` (a phase) | in its Act, a ManeuverGroup `PATH/emit` whose Event `PATH/emit e` runs a CustomCommandAction (type `emit`, content `e`): one `customCommand` line in the event log per emission |
//! | `call m(a, b)` (a phase) | likewise a group `PATH/call` whose Event `PATH/call m(a, b)` runs a CustomCommandAction (type `call`, content `m(a, b)`, the arguments as JSON values): the host runs m then (`resolve::call`) |
//! | `on c: emit e` / `call m(…)` (the i-th `on` of the scenario) | an Act `on.i` from the start until the root phase's end, with the same groups whose Events start at each occurrence of c (maximumExecutionCount unbounded) |
//! | what actors do when a phase ends (`avoid_collisions(true)`'s controller deactivated) | an Act `PATH/end` whose StartTrigger is the phase's end |
//! | initial lane, s and speed | Init: TeleportAction to a LanePosition, SpeedAction (step); an actor driving against s at s = L − u of its distance u along its direction of travel, in its lane of the left side (the engine heads it in the lane's driving direction) |
//! | a plan over the roads of a route through points (`map.create_route`) | Init: each vehicle with a road of the plan ahead of it an AssignRouteAction over them (a Waypoint where it starts, one mid-way along each later road, in its lane) |
//! | a vehicle | ScenarioObject with a Vehicle from the solver's values |
//! | a member of random traffic (`plan::random_traffic`) | its ScenarioObject's ObjectController `random_traffic` (the engine's `mobil` model); Init: an ActivateControllerAction on both domains after the SpeedAction; created after the start (`plan::random_traffic_late`): no Init, its creating phase's TeleportAction, SpeedAction and ActivateControllerAction |
//! | a person, an animal | ScenarioObject with a Pedestrian of category `pedestrian`, `animal` |
//! | a stationary object | ScenarioObject with a MiscObject (category `barrier`); Init: TeleportAction to the WorldPosition of its `location(pose)`, no speed |
//!
//! Acts are written children first, so that a composition that ends with its members sees
//! their end in the same step.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use scenario::{
    Act, Action, ActionKind, Actors, ConditionGroup, ControllerAction, DynamicsDimension,
    DynamicsShape, Entities, EntityObject, Event, FileHeader, Init, LaneChangeAt, LaneChangeTarget,
    LaneOffsetTarget, LateralAction, LongitudinalAction, Maneuver, ManeuverGroup, MiscObject,
    MiscObjectCategory, ObjectController, Orientation, Pedestrian, PedestrianCategory, Performance,
    Position, PositionKind, Priority, Private, PrivateAction, Properties, ReferenceContext,
    RoadNetwork, Route, RouteStrategy, RoutingAction, Rule, Scenario, ScenarioObject, SourcePos,
    SpeedTarget, Story, Storyboard, StoryboardElementState, TransitionDynamics, Trigger,
    UserDefinedAction, Vehicle, Waypoint,
};

use crate::plan::{
    driver_domains, Entity, HandlerPlan, Plan, Planned, When, MAX_ACCELERATION, MAX_SPEED,
};
use crate::resolve::ActorKind;
use crate::trigger::{act_state, sim_time};

/// Builds the scenario model of `plan`; `file` is the `.osc` path, `road` the OpenDRIVE file.
pub(crate) fn lower(plan: &Plan, name: &str, file: &Path, road: &Path) -> Scenario {
    let origin = SourcePos::start_of(Arc::from(file));
    let mut privates = Vec::new();
    let mut objects = Vec::new();
    for e in &plan.entities {
        let lane = e.track.start_lane();
        let (s, v) = e.track.at(0.0);
        // Against s the track's s is the distance u = L − s along the direction of travel,
        // its offset to the left of that direction (`crate::road`); the LanePosition's are
        // the road's (offset along t).
        let (s, side) = if e.against {
            (plan.end - s, -1.0)
        } else {
            (s, 1.0)
        };
        let (road_id, s) = plan.on_road(s);
        // A member of random traffic: its driver model, activated in the Init.
        let driver = e.driver.as_ref().map(|c| ObjectController {
            name: Some(c.name.clone()),
            controller: c.clone(),
        });
        objects.push(ScenarioObject {
            name: e.name.clone(),
            entity_object: entity_object(e),
            object_controllers: driver.iter().cloned().collect(),
            pos: origin.clone(),
        });
        let action = |kind| Action {
            name: String::new(),
            kind: ActionKind::Private(kind),
            pos: origin.clone(),
        };
        // Created later by its phase (a TeleportAction, its speed, its driver activated).
        if e.created.is_some() {
            continue;
        }
        if let ActorKind::Stationary(at) = e.data.kind {
            let ([x, y, z], [h, p, r]) = (at.position, at.orientation);
            privates.push(Private {
                entity_ref: e.name.clone(),
                actions: vec![action(PrivateAction::Teleport(Position {
                    kind: PositionKind::World {
                        x,
                        y,
                        z: Some(z),
                        h: Some(h),
                        p: Some(p),
                        r: Some(r),
                    },
                    pos: origin.clone(),
                }))],
            });
            continue;
        }
        // The plan's route runs in +s: none for an actor driving against s (whose roads the
        // engine's default controller drives, `PlanRoad::against`).
        let route = (plan.routed && e.data.kind == ActorKind::Vehicle && !e.against)
            .then(|| route_ahead(plan, lane, (road_id, s), &origin))
            .flatten()
            .map(|r| {
                action(PrivateAction::Routing(Box::new(
                    RoutingAction::AssignRoute(r),
                )))
            });
        privates.push(Private {
            entity_ref: e.name.clone(),
            actions: [
                action(PrivateAction::Teleport(Position {
                    kind: PositionKind::Lane {
                        road_id: road_id.to_string(),
                        lane_id: lane.to_string(),
                        s,
                        offset: Some(side * e.track.offset(0.0)),
                        // §8.9.9 yaw relative to the road's s-axis; the engine's relative
                        // heading counts from the lane's driving direction, which is the
                        // s-axis turned by pi for a lane driven against s.
                        orientation: e.yaw.as_ref().map(|(h, _)| Orientation {
                            h: if e.against {
                                opendrive::normalize_angle(*h - std::f64::consts::PI)
                            } else {
                                *h
                            },
                            p: 0.0,
                            r: 0.0,
                            reference: Some(ReferenceContext::Relative),
                        }),
                    },
                    pos: origin.clone(),
                })),
                action(PrivateAction::Longitudinal(LongitudinalAction::Speed {
                    dynamics: TransitionDynamics {
                        dynamics_shape: DynamicsShape::Step,
                        dynamics_dimension: DynamicsDimension::Time,
                        value: 0.0,
                        following_mode: None,
                    },
                    target: SpeedTarget::Absolute(v),
                })),
            ]
            .into_iter()
            .chain(route)
            .chain(driver.map(|d| {
                action(PrivateAction::Controller(Box::new(
                    ControllerAction::Activate {
                        domains: driver_domains(&d.controller),
                        object_controller_ref: d.name,
                    },
                )))
            }))
            .collect(),
        });
    }
    // Actors driving against s: their offsets turned to the road's t (`offsets_along_t`).
    let against: HashSet<&str> = plan
        .entities
        .iter()
        .filter(|e| e.against)
        .map(|e| e.name.as_str())
        .collect();
    // The run ends with the root phase (written last).
    let run_end = plan.phases.last().and_then(|root| trigger_of(&root.end));
    let mut acts = Vec::new();
    for ph in &plan.phases {
        let pos = ph.site.pos.clone();
        let mut groups = if ph.hold {
            vec![hold_group(&ph.path, pos.clone())]
        } else {
            Vec::new()
        };
        if let Some((ty, content)) = &ph.command {
            groups.push(command_group(
                &ph.path,
                ty,
                vec![(content.clone(), None, pos.clone())],
                1,
                pos.clone(),
            ));
        }
        groups.extend(actor_groups(&ph.path, &ph.actions, &against, &pos));
        let start_trigger = start_trigger_of(&ph.start);
        acts.push(Act {
            name: ph.path.clone(),
            maneuver_groups: groups,
            start_trigger: start_trigger.clone(),
            stop_trigger: trigger_of(&ph.end),
            pos: pos.clone(),
        });
        // What the actors do when the phase ends: an Act that starts then (none for a phase
        // that never ends). An end the plan does not time starts it on the phase's Act having
        // completed (the same step: its stop trigger is evaluated first), never on the end's
        // own conditions, which may hold before the phase runs and are first sampled one
        // step after it starts where the Act's stop trigger is concerned.
        if !ph.after.is_empty() {
            let end = match &ph.end {
                When::Dyn(_) => Some(Trigger {
                    condition_groups: vec![ConditionGroup {
                        conditions: vec![act_state(
                            &ph.path,
                            StoryboardElementState::CompleteState,
                            0.0,
                            pos.clone(),
                        )],
                    }],
                }),
                w => trigger_of(w),
            };
            if let Some(trigger) = end {
                let path = format!("{}/end", ph.path);
                acts.push(Act {
                    maneuver_groups: actor_groups(&path, &ph.after, &against, &pos),
                    name: path,
                    start_trigger: Some(trigger),
                    stop_trigger: None,
                    pos: pos.clone(),
                });
            }
        }
        // What goes on after the phase: an Act from its start to the end of the run (a later
        // action of the actor in the same domain replaces it in the engine).
        if !ph.persist.is_empty() {
            let path = format!("{}/continue", ph.path);
            acts.push(Act {
                maneuver_groups: actor_groups(&path, &ph.persist, &against, &pos),
                name: path,
                start_trigger,
                stop_trigger: run_end.clone(),
                pos,
            });
        }
    }
    // `on` handlers: one Act each, running until the root phase (written last) ends, or, for
    // an invoked behavior's, from its invocation's start to its end.
    // Per Act, its groups by command type (`emit` first), each with its commands.
    // Keyed by the first handler of each Act (its name and span are every one's).
    let mut handlers: Vec<(&HandlerPlan, Vec<Commands<'_>>)> = Vec::new();
    for h in &plan.handlers {
        let emit = (h.event.clone(), Some(h.trigger.clone()), h.site.pos.clone());
        let i = match handlers.iter().position(|(first, _)| first.act == h.act) {
            Some(i) => i,
            None => {
                handlers.push((h, Vec::new()));
                handlers.len() - 1
            }
        };
        let act = &mut handlers[i].1;
        match act.iter_mut().find(|(ty, _)| *ty == h.command_type) {
            Some((_, emits)) => emits.push(emit),
            None => act.push((h.command_type, vec![emit])),
        }
    }
    for (first, by_type) in handlers {
        let act = first.act.as_str();
        // Each entry was created with one command of one type.
        let pos = by_type[0].1[0].2.clone();
        let (start_trigger, stop_trigger) = match &first.span {
            Some((start, end)) => (start_trigger_of(start), trigger_of(end)),
            None => (None, run_end.clone()),
        };
        acts.push(Act {
            name: act.to_string(),
            maneuver_groups: by_type
                .into_iter()
                .map(|(ty, emits)| command_group(act, ty, emits, u32::MAX, pos.clone()))
                .collect(),
            start_trigger,
            stop_trigger,
            pos,
        });
    }
    Scenario {
        path: file.to_path_buf(),
        file_header: FileHeader {
            rev_major: 1,
            rev_minor: 3,
            date: String::new(),
            description: format!("OpenSCENARIO DSL scenario {name}, planned by oscsim"),
            author: String::new(),
            license: None,
        },
        parameter_declarations: Vec::new(),
        variable_declarations: Vec::new(),
        monitor_declarations: Vec::new(),
        catalog_locations: Vec::new(),
        road_network: RoadNetwork {
            logic_file: Some(PathBuf::from(road)),
            ..RoadNetwork::default()
        },
        entities: Entities {
            scenario_objects: objects,
            entity_selections: Vec::new(),
        },
        storyboard: Storyboard {
            init: Init {
                actions: Vec::new(),
                privates,
            },
            stories: vec![Story {
                name: name.to_string(),
                acts,
                pos: origin,
            }],
            stop_trigger: None,
        },
        parameter_value_distribution: None,
        warnings: Vec::new(),
        sources: scenario::Sources::default(),
    }
}

/// The route over the plan's roads from an actor's start (`lane`, road id and s) to the end
/// of the last road, when it has a road ahead: a Waypoint where it starts and one in the
/// middle of each later road in that lane (routeStrategy `shortest`; between waypoints on
/// roads that follow each other there is one path, so the engine drives the plan's roads).
fn route_ahead(plan: &Plan, lane: i32, (road, s): (&str, f64), pos: &SourcePos) -> Option<Route> {
    let here = plan.roads.iter().position(|(id, _)| id == road)?;
    let point = |road_id: &str, s: f64| Waypoint {
        route_strategy: RouteStrategy::Shortest,
        position: Position {
            kind: PositionKind::Lane {
                road_id: road_id.to_string(),
                lane_id: lane.to_string(),
                s,
                offset: None,
                orientation: None,
            },
            pos: pos.clone(),
        },
    };
    let mut waypoints = vec![point(road, s)];
    for (i, (id, start)) in plan.roads.iter().enumerate().skip(here + 1) {
        let end = plan.roads.get(i + 1).map_or(plan.end, |r| r.1);
        waypoints.push(point(id, (end - start) / 2.0));
    }
    (waypoints.len() > 1).then(|| Route {
        name: "plan".to_string(),
        closed: false,
        waypoints,
        catalog: None,
    })
}

/// Mass of a DSL person (kg): the DSL's person has no mass; the 1.x catalogs' pedestrian's.
const PERSON_MASS: f64 = 80.0;
/// Mass of a DSL animal (kg): a deer's.
const ANIMAL_MASS: f64 = 60.0;

/// The 1.x entity of a planned physical object (see the module table).
fn entity_object(e: &Entity) -> EntityObject {
    match e.data.kind {
        ActorKind::Vehicle => EntityObject::Vehicle(Box::new(vehicle(e))),
        ActorKind::Walker(category) => EntityObject::Pedestrian(Box::new(Pedestrian {
            name: e.name.clone(),
            pedestrian_category: category,
            mass: if category == PedestrianCategory::Animal {
                ANIMAL_MASS
            } else {
                PERSON_MASS
            },
            model3d: None,
            role: None,
            bounding_box: e.data.bounding_box,
            properties: Properties::default(),
            catalog: None,
        })),
        ActorKind::Stationary(_) => EntityObject::MiscObject(Box::new(MiscObject {
            name: e.name.clone(),
            misc_object_category: MiscObjectCategory::Barrier,
            mass: 0.0,
            model3d: None,
            bounding_box: e.data.bounding_box,
            properties: Properties::default(),
            catalog: None,
        })),
    }
}

/// The 1.x Vehicle of a planned vehicle: its fields, and the performance every DSL vehicle has
/// (the DSL's vehicle has no such fields).
fn vehicle(e: &Entity) -> Vehicle {
    Vehicle {
        name: e.name.clone(),
        vehicle_category: e.data.category,
        role: None,
        mass: None,
        model3d: None,
        bounding_box: e.data.bounding_box,
        performance: Performance {
            max_speed: MAX_SPEED,
            max_acceleration: MAX_ACCELERATION,
            max_deceleration: MAX_ACCELERATION,
            max_acceleration_rate: None,
            max_deceleration_rate: None,
        },
        axles: e.data.axles.clone(),
        properties: Properties::default(),
        trailer_hitch: None,
        trailer_coupler: None,
        trailer: None,
        catalog: None,
    }
}

/// One ManeuverGroup `PATH/ACTOR` per actor of `actions`, in the order they first act, with one
/// Event per action (starting with the Act, at an absolute time, or on its trigger).
/// `action` of an actor driving against s (`against`) with its offsets across the lane turned
/// from the left of its direction of travel, where the plan has them (`crate::road`), to the
/// road's t, along which the engine's LaneOffsetAction and LaneChangeAction offsets run.
fn offsets_along_t(action: PrivateAction, against: bool) -> PrivateAction {
    if !against {
        return action;
    }
    match action {
        PrivateAction::Lateral(LateralAction::LaneChange {
            target_lane_offset,
            dynamics,
            target,
        }) => PrivateAction::Lateral(LateralAction::LaneChange {
            target_lane_offset: target_lane_offset.map(|o| -o),
            dynamics,
            // Beside another actor: the t asked from x's, to the drivers' left in the plan.
            target: match target {
                LaneChangeTarget::Beside {
                    entity_ref,
                    t,
                    what,
                    follow,
                    roads,
                } => LaneChangeTarget::Beside {
                    entity_ref,
                    t: -t,
                    what,
                    follow,
                    roads,
                },
                other => other,
            },
        }),
        PrivateAction::Lateral(LateralAction::LaneChangeAt(at)) => {
            PrivateAction::Lateral(LateralAction::LaneChangeAt(Box::new(LaneChangeAt {
                target_lane_offset: at.target_lane_offset.map(|o| -o),
                ..*at
            })))
        }
        PrivateAction::Lateral(LateralAction::LaneOffset {
            continuous,
            dynamics_shape,
            max_lateral_acc,
            target,
        }) => PrivateAction::Lateral(LateralAction::LaneOffset {
            continuous,
            dynamics_shape,
            max_lateral_acc,
            target: match target {
                LaneOffsetTarget::Absolute(o) => LaneOffsetTarget::Absolute(-o),
                LaneOffsetTarget::Relative { entity_ref, value } => LaneOffsetTarget::Relative {
                    entity_ref,
                    value: -value,
                },
                // The planner writes no other form (non_exhaustive in the model).
                other => other,
            },
        }),
        other => other,
    }
}

fn actor_groups(
    path: &str,
    actions: &[Planned],
    against: &HashSet<&str>,
    pos: &SourcePos,
) -> Vec<ManeuverGroup> {
    let mut actors: Vec<&str> = Vec::new();
    for a in actions {
        if !actors.contains(&a.entity.as_str()) {
            actors.push(&a.entity);
        }
    }
    actors
        .into_iter()
        .map(|actor| {
            let events = actions
                .iter()
                .filter(|a| a.entity == actor)
                .map(|a| {
                    let pos = a.site.pos.clone();
                    Event {
                        name: a.name.clone(),
                        priority: Priority::Parallel,
                        maximum_execution_count: 1,
                        actions: vec![Action {
                            name: a.name.clone(),
                            kind: ActionKind::Private(offsets_along_t(
                                a.action.clone(),
                                against.contains(actor),
                            )),
                            pos: pos.clone(),
                        }],
                        start_trigger: match &a.at {
                            Some(When::At(t)) => Some(Trigger {
                                condition_groups: vec![ConditionGroup {
                                    conditions: vec![sim_time(
                                        *t,
                                        Rule::GreaterOrEqual,
                                        pos.clone(),
                                    )],
                                }],
                            }),
                            Some(w) => trigger_of(w),
                            None => None,
                        },
                        pos,
                    }
                })
                .collect();
            let name = format!("{path}/{actor}");
            ManeuverGroup {
                name: name.clone(),
                maximum_execution_count: 1,
                actors: Actors {
                    select_triggering_entities: false,
                    entity_refs: vec![actor.to_string()],
                },
                maneuvers: vec![Maneuver {
                    name,
                    events,
                    catalog: None,
                    pos: pos.clone(),
                }],
                pos: pos.clone(),
            }
        })
        .collect()
}

/// The start trigger of an Act starting at `w` (`None`: with the run).
fn start_trigger_of(w: &When) -> Option<Trigger> {
    match w {
        When::At(t) if *t <= 0.0 => None,
        w => trigger_of(w),
    }
}

/// The trigger of moment `w` (`None`: never).
fn trigger_of(w: &When) -> Option<Trigger> {
    let groups = w.groups();
    (!groups.is_empty()).then_some(Trigger {
        condition_groups: groups,
    })
}

/// The commands of one type (`emit`, `call`) of an Act.
type Commands<'a> = (&'a str, Vec<Emission>);

/// A command's content (an emitted event's name, a call), its Event's start trigger (`None`:
/// with the Act) and position.
type Emission = (String, Option<Trigger>, SourcePos);

/// The group of element `path` that logs commands of type `ty` (`emit`, `call`): one Event
/// `PATH/TY C` per command C, running a CustomCommandAction (type `ty`, content C) which the
/// engine records as one `customCommand` line of the event log. An Event starts on its trigger
/// (`None`: with the Act) up to `count` times.
fn command_group(
    path: &str,
    ty: &str,
    emits: Vec<Emission>,
    count: u32,
    pos: SourcePos,
) -> ManeuverGroup {
    let name = format!("{path}/{ty}");
    let events = emits
        .into_iter()
        .map(|(event, start_trigger, pos)| Event {
            name: format!("{name} {event}"),
            priority: Priority::Parallel,
            maximum_execution_count: count,
            actions: vec![Action {
                name: format!("{name} {event}"),
                kind: ActionKind::UserDefined(UserDefinedAction {
                    command_type: ty.into(),
                    content: event,
                }),
                pos: pos.clone(),
            }],
            start_trigger,
            pos,
        })
        .collect();
    actorless_group(name, events, pos)
}

/// The group that keeps a phase's Act running until its StopTrigger: an Event whose start
/// condition (simulation time below 0 s) never holds.
fn hold_group(path: &str, pos: SourcePos) -> ManeuverGroup {
    let name = format!("{path}/hold");
    let event = Event {
        name: name.clone(),
        priority: Priority::Parallel,
        maximum_execution_count: 1,
        actions: Vec::new(),
        start_trigger: Some(Trigger {
            condition_groups: vec![ConditionGroup {
                conditions: vec![sim_time(0.0, Rule::LessThan, pos.clone())],
            }],
        }),
        pos: pos.clone(),
    };
    actorless_group(name, vec![event], pos)
}

/// A ManeuverGroup `name` with no actors and one Maneuver `name` holding `events`.
fn actorless_group(name: String, events: Vec<Event>, pos: SourcePos) -> ManeuverGroup {
    ManeuverGroup {
        name: name.clone(),
        maximum_execution_count: 1,
        actors: Actors {
            select_triggering_entities: false,
            entity_refs: Vec::new(),
        },
        maneuvers: vec![Maneuver {
            name,
            events,
            catalog: None,
            pos: pos.clone(),
        }],
        pos,
    }
}
