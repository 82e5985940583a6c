//! Crossings of the map (ASAM OpenSCENARIO DSL 2.1 §8.12.2.2.9 `crossing_connects`, §8.12
//! `crossing`; OpenDRIVE 1.8 §13 objects, type `crosswalk`, §13.3 outlines): the way across
//! a crosswalk of the loaded network that joins two lanes, for the map's binding
//! (`map_lanes`) and the walk along it (`crossing_walk`).
//!
//! The standard: "Connect a crossing between two lanes. The s-coordinate of the crossing
//! increases from the start_lane to end_lane"; it starts on `start_lane`'s centreline at
//! `start_s_coord` and runs at `start_angle` to the lane's direction ("by default
//! perpendicular") "a straight line to the end_lane". oscsim generates no maps, so a crossing
//! is one of the map's crosswalks: the straight line from `start_lane`'s centre at s0 to
//! `end_lane`'s centre at s1 = s0 + |Δt|·cot(start_angle) must lie within the crosswalk's
//! outline, taken as its extent in the road's s and t (the outline's bounding box in road
//! coordinates: `cornerRoad` corners as they are, `cornerLocal` ones laid from the object's
//! (s, t) along its heading, which is exact where the reference line is straight under the
//! object; an object without an outline, its `length` × `width` box). Choices where the
//! standard is silent: without `start_s_coord`, s0 is the middle of the crosswalk's extent in
//! s; both lanes lie in one lane section of the crosswalk's road; the crosswalks are tried in
//! the road's order and the first that holds the line is the crossing.

use opendrive::{Corner, LaneHandle, Object, Road, RoadNetwork};

/// A crossing: the way across a crosswalk from one lane's centre to another's.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Crossing {
    /// The crosswalk's road (index into the network's roads).
    pub road: usize,
    /// The crosswalk's OpenDRIVE object id.
    pub object: String,
    /// Start: lane, s and t on the road (m).
    pub start: (i32, f64, f64),
    /// End: lane, s and t on the road (m).
    pub end: (i32, f64, f64),
}

/// A crossing field the map's `crossing_connects` bound.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct MapCrossing {
    /// The field's path.
    pub field: String,
    /// The crossing (s on its road).
    pub crossing: Crossing,
    /// The plan's s at the start of the crossing's road (a road of the plan).
    pub road_start: f64,
    /// What bound it, for messages.
    pub why: String,
}

/// The extent of `o`'s outline on `road` in s and t: (s_min, s_max, t_min, t_max), if it has
/// an outline or a length and width.
pub(super) fn extent(o: &Object) -> Option<(f64, f64, f64, f64)> {
    let (c, sn) = (o.hdg.cos(), o.hdg.sin());
    let local = |u: f64, v: f64| (o.s + u * c - v * sn, o.t + u * sn + v * c);
    let mut pts: Vec<(f64, f64)> = o
        .outlines
        .iter()
        .flatten()
        .map(|k| match *k {
            Corner::Road { s, t } => (s, t),
            Corner::Local { u, v } => local(u, v),
        })
        .collect();
    if pts.is_empty() {
        let (l, w) = (o.length? / 2.0, o.width? / 2.0);
        pts = vec![local(-l, -w), local(l, -w), local(l, w), local(-l, w)];
    }
    let fold = |f: fn(f64, f64) -> f64, k: fn(&(f64, f64)) -> f64, init: f64| {
        pts.iter().map(k).fold(init, f)
    };
    Some((
        fold(f64::min, |p| p.0, f64::INFINITY),
        fold(f64::max, |p| p.0, f64::NEG_INFINITY),
        fold(f64::min, |p| p.1, f64::INFINITY),
        fold(f64::max, |p| p.1, f64::NEG_INFINITY),
    ))
}

/// Whether the network has a crosswalk with an extent (an outline, or a length and width).
pub(super) fn has_crosswalk(net: &RoadNetwork) -> bool {
    net.roads()
        .iter()
        .flat_map(|r| &r.objects)
        .any(|o| o.is_crosswalk() && extent(o).is_some())
}

/// t of the centre of lane `lane` of `road` at s, if the lane is there.
fn centre(road: &Road, lane: i32, s: f64) -> Option<f64> {
    road.lane_span(lane, s).ok().map(|sp| sp.center())
}

/// The crossing from lane `a` to lane `b` (one lane section of one road) across a crosswalk,
/// starting at s = `start_s` (else the crosswalk's middle) at `angle` (rad, else π/2) to the
/// lane's direction: the first crosswalk of the road that holds it.
pub(super) fn crossing(
    net: &RoadNetwork,
    a: LaneHandle,
    b: LaneHandle,
    start_s: Option<f64>,
    angle: Option<f64>,
) -> Option<Crossing> {
    if (a.road, a.section) != (b.road, b.section) || a.lane == b.lane {
        return None;
    }
    let road = &net.roads()[a.road as usize];
    let k = a.section as usize;
    let s_lo = road.lane_sections[k].s;
    let s_hi = road.lane_sections.get(k + 1).map_or(road.length, |n| n.s);
    let angle = angle.unwrap_or(std::f64::consts::FRAC_PI_2);
    road.objects
        .iter()
        .filter(|o| o.is_crosswalk())
        .find_map(|o| {
            let (s_min, s_max, t_min, t_max) = extent(o)?;
            let s0 = start_s.unwrap_or((s_min + s_max) / 2.0);
            let t0 = centre(road, a.lane, s0)?;
            // End lane's centre where the line reaches it: s1 from its t at s0 (lanes of one
            // width across the crosswalk), then its t at s1.
            let s1 = s0 + (centre(road, b.lane, s0)? - t0).abs() / angle.tan();
            let t1 = centre(road, b.lane, s1)?;
            let inside = |s: f64, t: f64| {
                (s_min..=s_max).contains(&s)
                    && (t_min..=t_max).contains(&t)
                    && (s_lo..=s_hi).contains(&s)
            };
            (inside(s0, t0) && inside(s1, t1)).then(|| Crossing {
                road: a.road as usize,
                object: o.id.clone(),
                start: (a.lane, s0, t0),
                end: (b.lane, s1, t1),
            })
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::test_roads::net;

    /// Lanes are within 1e-9 m of their closed-form centres on the straight road.
    const TOL: f64 = 1e-9;

    #[test]
    fn a_crossing_runs_from_lane_centre_to_lane_centre_within_the_crosswalk() {
        // crosswalk.xodr: lanes -1 (t -3.5..0) and 1 (0..3.5), the crosswalk's outline s 98 to
        // 102 m, t -3.5 to 3.5 m: from lane -1 at its middle, s 100 m, t -1.75 m, to lane 1,
        // t 1.75 m; perpendicular, so s1 = 100 m.
        let net = net("crosswalk.xodr");
        let h = |lane| LaneHandle {
            road: 0,
            section: 0,
            lane,
        };
        let c = crossing(&net, h(-1), h(1), None, None).expect("a crossing");
        assert_eq!((c.object.as_str(), c.start.0, c.end.0), ("cw1", -1, 1));
        for (got, want) in [
            (c.start.1, 100.0),
            (c.start.2, -1.75),
            (c.end.1, 100.0),
            (c.end.2, 1.75),
        ] {
            assert!((got - want).abs() < TOL, "{c:?}");
        }
        // At 60° to the lane: s1 = 99 + 3.5/tan 60° = 101.0207 m, inside; at 45° from s 99 m:
        // s1 = 102.5 m, past the outline.
        let c = crossing(&net, h(-1), h(1), Some(99.0), Some(60f64.to_radians())).expect("60°");
        assert!((c.end.1 - (99.0 + 3.5 / 3f64.sqrt())).abs() < TOL, "{c:?}");
        assert!(crossing(&net, h(-1), h(1), Some(99.0), Some(45f64.to_radians())).is_none());
        // Off the crosswalk, or a lane to itself: none.
        assert!(crossing(&net, h(-1), h(1), Some(50.0), None).is_none());
        assert!(crossing(&net, h(-1), h(-1), None, None).is_none());
        assert!(
            has_crosswalk(&net) && !has_crosswalk(&crate::plan::test_roads::net("straight.xodr"))
        );
    }
}
