//! The roads of a route through points (ASAM OpenSCENARIO DSL 2.1 §8.12.2.1 `map.create_route`;
//! OpenDRIVE 1.8 §10.4 road linkage, §11.6 lane linkage, §12 junctions): leg by leg, the
//! network's shortest lane path in the driving direction (`opendrive::RoadNetwork::route`,
//! the length search the engine's route planner runs for routeStrategy `shortest`), which
//! at a junction takes the connection leading to the next point.
//!
//! The plan keeps one lane id over its roads, so the path must stay in the points' lane and
//! run in +s on every road, entering each next road at its start (as `chain` requires of the
//! roads after the start), or, in a lane of the left side (driven in −s), against s on every
//! road, the plan's roads being the path the other way round: a path that changes lanes, or
//! drives a road the other way, is an error naming the leg.

use opendrive::{Direction, LanePosition, RoadNetwork};

/// The roads (indices into `net.roads()`) of lane `lane` from `(road id, s)` to each next point
/// in turn, each once, in the order the plan drives them in +s; or what is wrong, as the rest
/// of a sentence "expected …, found …". A lane of the right side is driven in +s, so that is
/// its driving order; one of the left side (a positive id, right-hand traffic) is driven in
/// −s, its path runs against s over every road, and the plan's roads are that path the other
/// way round (an actor along it drives them against s, `PlanRoad::against`).
pub(crate) fn route_roads(
    net: &RoadNetwork,
    lane: i32,
    points: &[(String, f64)],
) -> Result<Vec<usize>, String> {
    let (along, how) = if lane > 0 {
        (Direction::Backward, "in -s")
    } else {
        (Direction::Forward, "in +s")
    };
    let index = |id: &str| net.roads().iter().position(|r| r.id == id);
    let first = points
        .first()
        .and_then(|(id, _)| index(id))
        .ok_or_else(|| "expected a route on a road of the network, found none".to_string())?;
    let mut out = vec![first];
    for leg in points.windows(2) {
        let at = |(id, s): &(String, f64)| LanePosition {
            road_id: id.clone(),
            lane_id: lane,
            s: *s,
            offset: 0.0,
        };
        let (from, to) = (at(&leg[0]), at(&leg[1]));
        let describe = |p: &LanePosition| format!("road {} at s = {} m", p.road_id, p.s);
        let path = net.route(&from, &to).ok_or_else(|| {
            format!(
                "expected a path in lane {lane} from {} to {} in the driving direction, found none",
                describe(&from),
                describe(&to)
            )
        })?;
        for seg in &path.segments {
            if seg.lane_id != lane || seg.direction != along {
                return Err(format!(
                    "expected the path from {} to {} in lane {lane} {how}, found it in lane {} of road {} {}",
                    describe(&from),
                    describe(&to),
                    seg.lane_id,
                    seg.road_id,
                    if seg.direction == Direction::Forward { "in +s" } else { "in -s" }
                ));
            }
            // The search returns stretches of roads of the network.
            let Some(i) = index(&seg.road_id) else {
                continue;
            };
            if out.last() != Some(&i) {
                if out.contains(&i) {
                    return Err(format!(
                        "expected a route over each road once, found road {} again",
                        seg.road_id
                    ));
                }
                out.push(i);
            }
        }
    }
    if lane > 0 {
        out.reverse();
    }
    Ok(out)
}
