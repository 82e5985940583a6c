//! SpeedProfileAction (OpenSCENARIO 1.3 §7.7.2.1, XSD `SpeedProfileAction`) in both following
//! modes, against hand-worked speeds and against esmini's reference run of speed-profile.xosc.
//!
//! The model documentation of `followingMode`: `position` applies "strictly linear
//! interpolation between speed target values"; `follow` applies "jerk (change rate of
//! acceleration/deceleration) and other optional constraints … resulting in a smoother speed
//! profile curve. For mode=follow the acceleration is zero at the start and end of the profile."
//!
//! speed_profile_modes.xosc: two cars at rest; at t = 1 s each starts the profile
//! 8 m/s after 4 s, 4 m/s after $T2 s, 10 m/s after $T3 s, with DynamicConstraints
//! maxAcceleration 4, maxDeceleration 6, maxAccelerationRate 2, maxDecelerationRate 4.
//! The runtime sets in each step the speed planned for the step's end, so the frame at time t
//! shows v(t).

use crate::runtime_support;

use approx::assert_abs_diff_eq;
use engine::storyboard::Transition;
use engine::{Engine, EngineConfig, EventRecord};
use runtime_support::{
    corpus, end_time, esmini_reference, esmini_reference_events, file, first_transition, run_with,
    Recorder,
};

/// Tolerance for speeds that are a few f64 operations from the closed form.
const EXACT: f64 = 1e-9;
/// Time step of the runs (s), EngineConfig's default.
const DT: f64 = 0.05;

/// Runs speed_profile_modes.xosc with T2 and T3 set.
fn run_modes(t2: &str, t3: &str) -> (Recorder, Vec<EventRecord>) {
    let path = file("speed_profile_modes.xosc");
    let (_, frames, events) = run_with(&path, &[("T2", t2), ("T3", t3)], EngineConfig::default());
    (frames, events)
}

/// Time of the step in which action `name` ends.
fn end_step(events: &[EventRecord], name: &str) -> f64 {
    end_time(events, name).unwrap_or_else(|| panic!("{name} never ends"))
}

/// `position`: vertices (1, 0), (5, 8), (9, 4), (12, 10) joined by straight lines, whatever the
/// constraints: v = 2(t − 1) up to 5 s, 8 − (t − 5) up to 9 s, 4 + 2(t − 9) up to 12 s.
#[test]
fn position_mode_reaches_each_entry_at_its_time() {
    let (frames, events) = run_modes("4", "3");
    for (t, v) in [
        (1.0, 0.0),
        (3.0, 4.0),
        (5.0, 8.0),
        (7.0, 6.0),
        (9.0, 4.0),
        (10.5, 7.0),
        (12.0, 10.0),
        (13.0, 10.0),
    ] {
        assert_abs_diff_eq!(frames.at("Position", t).speed, v, epsilon = EXACT);
    }
    // The last entry is reached at 12 s: the action ends in the step 11.95 … 12 s whose motion
    // completes it (esmini's log: 11.950 for Car2 of speed-profile.xosc).
    assert_abs_diff_eq!(end_step(&events, "PositionProfile"), 11.95, epsilon = EXACT);
}

/// `follow` on the same profile. The lines of the segments are L0: v = 2t − 2, L1: v = 13 − t,
/// L2: v = 2t − 14, then v = 10 from 12 s. Each change of slope Δk is a ramp of constant jerk
/// lasting |Δk| / rate, centred where the two lines cross; a ramp that cannot start in time
/// starts as soon as it can and lands on the next line shifted later.
///
/// - start: acceleration 0 → 2 at jerk 2, 1 s from 1 s (it cannot begin before the action), so
///   v(1.5) = ½·2·0.5² = 0.25, v(2) = 1, and the car then rides v = 2t − 3 (L0 ½ s late).
/// - 2t − 3 meets L1 at t = 16/3; Δk = −3 at jerk 4 lasts 0.75 s: ramp from 4.958 3̅ s at
///   v = 6.916 6̅, so v(5) = 6.916 6̅ + 2·(1/24) − 2·(1/24)² = 6.996 527 7̅ and
///   v(5.5) = 6.916 6̅ + 2·(13/24) − 2·(13/24)² = 7.413 194 4̅; on L1 from 5.708 3̅ s: v(7) = 6.
/// - L1 meets L2 at 9 s; Δk = +3 at jerk 2 lasts 1.5 s, from 8.25 s (v = 4.75):
///   v(9) = 4.75 − 0.75 + ½·2·0.75² = 4.5625; on L2 from 9.75 s: v(11) = 8.
/// - L2 meets v = 10 at 12 s; Δk = −2 at jerk 4 lasts 0.5 s, from 11.75 s (v = 9.5):
///   v(12) = 9.5 + 2·0.25 − ½·4·0.25² = 9.875, and 10 from 12.25 s, where the action is
///   complete.
#[test]
fn follow_mode_rounds_each_corner_with_a_jerk_ramp() {
    let (frames, events) = run_modes("4", "3");
    for (t, v) in [
        (1.0, 0.0),
        (1.5, 0.25),
        (2.0, 1.0),
        (4.5, 6.0),
        (5.0, 6.916_666_666_666_667 + 2.0 / 24.0 - 2.0 / 576.0),
        (
            5.5,
            6.916_666_666_666_667 + 26.0 / 24.0 - 2.0 * 169.0 / 576.0,
        ),
        (7.0, 6.0),
        (9.0, 4.5625),
        (11.0, 8.0),
        (12.0, 9.875),
        (12.5, 10.0),
    ] {
        assert_abs_diff_eq!(frames.at("Follow", t).speed, v, epsilon = EXACT);
    }
    // Complete at 12.25 s: it ends in the step 12.2 … 12.25 s.
    assert_abs_diff_eq!(end_step(&events, "FollowProfile"), 12.2, epsilon = EXACT);
}

/// `follow` keeps within the constraints: per step, the mean acceleration stays within
/// [−6, 4] m/s², and it changes by at most 2·dt upwards and 4·dt downwards (the jerk limits);
/// it starts from 0 (the first step's mean is v(1.05)/dt = ½·2·0.05²/0.05 = 0.05 m/s²) and ends
/// at 0.
#[test]
fn follow_mode_stays_within_the_dynamic_constraints() {
    let (frames, _) = run_modes("4", "3");
    let speeds: Vec<f64> = frames
        .0
        .iter()
        .filter(|r| r.name == "Follow" && r.time >= 1.0 - 1e-9)
        .map(|r| r.speed)
        .collect();
    let accelerations: Vec<f64> = speeds.windows(2).map(|w| (w[1] - w[0]) / DT).collect();
    assert_abs_diff_eq!(accelerations[0], 0.05, epsilon = 1e-9);
    for a in &accelerations {
        assert!((-6.0 - 1e-9..=4.0 + 1e-9).contains(a), "acceleration {a}");
    }
    for w in accelerations.windows(2) {
        let change = w[1] - w[0];
        assert!(
            (-4.0 * DT - 1e-9..=2.0 * DT + 1e-9).contains(&change),
            "change of acceleration {change} in one step"
        );
    }
    assert_abs_diff_eq!(accelerations[accelerations.len() - 1], 0.0, epsilon = EXACT);
}

/// `follow` when the corners crowd each other: T2 = 2, T3 = 1.5 give the lines L0: v = 2t − 2,
/// L1: v = 18 − 2t, L2: v = 4t − 24 and v = 10 from 8.5 s.
///
/// - start as before: on v = 2t − 3 from 2 s.
/// - it meets L1 at 5.25 s; Δk = −4 at jerk 4 lasts 1 s: 4.75 … 5.75 s, landing on L1 at 6.5.
/// - L1 meets L2 at 7 s; Δk = +6 at jerk 2 lasts 3 s, which would start at 5.5 s, before the
///   previous ramp ends: it runs 5.75 … 8.75 s, v(8.5) = 6.5 − 2·2.75 + ½·2·2.75² = 8.5625,
///   landing at v = 6.5 + 3·(−2 + 3) = 9.5 with slope 4.
/// - the level 10 is then 0.125 s away, less than half of the 1 s the jerk limit needs to bring
///   4 m/s² to 0, so the last ramp lands on 10 exactly with the jerk that fits: a from 4 to 0
///   over 2·0.5/4 = 0.25 s (16 m/s³), v(8.875) = 9.5 + 4·0.125 − ½·16·0.125² = 9.875, and 10
///   from 9 s, where the action ends.
#[test]
fn follow_mode_lands_on_the_last_speed_when_corners_crowd() {
    let (frames, events) = run_modes("2", "1.5");
    let at = |t: f64| frames.at("Follow", t).speed;
    // The frames are every 0.05 s; 8.875 s is not one, so check the ramp at 8.85 and 8.9.
    assert_abs_diff_eq!(at(5.25), 6.5 + 2.0 * 0.5 - 2.0 * 0.25, epsilon = EXACT);
    assert_abs_diff_eq!(at(8.5), 8.5625, epsilon = EXACT);
    assert_abs_diff_eq!(at(8.75), 9.5, epsilon = EXACT);
    assert_abs_diff_eq!(at(8.85), 9.5 + 0.4 - 8.0 * 0.01, epsilon = EXACT);
    assert_abs_diff_eq!(at(8.9), 9.5 + 0.6 - 8.0 * 0.0225, epsilon = EXACT);
    assert_abs_diff_eq!(at(9.0), 10.0, epsilon = EXACT);
    assert_abs_diff_eq!(end_step(&events, "FollowProfile"), 8.95, epsilon = EXACT);
    // Position mode meets every vertex on time: (5, 8), (7, 4), (8.5, 10).
    let pos = |t: f64| frames.at("Position", t).speed;
    assert_abs_diff_eq!(pos(5.0), 8.0, epsilon = EXACT);
    assert_abs_diff_eq!(pos(7.0), 4.0, epsilon = EXACT);
    assert_abs_diff_eq!(pos(8.5), 10.0, epsilon = EXACT);
}

/// speed_profile_untimed.xosc: from rest at 1 s, 10 m/s without a time, then 4 m/s with time 0,
/// held for 1 s; maxAcceleration 4, maxDeceleration 6, no jerk limit. The entry without a time
/// is reached at the acceleration limit: 10/4 = 2.5 s, at 3.5 s, in both modes (v(2) = 4,
/// v(3.45) = 9.8). Time 0 is a jump in `position` (4 m/s from the 3.5 s frame); `follow`
/// observes maxDeceleration instead, v = 10 − 6(t − 3.5), reaching 4 at 4.5 s (v(4) = 7).
/// Without a jerk limit the corners stay sharp. Both end at 4.5 s, in the step 4.45 … 4.5 s.
#[test]
fn entries_without_time_or_with_time_zero() {
    let (_, frames, events) = run_with(
        &file("speed_profile_untimed.xosc"),
        &[],
        EngineConfig::default(),
    );
    for (t, follow, position) in [
        (2.0, 4.0, 4.0),
        (3.45, 9.8, 9.8),
        (3.5, 10.0, 4.0),
        (4.0, 7.0, 4.0),
        (4.5, 4.0, 4.0),
        (5.0, 4.0, 4.0),
    ] {
        assert_abs_diff_eq!(frames.at("Follow", t).speed, follow, epsilon = EXACT);
        assert_abs_diff_eq!(frames.at("Position", t).speed, position, epsilon = EXACT);
    }
    for action in ["FollowProfile", "PositionProfile"] {
        assert_abs_diff_eq!(end_step(&events, action), 4.45, epsilon = EXACT);
    }
}

/// speed_relative.xosc, entity Profile: a `position` SpeedProfileAction with entityRef Lead
/// ("the speed values will be interpreted as relative delta to the speed of the referenced
/// entity") from 10 m/s at 1 s: Lead − 5 after 2 s, Lead + 5 2 s later. oscsim takes Lead's
/// speed when the action starts (20 m/s, as esmini does; the standard does not say when), so
/// the vertices are (1, 10), (3, 15), (5, 25): v(2) = 12.5, v(4) = 20, and Lead's step to
/// 30 m/s at 4 s does not move them.
#[test]
fn relative_profile_is_offset_from_the_reference_speed_at_the_start() {
    let (_, frames, _) = run_with(&file("speed_relative.xosc"), &[], EngineConfig::default());
    for (t, v) in [
        (2.0, 12.5),
        (3.0, 15.0),
        (4.0, 20.0),
        (4.5, 22.5),
        (5.0, 25.0),
        (7.0, 25.0),
    ] {
        assert_abs_diff_eq!(frames.at("Profile", t).speed, v, epsilon = EXACT);
    }
    assert_abs_diff_eq!(frames.at("Lead", 4.5).speed, 30.0, epsilon = EXACT);
}

/// XSD SpeedProfileEntry@time has the range [0..inf[: a negative time ($T2 = −1, the second
/// entry) stops the run with an error naming it and the Action's place (line 72, column 15 of
/// speed_profile_modes.xosc), instead of being read as a missing time.
#[test]
fn negative_entry_time_is_an_error_with_its_place() {
    let path = file("speed_profile_modes.xosc");
    let params = [("T2".to_owned(), "-1".to_owned())];
    let mut engine = Engine::load(&path, &params, EngineConfig::default())
        .unwrap_or_else(|e| panic!("speed_profile_modes.xosc does not load: {e}"));
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    let Err(error) = engine.run(&mut frames, &mut events) else {
        panic!("a negative SpeedProfileEntry time ran");
    };
    let message = error.to_string();
    assert!(
        message.contains(
            "expected a SpeedProfileEntry time of 0 s or more, found time -1 in SpeedProfileEntry 2"
        ) && message.contains("speed_profile_modes.xosc:72:15"),
        "{message}"
    );
}

/// esmini's speed-profile.xosc (Car1 follow, Car2 position, the same four entries and
/// DynamicConstraints) against esmini 3.6.0's run in reference/esmini/speed-profile.csv: the
/// speeds agree at every reference row to within the CSV's rounding (3 decimals), and each
/// action ends in the step esmini's log (speed-profile.events.txt) gives.
#[test]
fn speed_profile_corpus_speeds_match_the_esmini_reference() {
    let path = corpus("esmini/xosc/speed-profile.xosc");
    let (_, frames, events) = run_with(&path, &[], EngineConfig::default());
    let log = esmini_reference_events("speed-profile");
    for action in ["SpeedProfileAction1", "SpeedProfileAction2"] {
        let esmini = first_transition(&log, action, Transition::End)
            .unwrap_or_else(|| panic!("no end of {action} in esmini's log"));
        assert_abs_diff_eq!(end_step(&events, action), esmini, epsilon = 1e-6);
    }
    let mut compared = 0;
    for esmini in esmini_reference("speed-profile") {
        let (time, name, speed) = (esmini.time, esmini.name.as_str(), esmini.speed);
        if time > 14.0 {
            continue;
        }
        let ours = frames.at(name, time).speed;
        assert!(
            (ours - speed).abs() <= 1e-3,
            "{name} at {time} s: {ours} m/s, esmini {speed} m/s"
        );
        compared += 1;
    }
    // 0 … 14 s every 0.1 s, two cars.
    assert_eq!(compared, 2 * 141);
}
