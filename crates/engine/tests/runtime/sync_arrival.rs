//! SynchronizeAction (OpenSCENARIO 1.3 §7.7.2 private actions) against hand computations.
//!
//! Every scenario in tests/files/sync shares one set-up on the straight 500 m road (lane −1,
//! along +x): the master Ego starts at s = 50 m at a constant 10 m/s and its target is at
//! s = 250 m, so it arrives at T = 200 / 10 = 20 s. The NPC starts at s = 0 m at 5 m/s and
//! its target is at s = 300 m. Both tolerances are 0. The step is dt = 0.05 s.

use crate::runtime_support;

use engine::output::EventRecord;
use engine::storyboard::{ElementState, TransitionRecord};
use engine::{Engine, EngineConfig};
use runtime_support::{Recorder, Row};

/// The step length (s).
const DT: f64 = 0.05;
/// The master's arrival time (s): 200 m at 10 m/s.
const T: f64 = 20.0;

/// Runs `tests/files/sync/NAME.xosc` to its end.
fn run(name: &str) -> (Recorder, Vec<EventRecord>) {
    let (_, frames, events) = runtime_support::run(&format!("../sync/{name}.xosc"));
    (frames, events)
}

/// The NPC's rows in time order.
fn npc(frames: &Recorder) -> Vec<&Row> {
    frames.0.iter().filter(|r| r.name == "NPC").collect()
}

fn s_of(r: &Row) -> f64 {
    r.road.as_ref().map_or(f64::NAN, |p| p.2)
}

/// The time the NPC passes s = `at`, interpolated linearly between frames.
fn passing_time(rows: &[&Row], at: f64) -> f64 {
    for w in rows.windows(2) {
        let (a, b) = (s_of(w[0]), s_of(w[1]));
        if a < at && b >= at {
            return w[0].time + (at - a) / (b - a) * (w[1].time - w[0].time);
        }
    }
    panic!("the NPC never passes s = {at}");
}

/// The speed of the first frame at or after time `t`.
fn speed_at(rows: &[&Row], t: f64) -> f64 {
    rows.iter()
        .find(|r| r.time >= t - 1e-9)
        .map_or(f64::NAN, |r| r.speed)
}

/// The time the NPC's SynchronizeAction (an Init action) completes.
fn sync_end(events: &[EventRecord]) -> f64 {
    events
        .iter()
        .find_map(|e| match e {
            EventRecord::Transition(TransitionRecord { time, name, to, .. })
                if name == "Init NPC SynchronizeAction" && *to == ElementState::Complete =>
            {
                Some(*time)
            }
            _ => None,
        })
        .unwrap_or(f64::NAN)
}

/// Final speed 20 m/s. The profile (module doc of actions/synchronize.rs) covers
/// s = 300 m in t = 20 s from v0 = 5 to v1 = 20 with a peak, since s/t = 15 > (v0 + v1)/2 =
/// 12.5: v_x = 15 + √(((300 − 100)² + (300 − 400)²) / 2) / 20 = 15 + √25000 / 20 = 22.9057 m/s,
/// a = (2·22.9057 − 25) / 20 = 1.04057 m/s², reached at x = (22.9057 − 5) / 1.04057 = 17.207 s.
#[test]
fn arrives_with_the_master_at_the_final_speed() {
    let (frames, events) = run("sync_final_absolute");
    let rows = npc(&frames);
    let arrival = passing_time(&rows, 300.0);
    assert!(
        (arrival - T).abs() < DT,
        "arrival {arrival} s, master arrives at {T} s"
    );
    // The speed at arrival is the final speed, up to one step of the last phase's change
    // (its slope is (22.9 − 20) / (20 − 17.2) ≈ 1.04 m/s² → 0.052 m/s per step).
    let v = speed_at(&rows, arrival);
    assert!((v - 20.0).abs() < 0.06, "speed at arrival {v}");
    // Peak speed and its time, from the closed form above. The runtime moves each step with
    // the speed of the step's end, a·dt/2 = 0.026 m per step more than the continuous
    // profile (0.45 m by the peak), and re-plans from there, which lowers the peak a little:
    // allow two steps of acceleration, 2·1.04·0.05 ≈ 0.1 m/s.
    let peak = rows.iter().map(|r| r.speed).fold(0.0, f64::max);
    assert!((peak - 22.9057).abs() < 0.105, "peak {peak}");
    let peak_time = rows
        .iter()
        .find(|r| r.speed >= peak - 1e-12)
        .map_or(f64::NAN, |r| r.time);
    assert!((peak_time - 17.207).abs() < 2.0 * DT, "peak at {peak_time}");
    // Acceleration of the first phase: 1.04057 m/s² (speed 5 + 1.04057·t).
    assert!((speed_at(&rows, 10.0) - (5.0 + 1.04057 * 10.0)).abs() < 0.06);
    let end = sync_end(&events);
    assert!((end - T).abs() <= DT + 1e-9, "action ends at {end}");
}

/// No final speed: constant acceleration a = 2·(s − v0·T) / T² = 2·(300 − 100) / 400 =
/// 1 m/s², arriving at v0 + a·T = 25 m/s.
#[test]
fn without_final_speed_accelerates_constantly() {
    let (frames, _) = run("sync_no_final_speed");
    let rows = npc(&frames);
    let arrival = passing_time(&rows, 300.0);
    assert!((arrival - T).abs() < DT, "arrival {arrival}");
    for t in [2.0, 8.0, 14.0, 19.0] {
        let v = speed_at(&rows, t);
        // Re-planned each step, the discrete scheme stays within a few steps' change.
        assert!((v - (5.0 + t)).abs() < 0.15, "speed {v} at {t}");
    }
}

/// TargetDistanceSteadyState 50 m: the profile plans for 250 m in 20 − 50/20 = 17.5 s and
/// then holds 20 m/s; the NPC passes s = 250 at 17.5 s and arrives at s = 300 at 20 s.
#[test]
fn steady_distance_holds_the_final_speed() {
    let (frames, _) = run("sync_steady_distance");
    let rows = npc(&frames);
    let start = passing_time(&rows, 250.0);
    assert!((start - 17.5).abs() < 2.0 * DT, "steady state from {start}");
    for r in rows.iter().filter(|r| s_of(r) > 251.0 && r.time < T - 1e-9) {
        assert!(
            (r.speed - 20.0).abs() < 1e-9,
            "{} m/s at {}",
            r.speed,
            r.time
        );
    }
    let arrival = passing_time(&rows, 300.0);
    assert!((arrival - T).abs() < DT, "arrival {arrival}");
}

/// RelativeSpeedToMaster delta +10 → 20 m/s; TargetTimeSteadyState 2.5 s at 20 m/s is the
/// 50 m of the test above, so the same numbers hold.
#[test]
fn relative_final_speed_with_steady_time() {
    let (frames, _) = run("sync_relative_time");
    let rows = npc(&frames);
    let start = passing_time(&rows, 250.0);
    assert!((start - 17.5).abs() < 2.0 * DT, "steady state from {start}");
    let arrival = passing_time(&rows, 300.0);
    assert!((arrival - T).abs() < DT, "arrival {arrival}");
    assert!((speed_at(&rows, arrival) - 20.0).abs() < 1e-9);
}

/// maxAcceleration 0.5 m/s² (Performance): the speed never grows faster than 0.5·dt per step,
/// so in 20 s the NPC covers at most 5·20 + 0.25·400 = 200 m < 300 m and arrives late.
#[test]
fn performance_limits_bound_the_profile() {
    let (frames, _) = run("sync_limited");
    let rows = npc(&frames);
    for w in rows.windows(2) {
        let dv = w[1].speed - w[0].speed;
        assert!(dv <= 0.5 * DT + 1e-9, "dv {dv} at {}", w[1].time);
    }
    let s20 = rows
        .iter()
        .find(|r| r.time >= T - 1e-9)
        .map_or(f64::NAN, |r| s_of(r));
    assert!(s20 <= 200.0 + 1.0, "s at 20 s: {s20}");
}

/// sync_bad_master.xosc: masterEntityRef="Nobody" at line 73, column 49. Loading fails with an
/// error naming the attribute, the name and the place.
#[test]
fn unknown_master_names_the_attribute() {
    let path = runtime_support::file("../sync/sync_bad_master.xosc");
    let err = Engine::load(&path, &[], EngineConfig::default()).expect_err("Nobody is unknown");
    let message = err.to_string();
    assert!(
        message.contains("SynchronizeAction@masterEntityRef"),
        "{message}"
    );
    assert!(message.contains("Nobody"), "{message}");
    assert!(message.contains("sync_bad_master.xosc:73:49"), "{message}");
}
