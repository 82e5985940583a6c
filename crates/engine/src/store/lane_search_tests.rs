//! The gap search of the lane index split in two (issue 31: its first lane inline in the
//! caller, the walk on from there out of line, [`LaneIndex::nearest`]) against the one loop
//! it was, bit for bit, in random traffic on corpus roads.

use std::sync::atomic::AtomicU32;

use opendrive::{Direction, LaneHandle, Real, RoadHandle, RoadNetwork};

use super::lane_index::{Footprint, LaneIndex, Neighbour, MAX_HOPS};
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

/// The handles of the lanes of the section under footprint `f` (its own lane and every lane
/// beside it), at its s.
fn section_lanes<'a>(
    net: &'a RoadNetwork,
    f: &'a Footprint,
) -> impl Iterator<Item = LaneHandle> + 'a {
    let road = net.handle_road(f.handle);
    let section = &road.lane_sections[f.handle.section as usize];
    section
        .lanes()
        .map(|l| l.id)
        .filter(|&id| id != 0)
        .filter_map(|lane| net.lane_handle_on(RoadHandle(f.handle.road), lane, f.s))
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
                let Some(f) = index.footprint(e.id).cloned() else {
                    continue;
                };
                for h in section_lanes(&net, &f) {
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

/// The answers taken at the hint (store/lane_index.rs "The last answer re-validated": the
/// leader where the entries at the hint prove it, an occupant where the entry before the hint
/// does) against the search without a hint (`searched`, `overlapping`: `partition_point`
/// alone, the code the answers at the hint skip), bit for bit, in random traffic on
/// corpus roads with junctions (fabriksgatan), lane sections (two_plus_one) and a highway
/// (e6mini): 80 cars of 4–7 m, 100 steps each, the cars driven along their lanes, across
/// them, placed anew, hidden, through the store between the steps, the index kept and
/// refreshed as the engine does (`LaneIndex::refresh_from`). Each car asks, each step, in its
/// own lane and every lane of its section beside it, ahead and behind from both bumpers
/// (forward and backward) and whether the lane is occupied along its box, each question with
/// its own hint kept from step to step as the driver models keep theirs, and a stale hint
/// (a random index) in one question of four. Both outcomes of each proof occur thousands of
/// times: taken, and left to the search.
#[test]
fn the_answers_at_the_hint_are_the_searches_bit_for_bit() {
    use super::lane_index::{ahead_at_hint, behind_at_hint, occupied_at_hint, searched};
    use super::lane_kept_tests::write_through_store;
    use std::collections::HashMap;
    use std::sync::atomic::Ordering;

    let mut next = generator(0x2545_f491_4f6c_dd1d);
    let (mut leader_taken, mut leader_searched) = (0usize, 0usize);
    let (mut occupied_taken, mut occupied_searched_n) = (0usize, 0usize);
    let (mut found, mut none, mut occupied_true, mut occupied_false) = (0, 0, 0, 0);
    for name in ["fabriksgatan.xodr", "two_plus_one.xodr", "e6mini.xodr"] {
        let (net, mut w) = traffic(name, &mut next);
        let mut index = LaneIndex::default();
        let mut hints: HashMap<(EntityId, LaneHandle, usize), AtomicU32> = HashMap::new();
        for _ in 0..100 {
            for i in 0..w.entities().len() {
                write_through_store(&mut w, i, &mut next);
            }
            index.refresh_from(&mut w);
            for e in w.entities() {
                let Some(f) = index.footprint(e.id).cloned() else {
                    continue;
                };
                for h in section_lanes(&net, &f) {
                    // The question's hint as kept from the last step, made stale (a random
                    // index) one time in four; its value now.
                    let hint = |hints: &mut HashMap<_, AtomicU32>,
                                kind: usize,
                                next: &mut dyn FnMut() -> f64| {
                        let hint = hints.entry((e.id, h, kind)).or_default();
                        if next() < 0.25 {
                            hint.store((next() * 90.0) as u32, Ordering::Relaxed);
                        }
                        hint.load(Ordering::Relaxed)
                    };
                    for (k, dir) in [Direction::Forward, Direction::Backward]
                        .into_iter()
                        .enumerate()
                    {
                        for (j, from) in [f.front(dir), f.rear(dir)].into_iter().enumerate() {
                            let at = hint(&mut hints, 2 * k + j, &mut next);
                            let kept = &hints[&(e.id, h, 2 * k + j)];
                            let lane_entries = index.lane(h);
                            let proven = lane_entries.is_some_and(|l| {
                                let at = AtomicU32::new(at);
                                match dir {
                                    Direction::Forward => ahead_at_hint(l, from, e.id, &at),
                                    Direction::Backward => behind_at_hint(l, from, e.id, &at),
                                }
                                .is_some()
                            });
                            if proven {
                                leader_taken += 1;
                            } else {
                                leader_searched += 1;
                            }
                            let answer = index.in_lane(h, from, dir, e.id, Some(kept));
                            let reference = index
                                .lane(h)
                                .and_then(|l| searched(l, from, dir, e.id, None));
                            assert_eq!(
                                bits(answer),
                                bits(reference),
                                "{name}: car {:?} lane {h:?} from {from} {dir:?} hint {at}",
                                e.id
                            );
                            if answer.is_some() {
                                found += 1;
                            } else {
                                none += 1;
                            }
                        }
                    }
                    let at = hint(&mut hints, 4, &mut next);
                    let kept = &hints[&(e.id, h, 4)];
                    if index
                        .lane(h)
                        .is_some_and(|l| occupied_at_hint(l, f.s_range, e.id, &AtomicU32::new(at)))
                    {
                        occupied_taken += 1;
                    } else {
                        occupied_searched_n += 1;
                    }
                    let answer = index.occupied(h, f.s_range, e.id, Some(kept));
                    let reference = index.overlapping(h, f.s_range, e.id, None).next().is_some();
                    assert_eq!(answer, reference, "{name}: car {:?} lane {h:?}", e.id);
                    if answer {
                        occupied_true += 1;
                    } else {
                        occupied_false += 1;
                    }
                }
            }
        }
    }
    let counts = format!(
        "leader: {leader_taken} at the hint, {leader_searched} searched ({found} found, \
         {none} none); occupied: {occupied_taken} at the hint, {occupied_searched_n} searched \
         ({occupied_true} yes, {occupied_false} no)"
    );
    assert!(
        leader_taken > 2000
            && leader_searched > 2000
            && occupied_taken > 2000
            && occupied_searched_n > 2000
            && found > 2000
            && none > 2000
            && occupied_true > 2000
            && occupied_false > 2000,
        "{counts}"
    );
    println!("{counts}");
}
