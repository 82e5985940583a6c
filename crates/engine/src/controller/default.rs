//! The default controller (OpenSCENARIO 1.3 §7.5.1 "Default controller"): keeps the speed the
//! longitudinal domain last set and the lane offset the lateral domain last set, and follows
//! its lane along the road, through lane sections and junctions. With an assigned route it
//! takes the route's successor where a road ends and changes lanes where the route needs it
//! (`route`, `lane_change`); without one, or off it, the first lane link in the road model's
//! order, so the choice is deterministic (§7.5.1 leaves the choice at junctions open).
//!
//! Longitudinal then lateral, each step: the entity travels `speed · dt` metres along its lane
//! (at its lateral position t the reference line's s advances by that distance / (1 − κ·t)),
//! then its lateral position t is set from the lane centre plus offset, or from the lateral
//! transition in progress. Heading = direction of travel along the road + the slope of the
//! lateral motion, h = h_road + atan2(dt/ds, 1 − κ·t), plus the entity's own relative heading.
//! An entity off every lane moves straight along its heading.

use opendrive::{normalize_angle, Direction, Real, Road, RoadNetwork};

use crate::domain::{Acceleration6d, Vector3, Velocity6d};
use crate::world::entity::Entity;
use crate::world::lane_change;
use crate::world::lane_track::{CurvatureAt, LaneTrack};
use crate::world::lanes::{
    advance, curvature_with_heading, set_road_position, track_curvature, track_span,
};
use crate::world::zero_angle;
use crate::world::RouteFollow;

/// Moves entity `e` over one step of `dt` s: position, heading, road position, velocity,
/// acceleration, yaw rate and odometer. `travel`, when given, is the distance to travel (a
/// user controller's longitudinal command, controller/stage.rs) instead of speed × dt.
pub(crate) fn move_entity(net: &RoadNetwork, e: &mut Entity, dt: Real, travel: Option<Real>) {
    if !e.placed {
        return;
    }
    let old_h = e.pose.h;
    let old_v = e.travel_component(e.velocity.translational);
    // The running actions of a step act in storyboard (document) order, as in esmini: a
    // lateral action written before the running longitudinal one moves the entity before the
    // speed changes, so the entity travels at the speed of the step's start; otherwise at the
    // speed set for this step. The standard leaves the order within a step open; the
    // document order is fixed by the file alone (lane_change_simple: the Lane change
    // maneuver precedes the End Of Road speed maneuver, and esmini's lane change runs at the
    // speed of the step's start while the speed action accelerates).
    let speed = match travel {
        Some(d) => d / dt,
        None if e.lateral_first => e.start_speed,
        None => e.speed,
    };
    if e.held {
        // An action set the pose for this step: measure only.
        e.held = false;
        if e.track.is_none() {
            e.road_position = net.locate(e.pose.x, e.pose.y, Some(e.pose.h));
        }
    } else {
        advance_entity(net, e, speed, dt);
    }
    measure(e, old_h, old_v, dt);
}

/// Sets velocity, yaw rate and acceleration of `e` after a move of `dt` s from heading
/// `old_h` and speed along the travel `old_v`.
pub(crate) fn measure(e: &mut Entity, old_h: Real, old_v: Real, dt: Real) {
    e.velocity = Velocity6d {
        translational: e.travel_velocity(),
        rotational: Vector3::new(0.0, 0.0, normalize_angle(e.pose.h - old_h) / dt),
    };
    e.acceleration = Acceleration6d {
        translational: e.along_travel((e.speed - old_v) / dt),
        rotational: Vector3::ZERO,
    };
}

/// Moves `e` over `dt` s at `speed`: along its lane track, or straight along its heading.
/// The track is changed where it lies in the entity (no copy of it per step).
fn advance_entity(net: &RoadNetwork, e: &mut Entity, speed: Real, dt: Real) {
    let distance = speed * dt;
    let Some(track) = e.track.as_mut() else {
        e.pose.x += distance * e.pose.h.cos();
        e.pose.y += distance * e.pose.h.sin();
        e.odometer += distance.abs();
        e.road_position = net.locate(e.pose.x, e.pose.y, Some(e.pose.h));
        return;
    };
    if let Some(follow) = &mut e.route_follow {
        let lateral_free = e.lateral_action.is_none();
        let at = (e.odometer, speed, dt);
        follow_route(net, follow, track, lateral_free, at);
    }
    let signed = if distance >= 0.0 {
        distance
    } else {
        track.direction = track.direction.reverse();
        -distance
    };
    let road = net.road_at(track.road);
    let road_scale = along_scale(track_curvature(road, track), track.t);
    // The speed is along the path: a lateral transition moving sideways at x·v leaves
    // v·√(1 − x²) along the lane (x taken over the step: mean of its start and end). Without
    // a transition the share is 0.
    let end_share = match track.blend {
        Some(_) => lateral(road, track).map_or(0.0, |(_, _, x)| x),
        None => 0.0,
    };
    let x = (0.5 * (e.lateral_slope + end_share)).clamp(-1.0, 1.0);
    let along = signed * (1.0 - x * x).sqrt();
    // Reversing runs the route backwards: no route successor is on offer then.
    let left = match &mut e.route_follow {
        Some(follow) if distance >= 0.0 => {
            advance(net, track, along * road_scale, &mut |road, c| {
                follow.choose(net, road, c)
            })
        }
        _ => advance(net, track, along * road_scale, &mut |_, _| None),
    };
    if distance < 0.0 {
        track.direction = track.direction.reverse();
    }
    e.odometer += signed - (left / road_scale).min(signed);
    // The lane ends with no successor: after a second step standing at its end the entity
    // stops (speed 0), as in esmini's runs.
    let blocked = left > 0.0 && left >= along * road_scale - crate::tolerance::LENGTH;
    if blocked && e.at_lane_end {
        e.speed = 0.0;
    }
    e.at_lane_end = blocked;
    place_on_track(net, e);
}

/// Ratio of reference-line length to travelled length at lateral position t where the
/// reference line's curvature is `curvature`: 1 / (1 − κ·t).
fn along_scale(curvature: Real, t: Real) -> Real {
    let k = 1.0 - curvature * t;
    if k > 0.1 {
        1.0 / k
    } else {
        1.0
    }
}

/// The route's part of a step, before the move: finds the entity on its route, steps the lane
/// change the route needs or starts it. `(odometer, speed, dt)`: the odometer reading and the
/// step's speed and length. A lateral action owns the lateral domain (§7.5.1): while
/// `lateral_free` is false the route's lane change gives way.
fn follow_route(
    net: &RoadNetwork,
    follow: &mut RouteFollow,
    track: &mut LaneTrack,
    lateral_free: bool,
    (odometer, speed, dt): (Real, Real, Real),
) {
    let distance = speed * dt;
    follow.sync(track);
    if !lateral_free {
        follow.change = None;
        return;
    }
    if follow.change.is_none() && track.blend.is_none() && distance != 0.0 {
        if let Some(lane) = follow.needed_lane(net, track) {
            let room = match track.direction {
                Direction::Forward => net.road_at(track.road).length - track.s,
                Direction::Backward => track.s,
            };
            follow.change = lane_change::begin(net, track, lane, speed, odometer, room);
        }
    }
    if let Some(change) = follow.change {
        if !lane_change::step(&change, track, odometer, distance) {
            follow.change = None;
        }
    }
}

/// Lateral position t of a track at its s, the slope dt/ds of the path it follows there (the
/// lane centre plus offset, or the blend of a lateral transition), and the lateral transition's
/// share of the motion: lateral speed / speed (0 without a transition).
fn lateral(road: &Road, track: &mut LaneTrack) -> Option<(Real, Real, Real)> {
    let lane = track.lane_id;
    let span = track_span(road, track, lane).ok()?;
    let target = span.center() + track.offset;
    let Some(b) = track.blend else {
        return Some((target, span.d_center(), 0.0));
    };
    let Ok(from) = road.lane_span(b.from_lane, track.s) else {
        return Some((target, span.d_center(), 0.0));
    };
    let t0 = from.center() + b.from_offset;
    let t = (1.0 - b.weight) * t0 + b.weight * target;
    let slope = (1.0 - b.weight) * from.d_center()
        + b.weight * span.d_center()
        + (target - t0) * b.weight_per_m * sign(track.direction);
    // (target − t0)·dw/ds is the path's slope tan θ against the lane; its share is sin θ.
    Some((t, slope, ((target - t0) * b.weight_per_m).atan().sin()))
}

/// Sets t, pose and road position of `e` from its track after a move (nothing without one).
pub(crate) fn place_on_track(net: &RoadNetwork, e: &mut Entity) {
    let Some(track) = e.track.as_mut() else {
        return;
    };
    let road = net.road_at(track.road);
    let Some((t, dt_ds, share)) = lateral(road, track) else {
        return;
    };
    track.t = t;
    let Ok(mut pose) = road.pose(track.s, t) else {
        return;
    };
    // The pose's heading is the reference line's at s; the next move starts here and reads
    // the curvature back (world/lane_track.rs CurvatureAt).
    let k = curvature_with_heading(road, track.s, pose.h);
    track.curvature = Some(CurvatureAt {
        road: track.road,
        s_bits: track.s.to_bits(),
        value: k,
    });
    // dt/ds is exactly 0 off lane changes and widening lanes (world/zero_angle.rs: libm's bits).
    let slope = zero_angle::atan2(dt_ds, 1.0 - k * t);
    let road_h = pose.h;
    pose.h = match track.direction {
        Direction::Forward => normalize_angle(road_h + slope + track.relative_heading),
        Direction::Backward => {
            normalize_angle(road_h + std::f64::consts::PI + slope + track.relative_heading)
        }
    };
    e.pose = pose;
    e.lateral_slope = share;
    set_road_position(
        net,
        track,
        normalize_angle(pose.h - road_h),
        &mut e.road_position,
    );
}

fn sign(d: Direction) -> Real {
    match d {
        Direction::Forward => 1.0,
        Direction::Backward => -1.0,
    }
}
