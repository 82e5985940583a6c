//! The roads of a route through points (ASAM OpenSCENARIO DSL 2.1 §8.12.2.1 `map.create_route`;
//! OpenDRIVE 1.8 §10.3 road linkage, §11.5 lane linkage, §12 junctions): leg by leg, the
//! network's shortest lane path in the driving direction (`opendrive::RoadNetwork::route`,
//! the length search the engine's route planner runs for routeStrategy `shortest`), which
//! at a junction takes the connection leading to the next point.
//!
//! The plan keeps the lane ids of its roads, so each leg's path must stay in its points'
//! lanes and run in +s on every road, entering each next road at its start (as `chain`
//! requires of the roads after the start), or, in lanes of the left side (driven in −s),
//! against s on every road, the plan's roads being the path the other way round. A leg between
//! points in two lanes is the path in each of them over the same roads (the lanes side by side
//! from one point to the next: the actor changes lanes between them, `plan::route_moves`). A
//! path that changes lanes on its own, or drives a road the other way, is an error naming the
//! leg.

use opendrive::{Direction, LanePosition, RoadNetwork};

/// The roads (indices into `net.roads()`) of a route through `points` (road id, lane id, s),
/// from the first to each next point in turn, each once, in the order the plan drives them in
/// +s; or what is wrong, as the rest of a sentence "expected …, found …". Lanes of the right
/// side are driven in +s, so that is their driving order; lanes of the left side (a positive
/// id, right-hand traffic) are driven in −s, their path runs against s over every road, and
/// the plan's roads are that path the other way round (an actor along it drives them against
/// s, `PlanRoad::against`). Every point is on the same side (`resolve::route`).
pub(crate) fn route_roads(
    net: &RoadNetwork,
    points: &[(String, i32, f64)],
) -> Result<Vec<usize>, String> {
    let index = |id: &str| net.roads().iter().position(|r| r.id == id);
    let first = points
        .first()
        .and_then(|(id, _, _)| index(id))
        .ok_or_else(|| "expected a route on a road of the network, found none".to_string())?;
    let backward = points[0].1 > 0;
    let mut out = vec![first];
    for leg in points.windows(2) {
        let (a, b) = (&leg[0], &leg[1]);
        // In a's lane to b's place, and (points in two lanes) in b's lane from a's place: the
        // two lanes side by side over the same roads.
        let mut roads = leg_roads(net, a.1, (&a.0, a.2), (&b.0, b.2))?;
        if b.1 != a.1 {
            let other = leg_roads(net, b.1, (&a.0, a.2), (&b.0, b.2))?;
            if other != roads {
                let ids = |r: &[usize]| {
                    r.iter()
                        .map(|&i| net.roads()[i].id.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                };
                return Err(format!(
                    "expected lanes {} and {} side by side from road {} at s = {} m to road {} at s = {} m (the route changes lanes between the two points), found lane {} over roads {} and lane {} over roads {}",
                    a.1, b.1, a.0, a.2, b.0, b.2, a.1, ids(&roads), b.1, ids(&other)
                ));
            }
        }
        for i in roads.drain(..) {
            if out.last() != Some(&i) {
                if out.contains(&i) {
                    return Err(format!(
                        "expected a route over each road once, found road {} again",
                        net.roads()[i].id
                    ));
                }
                out.push(i);
            }
        }
    }
    if backward {
        out.reverse();
    }
    Ok(out)
}

/// The roads of the network's path in lane `lane` from `(road id, s)` to the other, in its
/// driving direction, in the order driven.
fn leg_roads(
    net: &RoadNetwork,
    lane: i32,
    from: (&str, f64),
    to: (&str, f64),
) -> Result<Vec<usize>, String> {
    let (along, how) = if lane > 0 {
        (Direction::Backward, "in -s")
    } else {
        (Direction::Forward, "in +s")
    };
    let at = |(id, s): (&str, f64)| LanePosition {
        road_id: id.to_string(),
        lane_id: lane,
        s,
        offset: 0.0,
    };
    let (from, to) = (at(from), at(to));
    let describe = |p: &LanePosition| format!("road {} at s = {} m", p.road_id, p.s);
    let path = net.route(&from, &to).ok_or_else(|| {
        format!(
            "expected a path in lane {lane} from {} to {} in the driving direction, found none",
            describe(&from),
            describe(&to)
        )
    })?;
    let mut out: Vec<usize> = Vec::new();
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
        let Some(i) = net.roads().iter().position(|r| r.id == seg.road_id) else {
            continue;
        };
        if out.last() != Some(&i) {
            out.push(i);
        }
    }
    Ok(out)
}
