//! oscsim's chain of roads (no 1.x form): the roads of an OpenSCENARIO DSL plan over several
//! roads (ASAM OpenSCENARIO DSL 2.1 §8.9 measured along the plan's roads; OpenDRIVE 1.8 §10.4
//! road linkage), each entered at its start and driven in +s with the same lane ids, given
//! with the plan's s at its start. The DSL runtime's state checks, marks and TravelAction
//! name them (`scenario::StateCheck::roads`, `scenario::Travel::roads`), so the engine
//! measures in the plan's s (a road's s plus its start) wherever on them an actor is, and
//! along a lane's centre line across their joints.
//!
//! An empty chain is one road: the road the actor is on, in that road's own s (what every
//! measure did before chains): two places compare only on one road there.

use opendrive::{angle_difference, Real, RoadNetwork, RoadPosition, GEOMETRY_GAP_TOLERANCE};

use super::lane_length::{lane_arc_length, s_at_lane_distance};

/// The roads of a plan with the plan's s at each start, in driving order (empty: one road).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RoadChain<'a> {
    roads: &'a [(String, Real)],
}

impl<'a> RoadChain<'a> {
    /// Over `roads` (`(road id, the plan's s at its start)`, in driving order).
    pub(crate) fn new(roads: &'a [(String, Real)]) -> Self {
        Self { roads }
    }

    /// Whether it is a chain of several roads (else one road, the actor's).
    pub(crate) fn is_chain(&self) -> bool {
        !self.roads.is_empty()
    }

    /// The plan's s of s = `s` on road `road` (a road's s plus its start), `None` off the
    /// chain's roads; on one road s itself.
    pub(crate) fn s_of(&self, road: &str, s: Real) -> Option<Real> {
        if !self.is_chain() {
            return Some(s);
        }
        self.roads
            .iter()
            .find(|(id, _)| id == road)
            .map(|(_, start)| start + s)
    }

    /// The s of `a` and `b` in one measure: the plan's s of both on a chain (each on one of
    /// its roads), else their own s on one and the same road; `None` where they do not compare.
    pub(crate) fn pair(&self, a: &RoadPosition, b: &RoadPosition) -> Option<(Real, Real)> {
        if !self.is_chain() && a.road_id != b.road_id {
            return None;
        }
        Some((self.s_of(&a.road_id, a.s)?, self.s_of(&b.road_id, b.s)?))
    }

    /// Whether t on road `a` and t on road `b` compare as one lateral measure: on one and the
    /// same road; on a chain (both of its roads) where every joint between them is continuous,
    /// the reference line's end on one road its start on the next in place and heading
    /// (within opendrive's `GEOMETRY_GAP_TOLERANCE`, m and rad: a point at t then moves by at
    /// most that times 1 + |t| across the joint), so t is measured from one continuous line.
    /// `Err` names the road that does not compare or the joint that is not continuous.
    pub(crate) fn lateral_compares(
        &self,
        network: &RoadNetwork,
        a: &str,
        b: &str,
    ) -> Result<(), String> {
        if a == b {
            return Ok(());
        }
        let index = |road: &str| self.roads.iter().position(|(id, _)| id == road);
        let (Some(i), Some(j)) = (index(a), index(b)) else {
            return Err(match self.is_chain() {
                true => format!("roads {a} and {b} both {}", self.describe()),
                false => format!("road {b} the same road as {a}"),
            });
        };
        let (lo, hi) = (i.min(j), i.max(j));
        for pair in self.roads[lo..=hi].windows(2) {
            let (from, to) = (pair[0].0.as_str(), pair[1].0.as_str());
            let end = network
                .road(from)
                .map(|r| r.length)
                .and_then(|l| network.road_pose(from, l, 0.0).ok());
            let start = network.road_pose(to, 0.0, 0.0).ok();
            let joins = end.zip(start).is_some_and(|(e, s)| {
                (e.x - s.x).hypot(e.y - s.y) <= GEOMETRY_GAP_TOLERANCE
                    && angle_difference(e.h, s.h).abs() <= GEOMETRY_GAP_TOLERANCE
            });
            if !joins {
                return Err(format!(
                    "road {from}'s reference line going on into road {to}'s (t measured from one line)"
                ));
            }
        }
        Ok(())
    }

    /// "one of roads 0, 1, 2", for messages.
    pub(crate) fn describe(&self) -> String {
        let ids: Vec<&str> = self.roads.iter().map(|(id, _)| id.as_str()).collect();
        format!("one of roads {}", ids.join(", "))
    }

    /// Where a measure is taken, for an error text: "one of roads 0, 1, 2" on a chain, else
    /// "road `road`" (the one road).
    pub(crate) fn roads_or(&self, road: &str) -> String {
        match self.is_chain() {
            true => self.describe(),
            false => format!("road {road}"),
        }
    }

    /// The roads with their start and end in the plan's s (`road`, its length from `network`),
    /// or on one road `road` itself from 0.
    fn spans(&self, network: &RoadNetwork, road: &'a str) -> Vec<(&'a str, Real, Real)> {
        let length = |id: &str| network.road(id).map_or(0.0, |r| r.length);
        match self.is_chain() {
            false => vec![(road, 0.0, length(road))],
            true => self
                .roads
                .iter()
                .map(|(id, start)| (id.as_str(), *start, start + length(id)))
                .collect(),
        }
    }

    /// The length (≥ 0) of lane `lane`'s centre line between the plan's s `s0` and `s1`,
    /// summed over the roads it crosses (`lane_length::lane_arc_length` on each); on one road
    /// between s0 and s1 of `road`. `None` outside the roads or where the lane is missing.
    pub(crate) fn lane_length(
        &self,
        network: &RoadNetwork,
        road: &'a str,
        lane: i32,
        (s0, s1): (Real, Real),
    ) -> Option<Real> {
        let (lo, hi) = (s0.min(s1), s0.max(s1));
        let spans = self.spans(network, road);
        let (first, last) = (spans.first()?, spans.last()?);
        if lo < first.1 - crate::tolerance::LENGTH || hi > last.2 + crate::tolerance::LENGTH {
            return None;
        }
        let mut total = 0.0;
        for (id, a, b) in spans {
            let (from, to) = (lo.max(a), hi.min(b));
            if to > from {
                total += lane_arc_length(network, id, lane, from - a, to - a)?;
            }
        }
        Some(total)
    }

    /// The plan's s reached after `distance` m (≥ 0) along lane `lane`'s centre line from s =
    /// `s0` of road `road` (one of the chain's), towards +s when `forward`, going on onto the
    /// next road (or the one before) at a joint; on one road that road's s. `Err` (the road
    /// model's words) where the last road (or the first) ends first, or `road` is off the
    /// chain.
    pub(crate) fn s_at_lane_distance(
        &self,
        network: &RoadNetwork,
        (road, lane, s0): (&'a str, i32, Real),
        distance: Real,
        forward: bool,
    ) -> Result<Real, String> {
        let spans = self.spans(network, road);
        let Some(mut k) = spans.iter().position(|(id, _, _)| *id == road) else {
            return Err(format!("road {road} is not {}", self.describe()));
        };
        let (mut s, mut left) = (s0, distance.max(0.0));
        loop {
            let (id, a, b) = spans[k];
            let end = if forward { b - a } else { 0.0 };
            let next = if forward { k + 1 } else { k.wrapping_sub(1) };
            let to_end = lane_arc_length(network, id, lane, s, end);
            match (to_end, spans.get(next)) {
                (Some(l), Some(_)) if l < left => {
                    left -= l;
                    k = next;
                    s = if forward {
                        0.0
                    } else {
                        spans[k].2 - spans[k].1
                    };
                }
                // It ends on this road (or this road is the last: the road model's error).
                _ => {
                    return s_at_lane_distance(network, id, lane, s, left, forward)
                        .map(|x| a + x)
                        .map_err(|e| e.to_string())
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn net() -> RoadNetwork {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../dsl_runtime/tests/roads/junction_trippel_twoway0.xodr");
        RoadNetwork::from_file(&path).expect("reads")
    }

    /// junction_trippel_twoway0: road 0 (100 m straight) → road 1 (30 m spiral, curvature
    /// 0.001 → 0.019 1/m, 0.3 rad left) → road 2; lane -1 at t = −1.5 m. On the straight the
    /// lane is as long as s; on the spiral ∫(1 + 1.5·κ) ds = 30 + 1.5·0.3 = 30.45 m (the
    /// lane's width is constant, so t_c′ = 0).
    #[test]
    fn a_lane_is_measured_and_walked_across_the_chains_joints() {
        let net = net();
        let roads = vec![
            ("0".to_string(), 0.0),
            ("1".to_string(), 100.0),
            ("2".to_string(), 130.0),
        ];
        let chain = RoadChain::new(&roads);
        const TOL: Real = 1e-6;
        // 27 m of road 0 → s 16.55 m of road 2: 73 + 30.45 + 16.55 = 120 m of lane.
        let l = chain
            .lane_length(&net, "0", -1, (27.0, 146.55))
            .expect("on the chain");
        assert!((l - 120.0).abs() < TOL, "{l}");
        let s = chain
            .s_at_lane_distance(&net, ("0", -1, 27.0), 120.0, true)
            .expect("on the chain");
        assert!((s - 146.55).abs() < TOL, "{s}");
        // And back from road 2 to road 0.
        let s = chain
            .s_at_lane_distance(&net, ("2", -1, 16.55), 120.0, false)
            .expect("on the chain");
        assert!((s - 27.0).abs() < TOL, "{s}");
        assert_eq!(
            chain.s_of("2", 16.55).map(|s| (s - 146.55).abs() < TOL),
            Some(true)
        );
        assert_eq!(chain.s_of("5", 1.0), None);
        // t compares across continuous joints: road 0 ends at (100, 0) heading 0 where road 1
        // starts; road 1's spiral ends at road 2's start (129.717, 3.130) heading 0.3 rad.
        assert_eq!(chain.lateral_compares(&net, "0", "2"), Ok(()));
        assert_eq!(chain.lateral_compares(&net, "1", "1"), Ok(()));
        assert!(chain.lateral_compares(&net, "0", "5").is_err());
        // Not where a chain skipped road 1: road 0's end is 29.88 m from road 2's start.
        let skipped = vec![("0".to_string(), 0.0), ("2".to_string(), 100.0)];
        assert!(RoadChain::new(&skipped)
            .lateral_compares(&net, "0", "2")
            .is_err());
        // One road: its own s, the road's end an error.
        let one = RoadChain::new(&[]);
        assert_eq!(one.s_of("7", 3.0), Some(3.0));
        assert!(one
            .s_at_lane_distance(&net, ("0", -1, 90.0), 20.0, true)
            .is_err());
    }
}
