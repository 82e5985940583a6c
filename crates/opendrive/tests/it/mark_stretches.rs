//! The stretches of [`LaneSection::lane_change_stretch`] and [`Road::lane_section_stretch`]
//! (issue 31): on corpus roads whose road marks change along the road, the answer kept while
//! its stretch holds is, at every s, the direct query's, bit for bit the same decision.

use opendrive::{LaneSection, Real, Road, RoadNetwork};

use crate::common::corpus;

/// The road-mark rule written out as it was before the stretches (the record in effect at
/// ds: the last of those starting at or before ds), the reference of the tests below.
fn permits_directly(section: &LaneSection, from: i32, to: i32, ds: Real) -> bool {
    let border_of = if from.signum() * to.signum() < 0 {
        0
    } else if from.abs() < to.abs() {
        from
    } else {
        to
    };
    let mark = section.lane(border_of).and_then(|lane| {
        lane.road_marks
            .iter()
            .take_while(|m| m.s_offset <= ds)
            .last()
    });
    mark.is_none_or(|m| m.permits_lane_change(border_of, to > from))
}

/// The corpus roads of the test: marks that change type along a lane (esmini's
/// multi_intersections: 28 lanes, straight_500m_roadmarks: solid, solid solid, solid broken,
/// broken solid along one lane, tunnels), roads with `laneChange` attributes, and roads of
/// several lane sections (two_plus_one, the generated lane adjustment, merge and split).
fn networks() -> Vec<(String, RoadNetwork)> {
    [
        "esmini/xodr/multi_intersections",
        "esmini/xodr/straight_500m_roadmarks",
        "esmini/xodr/tunnels",
        "esmini/xodr/fabriksgatan",
        "esmini/xodr/soderleden",
        "esmini/xodr/e6mini",
        "esmini/xodr/e6mini-lht",
        "esmini/xodr/two_plus_one",
        "generated/xodr/road_with_lane_adjustment0",
        "generated/xodr/highway_example_with_merge_and_split0",
        "generated/xodr/road_split_w_lane_split0",
        "generated/xodr/road_with_custom_roadmarkers0",
    ]
    .iter()
    .map(|name| {
        let path = corpus().join(format!("{name}.xodr"));
        let net = RoadNetwork::from_file(&path).unwrap_or_else(|e| panic!("{e}"));
        (name.to_string(), net)
    })
    .collect()
}

/// Sample points along [0, length]: a grid of 0.37 m, every boundary `at` and the doubles
/// two steps either side of it, and the road's ends.
fn samples(length: Real, at: impl Iterator<Item = Real>) -> Vec<Real> {
    let mut out: Vec<Real> = (0..)
        .map(|i| i as Real * 0.37)
        .take_while(|&s| s <= length)
        .collect();
    for b in at.chain([0.0, length]) {
        let (mut down, mut up) = (b, b);
        out.push(b);
        for _ in 0..2 {
            down = beside_double(down, false);
            up = beside_double(up, true);
            out.extend([down, up]);
        }
    }
    out.sort_by(Real::total_cmp);
    out
}

/// The double next to `x` towards +∞ (`up`) or −∞ (std's `next_up` / `next_down`).
fn beside_double(x: Real, up: bool) -> Real {
    if up {
        x.next_up()
    } else {
        x.next_down()
    }
}

/// Every pair of lanes side by side in `section`, both ways round.
fn adjacent_pairs(section: &LaneSection) -> Vec<(i32, i32)> {
    let ids: Vec<i32> = section
        .lanes()
        .map(|l| l.id)
        .filter(|&id| id != 0)
        .collect();
    let mut pairs = Vec::new();
    for w in ids.windows(2) {
        pairs.extend([(w[0], w[1]), (w[1], w[0])]);
    }
    pairs
}

/// For every section of every road of [`networks`], every pair of adjacent lanes and every
/// sample ds (each mark's start and the doubles beside it, a 0.37 m grid): the stretch's
/// answer is the direct rule's, its stretch holds at the ds asked, and an answer kept from
/// the last sample while its stretch holds is the direct rule's too. Both answers occur.
#[test]
fn a_kept_mark_answer_is_the_direct_query_at_every_s() {
    let (mut permitted, mut refused, mut kept_used, mut pairs_with_changes) = (0, 0, 0, 0);
    for (name, net) in networks() {
        for road in net.roads() {
            for (k, section) in road.lane_sections.iter().enumerate() {
                let length = road.lane_section_end(k) - section.s;
                let starts = section
                    .lanes()
                    .flat_map(|l| l.road_marks.iter().map(|m| m.s_offset));
                let points = samples(length, starts);
                for (from, to) in adjacent_pairs(section) {
                    let mut kept: Option<opendrive::MarkStretch> = None;
                    let mut answers = std::collections::BTreeSet::new();
                    for &ds in &points {
                        let direct = permits_directly(section, from, to, ds);
                        let here = section.lane_change_stretch(from, to, ds);
                        let at =
                            format!("{name} road {} section {k} {from}->{to} ds {ds}", road.id);
                        assert_eq!(here.permitted, direct, "{at}");
                        assert_eq!(section.permits_lane_change(from, to, ds), direct, "{at}");
                        assert!(here.holds(ds), "{at}: {here:?}");
                        match kept {
                            Some(k) if k.holds(ds) => {
                                assert_eq!(k.permitted, direct, "{at} (kept {k:?})");
                                kept_used += 1;
                            }
                            _ => kept = Some(here),
                        }
                        answers.insert(direct);
                        if direct {
                            permitted += 1;
                        } else {
                            refused += 1;
                        }
                    }
                    pairs_with_changes += usize::from(answers.len() > 1);
                }
            }
        }
    }
    assert!(
        permitted > 10_000 && refused > 10_000 && kept_used > 20_000 && pairs_with_changes > 10,
        "{permitted} permitted, {refused} refused, {kept_used} kept, {pairs_with_changes} pairs changing"
    );
}

/// A NaN ds is in no stretch, so a kept answer is never used for it; the direct rule finds
/// no record for it (no `sOffset` is at or before NaN): permitted.
#[test]
fn no_mark_stretch_holds_at_nan() {
    for (_, net) in networks() {
        for road in net.roads() {
            for section in &road.lane_sections {
                for (from, to) in adjacent_pairs(section) {
                    let at_nan = section.lane_change_stretch(from, to, Real::NAN);
                    assert!(at_nan.permitted && !at_nan.holds(Real::NAN));
                    let at_0 = section.lane_change_stretch(from, to, 0.0);
                    assert!(!at_0.holds(Real::NAN));
                }
            }
        }
    }
}

/// For every road of [`networks`] and every sample s (each section's start and the doubles
/// beside it, a 0.37 m grid, NaN): the stretch's section is `lane_section_index`'s, it holds
/// at the s asked (not at NaN), and a section kept from the last sample while its stretch
/// holds is `lane_section_index`'s too.
#[test]
fn a_kept_lane_section_is_the_direct_search_at_every_s() {
    let (mut kept_used, mut roads_with_sections) = (0, 0);
    for (name, net) in networks() {
        for road in net.roads() {
            let road: &Road = road;
            roads_with_sections += usize::from(road.lane_sections.len() > 1);
            let starts = road.lane_sections.iter().map(|ls| ls.s);
            let mut kept: Option<opendrive::SectionStretch> = None;
            for s in samples(road.length, starts) {
                let direct = road.lane_section_index(s);
                let here = road.lane_section_stretch(s);
                let at = format!("{name} road {} s {s}", road.id);
                assert_eq!(here.index, direct, "{at}");
                assert!(here.holds(s), "{at}: {here:?}");
                match kept {
                    Some(k) if k.holds(s) => {
                        assert_eq!(k.index, direct, "{at} (kept {k:?})");
                        kept_used += 1;
                    }
                    _ => kept = Some(here),
                }
            }
            let at_nan = road.lane_section_stretch(Real::NAN);
            assert_eq!(at_nan.index, road.lane_section_index(Real::NAN));
            assert!(!at_nan.holds(Real::NAN));
        }
    }
    assert!(
        kept_used > 10_000 && roads_with_sections > 10,
        "{kept_used} kept, {roads_with_sections} roads of several sections"
    );
}
