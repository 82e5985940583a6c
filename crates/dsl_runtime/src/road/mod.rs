//! The roads the planner places and moves the actors on (ASAM OpenDRIVE 1.8 §10 roads, §10.3
//! road linkage, §11 lanes, §12 junctions): a start road and the roads the engine drives onto
//! after it (`chain`), measured in one s from the start road's s = 0 (the plan's s: a road's s
//! plus the lengths of the roads before it). The start road is the road of the scenario's named
//! routes, else the first road of the network with driving lanes on its right side (right-hand
//! traffic: those lanes run in +s). A route through points (`map.create_route`) gives the
//! roads up to its last point itself (`path`: through a junction by the connection it names),
//! and the chain goes on from there. Lane ids are the roads' own, the same on every road of the
//! chain. Lanes are counted in the DSL's way (ASAM OpenSCENARIO DSL 2.1 §8.9 `lane()`
//! modifier): 1 is the rightmost driving lane in the direction of travel, or the leftmost with
//! `from: left`. A person walks on the sidewalks of the right side where the road has any
//! (counted the same way), else on its driving lanes.
//!
//! | module | computes |
//! | --- | --- |
//! | `chain` | which roads follow the start road |
//! | `path` | the roads of a route through points (`map.create_route`) |

mod chain;
mod path;

pub(crate) use path::route_roads;

use std::f64::consts::PI;

use opendrive::{LaneHandle, LaneType, Road, RoadNetwork};

/// One road of a plan and the plan's s at its start.
#[derive(Debug, Clone, Copy)]
struct Segment<'a> {
    road: &'a Road,
    start: f64,
}

/// The roads of a plan.
#[derive(Debug, Clone)]
pub(crate) struct PlanRoad<'a> {
    /// Never empty: the start road first.
    segments: Vec<Segment<'a>>,
    net: &'a RoadNetwork,
    /// The roads come from a route through points (`through`), which may take a junction's
    /// connection other than the first.
    routed: bool,
    /// The view of an actor driving the roads against s (see the module doc): every s the
    /// methods take or give is u = L − s, every t is −t, the lanes are the left side's.
    against: bool,
    /// Whether a lane section of these roads links a lane into one of another id (ASAM
    /// OpenDRIVE 1.8 §11.5 lane linkage). Where none does, [`lane_along`](Self::lane_along)
    /// gives every lane back as it is, and the plan's lane reads need no s along the lane.
    renumbers: bool,
}

impl<'a> PlanRoad<'a> {
    /// From the first road with a driving lane on its right side, if any.
    pub(crate) fn pick(net: &'a RoadNetwork) -> Option<Self> {
        let i = net.roads().iter().position(chain::drivable)?;
        Some(Self::from_index(net, i))
    }

    /// From road `id`, if it has a driving lane on its right side.
    pub(crate) fn by_id(net: &'a RoadNetwork, id: &str) -> Option<Self> {
        let i = net
            .roads()
            .iter()
            .position(|r| r.id == id && chain::drivable(r))?;
        Some(Self::from_index(net, i))
    }

    /// Over `roads` (indices into `net.roads()`, in driving order, never empty: a route's, from
    /// `route_roads`), then the roads the engine drives onto after the last of them.
    pub(crate) fn through(net: &'a RoadNetwork, roads: &[usize]) -> Self {
        let mut all = roads.to_vec();
        if let Some(&last) = roads.last() {
            for k in chain::chain(net, last).into_iter().skip(1) {
                if all.contains(&k) {
                    break;
                }
                all.push(k);
            }
        }
        let mut plan = Self::over(net, all);
        plan.routed = true;
        plan
    }

    fn from_index(net: &'a RoadNetwork, i: usize) -> Self {
        Self::over(net, chain::chain(net, i))
    }

    fn over(net: &'a RoadNetwork, roads: Vec<usize>) -> Self {
        let mut start = 0.0;
        let renumbers = roads.iter().any(|&k| renumbers_lanes(net, k));
        let segments = roads
            .into_iter()
            .map(|k| {
                let road = &net.roads()[k];
                let seg = Segment { road, start };
                start += road.length;
                seg
            })
            .collect();
        PlanRoad {
            segments,
            net,
            routed: false,
            against: false,
            renumbers,
        }
    }

    /// Whether a lane may be followed into one of another id along these roads (`renumbers`):
    /// when not, a lane planned at one s is the same id at every other.
    pub(crate) fn renumbers_lanes(&self) -> bool {
        self.renumbers
    }

    /// The same roads driven against s (see the module doc), or why they cannot be: over
    /// several roads, a driving lane of the left side that does not run on onto the road
    /// before it in the same lane (the rest of a sentence "expected …, found …").
    pub(crate) fn against(&self) -> Result<Self, String> {
        let index = |r: &Road| self.net.roads().iter().position(|q| q.id == r.id);
        for w in self.segments.windows(2) {
            let (Some(before), Some(after)) = (index(w[0].road), index(w[1].road)) else {
                continue;
            };
            if let Err(found) = chain::runs_back(self.net, after, before) {
                return Err(format!(
                    "expected the driving lanes of the left side (driven in -s) to run on from road {} onto road {} in the same lanes, as the plan's roads are driven in +s, found {found}",
                    w[1].road.id, w[0].road.id
                ));
            }
        }
        Ok(PlanRoad {
            against: true,
            ..self.clone()
        })
    }

    /// Whether this is the view of an actor driving against s.
    pub(crate) fn is_against(&self) -> bool {
        self.against
    }

    /// The plan's s of the distance `u` along this view's direction (the same in +s).
    pub(crate) fn forward_s(&self, u: f64) -> f64 {
        if self.against {
            self.length() - u
        } else {
            u
        }
    }

    /// +1 in +s, −1 against s: the sign of t, and of s along the direction of travel.
    fn sign(&self) -> f64 {
        if self.against {
            -1.0
        } else {
            1.0
        }
    }

    /// Whether the roads come from a route through points (`through`).
    pub(crate) fn routed(&self) -> bool {
        self.routed
    }

    /// The road network the roads are in.
    pub(crate) fn network(&self) -> &'a RoadNetwork {
        self.net
    }

    /// The OpenDRIVE id of the start road (in the view's direction: against s, the plan's
    /// last road).
    pub(crate) fn id(&self) -> &str {
        let g = if self.against {
            self.segments.last()
        } else {
            self.segments.first()
        };
        // `segments` is never empty.
        g.map_or("", |g| g.road.id.as_str())
    }

    /// The road ids in driving order (against s, the plan's last road first).
    pub(crate) fn ids(&self) -> Vec<String> {
        let mut ids: Vec<String> = self.segments.iter().map(|g| g.road.id.clone()).collect();
        if self.against {
            ids.reverse();
        }
        ids
    }

    /// The plan's s (against s: u) of s = `s` on road `id`, if that road is one of the plan's.
    pub(crate) fn plan_s(&self, id: &str, s: f64) -> Option<f64> {
        self.segments
            .iter()
            .find(|g| g.road.id == id)
            .map(|g| self.forward_s(g.start + s))
    }

    /// The plan's s (against s: u) of `s0` and `s1` on road `id`, when the plan drives it,
    /// the lesser first.
    pub(crate) fn plan_span(&self, id: &str, s0: f64, s1: f64) -> Option<(f64, f64)> {
        let (a, b) = (self.plan_s(id, s0)?, self.plan_s(id, s1)?);
        Some((a.min(b), a.max(b)))
    }

    /// The road and its own s at the plan's s `s` (against s: u), the later road in the
    /// direction of travel at a joint; clamped to the chain's ends.
    pub(crate) fn road_at(&self, s: f64) -> (&'a Road, f64) {
        let s = self.forward_s(s);
        let g = self.segment(s);
        (g.road, (s - g.start).clamp(0.0, g.road.length))
    }

    /// The road, its own s and the offset along its t of the point `offset` from the lane's
    /// centre at the plan's s `s` (against s: u, the offset to the left of that direction):
    /// the place an engine's LanePosition takes; clamped to the chain's ends.
    pub(crate) fn lane_position(&self, s: f64, offset: f64) -> (&'a Road, f64, f64) {
        let (road, s) = self.road_at(s);
        (road, s, self.sign() * offset)
    }

    /// `(road id, plan s at its start)` of every road, in +s order (in either view).
    pub(crate) fn starts(&self) -> Vec<(String, f64)> {
        self.segments
            .iter()
            .map(|g| (g.road.id.clone(), g.start))
            .collect()
    }

    /// The segment at the plan's s `s` (in +s), the later one in the view's direction at a
    /// joint.
    fn segment(&self, s: f64) -> Segment<'a> {
        // `segments` is never empty.
        let i = if self.against {
            self.segments
                .iter()
                .position(|g| s <= g.start + g.road.length)
                .unwrap_or(self.segments.len() - 1)
        } else {
            self.segments
                .iter()
                .rposition(|g| g.start <= s)
                .unwrap_or(0)
        };
        self.segments[i]
    }

    /// The length of all its roads (m).
    pub(crate) fn length(&self) -> f64 {
        self.segments
            .last()
            .map_or(0.0, |g| g.start + g.road.length)
    }

    /// Driving lanes of the right side in the direction of travel at `s`, rightmost first
    /// (−3, −2, −1; against s the left side's, 2, 1).
    pub(crate) fn driving_lanes(&self, s: f64) -> Vec<i32> {
        self.side_lanes(s, LaneType::is_drivable)
    }

    /// Sidewalks of the right side in the direction of travel at `s`, rightmost first.
    pub(crate) fn sidewalks(&self, s: f64) -> Vec<i32> {
        self.side_lanes(s, |t| *t == LaneType::Sidewalk)
    }

    /// Lanes of the right side in the direction of travel at `s` (against s: the road's left
    /// side) whose type passes `keep`, rightmost (outermost) first.
    fn side_lanes(&self, s: f64, keep: impl Fn(&LaneType) -> bool) -> Vec<i32> {
        let (road, s) = self.road_at(s);
        // The right side in +s, the left side against s: outermost first either way.
        road.lane_section_at(s)
            .side_from_right(self.against, self.against, keep)
    }

    /// The lane numbered `n` (1 = rightmost, or leftmost with `from_left`) at `s`: a driving
    /// lane, or for a walker a sidewalk where the road has any.
    pub(crate) fn numbered(&self, n: i64, from_left: bool, s: f64, walker: bool) -> Option<i32> {
        let mut lanes = match self.sidewalks(s) {
            w if walker && !w.is_empty() => w,
            _ => self.driving_lanes(s),
        };
        if from_left {
            lanes.reverse();
        }
        usize::try_from(n - 1)
            .ok()
            .and_then(|i| lanes.get(i).copied())
    }

    /// The lane `n` lanes to the left (or right) of `id` at `s`.
    pub(crate) fn beside(&self, id: i32, left: bool, n: i64, s: f64) -> Option<i32> {
        let lanes = self.driving_lanes(s);
        let i = lanes.iter().position(|l| *l == id)? as i64;
        let j = if left { i + n } else { i - n };
        usize::try_from(j).ok().and_then(|j| lanes.get(j).copied())
    }
}

impl PlanRoad<'_> {
    /// Where world point (x, y) projects onto the plan's roads: lane, the plan's s, and offset
    /// from the lane's centre (the nearest point of a road's surface when (x, y) lies off it),
    /// on the road nearest to the point (the first of equally near ones).
    pub(crate) fn locate(&self, x: f64, y: f64) -> Option<(i32, f64, f64)> {
        let mut best: Option<(f64, (i32, f64, f64))> = None;
        for g in &self.segments {
            let Some(p) = self.net.locate_on_road(&g.road.id, x, y) else {
                continue;
            };
            let here = g.road.pose(p.s.clamp(0.0, g.road.length), p.t);
            let d = here.map_or(f64::INFINITY, |q| (q.x - x).hypot(q.y - y));
            if !best.as_ref().is_some_and(|(b, _)| d >= *b) {
                let u = self.forward_s(g.start + p.s);
                best = Some((d, (p.lane_id, u, self.sign() * p.offset)));
            }
        }
        best.map(|(_, found)| found)
    }

    /// t of the centre of lane `lane` at `s` (m; against s to the left of that direction);
    /// 0 where the lane is missing.
    pub(crate) fn lane_center(&self, lane: i32, s: f64) -> f64 {
        let (road, s) = self.road_at(s);
        self.sign() * road.lane_span(lane, s).map_or(0.0, |sp| sp.center())
    }

    /// The driving lane of the right side whose span holds `t` at `s`, if any.
    pub(crate) fn lane_holding(&self, s: f64, t: f64) -> Option<i32> {
        let (road, local) = self.road_at(s);
        let t = self.sign() * t;
        self.driving_lanes(s).into_iter().find(|l| {
            road.lane_span(*l, local).is_ok_and(|sp| {
                let (a, b) = (sp.inner.min(sp.outer), sp.inner.max(sp.outer));
                (a..=b).contains(&t)
            })
        })
    }

    /// World x, y and the road's heading (rad, towards +s; against s towards −s) at the road
    /// point (s, t) (the plan's s; against s u and t to the left of that direction), if s is
    /// on the plan's roads.
    pub(crate) fn world_pose(&self, s: f64, t: f64) -> Option<(f64, f64, f64)> {
        if !(0.0..=self.length()).contains(&s) {
            return None;
        }
        let (road, s) = self.road_at(s);
        let turn = if self.against { PI } else { 0.0 };
        road.pose(s, self.sign() * t)
            .ok()
            .map(|p| (p.x, p.y, opendrive::normalize_angle(p.h + turn)))
    }

    /// Width of lane `lane` at `s` (m); 0 where the lane is missing.
    pub(crate) fn lane_width(&self, lane: i32, s: f64) -> f64 {
        let (road, s) = self.road_at(s);
        road.lane_span(lane, s).map_or(0.0, |sp| sp.width())
    }

    /// The lane that lane `lane` at the plan's s `s0` runs on into at `s1` (against s: u):
    /// across the lane sections of a road by the lanes' links (ASAM OpenDRIVE 1.8 §11.5 lane
    /// linkage, `<link><successor id=…>` and `<predecessor id=…>`: `RoadNetwork::successors`
    /// and `predecessors`, whichever leads towards `s1`); from one road of the plan to the next
    /// the same id (`chain` stops where a road link renumbers a lane). Where a lane has no
    /// link into the next lane section, or is missing at `s0`, the id it had there.
    pub(crate) fn lane_along(&self, lane: i32, s0: f64, s1: f64) -> i32 {
        if !self.renumbers {
            return lane;
        }
        let (a, b) = (self.forward_s(s0), self.forward_s(s1));
        let (lo, hi) = (a.min(b), a.max(b));
        let mut segments: Vec<&Segment<'_>> = self
            .segments
            .iter()
            .filter(|g| g.start <= hi && g.start + g.road.length >= lo)
            .collect();
        if b < a {
            segments.reverse();
        }
        let mut lane = lane;
        for g in segments {
            let local = |s: f64| (s - g.start).clamp(0.0, g.road.length);
            let Some(mut h) = self.net.lane_handle(&g.road.id, lane, local(a)) else {
                continue;
            };
            let target = g.road.lane_section_index(local(b)) as u32;
            while h.section != target {
                let next = if target > h.section {
                    h.section + 1
                } else {
                    h.section - 1
                };
                let linked = self
                    .net
                    .successors(h)
                    .iter()
                    .chain(self.net.predecessors(h))
                    .copied()
                    .find(|n| n.road == h.road && n.section == next);
                let Some(n) = linked else { break };
                h = n;
            }
            lane = h.lane;
        }
        lane
    }
}

/// Whether a lane section of road `k` links a lane of it into one of another id of the same
/// road (ASAM OpenDRIVE 1.8 §11.5: `<link><successor id=…>` / `<predecessor id=…>`, as the
/// network's lane graph holds them), the only way [`PlanRoad::lane_along`] changes a lane.
fn renumbers_lanes(net: &RoadNetwork, k: usize) -> bool {
    let road = &net.roads()[k];
    road.lane_sections.iter().enumerate().any(|(i, sec)| {
        sec.left.iter().chain(&sec.right).any(|lane| {
            let h = LaneHandle {
                road: k as u32,
                section: i as u32,
                lane: lane.id,
            };
            net.successors(h)
                .iter()
                .chain(net.predecessors(h))
                .any(|n| n.road == h.road && n.section != h.section && n.lane != h.lane)
        })
    })
}

/// Sampling step in s of lane centre lengths (m).
pub(crate) const LENGTH_STEP: f64 = 0.25;

impl PlanRoad<'_> {
    /// The same roads in +s (the view's lengths along lanes are those in +s, reversed).
    fn forward(&self) -> Self {
        PlanRoad {
            against: false,
            ..self.clone()
        }
    }

    /// Length of the centre line of lane `lane` (its id at `s0`, followed along its links
    /// across the lane sections on the way: [`lane_along`](Self::lane_along)) from `s0` to `s1`
    /// (negative when s1 < s0): the distance a vehicle following the lane covers, which
    /// differs from s on curves (a lane on the outside of a bend is longer). Summed over
    /// chords every [`LENGTH_STEP`] m of s; outside the roads, or where the lane is missing,
    /// 1 m per m of s.
    pub(crate) fn lane_distance(&self, lane: i32, s0: f64, s1: f64) -> f64 {
        if self.against {
            return -self
                .forward()
                .lane_distance(lane, self.forward_s(s0), self.forward_s(s1));
        }
        if s1 < s0 {
            return -self.lane_distance(self.stepped(lane, s0, s1), s1, s0);
        }
        let mut total = 0.0;
        let (mut s, mut lane) = (s0, lane);
        while s < s1 {
            let next = (s + LENGTH_STEP).min(s1);
            let then = self.stepped(lane, s, next);
            total += self.chord((lane, then), s, next);
            (s, lane) = (next, then);
        }
        total
    }

    /// The s reached from `s0` after `distance` along lane `lane`'s centre line (its id at
    /// `s0`, followed along its links as in [`lane_distance`](Self::lane_distance)).
    pub(crate) fn s_after(&self, lane: i32, s0: f64, distance: f64) -> f64 {
        if self.against {
            let s = self.forward().s_after(lane, self.forward_s(s0), -distance);
            return self.forward_s(s);
        }
        let dir = if distance < 0.0 { -1.0 } else { 1.0 };
        let mut left = distance.abs();
        let (mut s, mut lane) = (s0, lane);
        while left > 0.0 {
            let next = s + dir * LENGTH_STEP;
            let then = self.stepped(lane, s, next);
            let piece = if dir > 0.0 {
                self.chord((lane, then), s, next)
            } else {
                self.chord((then, lane), next, s)
            };
            if piece >= left {
                return s + dir * LENGTH_STEP * left / piece;
            }
            left -= piece;
            (s, lane) = (next, then);
        }
        s
    }

    /// Lane `lane` at `s` followed to `next`, one step of [`LENGTH_STEP`] or less away: itself
    /// within one lane section of one road (the lane sections at `s` and `next` asked first,
    /// the links only where a step crosses into another).
    fn stepped(&self, lane: i32, s: f64, next: f64) -> i32 {
        if !self.renumbers {
            return lane;
        }
        let section = |s: f64| {
            let g = self.segment(s);
            (g.start, g.road.lane_section_index(s - g.start))
        };
        if section(s) == section(next) {
            lane
        } else {
            self.lane_along(lane, s, next)
        }
    }

    /// Length of the chord of a lane between s `a` < `b`, its id `la` at `a` and `lb` at `b`
    /// (the same lane, [`stepped`](Self::stepped)), split where one road joins the next.
    fn chord(&self, (la, lb): (i32, i32), a: f64, b: f64) -> f64 {
        if !(0.0..=self.length()).contains(&a) || !(0.0..=self.length()).contains(&b) {
            return b - a;
        }
        if let Some(j) = self
            .segments
            .iter()
            .map(|g| g.start)
            .find(|j| a < *j && *j < b)
        {
            let lj = self.lane_along(la, a, j);
            return self.chord((la, lj), a, j) + self.chord((lj, lb), j, b);
        }
        // Both ends on the road of `a` (b may be its end).
        let g = self.segment(a);
        let (a, b) = (a - g.start, (b - g.start).min(g.road.length));
        match (g.road.lane_pose(la, a, 0.0), g.road.lane_pose(lb, b, 0.0)) {
            (Ok(p), Ok(q)) => (q.x - p.x).hypot(q.y - p.y),
            _ => b - a,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lane_length_on_an_arc() {
        // A 100 m arc of radius 100 m (curvature 0.01, a left bend); lane -1 of 3.5 m is centred
        // at t = -1.75 m, radius 101.75 m: its centre line is 100·101.75/100 = 101.75 m long
        // (chords of 0.25 m shorten it by under 1e-6 m).
        let xodr = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="7" length="100" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><arc curvature="0.01"/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#;
        let net = RoadNetwork::from_str(xodr, std::path::Path::new("arc.xodr")).expect("parses");
        let road = PlanRoad::pick(&net).expect("a road");
        let d = road.lane_distance(-1, 0.0, 100.0);
        assert!((d - 101.75).abs() < 1e-4, "{d}");
        assert!((road.s_after(-1, 0.0, 101.75) - 100.0).abs() < 1e-4);
        assert!((road.s_after(-1, 20.0, 50.875) - 70.0).abs() < 1e-4);
    }

    #[test]
    fn the_view_against_s_measures_from_the_roads_end_to_the_left_of_its_direction() {
        // The same arc with lane 1 (3.5 m, driven in -s) on its left side, centred at t =
        // 1.75 m, radius 98.25 m: 98.25 m long. Against s, u = 100 - s, t is -t, heading +pi.
        let xodr = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="7" length="100" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><arc curvature="0.01"/></geometry></planView>
<lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#;
        let net = RoadNetwork::from_str(xodr, std::path::Path::new("arc.xodr")).expect("parses");
        let road = PlanRoad::pick(&net).expect("a road");
        let back = road.against().expect("one road");
        assert_eq!(back.driving_lanes(10.0), [1]);
        assert_eq!(back.numbered(1, false, 10.0, false), Some(1));
        assert!((back.lane_center(1, 30.0) + 1.75).abs() < 1e-12);
        assert!((back.forward_s(30.0) - 70.0).abs() < 1e-12);
        assert_eq!(back.road_at(30.0).1, 70.0);
        // u = 0 is the road's end, s = 100 m: heading 1 rad (100 m of curvature 0.01) + pi.
        let (x, y, h) = back.world_pose(0.0, -1.75).expect("on the road");
        let r = 100.0 - 1.75;
        assert!((x - r * 1f64.sin()).abs() < 1e-9 && (y - (100.0 - r * 1f64.cos())).abs() < 1e-9);
        assert!((h - opendrive::normalize_angle(1.0 + PI)).abs() < 1e-9);
        assert_eq!(back.lane_holding(50.0, -1.75), Some(1));
        let d = back.lane_distance(1, 0.0, 100.0);
        assert!((d - 98.25).abs() < 1e-4, "{d}");
        assert!((back.s_after(1, 20.0, 49.125) - 70.0).abs() < 1e-4);
        assert_eq!(back.plan_span("7", 10.0, 40.0), Some((60.0, 90.0)));
        let (lane, u, offset) = back.locate(x, y).expect("on the road");
        assert_eq!(lane, 1);
        assert!(u.abs() < 1e-6 && offset.abs() < 1e-6, "{u} {offset}");
    }

    #[test]
    fn roads_are_driven_back_only_where_the_left_lanes_run_on_in_the_same_lanes() {
        // Road a (100 m) then road b (50 m) along +x; lanes -1 link a -> b, so the plan's roads
        // are a, b. Against s: b's lane 1 runs back onto a's lane 1 (`same`), or onto a's lane
        // 2 (`renumbered`), where the view would change lane ids.
        let net = |to: i32| {
            let xodr = format!(
                r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="a" length="100" junction="-1"><link><successor elementType="road" elementId="b" contactPoint="start"/></link><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><left><lane id="2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><link><successor id="-1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>
<road id="b" length="50" junction="-1"><link><predecessor elementType="road" elementId="a" contactPoint="end"/></link><planView><geometry s="0" x="100" y="0" hdg="0" length="50"><line/></geometry></planView>
<lanes><laneSection s="0"><left><lane id="1" type="driving"><link><predecessor id="{to}"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><link><predecessor id="-1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>"#
            );
            RoadNetwork::from_str(&xodr, std::path::Path::new("ab.xodr")).expect("parses")
        };
        let same = net(1);
        let road = PlanRoad::pick(&same).expect("a road");
        assert_eq!(road.ids(), ["a", "b"]);
        let back = road.against().expect("lane 1 runs back onto lane 1");
        assert_eq!(back.ids(), ["b", "a"]);
        // u = 30 m is 30 m back from b's end: b at s = 20 m; u = 70 m is a at s = 80 m.
        assert_eq!(back.road_at(30.0).0.id, "b");
        assert!((back.road_at(30.0).1 - 20.0).abs() < 1e-12);
        assert_eq!(back.road_at(70.0).0.id, "a");
        assert!((back.road_at(70.0).1 - 80.0).abs() < 1e-12);
        let renumbered = net(2);
        let e = PlanRoad::pick(&renumbered)
            .expect("a road")
            .against()
            .expect_err("lane 1 runs back onto lane 2");
        assert!(
            e.contains("found lane 1 of road b leading onto lane 2 of road a"),
            "{e}"
        );
    }

    /// A lane's length runs on along its links where a lane section renumbers it (ASAM
    /// OpenDRIVE 1.8 §11.5), on tests/roads/lane_add_inner.xodr: lane -1 of section 0 (t =
    /// -1.75 m, straight) leads at s = 300 m into -2, centred at t = -(w(d) + 1.75), the new
    /// lane -1 widening as w(d) = 0.00105·d² − 0.000007·d³ (d = s − 300), w'(d) = 0.0021·d −
    /// 0.000021·d² = 0.0021·d·(1 − d/100). From s = 250 to 350 m: 50 m, then
    /// ∫₀⁵⁰ √(1 + w'²) dd = 50 + ½∫w'² − ⅛∫w'⁴ with ∫₀⁵⁰ w'² = 0.0021²·10⁶·∫₀^½ x²(1−x)² dx =
    /// 4.41/60 = 0.0735 and ∫₀⁵⁰ w'⁴ = 0.0021⁴·10¹⁰/1260 = 0.000154: 50.036731 m, 100.036731 m
    /// in all. Along the new lane -1 (the id kept, centred at -w/2: slope w'/2) it would be
    /// 50 + ⅛·0.0735 − (1/128)·0.000154 = 50.009186 m.
    #[test]
    fn a_lanes_length_follows_its_links_across_lane_sections() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/roads/lane_add_inner.xodr");
        let text = std::fs::read_to_string(&path).expect("the bundled road");
        let net = RoadNetwork::from_str(&text, &path).expect("parses");
        let road = PlanRoad::pick(&net).expect("a road");
        assert_eq!(road.lane_along(-1, 250.0, 350.0), -2);
        let d = road.lane_distance(-1, 250.0, 350.0);
        assert!((d - 100.036731).abs() < 1e-6, "{d}");
        assert!((road.s_after(-1, 250.0, 100.036731) - 350.0).abs() < 1e-5);
        // Back from s = 350 m in lane -2: the same length, into -1 before s = 300 m.
        assert!((road.lane_distance(-2, 350.0, 250.0) + 100.036731).abs() < 1e-6);
        assert!((road.s_after(-2, 350.0, -100.036731) - 250.0).abs() < 1e-5);
    }

    #[test]
    fn only_a_road_whose_lane_sections_renumber_a_lane_is_followed_along_links() {
        let net = |name: &str| {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("tests/roads")
                .join(name);
            let text = std::fs::read_to_string(&path).expect("the bundled road");
            RoadNetwork::from_str(&text, &path).expect("parses")
        };
        // lane_add.xodr: two lane sections (s = 0 and 300 m), lanes 1, -1, -2 linked to the
        // same ids, -3 new at 300 m with no predecessor: no lane changes its id.
        let kept = net("lane_add.xodr");
        let road = PlanRoad::pick(&kept).expect("a road");
        assert!(!road.renumbers_lanes());
        assert_eq!(road.lane_along(-2, 250.0, 350.0), -2);
        // lane_add_inner.xodr: -1 and -2 of the first section lead into -2 and -3.
        let renumbered = net("lane_add_inner.xodr");
        let road = PlanRoad::pick(&renumbered).expect("a road");
        assert!(road.renumbers_lanes());
        assert_eq!(road.lane_along(-2, 250.0, 350.0), -3);
    }
}
