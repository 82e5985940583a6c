//! Speed changes at a rate in phases that start on a run-time condition (ASAM OpenSCENARIO DSL
//! 2.1 §8.9 `speed(…, at: end)` beside `acceleration(…)`, `distance(d)`): how long the change
//! takes depends on the speeds at the start, which only the engine has, so the engine runs it
//! and checks it then (and, for comparison, the plan's own change at a known start). Every
//! moment is worked by hand in the scenario file.

use super::runtime::{ego_speeds, fails, phases, ran_at, V_TOL};
use super::support::run;

/// runtime_speed_relative_at_rate.osc's comment, by hand: ego's change to lead's speed at
/// 4 m/s² takes the 3 s the engine finds at 3.35 s (20 → 8 m/s), blended to lead's speed as it
/// rises (v = 20 + (τ − 12)·τ/3), then follows it; tail's (projected) to lead's 8 m/s then.
#[test]
fn a_speed_relative_to_another_at_a_rate_after_an_until_takes_the_time_both_speeds_give() {
    let r = run("runtime_speed_relative_at_rate", 0, None);
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.follow", 3.35, 7.35)]);
    let ego = |tau: f64| 20.0 + (tau - 12.0) * tau / 3.0;
    ego_speeds(
        &r,
        &[
            (3.35, 20.0),
            (4.35, ego(1.0)),
            (4.85, 14.75),
            (6.35, 11.0),
            (6.85, 11.5),
            (7.35, 12.0),
        ],
    );
    for (t, v) in [(4.35, 9.0), (6.35, 11.0), (7.35, 12.0)] {
        let lead = r.at(t, "lead");
        assert!((lead.speed - v).abs() < V_TOL, "{t}: {lead:?}");
    }
    for (t, v) in [(3.35, 20.0), (4.85, 14.0), (6.35, 8.0), (7.35, 8.0)] {
        let tail = r.at(t, "tail");
        assert!((tail.speed - v).abs() < V_TOL, "{t}: {tail:?}");
    }
    ran_at(
        &r,
        &[
            ("do.follow.1/ego/1:check", 3.35),
            ("do.follow.1/ego/2:speed.end", 7.35),
        ],
    );
    // At 2 m/s² the change needs 6 s of the phase's 4: the engine's check at its start.
    let want = "expected 'ego''s speed from 20.000 to 8.000 m/s at 2.000 m/s² within 4.000 s (acceleration(…) at ";
    let tail =
        "runtime_speed_relative_at_rate_fails.osc:23:17), found it needs 6.000 s at t = 3.350 s";
    fails(
        "runtime_speed_relative_at_rate_fails",
        (want, tail),
        "do.follow.1/ego/1:check",
        3.35,
    );
}

/// runtime_rate_relative_over_distance.osc's comment, by hand: ego's change to 15 m/s runs at
/// lead's −2 m/s² − 1 as the engine reads it (3 m/s², v = 20 − 0.15·k after k steps), reaches
/// 15 m/s at 5.05 s and holds it; 60 m travelled since 3.35 s end the phase at 7.10 s, where
/// the engine's check at the end passes. With distance(20m) the phase ends at 4.45 s at
/// 16.7 m/s: the check fails.
#[test]
fn a_speed_change_at_another_actors_acceleration_over_a_distance_after_an_until_is_the_engines() {
    let r = run("runtime_rate_relative_over_distance", 0, None);
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.slow", 3.35, 7.10)]);
    ego_speeds(
        &r,
        &[
            (3.35, 20.0),
            (3.85, 18.5),
            (4.35, 17.0),
            (4.95, 15.2),
            (5.05, 15.0),
            (6.0, 15.0),
            (7.10, 15.0),
        ],
    );
    // s: 167 m at 3.35 s, then the covered distance worked out in the scenario's comment.
    for (t, s) in [
        (5.05, 167.0 + 29.5425),
        (7.05, 167.0 + 59.5425),
        (7.10, 167.0 + 60.2925),
    ] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.s - s).abs() < super::S_TOL,
            "{t}: {ego:?}, want s = {s}"
        );
    }
    ran_at(&r, &[("do.slow.1/ego/2:speed.end", 7.10)]);
    let want =
        "expected 'ego' at 15.000 m/s (within 0.01 m/s) (acceleration(…) at the phase end at ";
    let tail = "runtime_rate_relative_over_distance_fails.osc:25:17), found it at 16.700 m/s at t = 4.450 s";
    fails(
        "runtime_rate_relative_over_distance_fails",
        (want, tail),
        "do.slow.1/ego/2:speed.end",
        4.45,
    );
}

/// runtime_speed_relative_rate_relative.osc's comment, by hand: ego and tail change toward
/// lead's falling speed at lead's −1 m/s² − 5 (6 m/s²), meet it at 5.75 s (5.6 m/s) and follow
/// it; ego's 4 s phase ends at lead's 4 m/s, tail's distance(49.1m) at 10.15 s. At −1 − 2 the
/// change never meets lead within the 4 s: the run fails at 7.35 s.
#[test]
fn a_speed_relative_to_another_at_its_acceleration_after_an_until_follows_it() {
    let r = run("runtime_speed_relative_rate_relative", 0, None);
    phases(
        &r,
        &[("do.approach", 0.0, 3.35), ("do.follow", 3.35, 10.15)],
    );
    let (start, end) = r.phase("do.follow.1");
    assert!(
        (start - 3.35).abs() < 1e-9 && (end - 7.35).abs() < 1e-9,
        "ego's [{start}, {end}]"
    );
    let (start, end) = r.phase("do.follow.2");
    assert!(
        (start - 3.35).abs() < 1e-9 && (end - 10.15).abs() < 1e-9,
        "tail's [{start}, {end}]"
    );
    let want = [
        (3.35, 20.0),
        (4.35, 14.0),
        (5.35, 8.0),
        (5.70, 5.9),
        (5.75, 5.6),
        (6.75, 4.6),
        (7.35, 4.0),
    ];
    ego_speeds(&r, &want);
    for (t, v) in want {
        let tail = r.at(t, "tail");
        assert!((tail.speed - v).abs() < V_TOL, "{t}: {tail:?}");
    }
    // tail's distance from s = 167 m at 3.35 s, worked out in the scenario's comment.
    for (t, s) in [(5.75, 30.36), (7.35, 38.0), (10.15, 49.2)] {
        let tail = r.at(t, "tail");
        assert!(
            (tail.s - 167.0 - s).abs() < super::S_TOL,
            "{t}: {tail:?}, want {s} m on"
        );
    }
    ran_at(
        &r,
        &[
            ("do.follow.1/ego/2:speed.end", 7.35),
            ("do.follow.2/tail/2:speed.end", 10.15),
        ],
    );
    let want = "expected 'ego' at 4.000 m/s within 4.000 s of its start (acceleration(…) at ";
    let tail =
        "runtime_speed_relative_rate_relative_fails.osc:24:17), found 8.000 m/s at t = 7.350 s";
    fails(
        "runtime_speed_relative_rate_relative_fails",
        (want, tail),
        "do.follow.1/ego/2:speed",
        7.35,
    );
}

/// rate_relative_over_distance.osc's comment, by hand: at a start the plan knows, ego's change
/// to 10 m/s runs at lead's planned −1 m/s² − 1 (2 m/s²) from 1 s to 6 s, the other 25 m of
/// distance(100m) at 10 m/s end the phase at 8.5 s; tail's acceleration(2mpsps) of its own
/// the same.
#[test]
fn a_speed_change_at_another_actors_planned_acceleration_over_a_distance_is_the_plans() {
    let r = run("rate_relative_over_distance", 0, None);
    let (start, end) = r.phase("do.b.1");
    assert!(
        (start - 1.0).abs() < 1e-9 && (end - 8.5).abs() < 1e-9,
        "ego's [{start}, {end}]"
    );
    let (start, end) = r.phase("do.b.2");
    assert!(
        (start - 1.0).abs() < 1e-9 && (end - 8.5).abs() < 1e-9,
        "tail's [{start}, {end}]"
    );
    // (time, m/s, s) by hand; no s asserted half way through the change.
    let want = [
        (1.0, 20.0, Some(120.0)),
        (3.5, 15.0, None),
        (6.0, 10.0, Some(194.75)),
        (8.5, 10.0, Some(219.75)),
    ];
    for name in ["ego", "tail"] {
        for (t, v, s) in want {
            let o = r.at(t, name);
            assert!((o.speed - v).abs() < V_TOL, "{t}: {o:?}, want {v} m/s");
            if let Some(s) = s {
                assert!((o.s - s).abs() < super::S_TOL, "{t}: {o:?}, want s = {s}");
            }
        }
    }
}
