//! The lanes beside an entity's lane as far as the road decides them (OpenDRIVE 1.8 §11 lanes,
//! §11.8 road marks; issue 31): on each side, whether the lane there is a drivable lane of the
//! road at the entity's s driven the same way, its handle, whether it lies towards the keep
//! side of the road's traffic rule, and whether the road mark between lets the entity cross.
//! [`ControllerView::beside`](super::view::ControllerView::beside) asks it each time; the
//! `mobil` controller keeps the answer ([`KeptRoad`]) with the range of s over which it
//! holds, and asks again only when its entity has left that range or its lane.
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
//! query computes it, from the same section start). So an answer holds wherever the key is
//! the same and these three stretch tests hold; the road network of a run does not change.
//!
//! **One range of s.** For a fixed key the three stretch tests are a test of s alone, and
//! each is of the form a ≤ f(s) or f(s) < b with f(s) = s + `LENGTH_EPSILON` or s − the
//! section's start: rounding to nearest is monotone, so f never decreases as s grows, and
//! each test holds on an interval of the doubles (a ≤ f(s) from some s on, f(s) < b up to
//! some s). Their conjunction holds on the intersection, one interval: at every s between two
//! doubles at which it holds. When the answer is asked, the ends [lo, hi] of that interval
//! about the s asked at are found from the stretches' ends worked back to s (a rounding or
//! two from the true ends) and moved a double at a time until the test holds at each and
//! fails at the double beyond (`edge`); only the key and [lo, hi] are kept, and the test the
//! `mobil` controller makes per step ([`KeptRoad::within`]) is the key and lo ≤ s ≤ hi,
//! inline. The key is kept as the number the driver-input row gives it
//! ([`TrackInput::question`]: the own lane's slot and the direction, one-to-one with the
//! four fields where the own lane has a slot, store/driver_inputs.rs "The question's
//! number"), so it is one comparison; a track whose own lane has no slot has none, and its
//! answer is asked each time. So a kept answer is used only where the direct query would give it, bit for bit;
//! anywhere else (a NaN s included) it is asked again. Where an end is not found in a few
//! doubles the range stops short of it (at worst at the s asked at), never beyond where the
//! test holds: the answer is then asked again sooner, the same answer (issue 31: the three
//! tests and the key field by field, out of line, were ~52 instructions per `mobil`
//! entity-step; the test `the_kept_range_of_s_is_the_stretches_test_at_their_ends` finds
//! every end exact on four corpus roads; the key packed into three words was 26 of them,
//! the question's number `the_question_number_tells_every_question_apart`).

use opendrive::{LaneHandle, Real, RoadHandle, RoadNetwork, SectionStretch, TrafficRule};

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

/// One side's answer. Kept small: the controllers hold it by value.
#[derive(Debug, Clone, Copy, PartialEq)]
struct SideAnswer {
    /// The lane beside, when `found`.
    lane: i32,
    found: bool,
    toward_keep_side: bool,
    crossing_permitted: bool,
}

impl SideAnswer {
    /// No lane beside.
    const NONE: SideAnswer = SideAnswer {
        lane: 0,
        found: false,
        toward_keep_side: false,
        crossing_permitted: false,
    };
}

/// The stretches over which an answer holds (module doc): the section's, the section's start
/// s (ds = s − this, as the direct query computes it) and each side's mark's [from, to) of ds
/// (a side without a lane beside: every ds). Worked out when the answer is asked, to find
/// its range of s; not kept.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Stretches {
    section: SectionStretch,
    section_s: Real,
    /// Left, right.
    marks: [(Real, Real); 2],
}

impl Stretches {
    /// The stretches' test at `s`: s in the section's stretch and s − the section's start in
    /// both marks' (module doc).
    fn hold_at(&self, s: Real) -> bool {
        let ds = s - self.section_s;
        let mark = |&(from, to): &(Real, Real)| from <= ds && ds < to;
        self.section.holds(s) && mark(&self.marks[0]) && mark(&self.marks[1])
    }

    /// The range [lo, hi] of s over which the stretches hold, found about `s` (module doc
    /// "One range of s"); empty (lo > hi) where they do not hold at `s` (a NaN s).
    fn range(&self, s: Real) -> (Real, Real) {
        let holds = |x: Real| self.hold_at(x);
        if !holds(s) {
            return (Real::INFINITY, Real::NEG_INFINITY);
        }
        // Each stretch's ends as s: the section's tested at s + LENGTH_EPSILON, the marks'
        // at s − the section's start.
        let e = opendrive::LENGTH_EPSILON;
        let [l, r] = self.marks;
        let from = (self.section.from - e)
            .max(self.section_s + l.0)
            .max(self.section_s + r.0);
        let to = (self.section.to - e)
            .min(self.section_s + l.1)
            .min(self.section_s + r.1);
        (edge(holds, s, from, false), edge(holds, s, to, true))
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

/// The answers of both sides for one track with the range of s over which they hold
/// (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct KeptRoad {
    /// The number of the question asked ([`TrackInput::numbered`]): the track's road, lane,
    /// direction of travel and own lane, one-to-one (store/driver_inputs.rs "The question's
    /// number"); [`NO_QUESTION`](crate::store::driver_inputs::NO_QUESTION) where the track's
    /// own lane had no slot, which no track's question is (the answer is then used for no
    /// track).
    question: u64,
    /// The track's road.
    road: RoadHandle,
    /// The index of the section at the track's s.
    section: u32,
    /// Left, right.
    sides: [SideAnswer; 2],
    /// The lane index's slot of each side's lane ([`LaneIndex::slot`], left, right), where
    /// its entries are: a function of the lane's handle and the network, as the handle is of
    /// the question, so it holds wherever the answer does.
    slots: [Option<u32>; 2],
    /// The least and greatest s at which the stretches' test holds (module doc "One range of
    /// s"; an empty range, lo > hi, where none was found).
    lo: Real,
    hi: Real,
}

/// How many doubles [`edge`] moves an end at most: the ends worked back from the stretches
/// are a rounding or two from the true ones.
const EDGE_STEPS: u32 = 8;

/// The double next to `x` upwards (`up`) or downwards (std's `next_up` / `next_down`): `x`
/// itself at the infinity that way and at a NaN.
fn adjacent(x: Real, up: bool) -> Real {
    if up {
        x.next_up()
    } else {
        x.next_down()
    }
}

/// The end of the interval of doubles where `holds` is true that lies upwards (`up`) or
/// downwards from `inside`, at which it holds, found from `guess`: from the guess moved
/// towards `inside` until `holds` is true (at most [`EDGE_STEPS`] doubles; else `inside`
/// itself), then away while it holds a double further (at most as many). A double where
/// `holds` is true, between `inside` and the true end, both included (module doc "One range
/// of s": the set where it holds is an interval).
fn edge(holds: impl Fn(Real) -> bool, inside: Real, guess: Real, up: bool) -> Real {
    // A guess on the wrong side of `inside` (or NaN) starts at `inside`.
    let mut x = if (up && guess >= inside) || (!up && guess <= inside) {
        guess
    } else {
        inside
    };
    let mut n = 0;
    while !holds(x) {
        n += 1;
        if n > EDGE_STEPS {
            return inside;
        }
        x = adjacent(x, !up);
    }
    for _ in 0..EDGE_STEPS {
        let further = adjacent(x, up);
        if further == x || !holds(further) {
            break;
        }
        x = further;
    }
    x
}

impl KeptRoad {
    /// The answers for `track`, asked of the road, with the slots of their lanes in `index`.
    pub fn ask(network: &RoadNetwork, index: &LaneIndex, track: &TrackInput) -> Self {
        Self::ask_with_stretches(network, index, track).0
    }

    /// [`ask`](Self::ask) with the stretches the answers hold over.
    fn ask_with_stretches(
        network: &RoadNetwork,
        index: &LaneIndex,
        track: &TrackInput,
    ) -> (Self, Stretches) {
        let road = network.road_at(track.road);
        let section = road.lane_section_stretch(track.s);
        let ls = &road.lane_sections[section.index];
        let keep = match road.rule {
            TrafficRule::LeftHand => Side::Left,
            _ => Side::Right,
        };
        let ds = track.s - ls.s;
        let every_ds = (Real::NEG_INFINITY, Real::INFINITY);
        let side = |side: Side| {
            let n = match side {
                Side::Left => 1,
                Side::Right => -1,
            };
            let lane = lane_shift(track.lane_id, n, track.direction);
            let drivable = ls.lane(lane).is_some_and(|l| l.lane_type.is_drivable());
            let Some(own) = track.own.filter(|_| drivable) else {
                return (SideAnswer::NONE, every_ds);
            };
            if network.driving_direction(handle(track.road, section.index, lane))
                != network.driving_direction(own)
            {
                return (SideAnswer::NONE, every_ds);
            }
            let mark = ls.lane_change_stretch(track.lane_id, lane, ds);
            let answer = SideAnswer {
                lane,
                found: true,
                toward_keep_side: side == keep,
                crossing_permitted: mark.permitted,
            };
            (answer, (mark.from, mark.to))
        };
        let ((left, left_mark), (right, right_mark)) = (side(Side::Left), side(Side::Right));
        let stretches = Stretches {
            section,
            section_s: ls.s,
            marks: [left_mark, right_mark],
        };
        let slot = |a: &SideAnswer| {
            let h = handle(track.road, section.index, a.lane);
            a.found
                .then(|| index.slot(h).and_then(|k| u32::try_from(k).ok()))
                .flatten()
        };
        let (lo, hi) = stretches.range(track.s);
        let kept = KeptRoad {
            question: track.numbered(),
            road: track.road,
            // As `handle` numbers it.
            section: section.index as u32,
            slots: [slot(&left), slot(&right)],
            sides: [left, right],
            lo,
            hi,
        };
        (kept, stretches)
    }

    /// Whether the answers hold for `track`, decided by the question's number and the kept
    /// range of s: the same question (one comparison, store/driver_inputs.rs "The
    /// question's number") and lo ≤ s ≤ hi. True exactly where the question is the same,
    /// the track's own lane has a slot and the stretches' test holds at s (module doc "One
    /// range of s"), except near an end not found, where it is false and the answer is asked
    /// again (the same answer).
    #[inline(always)]
    pub fn within(&self, track: &TrackInput) -> bool {
        self.question == track.question() && self.lo <= track.s && track.s <= self.hi
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
            handle: handle(self.road, self.section as usize, a.lane),
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
        if !kept.as_ref().is_some_and(|k| k.within(track)) {
            *kept = None;
        }
        kept.get_or_insert_with(|| Self::ask_cold(network, index, track))
    }

    /// [`ask`](Self::ask) out of line: the kept answers' common case is the test alone.
    #[cold]
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::store::driver_inputs::{NO_QUESTION, NO_SLOT};
    use opendrive::Direction;
    use std::sync::Arc;

    /// The road network of esmini's corpus file `name` (`shared/corpus/esmini/xodr`).
    pub(crate) fn esmini_road(name: &str) -> RoadNetwork {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../../shared/corpus/esmini/xodr")
            .join(name);
        RoadNetwork::from_file(&path).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The ids of every lane of `road` but the centre lane, over all its sections.
    pub(crate) fn lane_ids(road: &opendrive::Road) -> std::collections::BTreeSet<i32> {
        road.lane_sections
            .iter()
            .flat_map(|ls| ls.lanes().map(|l| l.id))
            .filter(|&id| id != 0)
            .collect()
    }

    /// The doubles next to a few numbers, by hand: 1 + 2⁻⁵² above 1 and 1 − 2⁻⁵³ below it
    /// (the spacing halves below a power of two), the least subnormal 2⁻¹⁰⁷⁴ either side of
    /// both zeros, the largest finite double next to the infinities, and no move past an
    /// infinity or from a NaN.
    #[test]
    fn adjacent_doubles_by_hand() {
        assert_eq!(adjacent(1.0, true), 1.0 + 2f64.powi(-52));
        assert_eq!(adjacent(1.0, false), 1.0 - 2f64.powi(-53));
        assert_eq!(adjacent(-1.0, false), -1.0 - 2f64.powi(-52));
        // 2⁻¹⁰⁷⁴ as a product of two normal doubles (`powi(-1074)` underflows on the way).
        let tiny = 2f64.powi(-537) * 2f64.powi(-537);
        assert_eq!(tiny.to_bits(), 1);
        for zero in [0.0, -0.0] {
            assert_eq!(adjacent(zero, true), tiny);
            assert_eq!(adjacent(zero, false), -tiny);
        }
        assert_eq!(adjacent(tiny, false), 0.0);
        assert_eq!(adjacent(Real::NEG_INFINITY, true), -Real::MAX);
        assert_eq!(adjacent(Real::INFINITY, false), Real::MAX);
        assert_eq!(adjacent(Real::MAX, true), Real::INFINITY);
        assert_eq!(adjacent(Real::INFINITY, true), Real::INFINITY);
        assert_eq!(adjacent(Real::NEG_INFINITY, false), Real::NEG_INFINITY);
        assert!(adjacent(Real::NAN, true).is_nan());
    }

    /// `edge` on a test whose interval is known: x ≥ 2 and x < 3 holds on [2, 3 − 2⁻⁵¹]
    /// (the spacing of the doubles in [2, 4) is 2⁻⁵¹). Found from guesses a few doubles off
    /// either way, from the wrong side of the inside point and from a NaN (both from `inside`
    /// then), and shrunk to `inside` where the end is farther than `EDGE_STEPS` doubles away
    /// from a guess outside the interval.
    #[test]
    fn edge_finds_the_ends_of_a_known_interval() {
        let holds = |x: Real| (2.0..3.0).contains(&x);
        let below_3 = 3.0 - 2f64.powi(-51);
        let nudge = |x: Real, n: i32, up: bool| (0..n).fold(x, |x, _| adjacent(x, up));
        for n in 0..=3 {
            assert_eq!(edge(holds, 2.5, nudge(2.0, n, true), false), 2.0);
            assert_eq!(edge(holds, 2.5, nudge(2.0, n, false), false), 2.0);
            assert_eq!(edge(holds, 2.5, nudge(3.0, n, true), true), below_3);
            assert_eq!(edge(holds, 2.5, nudge(3.0, n, false), true), below_3);
        }
        // A guess above inside for the lower end: from inside, at most 8 doubles down.
        assert_eq!(edge(holds, 2.5, 2.7, false), nudge(2.5, 8, false));
        // From a NaN guess: from inside 2.5, whence the end 3 is 2⁵⁰ doubles away; the steps
        // stop at 2.5 + 8·2⁻⁵¹.
        let from_nan = edge(holds, 2.5, Real::NAN, true);
        assert_eq!(from_nan, 2.5 + 8.0 * 2f64.powi(-51));
        assert_eq!(from_nan, nudge(2.5, 8, true));
        assert_eq!(
            edge(holds, 2.5, 3.5, true),
            2.5,
            "a guess far outside: inside"
        );
    }

    /// The kept range of s decides exactly where the stretches' test holds: on the four
    /// corpus roads [`ROADS`], for a track in every lane and direction of every road (its
    /// own lane's slot the index's, as the driver-input row keeps it), asked at each section and mark start and at the doubles up
    /// to three from it and from where s + `LENGTH_EPSILON` reaches it (the section search's
    /// test), and at the road's ends and beyond them: `within` is `holds` at each of those
    /// points and at the kept range's ends and the doubles next to them; each range holds
    /// the s it was asked at, and its ends are the stretches' true ends (the test fails a
    /// double beyond each finite end). So the inline test uses the kept answer exactly where
    /// the stretches' test would. A track whose own lane has no slot (no lane at s) uses
    /// its answer nowhere, not even at the s it was asked at.
    #[test]
    fn the_kept_range_of_s_is_the_stretches_test_at_their_ends() {
        let (mut asked, mut inside, mut outside, mut finite_ends) = (0, 0, 0, 0);
        let mut unnumbered = 0;
        for name in ROADS {
            let (net, index) = road_numbered(name);
            for (r, road) in net.roads().iter().enumerate() {
                let mut starts = vec![0.0, road.length];
                for ls in &road.lane_sections {
                    starts.push(ls.s);
                    let marks = ls.lanes().flat_map(|l| l.road_marks.iter());
                    starts.extend(marks.map(|m| ls.s + m.s_offset));
                }
                let mut at = vec![-1.0, road.length + 1.0];
                for b in starts {
                    for c in [b, b - opendrive::LENGTH_EPSILON] {
                        at.push(c);
                        for up in [false, true] {
                            let mut x = c;
                            for _ in 0..3 {
                                x = adjacent(x, up);
                                at.push(x);
                            }
                        }
                    }
                }
                at.sort_by(Real::total_cmp);
                at.dedup();
                let ids = lane_ids(road);
                let road_handle = RoadHandle(r as u32);
                for &lane_id in &ids {
                    for direction in [Direction::Forward, Direction::Backward] {
                        let track_at = |s: Real, own: Option<LaneHandle>| {
                            track_with(&index, (road_handle, lane_id, s, direction), own)
                        };
                        // The stretches' test in full: the same question, the three
                        // stretches.
                        let holds = |k: &KeptRoad, st: &Stretches, t: &TrackInput| {
                            k.question == t.numbered() && st.hold_at(t.s)
                        };
                        let mut last: Option<(KeptRoad, Stretches)> = None;
                        for &s in &at {
                            let track = track_at(s, net.lane_handle_on(road_handle, lane_id, s));
                            // A new answer only where the last one's stretches end: each range
                            // is probed once.
                            if last.is_some_and(|(k, st)| holds(&k, &st, &track)) {
                                continue;
                            }
                            let (k, st) = KeptRoad::ask_with_stretches(&net, &index, &track);
                            asked += 1;
                            if track.own_slot == NO_SLOT {
                                // No number: used for no track, itself included.
                                assert!(!k.within(&track) && k.question == NO_QUESTION);
                                unnumbered += 1;
                                continue;
                            }
                            assert!(
                                holds(&k, &st, &track) && k.within(&track),
                                "{name} road {} s {s}",
                                road.id
                            );
                            let mut probes = at.clone();
                            for end in [k.lo, k.hi] {
                                probes.extend([adjacent(end, false), end, adjacent(end, true)]);
                                if end.is_finite() {
                                    finite_ends += 1;
                                }
                            }
                            for p in probes {
                                let probe = track_at(p, track.own);
                                let holds = holds(&k, &st, &probe);
                                assert_eq!(
                                    k.within(&probe),
                                    holds,
                                    "{name} road {} lane {lane_id} {direction:?} asked at {s}, s {p}, range [{}, {}]",
                                    road.id,
                                    k.lo,
                                    k.hi
                                );
                                if holds {
                                    inside += 1;
                                } else {
                                    outside += 1;
                                }
                            }
                            last = Some((k, st));
                        }
                    }
                }
            }
        }
        assert!(
            asked > 700
                && finite_ends > 1_000
                && inside > 25_000
                && outside > 15_000
                && unnumbered > 0,
            "{asked} asked, {finite_ends} finite ends, {inside} probes inside, {outside} \
             outside, {unnumbered} without a number"
        );
    }

    /// The corpus roads the kept answers are tested on: two_plus_one (five lane sections,
    /// lanes appearing and ending), straight_500m_roadmarks (the mark type changing every
    /// 50–100 m), multi_intersections and tunnels (junctions, several sections and marks).
    const ROADS: [&str; 4] = [
        "two_plus_one.xodr",
        "straight_500m_roadmarks.xodr",
        "multi_intersections.xodr",
        "tunnels.xodr",
    ];

    /// The network of corpus file `name` and an index of no entity on it: the network's lane
    /// numbering, for the own lanes' slots ([`slot_of`]).
    fn road_numbered(name: &str) -> (Arc<RoadNetwork>, LaneIndex) {
        let net = Arc::new(esmini_road(name));
        let index = LaneIndex::build(&net, &[]);
        (net, index)
    }

    /// Where a track is: its road, lane, s and direction of travel.
    pub(crate) type At = (RoadHandle, i32, Real, Direction);

    /// The track input at `at` with own lane `own`, numbered in `index` as the driver-input
    /// row numbers it ([`slot_of`]).
    pub(crate) fn track_with(index: &LaneIndex, at: At, own: Option<LaneHandle>) -> TrackInput {
        let (road, lane_id, s, direction) = at;
        TrackInput {
            road,
            lane_id,
            s,
            direction,
            blend_from: None,
            own,
            own_slot: slot_of(index, own),
        }
    }

    /// The track input at `at` on `net`, its own lane looked up there and numbered in `index`
    /// as the driver-input row does it.
    pub(crate) fn track_in(net: &RoadNetwork, index: &LaneIndex, at: At) -> TrackInput {
        let (road, lane_id, s, _) = at;
        track_with(index, at, net.lane_handle_on(road, lane_id, s))
    }

    /// The slot of `own` in `index`'s numbering as the driver-input row keeps it
    /// (store/driver_inputs.rs `slot_of`).
    fn slot_of(index: &LaneIndex, own: Option<LaneHandle>) -> u32 {
        own.and_then(|h| index.slot(h))
            .map_or(NO_SLOT, |k| u32::try_from(k).unwrap_or(NO_SLOT))
    }

    /// The question's number (store/driver_inputs.rs "The question's number") tells every
    /// two questions apart and only those: on five corpus networks ([`ROADS`] and
    /// fabriksgatan, a town's junctions), for every road, every lane
    /// id of any of its sections (the centre lane included) and both directions, asked at each
    /// section's start and middle and at the road's ends (the own lane's handle looked up
    /// there as the row does), two tracks whose own lanes have slots have the same number
    /// exactly where road, lane, direction and own handle are the same; so a change of any of
    /// the four changes the number. A track without a slot (no own lane, the centre lane, a
    /// row made outside an index) keeps the answer under [`NO_QUESTION`], which no track's
    /// number is. By hand on two_plus_one's first road (sections at s 0: lanes −1 | 1, 2; at
    /// 125: −1, −2 | 1, 2; at 175: −1, −2 | 1; store/lane_slots.rs numbers the right lanes
    /// first): lane −1 at s 0 is slot 0, lane 2 slot 1 + 1 = 2, lane 1 at s 200 slot 3 + 4 +
    /// 2 = 9; forward these are questions 0, 2 and 9, backward 2³² more.
    #[test]
    fn the_question_number_tells_every_question_apart() {
        use std::collections::HashMap;
        let (mut numbered, mut unnumbered, mut changes) = (0usize, 0usize, 0usize);
        for name in ROADS.into_iter().chain(["fabriksgatan.xodr"]) {
            let (net, index) = road_numbered(name);
            let mut by_number: HashMap<u64, (RoadHandle, i32, Direction, Option<LaneHandle>)> =
                HashMap::new();
            let mut tracks = Vec::new();
            for (r, road) in net.roads().iter().enumerate() {
                let road_handle = RoadHandle(r as u32);
                let mut at = vec![0.0, road.length];
                for (k, ls) in road.lane_sections.iter().enumerate() {
                    let end = road.lane_sections.get(k + 1).map_or(road.length, |n| n.s);
                    at.extend([ls.s, 0.5 * (ls.s + end)]);
                }
                let mut ids = lane_ids(road);
                ids.insert(0);
                for &lane_id in &ids {
                    for direction in [Direction::Forward, Direction::Backward] {
                        for &s in &at {
                            let at = (road_handle, lane_id, s, direction);
                            tracks.push(track_in(&net, &index, at));
                        }
                    }
                }
            }
            for t in &tracks {
                let fields = (t.road, t.lane_id, t.direction, t.own);
                if t.own_slot == NO_SLOT {
                    assert_eq!(t.numbered(), NO_QUESTION, "{name} {t:?}");
                    unnumbered += 1;
                    continue;
                }
                // The row's invariant the number rests on: the own lane is the track's lane.
                let own = t.own.expect("a slot is a lane's");
                assert_eq!((own.road, own.lane), (t.road.0, t.lane_id), "{name} {t:?}");
                assert_eq!(t.numbered(), t.question());
                assert!(t.question() < 1 << 33 && t.question() != NO_QUESTION);
                match by_number.insert(t.question(), fields) {
                    Some(other) => assert_eq!(other, fields, "{name}: one number, two questions"),
                    None => numbered += 1,
                }
            }
            // Every two numbered tracks: the same number exactly where the four fields are.
            let numbered_tracks: Vec<&TrackInput> =
                tracks.iter().filter(|t| t.own_slot != NO_SLOT).collect();
            for a in &numbered_tracks {
                for b in &numbered_tracks {
                    let fields = |t: &TrackInput| (t.road, t.lane_id, t.direction, t.own);
                    let same = fields(a) == fields(b);
                    assert_eq!(a.question() == b.question(), same, "{name} {a:?} {b:?}");
                    changes += usize::from(!same);
                }
            }
            if name == "two_plus_one.xodr" {
                let track = |lane_id, s, direction| {
                    track_in(&net, &index, (RoadHandle(0), lane_id, s, direction))
                };
                assert_eq!(track(-1, 0.0, Direction::Forward).question(), 0);
                assert_eq!(track(2, 0.0, Direction::Backward).question(), (1 << 32) + 2);
                assert_eq!(track(1, 200.0, Direction::Forward).question(), 9);
                assert_eq!(
                    track(1, 200.0, Direction::Backward).question(),
                    (1 << 32) + 9
                );
            }
        }
        assert!(
            numbered > 500 && unnumbered > 100 && changes > 1_000_000,
            "{numbered} numbers, {unnumbered} tracks without, {changes} pairs that differ"
        );
    }
}
