//! Actions against closed forms (OpenSCENARIO 1.3 §7.7.2): SpeedAction with a linear shape,
//! LaneChangeAction with a sinusoidal shape, TeleportAction to a LanePosition.

use crate::runtime_support;

use approx::assert_abs_diff_eq;
use opendrive::{normalize_angle, RoadNetwork};
use runtime_support::{file, run};

/// Tolerance for values that are sums of a few dozen f64 terms.
const EXACT: f64 = 1e-9;

/// speed_linear.xosc: from rest to 20 m/s in T = 4 s, linear in time, from s0 = 10 m, dt = 0.05 s.
///
/// Continuous closed forms: v(t) = 5 t, s(t) = s0 + 2.5 t². The runtime sets in step k the speed
/// of the step's end, v((k+1)·dt), and moves with it (stage 2 before stage 3), so after n steps
/// s = s0 + Σ_{i=1..n} 5·i·dt·dt = s0 + 2.5·t² + 2.5·t·dt, t = n·dt: the closed form plus the
/// scheme's first-order term a·t·dt/2 (a = 5 m/s²). After T the speed stays 20 m/s.
#[test]
fn speed_action_linear_time_matches_closed_form() {
    let (_, frames, _) = run("speed_linear.xosc");
    let dt = 0.05;
    for t in [0.5, 1.0, 2.0, 3.0, 4.0] {
        let row = frames.at("Ego", t);
        assert_abs_diff_eq!(row.speed, 5.0 * t, epsilon = EXACT);
        let s = row.road.as_ref().map(|r| r.2).unwrap_or(f64::NAN);
        assert_abs_diff_eq!(s, 10.0 + 2.5 * t * t + 2.5 * t * dt, epsilon = EXACT);
        // The scheme's distance exceeds the continuous one by a·t·dt/2 only.
        assert!((s - (10.0 + 2.5 * t * t) - 2.5 * t * dt).abs() < EXACT);
    }
    // t = 6 s: 2 s more at 20 m/s from 50.5 m.
    let row = frames.at("Ego", 6.0);
    assert_abs_diff_eq!(row.speed, 20.0, epsilon = EXACT);
    assert_abs_diff_eq!(row.x, 90.5, epsilon = EXACT);
}

/// lane_change_sinusoidal.xosc: lane -1 to lane 1 of straight_500m.xodr, each 3.07 m wide
/// (`<width a="3.07…">`), so the centres are at t = −1.535 and +1.535 and Δt = 3.07 m. The
/// change starts at 1.0 s and lasts 2 s; at half time f(½) = (1 − cos(π/2))/2 = ½, so t = 0.
/// At 1.5 s (p = ¼) f = (1 − cos(π/4))/2 ≈ 0.1464466, so t = −1.535 + 3.07·f.
#[test]
fn lane_change_sinusoidal_is_halfway_at_half_time() {
    let (_, frames, events) = run("lane_change_sinusoidal.xosc");
    let lateral = |time: f64| {
        frames
            .at("Ego", time)
            .road
            .as_ref()
            .map(|r| r.3)
            .unwrap_or(f64::NAN)
    };
    assert_abs_diff_eq!(lateral(1.0), -1.535, epsilon = EXACT);
    assert_abs_diff_eq!(lateral(2.0), 0.0, epsilon = EXACT);
    let quarter = (1.0 - std::f64::consts::FRAC_PI_4.cos()) / 2.0;
    assert_abs_diff_eq!(lateral(1.5), -1.535 + 3.07 * quarter, epsilon = EXACT);
    let end = frames.at("Ego", 3.5);
    let (_, lane, _, t, offset) = end.road.clone().unwrap_or_default();
    assert_eq!(lane, 1);
    assert_abs_diff_eq!(t, 1.535, epsilon = EXACT);
    assert_abs_diff_eq!(offset, 0.0, epsilon = EXACT);
    // Zero slope at both ends: heading equals the road's (0 rad) once the change is over.
    assert_abs_diff_eq!(end.h, 0.0, epsilon = EXACT);
    // The action starts at 1.0 s and ends when p reaches 1, in the step of 3.0 s.
    let started = events.iter().any(|e| {
        matches!(e, engine::EventRecord::Transition(r)
        if r.name == "Action" && r.transition == engine::storyboard::Transition::Start
            && (r.time - 1.0).abs() < 1e-9)
    });
    assert!(started, "the lane change starts at 1.0 s");
}

/// teleport_lane.xosc: LanePosition road 0, lane 1, s = 50, offset 0.3 → exactly the road
/// model's lane_pose, heading turned by π because lane 1 is driven towards −s (right-hand
/// traffic, OpenDRIVE 1.8 §11.2; semantics-pitfalls #15).
#[test]
fn teleport_to_lane_position_is_lane_pose() {
    let (_, frames, _) = run("teleport_lane.xosc");
    let net = RoadNetwork::from_file(&file("junction_trippel_twoway0.xodr")).expect("road loads");
    let pose = net.lane_pose("0", 1, 50.0, 0.3).expect("lane exists");
    let row = frames.at("Ego", 0.0);
    assert_abs_diff_eq!(row.x, pose.x, epsilon = EXACT);
    assert_abs_diff_eq!(row.y, pose.y, epsilon = EXACT);
    assert_abs_diff_eq!(row.z, pose.z, epsilon = EXACT);
    assert_abs_diff_eq!(
        normalize_angle(row.h - pose.h - std::f64::consts::PI),
        0.0,
        epsilon = EXACT
    );
    let (road, lane, s, _, offset) = row.road.clone().unwrap_or_default();
    assert_eq!((road.as_str(), lane), ("0", 1));
    assert_abs_diff_eq!(s, 50.0, epsilon = 1e-6);
    assert_abs_diff_eq!(offset, 0.3, epsilon = 1e-6);
}

/// lane_offset_sinusoidal.xosc: offset 0 → 1.0 m, sinusoidal, maxLateralAcc a = π²/8 m/s².
/// A sinusoidal change d over T peaks at d·π²/(2T²) lateral acceleration, so T = π·√(d/(2a))
/// = 2 s, starting at 1.0 s: offset ½ at 2.0 s, 1 at 3.0 s. At half time the lateral speed is
/// d·(π/2)/T = π/4 m/s, a share π/80 of the 20 m/s along the path, so the path leaves the lane
/// at asin(π/80) and that is the heading (road heading 0; runtime_lateral.rs shows the
/// heading follows the motion).
#[test]
fn lane_offset_sinusoidal_duration_from_max_lateral_acc() {
    let (_, frames, _) = run("lane_offset_sinusoidal.xosc");
    let offset = |time: f64| {
        frames
            .at("Ego", time)
            .road
            .as_ref()
            .map(|r| r.4)
            .unwrap_or(f64::NAN)
    };
    assert_abs_diff_eq!(offset(1.0), 0.0, epsilon = EXACT);
    assert_abs_diff_eq!(offset(2.0), 0.5, epsilon = EXACT);
    assert_abs_diff_eq!(offset(3.0), 1.0, epsilon = EXACT);
    assert_abs_diff_eq!(offset(3.5), 1.0, epsilon = EXACT);
    let share = std::f64::consts::PI / 80.0;
    assert_abs_diff_eq!(frames.at("Ego", 2.0).h, share.asin(), epsilon = EXACT);
}

/// lane_offset_sinusoidal.xosc with continuous="true" (issue 34 class 5). XSD
/// LaneOffsetAction.continuous: "If false, the action ends when the target lane offset is
/// reached. If true it does not end but can only be stopped." The offset follows the same
/// sinusoid (½ at 2.0 s, 1 at 3.0 s) and is then held; the action is still running when the
/// stop trigger ends the run at 4 s (esmini ends it once the offset is reached: not followed).
#[test]
fn a_continuous_lane_offset_holds_the_offset_and_does_not_end() {
    let (_, frames, events) = runtime_support::run_with(
        &file("lane_offset_sinusoidal.xosc"),
        &[("Continuous", "true")],
        engine::EngineConfig::default(),
    );
    let offset = |time: f64| {
        frames
            .at("Ego", time)
            .road
            .as_ref()
            .map_or(f64::NAN, |r| r.4)
    };
    assert_abs_diff_eq!(offset(2.0), 0.5, epsilon = EXACT);
    for t in [3.0, 3.5, 4.0] {
        assert_abs_diff_eq!(offset(t), 1.0, epsilon = EXACT);
    }
    // The action ends only with the storyboard's stop at 4 s (a stop transition, no earlier
    // end); with continuous false it ends in the step that reaches 1.0 m, [2.95, 3.0] s,
    // logged at that step's start.
    assert_eq!(runtime_support::end_time(&events, "Action"), None);
    let (_, _, once) = run("lane_offset_sinusoidal.xosc");
    let end = runtime_support::end_time(&once, "Action").expect("ends");
    assert_abs_diff_eq!(end, 2.95, epsilon = EXACT);
}

/// trajectory_reverse.xosc: Init sets −5 m/s, then FollowTrajectoryAction (no time reference)
/// on the polyline (20, 50) → (40, 50), 20 m long with tangent +x, 50 m off the road. Reverse
/// gear: Ego travels the polyline from its start at |v| = 5 m/s, facing against the tangent
/// (h = π): x(t) = 20 + 5·t, so x(1) = 25, and the end x = 40 at t = 4 s. Then the default
/// controller moves it on at −5 m/s along h = π, i.e. towards +x: x(5) = 40 + 5 = 45.
#[test]
fn negative_speed_drives_a_trajectory_in_reverse() {
    let (_, frames, _) = run("trajectory_reverse.xosc");
    for (t, x) in [(0.0, 20.0), (1.0, 25.0), (4.0, 40.0), (5.0, 45.0)] {
        let row = frames.at("Ego", t);
        assert_abs_diff_eq!(row.x, x, epsilon = 1e-9);
        assert_abs_diff_eq!(row.y, 50.0, epsilon = 1e-9);
        assert_abs_diff_eq!(
            normalize_angle(row.h - std::f64::consts::PI),
            0.0,
            epsilon = 1e-9
        );
        assert_abs_diff_eq!(row.speed, -5.0, epsilon = 1e-12);
    }
}

/// trajectory_timed_start.xosc: Ego, at rest and never teleported, follows from Init a polyline
/// on lane −1 of straight_500m.xodr (s = x, centre t = −1.535) from x = 20 at time 0 to x = 40 at
/// time 2 (Timing relative, offset 0, scale 1): 20 m / 2 s = 10 m/s. The frame at t = 0 already
/// shows that speed and the road position (road 1, lane −1, s = 20); at t = 1 s, x = 30.
#[test]
fn timed_trajectory_sets_speed_and_road_position_from_the_first_frame() {
    let (_, frames, _) = run("trajectory_timed_start.xosc");
    let first = frames.at("Ego", 0.0);
    assert_abs_diff_eq!(first.speed, 10.0, epsilon = 1e-9);
    let (road, lane, s, t, _) = first.road.clone().expect("on the road at t = 0");
    assert_eq!((road.as_str(), lane), ("1", -1));
    assert_abs_diff_eq!(s, 20.0, epsilon = 1e-9);
    assert_abs_diff_eq!(t, -1.535, epsilon = 1e-9);
    let later = frames.at("Ego", 1.0);
    assert_abs_diff_eq!(later.x, 30.0, epsilon = 1e-9);
    assert_abs_diff_eq!(later.speed, 10.0, epsilon = 1e-9);
}
