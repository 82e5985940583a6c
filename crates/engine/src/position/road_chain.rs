//! oscsim's chain of roads (no 1.x form): the roads an OpenSCENARIO DSL plan measures an
//! actor's places along (ASAM OpenSCENARIO DSL 2.1 §8.9 measured along the plan's roads;
//! OpenDRIVE 1.8 §10.3 road linkage), each entered at its start in +s with the same lane ids,
//! given with the plan's s at its start, and the direction the actor drives them in. The DSL
//! runtime's state checks, marks and TravelAction name them (`scenario::PlanRoads`, in
//! `StateCheck::roads` and `Travel::roads`), so the engine measures in the plan's measure
//! wherever on them an actor is, and along a lane's centre line across their joints.
//!
//! The measure is the plan's s (a road's s plus its start) for an actor driving in +s, and
//! for one driving the roads against s (OpenDRIVE 1.8 §11.2: with right-hand traffic the
//! lanes of the left side are driven in −s) the distance along its direction of travel, u =
//! L − s (L the length of the roads), with t and lane offsets taken to its left (−t): the
//! same numbers the DSL runtime plans such an actor in (`PlanRoad::against` there), so a
//! check, a mark or a travel goal is written as the plan has it and measured here. u = L − s
//! is its own inverse, so one function turns either into the other.
//!
//! An empty chain is one road: the road the actor is on, in that road's own s (u = its length
//! − s against s): two places compare only on one road there.

use opendrive::{angle_difference, Real, RoadNetwork, RoadPosition, GEOMETRY_GAP_TOLERANCE};
use scenario::PlanRoads;

use super::lane_length::{lane_arc_length, s_at_lane_distance};

/// The roads of a plan with the plan's s at each start, in +s order (empty: one road), and
/// the direction the actor drives them in.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RoadChain<'a> {
    network: &'a RoadNetwork,
    roads: &'a [(String, Real)],
    against: bool,
}

impl<'a> RoadChain<'a> {
    /// Over `plan`'s roads of `network` (`PlanRoads::chain`: `(road id, the plan's s at its
    /// start)`, in +s order), measured in its direction.
    pub(crate) fn new(network: &'a RoadNetwork, plan: &'a PlanRoads) -> Self {
        Self {
            network,
            roads: &plan.chain,
            against: plan.against,
        }
    }

    /// Whether it is a chain of several roads (else one road, the actor's).
    pub(crate) fn is_chain(&self) -> bool {
        !self.roads.is_empty()
    }

    /// The length of road `id` (0 for a road the network lacks).
    fn road_length(&self, id: &str) -> Real {
        self.network.road(id).map_or(0.0, |r| r.length)
    }

    /// The measure of the plan's s `s` (on one road, `road`'s own s): s itself in +s; against
    /// s u = L − s, L the length of the chain's roads (on one road, `road`'s). Its own
    /// inverse: it turns u back into s too.
    fn measure(&self, road: &str, s: Real) -> Real {
        if !self.against {
            return s;
        }
        let length = match self.roads.last() {
            Some((id, start)) => start + self.road_length(id),
            None => self.road_length(road),
        };
        length - s
    }

    /// A t (or a lateral offset, m) across the road to the left of the direction of travel:
    /// t itself in +s, −t against s. Its own inverse.
    pub(crate) fn left(&self, t: Real) -> Real {
        if self.against {
            -t
        } else {
            t
        }
    }

    /// Whether a motion along a lane towards +s (`forward`) increases the measure.
    pub(crate) fn increasing(&self, forward: bool) -> bool {
        forward != self.against
    }

    /// The measure at `v` m, for messages: "s = 12.000 m", or against s "u = 12.000 m along
    /// the direction of travel".
    pub(crate) fn place(&self, v: Real) -> String {
        match self.against {
            false => format!("s = {v:.3} m"),
            true => format!("u = {v:.3} m along the direction of travel (against s)"),
        }
    }

    /// How a distance between two places is measured, for messages: "along the road", or
    /// against s "along the direction of travel (against s)".
    pub(crate) fn along(&self) -> &'static str {
        match self.against {
            false => "along the road",
            true => "along the direction of travel (against s)",
        }
    }

    /// The measure of s = `s` on road `road` (the plan's s: a road's s plus its start; against
    /// s u = L − that), `None` off the chain's roads; on one road s itself (against s that
    /// road's length − s).
    pub(crate) fn s_of(&self, road: &str, s: Real) -> Option<Real> {
        if !self.is_chain() {
            return Some(self.measure(road, s));
        }
        self.roads
            .iter()
            .find(|(id, _)| id == road)
            .map(|(_, start)| self.measure(road, start + s))
    }

    /// The measures of `a` and `b` in one measure: on a chain each on one of its roads, else
    /// both on one and the same road; `None` where they do not compare.
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
    /// most that times 1 + |t| across the joint), so t is measured from one continuous line
    /// (in either direction of travel: against s −t on every road).
    /// `Err` names the road that does not compare or the joint that is not continuous.
    pub(crate) fn lateral_compares(&self, a: &str, b: &str) -> Result<(), String> {
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
            let network = self.network;
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

    /// The roads with their start and end in the plan's s (in +s, `road` the one road's
    /// length from the network), or on one road `road` itself from 0.
    fn spans(&self, road: &'a str) -> Vec<(&'a str, Real, Real)> {
        match self.is_chain() {
            false => vec![(road, 0.0, self.road_length(road))],
            true => self
                .roads
                .iter()
                .map(|(id, start)| (id.as_str(), *start, start + self.road_length(id)))
                .collect(),
        }
    }

    /// The length (≥ 0) of lane `lane`'s centre line between the measures `m0` and `m1`
    /// (the plan's s, or u against s), summed over the roads it crosses
    /// (`lane_length::lane_arc_length` on each); on one road between them on `road`. `None`
    /// outside the roads or where the lane is missing.
    pub(crate) fn lane_length(
        &self,
        road: &'a str,
        lane: i32,
        (m0, m1): (Real, Real),
    ) -> Option<Real> {
        let (s0, s1) = (self.measure(road, m0), self.measure(road, m1));
        let (lo, hi) = (s0.min(s1), s0.max(s1));
        let spans = self.spans(road);
        let (first, last) = (spans.first()?, spans.last()?);
        if lo < first.1 - crate::tolerance::LENGTH || hi > last.2 + crate::tolerance::LENGTH {
            return None;
        }
        let mut total = 0.0;
        for (id, a, b) in spans {
            let (from, to) = (lo.max(a), hi.min(b));
            if to > from {
                total += lane_arc_length(self.network, id, lane, from - a, to - a)?;
            }
        }
        Some(total)
    }

    /// The measure (the plan's s, or u against s) reached after `distance` m (≥ 0) along
    /// lane `lane`'s centre line from s = `s0` of road `road` (one of the chain's), towards +s
    /// when `forward`, going on onto the next road (or the one before) at a joint; on one road
    /// that road's. `Err` (the road model's words) where the last road (or the first) ends
    /// first, or `road` is off the chain.
    pub(crate) fn s_at_lane_distance(
        &self,
        (road, lane, s0): (&'a str, i32, Real),
        distance: Real,
        forward: bool,
    ) -> Result<Real, String> {
        let network = self.network;
        let spans = self.spans(road);
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
                        .map(|x| self.measure(id, a + x))
                        .map_err(|e| e.to_string())
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Roads 0, 1 and 2 of junction_trippel_twoway0 with the plan's s at each start.
    fn plan(against: bool) -> PlanRoads {
        PlanRoads {
            chain: vec![
                ("0".to_string(), 0.0),
                ("1".to_string(), 100.0),
                ("2".to_string(), 130.0),
            ],
            against,
        }
    }

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
        let roads = plan(false);
        let chain = RoadChain::new(&net, &roads);
        const TOL: Real = 1e-6;
        // 27 m of road 0 → s 16.55 m of road 2: 73 + 30.45 + 16.55 = 120 m of lane.
        let l = chain
            .lane_length("0", -1, (27.0, 146.55))
            .expect("on the chain");
        assert!((l - 120.0).abs() < TOL, "{l}");
        let s = chain
            .s_at_lane_distance(("0", -1, 27.0), 120.0, true)
            .expect("on the chain");
        assert!((s - 146.55).abs() < TOL, "{s}");
        // And back from road 2 to road 0.
        let s = chain
            .s_at_lane_distance(("2", -1, 16.55), 120.0, false)
            .expect("on the chain");
        assert!((s - 27.0).abs() < TOL, "{s}");
        assert_eq!(
            chain.s_of("2", 16.55).map(|s| (s - 146.55).abs() < TOL),
            Some(true)
        );
        assert_eq!(chain.s_of("5", 1.0), None);
        // t compares across continuous joints: road 0 ends at (100, 0) heading 0 where road 1
        // starts; road 1's spiral ends at road 2's start (129.717, 3.130) heading 0.3 rad.
        assert_eq!(chain.lateral_compares("0", "2"), Ok(()));
        assert_eq!(chain.lateral_compares("1", "1"), Ok(()));
        assert!(chain.lateral_compares("0", "5").is_err());
        // Not where a chain skipped road 1: road 0's end is 29.88 m from road 2's start.
        let skipped = PlanRoads {
            chain: vec![("0".to_string(), 0.0), ("2".to_string(), 100.0)],
            against: false,
        };
        assert!(RoadChain::new(&net, &skipped)
            .lateral_compares("0", "2")
            .is_err());
        // One road: its own s, the road's end an error.
        let one_road = PlanRoads::default();
        let one = RoadChain::new(&net, &one_road);
        assert_eq!(one.s_of("7", 3.0), Some(3.0));
        assert!(one.s_at_lane_distance(("0", -1, 90.0), 20.0, true).is_err());
    }

    /// The same roads driven against s (lane 1, t = +1.5 m, driven in −s): u = L − s with L =
    /// 100 + 30 + 100 = 230 m. Lane 1 lies on the inside of road 1's left turn, so it is
    /// shorter than the reference line there: ∫(1 − 1.5·κ) ds = 30 − 1.5·0.3 = 29.55 m. From
    /// s 50 m of road 2 (u = 230 − 180 = 50 m) 100 m of lane reach road 0 at s = 100 − (100 −
    /// 50 − 29.55) = 79.55 m, u = 150.45 m.
    #[test]
    fn against_s_the_chain_measures_along_the_direction_of_travel() {
        let net = net();
        let roads = plan(true);
        let chain = RoadChain::new(&net, &roads);
        const TOL: Real = 1e-6;
        let near = |got: Option<Real>, want: Real| got.is_some_and(|g| (g - want).abs() < TOL);
        assert!(near(chain.s_of("2", 50.0), 50.0));
        assert!(near(chain.s_of("0", 79.55), 150.45));
        assert!(near(chain.s_of("1", 0.0), 130.0));
        let u = chain
            .s_at_lane_distance(("2", 1, 50.0), 100.0, false)
            .expect("on the chain");
        assert!((u - 150.45).abs() < TOL, "{u}");
        let l = chain
            .lane_length("2", 1, (50.0, 150.45))
            .expect("on the chain");
        assert!((l - 100.0).abs() < TOL, "{l}");
        // Two places: u of each, the one further along the direction of travel the larger.
        let at = |road: &str, s: Real| {
            net.locate_on_road(road, 0.0, 0.0)
                .map(|p| RoadPosition { s, ..p })
                .expect("road")
        };
        let (a, b) = chain
            .pair(&at("0", 79.55), &at("2", 50.0))
            .expect("both on it");
        assert!(
            (a - 150.45).abs() < TOL && (b - 50.0).abs() < TOL,
            "{a} {b}"
        );
        // t and offsets to the left of the direction of travel; a motion towards -s increases u.
        assert_eq!(chain.left(1.5), -1.5);
        assert!(chain.increasing(false) && !chain.increasing(true));
        // One road against s: u = its length − s (road 0: 100 m).
        let one_road = PlanRoads {
            chain: Vec::new(),
            against: true,
        };
        let one = RoadChain::new(&net, &one_road);
        assert!(near(one.s_of("0", 30.0), 70.0));
        let u = one
            .s_at_lane_distance(("0", 1, 30.0), 20.0, false)
            .expect("on road 0");
        assert!((u - 90.0).abs() < TOL, "{u}");
        assert!(near(one.lane_length("0", 1, (70.0, 90.0)), 20.0));
        assert!(one.place(70.0).starts_with("u = 70.000 m"));
    }
}
