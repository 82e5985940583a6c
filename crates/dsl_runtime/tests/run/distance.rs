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
}

/// distance_speed_relative.osc's comment, by hand: lead 10 → 22 m/s at 1.2 m/s² from 1 s; ego
/// changes to lead's speed where distance(71m) ends its phase, 16 m/s at 6 s (10 → 16 m/s at
/// 2 m/s² in 3 s over 39 m, 32 m more at 16 m/s); tail (projected) keeps lead's 10 m/s of 1 s
/// and ends at 8.1 s.
#[test]
fn a_speed_relative_to_another_actor_beside_a_distance_is_its_speed_where_the_phase_ends() {
    let r = run("distance_speed_relative", 0, None);
    for (path, a, b) in [("do.go.1", 1.0, 6.0), ("do.go.2", 1.0, 8.1)] {
        let (s, e) = r.phase(path);
        assert!(
            (s - a).abs() < T_TOL && (e - b).abs() < T_TOL,
            "{path} [{s}, {e}]"
        );
    }
    for (t, want, v) in [
        (2.5, 110.0 + 15.0 + 2.25 + ramp_lead(2.0, 1.5), 13.0),
        (4.0, 110.0 + 39.0 + ramp_lead(2.0, 3.0), 16.0),
        (6.0, 110.0 + 71.0 + ramp_lead(2.0, 3.0), 16.0),
        (7.0, 110.0 + 87.0 + ramp_lead(2.0, 3.0), 16.0),
    ] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.s - want).abs() < S_TOL && (ego.speed - v).abs() < S_TOL,
            "{t}: {ego:?}, want {want} m at {v} m/s"
        );
    }
    // Where the phase ends ego is at lead's speed; lead goes on accelerating.
    assert!((r.at(6.0, "lead").speed - 16.0).abs() < S_TOL);
    assert!((r.at(7.0, "lead").speed - 17.2).abs() < S_TOL);
    let tail = r.at(8.1, "tail");
    assert!(
        (tail.s - 181.0).abs() < S_TOL && (tail.speed - 10.0).abs() < S_TOL,
        "{tail:?}"
    );
    // lead keeps 30 m/s: 10 → 30 m/s at 2 m/s² covers 200 m of the 100 m.
    refused(
        "err_distance_speed_relative",
        "expected the speed change from 10.00 m/s to 30.00 m/s at 2 m/s² within the phase's distance of 100 m, found it covers 200.00 m",
        "19:13",
    );
    // lead's speed jumps 10 -> 20 m/s at 8 s, where no change ends the phase: by hand, toward
    // 10 m/s the phase ends at 11 s (lead at 20), toward 20 m/s at 7.25 s (lead at 10).
    refused(
        "err_distance_speed_relative_unsettled",
        "expected a speed of `lead` where distance(100 m) ends the phase that a change to it at 2 m/s² from 10.00 m/s ends the phase with, found none settling in 200 rounds (the last two: 20.00 and 10.00 m/s;",
        "22:17",
    );
}
