//! Phases that start on a run-time condition (ASAM OpenSCENARIO DSL 2.1 §7.3.9 `until`,
//! `wait @e`): what the plan cannot place in time becomes the engine's action at the phase
//! start, or the engine's check there. Every moment is worked by hand in the scenario file.

use super::support::run;

/// Positions on the straight road: exact up to float round-off.
const S_TOL: f64 = 1e-6;
/// Phase times are step times.
const T_TOL: f64 = 1e-9;

#[test]
fn speed_and_lane_after_an_until_on_time_headway() {
    let r = run("runtime_until_speed_lane", 0, None);
    let (s, e) = r.phase("do.approach");
    assert!(
        s.abs() < T_TOL && (e - 3.35).abs() < T_TOL,
        "approach [{s}, {e}]"
    );
    let (s, e) = r.phase("do.evade");
    assert!(
        (s - 3.35).abs() < T_TOL && (e - 5.35).abs() < T_TOL,
        "evade [{s}, {e}]"
    );
    let ego = r.at(3.35, "ego");
    assert!((ego.s - 167.0).abs() < S_TOL, "{ego:?}");
    assert!((r.at(3.4, "ego").speed - 15.0).abs() < S_TOL);
    assert!((r.at(3.3, "ego").speed - 20.0).abs() < S_TOL);
    assert!(
        (r.at(4.35, "ego").y + 7.0).abs() < 1e-6,
        "{:?}",
        r.at(4.35, "ego")
    );
    // Moving sideways at 15 m/s along its path, ego gains less s than 15 m/s · 2 s: with the
    // sinusoid's lateral speed v_y = A·sin(πτ/T), A = πΔ/(2T) (Δ = 3.5 m, T = 2 s), the
    // deficit is ∫ v_y²/(2v) dτ = A²T/(4v) = π²Δ²/(16·T·v) = 0.2519 m (the next term,
    // ∫ v_y⁴/(8v³), is 0.0016 m).
    let deficit = std::f64::consts::PI.powi(2) * 3.5 * 3.5 / (16.0 * 2.0 * 15.0);
    let end = r.at(5.35, "ego");
    assert!((end.s - (197.0 - deficit)).abs() < 0.005, "{end:?}");
    assert!((end.y + 8.75).abs() < 1e-6 && end.lane == -3, "{end:?}");
    let (s, e) = r.phase("do.cruise");
    assert!(
        (s - 5.35).abs() < T_TOL && (e - 6.35).abs() < T_TOL,
        "cruise [{s}, {e}]"
    );
    // The engine's checks of lane(1) and position(46m, behind: lead) ran there and passed.
    for check in ["do.cruise/ego/1:check", "do.cruise/ego/2:check"] {
        let t = r.when(check, "End").expect("the check ran");
        assert!((t - 5.35).abs() < T_TOL, "{check} at {t}");
    }
    assert!((r.at(5.35, "lead").s - r.at(5.35, "ego").s - 46.0).abs() < 0.5);
}

#[test]
fn speed_and_lane_after_a_wait_on_an_emitted_event() {
    let r = run("runtime_wait_event", 0, None);
    let (s, e) = r.phase("do.signal.0");
    assert!(
        (s - 1.0).abs() < T_TOL && (e - 2.5).abs() < T_TOL,
        "npc [{s}, {e}]"
    );
    assert_eq!(r.emissions("do.signal.0.1/emit go", "go"), [2.5]);
    let (s, e) = r.phase("do.signal.1.w");
    assert!(
        (s - 1.0).abs() < T_TOL && (e - 2.55).abs() < T_TOL,
        "wait [{s}, {e}]"
    );
    let (s, e) = r.phase("do.signal.1.turn");
    assert!(
        (s - 2.55).abs() < T_TOL && (e - 4.55).abs() < T_TOL,
        "turn [{s}, {e}]"
    );
    assert!((r.at(2.55, "ego").s - 151.0).abs() < S_TOL);
    assert!((r.at(2.5, "ego").speed - 20.0).abs() < S_TOL);
    assert!((r.at(2.6, "ego").speed - 10.0).abs() < S_TOL);
    assert!((r.at(4.55, "ego").s - 171.0).abs() < S_TOL);
    // The engine's check of lane(lane_number) ran at the phase start and passed.
    let check = "do.signal.1.turn/ego/2:check";
    for transition in ["Start", "End"] {
        let t = r.when(check, transition).expect("the check ran");
        assert!((t - 2.55).abs() < T_TOL, "{transition} at {t}");
    }
}

#[test]
fn a_failed_check_at_a_run_time_start_is_an_error_record_and_a_failed_run() {
    let lowered = super::support::lower("runtime_wait_check_fails", 0, None)
        .unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = super::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    let lane = "runtime_wait_check_fails.osc:28:21";
    let want = "expected 'ego' in lane -3 of road 1 (lane(…) at ";
    assert!(
        error.starts_with(want)
            && error.contains(lane)
            && error.ends_with("), found it in lane -2 of road 1 at t = 2.550 s"),
        "{error}"
    );
    let logged: Vec<&(f64, String, String)> = records.iter().collect();
    assert_eq!(logged.len(), 1, "{logged:?}");
    assert!((logged[0].0 - 2.55).abs() < T_TOL);
    assert_eq!(logged[0].1, "do.signal.1.turn/ego/2:check");
    assert_eq!(logged[0].2, error);
}

/// Speeds set by linear pieces: exact up to float round-off.
pub(super) const V_TOL: f64 = 1e-9;

/// Runs `tests/scenarios/NAME.osc`, which must fail: its error starts with `want` and ends with
/// `tail`, and is the one error record of the event log, by `element` at `t`.
pub(super) fn fails(name: &str, (want, tail): (&str, &str), element: &str, t: f64) {
    let lowered = super::support::lower(name, 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = super::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    assert!(error.starts_with(want) && error.ends_with(tail), "{error}");
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - t).abs() < T_TOL, "{records:?}");
    assert_eq!(records[0].1, element);
    assert_eq!(records[0].2, error);
}

/// ego in lane -2 at each of `times` at y = −5.25 + a·(1 − cos(π·τ/2)) m, τ from 3.35 s to
/// 5.35 s: a 2 s sinusoidal move of 2a to the left from the lane's centre, then held.
fn sideways(r: &super::support::Run, a: f64, times: &[f64]) {
    let y = |t: f64| -5.25 + a * (1.0 - (std::f64::consts::PI * (t - 3.35) / 2.0).cos());
    for &t in times {
        let ego = r.at(t, "ego");
        let want = y(t.min(5.35));
        assert!(
            (ego.y - want).abs() < 1e-6 && ego.lane == -2,
            "{t}: {ego:?}, want {want}"
        );
    }
}

/// Each (phase, start, end) of `want` started and ended then.
pub(super) fn phases(r: &super::support::Run, want: &[(&str, f64, f64)]) {
    for (path, a, b) in want {
        let (s, e) = r.phase(path);
        assert!(
            (s - a).abs() < T_TOL && (e - b).abs() < T_TOL,
            "{path} [{s}, {e}]"
        );
    }
}

/// Each (element, time) of `want` ended then (a check that passed).
pub(super) fn ran_at(r: &super::support::Run, want: &[(&str, f64)]) {
    for &(check, t) in want {
        let at = r
            .when(check, "End")
            .unwrap_or_else(|| panic!("{check} ran"));
        assert!((at - t).abs() < T_TOL, "{check} at {at}");
    }
}

/// ego's speed at each (time, m/s) of `want`, exact up to float round-off.
pub(super) fn ego_speeds(r: &super::support::Run, want: &[(f64, f64)]) {
    for &(t, v) in want {
        let ego = r.at(t, "ego");
        assert!((ego.speed - v).abs() < V_TOL, "{t}: {ego:?}, want {v}");
    }
}

#[test]
fn position_and_distance_at_the_end_after_an_until_are_the_engines_profiles() {
    let r = run("runtime_travel", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.close", 3.35, 7.35),
            ("do.slow", 7.35, 9.35),
            ("do.park", 9.35, 11.35),
        ],
    );
    // do.close: position(30m, behind: lead, at: end), worked out at 3.35 s.
    assert!((r.at(3.35, "ego").s - 167.0).abs() < S_TOL);
    assert!((r.at(5.35, "ego").speed - 10.9).abs() < V_TOL);
    let (ego, lead) = (r.at(7.35, "ego"), r.at(7.35, "lead"));
    assert!((ego.s - 228.8).abs() < S_TOL, "{ego:?}");
    assert!((lead.s - ego.s - 30.0).abs() < S_TOL, "{lead:?}");
    assert!((ego.speed - 20.0).abs() < V_TOL);
    // do.slow: distance(30m) to 10 m/s.
    assert!((r.at(8.35, "ego").speed - 15.0).abs() < V_TOL);
    let ego = r.at(9.35, "ego");
    assert!(
        (ego.s - 258.55).abs() < S_TOL && (ego.speed - 10.0).abs() < V_TOL,
        "{ego:?}"
    );
    // do.park: position(280m, at: end).
    assert!((r.at(10.35, "ego").speed - 11.45).abs() < V_TOL);
    let ego = r.at(11.35, "ego");
    assert!(
        (ego.s - 280.0).abs() < S_TOL && (ego.speed - 10.0).abs() < V_TOL,
        "{ego:?}"
    );
}

#[test]
fn a_position_beyond_the_limits_after_an_until_is_an_error_record_and_a_failed_run() {
    let want = "expected 'ego' between 0 and 70 m/s (position(…) at ";
    let tail = "runtime_travel_fails.osc:20:13), found 133.000 m in 2 s from 20.000 m/s: 20.000 → 113.000 → 20.000 m/s at t = 3.350 s";
    fails(
        "runtime_travel_fails",
        (want, tail),
        "do.rush/ego/1:position",
        3.35,
    );
}

#[test]
fn lanes_relative_to_another_actor_after_an_until_are_the_engines() {
    let r = run("runtime_lane_relative", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.merge", 3.35, 5.35),
            ("do.hold", 5.35, 6.35),
        ],
    );
    let ego = r.at(3.35, "ego");
    assert!((ego.y + 5.25).abs() < S_TOL && ego.lane == -2, "{ego:?}");
    let ego = r.at(4.35, "ego");
    assert!((ego.y + 7.0).abs() < 1e-6, "{ego:?}");
    let ego = r.at(5.35, "ego");
    assert!((ego.y + 8.75).abs() < 1e-6 && ego.lane == -3, "{ego:?}");
    // The engine's checks of lane(same_as: npc) and lane(right_of: lead), at: all, held over
    // do.hold (no one changes lane in it: the engine's following of both lanes, 2:lanes,
    // changes nothing).
    for check in ["do.hold/ego/1:check", "do.hold/ego/3:check"] {
        r.held(check, (5.35, 6.35));
    }
}

#[test]
fn a_lane_left_of_another_actor_not_kept_is_an_error_record_and_a_failed_run() {
    let want =
        "expected 'ego' in lane -2 of road 1, 1 lane to the left of 'npc''s lane -3 (lane(…) at ";
    let tail =
        "runtime_lane_relative_fails.osc:32:13), found it in lane -3 of road 1 at t = 5.350 s";
    fails(
        "runtime_lane_relative_fails",
        (want, tail),
        "do.hold/ego/3:check",
        5.35,
    );
}

#[test]
fn change_and_assign_position_after_an_until_start_where_the_engine_finds_the_actor() {
    let r = run("runtime_place", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.cut", 3.35, 4.6),
            ("do.jump", 4.6, 4.65),
            ("do.on", 4.65, 5.65),
        ],
    );
    let ego = r.at(3.35, "ego");
    assert!(
        (ego.x - 167.0).abs() < S_TOL && (ego.y + 8.75).abs() < S_TOL,
        "{ego:?}"
    );
    let ego = r.at(4.1, "ego");
    assert!(
        (ego.x - 181.4).abs() < S_TOL && (ego.y + 4.55).abs() < S_TOL,
        "{ego:?}"
    );
    let ego = r.at(4.6, "ego");
    assert!(
        (ego.x - 191.0).abs() < S_TOL && (ego.y + 1.75).abs() < S_TOL,
        "{ego:?}"
    );
    let ego = r.at(4.65, "ego");
    assert!(
        (ego.x - 300.0).abs() < S_TOL && (ego.y + 5.25).abs() < S_TOL,
        "{ego:?}"
    );
    let ego = r.at(5.65, "ego");
    assert!((ego.x - 320.0).abs() < S_TOL && ego.lane == -2, "{ego:?}");
}

#[test]
fn a_lateral_position_at_the_end_after_an_until_starts_from_the_engines_offset() {
    let r = run("runtime_lateral", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.shift", 3.35, 5.35),
            ("do.hold", 5.35, 6.35),
        ],
    );
    // y = −5.25 + 0.5·(1 − cos(π·τ/2)), τ from 3.35 s.
    sideways(&r, 0.5, &[3.35, 3.85, 4.35, 5.35, 6.0]);
    let t = r.when("do.hold/ego/1:check", "End").expect("the check ran");
    assert!((t - 5.35).abs() < T_TOL, "check at {t}");
}

#[test]
fn gaps_at_the_other_actors_speed_after_an_until_are_the_engines() {
    let r = run("runtime_time_gap", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.close", 3.35, 7.35),
            ("do.hold", 7.35, 8.35),
        ],
    );
    assert!((r.at(5.35, "ego").speed - 17.9).abs() < V_TOL);
    let (ego, lead) = (r.at(7.35, "ego"), r.at(7.35, "lead"));
    assert!(
        (ego.s - 242.8).abs() < S_TOL && (lead.s - ego.s - 16.0).abs() < S_TOL,
        "{ego:?}"
    );
    // position(behind: lead) at: all: the engine's check held over do.hold (both at 8 m/s).
    r.held("do.hold/ego/1:check", (7.35, 8.35));
    assert!((r.at(7.4, "ego").speed - 8.0).abs() < V_TOL);
}

#[test]
fn a_time_gap_not_kept_after_an_until_is_an_error_record_and_a_failed_run() {
    let want = "expected 'lead' 24.000 m from 'ego' along the road (within 0.5 m) (position(…) at ";
    let tail = "runtime_time_gap_fails.osc:27:13), found 16.000 m at t = 7.350 s";
    fails(
        "runtime_time_gap_fails",
        (want, tail),
        "do.hold/ego/1:check",
        7.35,
    );
}

#[test]
fn a_named_route_after_an_until_is_the_engines_check() {
    let lowered = super::support::lower("runtime_along", 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = super::support::run_to_error(&lowered.scenario);
    // do.on_route's check passed at 3.35 s (no record); do.off_route's failed at 4.35 s.
    let error = error.expect("the run fails");
    assert_eq!(records.len(), 1, "{records:?}");
    assert_eq!(records[0].1, "do.off_route/ego/1:check");
    assert!((records[0].0 - 4.35).abs() < T_TOL, "{records:?}");
    // The route's interval: from 250 m to the road's end at 1000 m, 0.5 m more each side;
    // its middle 625 m and half its length 375.5 m.
    let want = "expected 'ego' at s = 625.000 m (within 375.5 m) (along(…) at ";
    assert!(
        error.starts_with(want) && error.contains("runtime_along.osc:27:13"),
        "{error}"
    );
    assert!(
        error.ends_with("found it at s = 187.000 m at t = 4.350 s"),
        "{error}"
    );
}

#[test]
fn lateral_beside_another_actor_in_later_phases_is_checked() {
    let lowered =
        super::support::lower("runtime_lateral_beside", 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = super::support::run_to_error(&lowered.scenario);
    // do.beside's check passed at 3.35 s (no record); do.closer's failed at 4.35 s.
    let error = error.expect("the run fails");
    assert_eq!(records.len(), 1, "{records:?}");
    assert_eq!(records[0].1, "do.closer/ego/1:check");
    assert!((records[0].0 - 4.35).abs() < T_TOL, "{records:?}");
    let want = "expected 'ego' 3.000 m to the left of 'npc' across the road (within 0.01 m) (lateral(…) at ";
    let tail = "runtime_lateral_beside.osc:37:13), found 3.500 m at t = 4.350 s";
    assert!(error.starts_with(want) && error.ends_with(tail), "{error}");
    // At a start the plan knows, the plan checks it.
    let e = super::support::error("err_lateral_beside_later");
    assert!(
        e.starts_with("expected `ego` 3.00 m to the left of `npc` across the road at the phase start, found it 3.50 m")
            && e.contains("err_lateral_beside_later.osc:15:13"),
        "{e}"
    );
}

#[test]
fn follow_lane_with_an_offset_after_an_until_starts_from_the_engines_offset() {
    let r = run("runtime_follow_lane", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.shift", 3.35, 5.35),
            ("do.after", 5.35, 6.35),
        ],
    );
    // y = −5.25 + 0.25·(1 − cos(π·τ/2)), τ from 3.35 s.
    sideways(&r, 0.25, &[3.35, 3.85, 4.35, 5.35, 6.35]);
}

#[test]
fn change_acceleration_over_a_duration_after_an_until_starts_from_the_engines_acceleration() {
    let r = run("runtime_change_acceleration", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.brake", 3.35, 5.35),
            ("do.after", 5.35, 6.35),
        ],
    );
    ego_speeds(
        &r,
        &[(3.35, 20.0), (4.35, 19.5), (5.35, 18.0), (6.35, 16.0)],
    );
}

/// runtime_acceleration_alone.osc's comment, by hand: 18 m/s at 5.35 s where the plan last
/// knows 0 m/s; acceleration(1mpsps) over 2 s from there: 19 m/s half way, 20 m/s at the end,
/// held after the phase.
#[test]
fn acceleration_alone_after_an_until_accelerates_from_the_speed_the_actor_has() {
    let r = run("runtime_acceleration_alone", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.brake", 3.35, 5.35),
            ("do.speed_up", 5.35, 7.35),
            ("do.after", 7.35, 8.35),
        ],
    );
    ego_speeds(
        &r,
        &[
            (5.35, 18.0),
            (5.85, 18.5),
            (6.35, 19.0),
            (7.35, 20.0),
            (8.35, 20.0),
        ],
    );
}

/// runtime_acceleration_alone_fails.osc's comment, by hand: from 18 m/s, −10 m/s² for 2 s
/// would stand ego after 1.8 s; the engine's check at the phase start fails the run.
#[test]
fn acceleration_alone_that_would_stop_the_actor_within_the_phase_after_an_until_fails_the_run() {
    fails(
        "runtime_acceleration_alone_fails",
        (
            "expected 'ego''s speed from 18.000 m/s at -10.000 m/s² for 2.000 s within 0 and 70.000 m/s (acceleration(…) at ",
            "runtime_acceleration_alone_fails.osc:30:13), found it reaches 0.000 m/s after 1.800 s (-2.000 m/s at the end) at t = 5.350 s",
        ),
        "do.speed_up/ego/1:check",
        5.35,
    );
}

/// runtime_speed_at_rate.osc's comment, by hand: from the 18 m/s the engine has at 5.35 s (the
/// plan knowing 0 m/s), 21 m/s at 1.5 m/s² takes the phase's 2 s, so the check passes.
#[test]
fn a_speed_change_at_a_rate_after_an_until_is_checked_from_the_engines_speed() {
    let r = run("runtime_speed_at_rate", 0, None);
    phases(
        &r,
        &[
            ("do.brake", 3.35, 5.35),
            ("do.speed_up", 5.35, 7.35),
            ("do.after", 7.35, 8.35),
        ],
    );
    ego_speeds(
        &r,
        &[(5.35, 18.0), (6.35, 19.5), (7.35, 21.0), (8.35, 21.0)],
    );
}

/// runtime_speed_at_rate_fails.osc's comment, by hand: 18 → 24 m/s at 1.5 m/s² needs 4 s, the
/// phase has 2 s.
#[test]
fn a_speed_change_at_a_rate_not_done_within_the_phase_after_an_until_fails_the_run() {
    fails(
        "runtime_speed_at_rate_fails",
        (
            "expected 'ego''s speed from 18.000 to 24.000 m/s at 1.500 m/s² within 2.000 s (acceleration(…) at ",
            "runtime_speed_at_rate_fails.osc:22:13), found it needs 4.000 s at t = 5.350 s",
        ),
        "do.speed_up/ego/1:check",
        5.35,
    );
}

/// runtime_speed_over_distance.osc's comment, by hand: from the 18 m/s the engine has at 5.35 s
/// (the plan knowing 0 m/s), 22 m/s at the default 2 m/s² covers 40 m (40.1 m in 0.05 s steps
/// at their end speeds) within distance(62m), so the check passes; the phase ends at 8.35 s,
/// the first step at 62 m or more since its start (62.1 m).
#[test]
fn a_speed_change_beside_a_distance_without_a_duration_after_an_until_runs_at_its_rate() {
    let r = run("runtime_speed_over_distance", 0, None);
    phases(
        &r,
        &[
            ("do.brake", 3.35, 5.35),
            ("do.speed_up", 5.35, 8.35),
            ("do.after", 8.35, 9.35),
        ],
    );
    ego_speeds(
        &r,
        &[
            (5.35, 18.0),
            (6.35, 20.0),
            (7.35, 22.0),
            (8.35, 22.0),
            (9.35, 22.0),
        ],
    );
    let from = r.at(5.35, "ego").s;
    for (t, d) in [(6.35, 19.05), (7.35, 40.1), (8.3, 61.0), (8.35, 62.1)] {
        let got = r.at(t, "ego").s - from;
        assert!((got - d).abs() < 1e-6, "{t}: {got} m, want {d}");
    }
    let at = r
        .when("do.speed_up/ego/1:check", "End")
        .expect("the check ran");
    assert!((at - 5.35).abs() < T_TOL, "check at {at}");
}

/// runtime_speed_over_distance_fails.osc's comment, by hand: 18 → 24 m/s at 1.5 m/s² covers
/// 84 m, more than the phase's 60 m.
#[test]
fn a_speed_change_not_done_within_a_distance_after_an_until_fails_the_run() {
    fails(
        "runtime_speed_over_distance_fails",
        (
            "expected 'ego''s speed from 18.000 to 24.000 m/s at 1.500 m/s² within 60.000 m (acceleration(…) at ",
            "runtime_speed_over_distance_fails.osc:24:13), found it needs 84.000 m at t = 5.350 s",
        ),
        "do.speed_up/ego/1:check",
        5.35,
    );
}

/// runtime_speed_rate_engine.osc's comment, by hand: from the 18 m/s the engine has at 5.35 s
/// (the plan knowing 0 m/s), 9 m/s² up over 2 s, then −9 m/s² over 1 s; both within 10 m/s²,
/// so the engine's checks pass and nothing is stretched.
#[test]
fn speed_changes_after_an_until_run_from_the_engines_speed_within_the_limit() {
    let r = run("runtime_speed_rate_engine", 0, None);
    phases(
        &r,
        &[
            ("do.brake", 3.35, 5.35),
            ("do.up", 5.35, 7.35),
            ("do.down", 7.35, 8.35),
        ],
    );
    ego_speeds(
        &r,
        &[
            (5.35, 18.0),
            (6.35, 27.0),
            (7.35, 36.0),
            (7.85, 31.5),
            (8.35, 27.0),
        ],
    );
}

/// runtime_speed_rate_engine_fails.osc's comment, by hand: 18 → 29 m/s in 1 s is 11 m/s².
#[test]
fn a_speed_change_beyond_the_limit_after_an_until_is_an_error_record_and_a_failed_run() {
    fails(
        "runtime_speed_rate_engine_fails",
        (
            "expected 'ego''s speed from 18.000 to 29.000 m/s within 1.000 s at the vehicle's 10.000 m/s² or less (change_speed(…) at ",
            "runtime_speed_rate_engine_fails.osc:21:13), found it needs 11.000 m/s² at t = 5.350 s",
        ),
        "do.jump/ego/1:check",
        5.35,
    );
}

/// actions/err_speed_after_acceleration.osc's comment, by hand: ego holds 12.8 m/s when the
/// until ends; change_speed(0 m/s, duration: 1.25 s) then needs 12.8 / 1.25 = 10.24 m/s².
#[test]
fn a_speed_change_from_the_speed_after_change_acceleration_beyond_the_limit_fails_the_run() {
    let name = "actions/err_speed_after_acceleration";
    let lowered = super::support::lower(name, 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = super::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    let want = "expected 'ego''s speed from 12.800 to 0.000 m/s within 1.250 s at the vehicle's 10.000 m/s² or less (change_speed(…) at ";
    let tail = "err_speed_after_acceleration.osc:26:9), found it needs 10.240 m/s² at t = ";
    assert!(error.starts_with(want) && error.contains(tail), "{error}");
    assert_eq!(records.len(), 1, "{records:?}");
    assert_eq!(records[0].1, "do.brake/ego/1:check");
    assert_eq!(records[0].2, error);
}

#[test]
fn a_speed_relative_to_another_actor_at_the_end_after_an_until_is_its_speed_then() {
    let r = run("runtime_speed_same_as", 0, None);
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.match", 3.35, 5.35)]);
    ego_speeds(&r, &[(3.35, 20.0), (4.35, 14.0), (5.35, 8.0)]);
    let ego = r.at(5.35, "ego");
    assert!((ego.s - 194.7).abs() < S_TOL, "{ego:?}");
}

/// runtime_acceleration_relative.osc's comment, by hand: from 3.35 s ego's acceleration is
/// lead's + 1 m/s² in every step, lead's changing from -2 to 0 m/s² at 5.35 s.
#[test]
fn an_acceleration_relative_to_one_that_changes_after_an_until_is_the_engines_following() {
    let r = run("runtime_acceleration_relative", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.follow", 3.35, 7.35),
            ("do.copy", 7.35, 9.35),
        ],
    );
    both_speeds(&r, &FOLLOWING_LEAD);
    // at: start: lead's 1 m/s² as do.copy starts, held after lead's change ends.
    both_speeds(&r, &[(8.35, 21.0, 5.0), (9.35, 22.0, 5.0)]);
}

/// (t, ego's speed, lead's) from 3.35 s while lead brakes 8 → 4 m/s at 2 m/s² to 5.35 s and
/// ego's acceleration is lead's + 1 m/s².
const FOLLOWING_LEAD: [(f64, f64, f64); 5] = [
    (3.35, 20.0, 8.0),
    (4.35, 19.0, 6.0),
    (5.35, 18.0, 4.0),
    (6.35, 19.0, 4.0),
    (7.35, 20.0, 4.0),
];

/// ego's and lead's speeds at each (t, ego, lead) of `want`.
fn both_speeds(r: &super::support::Run, want: &[(f64, f64, f64)]) {
    for &(t, ego, lead) in want {
        let (e, l) = (r.at(t, "ego").speed, r.at(t, "lead").speed);
        assert!((e - ego).abs() < V_TOL, "ego v({t}) = {e} vs {ego}");
        assert!((l - lead).abs() < V_TOL, "lead v({t}) = {l} vs {lead}");
    }
}

/// runtime_lateral_beside_end.osc's comment, by hand: from 3.35 s ego moves to 5.5 m left of
/// npc's centre as the engine finds npc then (track: projected), into lane -1.
#[test]
fn a_lateral_position_beside_another_actor_at_the_end_after_an_until_is_the_engines() {
    let r = run("runtime_lateral_beside_end", 0, None);
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.shift", 3.35, 5.35)]);
    for (t, y) in [(3.35, -5.25), (4.35, -4.25), (5.35, -3.25), (6.35, -3.25)] {
        let ego = r.at(t, "ego");
        assert!((ego.y - y).abs() < S_TOL, "ego y({t}) = {} vs {y}", ego.y);
    }
    assert_eq!(r.at(5.35, "ego").lane, -1);
    assert!((r.at(5.35, "npc").y + 8.75).abs() < S_TOL);
    // 9 m left of npc is t = 0.25 m, across the centre line: the engine's error at 3.35 s.
    let lowered = super::support::lower("runtime_lateral_beside_end_fails", 0, None)
        .unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = super::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 3.35).abs() < T_TOL, "{records:?}");
    // s = 100 + 20·3.35 = 167 m.
    let want = "expected a driving lane of road 1 at t = 0.250 m, s = 167.000 m (9.000 m from 'npc') (lateral(…) at ";
    assert!(
        error.starts_with(want)
            && error.ends_with(
                "runtime_lateral_beside_end_fails.osc:24:13), found none at t = 3.350 s"
            ),
        "{error}"
    );
}

/// runtime_change_acceleration_rate.osc's comment, by hand: from −1 m/s² at 3.40 s to −3 m/s²
/// at 1 m/s³, 2 s, the phase ending at 5.40 s where the target is reached; −3 m/s² held after.
#[test]
fn change_acceleration_at_a_rate_after_an_until_ends_when_the_engine_reaches_its_target() {
    let r = run("runtime_change_acceleration_rate", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.settle", 3.35, 3.4),
            ("do.brake", 3.4, 5.4),
            ("do.after", 5.4, 6.4),
        ],
    );
    ego_speeds(
        &r,
        &[
            (3.35, 20.0),
            (3.4, 19.95),
            (4.4, 18.45),
            (5.4, 15.95),
            (6.4, 12.95),
        ],
    );
}

/// runtime_keep_gap.osc's comment, by hand: the gap and the headway ego keeps after a run-time
/// start are the ones the engine measures then (59.8 m between the reference points, both at
/// 8 m/s), held to the phases' ends.
#[test]
fn gaps_and_headways_kept_after_an_until_are_the_ones_the_engine_measures_then() {
    let lowered =
        super::support::lower("runtime_keep_gap", 0, None).unwrap_or_else(|e| panic!("{e}"));
    // Each keep_* is a LongitudinalDistanceAction without a value, kept from its start.
    let kept: Vec<Option<scenario::GapAtStart>> = actions_of(&lowered)
        .filter_map(|a| match a {
            scenario::ActionKind::Private(scenario::PrivateAction::Longitudinal(
                scenario::LongitudinalAction::LongitudinalDistance {
                    distance: None,
                    time_gap: None,
                    at_start,
                    ..
                },
            )) => Some(*at_start),
            _ => None,
        })
        .collect();
    use scenario::GapAtStart::{Distance, TimeGap};
    assert_eq!(kept, [Some(Distance), Some(TimeGap)]);
    let r = run("runtime_keep_gap", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.slow", 3.35, 4.35),
            ("do.keep", 4.35, 6.35),
            ("do.headway", 6.35, 8.35),
        ],
    );
    for t in [4.35, 5.35, 6.35, 7.35, 8.35] {
        let (ego, lead) = (r.at(t, "ego"), r.at(t, "lead"));
        assert!(
            (lead.s - ego.s - 59.8).abs() < S_TOL,
            "{t}: {ego:?} {lead:?}"
        );
        assert!((ego.speed - 8.0).abs() < V_TOL, "{t}: {ego:?}");
    }
}

/// runtime_acceleration_relative_end.osc's comment, by hand: at: end after a run-time start,
/// ego's acceleration is lead's + 1 m/s² at the phase end (lead's 0 then, not its −2 at the
/// start), the engine following lead to the end.
#[test]
fn an_acceleration_relative_to_another_at_the_end_after_an_until_is_its_acceleration_then() {
    let r = run("runtime_acceleration_relative_end", 0, None);
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.follow", 3.35, 7.35)]);
    both_speeds(&r, &FOLLOWING_LEAD);
    // The last step's accelerations: ego's 1 m/s², lead's 0.
    let accel = |name: &str| (r.at(7.35, name).speed - r.at(7.3, name).speed) / 0.05;
    assert!((accel("ego") - 1.0).abs() < 1e-6, "{}", accel("ego"));
    assert!(accel("lead").abs() < 1e-6, "{}", accel("lead"));
}

/// runtime_acceleration_rate_relative.osc's comment, by hand: speed changes at the rate of
/// lead's acceleration as the engine reads it after a run-time start, at: start held (3 m/s²,
/// 20 → 17 m/s in 1 s) and at: all in every step (2 m/s², 17 → 19 m/s in 1 s); with a target
/// lead's acceleration never brings ego to in the phase, the engine's error at its end.
#[test]
fn speed_changes_at_the_rate_of_another_actors_acceleration_after_an_until_are_the_engines() {
    let r = run("runtime_acceleration_rate_relative", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.brake", 3.35, 5.35),
            ("do.match", 5.35, 7.35),
        ],
    );
    ego_speeds(
        &r,
        &[
            (3.35, 20.0),
            (3.85, 18.5),
            (4.35, 17.0),
            (5.35, 17.0),
            (5.85, 18.0),
            (6.35, 19.0),
            (7.35, 19.0),
        ],
    );
    let want = "expected 'ego' at 20.000 m/s within 2.000 s of its start (acceleration(…) at ";
    let tail =
        "runtime_acceleration_rate_relative_fails.osc:29:17), found 19.000 m/s at t = 7.350 s";
    fails(
        "runtime_acceleration_rate_relative_fails",
        (want, tail),
        "do.match.0/ego/1:speed",
        7.35,
    );
    // A rate beyond the vehicle's 10 m/s²: lead's −2 − 9 = −11 m/s², refused in the first step.
    let want = "expected a rate within 'ego''s 10.000 m/s² (acceleration(…) at ";
    let tail =
        "runtime_acceleration_rate_relative_limit.osc:22:17), found 11.000 m/s² at t = 3.400 s";
    fails(
        "runtime_acceleration_rate_relative_limit",
        (want, tail),
        "do.brake.0/ego/1:speed",
        3.4,
    );
}

/// runtime_acceleration_rate_relative_end.osc's comment, by hand: ego's change to 15 m/s at
/// lead's acceleration − 1 at: end reads lead's in each step: 2 m/s² while lead brakes at 1,
/// 3 m/s² after; done at 5.35 s.
#[test]
fn the_rate_of_a_speed_change_relative_to_another_at_the_end_after_an_until_follows_it() {
    let r = run("runtime_acceleration_rate_relative_end", 0, None);
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.brake", 3.35, 6.35)]);
    ego_speeds(
        &r,
        &[
            (3.35, 20.0),
            (3.85, 19.0),
            (4.35, 18.0),
            (4.85, 16.5),
            (5.35, 15.0),
            (5.85, 15.0),
            (6.35, 15.0),
        ],
    );
    for (t, v) in [(4.35, 7.0), (5.35, 5.0), (6.35, 3.0)] {
        let lead = r.at(t, "lead");
        assert!((lead.speed - v).abs() < V_TOL, "{t}: {lead:?}");
    }
}

/// runtime_keep_lateral_gap.osc's comment, by hand: the lateral gap ego keeps to npc after a
/// run-time start is the 1.5 m the engine measures then; ego stays on its lane's centre.
#[test]
fn a_lateral_gap_kept_after_an_until_is_the_one_the_engine_measures_then() {
    let r = run("runtime_keep_lateral_gap", 0, None);
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.beside", 3.35, 5.35)]);
    for t in [3.35, 4.35, 5.35] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.y + 5.25).abs() < S_TOL && ego.lane == -2,
            "{t}: {ego:?}"
        );
        assert!((ego.speed - 20.0).abs() < V_TOL, "{t}: {ego:?}");
    }
    assert!((r.at(5.35, "ego").s - 207.0).abs() < S_TOL);
}

/// runtime_distance_gap.osc's comment, by hand: from 3.35 s the engine measures distance(…)
/// and position(time: 2s, behind: lead, at: end) from each phase's start (a mark), checks a
/// distance and a position beside speed(v) at the phase end, and ends a travel at lead's speed
/// at its start plus 2 m/s, checked at the end.
#[test]
fn distances_and_gaps_without_a_duration_after_an_until_are_measured_from_the_phase_start() {
    let r = run("runtime_distance_gap", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.far", 3.35, 5.35),
            ("do.gap", 5.35, 13.35),
            ("do.hold", 13.35, 15.35),
            ("do.keep", 15.35, 17.35),
            ("do.match", 17.35, 19.35),
        ],
    );
    let s = |t: f64| r.at(t, "ego").s;
    let v = |t: f64| r.at(t, "ego").speed;
    // do.far: 10 m/s from 3.35 s, 20 m.
    assert!((s(4.35) - 177.0).abs() < S_TOL && (v(4.35) - 10.0).abs() < V_TOL);
    assert!((s(5.35) - 187.0).abs() < S_TOL, "{:?}", r.at(5.35, "ego"));
    // do.gap: 13 m/s, 16 m behind lead first reached at 13.35 s (0.05 m short at 13.30 s).
    assert!((s(9.35) - 239.0).abs() < S_TOL && (v(9.35) - 13.0).abs() < V_TOL);
    let (ego, lead) = (r.at(13.35, "ego"), r.at(13.35, "lead"));
    assert!((ego.s - 291.0).abs() < S_TOL, "{ego:?}");
    assert!((lead.s - ego.s - 15.8).abs() < S_TOL, "{lead:?}");
    let short = r.at(13.3, "lead").s - r.at(13.3, "ego").s;
    assert!((short - 16.05).abs() < S_TOL, "{short}");
    // do.hold and do.keep: the checks at their ends ran and passed.
    assert!((s(15.35) - 307.0).abs() < S_TOL && (v(15.35) - 8.0).abs() < V_TOL);
    assert!((s(17.35) - 323.0).abs() < S_TOL);
    ran_at(
        &r,
        &[
            ("do.hold/ego/2:distance.end", 15.35),
            ("do.keep/ego/2:position.end", 17.35),
            ("do.match/ego/3:position.speed", 19.35),
        ],
    );
    // do.match: 8 → 2.8 → 10 m/s, ending 20 m behind lead.
    assert!((v(18.35) - 2.8).abs() < V_TOL, "{}", v(18.35));
    let (ego, lead) = (r.at(19.35, "ego"), r.at(19.35, "lead"));
    assert!(
        (ego.s - 334.85).abs() < S_TOL && (ego.speed - 10.0).abs() < V_TOL,
        "{ego:?}"
    );
    assert!((lead.s - 354.8).abs() < S_TOL, "{lead:?}");
}

#[test]
fn a_distance_or_a_speed_not_met_at_the_end_after_an_until_is_an_error_record_and_a_failed_run() {
    let want = "expected 'ego' 20.000 m travelled since the phase start (within 0.5 m) (distance(…) at the phase end at ";
    let tail = "runtime_end_distance_fails.osc:21:13), found 16.000 m at t = 5.350 s";
    fails(
        "runtime_end_distance_fails",
        (want, tail),
        "do.hold/ego/2:distance.end",
        5.35,
    );
    let want = "expected 'ego' at 9.325 m/s ('lead''s 7.325 m/s +2.000 m/s) (within 0.01 m/s) (speed(…) at the phase end at ";
    let tail = "runtime_end_speed_fails.osc:22:17), found it at 10.000 m/s at t = 5.350 s";
    fails(
        "runtime_end_speed_fails",
        (want, tail),
        "do.ego.match/ego/3:position.speed",
        5.35,
    );
}

/// runtime_projected.osc's comment, by hand: after a run-time start, track: projected reads
/// lead as projected from each phase's start while lead brakes.
#[test]
fn a_projected_gap_and_speed_after_an_until_read_the_reference_at_the_phase_start() {
    let r = run("runtime_projected", 0, None);
    phases(
        &r,
        &[
            ("do.ego.approach", 0.0, 3.35),
            ("do.ego.close", 3.35, 11.35),
            ("do.ego.match", 11.35, 13.35),
        ],
    );
    let ego = |t: f64| r.at(t, "ego");
    assert!((ego(7.35).s - 219.0).abs() < S_TOL, "{:?}", ego(7.35));
    assert!((ego(11.35).s - 271.0).abs() < S_TOL, "{:?}", ego(11.35));
    // lead braked: it is far less than 20 m ahead when the projected gap is reached.
    assert!(r.at(11.35, "lead").s - ego(11.35).s < 7.0);
    let lead_v = r.at(11.35, "lead").speed;
    assert!((lead_v - 4.325).abs() < V_TOL, "{lead_v}");
    assert!(
        (ego(12.35).speed - 8.6625).abs() < V_TOL,
        "{:?}",
        ego(12.35)
    );
    assert!((ego(13.35).speed - 4.325).abs() < V_TOL, "{:?}", ego(13.35));
    assert!((r.at(13.35, "lead").speed - 4.0).abs() < V_TOL);
}

/// runtime_lateral_follow.osc's comment, by hand: from 3.35 s ego follows npc's actual t
/// (track: actual) while npc moves 1 m right, t = -5.25 + 2f - f².
#[test]
fn a_lateral_position_beside_a_moving_actor_after_an_until_follows_its_actual_t() {
    let r = run("runtime_lateral_follow", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.shift", 3.35, 5.35),
            ("do.after", 5.35, 6.35),
        ],
    );
    let f = |t: f64| (1.0 - (std::f64::consts::PI * (t - 3.35) / 2.0).cos()) / 2.0;
    for t in [3.35_f64, 3.85, 4.35, 4.85, 5.35, 5.85, 6.35] {
        let f = f(t.min(5.35));
        let (ego, npc) = (r.at(t, "ego"), r.at(t, "npc"));
        let want = -5.25 + 2.0 * f - f * f;
        assert!(
            (ego.y - want).abs() < S_TOL,
            "ego y({t}) = {} vs {want}",
            ego.y
        );
        assert!((npc.y + 8.75 + f).abs() < S_TOL, "npc y({t}) = {}", npc.y);
    }
    assert!((r.at(4.35, "ego").y + 4.5).abs() < S_TOL);
    assert!((r.at(5.35, "ego").y + 4.25).abs() < S_TOL);
    assert_eq!(r.at(5.35, "ego").lane, -2);
    assert_eq!(r.at(6.35, "ego").lane, -2);
}

/// runtime_lateral_keep_lane.osc's comment, by hand: ego follows npc's actual t and stays in
/// lane -2, so keep_lane()'s check at 5.35 s and lane(2)'s at 5.35 and 6.35 s pass.
#[test]
fn a_lane_kept_beside_a_lateral_position_beside_a_moving_actor_after_an_until_is_checked_at_the_end(
) {
    let r = run("runtime_lateral_keep_lane", 0, None);
    phases(
        &r,
        &[
            ("do.shift", 3.35, 5.35),
            ("do.hold", 5.35, 6.35),
            ("do.after", 6.35, 7.35),
        ],
    );
    for (t, y) in [(4.35, -4.5), (5.35, -4.25), (6.35, -4.25)] {
        let ego = r.at(t, "ego");
        assert!((ego.y - y).abs() < S_TOL && ego.lane == -2, "{t}: {ego:?}");
    }
    ran_at(
        &r,
        &[
            ("do.shift.0/ego/1:lane.end", 5.35),
            ("do.hold.0/ego/1:lane.end", 6.35),
            ("do.hold.0/ego/3:check", 5.35),
        ],
    );
}

/// runtime_lateral_keep_lane_fails.osc's comment, by hand: npc moves 1 m left, ego 5.5 m left
/// of it ends at t = -2.25 m in lane -1.
#[test]
fn a_lane_not_kept_beside_a_lateral_position_beside_a_moving_actor_after_an_until_fails_the_run() {
    fails(
        "runtime_lateral_keep_lane_fails",
        (
            "expected 'ego' in lane -2 of road 1, its lane at the phase start (keep_lane(…) at the phase end at ",
            "runtime_lateral_keep_lane_fails.osc:28:17), found it in lane -1 of road 1 at t = 5.350 s",
        ),
        "do.shift.0/ego/1:lane.end",
        5.35,
    );
}

/// runtime_lateral_beside_lane_change.osc's comment, by hand: beside change_lane(side: left)
/// ego follows npc's t plus 5.5 m, t = -5.25 + 2f + f², into lane -1; beside lane(2, at: end)
/// it changes to npc's projected t plus 3 m, t = -2.25 - 2.5f, into lane -2; both lanes
/// checked at the phase ends.
#[test]
fn a_lane_change_beside_a_lateral_position_beside_another_actor_after_an_until_is_checked_at_the_end(
) {
    let r = run("runtime_lateral_beside_lane_change", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.shift", 3.35, 5.35),
            ("do.back", 5.35, 7.35),
        ],
    );
    let f = |tau: f64| (1.0 - (std::f64::consts::PI * tau / 2.0).cos()) / 2.0;
    for k in 0..=40 {
        let t = 3.35 + 0.05 * f64::from(k);
        let g = f(t - 3.35);
        let want = -5.25 + 2.0 * g + g * g;
        let ego = r.at(t, "ego");
        assert!((ego.y - want).abs() < S_TOL, "{t}: {ego:?}, want {want}");
        let want = -2.25 - 2.5 * f(t - 3.35);
        let ego = r.at(t + 2.0, "ego");
        assert!(
            (ego.y - want).abs() < S_TOL,
            "{}: {ego:?}, want {want}",
            t + 2.0
        );
    }
    // At 6.35 s ego is on the border of lanes -1 and -2 (t = -3.5 m).
    for (t, y, lane) in [
        (4.35, -4.0, Some(-2)),
        (5.35, -2.25, Some(-1)),
        (6.35, -3.5, None),
        (7.35, -4.75, Some(-2)),
    ] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.y - y).abs() < S_TOL && lane.is_none_or(|l| ego.lane == l),
            "{t}: {ego:?}"
        );
    }
    ran_at(
        &r,
        &[
            ("do.shift.0/ego/2:lane.end", 5.35),
            ("do.back.0/ego/2:lane.end", 7.35),
        ],
    );
}

/// runtime_lateral_beside_lane_change_fails.osc's comment, by hand: ego ends at t = -2.25 m in
/// lane -1 where change_lane(side: right) asks lane -3.
#[test]
fn a_lane_change_not_where_a_lateral_position_beside_another_actor_puts_it_fails_the_run() {
    fails(
        "runtime_lateral_beside_lane_change_fails",
        (
            "expected 'ego' in lane -3 of road 1, 1 lane to the right of its lane -2 at the phase start (change_lane(…) at the phase end at ",
            "runtime_lateral_beside_lane_change_fails.osc:28:17), found it in lane -1 of road 1 at t = 5.350 s",
        ),
        "do.shift.0/ego/2:lane.end",
        5.35,
    );
}

/// runtime_place_on_road.osc's comment, by hand: from 3.35 s ego follows the sinusoid of the
/// distance along its lane into lane -2, arriving 40 m on at 5.3594 s.
#[test]
fn change_position_on_the_road_network_after_an_until_arrives_from_where_the_engine_finds_it() {
    let r = run("runtime_place_on_road", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.cut", 3.35, 5.45),
            ("do.on", 5.45, 6.45),
        ],
    );
    // The path: y as the sinusoid of the distance along, x − 167 m on the straight road (the
    // engine's along-road steps are corrected to what the controller drove: 1 mm).
    for k in 0..40 {
        let t = 3.35 + 0.05 * f64::from(k);
        let ego = r.at(t, "ego");
        let u = ego.x - 167.0;
        let want = -8.75 + 1.75 * (1.0 - (std::f64::consts::PI * u / 40.0).cos());
        assert!((ego.y - want).abs() < 1e-3, "{t}: {ego:?}, want y {want}");
    }
    let ego = r.at(5.4, "ego");
    assert!((ego.y + 5.25).abs() < S_TOL && ego.lane == -2, "{ego:?}");
    // Arrived at 5.3594 s: 0.0406 s on at 20 m/s by 5.40 s.
    assert!(
        (ego.x - (207.0 + 20.0 * (5.4 - 5.359412))).abs() < 0.01,
        "{ego:?}"
    );
    let ego = r.at(6.45, "ego");
    assert!((ego.y + 5.25).abs() < S_TOL && ego.lane == -2, "{ego:?}");
}

/// gap_reached_from_behind.osc's comment, by hand: a gap without a duration ends its phase
/// when ego reaches its place from the side it starts on, at a known start (closing from
/// behind) and after a run-time one (falling back).
#[test]
fn a_gap_without_a_duration_is_reached_from_the_side_the_actor_starts_on() {
    let r = run("gap_reached_from_behind", 0, None);
    phases(
        &r,
        &[
            ("do.0.first", 0.0, 6.7),
            ("do.0.brake", 6.7, 7.7),
            ("do.0.approach", 7.7, 7.85),
            ("do.0.close", 7.85, 9.9),
        ],
    );
    let gap = |t: f64| r.at(t, "lead").s - r.at(t, "ego").s;
    assert!((r.at(6.7, "ego").s - 234.0).abs() < S_TOL);
    assert!((gap(6.65) - 20.2).abs() < S_TOL && (gap(6.7) - 19.6).abs() < S_TOL);
    assert!((r.at(7.85, "ego").s - 245.0).abs() < S_TOL);
    assert!((gap(9.85) - 29.8).abs() < S_TOL && (gap(9.9) - 30.1).abs() < S_TOL);
    assert!((r.at(9.9, "ego").s - 249.1).abs() < S_TOL);
}

/// runtime_place_smooth.osc's comment, by hand: from 4.6 s ego follows the Hermite curve from
/// the pose the engine finds it in (facing the line it came along) to q, through (210.8,
/// −0.35) m at u = ½, arriving after 40.2109 m at 6.6105 s.
#[test]
fn change_position_smooth_after_an_until_curves_from_the_pose_the_engine_finds() {
    let r = run("runtime_place_smooth", 0, None);
    let (start, end) = r.phase("do.curve");
    assert!((start - 4.6).abs() < T_TOL, "curve starts at {start}");
    // Arrival at 6.6105 s, in the step ending at 6.65 s.
    assert!((end - 6.65).abs() < T_TOL, "curve ends at {end}");
    let h0 = 7.0_f64.atan2(24.0);
    let ego = r.at(4.6, "ego");
    assert!(
        (ego.x - 191.0).abs() < S_TOL && (ego.y + 1.75).abs() < S_TOL && (ego.h - h0).abs() < 1e-9,
        "start {ego:?}"
    );
    // The Bézier: x(u) rises, so each frame's x gives its u (bisection) and y(u) must match;
    // the frames near u = ½ pass (210.8, −0.35) m.
    let bezier = |u: f64| {
        let v = 1.0 - u;
        (
            191.0 * v.powi(3)
                + 3.0 * v * v * u * 203.8
                + 3.0 * v * u * u * (231.0 - 40.0 / 3.0)
                + 231.0 * u.powi(3),
            -1.75 + 3.0 * u * v * v * (40.0 / 3.0) * 7.0 / 25.0,
        )
    };
    assert!((bezier(0.5).0 - 210.8).abs() < 1e-9 && (bezier(0.5).1 + 0.35).abs() < 1e-9);
    // The engine samples the NURBS' arc length; a point is on the curve within 1 mm.
    const ON_CURVE: f64 = 1e-3;
    for k in 1..40 {
        let t = 4.6 + 0.05 * f64::from(k);
        let ego = r.at(t, "ego");
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if bezier(mid).0 < ego.x {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let want = bezier(0.5 * (lo + hi)).1;
        assert!(
            (ego.y - want).abs() < ON_CURVE,
            "{t}: {ego:?}, want y {want}"
        );
    }
    // Half the length, 20.105 m, at 20 m/s is reached 1.0053 s in: at 5.60 s ego has gone
    // 20 m, just before the mid-point (u = 0.5011, (210.844, −0.353) m by the same sums).
    let ego = r.at(5.6, "ego");
    assert!(
        (ego.x - 210.844).abs() < 0.01 && (ego.y + 0.353).abs() < 0.01,
        "{ego:?}"
    );
    // After the end: in lane -1 on its centre, facing along it.
    let ego = r.at(7.65, "ego");
    assert!(
        ego.lane == -1 && (ego.y + 1.75).abs() < S_TOL && ego.h.abs() < 1e-9,
        "{ego:?}"
    );
}

/// runtime_column_trajectory.osc's comment, by hand: after `wait @go` the column's member 1
/// follows its lead-in and the trajectory with its stamps shifted by 15 m over member 0's
/// 14 m/s then (1.0714 s), which the engine reads when the action starts.
#[test]
fn a_columns_trajectory_after_a_run_time_condition_is_shifted_by_the_engines_headway() {
    let r = run("runtime_column_trajectory", 0, None);
    phases(
        &r,
        &[
            ("do.signal.1.w", 0.55, 2.55),
            ("do.signal.1.follow", 2.55, 6.65),
        ],
    );
    let (m0, m1) = ("g.vehicles[0]", "g.vehicles[1]");
    // Member 0 accelerated at 2 m/s² from 0.55 s: 14 m/s at 2.55 s.
    assert!(
        (r.at(2.55, m0).speed - 14.0).abs() < V_TOL,
        "{:?}",
        r.at(2.55, m0)
    );
    let at = |name: &str, t: f64, x: f64| {
        let m = r.at(t, name);
        assert!(
            (m.x - x).abs() < S_TOL && (m.y + 8.75).abs() < S_TOL,
            "{name} at {t}: {m:?}, want x {x}"
        );
    };
    at(m0, 4.05, 94.0 + 14.0 * 1.5);
    at(m0, 5.55, 136.0);
    // Member 1: 7 m of its lead-in at 14 m/s by 3.05 s; on tr 1.4286 s at 5.05 s, 20 m.
    at(m1, 3.05, 86.0);
    at(m1, 5.05, 114.0);
    // Its last stamp at 6.6214 s: 0.3 m short of it at 6.60 s.
    at(m1, 6.6, 135.7);
}

/// The LateralDistanceActions of `name`'s lowered scenario in order: their distance and
/// whether the engine measures it at the start.
fn lateral_gaps(name: &str) -> Vec<(Option<f64>, bool)> {
    let lowered = super::support::lower(name, 0, None).unwrap_or_else(|e| panic!("{e}"));
    actions_of(&lowered)
        .filter_map(|a| match a {
            scenario::ActionKind::Private(scenario::PrivateAction::Lateral(
                scenario::LateralAction::LateralDistance {
                    distance, at_start, ..
                },
            )) => Some((*distance, *at_start)),
            _ => None,
        })
        .collect()
}

/// runtime_lateral_gap_drift.osc's comment, by hand: a keep_space_gap after a change to the
/// same reference with a phase between them keeps the gap the engine measures at its start
/// (5 m: npc moved a lane away), not the change's 1.5 m the plan last knows; right after the
/// change (lateral_gap.osc) it keeps the change's target.
#[test]
fn a_lateral_gap_kept_after_a_drift_following_a_change_is_the_one_the_engine_measures() {
    assert_eq!(
        lateral_gaps("runtime_lateral_gap_drift"),
        [(Some(1.5), false), (None, true)]
    );
    assert_eq!(
        lateral_gaps("actions/lateral_gap"),
        [(Some(0.5), false), (Some(0.5), false)]
    );
    let r = run("runtime_lateral_gap_drift", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.rest.0.open", 3.35, 3.4),
            ("do.rest.0.drift", 3.4, 5.4),
            ("do.rest.0.hold", 5.4, 7.4),
        ],
    );
    let npc = r.at(5.4, "npc");
    assert!((npc.y + 1.75).abs() < S_TOL && npc.lane == -1, "{npc:?}");
    for t in [3.4, 5.4, 6.4, 7.4] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.y + 8.75).abs() < S_TOL && ego.lane == -3,
            "{t}: {ego:?}"
        );
    }
}

/// The actions of `lowered`'s story, Act by Act, in order.
fn actions_of(lowered: &dsl_runtime::Lowered) -> impl Iterator<Item = &scenario::ActionKind> {
    lowered.scenario.storyboard.stories[0]
        .acts
        .iter()
        .flat_map(|a| &a.maneuver_groups)
        .flat_map(|g| &g.maneuvers)
        .flat_map(|m| &m.events)
        .flat_map(|e| &e.actions)
        .map(|a| &a.kind)
}

/// runtime_lateral_border.osc's comment, by hand: on a widening lane the check of a lateral
/// offset from the lane's border at a run-time start takes the width where the engine finds
/// ego (5.17 m at s = 167 m), so ego on its lane's centre passes it.
#[test]
fn a_lateral_offset_from_a_border_after_an_until_is_checked_in_the_lanes_width_then() {
    let r = super::support::run_on("runtime_lateral_border", "widening");
    phases(&r, &[("do.approach", 0.0, 3.35), ("do.beside", 3.35, 4.35)]);
    let t = r
        .when("do.beside/ego/1:check", "End")
        .expect("the check ran");
    assert!((t - 3.35).abs() < T_TOL, "check at {t}");
    // On the lane's centre: t = −7 − W/2 = −9.585 m at s = 167 m (1 mm: s and W as above).
    let ego = r.at(3.35, "ego");
    assert!(
        ego.lane == -3 && (ego.s - 167.0).abs() < 1e-2 && (ego.y + 9.585).abs() < 1e-3,
        "{ego:?}"
    );
}

/// runtime_lateral_border_end.osc's comment, by hand: on a widening lane the target offset of
/// `lateral(1.585m, measure_by: right_to_right, at: end)` after a run-time start is
/// 0.835 − 0.005·s with the width where ego is, f·(0.835 − 0.005·s) on the way: −0.05 m at
/// 4.35 s, −0.2 m at 5.35 s, 1.585 m from the right border then (the plan's width would end
/// it at +0.335 m, 2.12 m from it).
#[test]
fn a_lateral_offset_from_a_border_at_the_end_after_an_until_takes_the_lanes_width_at_the_end() {
    let r = super::support::run_on("runtime_lateral_border_end", "widening");
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.shift", 3.35, 5.35),
            ("do.hold", 5.35, 6.35),
        ],
    );
    let width = |s: f64| 3.5 + 0.01 * s;
    // The engine foresees each step's end s at its speed along the road; the path's slope
    // (the lane's centre's and the change's, below 0.01) shortens the step by less than
    // 5e-5 of it: 1e-6 m of offset.
    const FORESEEN: f64 = 1e-6;
    for k in 0..=40 {
        let t = 3.35 + 0.05 * f64::from(k);
        let ego = r.at(t, "ego");
        let f = (1.0 - (std::f64::consts::PI * (t - 3.35) / 2.0).cos()) / 2.0;
        let want = -7.0 - width(ego.s) / 2.0 + f * (0.835 - 0.005 * ego.s);
        assert!(
            (ego.y - want).abs() < FORESEEN && ego.lane == -3,
            "{t}: {ego:?}, want y {want}"
        );
    }
    // The comment's figures (s within 1 cm of 20 m/s from 167 m: W within 1e-4 m).
    for (t, s, y) in [(4.35, 187.0, -9.735), (5.35, 207.0, -9.985)] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.s - s).abs() < 1e-2 && (ego.y - y).abs() < 1e-4,
            "{t}: {ego:?}"
        );
    }
    // At the end ego's right side is 1.585 m from the lane's right border.
    let ego = r.at(5.35, "ego");
    let gap = (ego.y - 1.0) - (-7.0 - width(ego.s));
    assert!((gap - 1.585).abs() < FORESEEN, "{gap}");
    let t = r.when("do.hold/ego/1:check", "End").expect("the check ran");
    assert!((t - 5.35).abs() < T_TOL, "check at {t}");
}

/// runtime_lateral_border_lane_change.osc's comment, by hand: lane(1, at: end) beside
/// `lateral(1.585m, measure_by: right_to_right, at: end)` after a run-time start blends from
/// lane -2's centre into lane -3 at 0.835 − 0.005·s from its centre, in the width where ego
/// is: t = (1 − f)·(−5.25) + f·(−7.915 − 0.01·s), −9.985 m at 5.35 s, 1.585 m from the border.
#[test]
fn a_lane_change_beside_a_lateral_offset_from_a_border_after_an_until_takes_the_lanes_width_at_the_end(
) {
    let r = super::support::run_on("runtime_lateral_border_lane_change", "widening");
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.shift", 3.35, 5.35),
            ("do.hold", 5.35, 6.35),
        ],
    );
    // The step's end s foreseen at its speed and the sideways share of the step before: across
    // lanes the heading reaches 0.2 rad, and the share's change over a step leaves the
    // foreseen s up to 1e-3 m off, 5e-6 m of offset (k·W′·Δs); at the end the heading is 0.
    const FORESEEN_TURNING: f64 = 1e-5;
    const FORESEEN: f64 = 1e-6;
    for k in 0..=40 {
        let t = 3.35 + 0.05 * f64::from(k);
        let ego = r.at(t, "ego");
        let f = (1.0 - (std::f64::consts::PI * (t - 3.35) / 2.0).cos()) / 2.0;
        let want = (1.0 - f) * -5.25 + f * (-7.915 - 0.01 * ego.s);
        assert!(
            (ego.y - want).abs() < FORESEEN_TURNING,
            "{t}: {ego:?}, want y {want}"
        );
    }
    // The comment's figures: across the lanes ego's path is longer than the road's s, which
    // gains up to 0.35 m less than 20 m/s gives (the heading up to 0.18 rad): s within 0.4 m,
    // y within 0.01·0.4 = 4 mm of the figures at 187 and 207 m.
    for (t, s, y) in [(4.35, 187.0, -7.5175), (5.35, 207.0, -9.985)] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.s - s).abs() < 0.4 && (ego.y - y).abs() < 4e-3,
            "{t}: {ego:?}"
        );
    }
    let ego = r.at(5.35, "ego");
    let gap = (ego.y - 1.0) - (-7.0 - (3.5 + 0.01 * ego.s));
    assert!(
        (gap - 1.585).abs() < FORESEEN && ego.lane == -3,
        "{gap} {ego:?}"
    );
    ran_at(
        &r,
        &[("do.hold/ego/1:check", 5.35), ("do.hold/ego/2:check", 5.35)],
    );
}

/// runtime_lateral_gap_off.osc's comment, by hand: a lateral gap of 5 m right of npc after a
/// run-time start would put ego at t = −12.25 m, off the driving lanes: the engine's check at
/// the phase start fails the run.
#[test]
fn a_lateral_gap_off_the_driving_lanes_after_an_until_fails_the_run() {
    fails(
        "runtime_lateral_gap_off",
        (
            "expected 'ego''s place 7.000 m to the right of 'npc' in a driving lane of its side of road 1 (change_space_gap(…) at ",
            "runtime_lateral_gap_off.osc:34:9), found t = -12.250 m at s = 167.000 m, off them at t = 3.350 s",
        ),
        "do.away/ego/1:check",
        3.35,
    );
}
