//! `distance(d)` (§8.9): planned over a phase with a duration, or ending a phase without one.
//! Expectations in the scenario files.

use crate::along::refused;
use crate::ramp_lead;
use crate::support::run;

const S_TOL: f64 = 1e-6;
const T_TOL: f64 = 1e-9;

#[test]
fn distance_travelled_in_a_phase() {
    let r = run("distance", 0, None);
    // Ramps of ±5 m/s² over 2 s each: the engine's lead of the first is undone by the second.
    assert!((r.at(2.0, "ego").s - (50.0 + ramp_lead(5.0, 2.0))).abs() < S_TOL);
    assert!((r.at(2.0, "ego").speed - 20.0).abs() < S_TOL);
    assert!((r.at(4.0, "ego").s - 80.0).abs() < S_TOL);
    let (s, e) = r.phase("do.1");
    assert!(
        (s - 4.0).abs() < T_TOL && (e - 7.0).abs() < T_TOL,
        "[{s}, {e}]"
    );
    assert!((r.at(7.0, "ego").s - 110.0).abs() < S_TOL);
    assert!((r.at(8.0, "ego").s - 120.0).abs() < S_TOL);
    refused(
        "err_distance_constant",
        "expected distance(50 m) at the constant speed 10.00 m/s over 4 s, found 40.00 m",
        "7:9",
    );
}

/// distance_speed_change.osc's comment, by hand: 10 → 20 m/s at 2 m/s² covers 75 m in 5 s from
/// 1 s, the other 25 m at 20 m/s take 1.25 s: the phase ends at 7.25 s.
#[test]
fn a_speed_change_beside_a_distance_without_a_duration_runs_at_its_rate() {
    let r = run("distance_speed_change", 0, None);
    let (s, e) = r.phase("do.go");
    assert!(
        (s - 1.0).abs() < T_TOL && (e - 7.25).abs() < T_TOL,
        "[{s}, {e}]"
    );
    for (t, want, v) in [
        (3.5, 141.25 + ramp_lead(2.0, 2.5), 15.0),
        (6.0, 185.0 + ramp_lead(2.0, 5.0), 20.0),
        (7.25, 210.0 + ramp_lead(2.0, 5.0), 20.0),
        (8.25, 230.0 + ramp_lead(2.0, 5.0), 20.0),
    ] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.s - want).abs() < S_TOL && (ego.speed - v).abs() < S_TOL,
            "{t}: {ego:?}, want {want} m at {v} m/s"
        );
    }
    refused(
        "err_distance_speed_change",
        "expected the speed change from 10.00 m/s to 30.00 m/s at 2 m/s² within the phase's distance of 100 m, found it covers 200.00 m",
        "12:13",
    );
    // The message names distance(…)'s place by the file's whole path: its two sides.
    refused(
        "err_distance_speed_relative",
        "expected a speed of its own beside distance(…) at ",
        "18:13",
    );
    refused(
        "err_distance_speed_relative",
        "err_distance_speed_relative.osc:19:13 in a phase without a duration, found one relative to another actor (give the phase a duration)",
        "18:13",
    );
}
