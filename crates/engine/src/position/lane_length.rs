//! Arc length along a lane's centre line, between two s of one road: RelativeLanePosition's
//! `dsLane` ("travel the lane center line difference dsLane") and the lane-coordinate
//! distances of conditions (OpenSCENARIO 1.3 §6.4, "along the lane centerline").
//!
//! The centre line of a lane at t_c(s) from a reference line of curvature κ(s) has
//! |dP/ds| = √((1 − κ t_c)² + t_c′²) (OpenDRIVE 1.8 §8.3 frame; t_c′ from the lane widths).
//! The integral is taken by composite Simpson's rule on intervals of at most
//! [`SIMPSON_STEP`] m; the integrand is smooth inside a geometry and a lane section, and the
//! rule is exact for the constant integrand of a lane on a straight or an arc of constant
//! width.

use opendrive::{Real, RoadNetwork};

/// Longest Simpson interval (m).
pub const SIMPSON_STEP: Real = 2.0;

/// Bisection steps that place a distance inside one interval (2 m / 2⁴⁰ ≈ 2 pm).
const BISECTION_STEPS: usize = 40;

/// The length of lane `lane_id`'s centre line of road `road_id` between `s1` and `s2`
/// (≥ 0); `None` when the road or the lane is missing there.
pub(crate) fn lane_arc_length(
    network: &RoadNetwork,
    road_id: &str,
    lane_id: i32,
    s1: Real,
    s2: Real,
) -> Option<Real> {
    let road = network.road(road_id)?;
    let (a, b) = (s1.min(s2), s1.max(s2));
    let speed = |s: Real| -> Option<Real> {
        let span = road.lane_span(lane_id, s).ok()?;
        let kappa = road.plan_view.eval(s).curvature;
        Some((1.0 - kappa * span.center()).hypot(span.d_center()))
    };
    // An even number of intervals, each at most SIMPSON_STEP.
    let n = (((b - a) / SIMPSON_STEP).ceil() as usize).max(1) * 2;
    let h = (b - a) / n as Real;
    let mut sum = speed(a)? + speed(b)?;
    for i in 1..n {
        let w = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += w * speed(a + i as Real * h)?;
    }
    Some(sum * h / 3.0)
}

/// The s reached after `distance` m (≥ 0) along lane `lane_id`'s centre line from `s0`,
/// towards +s when `forward`: intervals of [`SIMPSON_STEP`] are measured until one holds the
/// rest, which bisection places. `Err` (the road model's error) where the road or the lane
/// ends first.
pub(crate) fn s_at_lane_distance(
    network: &RoadNetwork,
    road_id: &str,
    lane_id: i32,
    s0: Real,
    distance: Real,
    forward: bool,
) -> Result<Real, opendrive::Error> {
    // Reports an unknown road or lane, or s0 off the road, in the road model's words.
    network.lane_pose(road_id, lane_id, s0, 0.0)?;
    let length = network.road(road_id).map_or(0.0, |r| r.length);
    let sign = if forward { 1.0 } else { -1.0 };
    let mut s = s0;
    let mut left = distance.max(0.0);
    while left > 0.0 {
        let next = (s + sign * SIMPSON_STEP).clamp(0.0, length);
        if next == s {
            // At the road's end with distance left: the road model names s beyond it.
            network.lane_pose(road_id, lane_id, s + sign * left, 0.0)?;
            return Ok(s);
        }
        let Some(piece) = lane_arc_length(network, road_id, lane_id, s, next) else {
            network.lane_pose(road_id, lane_id, next, 0.0)?;
            return Ok(s);
        };
        if piece >= left {
            let (mut lo, mut hi) = (s, next);
            for _ in 0..BISECTION_STEPS {
                let mid = 0.5 * (lo + hi);
                match lane_arc_length(network, road_id, lane_id, s, mid) {
                    Some(l) if l < left => lo = mid,
                    _ => hi = mid,
                }
            }
            return Ok(0.5 * (lo + hi));
        }
        left -= piece;
        s = next;
    }
    Ok(s)
}
