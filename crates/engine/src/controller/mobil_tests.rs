//! The `mobil` controller's step against the straightforward rule, bit for bit: the rule as
//! the module doc states it, every acceleration computed in full for both lanes beside
//! ([`judge_each`], [`decide_each`], [`step_each`]: the controller's code before issue 31),
//! on many crowded highways and parameter sets.

use std::sync::atomic::AtomicU32;
use std::sync::atomic::Ordering::Relaxed;

use opendrive::{Direction, Real, RoadNetwork};

use super::*;
use crate::controller::car_following::with_red_light;
use crate::controller::command::FreeAcceleration;
use crate::controller::lane_beside::{KeptRoad, RoadBeside};
use crate::controller::test_world::{crowded, generator, network};
use crate::controller::view::{NeighbourLane, Side};
use crate::store::driver_inputs::{DriverInput, TrackInput, NO_SLOT};
use crate::store::lane_index::LaneIndex;
use crate::store::World;
use crate::world::entity::Entity;

/// The verdict on `lane` with every acceleration computed (the rule of the module doc).
fn judge_each(
    c: &MobilController,
    view: &ControllerView<'_>,
    lane: &NeighbourLane,
) -> Option<Real> {
    if lane.occupied || !lane.crossing_permitted {
        return None;
    }
    let verdict = c.mobil.judge(&candidate_each(c, view, lane));
    verdict.change().then_some(verdict.margin)
}

/// The accelerations of a change into `lane`, each computed in full.
fn candidate_each(
    c: &MobilController,
    view: &ControllerView<'_>,
    lane: &NeighbourLane,
) -> LaneChangeCandidate {
    let p = &c.idm.params;
    let v = view.entity().speed.max(0.0);
    let len = view.length();
    let own_leader = view.leader();
    let a_c = p.acceleration(v, with_red_light(view, own_leader.map(to)));
    let own_after = p.acceleration(v, with_red_light(view, lane.leader.map(to)));
    let old_follower = view.follower().map(|o| {
        let vo = o.speed.max(0.0);
        let behind_me = Leader {
            gap: o.gap,
            speed: v,
        };
        let behind_leader = own_leader.map(|l| Leader {
            gap: o.gap + len + l.gap,
            speed: l.speed,
        });
        FollowerChange {
            before: p.acceleration(vo, Some(behind_me)),
            after: p.acceleration(vo, behind_leader),
        }
    });
    let new_follower = lane.follower.map(|n| {
        let vn = n.speed.max(0.0);
        let before = lane.leader.map(|l| Leader {
            gap: n.gap + len + l.gap,
            speed: l.speed,
        });
        FollowerChange {
            before: p.acceleration(vn, before),
            after: p.acceleration(
                vn,
                Some(Leader {
                    gap: n.gap,
                    speed: v,
                }),
            ),
        }
    });
    LaneChangeCandidate {
        own: FollowerChange {
            before: a_c,
            after: own_after,
        },
        old_follower,
        new_follower,
        toward_keep_side: lane.toward_keep_side,
    }
}

/// The lane to change to, both lanes beside judged in full.
fn decide_each(c: &mut MobilController, view: &ControllerView<'_>) -> Option<i32> {
    let e = view.entity();
    let track = e.track.as_ref()?;
    if track.blend.is_some() || e.lateral_action.is_some() {
        return None;
    }
    if let Some(lane) = c.pending.take() {
        return (lane != track.lane_id).then_some(lane);
    }
    if e.speed < MIN_CHANGE_SPEED || view.time() - c.last_change < MIN_CHANGE_INTERVAL {
        return None;
    }
    let mut best: Option<(Real, i32)> = None;
    for side in [Side::Left, Side::Right] {
        let Some(lane) = view.neighbour_lane(side) else {
            continue;
        };
        // Not into a lane that ends within the change (module doc "A lane that ends").
        let ends = view
            .beside(side)
            .is_some_and(|b| view.lane_ends_within_change(&b, e.speed.max(0.0), view.length()));
        if let Some(margin) = judge_each(c, view, &lane).filter(|_| !ends) {
            if best.is_none_or(|(m, _)| margin > m) {
                best = Some((margin, lane.lane));
            }
        }
    }
    best.map(|(_, lane)| lane)
}

/// The command, the IDM's acceleration asked of the IDM controller.
fn step_each(c: &mut MobilController, view: &ControllerView<'_>) -> Command {
    let ordered = c.mandatory.is_none() && c.pending.is_some();
    let lateral = decide_each(c, view).map(|lane| {
        c.judged = (!ordered).then_some(c.last_change);
        c.last_change = view.time();
        Lateral::ChangeLane(lane)
    });
    Command::Motion {
        longitudinal: Some(Longitudinal::Acceleration(c.idm.acceleration(view))),
        lateral,
    }
}

/// Calls `f` with the seed, world, lane index, car and view of every car of 40 crowded
/// highways of 60 cars (seeds 1 to 40).
fn for_each_view(mut f: impl FnMut(u64, &World, &LaneIndex, &Entity, &ControllerView<'_>)) {
    for seed in 1..=40u64 {
        let w = crowded(60, seed);
        let index = LaneIndex::build(&w.network, w.entities());
        for e in w.entities() {
            f(seed, &w, &index, e, &view_of(10.0, &w, &index, e));
        }
    }
}

/// The view of `e` in `w` at `time`, with the lane index `index` of `w`.
fn view_of<'a>(
    time: Real,
    w: &'a World,
    index: &'a LaneIndex,
    e: &'a Entity,
) -> ControllerView<'a> {
    let input = index.input(e.id.index()).expect("a row per entity");
    view_with(time, w, index, e, input)
}

/// [`view_of`] with the driver inputs `input`.
fn view_with<'a>(
    time: Real,
    w: &'a World,
    index: &'a LaneIndex,
    e: &'a Entity,
    input: &'a DriverInput,
) -> ControllerView<'a> {
    ControllerView::new(
        time,
        e,
        input,
        w.entities(),
        &w.network,
        index,
        None,
        &w.signals,
    )
}

/// The MOBIL parameter sets of the tests: the defaults; egoistic with no threshold; a low
/// b_safe that makes many changes unsafe; no keep-side bias.
fn parameter_sets() -> [MobilParameters; 4] {
    [
        MobilParameters::default(),
        MobilParameters {
            politeness: 0.0,
            change_threshold: 0.0,
            ..MobilParameters::default()
        },
        MobilParameters {
            safe_deceleration: 0.5,
            ..MobilParameters::default()
        },
        MobilParameters {
            right_bias: 0.0,
            ..MobilParameters::default()
        },
    ]
}

/// On 40 highways of 60 cars, with four parameter sets (the defaults; egoistic with no
/// threshold; a low b_safe that makes many changes unsafe; no keep-side bias) and desired
/// speeds of 20 and 36 m/s, the step's command (acceleration and lane change) has the bits of
/// [`step_each`]'s, and so has the command the controllers stage takes from the model held by
/// value (drivers.rs `DriverModel::command`, which is `MobilController::command`: the
/// acceleration and lane as numbers), the controller's state after it too. Both kinds of outcome occur many times.
#[test]
fn the_shortcut_gives_the_full_rule_bit_for_bit() {
    let (mut changes, mut keeps) = (0, 0);
    for_each_view(|seed, _, _, e, view| {
        for mobil in parameter_sets() {
            for desired in [20.0, 36.0] {
                let idm = IdmParameters {
                    desired_speed: desired,
                    ..IdmParameters::default()
                };
                let mut fast = MobilController::new(idm, true, mobil);
                let mut full = fast.clone();
                let mut driver = fast.clone();
                let (a, b) = (fast.step(view, 0.05), step_each(&mut full, view));
                assert_eq!(
                    format!("{a:?}"),
                    format!("{b:?}"),
                    "seed {seed}, {}",
                    e.name
                );
                let (acceleration, lane) = driver.command(view);
                let c = Command::Motion {
                    longitudinal: Some(Longitudinal::Acceleration(acceleration)),
                    lateral: lane.map(Lateral::ChangeLane),
                };
                assert_eq!(
                    format!("{c:?} {driver:?}"),
                    format!("{b:?} {full:?}"),
                    "seed {seed}, {}",
                    e.name
                );
                match a {
                    Command::Motion {
                        lateral: Some(_), ..
                    } => changes += 1,
                    _ => keeps += 1,
                }
            }
        }
    });
    assert!(
        changes > 500 && keeps > 5_000,
        "{changes} changes, {keeps} keeps"
    );
}

/// The view keeps the handle of the entity's own lane from its making and a lane beside's
/// from `beside` (issue 31); on the 40 crowded highways its leader, follower and the leader and
/// follower of each lane beside are, bit for bit, the searches made with the lane's handle
/// asked of the network at each question (the view's code before), and the handle `beside`
/// makes from the section at the entity's s is the one the network gives.
#[test]
fn the_kept_lane_handles_give_the_searches_of_handles_asked_each_time() {
    let mut lanes_beside = 0;
    for_each_view(|_, w, index, e, view| {
        let (Some(track), Some(me)) = (e.track.as_ref(), index.footprint(e.id)) else {
            return;
        };
        assert!(track.blend.is_none(), "placed, not changing lanes");
        let dir = track.direction;
        let search = |lane: i32, from: Real, dir: Direction| {
            let h = w.network.lane_handle_on(track.road, lane, track.s)?;
            let none = &mut |_: &str, _: &[opendrive::LaneHandle]| None;
            let n = index.nearest(&w.network, h, from, dir, e.id, view.horizon(), none, None)?;
            Some((n.id, n.gap.to_bits()))
        };
        let ahead = |lane| search(lane, me.front(dir), dir);
        let behind = |lane| search(lane, me.rear(dir), dir.reverse());
        let bits = |g: Option<Gap>| g.map(|g| (g.id, g.gap.to_bits()));
        assert_eq!(bits(view.leader()), ahead(track.lane_id), "{}", e.name);
        assert_eq!(bits(view.follower()), behind(track.lane_id), "{}", e.name);
        for side in [Side::Left, Side::Right] {
            if let Some(b) = view.beside(side) {
                let asked = w.network.lane_handle_on(track.road, b.lane, track.s);
                assert_eq!(Some(b.at.0), asked, "{} {side:?}", e.name);
            }
            if let Some(n) = view.neighbour_lane(side) {
                lanes_beside += 1;
                assert_eq!(bits(n.leader), ahead(n.lane), "{} {side:?}", e.name);
                assert_eq!(bits(n.follower), behind(n.lane), "{} {side:?}", e.name);
            }
        }
    });
    // 2,400 cars on four lanes: each has one or two lanes beside.
    assert!(lanes_beside > 2_400, "{lanes_beside} lanes beside");
}

/// The own leader and the lanes beside's occupancy as the view answers them (issue 31: the
/// answer the entries at the search's hint prove, taken inline,
/// `LaneIndex::nearest_ahead_proven` and `occupied_proven`; the index's search otherwise) are,
/// bit for bit, the searches without a hint (entity, gap and speed; occupied or not), step
/// after step while the traffic moves and the index and its hints are kept as the engine
/// keeps them: 10 crowded highways of 60 cars, 40 steps, every car moved along its lane by
/// its speed (one in ten placed anew elsewhere, so that hints go stale; some across a
/// marking), each car's lanes beside kept as its `mobil` controller keeps them, their lanes'
/// slots asserted to be the index's. Every way occurs many times: proven at the hint and searched, a leader found and
/// none (the front cars; a gap beyond the horizon), a lane beside occupied and free.
#[test]
fn the_views_answers_at_the_hint_are_the_searches_bit_for_bit() {
    use crate::world::entity::EntityId;
    let (mut proven, mut searched, mut found, mut none) = (0, 0, 0, 0);
    let (mut occupied_proven, mut occupied, mut free) = (0, 0, 0);
    for seed in 1..=10u64 {
        let mut w = crowded(60, seed);
        let mut index = LaneIndex::default();
        let mut next = generator(seed + 100);
        // Each car's lanes beside kept from step to step, as its `mobil` controller keeps them.
        let mut kept: Vec<Option<KeptRoad>> = vec![None; 60];
        for step in 0..40 {
            for i in 0..60u32 {
                let id = EntityId(i);
                let e = w.entity(id);
                let Some(rp) = e.road_position.as_ref() else {
                    continue;
                };
                let (mut s, t) = (rp.s + e.speed * 0.05, rp.t);
                if next() < 0.1 || s > 990.0 {
                    s = 20.0 + next() * 900.0;
                }
                let pose = w.network.road_pose("A", s, t).expect("on road");
                let at = w.network.locate(pose.x, pose.y, Some(pose.h));
                w.place_resolved(id, pose, at);
            }
            index.refresh_from(&mut w);
            for e in w.entities() {
                let view = view_of(10.0 + step as Real * 0.05, &w, &index, e);
                let (Some(track), Some(me)) =
                    (view.input().track.as_ref(), index.footprint(e.id).cloned())
                else {
                    continue;
                };
                let dir = track.direction;
                let bits = |g: Option<Gap>| g.map(|g| (g.id, g.gap.to_bits(), g.speed.to_bits()));
                // The hint as the view will find it, before the view's search may store it.
                let hint = |kind: usize| {
                    AtomicU32::new(
                        index
                            .hint(e.id, kind)
                            .expect("hints per entity")
                            .load(Relaxed),
                    )
                };
                let h = track.own.expect("on its lane");
                // The own lane's slot the inputs keep from step to step is the index's.
                assert_eq!(
                    Some(track.own_slot as usize),
                    index.slot(h),
                    "seed {seed} step {step} {}",
                    e.name
                );
                let from = me.front(dir);
                if index
                    .nearest_ahead_proven(h, from, e.id, view.horizon(), &hint(0))
                    .is_some()
                {
                    proven += 1;
                } else {
                    searched += 1;
                }
                let none_chosen = &mut |_: &str, _: &[opendrive::LaneHandle]| None;
                let reference = index
                    .nearest(
                        &w.network,
                        h,
                        from,
                        dir,
                        e.id,
                        view.horizon(),
                        none_chosen,
                        None,
                    )
                    .map(|n| {
                        let along = index
                            .footprint(n.id)
                            .map_or(0.0, |f| f.speed_along(n.direction));
                        (n.id, n.gap.to_bits(), along.to_bits())
                    });
                assert_eq!(
                    bits(view.leader()),
                    reference,
                    "seed {seed} step {step} {}",
                    e.name
                );
                // The own lane read with one look-up of the footprint is the leader, the
                // length and the footprint's s-range asked one by one.
                let own = view.own_lane();
                assert_eq!(
                    bits(own.leader),
                    reference,
                    "seed {seed} step {step} {}",
                    e.name
                );
                assert_eq!(own.length.to_bits(), view.length().to_bits());
                assert_eq!(
                    own.range.map(|(lo, hi)| (lo.to_bits(), hi.to_bits())),
                    Some((me.s_range.0.to_bits(), me.s_range.1.to_bits()))
                );
                if reference.is_some() {
                    found += 1;
                } else {
                    none += 1;
                }
                // As the `mobil` step asks for them: with the range `own_lane` read (the
                // asserts below hold it to the footprint's).
                for b in view
                    .beside_kept_with(&mut kept[e.id.index()], own.range)
                    .into_iter()
                    .flatten()
                {
                    let side = if b.lane > track.lane_id {
                        "larger id"
                    } else {
                        "smaller id"
                    };
                    // The kept slot is the index's for the lane's handle at this step.
                    let slot = index.slot(b.at.0);
                    assert_eq!(b.slot, slot, "seed {seed} step {step} {} {side}", e.name);
                    let kind = if b.lane > track.lane_id { 5 } else { 8 };
                    // The s-range and hint the lane beside carries are the ones the
                    // occupancy's questions looked up per side: the footprint's, the hint of
                    // kind `kind` of the car.
                    let range = (b.range.0.to_bits(), b.range.1.to_bits());
                    assert_eq!(range, (me.s_range.0.to_bits(), me.s_range.1.to_bits()));
                    let alongside = index.hint(e.id, kind).expect("hints per entity");
                    assert!(
                        b.alongside.is_some_and(|h| std::ptr::eq(h, alongside)),
                        "seed {seed} step {step} {} {side}",
                        e.name
                    );
                    if index.occupied_proven(slot.expect("a lane"), me.s_range, e.id, &hint(kind)) {
                        occupied_proven += 1;
                    }
                    let reference = index
                        .overlapping(b.at.0, me.s_range, e.id, None)
                        .next()
                        .is_some();
                    assert_eq!(
                        view.occupied_beside(&b),
                        reference,
                        "seed {seed} step {step} {} {side}",
                        e.name
                    );
                    if reference {
                        occupied += 1;
                    } else {
                        free += 1;
                    }
                }
            }
        }
    }
    let counts = format!(
        "leader: {proven} proven at the hint, {searched} searched, {found} found, {none} none; \
         lanes beside: {occupied_proven} occupied at the hint, {occupied} occupied, {free} free"
    );
    assert!(
        proven > 5_000
            && searched > 1_000
            && found > 5_000
            && none > 100
            && occupied_proven > 2_000
            && occupied > occupied_proven
            && free > 2_000,
        "{counts}"
    );
    println!("{counts}");
}

/// The driver inputs the lane index copies (store/driver_inputs.rs, issue 31) are the
/// entity's own numbers bit for bit, and the own lane's handle, which the index takes from
/// the look-up of its footprint where the road position names the track's lane at the same
/// s, is the handle the network gives for the track's lane asked directly.
#[test]
fn the_driver_inputs_are_the_entitys_bit_for_bit() {
    let (mut tracks, mut leaders) = (0, 0);
    for_each_view(|_, w, index, e, view| {
        let row = index.input(e.id.index()).expect("a row per entity");
        assert_eq!(row.id, e.id);
        assert_eq!(row.placed, e.placed);
        assert_eq!(row.lateral_action, e.lateral_action.is_some());
        assert_eq!(row.speed.to_bits(), e.speed.to_bits(), "{}", e.name);
        assert_eq!(view.speed().to_bits(), e.speed.to_bits(), "{}", e.name);
        let Some(t) = e.track.as_ref() else {
            assert!(row.track.is_none(), "{}", e.name);
            return;
        };
        tracks += 1;
        let r = row.track.expect("the entity has a track");
        assert_eq!(
            (r.road, r.lane_id, r.direction),
            (t.road, t.lane_id, t.direction)
        );
        assert_eq!(r.s.to_bits(), t.s.to_bits(), "{}", e.name);
        assert_eq!(r.blend_from, t.blend.as_ref().map(|b| b.from_lane));
        let asked = w.network.lane_handle_on(t.road, t.lane_id, t.s);
        assert!(asked.is_some(), "{} is on a lane", e.name);
        assert_eq!(r.own, asked, "{}", e.name);
        // The own lane's slot is the index's slot of that handle; a row made outside an
        // index has none, and its view finds the same leader by the handle.
        let slot = asked.and_then(|h| index.slot(h));
        assert!(slot.is_some(), "{}'s lane has a slot", e.name);
        assert_eq!(slot, Some(r.own_slot as usize), "{}", e.name);
        let outside = DriverInput::of(e, &w.network);
        assert_eq!(outside.track.map(|t| t.own_slot), Some(NO_SLOT));
        let mut direct = outside;
        if let Some(t) = direct.track.as_mut() {
            t.own_slot = r.own_slot;
        }
        assert_eq!(*row, direct, "{}", e.name);
        let by_handle = view_with(10.0, w, index, e, &outside);
        let bits = |g: Option<Gap>| g.map(|g| (g.id, g.gap.to_bits(), g.speed.to_bits()));
        assert_eq!(bits(view.leader()), bits(by_handle.leader()), "{}", e.name);
        leaders += usize::from(view.leader().is_some());
    });
    assert!(leaders > 2_000, "{leaders} leaders found");
    assert_eq!(tracks, 2_400, "every car of the 40 highways has a track");
}

/// The road's part of a lane beside as `beside` worked it out before it was kept
/// (controller/lane_beside.rs, issue 31), written out: the section at s, the lane beside's
/// type, its handle asked of the network, both driving directions, the road mark at s.
fn road_beside_directly(net: &RoadNetwork, track: &TrackInput, side: Side) -> Option<RoadBeside> {
    let n = match side {
        Side::Left => 1,
        Side::Right => -1,
    };
    let lane = crate::world::lanes::lane_shift(track.lane_id, n, track.direction);
    let road = net.road_at(track.road);
    let section = road.lane_section_at(track.s);
    let drivable = section
        .lane(lane)
        .is_some_and(|l| l.lane_type.is_drivable());
    let own = track.own?;
    if !drivable {
        return None;
    }
    let handle = net.lane_handle_on(track.road, lane, track.s)?;
    if net.driving_direction(handle) != net.driving_direction(own) {
        return None;
    }
    let keep = match road.rule {
        opendrive::TrafficRule::LeftHand => Side::Left,
        _ => Side::Right,
    };
    Some(RoadBeside {
        lane,
        handle,
        toward_keep_side: side == keep,
        crossing_permitted: section.permits_lane_change(track.lane_id, lane, track.s - section.s),
    })
}

/// The lanes beside kept over the stretch they hold (controller/lane_beside.rs) are, on both
/// sides, the answer asked of the road directly ([`road_beside_directly`]), bit for bit: on
/// this module's road A (a solid mark from s 600 m between lanes −3 and −4) and on two corpus
/// roads (esmini's two_plus_one: five lane sections, lanes appearing and ending; and
/// straight_500m_roadmarks: the mark type changing every 50–100 m), for a track in each lane
/// and direction of each road moving along it in 0.37 m steps, each section and mark start
/// and the doubles about it, and NaN. Answers are kept many times, asked again at every
/// stretch's end; crossings refused and lanes without a neighbour occur.
#[test]
fn the_kept_lanes_beside_are_the_roads_answer_at_every_s() {
    let corpus = crate::controller::lane_beside::tests::esmini_road;
    let nets = [
        network(),
        corpus("two_plus_one.xodr"),
        corpus("straight_500m_roadmarks.xodr"),
    ];
    let (mut kept_used, mut asked, mut refused, mut none) = (0, 0, 0, 0);
    for net in nets {
        // An index of no entity: the lane numbering, whose slots number the questions
        // (store/driver_inputs.rs "The question's number"); the road's part is compared.
        let net = &std::sync::Arc::new(net);
        let index = LaneIndex::build(net, &[]);
        for (r, road) in net.roads().iter().enumerate() {
            let mut at: Vec<Real> = (0..)
                .map(|i| i as Real * 0.37)
                .take_while(|&s| s <= road.length)
                .collect();
            for ls in &road.lane_sections {
                let marks = ls.lanes().flat_map(|l| l.road_marks.iter());
                for b in std::iter::once(ls.s).chain(marks.map(|m| ls.s + m.s_offset)) {
                    // Each start, the doubles a rounding or two from it, and the same about
                    // where s + LENGTH_EPSILON reaches it (the section search's test).
                    for c in [b, b - opendrive::LENGTH_EPSILON] {
                        for f in [-2.0, -1.0, 0.0, 1.0, 2.0] {
                            at.push(c * (1.0 + f * Real::EPSILON));
                        }
                    }
                }
            }
            at.sort_by(Real::total_cmp);
            at.push(Real::NAN);
            let ids = crate::controller::lane_beside::tests::lane_ids(road);
            let road_handle = opendrive::RoadHandle(r as u32);
            for &lane_id in &ids {
                for direction in [Direction::Forward, Direction::Backward] {
                    let mut kept = None;
                    for &s in &at {
                        let at = (road_handle, lane_id, s, direction);
                        let track =
                            crate::controller::lane_beside::tests::track_in(net, &index, at);
                        if kept.is_some_and(|k: KeptRoad| k.within(&track)) {
                            kept_used += 1;
                        } else {
                            asked += 1;
                        }
                        let answer = KeptRoad::for_track(&mut kept, net, &index, &track);
                        for side in [Side::Left, Side::Right] {
                            let direct = road_beside_directly(net, &track, side);
                            assert_eq!(
                                answer.side(side),
                                direct,
                                "road {} lane {lane_id} {direction:?} s {s} {side:?}",
                                road.id
                            );
                            match direct {
                                None => none += 1,
                                Some(b) if !b.crossing_permitted => refused += 1,
                                Some(_) => {}
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(
        kept_used > 50_000 && asked > 100 && refused > 4_000 && none > 10_000,
        "{kept_used} kept, {asked} asked, {refused} refused, {none} without a lane"
    );
}

/// The bounds of the followers' free-road terms settle a candidate only where the rule
/// refuses it (`settled_without_powers`' proof), at the rule's edges: on the 40 crowded
/// highways, for every candidate the changer's safety criterion passes (desired speeds 20
/// and 36 m/s), (1) with the threshold set to the rule's incentive and 1–3 ulps either side
/// (no keep-side bias: the margin is then −k ulp exactly, a change for k < 0), and (2) with
/// b_safe set to the new follower's −ã_n and 1–3 ulps either side (no threshold to pass: a
/// change exactly where ã_n ≥ −b_safe). The bounds never settle a change; away from the
/// edges, at the default parameters, they settle more than two candidates in five of these
/// highways (speeds drawn from 0–35 m/s, where changes are common: about 1,998 of 3,612).
#[test]
fn the_bounds_settle_only_what_the_rule_refuses() {
    let (mut edges, mut edge_changes, mut settled, mut candidates) = (0, 0, 0, 0);
    for_each_view(|seed, _, _, e, view| {
        for desired in [20.0, 36.0] {
            let idm = IdmParameters {
                desired_speed: desired,
                ..IdmParameters::default()
            };
            let c = MobilController::new(idm, true, MobilParameters::default());
            let p = &c.idm.params;
            for side in [Side::Left, Side::Right] {
                let (Some(b), Some(lane)) = (view.beside(side), view.neighbour_lane(side)) else {
                    continue;
                };
                if lane.occupied || !lane.crossing_permitted {
                    continue;
                }
                let cand = candidate_each(&c, view, &lane);
                if !c.mobil.safe_for_changer(cand.own.after) {
                    continue;
                }
                let (v, len) = (view.speed().max(0.0), view.length());
                let n = lane
                    .follower
                    .map(|n| Weighed::new_follower(p, n, v, len, lane.leader));
                let settles = |mobil: &MobilParameters| {
                    let mut own = Own::new(&c.idm, view);
                    settled_without_powers(mobil, p, view, &mut own, cand.own, n, &b)
                };
                candidates += 1;
                settled += usize::from(settles(&c.mobil));
                let unbiased = MobilParameters {
                    change_threshold: 0.0,
                    right_bias: 0.0,
                    ..c.mobil
                };
                let incentive = unbiased.judge(&cand).margin;
                let mut thresholds = vec![incentive];
                let mut safeties = vec![];
                if let Some(after) = cand.new_follower.map(|n| n.after) {
                    safeties.push(-after);
                }
                for _ in 0..3 {
                    let (lo, hi) = (thresholds[0], thresholds[thresholds.len() - 1]);
                    thresholds.extend([lo.next_down(), hi.next_up()]);
                    thresholds.sort_by(Real::total_cmp);
                }
                let mut deceleration_edges = safeties.clone();
                for b_safe in safeties {
                    let mut x = b_safe;
                    let mut y = b_safe;
                    for _ in 0..3 {
                        x = x.next_down();
                        y = y.next_up();
                        deceleration_edges.extend([x, y]);
                    }
                }
                let at_threshold = thresholds.into_iter().map(|t| MobilParameters {
                    change_threshold: t,
                    ..unbiased
                });
                let at_safety = deceleration_edges.into_iter().map(|d| MobilParameters {
                    safe_deceleration: d,
                    change_threshold: Real::NEG_INFINITY,
                    ..unbiased
                });
                for mobil in at_threshold.chain(at_safety) {
                    let rule = mobil.judge(&cand).change();
                    edges += 1;
                    edge_changes += usize::from(rule);
                    assert!(
                        !(rule && settles(&mobil)),
                        "seed {seed}, {} {side:?}: {mobil:?} settled a change",
                        e.name
                    );
                }
            }
        }
    });
    assert!(
        edges > 20_000 && edge_changes > edges / 4 && settled * 5 > candidates * 2,
        "{edges} edge cases, {edge_changes} changes; {settled} of {candidates} settled"
    );
}

/// A mandatory lane (module doc "A mandatory lane") against MOBIL's safety criterion computed
/// in full ([`candidate_each`]): on the 40 crowded highways, for every car at 1 m/s or more
/// with no lateral transition, and each lane beside it as its mandatory lane, the controller
/// changes into that lane exactly where no box is alongside, the mark lets it cross, the
/// changer's ã_c ≥ −b_safe and the new follower's ã_n ≥ −b_safe; otherwise it keeps its lane
/// and its command is the IDM's, or −b where that is higher (it falls back behind what blocks
/// it, when that is not slower); an `idm` controller handed the same mandatory lane gives the
/// same command bit for bit. Beside a lane that is not the mandatory one, a car makes no
/// change of its own, however much MOBIL's incentive asks for one. (At seeds 1–40: 1,064
/// changes, 2,439 waits of which 156 fall back, 1,244 changes of MOBIL's own held.)
#[test]
fn a_mandatory_lane_is_changed_into_exactly_where_mobils_safety_criterion_accepts_the_gap() {
    let (mut changes, mut waits, mut falls_back, mut none_of_its_own) = (0, 0, 0, 0);
    for_each_view(|seed, _, _, e, view| {
        let Some(track) = e.track.as_ref() else {
            return;
        };
        if track.blend.is_some() || e.lateral_action.is_some() || e.speed < MIN_CHANGE_SPEED {
            return;
        }
        let fresh =
            || MobilController::new(IdmParameters::default(), true, MobilParameters::default());
        let idm = fresh().idm.acceleration(view);
        let b = IdmParameters::default().comfortable_deceleration;
        for side in [Side::Left, Side::Right] {
            let Some(lane) = view.neighbour_lane(side) else {
                continue;
            };
            let mut c = fresh();
            c.strategy(Strategy::MandatoryLane(Some(lane.lane)));
            let (a, change) = c.command(view);
            let cand = candidate_each(&c, view, &lane);
            let safe = !lane.occupied
                && lane.crossing_permitted
                && c.mobil.safe_for_changer(cand.own.after)
                && cand
                    .new_follower
                    .is_none_or(|n| c.mobil.safe_for_follower(n.after));
            let at = format!("seed {seed} {} lane {}", e.name, lane.lane);
            assert_eq!(change, safe.then_some(lane.lane), "{at}");
            // The `idm` handed the same mandatory lane runs the same code: the same command,
            // bit for bit (its MOBIL safety criterion at the default b_safe, as here).
            let mut idm_held = IdmDriver::new(IdmController::new(IdmParameters::default(), true));
            idm_held.strategy(Strategy::MandatoryLane(Some(lane.lane)));
            let (ia, ichange) = idm_held.command(view);
            assert!(
                ia.to_bits() == a.to_bits() && ichange == change,
                "{at}: idm {ia} {ichange:?}"
            );
            if safe {
                changes += 1;
                assert_eq!(a.to_bits(), idm.to_bits(), "{at}");
            } else {
                waits += 1;
                let lowered = a.to_bits() == idm.min(-b).to_bits() && idm > -b;
                falls_back += usize::from(lowered);
                assert!(a.to_bits() == idm.to_bits() || lowered, "{at}: {a} {idm}");
            }
            // Its own lane as the mandatory one: no change at all, whatever MOBIL would do.
            let mut kept = fresh();
            kept.strategy(Strategy::MandatoryLane(Some(track.lane_id)));
            let (a, change) = kept.command(view);
            none_of_its_own += usize::from(fresh().command(view).1.is_some());
            assert!(change.is_none() && a.to_bits() == idm.to_bits(), "{at}");
        }
    });
    assert!(
        changes > 500 && waits > 500 && falls_back > 100 && none_of_its_own > 100,
        "{changes} changes, {waits} waits ({falls_back} falling back), {none_of_its_own} MOBIL changes held"
    );
}

/// A free-road acceleration handed to a driver model (car_following.rs module doc, "A
/// free-road acceleration handed to the `idm`") replaces the IDM's free-road term a·(1 −
/// (v/v0)^δ) and nothing else: on the 40 crowded highways, for every car, the `idm` and the
/// `mobil` handed 1.5 m/s² command 1.5 less the IDM's interaction term a·(s*/s)² toward the
/// leader (Treiber, Hennecke, Helbing 2000, eq. (2)), bit for bit, exactly 1.5 with no leader;
/// where the gap asks for it the braking wins (the command below −b although 1.5 was handed).
/// Released, both give the same bits as models never handed one, lane decisions included:
/// ordinary traffic is unchanged. (At seeds 1–40: 2,400 cars, 161 with no leader, 919 braking
/// harder than b.)
#[test]
fn a_free_road_acceleration_replaces_only_the_free_term_and_its_release_restores_the_model() {
    let (mut free_road, mut braking, mut cars) = (0, 0, 0);
    let b = IdmParameters::default().comfortable_deceleration;
    for_each_view(|seed, _, _, e, view| {
        let at = format!("seed {seed} {}", e.name);
        let p = IdmParameters::default();
        let v = view.speed().max(0.0);
        let leader = with_red_light(view, crate::controller::car_following::leader(view));
        let want = match leader {
            None => 1.5,
            Some(l) => 1.5 - p.interaction(v, l),
        };
        let handed = Strategy::FreeAcceleration(Some(FreeAcceleration::Fixed(1.5)));
        let fresh_idm = || IdmDriver::new(IdmController::new(p, true));
        let fresh_mobil = || MobilController::new(p, true, MobilParameters::default());
        let mut idm = fresh_idm();
        idm.strategy(handed);
        let mut mobil = fresh_mobil();
        mobil.strategy(handed);
        let (ia, _) = idm.command(view);
        let (ma, _) = mobil.command(view);
        assert!(
            ia.to_bits() == want.to_bits() && ma.to_bits() == want.to_bits(),
            "{at}: idm {ia}, mobil {ma}, want {want}"
        );
        cars += 1;
        free_road += usize::from(leader.is_none());
        braking += usize::from(want < -b);
        // Released: the model's own free-road term again, bit for bit.
        idm.strategy(Strategy::FreeAcceleration(None));
        mobil.strategy(Strategy::FreeAcceleration(None));
        let (ia, il) = idm.command(view);
        let (fa, fl) = fresh_idm().command(view);
        assert!(
            ia.to_bits() == fa.to_bits() && il == fl,
            "{at}: idm {ia} {fa}"
        );
        // (A mobil that changed lanes in its handed step waits MIN_CHANGE_INTERVAL: one handed
        // and released before its step.)
        let mut mobil = fresh_mobil();
        mobil.strategy(handed);
        mobil.strategy(Strategy::FreeAcceleration(None));
        let (ma, ml) = mobil.command(view);
        let (fa, fl) = fresh_mobil().command(view);
        assert!(
            ma.to_bits() == fa.to_bits() && ml == fl,
            "{at}: mobil {ma} {fa}"
        );
    });
    assert!(
        cars == 2400 && free_road > 100 && braking > 500,
        "{cars} cars, {free_road} on a free road, {braking} braking harder than b"
    );
}

/// The bundled two-road map of the DSL runtime's tests (road_link_unequal_number_of_lanes0.xodr):
/// road 1 (100 m from (0, 0) along +x, right lanes −1, −2, −3 of 3 m) ends where road 2 (100 m
/// on, lanes −1 … −4) starts; lanes −1, −2 of road 1 lead into −1, −2 of road 2, lane −3 into
/// −4 (road 2's −3 is a lane that starts there, linked to nothing behind).
fn two_road_network() -> RoadNetwork {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../dsl_runtime/tests/roads/road_link_unequal_number_of_lanes0.xodr"
    );
    let text = std::fs::read_to_string(path).expect("the bundled map");
    RoadNetwork::from_str(&text, std::path::Path::new(path)).expect("the bundled map parses")
}

/// A 4.5 m car alone at 20 m/s on lane `lane`'s centre of road `road` at `s`.
fn alone_on(net: &std::sync::Arc<RoadNetwork>, road: &str, lane: i32, s: Real) -> World {
    use crate::domain::{BoundingBox, Vector3};
    use crate::world::entity::{EntityId, EntityKind};
    let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), 4.5, 2.0, 1.5).expect("box");
    let car = Entity::new(EntityId(0), "car", EntityKind::Vehicle, b);
    let mut w = World::new(net.clone(), vec![car]);
    // Lanes of 3 m: lane −k's centre at t = −3k + 1.5.
    let t = 3.0 * Real::from(lane) + 1.5;
    let pose = w.network.road_pose(road, s, t).expect("on the road");
    let found = w.network.locate(pose.x, pose.y, Some(pose.h));
    w.place_resolved(EntityId(0), pose, found);
    w.entity_mut(EntityId(0)).speed = 20.0;
    w
}

/// Issue 27 follow-up 4: a mandatory lane is a lane of the road where it is asked for; where
/// the entity passes onto the next road, the lane it must reach is the one the target lane's
/// links lead to there (OpenDRIVE 1.8 §11.5 lane linkage), not the lane of the same id. On the
/// two-road map, with lane −3 of road 1 as the mandatory lane (asked for at s = 80 m of road 1,
/// the first step):
/// - reached on road 1 (in lane −3 at s = 80 m), the car passes onto road 2, its track now in
///   lane −4 (−3's successor): no change; before, it changed back into road 2's lane −3, the
///   lane that starts there;
/// - asked for from lane −1 of road 1 (a change to −2 at s = 80 m, the road empty), the car
///   then in lane −2 at s = 10 m of road 2 changes to −3, and in −3 at s = 30 m on to −4 (two
///   lanes to go on road 2, where before −3 counted as reached);
/// - the idm and the mobil controller alike (one piece of code).
#[test]
fn a_mandatory_lane_across_a_road_end_follows_the_target_lanes_links() {
    let net = std::sync::Arc::new(two_road_network());
    // The lane `c` changes to for the car alone on `road`, `lane`, at `s`, at time `time`.
    fn command_at(
        c: &mut dyn FnMut(&ControllerView<'_>) -> Option<i32>,
        net: &std::sync::Arc<RoadNetwork>,
        (road, lane, s): (&str, i32, Real),
        time: Real,
    ) -> Option<i32> {
        let w = alone_on(net, road, lane, s);
        let e = &w.entities()[0];
        let track = e.track.as_ref().expect("a lane track");
        assert_eq!((track.road_id.as_str(), track.lane_id), (road, lane));
        let index = LaneIndex::build(&w.network, w.entities());
        c(&view_of(time, &w, &index, e))
    }
    let idm = IdmParameters {
        desired_speed: 20.0,
        ..IdmParameters::default()
    };
    // The idm and the mobil controller, each handed lane -3 as its mandatory lane.
    type LaneOf = Box<dyn FnMut(&ControllerView<'_>) -> Option<i32>>;
    let models = || -> [LaneOf; 2] {
        let mut i = IdmDriver::new(IdmController::new(idm, true));
        i.strategy(Strategy::MandatoryLane(Some(-3)));
        let mut m = MobilController::new(idm, true, MobilParameters::default());
        m.strategy(Strategy::MandatoryLane(Some(-3)));
        [
            Box::new(move |v: &ControllerView<'_>| i.command(v).1),
            Box::new(move |v: &ControllerView<'_>| m.command(v).1),
        ]
    };
    for (k, mut c) in models().into_iter().enumerate() {
        assert_eq!(command_at(&mut c, &net, ("1", -3, 80.0), 0.0), None, "{k}");
        assert_eq!(command_at(&mut c, &net, ("2", -4, 5.0), 1.0), None, "{k}");
    }
    for (k, mut c) in models().into_iter().enumerate() {
        assert_eq!(
            command_at(&mut c, &net, ("1", -1, 80.0), 0.0),
            Some(-2),
            "{k}"
        );
        assert_eq!(
            command_at(&mut c, &net, ("2", -2, 10.0), 5.0),
            Some(-3),
            "{k}"
        );
        assert_eq!(
            command_at(&mut c, &net, ("2", -3, 30.0), 10.0),
            Some(-4),
            "{k}"
        );
        assert_eq!(command_at(&mut c, &net, ("2", -4, 60.0), 15.0), None, "{k}");
    }
}

/// A mandatory lane whose links do not lead onto the entity's road is noted as lost, once per
/// road and lane section (module doc "Across roads"; found-not-fixed item 4: before, the
/// change just did not happen, and the event log said nothing). The two-road map with road 1's
/// lane −3 ending at the road's end (its `<successor id="-4"/>` taken out: a lane drop): asked
/// for lane −3 from lane −1 of road 1 at s = 80 m, the car changes to −2 (no note); on road 2
/// (lane −2, s = 10 m) −3's links lead nowhere: no change, and the note names road "2", lane
/// section 1; at s = 30 m of road 2 still no change and no second note. The idm and the mobil
/// alike.
#[test]
fn a_mandatory_lane_whose_links_do_not_reach_the_road_is_noted_as_lost_once() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../dsl_runtime/tests/roads/road_link_unequal_number_of_lanes0.xodr"
    );
    let text = std::fs::read_to_string(path).expect("the bundled map");
    let dropped = text.replacen(r#"<successor id="-4"/>"#, "", 1);
    assert_ne!(dropped, text, "the link is in the map");
    let net = std::sync::Arc::new(
        RoadNetwork::from_str(&dropped, std::path::Path::new(path)).expect("parses"),
    );
    let idm = IdmParameters {
        desired_speed: 20.0,
        ..IdmParameters::default()
    };
    let mut i = IdmDriver::new(IdmController::new(idm, true));
    let mut m = MobilController::new(idm, true, MobilParameters::default());
    let controllers: [&mut dyn Controller; 2] = [&mut i, &mut m];
    for c in controllers {
        c.strategy(Strategy::MandatoryLane(Some(-3)));
        let mut at = |(road, lane, s): (&str, i32, Real), time: Real| {
            let w = alone_on(&net, road, lane, s);
            let index = LaneIndex::build(&w.network, w.entities());
            let view = view_of(time, &w, &index, &w.entities()[0]);
            let lane = match c.step(&view, 0.05) {
                Command::Motion { lateral, .. } => lateral,
                Command::Pose(_) => None,
            };
            (lane, c.note())
        };
        assert_eq!(
            at(("1", -1, 80.0), 0.0),
            (Some(Lateral::ChangeLane(-2)), None)
        );
        assert_eq!(
            at(("2", -2, 10.0), 5.0),
            (
                None,
                Some(
                    "mandatory lane -3 lost: its lane links lead onto no lane of road \"2\" (lane section 1) where the entity is; it makes no change towards it there"
                        .to_owned()
                )
            )
        );
        assert_eq!(at(("2", -2, 30.0), 10.0), (None, None));
    }
}

/// A rate toward a speed handed to a driver model (car_following.rs module doc, "A rate toward
/// a speed"): on the 40 crowded highways, for every car at speed v, the `idm` and the `mobil`
/// handed a rate of −1.5 m/s² toward v + 10 m/s command +1.5 less the IDM's interaction term
/// toward the leader bit for bit (the magnitude, signed toward the speed; braking still wins),
/// and toward v + 0.01 m/s in a step of 0.05 s the cut term 0.01/0.05 = 0.2 m/s² less it
/// (within 1e-12: the cut's rounding). Toward v itself the first step releases it: the same
/// bits and lane decisions as a model never handed one.
#[test]
fn a_rate_toward_a_speed_is_its_magnitude_toward_it_cut_at_it_and_released_there() {
    let mut cars = 0;
    for_each_view(|seed, _, _, e, view| {
        let at = format!("seed {seed} {}", e.name);
        let p = IdmParameters::default();
        let v = view.speed().max(0.0);
        let leader = with_red_light(view, crate::controller::car_following::leader(view));
        let less = |a: Real| match leader {
            None => a,
            Some(l) => a - p.interaction(v, l),
        };
        let toward = |speed: Real| Strategy::FreeAccelerationToward {
            speed,
            rate: FreeAcceleration::Fixed(-1.5),
            of: None,
        };
        let fresh_idm = || IdmDriver::new(IdmController::new(p, true));
        let fresh_mobil = || MobilController::new(p, true, MobilParameters::default());
        // Far from it: the rate's magnitude toward the speed.
        let (mut idm, mut mobil) = (fresh_idm(), fresh_mobil());
        idm.strategy(toward(v + 10.0));
        mobil.strategy(toward(v + 10.0));
        let (ia, ma) = (idm.command(view).0, mobil.command(view).0);
        let want = less(1.5);
        assert!(
            ia.to_bits() == want.to_bits() && ma.to_bits() == want.to_bits(),
            "{at}: idm {ia}, mobil {ma}, want {want}"
        );
        // Within a step of it: cut so that the step ends there.
        let stepping = view.stepping(0.05);
        let (mut idm, mut mobil) = (fresh_idm(), fresh_mobil());
        idm.strategy(toward(v + 0.01));
        mobil.strategy(toward(v + 0.01));
        let (ia, ma) = (idm.command(&stepping).0, mobil.command(&stepping).0);
        let want = less(0.2);
        assert!(
            (ia - want).abs() < 1e-12 && (ma - want).abs() < 1e-12,
            "{at}: idm {ia}, mobil {ma}, want {want}"
        );
        // At it: released before the step, the model's own term.
        let (mut idm, mut mobil) = (fresh_idm(), fresh_mobil());
        idm.strategy(toward(v));
        mobil.strategy(toward(v));
        let (ia, il) = idm.command(&stepping);
        let (ma, ml) = mobil.command(&stepping);
        let mut own_idm = fresh_idm();
        own_idm.strategy(Strategy::Speed(v));
        let mut own_mobil = fresh_mobil();
        own_mobil.strategy(Strategy::Speed(v));
        let (fa, fl) = own_idm.command(&stepping);
        let (ga, gl) = own_mobil.command(&stepping);
        assert!(
            ia.to_bits() == fa.to_bits() && il == fl && ma.to_bits() == ga.to_bits() && ml == gl,
            "{at}: idm {ia} {fa}, mobil {ma} {ga}"
        );
        cars += 1;
    });
    assert_eq!(cars, 2400);
}

/// A rate toward another's speed (car_following.rs module doc, "A rate toward another's
/// speed"): for every car at v ≥ 10.5 m/s on the 40 crowded highways, with x the world's next
/// car at v_x and δ = v − v_x + 10: handed a rate of −1.5 m/s² toward x's speed + δ, the `idm`
/// and the `mobil` take x's speed as the step's view shows it: desired speed v_x + δ (= v + 10
/// up to rounding), command +1.5 less the IDM's interaction term toward the leader bit for bit
/// (|v + 10 − v| = 10 > 1.5·0.05: the full magnitude, signed toward it). In the same world with
/// x 20 m/s slower the same handed controllers read it at their next step: desired speed
/// (v_x − 20) + δ (= v − 10 ≥ 0.5), command −1.5 less the interaction term bit for bit: the
/// rate follows x and is not released. Released, the desired speed stays the last one read.
#[test]
fn a_rate_toward_anothers_speed_reads_it_at_every_step_and_follows_it() {
    let mut cars = 0;
    for seed in 1..=40u64 {
        let w = crowded(60, seed);
        let index = LaneIndex::build(&w.network, w.entities());
        let n = w.entities().len();
        for (i, e) in w.entities().iter().enumerate() {
            let v = e.speed.max(0.0);
            if v < 10.5 {
                continue;
            }
            let x = &w.entities()[(i + 1) % n];
            let at = format!("seed {seed} {} toward {}", e.name, x.name);
            let p = IdmParameters::default();
            let delta = v - x.speed + 10.0;
            let toward = || Strategy::FreeAccelerationToward {
                speed: delta,
                rate: FreeAcceleration::Fixed(-1.5),
                of: Some(x.id),
            };
            let mut idm = IdmDriver::new(IdmController::new(p, true));
            let mut mobil = MobilController::new(p, true, MobilParameters::default());
            idm.strategy(toward());
            mobil.strategy(toward());
            // Step 1: x at v_x.
            let view = view_of(10.0, &w, &index, e).stepping(0.05);
            let less = |view: &ControllerView<'_>, a: Real| match with_red_light(
                view,
                crate::controller::car_following::leader(view),
            ) {
                None => a,
                Some(l) => a - p.interaction(v, l),
            };
            let (ia, ma) = (idm.command(&view).0, mobil.command(&view).0);
            let want = less(&view, 1.5);
            let desired = x.speed + delta;
            assert!(
                ia.to_bits() == want.to_bits()
                    && ma.to_bits() == want.to_bits()
                    && idm.idm.params.desired_speed == desired
                    && mobil.idm.params.desired_speed == desired,
                "{at}: idm {ia}, mobil {ma}, want {want}; desired {}",
                idm.idm.params.desired_speed
            );
            // Step 2: x 20 m/s slower, read by the same controllers.
            let mut w2 = crowded(60, seed);
            w2.entity_mut(x.id).speed = x.speed - 20.0;
            let index2 = LaneIndex::build(&w2.network, w2.entities());
            let e2 = w2.entity(e.id);
            let view2 = view_of(10.05, &w2, &index2, e2).stepping(0.05);
            let (ia, ma) = (idm.command(&view2).0, mobil.command(&view2).0);
            let want = less(&view2, -1.5);
            let desired = (x.speed - 20.0) + delta;
            assert!(
                ia.to_bits() == want.to_bits()
                    && ma.to_bits() == want.to_bits()
                    && idm.idm.params.desired_speed == desired
                    && (desired - (v - 10.0)).abs() < 1e-9,
                "{at}: idm {ia}, mobil {ma}, want {want}; desired {}",
                idm.idm.params.desired_speed
            );
            // Released: the desired speed read last stays.
            idm.strategy(Strategy::FreeAcceleration(None));
            assert!(
                idm.idm.params.desired_speed == desired
                    && idm.idm.free_term(&view2, v).to_bits()
                        == idm.idm.params.free_acceleration(v).to_bits(),
                "{at}"
            );
            cars += 1;
        }
    }
    assert!(cars > 100, "{cars} cars at 10.5 m/s or more");
}

/// Road "R" of the ending-lane tests: 300 m along +x, right lanes of 3.5 m towards +s. Its
/// first lane section (s 0…150) has lanes −1, −2, −3; the second (s 150…300) −1 and −2,
/// linked from the first's −1 and −2. Lane −3 ends at s = 150: with no successor (OpenDRIVE
/// 1.8 §11.5; an acceleration lane), or, `narrowed`, linked on to a lane −3 of width 0 in the
/// second section (a lane whose width goes to 0). Every lane ends at the road's end, s = 300
/// (no road link).
fn ending_lane_network(narrowed: bool) -> RoadNetwork {
    let lane_of = |id: i32, link: &str, width: &str| {
        format!(
            r#"<lane id="{id}" type="driving"><link>{link}</link><width sOffset="0" a="{width}" b="0" c="0" d="0"/><roadMark sOffset="0" type="broken"/></lane>"#
        )
    };
    let lane = |id: i32, link: &str| lane_of(id, link, "3.5");
    let (a3, b3) = if narrowed {
        (
            lane(-3, r#"<successor id="-3"/>"#),
            lane_of(-3, r#"<predecessor id="-3"/>"#, "0"),
        )
    } else {
        (lane(-3, ""), String::new())
    };
    let xodr = format!(
        r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="R" junction="-1" length="300"><link/><planView><geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry></planView><lanes>
<laneSection s="0"><center><lane id="0" type="none"/></center><right>{a1}{a2}{a3}</right></laneSection>
<laneSection s="150"><center><lane id="0" type="none"/></center><right>{b1}{b2}{b3}</right></laneSection>
</lanes></road></OpenDRIVE>"#,
        a1 = lane(-1, r#"<successor id="-1"/>"#),
        a2 = lane(-2, r#"<successor id="-2"/>"#),
        b1 = lane(-1, r#"<predecessor id="-1"/>"#),
        b2 = lane(-2, r#"<predecessor id="-2"/>"#),
    );
    RoadNetwork::from_str(&xodr, std::path::Path::new("ending_lane.xodr")).expect("road")
}

/// 4.5 m × 2 m cars on road "R" of `net`, each at (lane, s, speed) on its lane's centre (3.5 m
/// lanes: lane −k's centre at t = 3.5·(−k) + 1.75).
fn cars_on(net: &std::sync::Arc<RoadNetwork>, cars: &[(i32, Real, Real)]) -> World {
    use crate::domain::{BoundingBox, Vector3};
    use crate::world::entity::{EntityId, EntityKind};
    let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), 4.5, 2.0, 1.5).expect("box");
    let entities = (0..cars.len() as u32)
        .map(|i| Entity::new(EntityId(i), &format!("c{i}"), EntityKind::Vehicle, b))
        .collect();
    let mut w = World::new(net.clone(), entities);
    for (i, &(lane, s, speed)) in cars.iter().enumerate() {
        let t = 3.5 * Real::from(lane) + 1.75;
        let pose = w.network.road_pose("R", s, t).expect("on the road");
        let found = w.network.locate(pose.x, pose.y, Some(pose.h));
        let id = EntityId(i as u32);
        w.place_resolved(id, pose, found);
        w.entity_mut(id).speed = speed;
    }
    w
}

/// A driver model does not start a change into a lane that ends within the change (module
/// doc "A lane that ends"). On road "R" ([`ending_lane_network`]: lane −3 ends at s = 150,
/// without a successor, and again where it narrows to width 0 there), a
/// `mobil` car at 20 m/s in lane −2 behind a leader at 5 m/s 10.5 m ahead (the leader 15 m
/// further along: rear 15 − 0.85 − 3.65 = 10.5 m from the car's front), lane −1 beside it
/// taken by a car alongside: MOBIL's incentive is all for lane −3 (free, on the keep side).
/// The change needs 20·√(6·3.5/1) = 20·4.5826 = 91.65 m (world/lane_change.rs) and the
/// car's 4.5 m, 96.15 m of lane −3 ahead: from s = 40 there are 110 m, the car changes to −3;
/// from s = 60 there are 90 m, it keeps its lane (before: it changed into −3 there too).
/// The `idm` and the `mobil` handed −3 as their mandatory lane alike. Lanes that end where
/// the car's own lane ends are not refused: at s = 250 in lane −1 behind the same slow
/// leader, lane −2 beside has 50 m left, as lane −1 has (both end at the road's end), and the
/// car changes to −2.
#[test]
fn a_driver_model_does_not_change_into_a_lane_that_ends_within_the_change() {
    for narrowed in [false, true] {
        a_driver_model_does_not_change_into_the_ending_lane_of(narrowed);
    }
}

/// [`a_driver_model_does_not_change_into_a_lane_that_ends_within_the_change`] on
/// [`ending_lane_network`]`(narrowed)`.
fn a_driver_model_does_not_change_into_the_ending_lane_of(narrowed: bool) {
    let net = std::sync::Arc::new(ending_lane_network(narrowed));
    let idm = IdmParameters::default();
    let change_at = |s: Real, mandatory: Option<i32>, idm_model: bool| {
        let w = cars_on(&net, &[(-2, s, 20.0), (-2, s + 15.0, 5.0), (-1, s, 20.0)]);
        let index = LaneIndex::build(&w.network, w.entities());
        let view = view_of(10.0, &w, &index, &w.entities()[0]);
        if idm_model {
            let mut c = IdmDriver::new(IdmController::new(idm, true));
            c.strategy(Strategy::MandatoryLane(mandatory));
            c.command(&view).1
        } else {
            let mut c = MobilController::new(idm, true, MobilParameters::default());
            if mandatory.is_some() {
                c.strategy(Strategy::MandatoryLane(mandatory));
            }
            c.command(&view).1
        }
    };
    assert_eq!(change_at(40.0, None, false), Some(-3), "{narrowed}");
    assert_eq!(change_at(60.0, None, false), None, "{narrowed}");
    for idm_model in [false, true] {
        let at = format!("{narrowed} {idm_model}");
        assert_eq!(change_at(40.0, Some(-3), idm_model), Some(-3), "{at}");
        assert_eq!(change_at(60.0, Some(-3), idm_model), None, "{at}");
    }
    // Both lanes end at the road's end: no refusal.
    let w = cars_on(&net, &[(-1, 250.0, 20.0), (-1, 265.0, 5.0)]);
    let index = LaneIndex::build(&w.network, w.entities());
    let view = view_of(10.0, &w, &index, &w.entities()[0]);
    let mut c = MobilController::new(idm, true, MobilParameters::default());
    assert_eq!(c.command(&view).1, Some(-2), "{narrowed}");
}
