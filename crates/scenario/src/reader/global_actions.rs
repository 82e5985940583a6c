//! Readers for global and user-defined actions (OpenSCENARIO 1.3, "Actions", XSD
//! `GlobalAction`, `EnvironmentAction`, `EntityAction`, `InfrastructureAction`,
//! `SetMonitorAction`, `ParameterAction`, `VariableAction`, `UserDefinedAction`).

use crate::error::Result;
use crate::model::{GlobalAction, ModifyRule, TrafficSignalAction, UserDefinedAction};
use crate::reader::context::{Ctx, Node};
use crate::reader::environment::read_environment_or_reference;
use crate::reader::positions::read_position_child;
use crate::reader::traffic::read_traffic_action;

const GLOBAL_ACTIONS: &str =
    "EnvironmentAction, EntityAction, InfrastructureAction, SetMonitorAction, \
ParameterAction, TrafficAction, VariableAction";

/// Reads XSD `GlobalAction`.
pub(crate) fn read_global_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<GlobalAction> {
    let c = ctx.choice(n, GLOBAL_ACTIONS)?;
    Ok(match c.tag_name().name() {
        "EnvironmentAction" => {
            let e = ctx.choice(c, "Environment, CatalogReference")?;
            GlobalAction::Environment(Box::new(read_environment_or_reference(ctx, c, e)?))
        }
        "EntityAction" => {
            let k = ctx.choice(c, "AddEntityAction, DeleteEntityAction")?;
            let add_at = match k.tag_name().name() {
                "AddEntityAction" => Some(read_position_child(ctx, k, "Position")?),
                "DeleteEntityAction" => None,
                _ => return Err(ctx.unexpected(c, k, "AddEntityAction, DeleteEntityAction")),
            };
            GlobalAction::Entity {
                entity_ref: ctx.entity(c, "entityRef")?,
                add_at,
            }
        }
        "InfrastructureAction" => {
            let s = ctx.child(c, "TrafficSignalAction")?;
            let k = ctx.choice(s, "TrafficSignalControllerAction, TrafficSignalStateAction")?;
            GlobalAction::TrafficSignal(match k.tag_name().name() {
                "TrafficSignalControllerAction" => TrafficSignalAction::Controller {
                    traffic_signal_controller_ref: ctx.req(k, "trafficSignalControllerRef")?,
                    phase: ctx.req(k, "phase")?,
                },
                "TrafficSignalStateAction" => TrafficSignalAction::State {
                    name: ctx.req(k, "name")?,
                    state: ctx.req(k, "state")?,
                },
                _ => {
                    return Err(ctx.unexpected(
                        s,
                        k,
                        "TrafficSignalControllerAction, TrafficSignalStateAction",
                    ))
                }
            })
        }
        "SetMonitorAction" => {
            ctx.since(c, 3);
            GlobalAction::SetMonitor {
                monitor_ref: ctx.req(c, "monitorRef")?,
                value: ctx.req(c, "value")?,
            }
        }
        "ParameterAction" => {
            if ctx.rev_minor() >= 2 {
                ctx.warn(
                    c,
                    "ParameterAction is deprecated since 1.2; use VariableAction".into(),
                );
            }
            GlobalAction::Parameter {
                parameter_ref: ctx.declared_param(c, "parameterRef")?,
                rule: read_modify_rule(ctx, c)?,
            }
        }
        "TrafficAction" => GlobalAction::Traffic {
            traffic_name: ctx.opt(c, "trafficName")?,
            action: Box::new(read_traffic_action(ctx, c)?),
        },
        "VariableAction" => {
            ctx.since(c, 2);
            GlobalAction::Variable {
                variable_ref: ctx.req(c, "variableRef")?,
                rule: read_modify_rule(ctx, c)?,
            }
        }
        _ => return Err(ctx.unexpected(n, c, GLOBAL_ACTIONS)),
    })
}

/// Reads the SetAction/ModifyAction choice of XSD `ParameterAction` and `VariableAction`.
fn read_modify_rule<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<ModifyRule> {
    let k = ctx.choice(n, "SetAction, ModifyAction")?;
    match k.tag_name().name() {
        "SetAction" => Ok(ModifyRule::Set(ctx.req(k, "value")?)),
        "ModifyAction" => {
            let rule = ctx.child(k, "Rule")?;
            let r = ctx.choice(rule, "AddValue, MultiplyByValue")?;
            match r.tag_name().name() {
                "AddValue" => Ok(ModifyRule::AddValue(ctx.req(r, "value")?)),
                "MultiplyByValue" => Ok(ModifyRule::MultiplyByValue(ctx.req(r, "value")?)),
                _ => Err(ctx.unexpected(rule, r, "AddValue, MultiplyByValue")),
            }
        }
        _ => Err(ctx.unexpected(n, k, "SetAction, ModifyAction")),
    }
}

/// Reads XSD `UserDefinedAction`.
pub(crate) fn read_user_defined_action<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
) -> Result<UserDefinedAction> {
    let c = ctx.child(n, "CustomCommandAction")?;
    let content = c
        .children()
        .filter_map(|t| t.text())
        .collect::<String>()
        .trim()
        .to_owned();
    Ok(UserDefinedAction {
        command_type: ctx.req(c, "type")?,
        content,
    })
}
