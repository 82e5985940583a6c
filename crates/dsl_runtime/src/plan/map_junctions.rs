//! Ways through a junction of the loaded network, for `roads_follow_in_junction` (ASAM
//! OpenSCENARIO DSL 2.1 §8.12.2.2.3; OpenDRIVE 1.8 §12 junctions, §10.3 road linkage, §11.5
//! lane linkage): the connecting lane from one lane to another, the turn it makes ([`Turn`],
//! from the headings), and the roads meeting at the junction for `clockwise_count` and
//! `number_of_roads`.
//!
//! The standard leaves open how roads are counted round a junction. oscsim's reading: the
//! roads of a junction are the roads outside it whose start or end links to it (its incoming
//! and outgoing roads, not its connecting roads), so a four-way crossing has four. Each is
//! placed at the angle of its linked end's reference-line point seen from the mean of those
//! points; going clockwise (seen from above, z up) from the in-road, the first road met has
//! `clockwise_count` 1, the next 2, and so on.

use std::f64::consts::TAU;

use opendrive::{ContactPoint, Direction, ElementType, LaneHandle, RoadNetwork};

/// The roads outside junction `id` linked to it (indices into `net.roads()`, in the network's
/// order) with the angle (rad) of their linked end round the junction.
fn arms(net: &RoadNetwork, id: &str) -> Vec<(usize, f64)> {
    let ends: Vec<(usize, [f64; 2])> = net
        .roads()
        .iter()
        .enumerate()
        .filter(|(_, r)| r.junction.is_none())
        .filter_map(|(i, r)| {
            let to_it = |l: &Option<opendrive::RoadLink>| {
                l.as_ref()
                    .is_some_and(|l| l.element_type == ElementType::Junction && l.element_id == id)
            };
            let end = if to_it(&r.links.predecessor) {
                ContactPoint::Start
            } else if to_it(&r.links.successor) {
                ContactPoint::End
            } else {
                return None;
            };
            let s = if end == ContactPoint::Start {
                0.0
            } else {
                r.length
            };
            let p = r.pose(s, 0.0).ok()?;
            Some((i, [p.x, p.y]))
        })
        .collect();
    if ends.is_empty() {
        return Vec::new();
    }
    let n = ends.len() as f64;
    let cx = ends.iter().map(|(_, p)| p[0]).sum::<f64>() / n;
    let cy = ends.iter().map(|(_, p)| p[1]).sum::<f64>() / n;
    ends.into_iter()
        .map(|(i, p)| (i, (p[1] - cy).atan2(p[0] - cx)))
        .collect()
}

/// How many roads outside junction `id` meet at it.
pub(super) fn number_of_roads(net: &RoadNetwork, id: &str) -> usize {
    arms(net, id).len()
}

/// The position of road `to` going clockwise round junction `id` from road `from` (1: the
/// first road met), when both meet at it.
pub(super) fn clockwise_count(net: &RoadNetwork, id: &str, from: usize, to: usize) -> Option<u32> {
    let arms = arms(net, id);
    let angle = |k: usize| arms.iter().find(|(i, _)| *i == k).map(|(_, a)| *a);
    let a0 = angle(from)?;
    let a1 = angle(to)?;
    // Clockwise is decreasing angle; the in-road itself is met last (a U-turn).
    let cw = |a: f64| {
        let d = (a0 - a).rem_euclid(TAU);
        if d == 0.0 {
            TAU
        } else {
            d
        }
    };
    let d1 = if from == to { TAU } else { cw(a1) };
    let before = arms
        .iter()
        .filter(|(i, a)| *i != from && *i != to && cw(*a) < d1)
        .count();
    u32::try_from(before + 1).ok()
}

/// The way a path through a junction turns (§8.12 `junction_direction`), from the change of
/// heading between the lane into the junction at its end and the lane out at its start, both
/// in their driving directions: within ±45° straight, from 45° to 150° left, from −45° to −150°
/// right, beyond ±150° a U-turn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Turn {
    /// `straight`.
    Straight,
    /// `left`.
    Left,
    /// `right`.
    Right,
    /// `u_turn`.
    Back,
}

impl Turn {
    pub(super) fn named(name: &str) -> Option<Self> {
        match name {
            "straight" => Some(Self::Straight),
            "left" => Some(Self::Left),
            "right" => Some(Self::Right),
            "u_turn" => Some(Self::Back),
            _ => None,
        }
    }

    /// The turn of a change of heading `d` (rad, wrapped to (−π, π]).
    pub(super) fn of(d: f64) -> Self {
        let deg = d.to_degrees();
        if deg.abs() <= 45.0 {
            Self::Straight
        } else if deg.abs() >= 150.0 {
            Self::Back
        } else if deg > 0.0 {
            Self::Left
        } else {
            Self::Right
        }
    }
}

/// The connecting lane of a junction that leads from lane `from` to lane `to`, if one does.
pub(super) fn connecting(
    net: &RoadNetwork,
    from: LaneHandle,
    to: LaneHandle,
) -> Option<LaneHandle> {
    net.successors(from).iter().copied().find(|c| {
        net.roads()[c.road as usize].junction.is_some() && net.successors(*c).contains(&to)
    })
}

/// The heading of lane `h` in its driving direction at its start (`start`) or end (rad).
fn heading(net: &RoadNetwork, h: LaneHandle, start: bool) -> Option<f64> {
    let r = &net.roads()[h.road as usize];
    let k = h.section as usize;
    let s0 = r.lane_sections.get(k)?.s;
    let s1 = r.lane_sections.get(k + 1).map_or(r.length, |n| n.s);
    let forward = net.driving_direction(h) == Direction::Forward;
    let s = if start == forward { s0 } else { s1 };
    let psi = r.heading(s).ok()?;
    Some(if forward {
        psi
    } else {
        psi + std::f64::consts::PI
    })
}

/// The change of heading from the end of lane `from` to the start of lane `to`, in (−π, π].
pub(super) fn heading_change(net: &RoadNetwork, from: LaneHandle, to: LaneHandle) -> Option<f64> {
    use std::f64::consts::{PI, TAU};
    let d = heading(net, to, true)? - heading(net, from, false)?;
    let w = d.rem_euclid(TAU);
    Some(if w > PI { w - TAU } else { w })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::test_roads::net;

    #[test]
    fn roads_round_a_junction_are_counted_clockwise_from_the_in_road() {
        // junction_trippel_twoway0.xodr, junction 1: road 0 ends at (100, 0); roads 2, 4, 6
        // start at (129.717, 3.130), (123.747, -12.967), (120, 0). Their mean (118.366,
        // -2.459); the angles from it: road 0 172.4°, road 6 56.5°, road 2 26.2°, road 4
        // -62.9°. Clockwise from road 0: 6, 2, 4.
        let net = net("junction_trippel_twoway0.xodr");
        let at = |id: &str| net.roads().iter().position(|r| r.id == id).expect("road");
        assert_eq!(number_of_roads(&net, "1"), 4);
        let (r0, r2, r4, r6) = (at("0"), at("2"), at("4"), at("6"));
        assert_eq!(clockwise_count(&net, "1", r0, r6), Some(1));
        assert_eq!(clockwise_count(&net, "1", r0, r2), Some(2));
        assert_eq!(clockwise_count(&net, "1", r0, r4), Some(3));
        assert_eq!(clockwise_count(&net, "1", r0, r0), Some(4));
        // From road 4 (-62.9°) clockwise: road 0 (172.4° = -187.6°) first.
        assert_eq!(clockwise_count(&net, "1", r4, r0), Some(1));
        assert_eq!(clockwise_count(&net, "1", r4, r6), Some(2));
        // A road not at the junction, a junction with no roads.
        assert_eq!(clockwise_count(&net, "1", r0, at("1")), None);
        assert_eq!(number_of_roads(&net, "9"), 0);
    }

    #[test]
    fn turns_through_a_junction_are_read_from_the_headings() {
        // junction_trippel_twoway0.xodr: road 0 at heading 0 into junction 1; out of it road 2
        // at 0.3 rad, road 4 at 4.768185307 rad (= -1.515 rad), road 6 at 0 (the planViews).
        let net = net("junction_trippel_twoway0.xodr");
        let lane = |id: &str, lane| LaneHandle {
            road: net.roads().iter().position(|r| r.id == id).expect("road") as u32,
            section: 0,
            lane,
        };
        let from = lane("0", -1);
        for (to, want, turn) in [
            ("2", 0.3, Turn::Straight),
            ("4", 4.768185307179586 - std::f64::consts::TAU, Turn::Right),
            ("6", 0.0, Turn::Straight),
        ] {
            let to = lane(to, -1);
            assert!(connecting(&net, from, to).is_some());
            let d = heading_change(&net, from, to).expect("headings");
            assert!((d - want).abs() < 1e-9, "{d} vs {want}");
            assert_eq!(Turn::of(d), turn);
        }
        // Into road 0 from road 4's lane 1 (driven in -s): from 1.627 rad to pi, a left turn.
        let d = heading_change(&net, lane("4", 1), lane("0", 1)).expect("headings");
        assert_eq!(Turn::of(d), Turn::Left, "{d}");
    }
}
