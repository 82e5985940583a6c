//! Readers for private actions (OpenSCENARIO 1.3, "Actions", XSD `PrivateAction`,
//! `LongitudinalAction`, `LateralAction`, `VisibilityAction`, `SynchronizeAction`,
//! `ControllerAction`, `TeleportAction`, `RoutingAction`, `TrailerAction`).
//!
//! Deprecated forms read onto the 1.3 model with a warning: PrivateAction/ActivateControllerAction
//! (1.0) as ControllerAction/ActivateControllerAction; FollowTrajectoryAction with a direct
//! Trajectory or CatalogReference (1.0) as its TrajectoryRef; AssignControllerAction with a
//! direct Controller or CatalogReference as the 1.3 ObjectController.

use crate::error::Result;
use crate::model::{
    ControllerAction, ControllerDomains, DynamicConstraints, FinalSpeed, LaneChangeTarget,
    LaneOffsetTarget, LateralAction, LongitudinalAction, PrivateAction, RoutingAction,
    SpeedProfileEntry, SpeedTarget, SteadyState, SynchronizeAction, Timing, TrailerAction,
    TransitionDynamics, VisibilityAction,
};
use crate::reader::appearance::{read_appearance_action, read_override_controller_value_action};
use crate::reader::context::{Ctx, Node};
use crate::reader::entities::read_controller_or_reference;
use crate::reader::positions::{read_position, read_position_child};
use crate::reader::routing::{read_route_ref, read_trajectory_or_reference, read_trajectory_ref};

const PRIVATE_ACTIONS: &str = "LongitudinalAction, LateralAction, VisibilityAction, SynchronizeAction, \
ActivateControllerAction, ControllerAction, TeleportAction, RoutingAction, AppearanceAction, TrailerAction";

/// Reads XSD `PrivateAction`.
pub(crate) fn read_private_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<PrivateAction> {
    let c = ctx.choice(n, PRIVATE_ACTIONS)?;
    Ok(match c.tag_name().name() {
        "LongitudinalAction" => PrivateAction::Longitudinal(read_longitudinal_action(ctx, c)?),
        "LateralAction" => PrivateAction::Lateral(read_lateral_action(ctx, c)?),
        "VisibilityAction" => {
            let mut sensor_references = Vec::new();
            if let Some(set) = ctx.opt_child(c, "SensorReferenceSet") {
                ctx.since(set, 2);
                for s in ctx.children(set, "SensorReference") {
                    sensor_references.push(ctx.req(s, "name")?);
                }
            }
            PrivateAction::Visibility(VisibilityAction {
                graphics: ctx.req(c, "graphics")?,
                sensors: ctx.req(c, "sensors")?,
                traffic: ctx.req(c, "traffic")?,
                sensor_references,
            })
        }
        "SynchronizeAction" => {
            PrivateAction::Synchronize(Box::new(read_synchronize_action(ctx, c)?))
        }
        "ActivateControllerAction" => {
            ctx.warn(c, "PrivateAction/ActivateControllerAction is deprecated, read as ControllerAction/ActivateControllerAction".into());
            PrivateAction::Controller(Box::new(read_activate_controller_action(ctx, c)?))
        }
        "ControllerAction" => PrivateAction::Controller(Box::new(read_controller_action(ctx, c)?)),
        "TeleportAction" => PrivateAction::Teleport(read_position_child(ctx, c, "Position")?),
        "RoutingAction" => PrivateAction::Routing(Box::new(read_routing_action(ctx, c)?)),
        "AppearanceAction" => {
            ctx.since(c, 2);
            PrivateAction::Appearance(read_appearance_action(ctx, c)?)
        }
        "TrailerAction" => {
            ctx.since(c, 3);
            let t = ctx.choice(c, "ConnectTrailerAction, DisconnectTrailerAction")?;
            PrivateAction::Trailer(match t.tag_name().name() {
                "ConnectTrailerAction" => TrailerAction::Connect {
                    trailer_ref: ctx.entity(t, "trailerRef")?,
                },
                "DisconnectTrailerAction" => TrailerAction::Disconnect,
                _ => {
                    return Err(ctx.unexpected(
                        c,
                        t,
                        "ConnectTrailerAction, DisconnectTrailerAction",
                    ))
                }
            })
        }
        _ => return Err(ctx.unexpected(n, c, PRIVATE_ACTIONS)),
    })
}

/// Reads XSD `TransitionDynamics` from child `name` of `n`.
pub(crate) fn read_transition_dynamics<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    name: &str,
) -> Result<TransitionDynamics> {
    let d = ctx.child(n, name)?;
    Ok(TransitionDynamics {
        dynamics_shape: ctx.req(d, "dynamicsShape")?,
        dynamics_dimension: ctx.req(d, "dynamicsDimension")?,
        value: ctx.req(d, "value")?,
        following_mode: ctx.opt(d, "followingMode")?,
    })
}

/// Reads the optional `DynamicConstraints` child of `n`.
fn read_dynamic_constraints<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
) -> Result<Option<DynamicConstraints>> {
    let Some(d) = ctx.opt_child(n, "DynamicConstraints") else {
        return Ok(None);
    };
    Ok(Some(DynamicConstraints {
        max_acceleration: ctx.opt(d, "maxAcceleration")?,
        max_acceleration_rate: ctx.opt(d, "maxAccelerationRate")?,
        max_deceleration: ctx.opt(d, "maxDeceleration")?,
        max_deceleration_rate: ctx.opt(d, "maxDecelerationRate")?,
        max_speed: ctx.opt(d, "maxSpeed")?,
    }))
}

/// Reads XSD `LongitudinalAction`.
fn read_longitudinal_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<LongitudinalAction> {
    const EXPECTED: &str = "SpeedAction, LongitudinalDistanceAction, SpeedProfileAction";
    let c = ctx.choice(n, EXPECTED)?;
    Ok(match c.tag_name().name() {
        "SpeedAction" => {
            let dynamics = read_transition_dynamics(ctx, c, "SpeedActionDynamics")?;
            let t = ctx.child(c, "SpeedActionTarget")?;
            let tc = ctx.choice(t, "RelativeTargetSpeed, AbsoluteTargetSpeed")?;
            let target = match tc.tag_name().name() {
                "AbsoluteTargetSpeed" => SpeedTarget::Absolute(ctx.req(tc, "value")?),
                "RelativeTargetSpeed" => SpeedTarget::Relative {
                    entity_ref: ctx.entity(tc, "entityRef")?,
                    value: ctx.req(tc, "value")?,
                    speed_target_value_type: ctx.req(tc, "speedTargetValueType")?,
                    continuous: ctx.req(tc, "continuous")?,
                },
                _ => return Err(ctx.unexpected(t, tc, "RelativeTargetSpeed, AbsoluteTargetSpeed")),
            };
            LongitudinalAction::Speed { dynamics, target }
        }
        "LongitudinalDistanceAction" => LongitudinalAction::LongitudinalDistance {
            entity_ref: ctx.entity(c, "entityRef")?,
            continuous: ctx.req(c, "continuous")?,
            distance: ctx.opt(c, "distance")?,
            time_gap: ctx.opt(c, "timeGap")?,
            freespace: ctx.req(c, "freespace")?,
            displacement: ctx.opt(c, "displacement")?,
            coordinate_system: ctx.opt(c, "coordinateSystem")?,
            dynamic_constraints: read_dynamic_constraints(ctx, c)?,
            at_start: None,
            at_least: None,
        },
        "SpeedProfileAction" => {
            ctx.since(c, 2);
            let mut entries = Vec::new();
            for e in ctx.children(c, "SpeedProfileEntry") {
                entries.push(SpeedProfileEntry {
                    speed: ctx.req(e, "speed")?,
                    time: ctx.opt(e, "time")?,
                });
            }
            LongitudinalAction::SpeedProfile {
                entity_ref: ctx.opt_entity(c, "entityRef")?,
                following_mode: ctx.req(c, "followingMode")?,
                dynamic_constraints: read_dynamic_constraints(ctx, c)?,
                entries,
            }
        }
        _ => return Err(ctx.unexpected(n, c, EXPECTED)),
    })
}

/// Reads XSD `LateralAction`.
fn read_lateral_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<LateralAction> {
    const EXPECTED: &str = "LaneChangeAction, LaneOffsetAction, LateralDistanceAction";
    let c = ctx.choice(n, EXPECTED)?;
    Ok(match c.tag_name().name() {
        "LaneChangeAction" => {
            let dynamics = read_transition_dynamics(ctx, c, "LaneChangeActionDynamics")?;
            let t = ctx.child(c, "LaneChangeTarget")?;
            let tc = ctx.choice(t, "RelativeTargetLane, AbsoluteTargetLane")?;
            let target = match tc.tag_name().name() {
                "RelativeTargetLane" => LaneChangeTarget::Relative {
                    entity_ref: ctx.entity(tc, "entityRef")?,
                    value: ctx.req(tc, "value")?,
                },
                "AbsoluteTargetLane" => LaneChangeTarget::Absolute(ctx.req(tc, "value")?),
                _ => return Err(ctx.unexpected(t, tc, "RelativeTargetLane, AbsoluteTargetLane")),
            };
            LateralAction::LaneChange {
                target_lane_offset: ctx.opt(c, "targetLaneOffset")?,
                dynamics,
                target,
            }
        }
        "LaneOffsetAction" => {
            let d = ctx.child(c, "LaneOffsetActionDynamics")?;
            let t = ctx.child(c, "LaneOffsetTarget")?;
            let tc = ctx.choice(t, "RelativeTargetLaneOffset, AbsoluteTargetLaneOffset")?;
            let target = match tc.tag_name().name() {
                "RelativeTargetLaneOffset" => LaneOffsetTarget::Relative {
                    entity_ref: ctx.entity(tc, "entityRef")?,
                    value: ctx.req(tc, "value")?,
                },
                "AbsoluteTargetLaneOffset" => LaneOffsetTarget::Absolute(ctx.req(tc, "value")?),
                _ => {
                    return Err(ctx.unexpected(
                        t,
                        tc,
                        "RelativeTargetLaneOffset, AbsoluteTargetLaneOffset",
                    ))
                }
            };
            LateralAction::LaneOffset {
                continuous: ctx.req(c, "continuous")?,
                dynamics_shape: ctx.req(d, "dynamicsShape")?,
                max_lateral_acc: ctx.opt(d, "maxLateralAcc")?,
                target,
            }
        }
        "LateralDistanceAction" => LateralAction::LateralDistance {
            entity_ref: ctx.entity(c, "entityRef")?,
            continuous: ctx.req(c, "continuous")?,
            distance: ctx.opt(c, "distance")?,
            freespace: ctx.req(c, "freespace")?,
            displacement: ctx.opt(c, "displacement")?,
            coordinate_system: ctx.opt(c, "coordinateSystem")?,
            dynamic_constraints: read_dynamic_constraints(ctx, c)?,
            at_start: false,
        },
        _ => return Err(ctx.unexpected(n, c, EXPECTED)),
    })
}

/// Reads XSD `SynchronizeAction`.
fn read_synchronize_action<'a>(ctx: &mut Ctx<'a>, c: Node<'a>) -> Result<SynchronizeAction> {
    let final_speed = match ctx.opt_child(c, "FinalSpeed") {
        Some(f) => {
            let k = ctx.choice(f, "AbsoluteSpeed, RelativeSpeedToMaster")?;
            let steady_state = read_steady_state(ctx, k)?;
            Some(match k.tag_name().name() {
                "AbsoluteSpeed" => FinalSpeed::Absolute {
                    value: ctx.req(k, "value")?,
                    steady_state,
                },
                "RelativeSpeedToMaster" => FinalSpeed::RelativeToMaster {
                    value: ctx.req(k, "value")?,
                    speed_target_value_type: ctx.req(k, "speedTargetValueType")?,
                    steady_state,
                },
                _ => return Err(ctx.unexpected(f, k, "AbsoluteSpeed, RelativeSpeedToMaster")),
            })
        }
        None => None,
    };
    Ok(SynchronizeAction {
        master_entity_ref: ctx.entity(c, "masterEntityRef")?,
        target_position_master: read_position_child(ctx, c, "TargetPositionMaster")?,
        target_position: read_position_child(ctx, c, "TargetPosition")?,
        target_tolerance_master: ctx.opt(c, "targetToleranceMaster")?,
        target_tolerance: ctx.opt(c, "targetTolerance")?,
        final_speed,
    })
}

/// Reads the optional XSD group `SteadyState` under `n`.
fn read_steady_state<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Option<SteadyState>> {
    if let Some(d) = ctx.opt_child(n, "TargetDistanceSteadyState") {
        return Ok(Some(SteadyState::Distance(ctx.req(d, "distance")?)));
    }
    if let Some(t) = ctx.opt_child(n, "TargetTimeSteadyState") {
        return Ok(Some(SteadyState::Time(ctx.req(t, "time")?)));
    }
    Ok(None)
}

/// Reads XSD `ControllerAction`. In 1.0–1.1 it held AssignControllerAction and
/// OverrideControllerValueAction side by side; the first of them is read.
fn read_controller_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<ControllerAction> {
    const EXPECTED: &str =
        "AssignControllerAction, OverrideControllerValueAction, ActivateControllerAction";
    let c = ctx.choice(n, EXPECTED)?;
    if n.children().filter(Node::is_element).count() > 1 {
        ctx.warn(
            n,
            format!(
                "ControllerAction holds more than one action (the 1.0 form); only {} is read",
                c.tag_name().name()
            ),
        );
    }
    Ok(match c.tag_name().name() {
        "AssignControllerAction" => {
            let activate = ControllerDomains {
                lateral: ctx.opt(c, "activateLateral")?,
                longitudinal: ctx.opt(c, "activateLongitudinal")?,
                animation: ctx.opt(c, "activateAnimation")?,
                lighting: ctx.opt(c, "activateLighting")?,
            };
            let k = ctx.choice(c, "Controller, CatalogReference, ObjectController")?;
            let (controller, object_controller_name) = if k.tag_name().name() == "ObjectController"
            {
                ctx.since(k, 3);
                let inner = ctx.choice(k, "Controller, CatalogReference")?;
                (
                    read_controller_or_reference(ctx, k, inner)?,
                    ctx.opt(k, "name")?,
                )
            } else {
                (read_controller_or_reference(ctx, c, k)?, None)
            };
            ControllerAction::Assign {
                controller,
                object_controller_name,
                activate,
            }
        }
        "OverrideControllerValueAction" => {
            ControllerAction::OverrideValues(read_override_controller_value_action(ctx, c)?)
        }
        "ActivateControllerAction" => read_activate_controller_action(ctx, c)?,
        _ => return Err(ctx.unexpected(n, c, EXPECTED)),
    })
}

/// Reads XSD `ActivateControllerAction`; the deprecated `controllerRef` is read as
/// `objectControllerRef`.
fn read_activate_controller_action<'a>(ctx: &mut Ctx<'a>, c: Node<'a>) -> Result<ControllerAction> {
    let old: Option<String> = ctx.opt(c, "controllerRef")?;
    if old.is_some() {
        ctx.warn(
            c,
            "ActivateControllerAction@controllerRef is deprecated, read as objectControllerRef"
                .into(),
        );
    }
    Ok(ControllerAction::Activate {
        object_controller_ref: ctx.opt(c, "objectControllerRef")?.or(old),
        domains: ControllerDomains {
            lateral: ctx.opt(c, "lateral")?,
            longitudinal: ctx.opt(c, "longitudinal")?,
            animation: ctx.opt(c, "animation")?,
            lighting: ctx.opt(c, "lighting")?,
        },
    })
}

/// Reads XSD `RoutingAction`.
fn read_routing_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<RoutingAction> {
    const EXPECTED: &str =
        "AssignRouteAction, FollowTrajectoryAction, AcquirePositionAction, RandomRouteAction";
    let c = ctx.choice(n, EXPECTED)?;
    Ok(match c.tag_name().name() {
        "AssignRouteAction" => RoutingAction::AssignRoute(read_route_ref(ctx, c, read_position)?),
        "FollowTrajectoryAction" => {
            let trajectory = if let Some(r) = ctx.opt_child(c, "TrajectoryRef") {
                read_trajectory_ref(ctx, r, read_position)?
            } else {
                let direct = c.children().find(|k| {
                    k.is_element()
                        && matches!(k.tag_name().name(), "Trajectory" | "CatalogReference")
                });
                match direct {
                    Some(k) => {
                        ctx.warn(
                            k,
                            format!(
                                "FollowTrajectoryAction/{} is deprecated, read as TrajectoryRef",
                                k.tag_name().name()
                            ),
                        );
                        read_trajectory_or_reference(ctx, c, k, read_position)?
                    }
                    None => ctx
                        .child(c, "TrajectoryRef")
                        .and_then(|r| read_trajectory_ref(ctx, r, read_position))?,
                }
            };
            let time_reference = match ctx.opt_child(c, "TimeReference") {
                Some(t) => read_time_reference(ctx, t)?,
                None => None,
            };
            let mode = ctx.child(c, "TrajectoryFollowingMode")?;
            RoutingAction::FollowTrajectory {
                trajectory: Box::new(trajectory),
                time_reference,
                following_mode: ctx.req(mode, "followingMode")?,
                initial_distance_offset: ctx.opt(c, "initialDistanceOffset")?,
            }
        }
        "AcquirePositionAction" => {
            RoutingAction::AcquirePosition(read_position_child(ctx, c, "Position")?)
        }
        "RandomRouteAction" => {
            ctx.since(c, 3);
            RoutingAction::RandomRoute
        }
        _ => return Err(ctx.unexpected(n, c, EXPECTED)),
    })
}

/// Reads XSD `TimeReference`: `None` (follow the geometry only) or `Timing`.
fn read_time_reference<'a>(ctx: &mut Ctx<'a>, t: Node<'a>) -> Result<Option<Timing>> {
    let k = ctx.choice(t, "None, Timing")?;
    match k.tag_name().name() {
        "None" => Ok(None),
        "Timing" => Ok(Some(Timing {
            domain_absolute_relative: ctx.req(k, "domainAbsoluteRelative")?,
            offset: ctx.req(k, "offset")?,
            scale: ctx.req(k, "scale")?,
        })),
        _ => Err(ctx.unexpected(t, k, "None, Timing")),
    }
}
