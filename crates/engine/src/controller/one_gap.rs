//! Two lane changes into one gap (OpenSCENARIO 1.3 §7.2.2.1 motion control; the driver
//! models' lane changes, controller/mobil.rs; issue 27).
//!
//! **The conflict.** Every command of a step is worked out from the world at the step's start
//! (controller/stage.rs, controller/parallel.rs), so two vehicles on either side of a lane L
//! can both judge the same gap in L free and change into it in the same step. And a vehicle
//! whose change into L is under way is in L's lane index only once its box reaches L
//! (store/lane_index.rs enters a box in the lanes its t-range overlaps: a 2 m box centred in
//! a 3.5 m lane reaches the next lane 0.75 m over, 1.3 s into a 4.6 s change), so for those
//! steps a vehicle on L's other side judges the same gap free as well. Nothing reserved the
//! gap: both ended in it, their boxes overlapping.
//!
//! **The rule: SUMO's order.** SUMO's lane changer (`MSLaneChanger::laneChange`) lets the
//! vehicles of a road change one at a time, the one furthest downstream first
//! (`findCandidate`: "the vehicle … with the largest position"; of equal positions the one on
//! the lane first in its order, the rightmost), and each later one judges its change with the
//! earlier changes made (the changed vehicle is registered on its new lane, `registerHop`).
//! Here, once the step's commands are merged, the driver models' changes into each lane are
//! taken in that order: front bumper furthest along the direction of travel first; of equal
//! fronts, the change from the keep side of the lane first (SUMO's rightmost lane under
//! right-hand traffic); then by entity index. A change yields when another vehicle would be
//! next to it in the lane and fails MOBIL's safety criterion there, as the changer's model
//! judges its own changes (controller/mobil.rs `gap_safe`; boxes that overlap along the lane
//! always fail): a change taken before it in this order, from either side, or a change under
//! way into the lane (the vehicle's lane track names the lane, its lateral transition leaving
//! the lane beyond it or the changer's own lane), searched in those two lanes within the
//! changer's gap-search horizon
//! ([`ControllerView::horizon`](super::view::ControllerView::horizon)). A yielding change is
//! not started, and its model is as if it had decided none ([`DriverModel::yield_change`]): it
//! decides again in the next step, and finds the other vehicle in the lane.
//!
//! **From the same side too.** Two vehicles of one lane judge the target lane from the step's
//! start, where neither is in it, so both can take the same gap in one step, and for the steps
//! until the first one's box reaches the lane the second still finds the gap free. SUMO weighs
//! them: `MSLaneChanger::getRealLeader` makes the vehicle that hopped into the target lane in
//! the step (`hoppedVeh`) the next candidate's leader there, whichever lane it came from, and a
//! vehicle changing is found as a leader on both lanes (`continueChange`: "set as hoppedVeh on
//! the shadow lane so it is found as leader on both lanes"; eclipse-sumo/sumo
//! src/microsim/MSLaneChanger.cpp). So here: the one behind (the one in front goes first)
//! weighs the one in front as its leader in the lane, at the gap it has behind it now. The two
//! keep their order and that gap, so its ã_c there is its acceleration behind it now: it yields
//! only where it already brakes harder than b_safe behind it (the one in front cut in close, or
//! stands), a gap it would not change into behind it. SUMO's model also judges the change's
//! incentive with that leader (its own gain then is none); oscsim's rule weighs safety only,
//! as for the other side.
//!
//! A LaneChangeAction of the storyboard (on an entity no `mobil` holds the lateral domain of)
//! is weighed as a change under way from the step it starts in: it sets the entity's lane
//! track to the target lane with the lateral transition from its lane (actions/lane_change.rs),
//! in the actions stage, before this stage reads the tracks; it never yields. A LaneChangeAction
//! handed to a `mobil` is carried out as ordered, as before: it does not yield, and counts as
//! taken.
//!
//! **Not weighed yet: across a road's joint.** The changes are grouped and measured on one
//! road (its s): a change whose lane track and box are on different roads (the steps where its
//! reference point has passed a road's end and its track not yet, or the other way) is neither
//! weighed nor weighed against, and two changes into one lane on either side of a joint (one
//! near road A's end, one at the start of its successor B, into the lane and its continuation)
//! are in different groups, and a change under way is searched on the changer's road only. So
//! two vehicles can still take one gap that spans a road's joint in the same step. Weighing
//! them needs the places on one measure across the lane links (OpenDRIVE 1.8 §11.5; the lane
//! graph's successors and predecessors, as store/lane_index.rs walks them for the gap
//! searches): not done.
//!
//! Ordinary MOBIL traffic has the same conflict (tests/controller/user_controllers.rs
//! `mobil_changes_from_both_sides_into_one_gap_one_after_the_other`), so its changes follow the
//! rule too; where no two changes meet so, its commands are what they were.
//!
//! **The same bits for any thread count.** The rule reads the merged commands and the world at
//! the step's start, and takes the changes in a total order that depends on neither the threads
//! nor the order the commands were worked out in (controller/parallel.rs).

use std::cmp::Ordering;

use opendrive::{Direction, Real, RoadHandle, TrafficRule};

use super::command::{Lateral, Merged};
use super::drivers::DriverModel;
use super::mobil::Next;
use super::parallel::StepWorld;
use crate::world::lanes::lane_shift;

/// A driver model's lane change in a step's merged commands.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Change {
    /// Its place in the merged commands.
    at: usize,
    /// The driver model's place (controller/drivers.rs).
    model: usize,
    /// The lane changed into.
    lane: i32,
    /// Where the entity is (filled by [`resolve`]).
    place: Place,
    /// Taken: not yielded.
    taken: bool,
}

/// Where a changing entity is at the step's start.
#[derive(Debug, Clone, Copy)]
struct Place {
    entity: usize,
    road: RoadHandle,
    /// The lane it leaves.
    from: i32,
    direction: Direction,
    /// Its box's s-range on `road`.
    s_range: (Real, Real),
    /// Its front bumper's s along the direction of travel (larger: further downstream).
    front: Real,
    /// It comes from the keep side of the lane it changes into.
    from_keep_side: bool,
    /// The lane is on its left.
    left: bool,
}

impl Change {
    /// The change of the driver model at place `model` into `lane`, merged at place `at`.
    pub fn asked(at: usize, model: usize, lane: i32) -> Self {
        Change {
            at,
            model,
            lane,
            place: Place {
                entity: 0,
                road: RoadHandle(0),
                from: 0,
                direction: Direction::Forward,
                s_range: (0.0, 0.0),
                front: 0.0,
                from_keep_side: false,
                left: false,
            },
            taken: true,
        }
    }
}

/// A distance along `direction` of travel: s towards +s, −s towards −s.
fn along(direction: Direction, s: Real) -> Real {
    match direction {
        Direction::Forward => s,
        Direction::Backward => -s,
    }
}

/// `other` (its box's s-range and speed along s) next to `me` along `direction`: ahead or
/// behind, with the bumper-to-bumper gap (≤ 0 where the boxes overlap along the lane).
fn next_to(
    me: (Real, Real),
    other: (Real, Real),
    direction: Direction,
    id: crate::world::EntityId,
    speed: Real,
) -> Next {
    let (lo, hi) = (along(direction, me.0), along(direction, me.1));
    let (me_rear, me_front) = (lo.min(hi), lo.max(hi));
    let (lo, hi) = (along(direction, other.0), along(direction, other.1));
    let (other_rear, other_front) = (lo.min(hi), lo.max(hi));
    let ahead = other_front > me_front || (other_front == me_front && other_rear >= me_rear);
    let gap = if ahead {
        other_rear - me_front
    } else {
        me_rear - other_front
    };
    Next {
        id,
        ahead,
        gap,
        speed,
    }
}

/// Finds where each change's entity is; `None` where it cannot be weighed (module doc).
fn place(world: &StepWorld<'_>, entity: usize, lane: i32) -> Option<Place> {
    let input = world.index.input(entity)?;
    let track = input.track.as_ref()?;
    let fp = world.index.footprint(input.id)?;
    if fp.handle.road != track.road.0 {
        return None;
    }
    let left = lane_shift(track.lane_id, 1, track.direction) == lane;
    if !left && lane_shift(track.lane_id, -1, track.direction) != lane {
        return None;
    }
    let keep_right = world.network.road_at(track.road).rule != TrafficRule::LeftHand;
    Some(Place {
        entity,
        road: track.road,
        from: track.lane_id,
        direction: track.direction,
        s_range: fp.s_range,
        front: along(track.direction, fp.front(track.direction)),
        from_keep_side: left == keep_right,
        left,
    })
}

/// The order of the changes (module doc): by road, lane and direction, then the front
/// furthest downstream first, the change from the keep side first, the entity index.
fn order(a: &Change, b: &Change) -> Ordering {
    let (p, q) = (&a.place, &b.place);
    (p.road.0, a.lane, p.direction as u8)
        .cmp(&(q.road.0, b.lane, q.direction as u8))
        .then_with(|| q.front.total_cmp(&p.front))
        .then_with(|| q.from_keep_side.cmp(&p.from_keep_side))
        .then_with(|| p.entity.cmp(&q.entity))
}

/// Applies the rule (module doc) to the driver models' lane changes `changes` of the merged
/// commands `merged`: a change that yields is taken out of its command, and its model told.
pub(crate) fn resolve(
    changes: &mut Vec<Change>,
    merged: &mut [(usize, Merged)],
    world: StepWorld<'_>,
    drivers: &mut [DriverModel],
) {
    changes.retain_mut(|c| {
        let Some(&(entity, m)) = merged.get(c.at) else {
            return false;
        };
        if m.lateral != Some(Lateral::ChangeLane(c.lane)) {
            return false;
        }
        match place(&world, entity, c.lane) {
            Some(p) => {
                c.place = p;
                true
            }
            None => false,
        }
    });
    // A total order (the entity index last): the unstable sort, which allocates nothing,
    // gives the one order there is.
    changes.sort_unstable_by(order);
    let mut group = 0;
    for j in 0..changes.len() {
        let x = changes[j];
        let same = |y: &Change| {
            (y.place.road, y.lane, y.place.direction) == (x.place.road, x.lane, x.place.direction)
        };
        if !same(&changes[group]) {
            group = j;
        }
        let Some(view) = world.view(x.place.entity) else {
            continue;
        };
        let Some(model) = drivers.get_mut(x.model) else {
            continue;
        };
        let p = &x.place;
        let entity_id = view.entity().id;
        // The changes taken before it into the lane, from either side (module doc: SUMO's
        // hopped vehicle is the next candidate's leader there, whichever lane it came from).
        let earlier = changes[group..j]
            .iter()
            .filter(|y| y.taken)
            .filter_map(|y| {
                let e = world.entities.get(y.place.entity)?;
                let fp = world.index.footprint(e.id)?;
                Some(next_to(
                    p.s_range,
                    y.place.s_range,
                    p.direction,
                    e.id,
                    fp.speed_along(p.direction),
                ))
            });
        // The changes under way into the lane from the lane beyond it, and from the lane the
        // changer leaves (its box still there, not yet in the lane's index).
        let beyond = lane_shift(x.lane, if p.left { 1 } else { -1 }, p.direction);
        let track_s = world
            .index
            .input(p.entity)
            .and_then(|i| i.track.as_ref())
            .map_or(Real::NAN, |t| t.s);
        let horizon = view.horizon();
        let under_way = [beyond, p.from]
            .into_iter()
            .flat_map(|from| {
                world
                    .network
                    .lane_handle_on(p.road, from, track_s)
                    .into_iter()
                    .map(move |h| (h, from))
            })
            .flat_map(|(h, from)| {
                world
                    .index
                    .overlapping(
                        h,
                        (p.s_range.0 - horizon, p.s_range.1 + horizon),
                        entity_id,
                        None,
                    )
                    .map(move |id| (id, from))
            })
            .filter_map(|(id, from)| {
                let t = world.index.input(id.index())?.track?;
                let fp = world.index.footprint(id)?;
                (t.road == p.road
                    && fp.handle.road == p.road.0
                    && t.lane_id == x.lane
                    && t.blend_from == Some(from))
                .then(|| {
                    next_to(
                        p.s_range,
                        fp.s_range,
                        p.direction,
                        id,
                        fp.speed_along(p.direction),
                    )
                })
            });
        let conflict = earlier
            .chain(under_way)
            .any(|next| !model.gap_safe(&view, next));
        if conflict && model.yield_change() {
            changes[j].taken = false;
            if let Some((_, m)) = merged.get_mut(x.at) {
                m.lateral = None;
            }
        }
    }
    changes.clear();
}
