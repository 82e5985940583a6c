//! Lane geometry the runtime needs on top of the road model (OpenDRIVE 1.8 §8.3 reference-line
//! coordinates, §11 lanes, §10–11.4 lane linkage): which lane holds a lateral position, the
//! reference line's curvature, lateral-lane arithmetic across the centre lane, and carrying a
//! [`LaneTrack`] along its lane through lane sections, road links and junctions.
//!
//! Written here because the road crate answers single queries (pose, span, successors) and the
//! runtime needs them combined per step; it adds no geometry of its own.

use opendrive::{angle_difference, Direction, LaneHandle, Real, Road, RoadNetwork, RoadPosition};

use super::entity::LaneTrack;

/// Step (m) of the finite difference that gives the reference line's curvature.
const CURVATURE_STEP: Real = 0.01;
/// Most lane-graph hops taken in one step (short junction roads); bounds the loop.
const MAX_HOPS: usize = 16;

/// The drivable lane of `road` whose borders enclose `t` at `s`, with the offset from its
/// centre; beyond the drivable lanes, the nearest one (so an entity on the shoulder keeps its
/// driving lane, with a large offset). Roads without drivable lanes use every lane. Lane 0
/// (the centre lane, zero width) is never chosen.
pub fn lane_at(road: &Road, s: Real, t: Real) -> Option<(i32, Real)> {
    let section = road.lane_section_at(s);
    let nearest = |drivable_only: bool| {
        let mut best: Option<(Real, i32, Real)> = None;
        for lane in section
            .lanes()
            .filter(|l| l.id != 0 && (!drivable_only || l.lane_type.is_drivable()))
        {
            let Ok(span) = road.lane_span(lane.id, s) else {
                continue;
            };
            let (lo, hi) = if span.inner <= span.outer {
                (span.inner, span.outer)
            } else {
                (span.outer, span.inner)
            };
            let gap = (lo - t).max(t - hi).max(0.0);
            if best.map_or(true, |(g, _, _)| gap < g) {
                best = Some((gap, lane.id, t - span.center()));
            }
        }
        best.map(|(_, id, offset)| (id, offset))
    };
    nearest(true).or_else(|| nearest(false))
}

/// Curvature (1/m) of the reference line of `road` at `s`, by a forward (or, at the road's
/// end, backward) difference of the heading.
pub fn curvature(road: &Road, s: Real) -> Real {
    let (a, b) = if s + CURVATURE_STEP <= road.length {
        (s, s + CURVATURE_STEP)
    } else {
        ((s - CURVATURE_STEP).max(0.0), s)
    };
    match (road.pose(a, 0.0), road.pose(b, 0.0)) {
        (Ok(pa), Ok(pb)) if b > a => angle_difference(pb.h, pa.h) / (b - a),
        _ => 0.0,
    }
}

/// The lane `n` lanes to the left of `lane` (right for negative `n`) as seen when driving in
/// `direction`, skipping the centre lane 0.
pub fn lane_shift(lane: i32, n: i32, direction: Direction) -> i32 {
    // Travelling towards +s, "left" is towards larger ids; towards −s it is towards smaller ids.
    let n = if direction == Direction::Forward {
        n
    } else {
        -n
    };
    let mut id = lane;
    for _ in 0..n.unsigned_abs() {
        id += n.signum();
        if id == 0 {
            id += n.signum();
        }
    }
    id
}

/// Moves `track` by `distance` m of travel along s in its direction, following lane links
/// (the first successor, in the road model's order, or the one `prefer` picks from the
/// successors where the road named by its first argument ends). Returns the distance that
/// could not be driven because the lane ends with no successor.
pub fn advance(
    net: &RoadNetwork,
    track: &mut LaneTrack,
    mut distance: Real,
    prefer: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
) -> Real {
    for _ in 0..MAX_HOPS {
        let Some(road) = net.road(&track.road_id) else {
            return distance;
        };
        let sign = if track.direction == Direction::Forward {
            1.0
        } else {
            -1.0
        };
        let target = track.s + sign * distance;
        if (0.0..=road.length).contains(&target) {
            cross_sections(net, track, target);
            track.s = target;
            return 0.0;
        }
        let end = if sign > 0.0 { road.length } else { 0.0 };
        distance -= (end - track.s).abs();
        cross_sections(net, track, end);
        track.s = end;
        let Some(handle) = net.lane_handle(&track.road_id, track.lane_id, end) else {
            return distance;
        };
        let successors = net.successors(handle);
        let Some(next) =
            prefer(&track.road_id, &successors).or_else(|| successors.first().copied())
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

/// The id that lane `lane` of road `road_id` at s `from` has at s `to`, travelling in
/// `direction`: lane links carry it across lane-section boundaries (OpenDRIVE 1.8 §11.4 "Lane
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
            .into_iter()
            .find(|n| n.road == h.road && n.section == next_section)
            .unwrap_or(LaneHandle {
                section: next_section,
                ..h
            });
    }
    h.lane
}

/// Carries the lane `track` follows, and the lane a lateral transition comes from, from its s
/// to s `to` across lane sections ([`carry_lane`]).
fn cross_sections(net: &RoadNetwork, track: &mut LaneTrack, to: Real) {
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

/// A road position built from a lane track (no look-up: the track knows its road);
/// `relative_heading` is the entity's heading minus the road's.
pub fn road_position(
    net: &RoadNetwork,
    track: &LaneTrack,
    relative_heading: Real,
) -> Option<RoadPosition> {
    let road = net.road(&track.road_id)?;
    let (lane_id, offset) = lane_at(road, track.s, track.t)?;
    Some(RoadPosition {
        road_id: track.road_id.clone(),
        lane_id,
        s: track.s,
        t: track.t,
        offset,
        junction_id: road.junction.clone(),
        relative_heading,
        distance: 0.0,
    })
}
