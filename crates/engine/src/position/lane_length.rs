//! Arc length along a lane's centre line (OpenSCENARIO 1.3 §6.4 distances in lane
//! coordinates: measured "along the lane centerline"), between two s of one road.
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
