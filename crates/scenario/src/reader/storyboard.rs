//! Readers for the storyboard (OpenSCENARIO 1.3 §7.2.1 "Storyboard", §7.3.1 "ManeuverGroups and
//! Actors"; XSD `Storyboard`, `Init`, `InitActions`, `Private`, `Story`, `Act`, `ManeuverGroup`,
//! `Actors`, `Maneuver`, `Event`, `Action`). ManeuverGroup CatalogReferences are resolved into
//! Maneuvers; Event@priority `overwrite` (deprecated) reads as `override`.

use crate::error::Result;
use crate::model::{
    Act, Action, ActionKind, Actors, Event, Init, Maneuver, ManeuverGroup, Private, Story,
    Storyboard,
};
use crate::reader::catalog::read_catalog_reference;
use crate::reader::conditions::read_trigger_child;
use crate::reader::context::{Ctx, Node};
use crate::reader::global_actions::{read_global_action, read_user_defined_action};
use crate::reader::private_actions::read_private_action;
use crate::reader::routing::expect_entry;

/// Reads XSD `Storyboard`.
pub(crate) fn read_storyboard<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Storyboard> {
    ctx.expect_children(n, &["Init", "Story", "StopTrigger"])?;
    let init = ctx.child(n, "Init")?;
    let init = read_init(ctx, init)?;
    let mut stories = Vec::new();
    for s in ctx.children(n, "Story") {
        stories.push(read_story(ctx, s)?);
    }
    Ok(Storyboard {
        init,
        stories,
        stop_trigger: read_trigger_child(ctx, n, "StopTrigger")?,
    })
}

/// Reads XSD `Init` and its `InitActions`.
fn read_init<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Init> {
    let actions = ctx.child(n, "Actions")?;
    let mut init = Init::default();
    for c in actions.children().filter(Node::is_element) {
        let pos = ctx.pos(c);
        match c.tag_name().name() {
            "GlobalAction" => {
                let kind = ActionKind::Global(read_global_action(ctx, c)?);
                init.actions.push(Action {
                    name: String::new(),
                    kind,
                    pos,
                });
            }
            "UserDefinedAction" => {
                let kind = ActionKind::UserDefined(read_user_defined_action(ctx, c)?);
                init.actions.push(Action {
                    name: String::new(),
                    kind,
                    pos,
                });
            }
            "Private" => {
                let mut private = Private {
                    entity_ref: ctx.entity(c, "entityRef")?,
                    actions: Vec::new(),
                };
                for p in ctx.children(c, "PrivateAction") {
                    let pos = ctx.pos(p);
                    let kind = ActionKind::Private(read_private_action(ctx, p)?);
                    private.actions.push(Action {
                        name: String::new(),
                        kind,
                        pos,
                    });
                }
                init.privates.push(private);
            }
            _ => {
                return Err(ctx.unexpected(actions, c, "GlobalAction, UserDefinedAction, Private"))
            }
        }
    }
    Ok(init)
}

/// Reads XSD `Story`.
fn read_story<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Story> {
    ctx.expect_children(n, &["ParameterDeclarations", "Act"])?;
    ctx.scoped(n, |ctx| {
        let mut acts = Vec::new();
        for a in ctx.children(n, "Act") {
            acts.push(read_act(ctx, a)?);
        }
        Ok(Story {
            name: ctx.req(n, "name")?,
            acts,
            pos: ctx.pos(n),
        })
    })
}

/// Reads XSD `Act`.
fn read_act<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Act> {
    ctx.expect_children(n, &["ManeuverGroup", "StartTrigger", "StopTrigger"])?;
    let mut maneuver_groups = Vec::new();
    for g in ctx.children(n, "ManeuverGroup") {
        maneuver_groups.push(read_maneuver_group(ctx, g)?);
    }
    Ok(Act {
        name: ctx.req(n, "name")?,
        maneuver_groups,
        start_trigger: read_trigger_child(ctx, n, "StartTrigger")?,
        stop_trigger: read_trigger_child(ctx, n, "StopTrigger")?,
        pos: ctx.pos(n),
    })
}

/// Reads XSD `ManeuverGroup`.
fn read_maneuver_group<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<ManeuverGroup> {
    let a = ctx.child(n, "Actors")?;
    let mut entity_refs = Vec::new();
    for e in ctx.children(a, "EntityRef") {
        entity_refs.push(ctx.entity(e, "entityRef")?);
    }
    let actors = Actors {
        select_triggering_entities: ctx.req(a, "selectTriggeringEntities")?,
        entity_refs,
    };
    let mut maneuvers = Vec::new();
    for c in n.children().filter(Node::is_element) {
        match c.tag_name().name() {
            "Maneuver" => maneuvers.push(read_maneuver(ctx, c)?),
            "CatalogReference" => {
                let (mut m, origin) = read_catalog_reference(ctx, c, |ctx, e| {
                    expect_entry(ctx, e, "Maneuver", read_maneuver)
                })?;
                m.catalog = Some(origin);
                maneuvers.push(m);
            }
            "Actors" => {}
            _ => return Err(ctx.unexpected(n, c, "Actors, CatalogReference, Maneuver")),
        }
    }
    Ok(ManeuverGroup {
        name: ctx.req(n, "name")?,
        maximum_execution_count: ctx.req(n, "maximumExecutionCount")?,
        actors,
        maneuvers,
        pos: ctx.pos(n),
    })
}

/// Reads XSD `Maneuver`.
pub(crate) fn read_maneuver<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Maneuver> {
    ctx.expect_children(n, &["ParameterDeclarations", "Event"])?;
    ctx.scoped(n, |ctx| {
        let mut events = Vec::new();
        for e in ctx.children(n, "Event") {
            events.push(read_event(ctx, e)?);
        }
        Ok(Maneuver {
            name: ctx.req(n, "name")?,
            events,
            catalog: None,
            pos: ctx.pos(n),
        })
    })
}

/// Reads XSD `Event`.
fn read_event<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Event> {
    ctx.expect_children(n, &["Action", "StartTrigger"])?;
    let mut actions = Vec::new();
    for a in ctx.children(n, "Action") {
        actions.push(read_action(ctx, a)?);
    }
    Ok(Event {
        name: ctx.req(n, "name")?,
        priority: ctx.req(n, "priority")?,
        maximum_execution_count: ctx.opt(n, "maximumExecutionCount")?.unwrap_or(1),
        actions,
        start_trigger: read_trigger_child(ctx, n, "StartTrigger")?,
        pos: ctx.pos(n),
    })
}

/// Reads XSD `Action`.
fn read_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Action> {
    const EXPECTED: &str = "GlobalAction, UserDefinedAction, PrivateAction";
    if !n.children().any(|c| c.is_element()) {
        // Invalid by the XSD (the choice is required) but harmless: nothing to do. Other
        // engines' test scenarios write `<Action name="…"/>` as a placeholder.
        let name: String = ctx.req(n, "name")?;
        let message = format!(
            "Action '{name}' has none of {EXPECTED}; it is read as an action that does nothing"
        );
        ctx.warn(n, message);
        return Ok(Action {
            name,
            kind: ActionKind::Empty,
            pos: ctx.pos(n),
        });
    }
    let c = ctx.choice(n, EXPECTED)?;
    let kind = match c.tag_name().name() {
        "GlobalAction" => ActionKind::Global(read_global_action(ctx, c)?),
        "UserDefinedAction" => ActionKind::UserDefined(read_user_defined_action(ctx, c)?),
        "PrivateAction" => ActionKind::Private(read_private_action(ctx, c)?),
        _ => return Err(ctx.unexpected(n, c, EXPECTED)),
    };
    Ok(Action {
        name: ctx.req(n, "name")?,
        kind,
        pos: ctx.pos(n),
    })
}
