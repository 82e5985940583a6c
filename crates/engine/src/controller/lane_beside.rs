//! The lanes beside an entity's lane as far as the road decides them (OpenDRIVE 1.8 §11 lanes,
//! §11.8 road marks; issue 31): on each side, whether the lane there is a drivable lane of the
//! road at the entity's s driven the same way, its handle, whether it lies towards the keep
//! side of the road's traffic rule, and whether the road mark between lets the entity cross.
//! [`ControllerView::beside`](super::view::ControllerView::beside) asks it each time; the
//! `mobil` controller keeps the answer ([`KeptRoad`]) with the stretch of road over which it
//! holds, and asks again only when its entity has left that stretch or its lane.
//!
//! **Why.** The answer needs the road, its lane section at s (a search), the lane beside's
//! type, both lanes' driving directions and the road mark in effect at s on the border (a
//! walk over the border lane's records): a chain of dependent loads, per side, per vehicle
//! and step. In `mobil` at 1,000 vehicles `beside` and `permits_lane_change` were 5.6 % and
//! 1.1 % of the run's samples (`perf record`, issue 31), for answers that change only where a
//! lane section or a mark record starts.
//!
//! **The same answer.** It depends on the track's road, lane, direction of travel and own
//! lane handle (the key), on the lane section at s, and on the mark record in effect at ds =
//! s − the section's start on each side's border; nothing else. The section is the same while
//! [`opendrive::SectionStretch::holds`] at s (the test `lane_section_index` makes, at the same
//! s), the record while [`opendrive::MarkStretch::holds`] at ds (ds computed as the direct
//! query computes it, from the same section start). So a kept answer is used only where the
//! direct query would give it, bit for bit; anywhere else (a NaN s included) it is asked
//! again. The road network of a run does not change.

use opendrive::{
    Direction, LaneHandle, Real, RoadHandle, RoadNetwork, SectionStretch, TrafficRule,
};

use crate::store::driver_inputs::TrackInput;
use crate::store::lane_index::LaneIndex;
use crate::world::lanes::lane_shift;

/// Which side of the direction of travel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// Left of the direction of travel.
    Left,
    /// Right of it.
    Right,
}

/// What the road says of the lane on one side (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RoadBeside {
    /// The lane's id on the entity's road.
    pub lane: i32,
    /// Its handle at the entity's s.
    pub handle: LaneHandle,
    /// It lies towards the keep side of the road's traffic rule.
    pub toward_keep_side: bool,
    /// The road mark between lets the entity cross towards it.
    pub crossing_permitted: bool,
}

/// One side's answer and the stretch [from, to) of ds over which its road mark record holds
/// (a side without a lane beside: every ds). Kept small: the controllers hold it by value.
#[derive(Debug, Clone, Copy, PartialEq)]
struct SideAnswer {
    from: Real,
    to: Real,
    /// The lane beside, when `found`.
    lane: i32,
    found: bool,
    toward_keep_side: bool,
    crossing_permitted: bool,
}

impl SideAnswer {
    /// No lane beside, at every ds.
    const NONE: SideAnswer = SideAnswer {
        from: Real::NEG_INFINITY,
        to: Real::INFINITY,
        lane: 0,
        found: false,
        toward_keep_side: false,
        crossing_permitted: false,
    };
}

/// The question an answer was asked for: the track's road, lane, direction of travel and
/// own lane handle.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Asked {
    road: RoadHandle,
    lane_id: i32,
    direction: Direction,
    own: Option<LaneHandle>,
}

impl Asked {
    #[inline]
    fn of(track: &TrackInput) -> Self {
        Asked {
            road: track.road,
            lane_id: track.lane_id,
            direction: track.direction,
            own: track.own,
        }
    }
}

/// The handle of `lane` of `road` in section `section`: the section holding a lane at
/// s is the section at s when that section has the lane (`Road::lane_section_index_holding`),
/// as a drivable lane of it has, so this is the handle `RoadNetwork::lane_handle_on` gives
/// (issue 31, step 9).
fn handle(road: RoadHandle, section: usize, lane: i32) -> LaneHandle {
    LaneHandle {
        road: road.0,
        section: section as u32,
        lane,
    }
}

/// The answers of both sides for one track with the stretch they hold over (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct KeptRoad {
    asked: Asked,
    section: SectionStretch,
    /// The section's start s (ds = s − this, as the direct query computes it).
    section_s: Real,
    /// Left, right.
    sides: [SideAnswer; 2],
    /// The lane index's slot of each side's lane ([`LaneIndex::slot`], left, right), where
    /// its entries are: a function of the lane's handle and the network, as the handle is of
    /// the question, so it holds wherever the answer does.
    slots: [Option<u32>; 2],
}

impl KeptRoad {
    /// The answers for `track`, asked of the road, with the slots of their lanes in `index`.
    pub fn ask(network: &RoadNetwork, index: &LaneIndex, track: &TrackInput) -> Self {
        let road = network.road_at(track.road);
        let section = road.lane_section_stretch(track.s);
        let ls = &road.lane_sections[section.index];
        let keep = match road.rule {
            TrafficRule::LeftHand => Side::Left,
            _ => Side::Right,
        };
        let ds = track.s - ls.s;
        let side = |side: Side| {
            let n = match side {
                Side::Left => 1,
                Side::Right => -1,
            };
            let lane = lane_shift(track.lane_id, n, track.direction);
            let drivable = ls.lane(lane).is_some_and(|l| l.lane_type.is_drivable());
            let Some(own) = track.own.filter(|_| drivable) else {
                return SideAnswer::NONE;
            };
            if network.driving_direction(handle(track.road, section.index, lane))
                != network.driving_direction(own)
            {
                return SideAnswer::NONE;
            }
            let mark = ls.lane_change_stretch(track.lane_id, lane, ds);
            SideAnswer {
                from: mark.from,
                to: mark.to,
                lane,
                found: true,
                toward_keep_side: side == keep,
                crossing_permitted: mark.permitted,
            }
        };
        let sides = [side(Side::Left), side(Side::Right)];
        let slot = |a: &SideAnswer| {
            let h = handle(track.road, section.index, a.lane);
            a.found
                .then(|| index.slot(h).and_then(|k| u32::try_from(k).ok()))
                .flatten()
        };
        KeptRoad {
            asked: Asked::of(track),
            section,
            section_s: ls.s,
            slots: [slot(&sides[0]), slot(&sides[1])],
            sides,
        }
    }

    /// Whether the answers hold for `track`: the same question, its s in the section's
    /// stretch and its ds in both marks' (module doc).
    #[inline]
    pub fn holds(&self, track: &TrackInput) -> bool {
        let ds = track.s - self.section_s;
        let mark = |a: &SideAnswer| a.from <= ds && ds < a.to;
        self.asked == Asked::of(track)
            && self.section.holds(track.s)
            && mark(&self.sides[0])
            && mark(&self.sides[1])
    }

    /// The answer on `side`: the lane there, or `None` when there is no drivable lane driven
    /// the same way.
    #[inline]
    pub fn side(&self, side: Side) -> Option<RoadBeside> {
        let a = &self.sides[match side {
            Side::Left => 0,
            Side::Right => 1,
        }];
        a.found.then(|| RoadBeside {
            lane: a.lane,
            handle: handle(self.asked.road, self.section.index, a.lane),
            toward_keep_side: a.toward_keep_side,
            crossing_permitted: a.crossing_permitted,
        })
    }

    /// The lane index's slot of the lane on `side` ([`LaneIndex::slot`] of its handle), when
    /// there is one.
    #[inline]
    pub fn slot(&self, side: Side) -> Option<usize> {
        self.slots[match side {
            Side::Left => 0,
            Side::Right => 1,
        }]
        .map(|k| k as usize)
    }

    /// The answers for `track`: `kept`'s when they hold, else asked of the road and kept.
    #[inline]
    pub fn for_track<'k>(
        kept: &'k mut Option<KeptRoad>,
        network: &RoadNetwork,
        index: &LaneIndex,
        track: &TrackInput,
    ) -> &'k KeptRoad {
        // By reference: `is_some_and` on the `Option` itself copied the kept answers (issue
        // 31).
        if !kept.as_ref().is_some_and(|k| k.holds(track)) {
            *kept = None;
        }
        kept.get_or_insert_with(|| Self::ask_cold(network, index, track))
    }

    /// [`ask`](Self::ask) out of line: the kept answers' common case is the test alone.
    #[inline(never)]
    fn ask_cold(network: &RoadNetwork, index: &LaneIndex, track: &TrackInput) -> Self {
        Self::ask(network, index, track)
    }
}

/// The kept answers of a `mobil` controller (module doc). A cache, not the controller's
/// state: its `Debug` does not show it, so a controller that kept answers prints as one
/// that asked the road each time.
#[derive(Clone, Copy, Default)]
pub(crate) struct KeptBeside(pub Option<KeptRoad>);

impl std::fmt::Debug for KeptBeside {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("KeptBeside")
    }
}
