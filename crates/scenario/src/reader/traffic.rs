//! Readers for traffic actions (OpenSCENARIO 1.3, "Actions", XSD `TrafficAction`,
//! `TrafficSourceAction`, `TrafficSinkAction`, `TrafficSwarmAction`, `TrafficAreaAction`,
//! `TrafficStopAction`, `TrafficDefinition`, `TrafficDistribution`, `TrafficArea`).

use crate::error::Result;
use crate::model::{
    RoadRange, ScenarioObject, TrafficAction, TrafficArea, TrafficDefinition,
    TrafficDistributionEntry, TrafficMix,
};
use crate::reader::context::{Ctx, Node};
use crate::reader::entities::{
    read_controller_or_reference, read_properties, read_scenario_object_body,
};
use crate::reader::positions::{read_position, read_position_child};

const TRAFFIC_ACTIONS: &str =
    "TrafficSourceAction, TrafficSinkAction, TrafficSwarmAction, TrafficAreaAction, TrafficStopAction";

/// Reads the choice of XSD `TrafficAction`.
pub(crate) fn read_traffic_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<TrafficAction> {
    let c = ctx.choice(n, TRAFFIC_ACTIONS)?;
    Ok(match c.tag_name().name() {
        "TrafficSourceAction" => {
            let old: Option<f64> = ctx.opt(c, "velocity")?;
            if old.is_some() {
                ctx.warn(
                    c,
                    "TrafficSourceAction@velocity is deprecated, read as speed".into(),
                );
            }
            TrafficAction::Source {
                position: read_position_child(ctx, c, "Position")?,
                radius: ctx.req(c, "radius")?,
                rate: ctx.req(c, "rate")?,
                speed: ctx.opt(c, "speed")?.or(old),
                traffic: read_traffic_mix(ctx, c)?,
            }
        }
        "TrafficSinkAction" => TrafficAction::Sink {
            position: read_position_child(ctx, c, "Position")?,
            radius: ctx.req(c, "radius")?,
            rate: ctx.opt(c, "rate")?,
            traffic: read_traffic_mix(ctx, c)?,
        },
        "TrafficSwarmAction" => {
            let central = ctx.child(c, "CentralObject")?;
            let initial_speed_range = match ctx.opt_child(c, "InitialSpeedRange") {
                Some(r) => Some(crate::model::Range {
                    lower_limit: ctx.req(r, "lowerLimit")?,
                    upper_limit: ctx.req(r, "upperLimit")?,
                }),
                None => None,
            };
            let direction_of_travel = match ctx.opt_child(c, "DirectionOfTravelDistribution") {
                Some(d) => Some((ctx.req(d, "same")?, ctx.req(d, "opposite")?)),
                None => None,
            };
            TrafficAction::Swarm {
                central_object: ctx.entity(central, "entityRef")?,
                inner_radius: ctx.req(c, "innerRadius")?,
                semi_major_axis: ctx.req(c, "semiMajorAxis")?,
                semi_minor_axis: ctx.req(c, "semiMinorAxis")?,
                offset: ctx.req(c, "offset")?,
                number_of_vehicles: ctx.req(c, "numberOfVehicles")?,
                velocity: ctx.opt(c, "velocity")?,
                initial_speed_range,
                direction_of_travel,
                traffic: read_traffic_mix(ctx, c)?,
            }
        }
        "TrafficAreaAction" => {
            ctx.since(c, 3);
            let a = ctx.child(c, "TrafficArea")?;
            let area = if let Some(p) = ctx.opt_child(a, "Polygon") {
                let mut corners = Vec::new();
                for q in ctx.children(p, "Position") {
                    corners.push(read_position(ctx, q)?);
                }
                TrafficArea::Polygon(corners)
            } else {
                let mut ranges = Vec::new();
                for r in ctx.children(a, "RoadRange") {
                    let mut cursors = Vec::new();
                    for k in ctx.children(r, "RoadCursor") {
                        let mut lanes = Vec::new();
                        for l in ctx.children(k, "Lane") {
                            lanes.push(ctx.req(l, "id")?);
                        }
                        cursors.push((ctx.req(k, "roadId")?, ctx.opt(k, "s")?, lanes));
                    }
                    ranges.push(RoadRange {
                        length: ctx.opt(r, "length")?,
                        cursors,
                    });
                }
                TrafficArea::RoadRanges(ranges)
            };
            let d = ctx.child(c, "TrafficDistribution")?;
            TrafficAction::Area {
                continuous: ctx.req(c, "continuous")?,
                number_of_entities: ctx.req(c, "numberOfEntities")?,
                area,
                distribution: read_traffic_distribution(ctx, d)?,
            }
        }
        "TrafficStopAction" => {
            ctx.since(c, 2);
            TrafficAction::Stop
        }
        _ => return Err(ctx.unexpected(n, c, TRAFFIC_ACTIONS)),
    })
}

/// Reads the TrafficDefinition and TrafficDistribution children of a traffic action.
fn read_traffic_mix<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<TrafficMix> {
    let mut mix = TrafficMix::default();
    if let Some(d) = ctx.opt_child(n, "TrafficDefinition") {
        mix.definition = Some(read_traffic_definition(ctx, d)?);
    }
    if let Some(d) = ctx.opt_child(n, "TrafficDistribution") {
        ctx.since(d, 3);
        mix.distribution = read_traffic_distribution(ctx, d)?;
    }
    Ok(mix)
}

/// Reads XSD `TrafficDefinition`.
fn read_traffic_definition<'a>(ctx: &mut Ctx<'a>, d: Node<'a>) -> Result<TrafficDefinition> {
    let mut def = TrafficDefinition {
        name: ctx.req(d, "name")?,
        vehicle_categories: Vec::new(),
        vehicle_roles: Vec::new(),
        controllers: Vec::new(),
    };
    let cats = ctx.child(d, "VehicleCategoryDistribution")?;
    for e in ctx.children(cats, "VehicleCategoryDistributionEntry") {
        def.vehicle_categories
            .push((ctx.req(e, "category")?, ctx.req(e, "weight")?));
    }
    if let Some(roles) = ctx.opt_child(d, "VehicleRoleDistribution") {
        for e in ctx.children(roles, "VehicleRoleDistributionEntry") {
            def.vehicle_roles
                .push((ctx.req(e, "role")?, ctx.req(e, "weight")?));
        }
    }
    let ctrls = ctx.child(d, "ControllerDistribution")?;
    for e in ctx.children(ctrls, "ControllerDistributionEntry") {
        let k = ctx.choice(e, "Controller, CatalogReference")?;
        def.controllers.push((
            read_controller_or_reference(ctx, e, k)?,
            ctx.req(e, "weight")?,
        ));
    }
    Ok(def)
}

/// Reads XSD `TrafficDistribution` (1.3).
fn read_traffic_distribution<'a>(
    ctx: &mut Ctx<'a>,
    d: Node<'a>,
) -> Result<Vec<TrafficDistributionEntry>> {
    let mut out = Vec::new();
    for e in ctx.children(d, "TrafficDistributionEntry") {
        let dist = ctx.child(e, "EntityDistribution")?;
        let mut entities = Vec::new();
        for x in ctx.children(dist, "EntityDistributionEntry") {
            let template = ctx.child(x, "ScenarioObjectTemplate")?;
            let object: ScenarioObject = read_scenario_object_body(ctx, template, String::new())?;
            entities.push((object, ctx.req(x, "weight")?));
        }
        out.push(TrafficDistributionEntry {
            weight: ctx.req(e, "weight")?,
            entities,
            properties: read_properties(ctx, e)?,
        });
    }
    Ok(out)
}
