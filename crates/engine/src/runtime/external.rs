//! ExternalObjectReference at runtime (OpenSCENARIO 1.3 §7.2.2 "Entities": "If an object is
//! already defined in the road network file, it can be instantiated in the scenario as Entity
//! as ExternalObjectReference"; OpenDRIVE 1.8 "Objects").
//!
//! The entity stands for the OpenDRIVE `<object>` whose `name` is the reference's name (the
//! first in road order; failing a name, the one with that `id`). It is placed from the start at
//! the object's s, t on its road, heading = road heading + `hdg`, z raised by `zOffset`, with
//! the object's length × width × height (a `radius` gives a 2r × 2r footprint; missing sizes are
//! 0) centred above the point, and never moves: the frames report it as a stationary object.

use opendrive::{normalize_angle, Object, Pose, RoadNetwork};
use scenario::{EntityObject, Scenario};

use crate::domain::{BoundingBox, Position3d};
use crate::error::Error;
use crate::store::World;

/// Places every ExternalObjectReference entity of `scenario` at its road-network object.
pub(crate) fn place_external_objects(scenario: &Scenario, world: &mut World) -> Result<(), Error> {
    for o in &scenario.entities.scenario_objects {
        let EntityObject::ExternalObjectReference(name) = &o.entity_object else {
            continue;
        };
        let Some(id) = world.id(&o.name) else {
            continue;
        };
        let (pose, object) = find(&world.network, name).ok_or_else(|| {
            Error::at(
                "an object of the road network with this name",
                format!("ExternalObjectReference '{name}'"),
                &o.pos,
            )
        })?;
        let radius = object.radius.map(|r| 2.0 * r);
        let size = |v: Option<f64>| v.or(radius).unwrap_or(0.0).max(0.0);
        let (length, width, height) = (size(object.length), size(object.width), object.height);
        let height = height.unwrap_or(0.0).max(0.0);
        let bb = BoundingBox::new(
            Position3d::new(0.0, 0.0, height / 2.0),
            length,
            width,
            height,
        )
        .map_err(|e| Error::at("object sizes >= 0", e.to_string(), &o.pos))?;
        let found = world.network.locate(pose.x, pose.y, Some(pose.h));
        world.place_resolved(id, pose, found);
        let e = world.entity_mut(id);
        e.bounding_box = bb;
        // A stationary object: the default controller must not move it along a lane.
        e.track = None;
        e.speed = 0.0;
    }
    Ok(())
}

/// The world pose of the object named (or else with id) `name`, and the object.
fn find<'n>(network: &'n RoadNetwork, name: &str) -> Option<(Pose, &'n Object)> {
    let by = |pick: &dyn Fn(&Object) -> bool| {
        network.roads().iter().find_map(|r| {
            let o = r.objects.iter().find(|o| pick(o))?;
            let mut pose = r.pose(o.s, o.t).ok()?;
            pose.h = normalize_angle(pose.h + o.hdg);
            pose.z += o.z_offset;
            Some((pose, o))
        })
    };
    by(&|o: &Object| o.name == name).or_else(|| by(&|o: &Object| o.id == name))
}
