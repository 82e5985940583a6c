//! A speed relative to another actor beside `distance(d)` without a duration after a run-time
//! start (issue 27, §8.9, §8.9.1.1.3 `track`): the engine's change at the rate to x's speed,
//! read at each step (actual) or at the start (projected). Expectations in the scenario files.

use super::support::{lower, run, run_to_error, stepped};

/// Times: the run's steps are exact multiples of 0.05 s up to float round-off.
const T_TOL: f64 = 1e-9;
/// Speeds and positions on a straight road: float round-off only.
const TOL: f64 = 1e-9;

/// runtime_speed_relative_over_distance.osc's comment, by hand: from 3.35 s (τ) ego moves to
/// lead's speed read at each step, v = 20 + (v_L − 20)·τ/3 over the 3 s its change takes from
/// lead's 8 m/s then, lead 8 → 12 m/s over 2 s; then lead's 12 m/s; tail (projected) to
/// lead's 8 m/s of 3.35 s at 4 m/s².
#[test]
fn a_speed_relative_to_another_actor_beside_a_distance_after_an_until_follows_its_speed() {
    let r = run("runtime_speed_relative_over_distance", 0, None);
    let v_lead = |t: f64| 8.0 + 2.0 * (t - 3.35).clamp(0.0, 2.0);
    let v_ego = |t: f64| {
        let tau = t - 3.35;
        if tau < 3.0 - T_TOL {
            20.0 + (v_lead(t) - 20.0) * tau / 3.0
        } else {
            v_lead(t)
        }
    };
    let v_tail = |t: f64| (20.0 - 4.0 * (t - 3.35)).max(8.0);
    for t in [4.35, 5.35, 6.35, 7.35, 8.35] {
        let (ego, lead) = (r.at(t, "ego"), r.at(t, "lead"));
        assert!((lead.speed - v_lead(t)).abs() < TOL, "{t}: {lead:?}");
        assert!(
            (ego.speed - v_ego(t)).abs() < TOL,
            "{t}: {ego:?}, want {}",
            v_ego(t)
        );
    }
    // The mid-point and the change's end, as the comment works them out.
    assert!((r.at(4.35, "ego").speed - 50.0 / 3.0).abs() < TOL);
    assert!((r.at(5.35, "ego").speed - 44.0 / 3.0).abs() < TOL);
    assert!((r.at(6.35, "ego").speed - 12.0).abs() < TOL);
    // The phase ends at the first step at 71 m or more since 3.35 s.
    let (s0, e0) = r.phase("do.follow.1");
    let end = 3.35
        + 0.05
            * (1..)
                .find(|k| stepped(v_ego, 3.35, 3.35 + 0.05 * *k as f64) >= 71.0)
                .unwrap() as f64;
    assert!(
        (s0 - 3.35).abs() < T_TOL && (e0 - end).abs() < T_TOL,
        "[{s0}, {e0}], want {end}"
    );
    assert!((end - 8.4).abs() < T_TOL, "{end}");
    for t in [5.35, 6.35, 8.35, 8.4] {
        let got = r.at(t, "ego").s - r.at(3.35, "ego").s;
        let want = stepped(v_ego, 3.35, t);
        assert!((got - want).abs() < 1e-6, "{t}: {got} m, want {want}");
    }
    // The steps at their end speeds, by hand: 46.912 m by 6.35 s (the integral 47.111 m),
    // 70.912 m at 8.35 s, 71.512 m at 8.40 s.
    for (t, d) in [(6.35, 46.911_667), (8.35, 70.911_667), (8.4, 71.511_667)] {
        assert!((stepped(v_ego, 3.35, t) - d).abs() < 1e-6, "{t}");
    }
    // The check at the end ran then and passed (a failure would have ended the run).
    let at = r
        .when("do.follow.1/ego/2:speed.end", "End")
        .expect("the end check ran");
    assert!((at - 8.4).abs() < T_TOL, "{at}");
    // tail: 20 → 8 m/s at 4 m/s², 14 m/s at 4.85 s, then 8 m/s; ends at 10.05 s.
    for t in [4.85, 6.35, 8.35] {
        let tail = r.at(t, "tail");
        assert!((tail.speed - v_tail(t)).abs() < TOL, "{t}: {tail:?}");
    }
    let (s1, e1) = r.phase("do.follow.2");
    assert!(
        (s1 - 3.35).abs() < T_TOL && (e1 - 10.05).abs() < T_TOL,
        "[{s1}, {e1}]"
    );
    let got = r.at(10.05, "tail").s - r.at(3.35, "tail").s;
    assert!(
        (got - stepped(v_tail, 3.35, 10.05)).abs() < 1e-6 && got >= 71.0,
        "{got}"
    );
    assert!((stepped(v_tail, 3.35, 6.35) - 41.7).abs() < 1e-9);
}

/// Runs `name` to its error: the run fails with the one error record, at `t`, whose text
/// starts with `head` and ends with `name`.osc's `tail`.
fn fails_at(name: &str, (head, tail): (&str, &str), t: f64) {
    let lowered = lower(name, 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    assert!(
        error.starts_with(head) && error.ends_with(&format!("{name}.osc:{tail}")),
        "{error}"
    );
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - t).abs() < T_TOL, "{records:?}");
    assert_eq!(records[0].2, error);
}

/// runtime_speed_relative_over_distance_fails.osc's comment, by hand: 20 → 8 m/s at 1 m/s²
/// covers 168 m of the 71 m.
#[test]
fn a_speed_relative_to_another_actor_not_reached_within_a_distance_after_an_until_fails_the_run() {
    fails_at(
        "runtime_speed_relative_over_distance_fails",
        (
            "expected 'ego''s speed from 20.000 to 8.000 m/s at 1.000 m/s² within 71.000 m (acceleration(…) at ",
            "30:17), found it needs 168.000 m at t = 3.350 s",
        ),
        3.35,
    );
}

/// runtime_speed_relative_over_distance_end_fails.osc's comment, by hand: lead 8 -> 16 m/s
/// over 1.5 s; ego's 3 s change toward it is cut at 45 m, at 5.90 s, at 16.6 m/s where lead
/// is at 16 m/s: the check at the phase end fails.
#[test]
fn a_speed_relative_to_another_actor_not_met_where_a_distance_ends_the_phase_fails_the_run() {
    fails_at(
        "runtime_speed_relative_over_distance_end_fails",
        (
            "expected 'ego' at 16.000 m/s ('lead''s 16.000 m/s +0.000 m/s) (within 0.01 m/s) (speed(…) at the phase end at ",
            "26:17), found it at 16.600 m/s at t = 5.900 s",
        ),
        5.9,
    );
}
