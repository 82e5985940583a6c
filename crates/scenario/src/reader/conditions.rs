//! Readers for triggers and conditions (OpenSCENARIO 1.3, "Conditions and triggers", XSD `Trigger`,
//! `ConditionGroup`, `Condition`, `ByEntityCondition`, `EntityCondition`,
//! `ByValueCondition`). The deprecated `alongRoute` attribute (1.0) is mapped onto
//! `coordinateSystem`/`relativeDistanceType` (see [`read_distance_measure`]).

use crate::error::{ErrorKind, Result};
use crate::model::{
    ByValueCondition, CollisionTarget, Condition, ConditionGroup, ConditionKind, CoordinateSystem,
    DistanceMeasure, EntityCondition, TimeToCollisionTarget, Trigger, TriggeringEntities,
};
use crate::reader::context::{Ctx, Node};
use crate::reader::positions::read_position_child;

const ENTITY_CONDITIONS: &str = "EndOfRoadCondition, CollisionCondition, OffroadCondition, \
TimeHeadwayCondition, TimeToCollisionCondition, AccelerationCondition, StandStillCondition, \
SpeedCondition, RelativeSpeedCondition, TraveledDistanceCondition, ReachPositionCondition, \
DistanceCondition, RelativeDistanceCondition, RelativeClearanceCondition, AngleCondition, \
RelativeAngleCondition";

const VALUE_CONDITIONS: &str = "ParameterCondition, TimeOfDayCondition, SimulationTimeCondition, \
StoryboardElementStateCondition, UserDefinedValueCondition, TrafficSignalCondition, \
TrafficSignalControllerCondition, VariableCondition";

/// Reads the optional trigger child `name` (`StartTrigger`, `StopTrigger`) of `n`.
pub(crate) fn read_trigger_child<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    name: &str,
) -> Result<Option<Trigger>> {
    match ctx.opt_child(n, name) {
        Some(t) => read_trigger(ctx, t).map(Some),
        None => Ok(None),
    }
}

/// Reads XSD `Trigger`.
pub(crate) fn read_trigger<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Trigger> {
    ctx.expect_children(n, &["ConditionGroup"])?;
    let mut trigger = Trigger::default();
    for g in ctx.children(n, "ConditionGroup") {
        ctx.expect_children(g, &["Condition"])?;
        let mut group = ConditionGroup::default();
        for c in ctx.children(g, "Condition") {
            group.conditions.push(read_condition(ctx, c)?);
        }
        trigger.condition_groups.push(group);
    }
    Ok(trigger)
}

/// Reads XSD `Condition`.
fn read_condition<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Condition> {
    let c = ctx.choice(n, "ByEntityCondition, ByValueCondition")?;
    let kind = match c.tag_name().name() {
        "ByEntityCondition" => {
            let t = ctx.child(c, "TriggeringEntities")?;
            let mut entity_refs = Vec::new();
            for e in ctx.children(t, "EntityRef") {
                entity_refs.push(ctx.entity(e, "entityRef")?);
            }
            let triggering_entities = TriggeringEntities {
                rule: ctx.req(t, "triggeringEntitiesRule")?,
                entity_refs,
            };
            let e = ctx.child(c, "EntityCondition")?;
            ConditionKind::ByEntity {
                triggering_entities,
                entity_condition: read_entity_condition(ctx, e)?,
            }
        }
        "ByValueCondition" => ConditionKind::ByValue(read_by_value_condition(ctx, c)?),
        _ => return Err(ctx.unexpected(n, c, "ByEntityCondition, ByValueCondition")),
    };
    Ok(Condition {
        name: ctx.req(n, "name")?,
        condition_edge: ctx.req(n, "conditionEdge")?,
        delay: ctx.req(n, "delay")?,
        kind,
        pos: ctx.pos(n),
    })
}

/// Reads the measurement attributes shared by the distance-based conditions.
///
/// The deprecated `alongRoute` (1.0) meant "true: along the road, routing taken into
/// account; false: straight-line distance". It speaks of the coordinate system only, so where
/// the 1.1 attributes are absent `alongRoute="true"` reads as `coordinateSystem="road"` with
/// `relativeDistanceType` left at its 1.3 default (`euclidianDistance`: √(ds² + dt²) in road
/// coordinates), and `false` as the 1.3 defaults (entity frame, euclidian distance), with a
/// warning either way. (An earlier reading also set `longitudinal`, which the attribute does
/// not say; esmini's cut-in_external reference measures the headway of two cars in adjacent
/// lanes with the lateral part included.)
fn read_distance_measure<'a>(ctx: &mut Ctx<'a>, c: Node<'a>) -> Result<DistanceMeasure> {
    let mut measure = DistanceMeasure {
        freespace: ctx.req(c, "freespace")?,
        coordinate_system: ctx.opt(c, "coordinateSystem")?,
        relative_distance_type: ctx.opt(c, "relativeDistanceType")?,
        routing_algorithm: ctx.opt(c, "routingAlgorithm")?,
    };
    let Some(along_route) = ctx.opt::<bool>(c, "alongRoute")? else {
        return Ok(measure);
    };
    let name = c.tag_name().name();
    let explicit = measure.coordinate_system.is_some() || measure.relative_distance_type.is_some();
    let read_as = if explicit {
        "ignored: coordinateSystem/relativeDistanceType are given"
    } else if along_route {
        measure.coordinate_system = Some(CoordinateSystem::Road);
        "read as coordinateSystem=\"road\" (relativeDistanceType keeps its default)"
    } else {
        "read as the default straight-line distance"
    };
    ctx.warn(
        c,
        format!("{name}@alongRoute=\"{along_route}\" is deprecated, {read_as}"),
    );
    Ok(measure)
}

/// Reads XSD `EntityCondition`.
fn read_entity_condition<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<EntityCondition> {
    let c = ctx.choice(n, ENTITY_CONDITIONS)?;
    Ok(match c.tag_name().name() {
        "EndOfRoadCondition" => EntityCondition::EndOfRoad {
            duration: ctx.req(c, "duration")?,
        },
        "CollisionCondition" => {
            let t = ctx.choice(c, "EntityRef, ByType")?;
            EntityCondition::Collision(match t.tag_name().name() {
                "EntityRef" => CollisionTarget::EntityRef(ctx.entity(t, "entityRef")?),
                "ByType" => CollisionTarget::ByType(ctx.req(t, "type")?),
                _ => return Err(ctx.unexpected(c, t, "EntityRef, ByType")),
            })
        }
        "OffroadCondition" => EntityCondition::Offroad {
            duration: ctx.req(c, "duration")?,
        },
        "TimeHeadwayCondition" => EntityCondition::TimeHeadway {
            entity_ref: ctx.entity(c, "entityRef")?,
            value: ctx.req(c, "value")?,
            rule: ctx.req(c, "rule")?,
            measure: read_distance_measure(ctx, c)?,
        },
        "TimeToCollisionCondition" => {
            let t = ctx.child(c, "TimeToCollisionConditionTarget")?;
            let tc = ctx.choice(t, "Position, EntityRef")?;
            let target = match tc.tag_name().name() {
                "Position" => {
                    TimeToCollisionTarget::Position(read_position_child(ctx, t, "Position")?)
                }
                "EntityRef" => TimeToCollisionTarget::EntityRef(ctx.entity(tc, "entityRef")?),
                _ => return Err(ctx.unexpected(t, tc, "Position, EntityRef")),
            };
            EntityCondition::TimeToCollision {
                target,
                value: ctx.req(c, "value")?,
                rule: ctx.req(c, "rule")?,
                measure: read_distance_measure(ctx, c)?,
            }
        }
        "AccelerationCondition" => EntityCondition::Acceleration {
            value: ctx.req(c, "value")?,
            rule: ctx.req(c, "rule")?,
            direction: ctx.opt(c, "direction")?,
        },
        "StandStillCondition" => EntityCondition::StandStill {
            duration: ctx.req(c, "duration")?,
        },
        "SpeedCondition" => EntityCondition::Speed {
            value: ctx.req(c, "value")?,
            rule: ctx.req(c, "rule")?,
            direction: ctx.opt(c, "direction")?,
        },
        "RelativeSpeedCondition" => EntityCondition::RelativeSpeed {
            entity_ref: ctx.entity(c, "entityRef")?,
            value: ctx.req(c, "value")?,
            rule: ctx.req(c, "rule")?,
            direction: ctx.opt(c, "direction")?,
        },
        "TraveledDistanceCondition" => EntityCondition::TraveledDistance {
            value: ctx.req(c, "value")?,
        },
        "ReachPositionCondition" => {
            ctx.warn(
                c,
                "ReachPositionCondition is deprecated since 1.2; use DistanceCondition".into(),
            );
            EntityCondition::ReachPosition {
                position: read_position_child(ctx, c, "Position")?,
                tolerance: ctx.req(c, "tolerance")?,
            }
        }
        "DistanceCondition" => EntityCondition::Distance {
            position: read_position_child(ctx, c, "Position")?,
            value: ctx.req(c, "value")?,
            rule: ctx.req(c, "rule")?,
            measure: read_distance_measure(ctx, c)?,
        },
        "RelativeDistanceCondition" => EntityCondition::RelativeDistance {
            entity_ref: ctx.entity(c, "entityRef")?,
            value: ctx.req(c, "value")?,
            rule: ctx.req(c, "rule")?,
            measure: {
                // relativeDistanceType is required here, optional elsewhere.
                if ctx.raw_attr(c, "relativeDistanceType").is_none() {
                    return Err(ctx.err(
                        c,
                        ErrorKind::MissingAttribute {
                            element: "RelativeDistanceCondition".into(),
                            attribute: "relativeDistanceType",
                        },
                    ));
                }
                read_distance_measure(ctx, c)?
            },
        },
        "RelativeClearanceCondition" => {
            ctx.since(c, 2);
            let mut relative_lane_ranges = Vec::new();
            for r in ctx.children(c, "RelativeLaneRange") {
                relative_lane_ranges.push((ctx.opt(r, "from")?, ctx.opt(r, "to")?));
            }
            let mut entity_refs = Vec::new();
            for e in ctx.children(c, "EntityRef") {
                entity_refs.push(ctx.entity(e, "entityRef")?);
            }
            EntityCondition::RelativeClearance {
                opposite_lanes: ctx.req(c, "oppositeLanes")?,
                distance_forward: ctx.opt(c, "distanceForward")?,
                distance_backward: ctx.opt(c, "distanceBackward")?,
                free_space: ctx.req(c, "freeSpace")?,
                relative_lane_ranges,
                entity_refs,
            }
        }
        "AngleCondition" => {
            ctx.since(c, 3);
            EntityCondition::Angle {
                angle_type: ctx.req(c, "angleType")?,
                angle: ctx.req(c, "angle")?,
                angle_tolerance: ctx.req(c, "angleTolerance")?,
                coordinate_system: ctx.opt(c, "coordinateSystem")?,
            }
        }
        "RelativeAngleCondition" => {
            ctx.since(c, 3);
            EntityCondition::RelativeAngle {
                entity_ref: ctx.entity(c, "entityRef")?,
                angle_type: ctx.req(c, "angleType")?,
                angle: ctx.req(c, "angle")?,
                angle_tolerance: ctx.req(c, "angleTolerance")?,
                coordinate_system: ctx.opt(c, "coordinateSystem")?,
            }
        }
        _ => return Err(ctx.unexpected(n, c, ENTITY_CONDITIONS)),
    })
}

/// Reads XSD `ByValueCondition`.
fn read_by_value_condition<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<ByValueCondition> {
    let c = ctx.choice(n, VALUE_CONDITIONS)?;
    Ok(match c.tag_name().name() {
        "ParameterCondition" => ByValueCondition::Parameter {
            parameter_ref: ctx.declared_param(c, "parameterRef")?,
            rule: ctx.req(c, "rule")?,
            value: ctx.req(c, "value")?,
        },
        "TimeOfDayCondition" => ByValueCondition::TimeOfDay {
            rule: ctx.req(c, "rule")?,
            date_time: ctx.req(c, "dateTime")?,
        },
        "SimulationTimeCondition" => ByValueCondition::SimulationTime {
            value: ctx.req(c, "value")?,
            rule: ctx.req(c, "rule")?,
        },
        "StoryboardElementStateCondition" => ByValueCondition::StoryboardElementState {
            storyboard_element_type: ctx.req(c, "storyboardElementType")?,
            storyboard_element_ref: ctx.req(c, "storyboardElementRef")?,
            state: ctx.req(c, "state")?,
        },
        "UserDefinedValueCondition" => ByValueCondition::UserDefinedValue {
            name: ctx.req(c, "name")?,
            rule: ctx.req(c, "rule")?,
            value: ctx.req(c, "value")?,
        },
        "TrafficSignalCondition" => ByValueCondition::TrafficSignal {
            name: ctx.req(c, "name")?,
            state: ctx.req(c, "state")?,
        },
        "TrafficSignalControllerCondition" => ByValueCondition::TrafficSignalController {
            traffic_signal_controller_ref: ctx.req(c, "trafficSignalControllerRef")?,
            phase: ctx.req(c, "phase")?,
        },
        "VariableCondition" => {
            ctx.since(c, 2);
            ByValueCondition::Variable {
                variable_ref: ctx.req(c, "variableRef")?,
                rule: ctx.req(c, "rule")?,
                value: ctx.req(c, "value")?,
            }
        }
        _ => return Err(ctx.unexpected(n, c, VALUE_CONDITIONS)),
    })
}
