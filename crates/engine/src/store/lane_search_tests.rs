//! The gap search of the lane index split in two (issue 31: its first lane inline in the
//! caller, the walk on from there out of line, [`LaneIndex::nearest`]) against the one loop
//! it was, bit for bit, in random traffic on corpus roads.

use std::sync::atomic::AtomicU32;

use opendrive::{Direction, LaneHandle, Real, RoadHandle, RoadNetwork};

use super::lane_index::{LaneIndex, Neighbour, MAX_HOPS};
use super::lane_kept::tests::generator;
use super::lane_kept_tests::traffic;
use crate::world::entity::EntityId;

/// The search as one loop, every lane, the first included, searched in the same walk: the
/// code of `LaneIndex::nearest` before the split, kept here as the reference.
#[allow(clippy::too_many_arguments)]
fn nearest_walk(
    index: &LaneIndex,
    net: &RoadNetwork,
    start: LaneHandle,
    from: Real,
    direction: Direction,
    exclude: EntityId,
    horizon: Real,
    choose: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
    hint: Option<&AtomicU32>,
) -> Option<Neighbour> {
    let (mut h, mut at, mut direction) = (start, from, direction);
    let mut hint = hint;
    let mut walked = 0.0;
    for _ in 0..MAX_HOPS {
        if let Some(found) = index.in_lane(h, at, direction, exclude, hint.take()) {
            let gap = walked + found.gap;
            return (gap <= horizon).then_some(Neighbour { gap, ..found });
        }
        let road = net.handle_road(h);
        let k = h.section as usize;
        let end = match direction {
            Direction::Forward => road.lane_section_end(k),
            Direction::Backward => road.lane_sections[k].s,
        };
        walked += (end - at).abs();
        if walked > horizon {
            return None;
        }
        let with_traffic = direction == net.driving_direction(h);
        let next = if with_traffic {
            net.successors(h)
        } else {
            net.predecessors(h)
        };
        let pick = match next.iter().find(|n| n.road == h.road) {
            Some(&n) => n,
            None => choose(&road.id, next).or_else(|| next.first().copied())?,
        };
        direction = if with_traffic {
            net.driving_direction(pick)
        } else {
            net.driving_direction(pick).reverse()
        };
        let next_road = net.handle_road(pick);
        at = match direction {
            Direction::Forward => next_road.lane_sections[pick.section as usize].s,
            Direction::Backward => next_road.lane_section_end(pick.section as usize),
        };
        h = pick;
    }
    None
}

/// The answer as bits: entity, gap, direction.
fn bits(n: Option<Neighbour>) -> Option<(EntityId, u64, Direction)> {
    n.map(|n| (n.id, n.gap.to_bits(), n.direction))
}

/// From every car's front and rear bumper, ahead and behind, in its own lane and each lane
/// of its section beside it, with horizons from 20 m to 1 km, the successor at a road's end
/// the first or the last on offer, with and without a hint (each search kind's hint kept
/// between the searches, as the driver models keep theirs): the split search and the one
/// loop give the same entity, the same gap to the bit and the same direction, on corpus
/// roads with junctions (fabriksgatan), lane sections (two_plus_one) and a highway (e6mini),
/// 80 cars each, 20 placements. Both outcomes of the first lane and of the walk on occur:
/// found in the first lane, found past it, none within the horizon.
#[test]
fn the_split_search_gives_the_walks_answers_bit_for_bit() {
    let mut next = generator(0x9e37_79b9_7f4a_7c15);
    let (mut first, mut beyond, mut none, mut searches) = (0usize, 0usize, 0usize, 0usize);
    for name in ["fabriksgatan.xodr", "two_plus_one.xodr", "e6mini.xodr"] {
        for _ in 0..20 {
            let (net, w) = traffic(name, &mut next);
            let index = LaneIndex::build(&net, w.entities());
            let hints: Vec<AtomicU32> = (0..4).map(|_| AtomicU32::new(0)).collect();
            for e in w.entities() {
                let Some(f) = index.footprint(e.id) else {
                    continue;
                };
                let road = net.handle_road(f.handle);
                let section = &road.lane_sections[f.handle.section as usize];
                for lane in section.lanes().map(|l| l.id).filter(|&id| id != 0) {
                    let Some(h) = net.lane_handle_on(RoadHandle(f.handle.road), lane, f.s) else {
                        continue;
                    };
                    for (k, dir) in [Direction::Forward, Direction::Backward]
                        .into_iter()
                        .enumerate()
                    {
                        for (j, from) in [f.front(dir), f.rear(dir)].into_iter().enumerate() {
                            let horizon = 20.0 + 980.0 * next();
                            let hint = (next() < 0.7).then(|| &hints[2 * k + j]);
                            let last = next() < 0.5;
                            let mut choose = |_: &str, c: &[LaneHandle]| {
                                if last {
                                    c.last().copied()
                                } else {
                                    None
                                }
                            };
                            let split =
                                index.nearest(&net, h, from, dir, e.id, horizon, &mut choose, hint);
                            let walk = nearest_walk(
                                &index,
                                &net,
                                h,
                                from,
                                dir,
                                e.id,
                                horizon,
                                &mut choose,
                                hint,
                            );
                            assert_eq!(bits(split), bits(walk), "{name}: car {:?}", e.id);
                            searches += 1;
                            match split {
                                None => none += 1,
                                Some(_) if index.in_lane(h, from, dir, e.id, None).is_some() => {
                                    first += 1
                                }
                                Some(_) => beyond += 1,
                            }
                        }
                    }
                }
            }
        }
    }
    // Measured: 127,872 searches, 92,872 found in the first lane, 5,219 past it, 29,781 none.
    assert!(
        first > 1000 && beyond > 1000 && none > 1000,
        "{first} in the first lane, {beyond} past it, {none} none of {searches}"
    );
}
