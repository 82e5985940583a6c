//! Spawned vehicles (OpenSCENARIO 1.3 §7.2.2.3): what they are, where they may appear, and
//! their entry and exit.
//!
//! A spawned object is a vehicle (§7.2.2.3: "spawned objects are considered to be of type
//! vehicle") named `<traffic name>.entity_<n>`, n counting from 1 per action (the naming scheme
//! §7.2.2.3 proposes), driven by the default controller at its start speed along the lane it
//! appears on, in the lane's driving direction. Its template is drawn from the action's
//! TrafficDistribution (1.3) or the vehicle categories of its TrafficDefinition, else a car.
//! Its role (XSD `Role`) is drawn by weight from the TrafficDefinition's
//! VehicleRoleDistribution, if it has one, else it is the template's `role`; the draw uses a
//! stream of its own per vehicle (the run's seed, stream keyed by the vehicle's name and
//! "/role", as the controller draw in traffic/controllers.rs), so that positions, speeds,
//! templates and controllers are those of a run without roles. The spawn's event-log line
//! names the role: `spawned (role police)`.
//! It appears only on a drivable lane's centre line and at least [`MIN_GAP`] m from every
//! other placed entity. A removed vehicle keeps its id and name but is no longer placed, so it
//! leaves the frames, the conditions and the ByType selections.

use opendrive::{Direction, Pose, Real};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use scenario::{ObjectController, Performance, TrafficMix, VehicleCategory};

use super::controllers::equip;
use super::random::{stream, weighted};
use super::spawning::{Running, Spawning, Tables};
use crate::domain::{BoundingBox, Position3d};
use crate::error::Error;
use crate::store::World;
use crate::world::entity::{Entity, EntityId, EntityKind};

/// Least distance (m) between a new vehicle's reference point and any placed entity's.
pub(crate) const MIN_GAP: Real = 10.0;

/// Performance of spawned vehicles without a template: 70 m/s, 10 m/s² both ways.
const DEFAULT_PERFORMANCE: Performance = Performance {
    max_speed: 70.0,
    max_acceleration: 10.0,
    max_deceleration: 10.0,
    max_acceleration_rate: None,
    max_deceleration_rate: None,
};

/// Box of a spawned vehicle of `category` (length, width, height; centre 1.4 m ahead of the
/// rear axle for cars, half the overhang otherwise): typical sizes, as the category alone
/// gives none.
fn default_box(category: VehicleCategory) -> (Real, Real, Real, Real) {
    match category {
        VehicleCategory::Truck | VehicleCategory::Bus => (12.0, 2.5, 3.5, 4.0),
        VehicleCategory::Van => (5.5, 2.0, 2.2, 1.8),
        VehicleCategory::Motorbike | VehicleCategory::Bicycle => (2.0, 0.8, 1.5, 0.7),
        _ => (4.5, 1.8, 1.5, 1.4),
    }
}

/// A new, unplaced vehicle for a traffic action: from the mix's distribution or categories,
/// with its role drawn under the run's `seed` (module doc). Also returns the template's
/// ObjectControllers (traffic/controllers.rs gives them to the vehicle).
pub(crate) fn template(
    rng: &mut ChaCha8Rng,
    seed: u64,
    mix: &TrafficMix,
    name: String,
) -> Result<(Entity, Vec<ObjectController>), Error> {
    let (mut e, controllers) = body(rng, mix, name)?;
    if let Some(roles) = mix.definition.as_ref().map(|d| &d.vehicle_roles) {
        let mut rng = stream(seed, &format!("{}/role", e.name));
        if let Some(i) = weighted(&mut rng, roles.iter().map(|(_, w)| *w)) {
            e.role = Some(roles[i].0);
        }
    }
    Ok((e, controllers))
}

/// The vehicle of [`template`] before its role is drawn.
fn body(
    rng: &mut ChaCha8Rng,
    mix: &TrafficMix,
    name: String,
) -> Result<(Entity, Vec<ObjectController>), Error> {
    let id = EntityId(u32::MAX);
    if let Some(entry) =
        weighted(rng, mix.distribution.iter().map(|e| e.weight)).map(|i| &mix.distribution[i])
    {
        if let Some(i) = weighted(rng, entry.entities.iter().map(|(_, w)| *w)) {
            let template = &entry.entities[i].0;
            let mut e = crate::store::entity(id, template)?;
            e.name = name;
            return Ok((e, template.object_controllers.clone()));
        }
    }
    let category = mix
        .definition
        .as_ref()
        .and_then(|d| {
            weighted(rng, d.vehicle_categories.iter().map(|(_, w)| *w))
                .map(|i| d.vehicle_categories[i].0)
        })
        .unwrap_or(VehicleCategory::Car);
    let (length, width, height, cx) = default_box(category);
    // The dimensions are positive constants, so the box is valid.
    let bb = BoundingBox::new(
        Position3d::new(cx, 0.0, height / 2.0),
        length,
        width,
        height,
    )
    .expect("positive constant dimensions");
    let mut e = Entity::new(id, &name, EntityKind::Vehicle, bb);
    e.vehicle_category = Some(category);
    e.performance = Some(DEFAULT_PERFORMANCE);
    Ok((e, Vec::new()))
}

/// The pose on the centre line of the drivable lane nearest to (x, y), facing the lane's
/// driving direction, if (x, y) lies on such a lane and the lane centre is at least
/// [`MIN_GAP`] from every placed entity.
pub(crate) fn lane_point(world: &World, x: Real, y: Real) -> Option<Pose> {
    let net = &world.network;
    let rp = net.locate(x, y, None)?;
    if rp.distance > opendrive::LENGTH_EPSILON {
        return None;
    }
    let road = net.road(&rp.road_id)?;
    let lane_id = rp.lane_id;
    let lane = road.lane_section_at(rp.s).lane(lane_id)?;
    if lane_id == 0 || !lane.lane_type.is_drivable() {
        return None;
    }
    let mut pose = road.lane_pose(lane_id, rp.s, 0.0).ok()?;
    let handle = net.lane_handle(&rp.road_id, lane_id, rp.s)?;
    if net.driving_direction(handle) == Direction::Backward {
        pose.h = opendrive::normalize_angle(pose.h + std::f64::consts::PI);
    }
    let free = world
        .entities()
        .iter()
        .filter(|e| e.placed)
        .all(|e| (e.pose.x - pose.x).hypot(e.pose.y - pose.y) >= MIN_GAP);
    free.then_some(pose)
}

/// Adds `e` at `pose` with `speed`, on the lane there, for traffic action `element` (logged);
/// returns its id.
fn enter(
    world: &mut World,
    spawning: &mut Spawning,
    element: &str,
    e: Entity,
    pose: Pose,
    speed: Real,
) -> EntityId {
    let change = match e.role {
        Some(role) => format!("spawned (role {})", role.as_str()),
        None => "spawned".to_owned(),
    };
    spawning.note(element, &e.name, &change);
    let id = world.spawn(e);
    let found = world.network.locate(pose.x, pose.y, Some(pose.h));
    world.place_resolved(id, pose, found);
    let e = world.entity_mut(id);
    e.speed = speed;
    id
}

/// Adds the next vehicle of `run` at `pose` with `speed`: its template drawn from `mix`, on
/// the lane there, with its controller (traffic/controllers.rs), one of the run's members.
pub(crate) fn add(
    world: &mut World,
    tables: &mut Tables<'_>,
    run: &mut Running,
    mix: &TrafficMix,
    pose: Pose,
    speed: Real,
) -> Result<(), Error> {
    let name = run.next_name(world);
    let (e, templates) = template(&mut run.rng, world.seed, mix, name)?;
    let id = enter(world, tables.spawning, &run.name, e, pose, speed);
    equip(world, tables, id, mix, &templates, &run.name)?;
    run.members.push(id);
    Ok(())
}

/// Takes entity `id` out of the scenario for traffic action `element` (logged).
pub(crate) fn remove(world: &mut World, spawning: &mut Spawning, element: &str, id: EntityId) {
    let name = world.entity(id).name.clone();
    spawning.note(element, &name, "removed");
    leave(world, id);
}

/// Takes entity `id` out of the scenario: not placed, at rest, no actions, no track.
pub(crate) fn leave(world: &mut World, id: EntityId) {
    let e = world.entity_mut(id);
    e.placed = false;
    e.departed = true;
    e.speed = 0.0;
    e.track = None;
    e.road_position = None;
    e.longitudinal_action = None;
    e.lateral_action = None;
}

/// A uniformly random point of the disc of `radius` around (x, y).
pub(crate) fn in_disc(rng: &mut ChaCha8Rng, x: Real, y: Real, radius: Real) -> (Real, Real) {
    let r = radius * rng.gen::<f64>().sqrt();
    let a = rng.gen::<f64>() * std::f64::consts::TAU;
    (x + r * a.cos(), y + r * a.sin())
}
