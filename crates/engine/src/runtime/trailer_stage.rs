//! The trailer stage of the step (OpenSCENARIO 1.3 §7.2.2.6 "Trailer modeling"): after the
//! controllers moved the tow vehicles, each connected trailer is placed behind its tow by the
//! one-axle kinematics of `store::trailer` (its module doc gives the tractrix and the choices),
//! tow first along a chain.

use opendrive::{normalize_angle, Pose, Real};

use crate::domain::{Acceleration6d, Vector3, Velocity6d};
use crate::store::trailer::{mount_point, tractrix_heading, Link};
use crate::store::World;
use crate::world::entity::EntityId;

/// Hitch travel beyond the tow's own distance per step (m) that counts as a jump.
const JUMP_SLACK: Real = 1.0;

/// The trailer stage: after the controllers moved every tow vehicle over `dt`, places each
/// connected trailer, tow first along a chain, and sets its speed, velocity, yaw rate,
/// acceleration and odometer. With `dt` = 0 (the initial frame) it only places.
pub(crate) fn follow(world: &mut World, dt: Real) {
    let order = world.trailers.order();
    for link in world.trailers.links.clone() {
        world.entity_mut(link.tow).trailer = Some(link.trailer);
    }
    for i in order {
        let link = world.trailers.links[i].clone();
        let Some(updated) = follow_link(world, link, dt) else {
            continue;
        };
        world.trailers.links[i] = updated;
    }
}

/// Places the trailer of `link`; the updated link, or `None` when the tow is not placed.
fn follow_link(world: &mut World, mut link: Link, dt: Real) -> Option<Link> {
    let joints = |id: EntityId| world.trailers.joints.get(&id).copied().unwrap_or_default();
    let (hitch_dx, l) = (joints(link.tow).hitch?, joints(link.trailer).coupler?);
    let tow = world.entity(link.tow);
    if !tow.placed {
        return None;
    }
    let (tow_pose, tow_speed) = (tow.pose, tow.speed);
    let hitch = mount_point(&tow_pose, hitch_dx);
    let trailer = world.entity(link.trailer);
    let old_pose = if link.last_hitch.is_some() {
        link.last_pose
    } else {
        trailer.pose
    };
    let old_speed = trailer.speed;
    // A hitch that jumped farther than the tow can drive in a step (a TeleportAction on the
    // tow) takes its trailer along in line, as at definition.
    let jumped = link.last_hitch.is_some_and(|from| {
        (hitch.0 - from.0).hypot(hitch.1 - from.1) > tow_speed.abs() * dt + JUMP_SLACK
    });
    let heading = match link.last_hitch.filter(|_| !jumped) {
        Some(from) => tractrix_heading(old_pose.h, from, hitch, l),
        None if jumped => tow_pose.h,
        None if link.align || !trailer.placed => tow_pose.h,
        // Connected where it stands: turned towards the hitch.
        None => (hitch.1 - old_pose.y).atan2(hitch.0 - old_pose.x),
    };
    let pose = Pose {
        x: hitch.0 - l * heading.cos(),
        y: hitch.1 - l * heading.sin(),
        z: tow_pose.z,
        h: heading,
        ..tow_pose
    };
    let moved = (pose.x - old_pose.x).hypot(pose.y - old_pose.y);
    let first = link.last_hitch.is_none() || jumped;
    let found = world.network.locate(pose.x, pose.y, Some(pose.h));
    world.place_resolved(link.trailer, pose, found);
    let e = world.entity_mut(link.trailer);
    // The trailer is moved here, not by the default controller.
    e.track = None;
    if !first && dt > 0.0 {
        let speed = if tow_speed < 0.0 { -moved } else { moved } / dt;
        e.speed = speed;
        e.odometer = link.odometer + moved;
        e.velocity = Velocity6d {
            translational: Vector3::new(speed, 0.0, 0.0),
            rotational: Vector3::new(0.0, 0.0, normalize_angle(heading - old_pose.h) / dt),
        };
        e.acceleration = Acceleration6d {
            translational: Vector3::new((speed - old_speed) / dt, 0.0, 0.0),
            rotational: Vector3::ZERO,
        };
    } else {
        e.speed = tow_speed;
        e.velocity = Velocity6d {
            translational: Vector3::new(tow_speed, 0.0, 0.0),
            rotational: Vector3::ZERO,
        };
    }
    link.odometer = e.odometer;
    link.last_hitch = Some(hitch);
    link.last_pose = pose;
    Some(link)
}
