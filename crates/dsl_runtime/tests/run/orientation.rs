//! `yaw(…)` and `orientation(…)` relative to the road: zero angles hold where the vehicle does
//! not move sideways; other forms are errors. Expectations in the scenario files.

use crate::along::refused;
use crate::support::run;

/// Heading on the straight road: float round-off.
const H_TOL: f64 = 1e-9;

#[test]
fn zero_orientation_relative_to_the_road_holds_where_planned() {
    let r = run("orientation_zero", 0, None);
    for t in [0.0, 1.0, 2.0, 6.0] {
        let h = r.at(t, "ego").h;
        assert!(h.abs() < H_TOL, "heading {h} at {t} s");
    }
    // Half way through the lane change the vehicle is turned: yaw(0deg) could not hold
    // throughout that phase (err_yaw_all).
    assert!(r.at(4.0, "ego").h.abs() > 1e-3);
    assert_eq!(r.at(6.0, "ego").lane, -2);
}

#[test]
fn orientations_the_planner_does_not_steer_are_errors() {
    refused(
        "err_yaw_all",
        "expected no lateral movement while yaw(…) at ",
        "8:9",
    );
    refused(
        "err_yaw_angle",
        "expected angle 0 relative to the road (the engine's vehicles drive along their lane), found 0.0873 rad",
        "6:13",
    );
    refused(
        "err_orientation_relative",
        "expected orientation(…) relative to the road, found relative_to:",
        "7:45",
    );
}
