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

use opendrive::{normalize_angle, Direction, LaneSpan, Real, Road, RoadNetwork};

use crate::domain::{Acceleration6d, Vector3, Velocity6d};
use crate::world::entity::{along, component_along, Entity};
use crate::world::lane_change;
use crate::world::lane_track::{Blend, LaneTrack};
use crate::world::lanes::{
    advance, keep_curvature, set_road_position, track_curvature, track_pose, track_span,
};
use crate::world::zero_angle;
use crate::world::RouteFollow;

/// Moves entity `e` over one step of `dt` s: position, heading, road position, velocity,
/// acceleration, yaw rate and odometer. `distance`, when given, is the distance to travel (a
/// user controller's longitudinal command, controller/stage.rs) instead of speed × dt.
pub(crate) fn move_entity(net: &RoadNetwork, e: &mut Entity, dt: Real, distance: Option<Real>) {
    if !e.placed {
        return;
    }
    let old_h = e.pose.h;
    // The move changes neither the entity's track's presence nor its heading relative to the
    // lane (`LaneTrack::relative_heading` is set where a track is made): the cosine and sine
    // of that heading are the same before and after it, asked once.
    let travel = e.travel_cos_sin();
    let old_v = component_along(e.velocity.translational, travel);
    // The running actions of a step act in storyboard (document) order, as in esmini: a
    // lateral action written before the running longitudinal one moves the entity before the
    // speed changes, so the entity travels at the speed of the step's start; otherwise at the
    // speed set for this step. The standard leaves the order within a step open; the
    // document order is fixed by the file alone (lane_change_simple: the Lane change
    // maneuver precedes the End Of Road speed maneuver, and esmini's lane change runs at the
    // speed of the step's start while the speed action accelerates).
    let speed = match distance {
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
    measure_along(e, old_h, old_v, dt, travel);
}

/// Sets velocity, yaw rate and acceleration of `e` after a move of `dt` s from heading
/// `old_h` and speed along the travel `old_v`.
pub(crate) fn measure(e: &mut Entity, old_h: Real, old_v: Real, dt: Real) {
    let travel = e.travel_cos_sin();
    measure_along(e, old_h, old_v, dt, travel);
}

/// [`measure`] given the cosine and sine of the entity's heading relative to its direction of
/// travel ([`Entity::travel_cos_sin`]).
#[inline(always)]
fn measure_along(e: &mut Entity, old_h: Real, old_v: Real, dt: Real, travel: (Real, Real)) {
    e.velocity = Velocity6d {
        translational: along(e.speed, travel),
        rotational: Vector3::new(0.0, 0.0, normalize_angle(e.pose.h - old_h) / dt),
    };
    e.acceleration = Acceleration6d {
        translational: along((e.speed - old_v) / dt, travel),
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
    // On a straight road the curvature is +0 (`track_curvature`), and `along_scale(+0, t)` is
    // exactly 1.0: 1 − (+0)·t is 1 for a finite t (0·t = ±0) and 1 / 1 = 1; for an infinite
    // or NaN t, 0·t and so k are NaN, which takes the scale's 1.0 branch. So there the scale
    // is 1.0 without the product, the test and the division.
    let road_scale = if road.plan_view.straight_heading().is_some() {
        1.0
    } else {
        along_scale(track_curvature(road, track), track.t)
    };
    // The speed is along the path: a lateral transition moving sideways at x·v leaves
    // v·√(1 − x²) along the lane (x taken over the step: mean of its start and end). Without
    // a transition the share is 0. Without one, and with no lateral motion left from the step
    // before (lateral_slope ±0: every move along a lane), x = 0.5·(±0 + 0) = +0, 1 − x² = 1,
    // √1 = 1 and signed·1 = signed, exactly (signed is never a signalling NaN: it is a
    // product or its negation), so `along` is `signed` without the arithmetic.
    let along = match track.blend {
        None if e.lateral_slope == 0.0 => signed,
        None => along_path(signed, e.lateral_slope, 0.0),
        Some(_) => {
            let end_share = lateral(road, track, false).map_or(0.0, |(_, _, x)| x);
            along_path(signed, e.lateral_slope, end_share)
        }
    };
    // Reversing runs the route backwards: no route successor is on offer then.
    let (left, memo_holds) = match &mut e.route_follow {
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
    if memo_holds && road_scale > 0.0 {
        // Inside the memo's range `advance` returns left = +0, so (+0 / scale) is +0 for a
        // scale > 0, signed − min(+0, signed) is signed (x − (+0) = x for every x, −0 and
        // NaN included; for signed = −0, min's +0 — x86's `minsd` returns its second operand
        // on equal zeros, and the odometer is never −0 either way), and the lane end is not
        // reached (left > 0 is false). The scale is +0 only where 1 − κ·t is +∞ (an infinite
        // t on a curved road), which takes the full rule.
        e.odometer += signed;
        e.at_lane_end = false;
    } else {
        e.odometer += signed - (left / road_scale).min(signed);
        // The lane ends with no successor: after a second step standing at its end the
        // entity stops (speed 0), as in esmini's runs.
        let blocked = left > 0.0 && left >= along * road_scale - crate::tolerance::LENGTH;
        if blocked && e.at_lane_end {
            e.speed = 0.0;
        }
        e.at_lane_end = blocked;
    }
    // Two copies of the placing, so that the move inside the memo's range (nearly every one)
    // runs without the memo's tests instead of testing the flag in their place. Inside the
    // range the track is on the road it was on (`advance` set only its s), so the road is
    // the one looked up above; otherwise the walk may have carried it onto another.
    if memo_holds {
        place(road, e, true);
    } else {
        let road = net.road_at(track.road);
        place(road, e, false);
    }
}

/// The travel `signed` along the lane of a path moving sideways at shares `start` and `end`
/// of its speed at the step's start and end: signed·√(1 − x²), x their mean (clamped to ±1).
#[inline(always)]
fn along_path(signed: Real, start: Real, end: Real) -> Real {
    let x = (0.5 * (start + end)).clamp(-1.0, 1.0);
    signed * (1.0 - x * x).sqrt()
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
            let room = lane_change::road_left(net, track);
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
///
/// Always inlined: a lane followed without a transition (nearly every move) needs only the
/// span. `memo_holds`: whether the track's lanes memo is known to hold its s
/// (world/lanes.rs `memo_held`).
#[inline(always)]
fn lateral(road: &Road, track: &mut LaneTrack, memo_holds: bool) -> Option<(Real, Real, Real)> {
    let lane = track.lane_id;
    let span = track_span(road, track, lane, memo_holds).ok()?;
    let target = span.center() + track.offset;
    match track.blend {
        None => Some((target, span.d_center(), 0.0)),
        Some(b) => Some(blended(road, track, b, span, target)),
    }
}

/// [`lateral`] during the transition `b` towards `target` on the lane of span `span`.
#[inline(never)]
fn blended(
    road: &Road,
    track: &LaneTrack,
    b: Blend,
    span: LaneSpan,
    target: Real,
) -> (Real, Real, Real) {
    let Ok(from) = road.lane_span(b.from_lane, track.s) else {
        return (target, span.d_center(), 0.0);
    };
    let t0 = from.center() + b.from_offset;
    let t = (1.0 - b.weight) * t0 + b.weight * target;
    let slope = (1.0 - b.weight) * from.d_center()
        + b.weight * span.d_center()
        + (target - t0) * b.weight_per_m * sign(track.direction);
    // (target − t0)·dw/ds is the path's slope tan θ against the lane; its share is sin θ.
    (t, slope, ((target - t0) * b.weight_per_m).atan().sin())
}

/// Sets t, pose and road position of `e` from its track after a move (nothing without one).
#[inline(never)]
pub(crate) fn place_on_track(net: &RoadNetwork, e: &mut Entity) {
    if let Some(track) = &e.track {
        place(net.road_at(track.road), e, false);
    }
}

/// [`place_on_track`], always inlined into the move (no call, and the road and the track's
/// memos it has just read stay in registers). `road`: the track's road (the caller has it).
/// `memo_holds`: the move stayed inside the track's lanes memo's range (world/lanes.rs
/// `advance`, `memo_held`), so the lane answers are the memo's without testing its range
/// again.
#[inline(always)]
fn place(road: &Road, e: &mut Entity, memo_holds: bool) {
    let Some(track) = e.track.as_mut() else {
        return;
    };
    let Some((t, dt_ds, share)) = lateral(road, track, memo_holds) else {
        return;
    };
    track.t = t;
    let Ok(mut pose) = track_pose(road, track, t, memo_holds) else {
        return;
    };
    // The pose's heading is the reference line's at s; the next move starts here and reads
    // the curvature back (world/lane_track.rs CurvatureAt).
    let k = keep_curvature(road, track, pose.h);
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
        road,
        track,
        normalize_angle(pose.h - road_h),
        &mut e.road_position,
        memo_holds,
    );
}

fn sign(d: Direction) -> Real {
    match d {
        Direction::Forward => 1.0,
        Direction::Backward => -1.0,
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use opendrive::{Pose, RoadPosition};

    use super::*;
    use crate::domain::{BoundingBox, Vector3};
    use crate::store::place_on_lane;
    use crate::world::entity::{EntityId, EntityKind};
    use crate::world::lane_change::{self, RouteLaneChange};

    /// esmini's corpus road `name`.
    fn corpus(name: &str) -> RoadNetwork {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../../shared/corpus/esmini/xodr")
            .join(name);
        RoadNetwork::from_file(&path).unwrap_or_else(|e| panic!("{e}"))
    }

    /// One road of 300 m with every feature the shortcuts must leave to the full move: two
    /// lines of one heading (0–100, 100–150 m), an arc (150–200 m) and a line; a constant
    /// elevation, then a climb (from 120 m), then constant again (from 250 m); no bank, a
    /// constant bank (from 60 m), a bank growing (from 220 m); a lane offset constant, varying
    /// (80–100 m), constant; two lane sections, the second's lane −1 widening.
    fn features() -> RoadNetwork {
        let xodr = r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" junction="-1" length="300"><link/><planView>
<geometry s="0" x="10" y="20" hdg="0.3" length="100"><line/></geometry>
<geometry s="100" x="105.533649" y="49.552021" hdg="0.3" length="50"><line/></geometry>
<geometry s="150" x="153.300473" y="64.328031" hdg="0.3" length="50"><arc curvature="0.005"/></geometry>
<geometry s="200" x="198.733878" y="84.890424" hdg="0.55" length="100"><line/></geometry>
</planView>
<elevationProfile><elevation s="0" a="2" b="0" c="0" d="0"/><elevation s="120" a="2" b="0.01" c="0" d="0"/><elevation s="250" a="3.3" b="0" c="0" d="0"/></elevationProfile>
<lateralProfile><superelevation s="0" a="0" b="0" c="0" d="0"/><superelevation s="60" a="0.03" b="0" c="0" d="0"/><superelevation s="220" a="0.03" b="0.0002" c="0" d="0"/></lateralProfile>
<lanes><laneOffset s="0" a="0" b="0" c="0" d="0"/><laneOffset s="80" a="0" b="0.01" c="0" d="0"/><laneOffset s="100" a="0.2" b="0" c="0" d="0"/>
<laneSection s="0"><left><lane id="1" type="driving"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane><lane id="-2" type="driving"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection>
<laneSection s="180"><left><lane id="1" type="driving"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><link/><width sOffset="0" a="3.5" b="0.005" c="0" d="0"/></lane><lane id="-2" type="driving"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection>
</lanes></road></OpenDRIVE>"#;
        RoadNetwork::from_str(xodr, Path::new("features.xodr")).expect("the features road")
    }

    /// Every number a move writes, as bits (the flags as 0 and 1), and the road and junction
    /// ids.
    fn state(e: &Entity) -> (Vec<u64>, String) {
        let p = e.pose;
        let v = |a: Vector3| [a.x, a.y, a.z];
        let mut out: Vec<Real> = vec![p.x, p.y, p.z, p.h, p.p, p.r, e.speed, e.odometer];
        let mut ids = String::new();
        out.extend(v(e.velocity.translational));
        out.extend(v(e.velocity.rotational));
        out.extend(v(e.acceleration.translational));
        out.extend([e.lateral_slope, Real::from(u8::from(e.at_lane_end))]);
        if let Some(rp) = &e.road_position {
            let RoadPosition {
                road_id,
                road,
                lane_id,
                s,
                t,
                offset,
                junction_id,
                relative_heading,
                distance,
            } = rp;
            ids = format!("{road_id} {road:?} {junction_id:?}");
            out.push(Real::from(*lane_id));
            out.extend([*s, *t, *offset, *relative_heading, *distance]);
        }
        if let Some(track) = &e.track {
            ids.push_str(&track.road_id);
            out.extend([track.s, track.t, track.offset, track.relative_heading]);
            out.extend([Real::from(track.lane_id), Real::from(track.road.0)]);
            out.push(Real::from(u8::from(track.direction == Direction::Forward)));
            if let Some(b) = track.blend {
                out.extend([
                    Real::from(b.from_lane),
                    b.from_offset,
                    b.weight,
                    b.weight_per_m,
                ]);
            }
        }
        (out.into_iter().map(Real::to_bits).collect(), ids)
    }

    /// A car on `net` placed at the centre of lane `lane` of road `road` at `s` (plus
    /// `offset`), facing its direction of travel under right-hand traffic.
    fn car(net: &RoadNetwork, road: usize, lane: i32, s: Real, offset: Real) -> Option<Entity> {
        let r = &net.roads()[road];
        let mut pose: Pose = r.lane_pose(lane, s, offset).ok()?;
        if lane > 0 {
            pose.h = normalize_angle(pose.h + std::f64::consts::PI);
        }
        let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), 4.5, 2.0, 1.5).expect("box");
        let mut e = Entity::new(EntityId(0), "car", EntityKind::Vehicle, b);
        place_on_lane(net, &mut e, pose, net.locate(pose.x, pose.y, Some(pose.h)));
        e.track.is_some().then_some(e)
    }

    /// Counts of what the test drove through.
    #[derive(Debug, Default)]
    struct Seen {
        moves: usize,
        advanced_in_memo: usize,
        straight_poses: usize,
        left_a_straight_stretch: usize,
        to_a_range_end: usize,
        blended: usize,
    }

    /// Drives the cars `cars` (each twice: with the memos the moves keep, and with them
    /// cleared before each move, so that it walks the lane graph, computes the pose in full
    /// and looks up every lane) `steps` steps, comparing their states after every move.
    fn drive(net: &RoadNetwork, name: &str, cars: Vec<Entity>, steps: usize, seen: &mut Seen) {
        let dt = 0.05;
        let mut rng = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            (rng >> 11) as Real / (1u64 << 53) as Real
        };
        for (i, car) in cars.into_iter().enumerate() {
            let (mut fast, mut full) = (car.clone(), car);
            let mut change: Option<RouteLaneChange> = None;
            let speed = 5.0 + 40.0 * next();
            for step in 0..steps {
                let track = fast.track.as_ref().expect("a track");
                let (s, road) = (track.s, track.road);
                let memo = track
                    .lanes
                    .filter(|m| m.road == road && m.lo <= s && s <= m.hi);
                let frame = track.frame.filter(|f| f.road == road && f.stretch.holds(s));
                // Mostly the car's speed; now and then onto the end of the lanes memo's or
                // the straight stretch's range, an ulp either side, or backwards.
                let mut d = speed * dt;
                let toward = |hi: Real| match track.direction {
                    Direction::Forward => hi - s,
                    Direction::Backward => s - hi,
                };
                match (step % 7, memo, frame) {
                    (1, Some(m), _) => d = toward(m.hi),
                    (2, Some(m), _) => d = toward(m.hi).next_up(),
                    (3, _, Some(f)) => d = toward(f.stretch.hi),
                    (4, _, Some(f)) => d = toward(f.stretch.hi).next_down(),
                    (5, Some(m), _) => d = toward(m.lo),
                    _ if next() < 0.02 => d = -d,
                    _ => {}
                }
                if matches!(step % 7, 1..=5) && d != speed * dt {
                    seen.to_a_range_end += 1;
                }
                // Now and then a lane change (the route's), the same in both.
                if change.is_none() && next() < 0.01 {
                    let track = fast.track.as_ref().expect("a track");
                    let lane = if track.lane_id.abs() > 1 || next() < 0.5 {
                        track.lane_id - track.lane_id.signum()
                    } else {
                        track.lane_id + track.lane_id.signum()
                    };
                    let odometer = fast.odometer;
                    let [c, same] = [&mut fast, &mut full].map(|e| {
                        let track = e.track.as_mut().expect("a track");
                        lane_change::begin(net, track, lane, speed, odometer, 60.0)
                    });
                    assert_eq!(c, same);
                    change = c;
                }
                if let Some(c) = change {
                    let [more, same] = [&mut fast, &mut full].map(|e| {
                        let track = e.track.as_mut().expect("a track");
                        lane_change::step(&c, track, e.odometer, d)
                    });
                    assert_eq!(more, same);
                    if !more {
                        change = None;
                    }
                    seen.blended += 1;
                }
                if let Some(t) = full.track.as_mut() {
                    (t.lanes, t.frame, t.curvature) = (None, None, None);
                }
                let before = fast.track.as_ref().map(|t| (t.road, t.s));
                move_entity(net, &mut fast, dt, Some(d));
                move_entity(net, &mut full, dt, Some(d));
                assert_eq!(
                    state(&fast),
                    state(&full),
                    "{name}, car {i}, step {step}: s {s}, d {d}\n{:?}\n{:?}",
                    fast.track,
                    full.track
                );
                seen.moves += 1;
                let track = fast.track.as_ref().expect("a track");
                let after = (track.road, track.s);
                if memo.is_some_and(|m| m.lo <= after.1 && after.1 <= m.hi)
                    && before.map(|b| b.0) == Some(after.0)
                {
                    seen.advanced_in_memo += 1;
                }
                let straight = frame.filter(|f| f.stretch.is_straight());
                match straight {
                    Some(f) if f.road == after.0 && f.stretch.holds(after.1) => {
                        seen.straight_poses += 1
                    }
                    Some(_) => seen.left_a_straight_stretch += 1,
                    None => {}
                }
                if fast.at_lane_end {
                    break;
                }
            }
        }
    }

    /// The travel along the lane without a lateral transition and without lateral motion left
    /// (`advance_entity`'s shortcut, `along = signed`) against [`along_path`] at shares ±0 and
    /// +0 (`end_share` without a transition), bit for bit: the distances of a step, ±0, the
    /// smallest subnormal, 1e300, +∞ and NaN (a quiet one, as products give). By hand:
    /// x = 0.5·(−0 + 0) = +0, √(1 − 0) = 1, 7.25·1 = 7.25.
    #[test]
    fn the_travel_without_lateral_motion_is_the_distance_bit_for_bit() {
        let distances = [
            0.0,
            -0.0,
            Real::from_bits(1),
            0.05,
            1.75,
            7.25,
            33.3,
            1e300,
            Real::INFINITY,
            Real::NAN,
        ];
        for signed in distances {
            for start in [0.0, -0.0] {
                let full = along_path(signed, start, 0.0);
                assert_eq!(full.to_bits(), signed.to_bits(), "{signed} at {start}");
            }
        }
        assert_eq!(along_path(7.25, -0.0, 0.0), 7.25);
        // A lateral share left from the step before is not the shortcut's: 0.6 and 0.8 give
        // x = 0.7, √0.51 ≈ 0.714143.
        assert!((along_path(1.0, 0.6, 0.8) - 0.714_143).abs() < 1e-6);
    }

    /// The move with its shortcuts (advance inside the lanes memo's range, the pose along a
    /// straight stretch: world/lanes.rs `advance` and `track_pose`, opendrive's
    /// `FrameStretch`) against the move without them, bit for bit in every number it writes:
    /// on a road with every feature the shortcuts leave to the full move (arcs, elevation
    /// and bank constant and varying, a varying lane offset, a widening lane, two lane
    /// sections) and on corpus roads (straight, curved, climbing, banked, junctions and lane
    /// sections of a town), with lane changes, reversing, and moves onto the ends of the
    /// ranges, an ulp either side.
    #[test]
    fn the_moves_shortcuts_give_the_full_moves_bits() {
        let mut seen = Seen::default();
        let roads: Vec<(&str, RoadNetwork)> = vec![
            ("features", features()),
            ("straight_500m", corpus("straight_500m.xodr")),
            ("crest-curve", corpus("crest-curve.xodr")),
            ("velodrome", corpus("velodrome.xodr")),
            ("two_plus_one", corpus("two_plus_one.xodr")),
            ("multi_intersections", corpus("multi_intersections.xodr")),
        ];
        for (name, net) in &roads {
            let mut cars = Vec::new();
            for (r, road) in net.roads().iter().enumerate() {
                for k in 0..4 {
                    let s = road.length * (Real::from(k) + 0.3) / 4.0;
                    for lane in road
                        .lane_section_at(s)
                        .lanes()
                        .map(|l| l.id)
                        .filter(|&l| l != 0)
                    {
                        let offset = if k == 1 { 0.3 } else { 0.0 };
                        cars.extend(car(net, r, lane, s, offset));
                    }
                }
            }
            let steps = if net.roads().len() > 20 { 120 } else { 400 };
            drive(net, name, cars, steps, &mut seen);
        }
        // Both shortcuts were taken, and the ranges' ends were met and left.
        assert!(seen.advanced_in_memo > seen.moves / 2, "{seen:?}");
        assert!(seen.straight_poses > seen.moves / 4, "{seen:?}");
        assert!(seen.left_a_straight_stretch > 100, "{seen:?}");
        assert!(seen.to_a_range_end > 1000, "{seen:?}");
        assert!(seen.blended > 1000, "{seen:?}");
    }
}
