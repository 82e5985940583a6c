//! Readers for entities (OpenSCENARIO 1.3 §7.2.2 "Entities", XSD `Entities`, `ScenarioObject`,
//! `Vehicle`, `Pedestrian`, `MiscObject`, `Controller`, `ObjectController`,
//! `EntitySelection`). Catalog references are resolved in place.

use crate::error::{ErrorKind, Result};
use crate::model::{
    Axle, Axles, BoundingBox, Controller, Entities, EntityObject, EntitySelection, MiscObject,
    ObjectController, Pedestrian, Performance, Properties, ScenarioObject, SelectionMember,
    Trailer, TrailerJoint, Vehicle,
};
use crate::reader::catalog::read_catalog_reference;
use crate::reader::context::{Ctx, Node};
use crate::reader::routing::expect_entry;

const ENTITY_OBJECTS: &str =
    "CatalogReference, Vehicle, Pedestrian, MiscObject, ExternalObjectReference";

/// Reads XSD `Entities`.
pub(crate) fn read_entities<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Entities> {
    let mut entities = Entities::default();
    for c in n.children().filter(Node::is_element) {
        match c.tag_name().name() {
            "ScenarioObject" => entities
                .scenario_objects
                .push(read_scenario_object(ctx, c)?),
            "EntitySelection" => entities
                .entity_selections
                .push(read_entity_selection(ctx, c)?),
            _ => return Err(ctx.unexpected(n, c, "ScenarioObject, EntitySelection")),
        }
    }
    Ok(entities)
}

/// Reads XSD `ScenarioObject` (also a Trailer's inline object).
pub(crate) fn read_scenario_object<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<ScenarioObject> {
    let name: String = ctx.req(n, "name")?;
    read_scenario_object_body(ctx, n, name)
}

/// Reads the EntityObject and ObjectControllers of a ScenarioObject or
/// ScenarioObjectTemplate `n` (the template has no name: pass an empty one).
pub(crate) fn read_scenario_object_body<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    name: String,
) -> Result<ScenarioObject> {
    ctx.check_depth(n)?;
    let object = n
        .children()
        .find(|c| c.is_element() && c.tag_name().name() != "ObjectController")
        .ok_or_else(|| {
            ctx.err(
                n,
                ErrorKind::MissingElement {
                    parent: n.tag_name().name().into(),
                    expected: format!("one of {ENTITY_OBJECTS}"),
                },
            )
        })?;
    let entity_object = read_entity_object(ctx, n, object)?;
    let mut object_controllers = Vec::new();
    for c in ctx.children(n, "ObjectController") {
        if !c.children().any(|e| e.is_element()) {
            // Invalid by the XSD (the choice of CatalogReference and Controller is required)
            // but nothing is lost: no controller is named. ASAM's own 1.2 SimpleOvertake
            // example writes `<ObjectController/>`.
            ctx.warn(
                c,
                "ObjectController has none of CatalogReference, Controller; it is read as no \
                 controller (the default controller drives)"
                    .into(),
            );
            continue;
        }
        object_controllers.push(read_object_controller(ctx, c)?);
    }
    if object_controllers.len() > 1 {
        ctx.since(n, 2);
    }
    Ok(ScenarioObject {
        name,
        entity_object,
        object_controllers,
        pos: ctx.pos(n),
    })
}

/// Reads the XSD group `EntityObject` from child `c` of `parent`.
fn read_entity_object<'a>(
    ctx: &mut Ctx<'a>,
    parent: Node<'a>,
    c: Node<'a>,
) -> Result<EntityObject> {
    Ok(match c.tag_name().name() {
        "Vehicle" => EntityObject::Vehicle(Box::new(read_vehicle(ctx, c)?)),
        "Pedestrian" => EntityObject::Pedestrian(Box::new(read_pedestrian(ctx, c)?)),
        "MiscObject" => EntityObject::MiscObject(Box::new(read_misc_object(ctx, c)?)),
        "ExternalObjectReference" => {
            ctx.since(c, 1);
            EntityObject::ExternalObjectReference(ctx.req(c, "name")?)
        }
        "CatalogReference" => {
            let (mut object, origin) =
                read_catalog_reference(ctx, c, |ctx, e| match e.tag_name().name() {
                    "Vehicle" | "Pedestrian" | "MiscObject" => read_entity_object(ctx, parent, e),
                    found => Err(ctx.err(
                        e,
                        ErrorKind::UnexpectedElement {
                            parent: "Catalog".into(),
                            found: found.into(),
                            expected: "a Vehicle, Pedestrian or MiscObject entry".into(),
                        },
                    )),
                })?;
            match &mut object {
                EntityObject::Vehicle(v) => v.catalog = Some(origin),
                EntityObject::Pedestrian(p) => p.catalog = Some(origin),
                EntityObject::MiscObject(m) => m.catalog = Some(origin),
                EntityObject::ExternalObjectReference(_) => {}
            }
            object
        }
        _ => return Err(ctx.unexpected(parent, c, ENTITY_OBJECTS)),
    })
}

/// Reads XSD `Vehicle`.
pub(crate) fn read_vehicle<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Vehicle> {
    ctx.expect_children(
        n,
        &[
            "ParameterDeclarations",
            "BoundingBox",
            "Performance",
            "Axles",
            "Properties",
            "TrailerHitch",
            "TrailerCoupler",
            "Trailer",
        ],
    )?;
    ctx.scoped(n, |ctx| {
        let bounding_box = read_bounding_box(ctx, n)?;
        let p = ctx.child(n, "Performance")?;
        let performance = Performance {
            max_speed: ctx.req_non_negative(p, "maxSpeed")?,
            max_acceleration: ctx.req_non_negative(p, "maxAcceleration")?,
            max_deceleration: ctx.req_non_negative(p, "maxDeceleration")?,
            max_acceleration_rate: ctx.opt_non_negative(p, "maxAccelerationRate")?,
            max_deceleration_rate: ctx.opt_non_negative(p, "maxDecelerationRate")?,
        };
        let a = ctx.child(n, "Axles")?;
        let front_axle = match ctx.opt_child(a, "FrontAxle") {
            Some(f) => Some(read_axle(ctx, f)?),
            None => None,
        };
        let rear = ctx.child(a, "RearAxle")?;
        let rear_axle = read_axle(ctx, rear)?;
        let mut additional_axles = Vec::new();
        for x in ctx.children(a, "AdditionalAxle") {
            additional_axles.push(read_axle(ctx, x)?);
        }
        let trailer_hitch = read_joint(ctx, n, "TrailerHitch")?;
        let trailer_coupler = read_joint(ctx, n, "TrailerCoupler")?;
        let trailer = match ctx.opt_child(n, "Trailer") {
            Some(t) => read_trailer(ctx, t)?,
            None => None,
        };
        let mass = ctx.opt(n, "mass")?;
        let role = ctx.opt(n, "role")?;
        if mass.is_some() || role.is_some() {
            ctx.since(n, 2);
        }
        Ok(Vehicle {
            name: ctx.req(n, "name")?,
            vehicle_category: ctx.req(n, "vehicleCategory")?,
            role,
            mass,
            model3d: ctx.opt(n, "model3d")?,
            bounding_box,
            performance,
            axles: Axles {
                front_axle,
                rear_axle,
                additional_axles,
            },
            properties: read_properties(ctx, n)?,
            trailer_hitch,
            trailer_coupler,
            trailer,
            catalog: None,
        })
    })
}

fn read_axle<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Axle> {
    Ok(Axle {
        max_steering: ctx.req(n, "maxSteering")?,
        wheel_diameter: ctx.req(n, "wheelDiameter")?,
        track_width: ctx.req(n, "trackWidth")?,
        position_x: ctx.req(n, "positionX")?,
        position_z: ctx.req(n, "positionZ")?,
    })
}

/// Reads XSD `TrailerHitch` or `TrailerCoupler` child `name` of `n`.
fn read_joint<'a>(ctx: &mut Ctx<'a>, n: Node<'a>, name: &str) -> Result<Option<TrailerJoint>> {
    let Some(j) = ctx.opt_child(n, name) else {
        return Ok(None);
    };
    ctx.since(j, 3);
    Ok(Some(TrailerJoint {
        dx: ctx.req(j, "dx")?,
        dz: ctx.opt(j, "dz")?,
    }))
}

/// Reads XSD `Trailer`. An empty TrailerRef (a catalog default meaning "no trailer") reads
/// as none.
fn read_trailer<'a>(ctx: &mut Ctx<'a>, t: Node<'a>) -> Result<Option<Trailer>> {
    ctx.since(t, 3);
    let c = ctx.choice(t, "Trailer, TrailerRef")?;
    Ok(match c.tag_name().name() {
        "Trailer" => Some(Trailer::Trailer(Box::new(read_scenario_object(ctx, c)?))),
        "TrailerRef" => {
            let name: String = ctx.req(c, "entityRef")?;
            if name.trim().is_empty() {
                None
            } else {
                Some(Trailer::TrailerRef(ctx.entity(c, "entityRef")?))
            }
        }
        _ => return Err(ctx.unexpected(t, c, "Trailer, TrailerRef")),
    })
}

/// Reads XSD `Pedestrian`; the deprecated `model` is read as `model3d`.
pub(crate) fn read_pedestrian<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Pedestrian> {
    ctx.expect_children(n, &["ParameterDeclarations", "BoundingBox", "Properties"])?;
    ctx.scoped(n, |ctx| {
        let old_model: Option<String> = ctx.opt(n, "model")?;
        if old_model.is_some() {
            ctx.warn(n, "Pedestrian@model is deprecated, read as model3d".into());
        }
        Ok(Pedestrian {
            name: ctx.req(n, "name")?,
            pedestrian_category: ctx.req(n, "pedestrianCategory")?,
            mass: ctx.req(n, "mass")?,
            model3d: ctx.opt(n, "model3d")?.or(old_model),
            role: ctx.opt(n, "role")?,
            bounding_box: read_bounding_box(ctx, n)?,
            properties: read_properties(ctx, n)?,
            catalog: None,
        })
    })
}

/// Reads XSD `MiscObject`.
pub(crate) fn read_misc_object<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<MiscObject> {
    ctx.expect_children(n, &["ParameterDeclarations", "BoundingBox", "Properties"])?;
    ctx.scoped(n, |ctx| {
        Ok(MiscObject {
            name: ctx.req(n, "name")?,
            misc_object_category: ctx.req(n, "miscObjectCategory")?,
            mass: ctx.req(n, "mass")?,
            model3d: ctx.opt(n, "model3d")?,
            bounding_box: read_bounding_box(ctx, n)?,
            properties: read_properties(ctx, n)?,
            catalog: None,
        })
    })
}

/// Reads the `BoundingBox` child of `n`.
pub(crate) fn read_bounding_box<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<BoundingBox> {
    let b = ctx.child(n, "BoundingBox")?;
    let c = ctx.child(b, "Center")?;
    let d = ctx.child(b, "Dimensions")?;
    Ok(BoundingBox {
        center: [ctx.req(c, "x")?, ctx.req(c, "y")?, ctx.req(c, "z")?],
        width: ctx.req(d, "width")?,
        length: ctx.req(d, "length")?,
        height: ctx.req(d, "height")?,
    })
}

/// Reads the optional `Properties` child of `n` (XSD `Properties`).
pub(crate) fn read_properties<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Properties> {
    let mut out = Properties::default();
    let Some(p) = ctx.opt_child(n, "Properties") else {
        return Ok(out);
    };
    for c in ctx.children(p, "Property") {
        out.properties
            .push((ctx.req(c, "name")?, ctx.req(c, "value")?));
        out.positions.push(ctx.pos(c));
    }
    for f in ctx.children(p, "File") {
        out.files.push(ctx.req(f, "filepath")?);
    }
    for c in ctx.children(p, "CustomContent") {
        out.custom_content
            .push(c.text().unwrap_or_default().trim().to_owned());
    }
    Ok(out)
}

/// Reads XSD `Controller`.
pub(crate) fn read_controller<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Controller> {
    ctx.scoped(n, |ctx| {
        Ok(Controller {
            pos: ctx.pos(n),
            name: ctx.req(n, "name")?,
            controller_type: ctx.opt(n, "controllerType")?,
            properties: read_properties(ctx, n)?,
            catalog: None,
        })
    })
}

/// Reads `c`, a `Controller` or a `CatalogReference` to one, child of `parent`.
pub(crate) fn read_controller_or_reference<'a>(
    ctx: &mut Ctx<'a>,
    parent: Node<'a>,
    c: Node<'a>,
) -> Result<Controller> {
    match c.tag_name().name() {
        "Controller" => read_controller(ctx, c),
        "CatalogReference" => {
            let (mut controller, origin) = read_catalog_reference(ctx, c, |ctx, e| {
                expect_entry(ctx, e, "Controller", read_controller)
            })?;
            controller.catalog = Some(origin);
            Ok(controller)
        }
        _ => Err(ctx.unexpected(parent, c, "Controller, CatalogReference")),
    }
}

/// Reads XSD `ObjectController`.
fn read_object_controller<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<ObjectController> {
    let c = ctx.choice(n, "CatalogReference, Controller")?;
    Ok(ObjectController {
        name: ctx.opt(n, "name")?,
        controller: read_controller_or_reference(ctx, n, c)?,
    })
}

/// Reads XSD `EntitySelection`; members are expanded later, once all names are known.
fn read_entity_selection<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<EntitySelection> {
    let members_node = ctx.child(n, "Members")?;
    let mut members = Vec::new();
    for m in members_node.children().filter(Node::is_element) {
        members.push(match m.tag_name().name() {
            "EntityRef" => SelectionMember::EntityRef(ctx.entity(m, "entityRef")?),
            "ByType" => SelectionMember::ByType(ctx.req(m, "objectType")?),
            _ => return Err(ctx.unexpected(members_node, m, "EntityRef, ByType")),
        });
    }
    Ok(EntitySelection {
        name: ctx.req(n, "name")?,
        members,
        objects: Vec::new(),
        pos: ctx.pos(n),
    })
}
