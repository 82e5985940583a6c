//! The lane index kept from step to step (store/lane_kept.rs) against a full build, and the
//! driver-input row written in place (store/driver_inputs.rs) against one made anew, in
//! random traffic on corpus roads (issue 31).

use std::sync::Arc;

use opendrive::{Direction, LaneHandle, Real, RoadHandle, RoadNetwork};

use super::driver_inputs::DriverInput;
use super::lane_index::LaneIndex;
use super::lane_kept::tests::generator;
use super::lane_slots::LaneSlots;
use crate::domain::{BoundingBox, Vector3};
use crate::position::lane_at;
use crate::store::World;
use crate::world::entity::{Entity, EntityId, EntityKind};

/// A car of `length` × 2 m whose box centre is 1.4 m ahead of its reference point.
fn car(i: u32, length: Real) -> Entity {
    let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), length, 2.0, 1.5).expect("box");
    Entity::new(EntityId(i), &format!("c{i}"), EntityKind::Vehicle, b)
}

/// Places car `id` at a random s of a random road, in the middle of a random lane there
/// (driving along the lane's direction under right-hand traffic), or off its centre.
pub(super) fn place_randomly(w: &mut World, id: EntityId, next: &mut impl FnMut() -> f64) {
    let net = Arc::clone(&w.network);
    if let Some((pose, found)) = random_place(&net, next) {
        w.place_resolved(id, pose, found);
    }
}

/// A random pose for [`place_randomly`] and the road position there.
pub(super) fn random_place(
    net: &RoadNetwork,
    next: &mut impl FnMut() -> f64,
) -> Option<(opendrive::Pose, Option<opendrive::RoadPosition>)> {
    for _ in 0..20 {
        let road = &net.roads()[(next() * net.roads().len() as f64) as usize];
        let s = next() * road.length;
        let lanes: Vec<i32> = road
            .lane_section_at(s)
            .lanes()
            .filter(|l| l.id != 0)
            .map(|l| l.id)
            .collect();
        if lanes.is_empty() {
            continue;
        }
        let lane = lanes[(next() * lanes.len() as f64) as usize];
        let Ok(span) = road.lane_span(lane, s) else {
            continue;
        };
        let off = if next() < 0.8 { 0.0 } else { next() - 0.5 };
        let t = 0.5 * (span.inner + span.outer) + off;
        let Ok(mut pose) = road.pose(s, t) else {
            continue;
        };
        if lane > 0 {
            pose.h += std::f64::consts::PI;
        }
        let found = net.locate(pose.x, pose.y, Some(pose.h));
        return Some((pose, found));
    }
    None
}

/// Moves car `i` `ds` along its direction of travel on its road, its t and heading relative
/// to the road kept (as a vehicle following a lane), or shifted by `dt` (a lane change);
/// off the road's ends it is placed anew.
fn drive(w: &mut World, i: usize, ds: Real, dt: Real, next: &mut impl FnMut() -> f64) {
    let net = Arc::clone(&w.network);
    if !drive_entity(&net, w.entity_mut(EntityId(i as u32)), ds, dt) {
        place_randomly(w, EntityId(i as u32), next);
    }
}

/// [`drive`] on the entity: false where it left its road (or has no lane track) and must be
/// placed anew.
fn drive_entity(net: &RoadNetwork, e: &mut Entity, ds: Real, dt: Real) -> bool {
    let (Some(rp), Some(track)) = (e.road_position.as_mut(), e.track.as_mut()) else {
        return false;
    };
    let road = net.road_at(rp.road);
    let s = match track.direction {
        Direction::Forward => rp.s + ds,
        Direction::Backward => rp.s - ds,
    };
    let t = rp.t + dt;
    let (Some((lane, offset)), Ok(pose)) = (lane_at(road, s, t), road.pose(s, t)) else {
        return false;
    };
    (rp.s, rp.t, rp.lane_id, rp.offset) = (s, t, lane, offset);
    (track.s, track.t) = (s, t);
    if dt != 0.0 {
        track.lane_id = lane;
    }
    e.pose.x = pose.x;
    e.pose.y = pose.y;
    e.pose.h = pose.h + rp.relative_heading;
    e.speed = ds / 0.05;
    true
}

/// 80 cars of 4 to 7 m placed at random on esmini's corpus road `name`.
pub(super) fn traffic(name: &str, next: &mut impl FnMut() -> f64) -> (Arc<RoadNetwork>, World) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/corpus/esmini/xodr")
        .join(name);
    let net = Arc::new(RoadNetwork::from_file(&path).unwrap_or_else(|e| panic!("{e}")));
    let cars = 80;
    let entities = (0..cars).map(|i| car(i, 4.0 + (i % 4) as Real)).collect();
    let mut w = World::new(Arc::clone(&net), entities);
    for i in 0..cars {
        place_randomly(&mut w, EntityId(i), next);
    }
    (net, w)
}

/// Changes car `i` through the store (each way marks it written, but the last): mostly
/// moved along its lane, sometimes across it, placed elsewhere, hidden from traffic or shown,
/// taken off the road or put back, its box or its heading relative to the road changed.
pub(super) fn write_through_store(w: &mut World, i: usize, next: &mut impl FnMut() -> f64) {
    let id = EntityId(i as u32);
    let ds = 0.05 * 30.0 * next();
    match next() {
        x if x < 0.85 => drive(w, i, ds, 0.0, next),
        x if x < 0.90 => drive(w, i, ds, 0.7 * (next() - 0.5), next),
        x if x < 0.92 => place_randomly(w, id, next),
        x if x < 0.94 => {
            let v = &mut w.entity_mut(id).visibility.traffic;
            *v = !*v;
        }
        x if x < 0.95 => {
            let p = &mut w.entity_mut(id).placed;
            *p = !*p;
        }
        x if x < 0.97 => {
            let length = 3.0 + 10.0 * next();
            w.entity_mut(id).bounding_box = car(0, length).bounding_box;
        }
        x if x < 0.98 => {
            if let Some(rp) = w.entity_mut(id).road_position.as_mut() {
                rp.relative_heading += 0.2 * (next() - 0.5);
            }
        }
        _ => {}
    }
}

/// The index whose entries the moves' walk made, each entity entered right after its move
/// (store/lane_refresh.rs), and made anew at the next step's start only for the entities
/// written through the store since, gives a full build's answers at every step's start: in
/// random traffic on the three corpus roads of the test above, every car moved in the walk
/// (along its lane, across it, or placed anew where it leaves its road), then about one in
/// ten written through the store in every way `write_through_store` has, a car spawned
/// midway (not entered by any walk before), and every tenth step a moves' walk that enters
/// nothing (no model holding a domain: the next build enters every entity); every fifth step
/// nothing is written between the walks (the refresh enters nothing: at the steps 3, 13, …,
/// 193 of each road after a walk that entered every car, 20 per road; at 8, 18, …, 198 the
/// walk before entered nothing, step % 10 == 7). The comparison
/// is that of `LaneIndex::assert_same_as`: the lanes' entries in order, bounds and flags,
/// footprints, driver inputs, bit for bit.
#[test]
fn entries_made_in_the_moves_walk_and_refreshed_where_written_give_the_full_builds_answers() {
    let mut next = generator(0x2545_f491_4f6c_dd1d);
    let (mut steps, mut stood, mut refreshed, mut quiet) = (0, 0usize, 0usize, 0);
    for name in ["fabriksgatan.xodr", "two_plus_one.xodr", "e6mini.xodr"] {
        let (net, mut w) = traffic(name, &mut next);
        let mut index = LaneIndex::default();
        let mut entered_by_walk = false;
        for step in 0..200 {
            // The step's start: the build the commands read, against a full one.
            let mut written = 0;
            if step == 100 {
                let id = w.spawn(car(0, 5.0));
                place_randomly(&mut w, id, &mut next);
                written += 1;
            }
            let n = w.entities().len();
            for i in 0..n {
                if step % 5 != 3 && next() < 0.1 {
                    write_through_store(&mut w, i, &mut next);
                    written += 1;
                }
            }
            if entered_by_walk {
                refreshed += written;
                stood += n - written;
                quiet += usize::from(written == 0);
            }
            index.refresh_from(&mut w);
            index.assert_same_as(&LaneIndex::build(&net, w.entities()));
            steps += 1;
            // The moves' walk.
            entered_by_walk = step % 10 != 7;
            let (net, entities, _) = w.moves();
            if entered_by_walk {
                index.begin_moves(n);
            }
            for e in entities.iter_mut() {
                let ds = 0.05 * 30.0 * next();
                let dt = if next() < 0.1 {
                    0.7 * (next() - 0.5)
                } else {
                    0.0
                };
                if !drive_entity(net, e, ds, dt) {
                    if let Some((pose, found)) = random_place(net, &mut next) {
                        crate::store::place_on_lane(net, e, pose, found);
                    }
                }
                if entered_by_walk {
                    index.enter_moved(net, e);
                }
            }
            index.end_moves(entered_by_walk.then_some(n));
        }
    }
    assert_eq!(steps, 600);
    assert_eq!(
        quiet,
        3 * 20,
        "steps with nothing written after a walk that entered all"
    );
    // About one car in ten written between the walks: the others' entries stood as the walk
    // made them (measured: 38,996 entity-steps stood, 4,234 entered anew).
    assert!(
        stood > 8 * refreshed,
        "{stood} stood, {refreshed} entered anew"
    );
}

/// The kept index gives a full build's answers, step after step, in random traffic on
/// corpus roads with junctions (fabriksgatan), lane sections and lanes that widen
/// (two_plus_one) and a highway (e6mini): cars following their lane at various speeds in
/// both directions (their entries stay), drifting across lane borders, jumping elsewhere,
/// hidden from traffic, taken off the road and put back, their boxes and headings changed,
/// a car spawned midway. Each step the kept index is compared with the step's full build
/// (the lanes' entries in order, bounds and flags, footprints, driver inputs, bit for bit);
/// most entries stay, and every kind of change happens.
#[test]
fn a_kept_index_gives_the_full_builds_answers_in_random_traffic() {
    let mut next = generator(0x5851_f42d_4c95_7f2d);
    let mut steps = 0;
    let mut shares = Vec::new();
    for name in ["fabriksgatan.xodr", "two_plus_one.xodr", "e6mini.xodr"] {
        let (mut stayed, mut entered) = (0usize, 0usize);
        let (net, mut w) = traffic(name, &mut next);
        let mut kept = LaneIndex::default();
        for step in 0..200 {
            if step == 100 {
                let id = w.spawn(car(0, 5.0));
                place_randomly(&mut w, id, &mut next);
            }
            for i in 0..w.entities().len() {
                write_through_store(&mut w, i, &mut next);
            }
            kept.refresh_from(&mut w);
            let full = LaneIndex::build(&net, w.entities());
            kept.assert_same_as(&full);
            stayed += kept.kept.iter().filter(|k| k.stays).count();
            entered += kept.kept.iter().filter(|k| k.entered).count();
            steps += 1;
        }
        shares.push(stayed as f64 / entered as f64);
    }
    assert_eq!(steps, 600);
    // About 85 % of the cars follow their lane in a step; their entries stay but where a
    // junction's road, a new section or borders made at each s (a lane widening,
    // store/lane_slots.rs) are under them: measured 37 % of the entered cars in the town,
    // 68 % on two_plus_one, 88 % on the highway.
    assert!(shares.iter().all(|&f| f > 0.3), "{shares:?}");
}

/// An entity's entries stay, and only the fields that moved are written
/// (`LaneIndex::stay`), exactly where the full way would keep them: at each boundary of its
/// conditions the kept index is a full build's (`LaneIndex::assert_same_as`) and the car's
/// entries stay or are made anew as worked out by hand. Road "A", 100 m along +x, lanes −1
/// and −2 of 3.5 m in the section from s 0; from s 50 lane −2 widens (0.01 m per m), so the
/// borders there are made at each s and no entry stays. A 5 m × 2 m car in lane −1
/// (t −1.75), moved by writing its road position (marked written, so every build enters it):
/// s 40 (first build: made), 40.5 and 41 (stay), 41.5 with t one ulp up (its box's t-range
/// bits change: made), 42 (stay again), 49.5 (stay), 49.999995 (past the kept borders' range,
/// which ends 1e-5 inside the section: made, from borders made for that s), 50 (the next
/// section: made), 55 (widening lane: made), 45 (back in the first section: made), 45.5
/// (stay), 45.5 hidden from traffic (not entered), 46 shown again (made), 46.5 (stay), 47
/// with the heading relative to the road one ulp up (its sine, 2.2e-16, moves no corner's
/// t: the t-range's bits are the same and the entries stay, with the s-range new), 47.5
/// (stay).
#[test]
fn an_entity_stays_exactly_where_the_full_way_keeps_it() {
    let lanes = |b2: &str| {
        format!(
            r#"<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane><lane id="-2" type="driving"><width sOffset="0" a="3.5" b="{b2}" c="0" d="0"/></lane></right>"#
        )
    };
    let xodr = format!(
        r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="A" junction="-1" length="100"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView><lanes><laneSection s="0"><center><lane id="0" type="none"/></center>{}</laneSection><laneSection s="50"><center><lane id="0" type="none"/></center>{}</laneSection></lanes></road>
</OpenDRIVE>"#,
        lanes("0"),
        lanes("0.01")
    );
    let net =
        Arc::new(RoadNetwork::from_str(&xodr, std::path::Path::new("stay.xodr")).expect("road"));
    let mut w = World::new(Arc::clone(&net), vec![car(0, 5.0)]);
    let id = EntityId(0);
    let pose = net.road_pose("A", 40.0, -1.75).expect("on road");
    let found = net.locate(pose.x, pose.y, Some(pose.h));
    w.place_resolved(id, pose, found);
    let t: Real = -1.75;
    // (s, t, relative heading, visible to traffic, stays)
    let steps = [
        (40.0, t, 0.0, true, false),
        (40.5, t, 0.0, true, true),
        (41.0, t, 0.0, true, true),
        (41.5, t.next_up(), 0.0, true, false),
        (42.0, t.next_up(), 0.0, true, true),
        (49.5, t.next_up(), 0.0, true, true),
        (49.999995, t.next_up(), 0.0, true, false),
        (50.0, t.next_up(), 0.0, true, false),
        (55.0, t.next_up(), 0.0, true, false),
        (45.0, t.next_up(), 0.0, true, false),
        (45.5, t.next_up(), 0.0, true, true),
        (45.5, t.next_up(), 0.0, false, false),
        (46.0, t.next_up(), 0.0, true, false),
        (46.5, t.next_up(), 0.0, true, true),
        (47.0, t.next_up(), 0.0_f64.next_up(), true, true),
        (47.5, t.next_up(), 0.0_f64.next_up(), true, true),
    ];
    let mut index = LaneIndex::default();
    let mut stayed = Vec::new();
    for &(s, t, rel, visible, _) in &steps {
        let e = w.entity_mut(id);
        let rp = e.road_position.as_mut().expect("on the road");
        (rp.s, rp.t, rp.relative_heading) = (s, t, rel);
        e.visibility.traffic = visible;
        index.refresh_from(&mut w);
        index.assert_same_as(&LaneIndex::build(&net, w.entities()));
        assert_eq!(index.footprint(id).is_some(), visible);
        stayed.push(index.kept[0].stays);
    }
    let expected: Vec<bool> = steps.iter().map(|s| s.4).collect();
    assert_eq!(stayed, expected);
}

/// Every number of a row, the floats as bits.
#[allow(clippy::type_complexity)]
fn bits(
    d: &DriverInput,
) -> (
    EntityId,
    bool,
    bool,
    u64,
    Option<(
        RoadHandle,
        i32,
        u64,
        Direction,
        Option<i32>,
        Option<LaneHandle>,
        u32,
    )>,
) {
    let track = d.track.map(|t| {
        let (road, lane, s, dir) = (t.road, t.lane_id, t.s.to_bits(), t.direction);
        (road, lane, s, dir, t.blend_from, t.own, t.own_slot)
    });
    (d.id, d.placed, d.lateral_action, d.speed.to_bits(), track)
}

/// The row as it was made before the write in place (the straightforward computation):
/// the whole row anew, the own lane's handle the look-up's where it is of the track's
/// road, lane and s (their bits), else asked of the network, its slot `slots`'.
fn made_anew(
    e: &Entity,
    net: &RoadNetwork,
    slots: &LaneSlots,
    looked_up: Option<(RoadHandle, i32, Real, LaneHandle)>,
) -> DriverInput {
    let own = |road, lane, s: Real| match looked_up {
        Some((r, l, at, h)) if (r, l) == (road, lane) && at.to_bits() == s.to_bits() => Some(h),
        _ => net.lane_handle_on(road, lane, s),
    };
    DriverInput::with_own(e, own, Some(slots))
}

/// The row `DriverInput::write` (store/driver_inputs.rs) leaves, written over any row there was, is the row made
/// anew bit for bit: on three corpus roads (two_plus_one: lanes appearing and ending;
/// multi_intersections and fabriksgatan: junctions), 80 cars each placed at random and
/// then without a track, with one off every lane (lane 99: no own lane), not placed, and
/// at s one double further; written over no row, a row without a track, the row of the
/// car somewhere else (another own lane and its slot, another road, lane and s), and the
/// car's own row; with no look-up, the look-up of the track's road, lane and s (its
/// handle the network's, and another handle, which the row must then take), of s one
/// double off (the network asked) and of the next lane. Every own lane that changed has
/// its slot anew; one that did not keeps it (the same number). So the in-place write,
/// its cold paths included, is the full computation.
#[test]
fn the_driver_input_row_written_in_place_is_the_row_made_anew_bit_for_bit() {
    let mut next = generator(31);
    let (mut written, mut own_changed, mut looked_up_used, mut no_own) = (0, 0, 0, 0);
    for name in [
        "two_plus_one.xodr",
        "multi_intersections.xodr",
        "fabriksgatan.xodr",
    ] {
        let (net, w) = traffic(name, &mut next);
        let slots = LaneSlots::new(&net);
        let numbered = Some(slots.clone());
        let elsewhere = w.entities();
        for (k, car) in w.entities().iter().enumerate() {
            let mut states = vec![car.clone()];
            if let Some(t) = car.track.as_ref() {
                let mut further = car.clone();
                if let Some(ft) = further.track.as_mut() {
                    ft.s = Real::from_bits(t.s.to_bits() + 1);
                }
                let mut off = car.clone();
                if let Some(ot) = off.track.as_mut() {
                    ot.lane_id = 99;
                }
                let mut unplaced = car.clone();
                unplaced.placed = false;
                let mut no_track = car.clone();
                no_track.track = None;
                states.extend([further, off, unplaced, no_track]);
            }
            for e in &states {
                // Rows there may be: none, one without a track, the car's row elsewhere
                // (another car's numbers under this car's id), its own row.
                let other = &elsewhere[(k + 1 + (next() * 79.0) as usize) % elsewhere.len()];
                let mut before = vec![
                    None,
                    Some(DriverInput {
                        track: None,
                        ..made_anew(car, &net, &slots, None)
                    }),
                    Some(DriverInput {
                        id: car.id,
                        ..made_anew(other, &net, &slots, None)
                    }),
                    Some(made_anew(car, &net, &slots, None)),
                ];
                before.retain(|r| r.is_none() || r.is_some_and(|r| r.id == e.id));
                let mut look_ups = vec![None];
                if let Some(t) = e.track.as_ref() {
                    let h = net.lane_handle_on(t.road, t.lane_id, t.s);
                    let another = LaneHandle {
                        road: t.road.0,
                        section: 0,
                        lane: t.lane_id,
                    };
                    let ulp = Real::from_bits(t.s.to_bits() + 1);
                    for handle in h.into_iter().chain([another]) {
                        look_ups.extend([
                            Some((t.road, t.lane_id, t.s, handle)),
                            Some((t.road, t.lane_id, ulp, handle)),
                            Some((t.road, t.lane_id + 1, t.s, handle)),
                        ]);
                    }
                }
                for row in &before {
                    for &looked_up in &look_ups {
                        let mut r = *row;
                        DriverInput::write(&mut r, e, &net, &numbered, looked_up);
                        let anew = made_anew(e, &net, &slots, looked_up);
                        let r = r.expect("a row written");
                        assert_eq!(bits(&r), bits(&anew), "{name} {} {looked_up:?}", e.name);
                        written += 1;
                        let (was, now) = (row.and_then(|r| r.track), r.track);
                        if was.map(|t| t.own) != now.map(|t| t.own) {
                            own_changed += 1;
                        }
                        if now.is_some_and(|t| t.own.is_none()) {
                            no_own += 1;
                        }
                        if let (Some((.., h)), Some(t)) = (looked_up, now) {
                            looked_up_used += usize::from(t.own == Some(h));
                        }
                    }
                }
            }
        }
    }
    assert!(
        written > 20_000 && own_changed > 15_000 && looked_up_used > 15_000 && no_own > 2_000,
        "{written} written, {own_changed} own lanes changed, {looked_up_used} look-ups \
         taken, {no_own} without an own lane"
    );
}
