//! Class 5 — trajectory-based synchronisation for pedestrians (OpenSCENARIO 1.3
//! SynchronizeAction: the actor reaches its target position when the master reaches its own;
//! FollowTrajectoryAction without a time reference holds the lateral domain only, so the speed
//! along the trajectory is the SynchronizeAction's). The actor's remaining distance is the arc
//! length along its trajectory (`actions::synchronize`), not |Δs| along the road it crosses
//! (0 for a pedestrian crossing at one s, which ended the action at once before).
//!
//! Fixture `pedestrian_sync.xosc`: Car at 10 m/s, 100 m from its target: T = 10 s. Walker,
//! at rest, must cover 16 m along its Polyline in 10 s: without a final speed the plan is the
//! constant acceleration a = 2·(16 − 0·10) / 10² = 0.32 m/s², s(t) = 0.16·t², v(10) = 3.2 m/s.

use crate::support::run;

/// The plan is re-made each 0.05 s step and the motion integrated step-wise (position with the
/// step's end speed): a few centimetres from the closed form.
const PLAN_TOL: f64 = 0.1;

#[test]
fn a_pedestrian_crossing_on_a_trajectory_meets_the_car() {
    let (_, rows, _) = run("pedestrian_sync.xosc", &[]);
    // t = 5 s: s = 0.16 · 25 = 4 m along, y = −8 + 4 = −4; v = 1.6 m/s.
    let w = rows.at("Walker", 5.0);
    assert!((w.y + 4.0).abs() < PLAN_TOL, "{w:?}");
    assert!((w.x - 100.0).abs() < 1e-9, "{w:?}");
    assert!((w.speed - 1.6).abs() < PLAN_TOL, "{w:?}");
    // The Car reaches x = 100 at 10 s; the Walker is then at its target, y = 8 (within the
    // tolerance of the step-wise plan).
    let car = rows.at("Car", 10.0);
    assert!((car.x - 100.0).abs() < 1e-6, "{car:?}");
    let w = rows.at("Walker", 10.0);
    assert!((w.y - 8.0).abs() < PLAN_TOL, "{w:?}");
}

/// SynchronizeAction with SteadyState (XSD `TargetDistanceSteadyState`,
/// `TargetTimeSteadyState`, 1.1+): the actor reaches the final speed a steady-state distance
/// (or time at the final speed) before its target and holds it to the target.
///
/// Fixture `steady_state.xosc`: Car's target is 10 s away. ByDistance and ByTime, at 10 m/s,
/// must cover 160 m and end at 20 m/s, held over 40 m (= 2 s at 20 m/s): 120 m in the first
/// 8 s, from 10 to 20 m/s, a constant 1.25 m/s² ((10 + 20)/2 · 8 = 120), reaching s = 40 +
/// 120 = 160 at 8 s; then 20 m/s to s = 200 at 10 s.
#[test]
fn a_steady_state_is_reached_before_the_target_and_held() {
    let (_, rows, _) = run("steady_state.xosc", &[]);
    for name in ["ByDistance", "ByTime"] {
        // Half-way through the first phase (4 s): 15 m/s at s = 40 + 10·4 + 0.625·16 = 90.
        let r = rows.at(name, 4.0);
        assert!((r.speed - 15.0).abs() < PLAN_TOL, "{r:?}");
        assert!((r.x - 90.0).abs() < PLAN_TOL, "{r:?}");
        // The steady state begins at 8 s, s = 160, at 20 m/s, and holds to s = 200 at 10 s.
        let r = rows.at(name, 8.0);
        assert!(
            (r.x - 160.0).abs() < PLAN_TOL && (r.speed - 20.0).abs() < PLAN_TOL,
            "{r:?}"
        );
        let r = rows.at(name, 10.0);
        assert!(
            (r.x - 200.0).abs() < PLAN_TOL && (r.speed - 20.0).abs() < PLAN_TOL,
            "{r:?}"
        );
    }
}
