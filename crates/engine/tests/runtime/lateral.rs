//! LaneChangeAction and LaneOffsetAction (OpenSCENARIO 1.3 §7.7.2.2 "LateralAction", with the
//! TransitionDynamics of §7.7.2: shapes and dimensions) against hand computations.
//!
//! The road is esmini's straight_500m.xodr along +x: lane −1's centre at t = −1.535, lane 1's
//! at t = +1.535 (3.07 m wide lanes), so on it s = x and t = y.

use crate::runtime_support;

use approx::assert_abs_diff_eq;
use runtime_support::{run, Recorder, Row};

/// Tolerance for positions that the runtime computes exactly up to rounding.
const EXACT: f64 = 1e-9;

/// Lateral position t of a frame (m).
fn t(row: &Row) -> f64 {
    row.road.clone().unwrap_or_default().3
}

/// Asserts `value` of Ego's frame at each `(time, expected)`, to [`EXACT`].
fn assert_ego(frames: &Recorder, value: impl Fn(&Row) -> f64, expected: &[(f64, f64)]) {
    for &(time, want) in expected {
        let got = value(frames.at("Ego", time));
        assert!(
            (got - want).abs() < EXACT,
            "at {time} s: {got}, want {want}"
        );
    }
}

/// The cubic shape of §7.7.2: f(u) = 3u² − 2u³.
fn cubic(u: f64) -> f64 {
    3.0 * u * u - 2.0 * u * u * u
}

/// lateral_distance_cubic.xosc: a cubic lane change of Δ = 3.5 m (lane −1's centre, t = −1.535,
/// to 0.43 m left of lane 1's centre, t = 1.965) over D = 50 m, at 10 m/s, starting at 1.0 s
/// where s = 20 + 10·1 = 30 m.
///
/// `dynamicsDimension="distance"` is the distance along the road (LaneChangeAction: "time and
/// distance are measured between the start position and the end position of the action"; the
/// lateral position is a function of the longitudinal one, as in esmini's LatLaneChangeAction,
/// which advances the shape by the longitudinal part of each step). On a straight road the distance
/// along the road is s − 30, so at every frame t = −1.535 + 3.5·f((s − 30)/50); half-way,
/// at s = 55, f(½) = ¾ − ¼ = ½ and t = −1.535 + 1.75 = 0.215. The path is longer than 50 m:
/// ∫√(1 + t′²) ds = 50·(1 + (3.5/50)²·⟨f′²⟩/2) ≈ 50.147 m with ⟨f′²⟩ = 36/30 = 1.2, so
/// measuring the path instead would put t 3.5·1.5·0.0735/50 ≈ 7.7 mm ahead at half-way.
#[test]
fn lane_change_over_a_distance_follows_the_cubic_of_the_distance_along_the_road() {
    let (_, frames, _) = run("lateral_distance_cubic.xosc");
    let (s0, t0, delta, d) = (30.0, -1.535, 3.5, 50.0);
    let mut checked = 0;
    let mut half = None;
    let mut previous: Option<(f64, f64)> = None;
    for row in frames.0.iter().filter(|r| r.name == "Ego" && r.time >= 1.0) {
        let (_, _, s, t, _) = row.road.clone().unwrap_or_default();
        let u = (s - s0) / d;
        if u >= 1.0 {
            // Done: 0.43 m left of lane 1's centre.
            assert_abs_diff_eq!(t, 1.965, epsilon = EXACT);
            continue;
        }
        assert_abs_diff_eq!(t, t0 + delta * cubic(u), epsilon = EXACT);
        checked += 1;
        if let Some((s_prev, t_prev)) = previous {
            if s_prev <= s0 + 25.0 && s > s0 + 25.0 {
                // Linear interpolation between the two frames around s = 55 m, off by at
                // most h²/8·|t″| with h = 0.5 m and t″ = 3.5·(6 − 12u)/50² ≤ 8.4·10⁻⁵ /m
                // within a step of u = ½: 2.6·10⁻⁶ m.
                half = Some(t_prev + (t - t_prev) * (s0 + 25.0 - s_prev) / (s - s_prev));
            }
        }
        previous = Some((s, t));
    }
    assert!(
        checked > 90,
        "the change takes some 100 steps of 0.5 m: {checked}"
    );
    let half = half.unwrap_or(f64::NAN);
    assert_abs_diff_eq!(half - t0, 1.75, epsilon = 3e-6);
}

/// lateral_distance_accel.xosc: the lane change of lateral_distance_cubic.xosc (Δ = 3.5 m over
/// D = 50 m along the road, from 1.0 s) while a SpeedAction, started at 0.5 s, takes the speed
/// from 10 to 20 m/s in 4 s (a = 2.5 m/s²). The lane change's action steps first in each step,
/// before the speed action sets the speed the step is driven with, so it foresees each step's
/// travel a·dt² = 2.5·0.05² m short; the next step takes the distance actually driven (the
/// odometer), so the error does not add up. One step's worth at most, Δ·max f′·a·dt²/D =
/// 3.5·1.5·0.00625/50 = 6.6·10⁻⁴ m, is left against t = t₀ + Δ·f((s − s₀)/D); adding up, it
/// reached 2.7 cm.
#[test]
fn lane_change_over_a_distance_follows_the_road_distance_while_the_speed_changes() {
    let (_, frames, _) = run("lateral_distance_accel.xosc");
    let s0 = frames.at("Ego", 1.0).road.clone().unwrap_or_default().2;
    let bound = 3.5 * 1.5 * 2.5 * 0.05 * 0.05 / 50.0;
    let mut checked = 0;
    for row in frames.0.iter().filter(|r| r.name == "Ego" && r.time >= 1.0) {
        let (_, _, s, t, _) = row.road.clone().unwrap_or_default();
        let u = (s - s0) / 50.0;
        if u < 1.0 {
            let off = t - (-1.535 + 3.5 * cubic(u));
            assert!(off.abs() <= bound, "{off} m off at {} s", row.time);
            checked += 1;
        }
    }
    assert!(checked > 50, "{checked} frames during the change");
}

/// lateral_slow_heading.xosc: a sinusoidal lane change of Δ = 3.07 m in T = 2 s at 5 m/s,
/// starting at 1.0 s, on a road along +x (road heading 0).
///
/// At half time, 2.0 s, the lateral speed peaks at Δ·π/(2T) = 3.07·π/4 = 2.411172 m/s. The
/// speed is the speed along the path, so the path leaves the lane at θ with
/// sin θ = 2.411172/5 = 0.482234 and θ = asin(0.482234) = 0.503204 rad; the heading is θ
/// (the longitudinal speed is 5·cos θ = 4.380 m/s, and 2.411172/4.380 = tan θ). Reading the
/// lateral speed over the whole speed as the slope would give atan(0.482234) = 0.449334 rad,
/// 3° off the direction the car moves in. The frames either side, 1.95 s and 2.05 s, show
/// that direction: their chord's slope Δy/Δx is tan θ up to the O(dt²) change of θ around its
/// peak, (5·0.05)²·|θ″| ≈ 10⁻³.
#[test]
fn heading_follows_the_motion_during_a_slow_lane_change() {
    let (_, frames, _) = run("lateral_slow_heading.xosc");
    let theta = (3.07 * std::f64::consts::PI / 4.0 / 5.0).asin();
    assert_abs_diff_eq!(theta, 0.503_203_571_711_707_8, epsilon = EXACT);
    let mid = frames.at("Ego", 2.0);
    assert_abs_diff_eq!(mid.h, theta, epsilon = EXACT);
    let (before, after) = (frames.at("Ego", 1.95), frames.at("Ego", 2.05));
    let chord = ((after.y - before.y) / (after.x - before.x)).atan();
    assert_abs_diff_eq!(chord, theta, epsilon = 1e-3);
    // Zero slope at both ends (§7.7.2, sinusoidal): the heading is the road's again at 3.0 s.
    assert_abs_diff_eq!(frames.at("Ego", 3.5).h, 0.0, epsilon = EXACT);
}

/// lateral_rate_linear.xosc: a linear lane change at a rate of 1 m/s (§7.7.2: `rate` is the
/// rate of change of the value, here the lateral speed) over Δ = 3.07 m, at 20 m/s, from
/// 1.0 s: it takes 3.07 s, so t = −1.535 + 1·(T − 1) until 4.07 s; at 2.0 s t = −0.535 and
/// at 3.0 s t = 0.465. The lateral speed is 1 m/s throughout: sin θ = 1/20, heading
/// asin(0.05). The step from 4.05 s passes 4.07 s and ends the change in lane 1.
#[test]
fn linear_lane_change_at_a_rate_moves_at_that_lateral_speed() {
    let (_, frames, events) = run("lateral_rate_linear.xosc");
    let lateral = [
        (1.0, -1.535),
        (2.0, -0.535),
        (3.0, 0.465),
        (4.05, 1.515),
        (4.1, 1.535),
    ];
    assert_ego(&frames, t, &lateral);
    assert_ego(&frames, |r| r.h, &[(2.0, 0.05f64.asin()), (4.5, 0.0)]);
    let ended = runtime_support::end_time(&events, "Action").unwrap_or(f64::NAN);
    assert_abs_diff_eq!(ended, 4.05, epsilon = EXACT);
}

/// lateral_step.xosc: the step shape takes no time (§7.7.2 DynamicsShape `step`, whatever the
/// value says; semantics-pitfalls #8): the change started at 1.0 s is done in that step, so
/// the frame at 1.05 s is on lane 1's centre (t = 1.535), heading along the road, and the
/// action ends in the step it starts in.
#[test]
fn step_lane_change_takes_no_time() {
    let (_, frames, events) = run("lateral_step.xosc");
    assert_ego(&frames, t, &[(1.0, -1.535), (1.05, 1.535)]);
    assert_eq!(frames.at("Ego", 1.05).road.clone().unwrap_or_default().1, 1);
    assert_ego(&frames, |r| r.h, &[(1.05, 0.0)]);
    let ended = runtime_support::end_time(&events, "Action").unwrap_or(f64::NAN);
    assert_abs_diff_eq!(ended, 1.0, epsilon = EXACT);
}

/// lateral_offset_linear.xosc: LaneOffsetAction, linear, 0 → 1.5 m, maxLateralAcc a = 1 m/s²,
/// from 1.0 s at 20 m/s.
///
/// A linear change has an infinite lateral acceleration at its ends whatever its duration
/// (§7.7.2.2 LaneOffsetActionDynamics gives maxLateralAcc, the shapes of §7.7.2 give no more);
/// oscsim takes the cubic's duration, T = √(6Δ/a) = √(6·1.5/1) = 3 s, as esmini does
/// (lane_offset.rs). So the offset is 1.5·(2.5 − 1)/3 = 0.75 m at 2.5 s and 1.5 m at 4.0 s.
/// The lateral speed is Δ/T = 0.5 m/s all along, sin θ = 0.5/20 = 0.025: heading asin(0.025).
#[test]
fn linear_lane_offset_takes_the_cubic_duration() {
    let (_, frames, events) = run("lateral_offset_linear.xosc");
    let offset = |r: &Row| r.road.clone().unwrap_or_default().4;
    assert_ego(
        &frames,
        offset,
        &[(1.0, 0.0), (2.5, 0.75), (4.0, 1.5), (4.5, 1.5)],
    );
    assert_ego(&frames, |r| r.h, &[(2.5, 0.025f64.asin()), (4.5, 0.0)]);
    // The step from 3.95 s reaches p = 1 at 4.0 s and ends the action; the log carries the
    // step's start.
    let ended = runtime_support::end_time(&events, "Action").unwrap_or(f64::NAN);
    assert_abs_diff_eq!(ended, 3.95, epsilon = EXACT);
}

/// lateral_reversed_successor.xosc: a sinusoidal lane change of 3.5 m (lane −1 to lane −2,
/// y = −1.75 to −5.25) over 2 s from 1.0 s at 10 m/s, starting 10 m before road 1 ends. Road 1
/// runs along +x from x = 0; road 2 runs from x = 200 back to x = 100 and meets road 1 end to
/// end, so at 2.0 s the entity passes onto road 2, in its lanes 1 and 2, where t points the
/// other way (t = −y). The world position does not care: y(T) = −1.75 − 3.5·(1 − cos(π(T −
/// 1)/2))/2 at every frame, through the crossing, and the entity ends in road 2's lane 2.
#[test]
fn lane_change_runs_on_across_a_reversed_successor() {
    let (_, frames, _) = run("lateral_reversed_successor.xosc");
    for row in frames.0.iter().filter(|r| r.name == "Ego") {
        let p = ((row.time - 1.0) / 2.0).clamp(0.0, 1.0);
        let y = -1.75 - 3.5 * (1.0 - (std::f64::consts::PI * p).cos()) / 2.0;
        assert!(
            (row.y - y).abs() < EXACT,
            "y({}) = {}, want {y}",
            row.time,
            row.y
        );
    }
    let end = frames.at("Ego", 3.5).road.clone().unwrap_or_default();
    assert_eq!((end.0.as_str(), end.1), ("2", 2));
}
