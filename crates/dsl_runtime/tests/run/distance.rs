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
