//! Lane geometry the runtime needs on top of the road model (OpenDRIVE 1.8 §8.3 reference-line
//! coordinates, §11 lanes, §10.3 road linkage, §11.5 lane linkage): the reference line's curvature, lateral-lane arithmetic across the centre lane, and carrying a
//! [`LaneTrack`] along its lane through lane sections, road links and junctions.
//!
//! Written here because the road crate answers single queries (pose, span, successors) and the
//! runtime needs them combined per step; it adds no geometry of its own.

use opendrive::{
    angle_difference, Direction, LaneHandle, LaneSpan, LaneType, Pose, Real, Road, RoadNetwork,
    RoadPosition,
};

use super::lane_track::{CurvatureAt, FrameAt, LaneTrack, LanesMemo};
use crate::position::{add_lanes, lane_at};

/// Step (m) of the finite difference that gives the reference line's curvature.
const CURVATURE_STEP: Real = 0.01;
/// Most lane-graph hops taken in one step (short junction roads); bounds the loop.
const MAX_HOPS: usize = 16;

/// Curvature (1/m) of the reference line of `road` at `s`, by a forward (or, at the road's
/// end, backward) difference of the heading.
pub fn curvature(road: &Road, s: Real) -> Real {
    road.heading(s)
        .map_or(0.0, |h| curvature_with_heading(road, s, h))
}

/// [`curvature`] given the reference line's heading at `s` (the `h` of any [`Road::pose`] at
/// that `s`, which does not depend on t): one pose less to evaluate, the same value bit for
/// bit.
///
/// On a straight road ([`PlanView::straight_heading`](opendrive::PlanView::straight_heading):
/// one line heading everywhere) given that heading it is +0 without a second heading: the
/// difference below is then `angle_difference(h, h) / (b − a)` = +0 / (b − a) = +0 (h − h is
/// +0 for a finite h, §9.2.1 a line's heading does not change along it), and every other
/// branch returns 0.0 too. Any other heading or road takes the difference
/// ([`curvature_by_difference`]); the test `the_straight_roads_shortcut_gives_the_difference_bit_for_bit`
/// compares the two.
#[inline]
pub(crate) fn curvature_with_heading(road: &Road, s: Real, heading: Real) -> Real {
    if road.plan_view.straight_heading().map(Real::to_bits) == Some(heading.to_bits()) {
        return 0.0;
    }
    curvature_by_difference(road, s, heading)
}

/// [`curvature_with_heading`] by the finite difference of the heading, whatever the road.
#[inline(never)]
fn curvature_by_difference(road: &Road, s: Real, heading: Real) -> Real {
    let forward = s + CURVATURE_STEP <= road.length;
    let (a, b) = if forward {
        (s, s + CURVATURE_STEP)
    } else {
        ((s - CURVATURE_STEP).max(0.0), s)
    };
    match road.heading(if forward { b } else { a }) {
        Ok(other) if b > a => {
            let (ha, hb) = if forward {
                (heading, other)
            } else {
                (other, heading)
            };
            angle_difference(hb, ha) / (b - a)
        }
        _ => 0.0,
    }
}

/// [`curvature`] at the track's road and s: +0 on a straight road, else the value the last
/// move left there ([`keep_curvature`]), else computed.
///
/// On a straight road ([`PlanView::straight_heading`](opendrive::PlanView::straight_heading))
/// [`curvature`] is +0 at every s: where `Road::heading` answers, it answers that heading
/// (its doc), for which [`curvature_with_heading`] is +0; where it does not (s off the road,
/// NaN), `curvature` is 0.0 = +0 as well. So there the memo is neither read nor written.
#[inline(always)]
pub(crate) fn track_curvature(road: &Road, track: &LaneTrack) -> Real {
    if road.plan_view.straight_heading().is_some() {
        return 0.0;
    }
    track
        .curvature_here()
        .unwrap_or_else(|| curvature(road, track.s))
}

/// [`curvature_with_heading`] at the track's road and s, given the reference line's heading
/// there (the `h` of the road's pose at s), kept in the track's curvature memo for the next
/// move's [`track_curvature`]; on a straight road +0 without the memo (the argument of
/// [`track_curvature`]: the heading given is then the straight heading).
#[inline(always)]
pub(crate) fn keep_curvature(road: &Road, track: &mut LaneTrack, heading: Real) -> Real {
    if road.plan_view.straight_heading().is_some() {
        return 0.0;
    }
    let k = curvature_with_heading(road, track.s, heading);
    track.curvature = Some(CurvatureAt {
        road: track.road,
        s_bits: track.s.to_bits(),
        value: k,
    });
    k
}

/// The track's lane memo, if it holds the track's road and s.
fn memo(track: &mut LaneTrack) -> Option<&mut LanesMemo> {
    let (road, s) = (track.road, track.s);
    track
        .lanes
        .as_mut()
        .filter(|m| m.road == road && m.lo <= s && s <= m.hi)
}

/// [`memo`], where `memo_holds` says whether the caller knows that the memo holds the track's
/// road and s: [`advance`] moved the track inside the memo's range (its second value) and
/// nothing has changed the track's road, s or memo since but [`track_span`], which keeps a
/// memo that holds s holding it. Then the memo is the track's without the test.
#[inline(always)]
fn memo_held(track: &mut LaneTrack, memo_holds: bool) -> Option<&mut LanesMemo> {
    if memo_holds {
        track.lanes.as_mut()
    } else {
        memo(track)
    }
}

/// The span of the followed lane `lane` of the track's road at its s ([`Road::lane_span`]):
/// from the track's memo while the lanes stay the same, else computed, and the memo made anew
/// where the lanes are constant around s. `memo_holds`: [`memo_held`].
#[inline(always)]
pub(crate) fn track_span(
    road: &Road,
    track: &mut LaneTrack,
    lane: i32,
    memo_holds: bool,
) -> Result<LaneSpan, opendrive::Error> {
    let s = track.s;
    if let Some(m) = memo_held(track, memo_holds) {
        if m.lane == lane {
            return Ok(m.span);
        }
    }
    track_span_anew(road, track, lane, s)
}

/// [`track_span`] where the memo does not hold the lane's span at s: the span computed, and
/// kept in the memo that holds s (another lane followed: a lane change ended), else in a
/// memo made anew where the lanes are constant around s.
#[inline(never)]
fn track_span_anew(
    road: &Road,
    track: &mut LaneTrack,
    lane: i32,
    s: Real,
) -> Result<LaneSpan, opendrive::Error> {
    if let Some(m) = memo(track) {
        m.span = road.lane_span(lane, s)?;
        m.lane = lane;
        return Ok(m.span);
    }
    let span = road.lane_span(lane, s)?;
    // The memo is made inside the track's frame stretch at s (`LaneTrack::lanes`), so that a
    // move inside it takes the pose from that stretch without testing it (`track_pose`).
    let held = (track.frame.as_ref()).is_some_and(|f| f.road == track.road && f.stretch.holds(s));
    if !held {
        refresh_frame(road, track);
    }
    track.lanes = match (road.constant_lanes(s), &track.frame) {
        (Some((lo, hi)), Some(f)) if f.road == track.road => Some(LanesMemo {
            road: track.road,
            lo: lo.max(f.stretch.lo),
            hi: hi.min(f.stretch.hi),
            lane,
            span,
            at: None,
        }),
        _ => None,
    };
    Ok(span)
}

/// [`Road::pose`] at the track's road and s and lateral position `t`: from the frame stretch
/// the track keeps while it holds s ([`Road::pose_in`]: on a straight stretch without a
/// look-up, the same bits), else computed and the stretch around s kept. Always inlined
/// into the move, its one caller (out of line, its pose came back through memory).
/// `memo_holds` ([`memo_held`]): the lanes memo holds the track's road and s, and it lies
/// inside the kept stretch (`LaneTrack::lanes`), so the stretch holds them too and is used
/// without its road and range tests ([`Road::pose_in_held`]).
#[inline(always)]
pub(crate) fn track_pose(
    road: &Road,
    track: &mut LaneTrack,
    t: Real,
    memo_holds: bool,
) -> Result<Pose, opendrive::Error> {
    let s = track.s;
    if memo_holds {
        if let Some(f) = &track.frame {
            return road.pose_in_held(&f.stretch, s, t);
        }
    }
    match &track.frame {
        Some(f) if f.road == track.road && f.stretch.holds(s) => road.pose_in(&f.stretch, s, t),
        _ => {
            refresh_frame(road, track);
            road.pose(s, t)
        }
    }
}

/// Makes the track's frame stretch anew at its road and s ([`Road::frame_stretch`]), and
/// drops a lanes memo that does not lie inside the new stretch, so that every kept memo
/// does (`LaneTrack::lanes`; a track reversing into an old memo's range would otherwise
/// take a stretch that no longer holds it).
#[inline(never)]
fn refresh_frame(road: &Road, track: &mut LaneTrack) {
    track.frame = road.frame_stretch(track.s).map(|stretch| FrameAt {
        road: track.road,
        stretch,
    });
    let inside = match (&track.lanes, &track.frame) {
        (None, _) => true,
        (Some(m), Some(f)) => m.road == f.road && f.stretch.lo <= m.lo && m.hi <= f.stretch.hi,
        (Some(_), None) => false,
    };
    if !inside {
        track.lanes = None;
    }
}

/// [`lane_at`] at the track's road, s and t: from the memo while the lanes and t stay the
/// same. `memo_holds`: [`memo_held`].
#[inline(always)]
pub(crate) fn track_lane_at(
    road: &Road,
    track: &mut LaneTrack,
    memo_holds: bool,
) -> Option<(i32, Real)> {
    let (s, t) = (track.s, track.t);
    let Some(m) = memo_held(track, memo_holds) else {
        return lane_at(road, s, t);
    };
    match m.at {
        Some((bits, found)) if bits == t.to_bits() => found,
        _ => {
            let found = lane_at(road, s, t);
            m.at = Some((t.to_bits(), found));
            found
        }
    }
}

/// The lane `n` lanes to the left of `lane` (right for negative `n`) as seen when driving in
/// `direction`, skipping the centre lane 0.
///
/// Ids saturate at `i32::MIN`/`i32::MAX`: a scenario's shift (a RelativeTargetLane's `value`)
/// is any integer, and stepping lane by lane took |n| steps and overflowed past the ends.
pub fn lane_shift(lane: i32, n: i32, direction: Direction) -> i32 {
    // Travelling towards +s, "left" is towards larger ids; towards −s it is towards smaller ids.
    let n = if direction == Direction::Forward {
        n
    } else {
        n.saturating_neg()
    };
    add_lanes(lane, n)
}

/// The drivable lane numbered `n` (1 or more) among the drivable lanes of the side of `road`
/// that holds `lane`, at `s`, counted from the right as seen when driving in `direction` (from
/// the left with `from_left`): ASAM OpenSCENARIO DSL 2.1 §8.9 `lane(n [, from: left])`.
/// Driving towards +s, the rightmost is the smallest id (−3 before −2; 1 before 2 on the
/// left side); towards −s the largest.
pub fn numbered_lane(
    road: &Road,
    lane: i32,
    s: Real,
    direction: Direction,
    (n, from_left): (u32, bool),
) -> Option<i32> {
    let mut ids = road.lane_section_at(s).side_from_right(
        lane > 0,
        direction == Direction::Backward,
        LaneType::is_drivable,
    );
    if from_left {
        ids.reverse();
    }
    ids.get(usize::try_from(n).ok()?.checked_sub(1)?).copied()
}

/// Moves `track` by `distance` m of travel along s in its direction, following lane links
/// (the first successor, in the road model's order, or the one `prefer` picks from the
/// successors where the road named by its first argument ends). Returns the distance that
/// could not be driven because the lane ends with no successor, and whether the track moved
/// inside its lanes memo's range (so that the memo holds its road and new s: [`memo_held`]).
///
/// Inside the track's lanes memo's range (the lanes of one road constant, one lane section,
/// a `CONSTANT_MARGIN` > `S_TOLERANCE` inside its ends, on the road) the move is the first
/// pass of the walk (`walk`) with nothing crossed: there the target is on the road and the
/// section at the target and the section holding any lane at s are that one, so
/// `cross_sections` keeps every lane; so where s and the target both lie in the range, s
/// becomes the target and nothing else changes, without the walk.
#[inline]
pub fn advance(
    net: &RoadNetwork,
    track: &mut LaneTrack,
    distance: Real,
    prefer: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
) -> (Real, bool) {
    let target = target(track, distance);
    if memo(track).is_some_and(|m| m.lo <= target && target <= m.hi) {
        track.s = target;
        return (0.0, true);
    }
    (walk(net, track, distance, prefer), false)
}

/// The s `distance` m of travel from the track's s in its direction.
#[inline]
fn target(track: &LaneTrack, distance: Real) -> Real {
    let sign = if track.direction == Direction::Forward {
        1.0
    } else {
        -1.0
    };
    track.s + sign * distance
}

/// [`advance`] hop by hop along the lane graph.
#[inline(never)]
fn walk(
    net: &RoadNetwork,
    track: &mut LaneTrack,
    mut distance: Real,
    prefer: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
) -> Real {
    for _ in 0..MAX_HOPS {
        let road = net.road_at(track.road);
        let target = target(track, distance);
        if (0.0..=road.length).contains(&target) {
            cross_sections(net, road, track, target);
            track.s = target;
            return 0.0;
        }
        let end = match track.direction {
            Direction::Forward => road.length,
            Direction::Backward => 0.0,
        };
        distance -= (end - track.s).abs();
        cross_sections(net, road, track, end);
        track.s = end;
        let Some(handle) = net.lane_handle(&track.road_id, track.lane_id, end) else {
            return distance;
        };
        let successors = net.successors(handle);
        let Some(next) = prefer(&track.road_id, successors).or_else(|| successors.first().copied())
        else {
            return distance;
        };
        let next_road = net.handle_road(next);
        let direction = net.driving_direction(next);
        // A lateral transition in progress goes on from the lane followed, which the link
        // carries onto the next road: its start point is re-expressed from that lane's centre.
        anchor_blend(road, track, end);
        if direction != track.direction {
            // The roads meet end to end (or start to start): the next road's t axis points
            // the other way, so offsets from the lane centre change sign (0 − x keeps a zero
            // offset +0).
            track.offset = 0.0 - track.offset;
            if let Some(b) = &mut track.blend {
                b.from_offset = 0.0 - b.from_offset;
            }
        }
        track.road_id.clone_from(&next_road.id);
        track.road = next.road_handle();
        track.lane_id = next.lane;
        if let Some(b) = &mut track.blend {
            b.from_lane = next.lane;
        }
        track.direction = direction;
        track.s = if direction == Direction::Forward {
            next_road.lane_sections[next.section as usize].s
        } else {
            next_road.lane_section_end(next.section as usize)
        };
    }
    distance
}

/// Where lane section `k` of `road` ends travelling `direction`: its end s forward, its start
/// s backward.
#[inline]
pub(crate) fn section_end(road: &Road, k: usize, direction: Direction) -> Real {
    match direction {
        Direction::Forward => road.lane_section_end(k),
        Direction::Backward => road.lane_sections[k].s,
    }
}

/// The lane that follows lane `h` travelled in `direction` where its lane section ends
/// ([`section_end`]), through lane sections, road links and junctions (OpenDRIVE 1.8 §11.5
/// lane linkage; its successors when travelled with its driving direction, else its
/// predecessors): the next section of the same road, else `choose`'s pick among the lanes on
/// other roads, given the road's id (`None`: the first). With the direction of travel on it
/// and the s where it is entered. `None` where no lane follows: the lane ends there.
#[inline]
pub(crate) fn next_lane(
    net: &RoadNetwork,
    h: LaneHandle,
    direction: Direction,
    choose: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
) -> Option<(LaneHandle, Direction, Real)> {
    let with_traffic = direction == net.driving_direction(h);
    let next = if with_traffic {
        net.successors(h)
    } else {
        net.predecessors(h)
    };
    let pick = match next.iter().find(|n| n.road == h.road) {
        Some(&n) => n,
        None => choose(&net.handle_road(h).id, next).or_else(|| next.first().copied())?,
    };
    let direction = if with_traffic {
        net.driving_direction(pick)
    } else {
        net.driving_direction(pick).reverse()
    };
    let at = section_end(
        net.handle_road(pick),
        pick.section as usize,
        direction.reverse(),
    );
    Some((pick, direction, at))
}

/// A lane narrower than this (m) at a lane section's end has ended there ([`lane_left`]).
pub(crate) const ENDED_WIDTH: Real = 0.01;

/// How much of lane `h` lies ahead of s `from` travelling `direction` (m), following it
/// through lane sections, road links and junctions as [`next_lane`] does (`choose` picks at a
/// road's end), up to where it ends (OpenDRIVE 1.8 §11: where its lane section ends and no
/// lane follows, or where it has narrowed to nothing, under [`ENDED_WIDTH`] at a section's
/// end). Walked only until `cap` m: a number ≥ `cap` says "at least `cap`". Past
/// [`MAX_HOPS`] lanes, +∞ (not known to end).
pub(crate) fn lane_left(
    net: &RoadNetwork,
    mut h: LaneHandle,
    mut direction: Direction,
    mut from: Real,
    cap: Real,
    choose: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
) -> Real {
    let mut left = 0.0;
    for _ in 0..MAX_HOPS {
        let road = net.handle_road(h);
        let end = section_end(road, h.section as usize, direction);
        left += (end - from).abs();
        if left >= cap {
            return left;
        }
        let narrowed = road
            .lane_span(h.lane, end)
            .map_or(true, |span| span.width() < ENDED_WIDTH);
        if narrowed {
            return left;
        }
        let Some(next) = next_lane(net, h, direction, choose) else {
            return left;
        };
        (h, direction, from) = next;
    }
    Real::INFINITY
}

/// The id that lane `lane` of road `road_id` at s `from` has at s `to`, travelling in
/// `direction`: lane links carry it across lane-section boundaries (OpenDRIVE 1.8 §11.5 "Lane
/// linkage"); a lane without a link into the next section keeps its id.
pub fn carry_lane(
    net: &RoadNetwork,
    road_id: &str,
    lane: i32,
    from: Real,
    to: Real,
    direction: Direction,
) -> i32 {
    let (Some(road), Some(mut h)) = (net.road(road_id), net.lane_handle(road_id, lane, from))
    else {
        return lane;
    };
    let last = road.lane_section_index(to);
    let step: i64 = if last as i64 > i64::from(h.section) {
        1
    } else {
        -1
    };
    while h.section as usize != last {
        let linked = if direction == net.driving_direction(h) {
            net.successors(h)
        } else {
            net.predecessors(h)
        };
        let next_section = (i64::from(h.section) + step) as u32;
        h = linked
            .iter()
            .copied()
            .find(|n| n.road == h.road && n.section == next_section)
            .unwrap_or(LaneHandle {
                section: next_section,
                ..h
            });
    }
    h.lane
}

/// Carries the lane `track` follows (on `road`), and the lane a lateral transition comes
/// from, from its s to s `to` across lane sections ([`carry_lane`]); within one lane section
/// (most steps) both stay as they are.
fn cross_sections(net: &RoadNetwork, road: &Road, track: &mut LaneTrack, to: Real) {
    // carry_lane's own test: the section holding the lane at s (net.lane_handle) is the one
    // at `to`.
    let last = road.lane_section_index(to);
    let stays = |lane| road.lane_section_index_holding(lane, track.s) == last;
    let blend_stays = match track.blend {
        Some(b) => stays(b.from_lane),
        None => true,
    };
    if stays(track.lane_id) && blend_stays {
        return;
    }
    let carry = |lane| carry_lane(net, &track.road_id, lane, track.s, to, track.direction);
    let lane = carry(track.lane_id);
    let from = track.blend.map(|b| carry(b.from_lane));
    track.lane_id = lane;
    if let (Some(b), Some(from)) = (&mut track.blend, from) {
        b.from_lane = from;
    }
}

/// Re-expresses the lateral transition in progress on `track` (if any) from its own lane at
/// `s` of `road`: the lane it left becomes the lane it goes to, at the offset from that lane's
/// centre its start point has (the transition then follows that lane's centre at both ends).
fn anchor_blend(road: &Road, track: &mut LaneTrack, s: Real) {
    let Some(b) = &mut track.blend else {
        return;
    };
    if let (Ok(from), Ok(to)) = (
        road.lane_span(b.from_lane, s),
        road.lane_span(track.lane_id, s),
    ) {
        b.from_offset += from.center() - to.center();
        b.from_lane = track.lane_id;
    }
}

/// Sets `out` to the road position of `track` (no look-up: the track knows its road);
/// `relative_heading` is the entity's heading minus the road's. The strings of the position
/// `out` held are reused, so that a step allocates nothing. `None` where the track's lane
/// section has no lanes at its s. `road`: the track's road. `memo_holds`: [`memo_held`].
/// Always inlined into the move, its one caller.
#[inline(always)]
pub fn set_road_position(
    road: &Road,
    track: &mut LaneTrack,
    relative_heading: Real,
    out: &mut Option<RoadPosition>,
    memo_holds: bool,
) {
    let Some((lane_id, offset)) = track_lane_at(road, track, memo_holds) else {
        *out = None;
        return;
    };
    let Some(rp) = out else {
        *out = Some(RoadPosition {
            road_id: track.road_id.clone(),
            road: track.road,
            lane_id,
            s: track.s,
            t: track.t,
            offset,
            junction_id: road.junction.clone(),
            relative_heading,
            distance: 0.0,
        });
        return;
    };
    // In place (every field named, so that a new one cannot be missed); the ids are copied
    // only when the road changed, which the handles tell (the id strings are each entity's
    // own heap allocations: comparing them was a cache miss per entity and step).
    let RoadPosition {
        road_id: rp_road_id,
        road: rp_road,
        lane_id: rp_lane,
        s: rp_s,
        t: rp_t,
        offset: rp_offset,
        junction_id: rp_junction,
        relative_heading: rp_heading,
        distance: rp_distance,
    } = rp;
    if *rp_road != track.road {
        *rp_road = track.road;
        rp_road_id.clone_from(&track.road_id);
        rp_junction.clone_from(&road.junction);
    } else if *rp_junction != road.junction {
        rp_junction.clone_from(&road.junction);
    }
    *rp_lane = lane_id;
    *rp_s = track.s;
    *rp_t = track.t;
    *rp_offset = offset;
    *rp_heading = relative_heading;
    *rp_distance = 0.0;
}

#[cfg(test)]
mod tests {
    use opendrive::RoadHandle;

    use super::*;

    #[test]
    fn lane_shift_steps_over_the_centre_lane_and_saturates_at_the_ends() {
        use Direction::{Backward, Forward};
        // Stepping one lane at a time, skipping 0 (the rule as it was written before).
        let stepped = |lane: i32, n: i32| {
            let mut id = lane;
            for _ in 0..n.unsigned_abs() {
                id += n.signum();
                if id == 0 {
                    id += n.signum();
                }
            }
            id
        };
        for lane in -6..=6 {
            for n in -8..=8 {
                assert_eq!(lane_shift(lane, n, Forward), stepped(lane, n), "{lane} {n}");
                assert_eq!(
                    lane_shift(lane, n, Backward),
                    stepped(lane, -n),
                    "{lane} {n}"
                );
            }
        }
        // By hand: −1 two to the left driving +s is 2 (−1 → 1 → 2); driving −s it is −3.
        assert_eq!(lane_shift(-1, 2, Forward), 2);
        assert_eq!(lane_shift(-1, 2, Backward), -3);
        // A shift of any size is one addition, saturating: no overflow, no 2^31 steps.
        assert_eq!(lane_shift(i32::MAX, 1, Forward), i32::MAX);
        assert_eq!(lane_shift(-1, i32::MIN, Backward), i32::MAX);
        // 1 by −2^31: the first step lands on −1 (over 0), the other 2^31 − 1 steps end at
        // −1 − (2^31 − 1) = −2^31. −3 by 2^31 − 1: three steps to 1, then 1 + 2^31 − 4.
        assert_eq!(lane_shift(1, i32::MIN, Forward), i32::MIN);
        assert_eq!(lane_shift(-3, i32::MAX, Forward), i32::MAX - 2);
    }

    /// A 30 m road of two lanes on the plan view `geometry` (its `<geometry>` elements).
    fn road(geometry: &str) -> RoadNetwork {
        let xodr = format!(
            r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="A" junction="-1" length="30"><link/><planView>{geometry}</planView><lanes>
<laneSection s="0"><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection>
</lanes></road></OpenDRIVE>"#
        );
        RoadNetwork::from_str(&xodr, std::path::Path::new("curvature.xodr")).expect("road")
    }

    /// The shortcut of a straight road against the finite difference, bit for bit, at every
    /// s of a grid over the road (the ends, 1 cm before the end where the difference turns
    /// backward, just outside) and for headings that are and are not the road's.
    #[test]
    fn the_straight_roads_shortcut_gives_the_difference_bit_for_bit() {
        let line = |s: f64, x: f64, y: f64, hdg: f64, len: f64| {
            format!(
                r#"<geometry s="{s}" x="{x}" y="{y}" hdg="{hdg}" length="{len}"><line/></geometry>"#
            )
        };
        // Three lines of one heading (0.5 rad; the second starts where the first ends,
        // 10·(cos 0.5, sin 0.5) = (8.7758, 4.7943)), one line of heading 0, a line with a
        // kink at s = 10 (0.5 then 0.6 rad), a line then an arc of 0.01 /m.
        let (c, sn) = (0.5_f64.cos(), 0.5_f64.sin());
        let straight = road(&format!(
            "{}{}{}",
            line(0.0, 0.0, 0.0, 0.5, 10.0),
            line(10.0, 10.0 * c, 10.0 * sn, 0.5, 10.0),
            line(20.0, 20.0 * c, 20.0 * sn, 0.5, 10.0)
        ));
        let zero = road(&line(0.0, 0.0, 0.0, 0.0, 30.0));
        let kinked = road(&format!(
            "{}{}",
            line(0.0, 0.0, 0.0, 0.5, 10.0),
            line(10.0, 10.0 * c, 10.0 * sn, 0.6, 20.0)
        ));
        let arc = road(&format!(
            r#"{}<geometry s="10" x="{}" y="{}" hdg="0.5" length="20"><arc curvature="0.01"/></geometry>"#,
            line(0.0, 0.0, 0.0, 0.5, 10.0),
            10.0 * c,
            10.0 * sn
        ));
        let mut grid: Vec<f64> = (0..=3000).map(|i| f64::from(i) * 0.01).collect();
        grid.extend([-1e-9, 9.995, 29.995, 29.999, 30.0 + 1e-9, 31.0, f64::NAN]);
        let mut shortcuts = 0;
        let roads = [
            ("straight", &straight),
            ("zero", &zero),
            ("kinked", &kinked),
            ("arc", &arc),
        ];
        for (name, net) in roads {
            let r = &net.roads()[0];
            for &s in &grid {
                let own = r.heading(s).unwrap_or(0.5);
                for h in [own, own + 1e-3, -own, 0.0, -0.0, 0.5, 0.6] {
                    let fast = curvature_with_heading(r, s, h);
                    let full = curvature_by_difference(r, s, h);
                    assert_eq!(
                        fast.to_bits(),
                        full.to_bits(),
                        "{name} at s = {s}, heading {h}: {fast} against {full}"
                    );
                    shortcuts += usize::from(
                        r.plan_view.straight_heading().map(f64::to_bits) == Some(h.to_bits()),
                    );
                }
            }
        }
        // The shortcut was taken: on "straight" for the own heading and 0.5 (the same
        // bits) at every s, on "zero" for the own heading and 0.0 (+0; −0 is not its bits)
        // except at 31 m and NaN, where the road has no heading and the test's 0.5 stands in.
        assert_eq!(shortcuts, 4 * grid.len() - 2);
        // The kink is seen 1 cm before it: (0.6 − 0.5) / 0.01 = 10 /m (rounded), and the arc's
        // curvature by the difference is its 0.01 /m to the rounding of the headings.
        let k = kinked.roads()[0].heading(9.995).unwrap();
        assert!((curvature_with_heading(&kinked.roads()[0], 9.995, k) - 10.0).abs() < 1e-9);
        let k = arc.roads()[0].heading(15.0).unwrap();
        assert!((curvature_with_heading(&arc.roads()[0], 15.0, k) - 0.01).abs() < 1e-9);
        // On the straight road the value is +0.
        let h = straight.roads()[0].heading(12.0).unwrap();
        assert_eq!(
            curvature_with_heading(&straight.roads()[0], 12.0, h).to_bits(),
            0
        );

        // The track's curvature (`track_curvature`, `keep_curvature`, which on a straight road
        // neither read nor write the memo) against `curvature` of the road at s, bit for bit:
        // at every s of the grid, with the memo empty, as a move left it at that s (given the
        // road's own heading there, as the move gives its pose's), and left at another s.
        let mut kept = 0;
        for (name, net) in roads {
            let r = &net.roads()[0];
            let is_straight = r.plan_view.straight_heading().is_some();
            assert_eq!(is_straight, name == "straight" || name == "zero");
            let mut track = LaneTrack {
                road_id: r.id.clone(),
                road: RoadHandle(0),
                lane_id: -1,
                s: 0.0,
                t: -1.75,
                offset: 0.0,
                direction: Direction::Forward,
                relative_heading: 0.0,
                blend: None,
                curvature: None,
                lanes: None,
                frame: None,
            };
            for &s in &grid {
                let full = curvature(r, s).to_bits();
                track.s = s;
                track.curvature = None;
                assert_eq!(track_curvature(r, &track).to_bits(), full, "{name} at {s}");
                if let Ok(h) = r.heading(s) {
                    assert_eq!(keep_curvature(r, &mut track, h).to_bits(), full);
                    // Kept for the next move where the road is not straight.
                    assert_eq!(track.curvature.is_some(), !is_straight, "{name} at {s}");
                    kept += usize::from(track.curvature.is_some());
                    assert_eq!(track_curvature(r, &track).to_bits(), full, "{name} at {s}");
                    // Left at another s: not read there.
                    track.s = s + 0.5;
                    let there = curvature(r, track.s).to_bits();
                    assert_eq!(track_curvature(r, &track).to_bits(), there, "{name} at {s}");
                }
                if is_straight {
                    assert_eq!(full, 0, "{name} at {s}: +0 everywhere on a straight road");
                }
            }
        }
        // The two curved roads kept a curvature at every s of the grid on the road (the 3,001
        // of the grid, 9.995, 29.995 and 29.999 m, and any end within the road's tolerance).
        let on_road = grid
            .iter()
            .filter(|&&s| arc.roads()[0].heading(s).is_ok())
            .count();
        assert!(on_road >= 3004, "{on_road}");
        assert_eq!(kept, 2 * on_road);
    }
}
