//! SpeedAction (OpenSCENARIO 1.3 §7.7.2.1, XSD `SpeedAction`, `TransitionDynamics`) against
//! closed forms: the shapes (f(p) = p, 3p² − 2p³, (1 − cos πp)/2, a step taking no time) over
//! each dimension (time, distance, rate), the vehicle's Performance with followingMode
//! `follow` and `position`, a change of direction over a distance, and relative targets
//! (delta, factor, continuous or not).
//!
//! speed_shapes.xosc: Ego at s = 100 m drives at $V0 and at t = 1 s starts a SpeedAction to
//! $Target with $Shape / $Dimension / $Value / followingMode $Mode; its Performance has
//! maxAcceleration $MaxAcc (default 10) and maxDeceleration 10 m/s². The runtime sets in each
//! step the speed of the step's end and moves with it, so the frame at t shows v(t) and the
//! distance is Σ v(tₖ)·dt over the step ends tₖ.

use crate::runtime_support;

use std::f64::consts::PI;

use approx::assert_abs_diff_eq;
use engine::storyboard::Transition;
use engine::{EngineConfig, EventRecord};
use runtime_support::{end_time, file, Recorder};

/// Tolerance for values that are sums of a few hundred f64 terms.
const EXACT: f64 = 1e-9;
/// Time step of the runs (s), EngineConfig's default.
const DT: f64 = 0.05;

/// Runs test scenario `name` with the parameters `params` ("NAME=VALUE").
fn run_with(name: &str, params: &[&str]) -> (Recorder, Vec<EventRecord>) {
    let params: Vec<(&str, &str)> = params.iter().filter_map(|p| p.split_once('=')).collect();
    let (_, frames, events) =
        runtime_support::run_with(&file(name), &params, EngineConfig::default());
    (frames, events)
}

/// Time of the step in which action `name` ends (the step whose motion completes it).
fn end_step(events: &[EventRecord], name: &str) -> f64 {
    end_time(events, name).unwrap_or_else(|| panic!("{name} never ends"))
}

/// The longitudinal road coordinate s of `name` at `t`.
fn s_at(frames: &Recorder, name: &str, t: f64) -> f64 {
    frames.at(name, t).road.as_ref().map_or(f64::NAN, |r| r.2)
}

/// cubic over 4 s, 10 → 20 m/s: v = 10 + 10·(3p² − 2p³), p = (t − 1)/4; v(2) = 10 + 10·(3/16 −
/// 2/64) = 11.5625, v(3) = 15, v(5) = 20. Peak rate 1.5·10/4 = 3.75 m/s² is within
/// maxAcceleration, so nothing stretches. Distance: f(p) + f(1 − p) = 1, so over the N = 80
/// steps Σ f(k/N) = (N + 1)/2 and the transition covers 10·4 + 10·4·81/160 = 60.25 m:
/// s(5) = 100 + 10 (the first second) + 60.25.
#[test]
fn cubic_over_time_follows_the_closed_form() {
    let (frames, events) = run_with("speed_shapes.xosc", &[]);
    let v = |t: f64| frames.at("Ego", t).speed;
    assert_abs_diff_eq!(v(1.0), 10.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(2.0), 11.5625, epsilon = EXACT);
    assert_abs_diff_eq!(v(3.0), 15.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(5.0), 20.0, epsilon = EXACT);
    assert_abs_diff_eq!(s_at(&frames, "Ego", 5.0), 170.25, epsilon = EXACT);
    // It ends in the step 4.95 … 5.00 s whose motion completes it.
    assert_abs_diff_eq!(end_step(&events, "Speed"), 4.95, epsilon = EXACT);
}

/// sinusoidal over 60 m, 10 → 20 m/s: every symmetric shape covers (v0 + v1)·T/2, so
/// T = 2·60/30 = 4 s; v(2) = 10 + 10·(1 − cos(π/4))/2, and the distance is that of the cubic
/// case, 60.25 m in the scheme (60 m and the first-order term), s(5) = 170.25.
#[test]
fn sinusoidal_over_distance_covers_the_distance() {
    let (frames, _) = run_with(
        "speed_shapes.xosc",
        &["Shape=sinusoidal", "Dimension=distance", "Value=60"],
    );
    let v = |t: f64| frames.at("Ego", t).speed;
    assert_abs_diff_eq!(
        v(2.0),
        10.0 + 10.0 * (1.0 - (PI / 4.0).cos()) / 2.0,
        epsilon = EXACT
    );
    assert_abs_diff_eq!(v(3.0), 15.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(5.0), 20.0, epsilon = EXACT);
    assert_abs_diff_eq!(s_at(&frames, "Ego", 5.0), 170.25, epsilon = EXACT);
}

/// linear at rate 2 m/s², 10 → 20 m/s: 5 s, v = 10 + 2(t − 1); v(3.5) = 15, 20 from 6 s.
#[test]
fn linear_at_a_rate_takes_the_change_over_the_rate() {
    let (frames, events) = run_with(
        "speed_shapes.xosc",
        &["Shape=linear", "Dimension=rate", "Value=2"],
    );
    let v = |t: f64| frames.at("Ego", t).speed;
    assert_abs_diff_eq!(v(3.5), 15.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(6.0), 20.0, epsilon = EXACT);
    assert_abs_diff_eq!(end_step(&events, "Speed"), 5.95, epsilon = EXACT);
}

/// sinusoidal at rate 2 m/s², read as the peak rate (semantics-pitfalls #8): the peak slope of
/// (1 − cos πp)/2 is π/2, so T = 10·(π/2)/2 = 2.5π s and v = 10 + 5·(1 − cos(0.4·(t − 1))),
/// whose largest rate is 5·0.4 = 2 m/s².
#[test]
fn sinusoidal_at_a_rate_peaks_at_the_rate() {
    let (frames, _) = run_with(
        "speed_shapes.xosc",
        &["Shape=sinusoidal", "Dimension=rate", "Value=2"],
    );
    for t in [2.0_f64, 3.0, 5.0, 8.0] {
        let expected = 10.0 + 5.0 * (1.0 - (0.4 * (t - 1.0)).cos());
        assert_abs_diff_eq!(frames.at("Ego", t).speed, expected, epsilon = EXACT);
    }
    assert_abs_diff_eq!(frames.at("Ego", 9.0).speed, 20.0, epsilon = EXACT);
    let speeds: Vec<f64> = frames.0.iter().map(|r| r.speed).collect();
    let peak = speeds
        .windows(2)
        .map(|w| (w[1] - w[0]) / DT)
        .fold(0.0, f64::max);
    assert!(peak <= 2.0 + EXACT && peak > 1.99, "peak rate {peak}");
}

/// step takes no time: the speed is 20 m/s from the first step after the start, whatever the
/// value, and the car covers 20·0.05 = 1 m in that step.
#[test]
fn step_takes_no_time() {
    let (frames, _) = run_with("speed_shapes.xosc", &["Shape=step", "Value=3"]);
    assert_abs_diff_eq!(frames.at("Ego", 1.0).speed, 10.0, epsilon = EXACT);
    assert_abs_diff_eq!(frames.at("Ego", 1.05).speed, 20.0, epsilon = EXACT);
    assert_abs_diff_eq!(s_at(&frames, "Ego", 1.05), 111.0, epsilon = EXACT);
}

/// cubic over 1 s, 10 → 20 m/s: its peak rate 1.5·10/1 = 15 m/s² exceeds maxAcceleration 10.
/// Without a followingMode, and with `follow` (FollowingMode: "observing the dynamic
/// constraints of the entity"), the shape is kept and stretched to 1.5 s: v(1.75) = 15,
/// v(2.5) = 20, ending in the step 2.45 … 2.5 s. With `position` ("ignoring the dynamic
/// constraints") it runs in 1 s: v(1.5) = 15, v(2) = 20, with a step rate above 10 m/s².
#[test]
fn performance_bounds_the_transition_unless_following_mode_is_position() {
    for mode in ["follow", "position"] {
        let mode_param = format!("Mode={mode}");
        let (frames, events) = run_with("speed_shapes.xosc", &["Value=1", &mode_param]);
        let v = |t: f64| frames.at("Ego", t).speed;
        let speeds: Vec<f64> = frames.0.iter().map(|r| r.speed).collect();
        let peak = speeds
            .windows(2)
            .map(|w| (w[1] - w[0]) / DT)
            .fold(0.0, f64::max);
        if mode == "follow" {
            assert_abs_diff_eq!(v(1.75), 15.0, epsilon = EXACT);
            assert_abs_diff_eq!(v(2.5), 20.0, epsilon = EXACT);
            assert_abs_diff_eq!(end_step(&events, "Speed"), 2.45, epsilon = EXACT);
            assert!(peak <= 10.0 + EXACT, "{mode}: peak rate {peak}");
        } else {
            assert_abs_diff_eq!(v(1.5), 15.0, epsilon = EXACT);
            assert_abs_diff_eq!(v(2.0), 20.0, epsilon = EXACT);
            assert_abs_diff_eq!(end_step(&events, "Speed"), 1.95, epsilon = EXACT);
            assert!(peak > 14.0, "{mode}: peak rate {peak}");
        }
    }
}

/// linear over a path of 5 m from 5 to −5 m/s (forward, stop, reverse). The path is
/// 5·T₀/2 + 5·T₁/2 with T₀ = T₁ = T/2, so T = 2·5·(5 + 5)/(25 + 25) = 2 s (before, the mean
/// speed 0 made it a jump): v(2) = 0, v(3) = −5. The car runs 2.5 m out and 2.5 m back; in the
/// scheme Σ (5 − 10k/40)·0.05 over k = 1 … 40 = −0.25 m, so s(3) = 105 − 0.25.
#[test]
fn distance_through_a_change_of_direction_is_the_path_length() {
    let (frames, events) = run_with(
        "speed_shapes.xosc",
        &[
            "V0=5",
            "Target=-5",
            "Shape=linear",
            "Dimension=distance",
            "Value=5",
        ],
    );
    let v = |t: f64| frames.at("Ego", t).speed;
    assert_abs_diff_eq!(v(1.5), 2.5, epsilon = EXACT);
    assert_abs_diff_eq!(v(2.0), 0.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(3.0), -5.0, epsilon = EXACT);
    assert_abs_diff_eq!(s_at(&frames, "Ego", 3.0), 104.75, epsilon = EXACT);
    assert_abs_diff_eq!(end_step(&events, "Speed"), 2.95, epsilon = EXACT);
}

/// speed_relative.xosc: Lead drives 20 m/s and steps to 30 m/s at 4 s (seen from the 4.05 s
/// frame). From 1 s: Delta goes linearly in 2 s to Lead − 5 = 15 m/s and ends (not
/// continuous), staying at 15; DeltaCont does the same and keeps following: after Lead's step
/// its target is 25, reached at maxAcceleration 10 m/s², 0.5 m/s per step, from 4.05 s to
/// 5.0 s; Factor steps to 1.5·20 = 30 and to 1.5·30 = 45 with Lead (a step takes no time).
#[test]
fn relative_targets_delta_factor_and_continuous() {
    let (frames, events) = run_with("speed_relative.xosc", &[]);
    let v = |name: &str, t: f64| frames.at(name, t).speed;
    for name in ["Delta", "DeltaCont"] {
        assert_abs_diff_eq!(v(name, 2.0), 12.5, epsilon = EXACT);
        assert_abs_diff_eq!(v(name, 3.0), 15.0, epsilon = EXACT);
    }
    assert_abs_diff_eq!(end_step(&events, "DeltaSpeed"), 2.95, epsilon = EXACT);
    assert_abs_diff_eq!(v("Delta", 6.0), 15.0, epsilon = EXACT);
    assert_abs_diff_eq!(v("DeltaCont", 4.05), 15.5, epsilon = EXACT);
    assert_abs_diff_eq!(v("DeltaCont", 4.5), 20.0, epsilon = EXACT);
    assert_abs_diff_eq!(v("DeltaCont", 5.0), 25.0, epsilon = EXACT);
    assert_abs_diff_eq!(v("DeltaCont", 7.0), 25.0, epsilon = EXACT);
    assert_abs_diff_eq!(v("Factor", 1.05), 30.0, epsilon = EXACT);
    assert_abs_diff_eq!(v("Factor", 4.0), 30.0, epsilon = EXACT);
    assert_abs_diff_eq!(v("Factor", 4.05), 45.0, epsilon = EXACT);
    // Continuous targets never end by themselves.
    let continuous_ended = events.iter().any(|e| {
        matches!(e, EventRecord::Transition(r)
            if (r.name == "DeltaContSpeed" || r.name == "FactorSpeed")
                && r.transition == Transition::End)
    });
    assert!(!continuous_ended, "a continuous SpeedAction ended");
}
