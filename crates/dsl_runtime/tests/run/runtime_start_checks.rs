//! The engine's checks in phases that start on a run-time condition of what the plan keeps by
//! construction at a known start (ASAM OpenSCENARIO DSL 2.1 §8.9.9 `yaw`, §8.9.10
//! `orientation` relative to the road; §8.9 `keep_position`): the actor's heading and speed
//! then are the run's. Every moment is worked by hand in the scenario file.

use super::runtime::{ego_speeds, fails, phases, ran_at};
use super::support::run;

/// Positions on the straight road: exact up to float round-off.
const S_TOL: f64 = 1e-6;
/// Headings along the lane: exact up to float round-off.
const H_TOL: f64 = 1e-9;

/// runtime_yaw.osc's comment, by hand: ego's lane change from 3.35 s turns it mid-way and
/// ends along lane -1 at 5.35 s, where yaw(0deg, at: end) passes; orientation(yaw: 0deg)
/// passes at 5.35 and 6.35 s. runtime_yaw_fails.osc: a line cut short leaves ego at
/// atan(7/24) from the road, and yaw(0deg) fails at 4.6 s.
#[test]
fn a_yaw_relative_to_the_road_after_an_until_is_the_engines_check_at_the_start_and_end() {
    let r = run("runtime_yaw", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.turn", 3.35, 5.35),
            ("do.on", 5.35, 6.35),
        ],
    );
    for (t, y, h0) in [
        (3.35, -5.25, true),
        (4.35, -3.5, false),
        (5.35, -1.75, true),
    ] {
        let ego = r.at(t, "ego");
        let turned = if h0 { ego.h.abs() < H_TOL } else { ego.h > 0.1 };
        assert!((ego.y - y).abs() < S_TOL && turned, "{t}: {ego:?}");
    }
    ran_at(
        &r,
        &[
            ("do.turn/ego/1:yaw.end", 5.35),
            ("do.on/ego/1:check", 5.35),
            ("do.on/ego/2:yaw.end", 6.35),
        ],
    );
    let want = "expected 'ego' at heading 0.0000 rad (relative_to_road 0.0000 rad, the road's s-axis at 0.0000 rad, within 0.001 rad) (yaw(…) at ";
    let tail = "runtime_yaw_fails.osc:30:13), found it at 0.2838 rad, its lane's heading 0.0000 rad at t = 4.600 s";
    fails("runtime_yaw_fails", (want, tail), "do.on/ego/1:check", 4.6);
}

/// runtime_keep_position.osc's comment, by hand: ego stops 20 → 0 m/s over 3.35-7.35 s at
/// s = 206.5 m; keep_position()'s check passes at 7.35 s and ego stands there to 9.35 s.
/// runtime_keep_position_fails.osc: after change_acceleration ego is at 18 m/s at 5.35 s
/// (where the plan records 0 m/s): the check fails.
#[test]
fn keep_position_after_an_until_is_the_engines_check_that_the_actor_stands() {
    let r = run("runtime_keep_position", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.stop", 3.35, 7.35),
            ("do.stand", 7.35, 9.35),
        ],
    );
    ego_speeds(&r, &[(5.35, 10.0), (7.35, 0.0), (8.35, 0.0), (9.35, 0.0)]);
    for t in [7.35, 8.35, 9.35] {
        let ego = r.at(t, "ego");
        assert!((ego.s - 206.5).abs() < S_TOL, "{t}: {ego:?}");
    }
    ran_at(&r, &[("do.stand/ego/1:check", 7.35)]);
    let want = "expected 'ego' at 0.000 m/s (within 0.01 m/s) (keep_position(…) at ";
    let tail = "runtime_keep_position_fails.osc:24:13), found it at 18.000 m/s at t = 5.350 s";
    fails(
        "runtime_keep_position_fails",
        (want, tail),
        "do.stand/ego/1:check",
        5.35,
    );
}
