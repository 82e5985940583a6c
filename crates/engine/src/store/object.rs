//! An [`Entity`] from its ScenarioObject (OpenSCENARIO 1.3 §7.2.2 "Entities", XSD
//! `ScenarioObject`, `Vehicle`, `Pedestrian`, `MiscObject`): kind, bounding box, categories,
//! axles and the appearance properties; also the template of vehicles that traffic spawns.

use scenario::EntityObject;

use crate::domain::{BoundingBox, Color, Position3d};
use crate::error::Error;
use crate::world::entity::{Entity, EntityId, EntityKind};

fn bounding_box(
    bb: &scenario::BoundingBox,
    pos: &scenario::SourcePos,
) -> Result<BoundingBox, Error> {
    let [x, y, z] = bb.center;
    BoundingBox::new(Position3d::new(x, y, z), bb.length, bb.width, bb.height)
        .map_err(|e| Error::at("a valid BoundingBox", e.to_string(), pos))
}

/// The entity of scenario object `o` (also the template of spawned vehicles).
pub(crate) fn entity(id: EntityId, o: &scenario::ScenarioObject) -> Result<Entity, Error> {
    let color_of = |props: &scenario::Properties| {
        props
            .properties
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case("color") || k.eq_ignore_ascii_case("colour"))
            .and_then(|(_, v)| Color::from_name(v))
    };
    let zero = scenario::BoundingBox {
        center: [0.0; 3],
        width: 0.0,
        length: 0.0,
        height: 0.0,
    };
    let (kind, bb) = match &o.entity_object {
        EntityObject::Vehicle(v) => (EntityKind::Vehicle, &v.bounding_box),
        EntityObject::Pedestrian(p) => (EntityKind::Pedestrian, &p.bounding_box),
        EntityObject::MiscObject(m) => (EntityKind::MiscObject, &m.bounding_box),
        _ => (EntityKind::External, &zero),
    };
    let mut e = Entity::new(id, &o.name, kind, bounding_box(bb, &o.pos)?);
    match &o.entity_object {
        EntityObject::Vehicle(v) => {
            e.vehicle_category = Some(v.vehicle_category);
            e.performance = Some(v.performance);
            e.max_curvature = crate::trajectory::max_curvature(&v.axles);
            e.axles = Some(v.axles.clone());
            e.mass = v.mass;
            e.role = v.role;
            e.model3d.clone_from(&v.model3d);
            e.color = color_of(&v.properties);
        }
        EntityObject::Pedestrian(p) => {
            e.pedestrian_category = Some(p.pedestrian_category);
            e.role = p.role;
            e.model3d.clone_from(&p.model3d);
            e.color = color_of(&p.properties);
        }
        EntityObject::MiscObject(m) => {
            e.misc_object_category = Some(m.misc_object_category);
            e.model3d.clone_from(&m.model3d);
            e.color = color_of(&m.properties);
        }
        _ => {}
    }
    Ok(e)
}
