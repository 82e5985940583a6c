//! Two look-ups of the per-lane index (store/lane_index.rs) made cheap (issue 31): a dense
//! number for every lane of the network (OpenDRIVE 1.8 §11: a lane of one lane section), so the
//! index keeps its lanes in a vector instead of a hash map; and the lateral borders of every
//! lane of a road at s (§11.4 lane offset, §11.6 lane width), kept per road over the s-range
//! where they do not change.
//!
//! **Slots.** Lane `id` of section `k` of road `r` has slot `base(r, k) + position`, the
//! position counting the right lanes (−1, −2, …) first, then the left ones (1, 2, …); the
//! centre lane has none. A handle the network gave ([`RoadNetwork::lane_handle`]) names a lane
//! the section holds, so its slot is its own.
//!
//! **Borders.** [`LaneBorders::at`] gives the lanes of the road's section at s, each with
//! (min, max) of its two borders' t, as `Road::lane_span` gives them lane by lane. Where
//! `Road::constant_lanes` holds at s, every border is the same number at every s of its range
//! (opendrive query/constant_lanes.rs says why, bit for bit), so the list made at one s of the
//! range is the list at any other: it is kept per lane section with its range (one list per
//! road was replaced at every step where vehicles drove in two of its sections). Elsewhere the
//! list is made anew at each call. Each kept list has a generation number, new at every list made, so
//! that the index can tell the list an entity's lanes were taken from is still the one at its
//! s (store/lane_kept.rs).

use std::sync::Arc;

use opendrive::{LaneHandle, Real, Road, RoadHandle, RoadNetwork};

/// The slots of one lane section.
#[derive(Debug, Clone, Copy)]
struct SectionSlots {
    base: u32,
    right: u32,
    left: u32,
}

/// The dense numbering of one network's lanes (module doc).
#[derive(Debug, Clone)]
pub(crate) struct LaneSlots {
    /// The network numbered (held, so that no other network can take its address).
    network: Arc<RoadNetwork>,
    /// Per road: the index of its first section in `sections`.
    first_section: Vec<u32>,
    sections: Vec<SectionSlots>,
    len: usize,
}

impl LaneSlots {
    /// Numbers every lane of `network`.
    pub(crate) fn new(network: &Arc<RoadNetwork>) -> Self {
        let (mut first_section, mut sections, mut len) = (Vec::new(), Vec::new(), 0u32);
        for road in network.roads() {
            first_section.push(sections.len() as u32);
            for section in &road.lane_sections {
                let (right, left) = (section.right.len() as u32, section.left.len() as u32);
                sections.push(SectionSlots {
                    base: len,
                    right,
                    left,
                });
                len += right + left;
            }
        }
        LaneSlots {
            network: Arc::clone(network),
            first_section,
            sections,
            len: len as usize,
        }
    }

    /// Whether these are the slots of `network`.
    pub(crate) fn numbers(&self, network: &Arc<RoadNetwork>) -> bool {
        Arc::ptr_eq(&self.network, network)
    }

    /// How many slots there are.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// The slot of lane `h`; `None` for the centre lane and for ids the section does not have.
    #[inline]
    pub(crate) fn slot(&self, h: LaneHandle) -> Option<usize> {
        let first = *self.first_section.get(h.road as usize)?;
        let s = self.sections.get(first as usize + h.section as usize)?;
        let n = h.lane.unsigned_abs();
        let position = match h.lane {
            0 => return None,
            id if id < 0 => (n <= s.right).then_some(n - 1)?,
            _ => (n <= s.left).then_some(s.right + n - 1)?,
        };
        Some((s.base + position) as usize)
    }
}

/// A lane of a section at s with the smaller and larger t of its two borders.
pub(crate) type Borders = (i32, Real, Real);

/// The borders of one road's lanes over an s-range [lo, hi] where they stay the same numbers;
/// none kept ([`Kept::NONE`]) an empty range, lo > hi, that holds no s.
#[derive(Debug, Clone)]
struct Kept {
    lo: Real,
    hi: Real,
    lanes: Vec<Borders>,
    /// Which list this is: new at each list made ([`LaneBorders::at`]), counted modulo 2³²:
    /// an entity compares the generation of one step with the next, between which fewer than
    /// 2³² lists are made (at most one per entry made), so equal numbers are the same list.
    generation: u32,
}

impl Kept {
    /// No list kept: a range that holds no s (and no NaN: every comparison with one fails).
    const NONE: Kept = Kept {
        lo: Real::INFINITY,
        hi: Real::NEG_INFINITY,
        lanes: Vec::new(),
        generation: 0,
    };
}

/// Lane borders per lane section, kept where constant (module doc).
#[derive(Debug, Clone, Default)]
pub(crate) struct LaneBorders {
    /// By road index, then lane section index; [`Kept::NONE`] where no list is kept, so that
    /// [`holds`](LaneBorders::holds) tests the range alone (no `Option` to test first: it is
    /// inline on every entry of the lane index, issue 31).
    kept: Vec<Vec<Kept>>,
    /// The list made at the last call outside a constant range.
    fresh: Vec<Borders>,
    /// The generation of the last kept list made.
    generations: u32,
}

impl LaneBorders {
    /// Forgets every kept list (another network).
    pub(crate) fn clear(&mut self) {
        self.kept.clear();
    }

    /// The lanes (other than the centre lane) of `road`'s section at `s` with their borders
    /// there: `Road::lane_span` of each, as (id, min t, max t); none where s is off the road.
    /// With them the generation of the kept list they are ([`holds`](Self::holds)), `None`
    /// for a list made for this call alone. `section` is the section at s
    /// (`Road::lane_section_index`).
    pub(crate) fn at(
        &mut self,
        road: RoadHandle,
        section: u32,
        r: &Road,
        s: Real,
    ) -> (&[Borders], Option<u32>) {
        let (i, k) = (road.index(), section as usize);
        if self.kept.len() <= i {
            self.kept.resize_with(i + 1, Vec::new);
        }
        if self.kept[i].len() <= k {
            self.kept[i].resize(k + 1, Kept::NONE);
        }
        if self.holds(road, section, s).is_none() {
            match r.constant_lanes(s) {
                Some((lo, hi)) => {
                    let kept = &mut self.kept[i][k];
                    borders(r, s, &mut kept.lanes);
                    self.generations = self.generations.wrapping_add(1);
                    (kept.lo, kept.hi, kept.generation) = (lo, hi, self.generations);
                }
                None => {
                    borders(r, s, &mut self.fresh);
                    return (&self.fresh, None);
                }
            }
        }
        // The list that held s, or the one made just above (whose range, `constant_lanes`'
        // at s, holds s: opendrive road/constant_lanes.rs).
        let kept = &self.kept[i][k];
        (&kept.lanes[..], Some(kept.generation))
    }

    /// The generation of the list kept for `road`'s section `section` if its range holds
    /// `s`: [`at`](Self::at) gives that list there until another is made for the section.
    /// Always inline: the lane index asks it for every entity it enters (issue 31: out of
    /// line it was ~30 instructions per `mobil` entity-step with the call).
    #[inline(always)]
    pub(crate) fn holds(&self, road: RoadHandle, section: u32, s: Real) -> Option<u32> {
        let k = self.kept.get(road.index())?.get(section as usize)?;
        (k.lo <= s && s <= k.hi).then_some(k.generation)
    }
}

/// Writes the lanes of `road`'s section at `s` with their borders into `out` (emptied first):
/// in one pass over the section (`Road::lane_spans`, each span the one `Road::lane_span`
/// gives) where s lies on the road, else lane by lane as `Road::lane_span` answers.
pub(crate) fn borders(road: &Road, s: Real, out: &mut Vec<Borders>) {
    out.clear();
    let push = |out: &mut Vec<Borders>, id: i32, span: opendrive::LaneSpan| {
        out.push((id, span.inner.min(span.outer), span.inner.max(span.outer)));
    };
    if (0.0..=road.length).contains(&s) {
        // On the road `lane_spans` evaluates at s itself, in the section `lane_span` takes
        // for a lane of the section at s: the same numbers.
        let _ = road.lane_spans(s, |lane, span| {
            if lane.id != 0 {
                push(out, lane.id, span);
            }
        });
        return;
    }
    for lane in road.lane_section_at(s).lanes().filter(|l| l.id != 0) {
        if let Ok(span) = road.lane_span(lane.id, s) {
            push(out, lane.id, span);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Road "A": 100 m; section 1 (s 0..40) has lanes 1, −1, −2, section 2 (s 40..100) has
    /// lanes 2, 1, −1, whose width grows from 3 m by 0.01 m per m.
    fn network() -> Arc<RoadNetwork> {
        let w = |a: f64, b: f64| format!(r#"<width sOffset="0" a="{a}" b="{b}" c="0" d="0"/>"#);
        let lane = |id: i32, width: String| {
            format!(r#"<lane id="{id}" type="driving"><link/>{width}</lane>"#)
        };
        let xodr = format!(
            r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="A" junction="-1" length="100"><link/><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView><lanes>
<laneSection s="0"><left>{l1}</left><center><lane id="0" type="none"/></center><right>{r1}{r2}</right></laneSection>
<laneSection s="40"><left>{l2}{l1}</left><center><lane id="0" type="none"/></center><right>{r1w}</right></laneSection>
</lanes></road></OpenDRIVE>"#,
            l1 = lane(1, w(3.5, 0.0)),
            l2 = lane(2, w(3.5, 0.0)),
            r1 = lane(-1, w(3.5, 0.0)),
            r2 = lane(-2, w(3.5, 0.0)),
            r1w = lane(-1, w(3.0, 0.01)),
        );
        let net = RoadNetwork::from_str(&xodr, std::path::Path::new("slots.xodr")).expect("road");
        Arc::new(net)
    }

    /// Section 1: right lanes −1, −2 → slots 0, 1, left lane 1 → 2; section 2: −1 → 3,
    /// 1 → 4, 2 → 5; the centre lane and lane −2 of section 2 have none.
    #[test]
    fn every_lane_has_its_own_slot() {
        let net = network();
        let slots = LaneSlots::new(&net);
        assert_eq!(slots.len(), 6);
        let at = |section, lane| {
            slots.slot(LaneHandle {
                road: 0,
                section,
                lane,
            })
        };
        let got: Vec<_> = [(0, -1), (0, -2), (0, 1), (1, -1), (1, 1), (1, 2)]
            .iter()
            .map(|&(k, l)| at(k, l))
            .collect();
        assert_eq!(got, [0, 1, 2, 3, 4, 5].map(Some));
        assert_eq!(at(0, 0), None);
        assert_eq!(at(1, -2), None);
        assert_eq!(at(0, 3), None);
        assert!(slots.numbers(&net) && !slots.numbers(&network()));
    }

    /// The kept list and the fresh one equal `Road::lane_span` bit for bit, at each s of the
    /// constant section (kept once) and of the widening one (made at each call), and off the
    /// road's ends.
    #[test]
    fn kept_borders_are_the_lane_spans_bit_for_bit() {
        let net = network();
        let road = &net.roads()[0];
        let mut memo = LaneBorders::default();
        for s in [
            0.0,
            3.7,
            12.5,
            39.0,
            40.0,
            40.5,
            77.25,
            100.0,
            -1e-9,
            100.0 + 1e-9,
        ] {
            let got = memo
                .at(RoadHandle(0), road.lane_section_index(s) as u32, road, s)
                .0
                .to_vec();
            let section = road.lane_section_at(s);
            let expected: Vec<Borders> = section
                .lanes()
                .filter(|l| l.id != 0)
                .map(|l| {
                    let span = road.lane_span(l.id, s).expect("on the road");
                    (l.id, span.inner.min(span.outer), span.inner.max(span.outer))
                })
                .collect();
            let mut got_sorted = got.clone();
            got_sorted.sort_by_key(|b| b.0);
            let mut expected = expected;
            expected.sort_by_key(|b| b.0);
            let bits = |v: &[Borders]| -> Vec<(i32, u64, u64)> {
                v.iter()
                    .map(|&(id, lo, hi)| (id, lo.to_bits(), hi.to_bits()))
                    .collect()
            };
            assert_eq!(bits(&got_sorted), bits(&expected), "s = {s}");
        }
        // Lane −1 at s 77.25 of section 2: width 3 + 0.01·37.25 = 3.3725, t −3.3725..0.
        let at = memo.at(RoadHandle(0), 1, road, 77.25).0.to_vec();
        let minus_one = at.iter().find(|b| b.0 == -1).expect("lane −1");
        assert!((minus_one.1 + 3.3725).abs() < 1e-12 && minus_one.2 == 0.0);
    }

    /// `holds` gives a kept list's generation exactly on its range and nothing elsewhere:
    /// section 1's list, made at s 12.5, holds from 0 + 10⁻⁵ to 40 − 10⁻⁵ (`constant_lanes`
    /// keeps `CONSTANT_MARGIN` = 10⁻⁵ m from the section's ends), both ends included, and not
    /// a double beyond either; none at a NaN, in section 2 whose lane −1 widens (no list is
    /// kept there: made at each call, `at` gives no generation), in a section or road never
    /// asked; a second list for section 1 (made at s 2.0 after the first is forgotten) has a
    /// generation of its own.
    #[test]
    fn the_kept_range_holds_exactly_between_its_ends() {
        let net = network();
        let road = &net.roads()[0];
        let a = RoadHandle(0);
        let mut memo = LaneBorders::default();
        assert_eq!(memo.holds(a, 0, 12.5), None, "nothing asked yet");
        let first = memo.at(a, 0, road, 12.5).1.expect("section 1 is constant");
        let (lo, hi) = (1e-5, 40.0 - 1e-5);
        let below = |x: Real| Real::from_bits(x.to_bits() - 1);
        let above = |x: Real| Real::from_bits(x.to_bits() + 1);
        for s in [lo, above(lo), 12.5, below(hi), hi] {
            assert_eq!(memo.holds(a, 0, s), Some(first), "s = {s}");
        }
        for s in [below(lo), above(hi), 0.0, 40.0, Real::NAN] {
            assert_eq!(memo.holds(a, 0, s), None, "s = {s}");
        }
        assert_eq!(memo.at(a, 1, road, 77.25).1, None, "section 2 widens");
        assert_eq!(memo.holds(a, 1, 77.25), None);
        assert_eq!(memo.holds(a, 2, 12.5), None, "no third section");
        assert_eq!(memo.holds(RoadHandle(1), 0, 12.5), None, "no second road");
        memo.clear();
        assert_eq!(memo.holds(a, 0, 12.5), None, "forgotten");
        let second = memo.at(a, 0, road, 2.0).1.expect("section 1 is constant");
        assert_ne!(second, first);
        assert_eq!(memo.holds(a, 0, hi), Some(second));
    }
}
