//! oscsim's marks (no XML form): what a state check (`scenario::StateCheck::mark`, written by
//! the OpenSCENARIO DSL runtime at the start of a phase that starts on a run-time condition,
//! ASAM OpenSCENARIO DSL 2.1 §8.9) notes on its actor, and the two conditions that measure from
//! it: `TraveledSinceMark` (the odometer's advance since the mark: `distance(d)` without a
//! duration) and `GapReachedSinceMark` (the actor has reached its place relative to another
//! entity from the side it was on at the mark: `position(time: t / neither, ahead_of/behind:
//! x, at: end)` without a duration; with `track: projected` x as projected from the mark on:
//! along its lane at the speed it had then). Both are false before the mark is noted, so they may
//! stand in any trigger. The places are measured as the check's `roads` (kept on the mark)
//! say (`position::RoadChain`): on a plan over several roads in the plan's s on any of its
//! roads, x projected along its lane across their joints; for an actor driving against s along
//! its direction of travel (u = L − s), so "ahead" and "behind" are its own.

use std::collections::HashMap;

use opendrive::{Real, RoadNetwork, RoadPosition};
use scenario::{PlanRoads, SpeedGap};

use crate::position::{EntityView, RoadChain};

/// What a state check noted on its actor.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Mark {
    /// The actor's odometer then (m).
    pub odometer: Real,
    /// The actor's road and lane id then (`None`: off every lane).
    pub lane: Option<(String, i32)>,
    /// With a gap: the actor's place error relative to the gap's entity then
    /// (the actor's s minus the entity's less the gap's offset, m).
    pub gap_error: Option<Real>,
    /// With a projected gap: the gap's entity as it was then, projected from then on.
    pub projection: Option<Projection>,
    /// The roads the check's gap is measured along, and the direction of travel (the check's
    /// `roads`).
    pub roads: PlanRoads,
}

/// The slot of a mark: marks are named in the scenario (`scenario::StateCheck::mark`, a
/// check's `travelled` and `lane_at_mark`, TraveledSinceMark, GapReachedSinceMark) and given
/// a slot each when the storyboard is built (`MarkIds`), so that noting and reading one is
/// an index, never a look-up by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct MarkId(pub u32);

/// The slots of the marks, by name: filled while the storyboard is built, each name given the
/// next slot the first time it is met (by the check that notes it or by what reads it).
#[derive(Debug, Clone, Default)]
pub(crate) struct MarkIds {
    ids: HashMap<String, MarkId>,
}

impl MarkIds {
    /// The slot of mark `name`, given now if it has none yet.
    pub(crate) fn id(&mut self, name: &str) -> MarkId {
        let next = MarkId(self.ids.len() as u32);
        *self.ids.entry(name.to_owned()).or_insert(next)
    }

    /// The slot of mark `name`, if it has one.
    pub(crate) fn get(&self, name: &str) -> Option<MarkId> {
        self.ids.get(name).copied()
    }

    /// The marks' store for a run: one empty slot per mark.
    pub(crate) fn store(&self) -> Marks {
        Marks {
            noted: vec![None; self.ids.len()],
        }
    }
}

/// The marks noted so far in a run, by slot (`None`: not noted yet).
#[derive(Debug, Clone, Default)]
pub(crate) struct Marks {
    noted: Vec<Option<Mark>>,
}

impl Marks {
    /// Mark `id`, if noted.
    pub(crate) fn get(&self, id: MarkId) -> Option<&Mark> {
        self.noted.get(id.0 as usize).and_then(Option::as_ref)
    }

    /// Notes `mark` in slot `id` (replacing what it held).
    pub(crate) fn note(&mut self, id: MarkId, mark: Mark) {
        if let Some(slot) = self.noted.get_mut(id.0 as usize) {
            *slot = Some(mark);
        }
    }
}

/// An entity projected from a moment on (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.3 `track:
/// projected`): along its lane at the speed it had then.
#[derive(Debug, Clone, PartialEq)]
pub struct Projection {
    /// Its road and lane then.
    pub road: String,
    /// Lane id.
    pub lane: i32,
    /// Its s then (m).
    pub s: Real,
    /// Its speed then (m/s).
    pub speed: Real,
    /// It drove along +s.
    pub forward: bool,
    /// The moment (s).
    pub time: Real,
}

impl Projection {
    /// Its place at `now` in `chain`'s measure (`None` where its lane ends first).
    pub(crate) fn s_at(&self, chain: RoadChain<'_>, now: Real) -> Option<Real> {
        let d = (self.speed * (now - self.time)).abs();
        let forward = self.forward == (self.speed >= 0.0);
        chain
            .s_at_lane_distance((&self.road, self.lane, self.s), d, forward)
            .ok()
    }
}

/// The actor's s minus the gap's entity's, less [`SpeedGap::offset`] at that entity's speed
/// `speed` (m), in `chain`'s measure (the plan's s, or u along the direction of travel
/// against s): 0 where the gap asks the actor to be, positive beyond. `None` when s is not comparable (on one road, the two on different roads; on a
/// chain, either off it).
pub(crate) fn place_error(
    chain: RoadChain<'_>,
    actor: &RoadPosition,
    other: &RoadPosition,
    speed: Real,
    gap: &SpeedGap,
) -> Option<Real> {
    let (a, x) = chain.pair(actor, other)?;
    Some(a - x - gap.offset(speed))
}

/// TraveledSinceMark: `e`'s odometer has advanced `value` m or more since `mark`.
pub(super) fn traveled_since(e: &EntityView<'_>, mark: Option<&Mark>, value: Real) -> bool {
    mark.is_some_and(|m| e.odometer - m.odometer >= value)
}

/// GapReachedSinceMark: `e`'s place error relative to `other` (or to its projection, if the
/// mark has one) is 0 or of the sign opposite to the one noted at `mark`.
pub(super) fn gap_reached_since(
    network: &RoadNetwork,
    now: Real,
    e: &EntityView<'_>,
    other: &EntityView<'_>,
    mark: Option<&Mark>,
    gap: &SpeedGap,
) -> bool {
    let (Some(m), Some(a)) = (mark, e.road_position) else {
        return false;
    };
    let Some(m0) = m.gap_error else {
        return false;
    };
    let chain = RoadChain::new(network, &m.roads);
    let now_error = match &m.projection {
        Some(p) => p
            .s_at(chain, now)
            .zip(match chain.is_chain() || a.road_id == p.road {
                true => chain.s_of(&a.road_id, a.s),
                false => None,
            })
            .map(|(s, at)| at - s - gap.offset(p.speed)),
        None => other
            .road_position
            .and_then(|x| place_error(chain, a, x, other.speed, gap)),
    };
    now_error.is_some_and(|now| now == 0.0 || (now > 0.0) != (m0 > 0.0))
}
