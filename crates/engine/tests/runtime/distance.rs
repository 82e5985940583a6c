//! LongitudinalDistanceAction and LateralDistanceAction (OpenSCENARIO 1.3 §7.7.2.1, §7.7.2.2)
//! against hand computations, on the scenarios of `tests/files/distance` (README there).
//!
//! The law under test (actions/distance): a critically damped spring a = k·u − 2√k·w,
//! k = 0.4 /m × the tension limit, clamped to the DynamicConstraints; time gap × the
//! reference's speed; freespace = reference-point distance less the boxes' extents. The cars of
//! the fixtures are 5 m × 2 m with the box centre 1.4 m ahead of the reference point: front
//! extent 3.9 m, rear 1.1 m, 1 m to each side. dt = 0.05 s; the actions start at t = 1 s.

use crate::runtime_support;

use std::path::PathBuf;

use engine::output::EventRecord;
use engine::EngineConfig;
use runtime_support::{end_time, run_with, Recorder, Row};

/// The default step (s).
const DT: f64 = 0.05;
/// Values computed by a handful of f64 operations.
const EXACT: f64 = 1e-9;

fn fixture(name: &str) -> PathBuf {
    crate::corpus::fixture("distance").join(name)
}

fn run(name: &str, params: &[(&str, &str)]) -> (Recorder, Vec<EventRecord>) {
    let (_, frames, events) = run_with(&fixture(name), params, EngineConfig::default());
    (frames, events)
}

/// The rows of `name`, in time order.
fn rows<'a>(frames: &'a Recorder, name: &str) -> Vec<&'a Row> {
    frames.0.iter().filter(|r| r.name == name).collect()
}

/// Ref's x minus Ego's x at `t` (both drive along +x on the straight road).
fn gap(frames: &Recorder, t: f64) -> f64 {
    frames.at("Ref", t).x - frames.at("Ego", t).x
}

/// Accelerations (m/s²) between consecutive frames of `name`.
fn accelerations(frames: &Recorder, name: &str) -> Vec<f64> {
    rows(frames, name)
        .windows(2)
        .map(|w| (w[1].speed - w[0].speed) / DT)
        .collect()
}

/// longitudinal_distance.xosc: Ego 50 m behind Ref, both 20 m/s, keeps 30 m between reference
/// points with maxAcceleration 3, maxDeceleration 5.
///
/// First step (t = 1.00 → 1.05): u = 50 − 30 = 20 m (Ego must close up), tension =
/// maxDeceleration = 5 → k = 2 /s², a = 2·20 − 2√2·0 = 40 → clamped to 3 m/s², so the speed
/// at 1.05 is 20 + 3·0.05 = 20.15 m/s. Settling: once the spring is unsaturated (≈ 4 s in)
/// the error decays at least as (1 + ωt)·e^(−ωt) with ω = √(0.4·3) ≈ 1.10 /s (the softer of
/// the two tensions); from ≤ 10 m over 12 s that is below 1e-4 m, so at t = 17 s the gap is
/// 30 m and the speeds agree to 1e-3.
#[test]
fn longitudinal_distance_settles_behind_within_limits() {
    let (frames, _) = run("longitudinal_distance.xosc", &[]);
    assert!((frames.at("Ego", 1.0).speed - 20.0).abs() < EXACT);
    assert!((frames.at("Ego", 1.05).speed - 20.15).abs() < EXACT);
    assert!(
        (gap(&frames, 17.0) - 30.0).abs() < 1e-3,
        "{}",
        gap(&frames, 17.0)
    );
    assert!((frames.at("Ego", 17.0).speed - 20.0).abs() < 1e-3);
    let acc = accelerations(&frames, "Ego");
    let (lo, hi) = acc
        .iter()
        .fold((0.0_f64, 0.0_f64), |(l, h), &a| (l.min(a), h.max(a)));
    assert!(hi <= 3.0 + EXACT, "max acceleration {hi}");
    assert!(lo >= -5.0 - EXACT, "max deceleration {lo}");
    // The limit is reached: the clamp, not the spring, shaped the start.
    assert!(hi >= 3.0 - EXACT);
}

/// longitudinal_time_gap.xosc with freespace: timeGap 1.5 s × Ref's 20 m/s = 30 m between the
/// boxes, i.e. 30 + 3.9 (Ego's front) + 1.1 (Ref's rear) = 35 m between reference points.
#[test]
fn time_gap_with_freespace_keeps_gap_times_reference_speed() {
    let (frames, _) = run("longitudinal_time_gap.xosc", &[("Freespace", "true")]);
    assert!(
        (gap(&frames, 17.0) - 35.0).abs() < 1e-3,
        "{}",
        gap(&frames, 17.0)
    );
    assert!((frames.at("Ego", 17.0).speed - 20.0).abs() < 1e-3);
}

/// leadingReferencedEntity with freespace, 10 m: Ego must stay ahead of Ref with 10 m between
/// Ego's rear (1.1 m behind its reference point) and Ref's front (3.9 m ahead of its): Ego's x
/// − Ref's x = 15 m. Ego starts 10 m ahead (5 m short), so it speeds up. `any` chooses the
/// same side from the start positions (Ref behind).
#[test]
fn leading_displacement_keeps_the_actor_ahead() {
    for displacement in ["leadingReferencedEntity", "any"] {
        let params = [
            ("Displacement", displacement),
            ("Freespace", "true"),
            ("Distance", "10"),
            ("EgoX", "50"),
            ("RefX", "40"),
        ];
        let (frames, _) = run("longitudinal_distance.xosc", &params);
        assert!(frames.at("Ego", 1.05).speed > 20.0, "{displacement}");
        assert!(
            (-gap(&frames, 17.0) - 15.0).abs() < 1e-3,
            "{displacement}: {}",
            -gap(&frames, 17.0)
        );
    }
}

/// Ego closes in at 30 m/s on Ref at 20 m/s from 50 m, to keep 30 m: it must brake. u = 20 m
/// (too far now) but w = +10 m/s: a = 2·20 − 2√2·10 = 11.7 at the start, then the closing speed
/// turns it into braking, clamped at maxDeceleration = 5 m/s², which it reaches.
#[test]
fn braking_stays_within_max_deceleration() {
    let (frames, _) = run("longitudinal_distance.xosc", &[("EgoSpeed", "30")]);
    let acc = accelerations(&frames, "Ego");
    let lo = acc.iter().cloned().fold(f64::INFINITY, f64::min);
    assert!(lo >= -5.0 - EXACT, "max deceleration {lo}");
    assert!(lo <= -5.0 + EXACT, "the limit is never reached: {lo}");
    assert!(acc.iter().all(|&a| a <= 3.0 + EXACT));
    assert!(
        (gap(&frames, 17.0) - 30.0).abs() < 1e-3,
        "{}",
        gap(&frames, 17.0)
    );
}

/// maxAccelerationRate 2 m/s³, maxDecelerationRate 4 m/s³: the acceleration changes by at most
/// 2·0.05 = 0.1 (rising) and 4·0.05 = 0.2 m/s² (falling) per step, so it takes 30 steps to
/// reach the 3 m/s² limit: 20.0 + Σ_{i=1..n} 0.1·i·0.05 m/s after n steps, e.g. 20.0 + 0.005·55
/// = 20.275 m/s at t = 1.5 s (n = 10).
#[test]
fn jerk_limits_bound_the_change_of_acceleration() {
    let params = [("MaxAccRate", "2"), ("MaxDecRate", "4")];
    let (frames, _) = run("longitudinal_distance.xosc", &params);
    let acc = accelerations(&frames, "Ego");
    for w in acc.windows(2) {
        let jerk = (w[1] - w[0]) / DT;
        assert!((-4.0 - 1e-6..=2.0 + 1e-6).contains(&jerk), "jerk {jerk}");
    }
    assert!((frames.at("Ego", 1.5).speed - 20.275).abs() < 1e-9);
}

/// Without DynamicConstraints the actor is put at the distance at once and takes Ref's speed
/// (t = 1.05: 30 m exactly). Ref then speeds up at 2 m/s² (20 → 30 m/s over 5 s from t = 2 s);
/// the action reads Ref's speed before Ref's own action raises it in the step, so each step Ego
/// drives 2·0.05 m/s slower for 0.05 s: the gap is 30 m + at most 2·0.05² = 0.005 m, restored at
/// every step's start.
#[test]
fn rigid_keeping_holds_the_distance_every_step() {
    let (frames, _) = run("longitudinal_rigid.xosc", &[]);
    assert!((gap(&frames, 1.05) - 30.0).abs() < EXACT);
    for r in rows(&frames, "Ego").iter().filter(|r| r.time > 1.04) {
        let g = gap(&frames, r.time);
        assert!(
            (g - 30.0).abs() <= 2.0 * DT * DT + EXACT,
            "t = {}: {g}",
            r.time
        );
    }
    assert!((frames.at("Ego", 9.0).speed - 30.0).abs() < EXACT);
}

/// continuous = false ends when the distance is reached (error ≤ 0.1 m). The action finds it at
/// the first frame within 0.1 m of 30 m (its step's control still applies); the storyboard logs
/// the end at the next step's transitions, so that frame is the one before the logged end, and
/// the frame before it was still farther than 0.1 m.
#[test]
fn non_continuous_longitudinal_ends_when_reached() {
    let (frames, events) = run("longitudinal_distance.xosc", &[("Continuous", "false")]);
    let end = end_time(&events, "Keep").expect("the action ends");
    let reached = end - DT;
    assert!(
        (gap(&frames, reached) - 30.0).abs() <= 0.1,
        "{}",
        gap(&frames, reached)
    );
    assert!((gap(&frames, reached - DT) - 30.0).abs() > 0.1);
    // Ended: Ego keeps the speed of its last step from then on.
    let v = frames.at("Ego", end).speed;
    let after = rows(&frames, "Ego");
    assert!(after
        .iter()
        .filter(|r| r.time >= end)
        .all(|r| (r.speed - v).abs() < EXACT));
}

/// lateral_distance.xosc: Ego at t = 4.5 m, Ref on lane −1's centre (t = −1.535), side by side
/// at 20 m/s; Ego keeps 1 m left of Ref with maxAcceleration = maxDeceleration = 2 m/s²,
/// maxSpeed 0.8 m/s.
///
/// u = −(6.035 − 1) = −5.035 m (to the right). The step that starts the action only sets the
/// lateral speed going (forward Euler): no motion by 1.05. k = 0.4·2 = 0.8, k·u = −4.028 →
/// clamped to −2 m/s², so v = −0.1 m/s and Ego moves 0.005 m right by 1.10, with its heading
/// turned by atan(−0.1 / 20). Afterwards |a| ≤ 2 m/s² and |v| ≤ 0.8 m/s (reached). Settling:
/// at 0.8 m/s the 5 m take ≈ 6 s; from there the spring (ω = √0.8 ≈ 0.89 /s) leaves less than
/// (1 + ωt)·e^(−ωt)·1 m < 1e-3 m after 12 s, so the distance is 1 m at t = 20 s.
#[test]
fn lateral_keeping_approaches_gradually_within_limits() {
    let params = [
        ("EgoY", "4.5"),
        ("MaxSpeed", "0.8"),
        ("MaxAcc", "2"),
        ("MaxDec", "2"),
    ];
    let (frames, _) = run("lateral_distance.xosc", &params);
    let y = |t: f64| frames.at("Ego", t).y;
    assert!((y(1.05) - 4.5).abs() < EXACT);
    assert!((y(1.1) - (4.5 - 0.005)).abs() < EXACT, "{}", y(1.1));
    assert!((frames.at("Ego", 1.1).h - (-0.1_f64 / 20.0).atan()).abs() < EXACT);
    let ys: Vec<f64> = rows(&frames, "Ego").iter().map(|r| r.y).collect();
    let v: Vec<f64> = ys.windows(2).map(|w| (w[1] - w[0]) / DT).collect();
    let a: Vec<f64> = v.windows(2).map(|w| (w[1] - w[0]) / DT).collect();
    assert!(v.iter().all(|v| v.abs() <= 0.8 + 1e-9));
    assert!(
        v.iter().any(|v| v.abs() >= 0.8 - 1e-9),
        "maxSpeed never reached"
    );
    assert!(a.iter().all(|a| a.abs() <= 2.0 + 1e-6));
    assert!(
        (y(20.0) - frames.at("Ref", 20.0).y - 1.0).abs() < 1e-3,
        "{}",
        y(20.0)
    );
}

/// rightToReferencedEntity with freespace, 0.5 m, not continuous: Ref on lane 1 (t = 1.535),
/// Ego on lane −1 (t = −1.535); the boxes' inner sides must be 0.5 m apart, the reference points
/// 0.5 + 1 + 1 = 2.5 m: Ego ends at t = −0.965 (within the 0.01 m of "reached") and stays there.
#[test]
fn lateral_freespace_right_ends_when_reached() {
    let params = [
        ("EgoY", "-1.535"),
        ("RefY", "1.535"),
        ("Displacement", "rightToReferencedEntity"),
        ("Freespace", "true"),
        ("Distance", "0.5"),
        ("Continuous", "false"),
        ("MaxAcc", "2"),
        ("MaxDec", "2"),
    ];
    let (frames, events) = run("lateral_distance.xosc", &params);
    let end = end_time(&events, "Keep").expect("the action ends");
    let y_end = frames.at("Ego", end).y;
    assert!((y_end - (-0.965)).abs() <= 0.01, "{y_end}");
    for r in rows(&frames, "Ego").iter().filter(|r| r.time > end) {
        assert!((r.y - y_end).abs() < EXACT, "moved after the end: {}", r.y);
        assert!(r.h.abs() < EXACT);
    }
}

/// Without DynamicConstraints the actor is put at the distance in the first step: 1 m left of
/// Ref at t = 1.05.
#[test]
fn lateral_rigid_moves_in_one_step() {
    let (frames, _) = run("lateral_rigid.xosc", &[]);
    assert!((frames.at("Ego", 1.0).y - 1.535).abs() < EXACT);
    assert!((frames.at("Ego", 1.05).y - (-1.535 + 1.0)).abs() < EXACT);
}

/// Bad input: distance and timeGap together ("not to be used together") fail with the place.
#[test]
fn distance_and_time_gap_together_is_an_error_with_its_place() {
    let path = fixture("longitudinal_both.xosc");
    let mut engine = engine::Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    let err = engine
        .run(&mut frames, &mut events)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("LongitudinalDistanceAction with either distance or timeGap")
            && err.contains("found both")
            && err.contains("longitudinal_both.xosc:92:15"),
        "{err}"
    );
}

/// longitudinal_rigid.xosc with its action "Keep" keeping, instead of its 30 m, the value it
/// measures at its start (oscsim's `at_start`, no XML form) as `kind`.
fn rigid_kept_from_start(kind: scenario::GapAtStart) -> Recorder {
    use scenario::{ActionKind, LongitudinalAction, PrivateAction};
    let mut scenario =
        scenario::Scenario::load(&fixture("longitudinal_rigid.xosc")).expect("loads");
    let keep = scenario.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0]
        .actions
        .iter_mut()
        .find(|a| a.name == "Keep")
        .expect("the action Keep");
    let ActionKind::Private(PrivateAction::Longitudinal(
        LongitudinalAction::LongitudinalDistance {
            distance, at_start, ..
        },
    )) = &mut keep.kind
    else {
        panic!("Keep is a LongitudinalDistanceAction");
    };
    (*distance, *at_start) = (None, Some(kind));
    let network = engine::load::road_network(&scenario).expect("road loads");
    let mut engine =
        engine::Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::<EventRecord>::new());
    engine.run(&mut frames, &mut events).expect("runs");
    frames
}

/// Kept from the start: at t = 1 s Ego (x 50 + 20·1) is 50 m behind Ref (100 + 20·1), both at
/// 20 m/s, so the rigid action keeps those 50 m (not the file's 30 m): 50 m at 1.05 s, and
/// within 2·dt² of it (as in the test above) while Ref speeds up to 30 m/s. As a time gap it
/// keeps 50 m / 20 m/s = 2.5 s, which is 2.5 × 30 = 75 m once Ref holds 30 m/s (from 7 s):
/// 75 m at 9 s, Ego at 30 m/s.
#[test]
fn a_distance_or_time_gap_kept_from_the_start_is_the_one_measured_then() {
    let frames = rigid_kept_from_start(scenario::GapAtStart::Distance);
    assert!((gap(&frames, 1.05) - 50.0).abs() < EXACT);
    for r in rows(&frames, "Ego").iter().filter(|r| r.time > 1.04) {
        let g = gap(&frames, r.time);
        assert!(
            (g - 50.0).abs() <= 2.0 * DT * DT + EXACT,
            "t = {}: {g}",
            r.time
        );
    }
    let frames = rigid_kept_from_start(scenario::GapAtStart::TimeGap);
    assert!((gap(&frames, 1.05) - 50.0).abs() < EXACT);
    assert!(
        (gap(&frames, 9.0) - 75.0).abs() < EXACT,
        "{}",
        gap(&frames, 9.0)
    );
    assert!((frames.at("Ego", 9.0).speed - 30.0).abs() < EXACT);
}
