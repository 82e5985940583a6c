//! Relations to another actor at `at: all` held throughout the phase (ASAM OpenSCENARIO DSL 2.1
//! §8.9.1.1.1: a constraint at `all` "holds throughout the phase"; issue 27, found in review:
//! before, `position(d, behind: x)`, `lane(same_as: x)` and, after a run-time start,
//! `lateral(…, left_of: x)` were checked at the phase start only, and a run in which they
//! stopped holding passed). Every moment is worked by hand in the scenario file
//! (`tests/scenarios/held/`).

use crate::runtime::fails;
use crate::support::{error, lower, run, run_to_error, stepped, DT};

/// Positions on the straight road: the engine's hold puts the actor at x's s − d exactly,
/// up to float round-off.
const S_TOL: f64 = 1e-6;
/// Event times are step times.
const T_TOL: f64 = 1e-9;

/// The run of `tests/scenarios/NAME.osc`, which ends without an error or an error record.
fn passes(name: &str) -> crate::support::Run {
    let lowered = lower(name, 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = run_to_error(&lowered.scenario);
    assert!(
        error.is_none() && records.is_empty(),
        "{error:?} {records:?}"
    );
    run(name, 0, None)
}

/// ego at `v` from s = `s0` at `t0`, at each of the `steps` steps after: s0 + v·(t − t0).
fn at_speed_from(r: &crate::support::Run, (t0, s0): (f64, f64), v: f64, steps: usize) {
    for k in 1..=steps {
        let t = t0 + k as f64 * DT;
        let ego = r.at(t, "ego");
        let want = s0 + v * (t - t0);
        assert!(
            (ego.s - want).abs() < S_TOL && (ego.speed - v).abs() < S_TOL,
            "{t}: {ego:?}, want {want}"
        );
    }
}

/// do.cruise from `t0` for 2 s (40 steps): lead from s = `s0` at `v_lead`, each step's speed
/// set at its end (`stepped`); ego `start_gap` behind it at `t0`, then held `gap` behind it
/// with its speed at each step, at `s_end` and lead's 12 m/s at the end; the engine's check
/// held over the phase.
fn held_behind(
    r: &crate::support::Run,
    (t0, s0): (f64, f64),
    (v_lead, gap): (&dyn Fn(f64) -> f64, &dyn Fn(f64) -> f64),
    (start_gap, s_end): (f64, f64),
) {
    assert!((r.at(t0, "lead").s - r.at(t0, "ego").s - start_gap).abs() < S_TOL);
    let ego = r.at(t0 + 2.0, "ego");
    assert!(
        (ego.s - s_end).abs() < S_TOL && (ego.speed - 12.0).abs() < S_TOL,
        "{ego:?}"
    );
    r.held("do.cruise.0/ego/1:check", (t0, t0 + 2.0));
    for k in 0..=40 {
        let t = t0 + k as f64 * DT;
        let (ego, lead) = (r.at(t, "ego"), r.at(t, "lead"));
        let s_lead = s0 + stepped(v_lead, t0, t);
        assert!((lead.s - s_lead).abs() < S_TOL, "lead {t}: {lead:?}");
        if k > 0 {
            assert!((lead.s - ego.s - gap(t)).abs() < S_TOL, "ego {t}: {ego:?}");
            assert!((ego.speed - v_lead(t)).abs() < S_TOL, "ego {t}: {ego:?}");
        }
    }
}

/// The plan's error of `tests/scenarios/held/NAME.osc`: `want`, then its place `at`.
fn refused(name: &str, want: &str, at: &str) {
    let e = error(&format!("held/{name}"));
    let tail = format!("held/{name}.osc:{at}");
    assert!(e.starts_with(want) && e.ends_with(&tail), "{e}");
}

/// behind_fails.osc: ego at its own 15 m/s, 32 m behind lead at 8 m/s at the phase start, is
/// 31.30 m behind at 2.10 s, the first step 0.5 m off: an error before the run.
#[test]
fn a_position_behind_another_that_its_own_speed_breaks_is_an_error_before_the_run() {
    let want = "expected `ego` 32.00 m behind `lead` throughout the phase (position(…) at: all, within 0.5 m), found 31.30 m at 2.10 s: `ego`'s speed 15.00 m/s, `lead`'s 8.00 m/s at ";
    refused("behind_fails", want, "23:13");
}

/// behind_fails_runtime.osc: after the until at 5.75 s, 59.75 m behind at the start and
/// closing at 7 m/s, the engine's held check finds 59.05 m at 5.85 s: an error record (at the
/// end of that step, 5.90 s) and a failed run.
#[test]
fn a_position_behind_another_after_an_until_is_the_engines_check_held_over_the_phase() {
    let want = "expected 'lead' 59.750 m from 'ego' along the road (within 0.5 m) (position(…) at ";
    let tail = "held/behind_fails_runtime.osc:26:13), found 59.050 m at t = 5.850 s";
    let element = "do.cruise/ego/2:check";
    fails("held/behind_fails_runtime", (want, tail), element, 5.9);
}

/// behind_held.osc: ego has nothing of its own along its lane, so position(32m, behind: lead)
/// determines its motion: s_ego = s_lead − 32 and lead's speed at every step while lead
/// accelerates 8 → 16 m/s over [2, 6] s; the plan's track took lead's profile (do.after's
/// check of 178 m at 6 s passes), and ego keeps 16 m/s after.
#[test]
fn a_position_behind_another_alone_holds_the_actor_there_throughout() {
    let r = run("held/behind_held", 0, None);
    let (s, e) = r.phase("do.follow");
    assert!(
        (s - 2.0).abs() < T_TOL && (e - 6.0).abs() < T_TOL,
        "[{s}, {e}]"
    );
    // lead: 8 + 2·τ m/s from 2 s, each step's speed set at its end (support::stepped).
    let v_lead = |t: f64| 8.0 + 2.0 * (t.clamp(2.0, 6.0) - 2.0);
    for k in 0..=80 {
        let t = 2.0 + k as f64 * DT;
        let (ego, lead) = (r.at(t, "ego"), r.at(t, "lead"));
        let s_lead = 162.0 + stepped(v_lead, 2.0, t);
        assert!((lead.s - s_lead).abs() < S_TOL, "lead {t}: {lead:?}");
        assert!((ego.s - (s_lead - 32.0)).abs() < S_TOL, "ego {t}: {ego:?}");
        if k > 0 {
            assert!((ego.speed - v_lead(t)).abs() < S_TOL, "ego {t}: {ego:?}");
        }
    }
    // 150.1 m and 12 m/s at 4 s, 178.2 m and 16 m/s at 6 s (the steps' 0.05·τ m over the
    // closed form 130 + 8τ + τ²), then 16 m/s: 194.2 m at 7 s.
    for (t, s, v) in [(4.0, 150.1, 12.0), (6.0, 178.2, 16.0), (7.0, 194.2, 16.0)] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.s - s).abs() < S_TOL && (ego.speed - v).abs() < S_TOL,
            "{t}: {ego:?}"
        );
    }
}

/// lane_same_as_fails.osc: npc changes into lane -1 over [1, 5] s and ego, lane(same_as: npc)
/// at: all beside keep_lane(), does not: an error before the run at 5.00 s, where the plan has
/// npc in lane -1.
#[test]
fn a_lane_same_as_another_that_changes_lane_while_the_actor_keeps_its_lane_is_an_error() {
    let want = "expected `ego` in lane -1 throughout the phase (lane(…) at: all, counted from `npc`'s lane -1 then), found it in lane -2 at 5.00 s at ";
    refused("lane_same_as_fails", want, "24:17");
}

/// lane_same_as_follows.osc: ego changes lane with npc, over the same 4 s: in npc's lane at
/// every step (both cross the border between lanes -2 and -1 half way, at 3 s), both in lane
/// -1 from there.
#[test]
fn a_lane_same_as_another_that_changes_lane_with_it_holds_throughout() {
    let r = run("held/lane_same_as_follows", 0, None);
    for k in 0..=100 {
        let t = k as f64 * DT;
        let (ego, npc) = (r.at(t, "ego"), r.at(t, "npc"));
        assert_eq!(ego.lane, npc.lane, "{t}: {ego:?} {npc:?}");
        let want = if t < 3.0 - T_TOL { -2 } else { -1 };
        if (t - 3.0).abs() > DT / 2.0 {
            assert_eq!(ego.lane, want, "{t}: {ego:?}");
        }
    }
}

/// lateral_follow_runtime.osc: after the until at 3.35 s npc moves 1 m right over 2 s and ego,
/// lateral(3.5m, left_of: npc) at: all, follows it: t = -5.25 - f at every step, f = (1 −
/// cos(π·τ/2))/2, -5.75 m at 4.35 s, -6.25 m in lane -2 at 5.35 s; the engine's check of
/// t − t_x held over the phase passes (the run ends without an error).
#[test]
fn a_lateral_position_beside_another_after_an_until_follows_it_throughout() {
    let r = passes("held/lateral_follow_runtime");
    let (s, e) = r.phase("do.shift");
    assert!(
        (s - 3.35).abs() < T_TOL && (e - 5.35).abs() < T_TOL,
        "[{s}, {e}]"
    );
    let f = |t: f64| (1.0 - (std::f64::consts::PI * (t.min(5.35) - 3.35) / 2.0).cos()) / 2.0;
    for k in 0..=60 {
        let t = 3.35 + k as f64 * DT;
        let (ego, npc) = (r.at(t, "ego"), r.at(t, "npc"));
        assert!((npc.y - (-8.75 - f(t))).abs() < S_TOL, "npc {t}: {npc:?}");
        assert!((ego.y - (-5.25 - f(t))).abs() < S_TOL, "ego {t}: {ego:?}");
        assert_eq!(ego.lane, -2, "{t}: {ego:?}");
    }
    assert!((r.at(4.35, "ego").y + 5.75).abs() < S_TOL);
    assert!((r.at(5.35, "ego").y + 6.25).abs() < S_TOL);
    r.held("do.shift.0/ego/1:check", (3.35, 5.35));
}

/// behind_held_runtime.osc: after the until at 5.75 s ego, free along its lane, is held
/// 59.75 m behind lead while lead accelerates 8 → 12 m/s over 2 s: s_ego = s_lead − 59.75 and
/// lead's speed at every step, 206.35 m and 12 m/s at 7.75 s (lead 266.1 m); the engine's held
/// check passes.
#[test]
fn a_position_behind_another_alone_after_an_until_is_the_engines_hold() {
    let r = run("held/behind_held_runtime", 0, None);
    let (s, e) = r.phase("do.cruise");
    assert!(
        (s - 5.75).abs() < T_TOL && (e - 7.75).abs() < T_TOL,
        "[{s}, {e}]"
    );
    let v_lead = |t: f64| 8.0 + 2.0 * (t.clamp(5.75, 7.75) - 5.75);
    held_behind(&r, (5.75, 246.0), (&v_lead, &|_| 59.75), (59.75, 206.35));
}

/// first_phase_fails.osc: a first phase's position(20m, ahead_of: lead) at: all with ego's own
/// 10 m/s against lead's 20 m/s: an error before the run at 0.10 s.
#[test]
fn a_first_phases_position_ahead_of_another_its_speed_breaks_is_an_error_before_the_run() {
    let want = "expected `ego` 20.00 m ahead of `lead` throughout the phase (position(…) at: all, within 0.5 m), found 19.00 m at 0.10 s: `ego`'s speed 10.00 m/s, `lead`'s 20.00 m/s at ";
    refused("first_phase_fails", want, "16:13");
}

/// behind_projected.osc: ego, free along its lane, 32 m behind lead as projected from 2 s
/// (track: projected) keeps lead's 8 m/s of the start while lead accelerates: s_ego = 130 +
/// 8·τ at every step, 162 m at 6 s (the plan's check there passes), 170 m at 7 s.
#[test]
fn a_position_behind_a_projected_actor_alone_keeps_its_speed_of_the_start() {
    let r = run("held/behind_projected", 0, None);
    at_speed_from(&r, (2.0, 130.0), 8.0, 100);
    assert!((r.at(6.0, "lead").s - 210.2).abs() < S_TOL);
}

/// lane_same_as_followed.osc: npc changes into lane -1 over [1, 5] s and ego, lane(same_as:
/// npc) at: all with no sideways motion of its own, follows it: y = -5.25 + 3.5·f at every step
/// for both, f = (1 − cos(π·τ/4))/2, the same lane at every step (-2 before 3 s, -1 after).
#[test]
fn a_lane_same_as_another_that_changes_lane_is_followed() {
    let r = run("held/lane_same_as_followed", 0, None);
    lane_followed(&r, 0.0, 1.0, 100);
}

/// npc's 4 s sinusoidal change from lane -2 into lane -1 from `t0` and ego following it at
/// each of the `steps` steps from `from`: y = -5.25 + 3.5·f for both, f = (1 − cos(π·τ/4))/2,
/// τ = t − t0, in one lane (-2 before the border at t0 + 2 s, -1 after).
fn lane_followed(r: &crate::support::Run, from: f64, t0: f64, steps: usize) {
    let f =
        |t: f64| (1.0 - (std::f64::consts::PI * (t.clamp(t0, t0 + 4.0) - t0) / 4.0).cos()) / 2.0;
    let border = t0 + 2.0;
    for k in 0..=steps {
        let t = from + k as f64 * DT;
        let (ego, npc) = (r.at(t, "ego"), r.at(t, "npc"));
        let want = -5.25 + 3.5 * f(t);
        assert!((npc.y - want).abs() < S_TOL, "npc {t}: {npc:?}");
        assert!((ego.y - want).abs() < S_TOL, "ego {t}: {ego:?}");
        assert_eq!(ego.lane, npc.lane, "{t}: {ego:?} {npc:?}");
        if (t - border).abs() > DT / 2.0 {
            assert_eq!(ego.lane, if t < border { -2 } else { -1 }, "{t}: {ego:?}");
        }
    }
}

/// speed_faster_than.osc: `speed(2mps, faster_than: lead)` at: all in ego's first phase is
/// lead's speed + 2 at every step while lead accelerates (before, lead's at the start + 2,
/// held), and the speed ego has where the phase ends (18 m/s) is the plan's for the next.
#[test]
fn a_speed_faster_than_another_in_a_first_phase_follows_its_speed_throughout() {
    let r = run("held/speed_faster_than", 0, None);
    for k in 0..=120 {
        let t = k as f64 * DT;
        let (ego, lead) = (r.at(t, "ego"), r.at(t, "lead"));
        // v_l = 10 + t (lead's acceleration), v_e = v_l + 2.
        assert!(
            (lead.speed - (10.0 + t)).abs() < S_TOL,
            "lead {t}: {lead:?}"
        );
        assert!(
            (ego.speed - (lead.speed + 2.0)).abs() < S_TOL,
            "ego {t}: {ego:?}"
        );
        // Both move a step at the step's end speed: the gap closes by 2 m/s, 50 - 2t.
        assert!(
            ((lead.s - ego.s) - (50.0 - 2.0 * t)).abs() < S_TOL,
            "{t}: {ego:?} {lead:?}"
        );
    }
    // 44 m at 3 s, 38 m at 6 s; then 18 m/s (lead's 16 + 2 at 6 s) with lead at 17 m/s at 7 s.
    for (t, gap) in [(3.0, 44.0), (6.0, 38.0)] {
        assert!(((r.at(t, "lead").s - r.at(t, "ego").s) - gap).abs() < S_TOL);
    }
    let ego7 = r.at(7.0, "ego");
    assert!((ego7.speed - 18.0).abs() < S_TOL, "{ego7:?}");
    assert!((r.at(7.0, "lead").speed - 17.0).abs() < S_TOL);
}

/// behind_projected_runtime.osc: after the until at 5.75 s ego, free along its lane, 59.75 m
/// behind lead as projected from then (track: projected), keeps lead's 8 m/s of the start while
/// lead accelerates to 12 m/s: s_ego = 186.25 + 8·τ at every step, 202.25 m at 7.75 s (lead at
/// 266.1 m); the engine's check against the projection, held over the phase, passes.
#[test]
fn a_position_behind_a_projected_actor_after_an_until_keeps_its_speed_of_the_start() {
    let r = passes("held/behind_projected_runtime");
    let (s, e) = r.phase("do.cruise");
    assert!(
        (s - 5.75).abs() < T_TOL && (e - 7.75).abs() < T_TOL,
        "[{s}, {e}]"
    );
    at_speed_from(&r, (5.75, 186.25), 8.0, 40);
    assert!((r.at(7.75, "lead").s - 266.1).abs() < S_TOL);
    r.held("do.cruise.0/ego/1:check", (5.75, 7.75));
}

/// behind_projected_runtime_fails.osc: after the until at 5.75 s ego at its own 11 m/s while
/// lead accelerates 8 → 11 m/s; lead projected from 5.75 s goes on at 8 m/s: the gap to it is
/// 59.75 − 3·τ, 59.15 m at 5.95 s, the first step 0.5 m off (against lead as it is: 59.1875
/// m): an error record (at the end of that step, 6.00 s) and a failed run.
#[test]
fn a_position_behind_a_projected_actor_after_an_until_is_the_engines_check_held_over_the_phase() {
    let want = "expected 'lead' projected from 5.750 s at 8.000 m/s 59.750 m from 'ego' along the road (within 0.5 m) (position(…) at ";
    let tail = "held/behind_projected_runtime_fails.osc:31:17), found 59.150 m at t = 5.950 s";
    let element = "do.cruise.0/ego/2:check";
    fails(
        "held/behind_projected_runtime_fails",
        (want, tail),
        element,
        6.0,
    );
}

/// group_behind_fails.osc: a group's position(50m, behind: lead) at: all is member 0's, checked
/// at every step: member 0 at its own 10 m/s while lead accelerates at 2 m/s², 50 + τ² m apart,
/// 50.56 m at 2.75 s, the first step 0.5 m off: an error before the run.
#[test]
fn a_groups_position_behind_another_that_breaks_is_an_error_before_the_run() {
    let want = "expected `g.vehicles[0]` 50.00 m behind `lead` throughout the phase (position(…) at: all, within 0.5 m), found 50.56 m at 2.75 s: `g.vehicles[0]`'s speed 10.00 m/s, `lead`'s 11.50 m/s at ";
    refused("group_behind_fails", want, "29:17");
}

/// lane_same_as_projected_runtime.osc: after the until at 5.75 s npc changes into lane -1 over
/// 4 s; ego, lane(same_as: npc, track: projected) beside keep_lane(), stays in npc's lane of
/// the start, -2, at every step while npc is in lane -1 from 7.75 s: the engine's check held
/// over the phase against that lane passes.
#[test]
fn a_lane_same_as_a_projected_actor_after_an_until_is_its_lane_at_the_start() {
    let r = passes("held/lane_same_as_projected_runtime");
    let (s, e) = r.phase("do.both");
    assert!(
        (s - 5.75).abs() < T_TOL && (e - 9.75).abs() < T_TOL,
        "[{s}, {e}]"
    );
    for k in 0..=80 {
        let t = 5.75 + k as f64 * DT;
        assert_eq!(r.at(t, "ego").lane, -2, "{t}");
    }
    assert_eq!(r.at(8.0, "npc").lane, -1);
    assert_eq!(r.at(9.75, "npc").lane, -1);
    r.held("do.both.0/ego/1:check", (5.75, 9.75));
}

/// lateral_projected_runtime.osc: after the until at 3.35 s npc moves 1 m right over 2 s; ego,
/// lateral(3.5m, left_of: npc, track: projected) at: all, stays 3.5 m left of npc's t at 3.35 s:
/// y = -5.25 m at every step while npc reaches -9.75 m; the engine's check against that t, held
/// over the phase, passes.
#[test]
fn a_lateral_position_beside_a_projected_actor_after_an_until_is_beside_its_t_at_the_start() {
    let r = passes("held/lateral_projected_runtime");
    for k in 0..=40 {
        let t = 3.35 + k as f64 * DT;
        let ego = r.at(t, "ego");
        assert!(
            (ego.y + 5.25).abs() < S_TOL && ego.lane == -2,
            "{t}: {ego:?}"
        );
    }
    assert!((r.at(5.35, "npc").y + 9.75).abs() < S_TOL);
    r.held("do.shift.0/ego/1:check", (3.35, 5.35));
}

/// behind_projected_until.osc: from 2 s (a start the plan knows) until lead is above 12 m/s
/// (an end it does not), ego, free along its lane, 32 m behind lead projected from 2 s, keeps
/// lead's 8 m/s of the start: s_ego = 130 + 8·τ at every step to 4 s while lead accelerates;
/// the engine's check against the projection, held over the phase, passes.
#[test]
fn a_position_behind_a_projected_actor_until_a_run_time_end_is_the_engines_held_check() {
    let r = passes("held/behind_projected_until");
    let (s, e) = r.phase("do.follow.0");
    assert!(
        (s - 2.0).abs() < T_TOL && (4.0..=4.2).contains(&e),
        "[{s}, {e}]"
    );
    at_speed_from(&r, (2.0, 130.0), 8.0, 40);
    let check = "do.follow.0/ego/2:check";
    assert!(r
        .when(check, "Start")
        .is_some_and(|t| (t - 2.0).abs() < T_TOL));
    assert!(r.when(check, "End").is_none());
}

/// opposite_behind_projected_fails.osc: npc and truck oncoming (lane 1, driven in -s); after
/// quick at 1.10 s npc at its own 23 m/s 30 m behind truck projected from then at 20 m/s along
/// their direction of travel: the gap 30 − 3·τ, 29.40 m at 1.30 s, the first step 0.5 m off: an
/// error record (at the end of that step, 1.35 s) and a failed run.
#[test]
fn an_oncoming_position_behind_a_projected_actor_is_measured_along_its_direction_of_travel() {
    let want = "expected 'truck' projected from 1.100 s at 20.000 m/s 30.000 m from 'npc' along the direction of travel (against s) (within 0.5 m) (position(…) at ";
    let tail = "held/opposite_behind_projected_fails.osc:45:17), found 29.400 m at t = 1.300 s";
    let element = "do.2.1/npc/2:check";
    fails(
        "held/opposite_behind_projected_fails",
        (want, tail),
        element,
        1.35,
    );
}

/// first_phase_runtime_fails.osc: npc's first phase starts at 5.75 s (after an until) with
/// position(30m, behind: lead) at: all; placed 30 m behind lead at the run's start and driving
/// its 20 m/s from then, npc is 39 m ahead of lead when the phase starts: the engine's check
/// then, an error record at 5.75 s and a failed run.
#[test]
fn a_first_phase_after_a_run_time_start_is_the_engines_check_of_its_relation() {
    let want = "expected 'lead' 30.000 m from 'npc' along the road (within 0.5 m) (position(…) at ";
    let tail = "held/first_phase_runtime_fails.osc:28:17), found -39.000 m at t = 5.750 s";
    let element = "do.later.0/npc/1:check";
    fails(
        "held/first_phase_runtime_fails",
        (want, tail),
        element,
        5.75,
    );
}

/// first_phase_runtime_position_fails.osc: npc's first phase starts at run time (5.75 s) and
/// asks position(50m, at: start); placed there at the run's start at 20 m/s, npc is at 165 m
/// when the phase starts: the engine's check then, an error record at 5.75 s and a failed run.
#[test]
fn a_first_phases_absolute_position_after_a_run_time_start_is_the_engines_check() {
    let want = "expected 'npc' at s = 50.000 m (within 0.5 m) (position(…) at ";
    let tail = "held/first_phase_runtime_position_fails.osc:29:17), found it at s = 165.000 m at t = 5.750 s";
    fails(
        "held/first_phase_runtime_position_fails",
        (want, tail),
        // Its second check: lane(2)'s, the first, holds.
        "do.later.0/npc/2:check",
        5.75,
    );
}

/// behind_default_held_runtime.osc: after the until at 11.95 s ego, free along its lane with
/// the default gap, is held 2 s · v_lead behind lead while lead accelerates 8 → 12 m/s over
/// 2 s: s_ego = s_lead − 2·v_lead and lead's speed at every step, 291.7 m and 12 m/s at 13.95 s
/// (lead 315.7 m); the engine's held check passes.
#[test]
fn a_default_gap_behind_another_alone_after_an_until_is_the_engines_hold() {
    let r = passes("held/behind_default_held_runtime");
    crate::runtime::phases(&r, &[("do.cruise", 11.95, 13.95)]);
    let v_lead = |t: f64| 8.0 + 2.0 * (t.clamp(11.95, 13.95) - 11.95);
    // At the start the check found 16.35 m where 16 m is asked (within 0.5 m).
    held_behind(
        &r,
        (11.95, 295.6),
        (&v_lead, &|t| 2.0 * v_lead(t)),
        (16.35, 291.7),
    );
}

/// lane_same_as_followed_runtime.osc: after the until at 5.05 s npc changes into lane -1 over
/// [5.05, 9.05] s and ego, lane(same_as: npc) at: all with no sideways motion of its own, is
/// the engine's to follow: y = -5.25 + 3.5·f at every step for both, f = (1 − cos(π·τ/4))/2,
/// τ = t − 5.05, the same lane at every step (-2 before 7.05 s, -1 after); car, lane(right_of:
/// npc), from lane -3 into -2 with it, 3.5 m to the right (at 7.0 s npc's -3.568705 m less
/// 3.5); the engine's held checks pass.
#[test]
fn a_lane_same_as_another_that_changes_lane_after_an_until_is_followed() {
    let r = passes("held/lane_same_as_followed_runtime");
    let both = [("do.approach", 0.0, 5.05), ("do.both", 5.05, 9.05)];
    crate::runtime::phases(&r, &both);
    lane_followed(&r, 5.05, 5.05, 80);
    // car one lane to the right of npc's: -8.75 + 3.5·f, lane -3, then -2 (after 7.05 s).
    for (t, y, lane) in [
        (5.05, -8.75, -3),
        (7.0, -7.068705, -3),
        (7.1, -6.931295, -2),
    ] {
        let car = r.at(t, "car");
        assert!(
            (car.y - y).abs() < S_TOL && car.lane == lane,
            "{t}: {car:?}"
        );
    }
    let car = r.at(9.05, "car");
    assert!((car.y + 5.25).abs() < S_TOL && car.lane == -2, "{car:?}");
    r.held("do.both.2/car/1:check", (5.05, 9.05));
    r.held("do.both.0/ego/1:check", (5.05, 9.05));
}

/// (name, the lane before and after the border at 7.05 s, y at the change's start) of each
/// actor `want` asks: from 5.05 s, 80 steps, y = y0 + 3.5·f at every step, f = (1 −
/// cos(π·τ/4))/2, τ = t − 5.05 (npc's 4 s change from lane -2 into -1, followed), the lane
/// `before` until the border step and `after` from the step after it; and `who`'s y at each
/// (t, y) of `by_hand`, worked by hand (within 1e-6 m).
fn lanes_followed(
    r: &crate::support::Run,
    want: &[(&str, (i32, i32), f64)],
    (who, by_hand): (&str, &[(f64, f64)]),
) {
    let f = |t: f64| (1.0 - (std::f64::consts::PI * (t.min(9.05) - 5.05) / 4.0).cos()) / 2.0;
    for k in 0..=80 {
        let t = 5.05 + k as f64 * DT;
        for &(name, (before, after), y0) in want {
            let e = r.at(t, name);
            let y = y0 + 3.5 * f(t);
            assert!((e.y - y).abs() < S_TOL, "{name} {t}: {e:?}, want y {y}");
            if (t - 7.05).abs() > DT / 2.0 {
                let lane = if t < 7.05 { before } else { after };
                assert_eq!(e.lane, lane, "{name} {t}: {e:?}");
            }
        }
    }
    for &(t, y) in by_hand {
        let e = r.at(t, who);
        assert!((e.y - y).abs() < 1e-6, "{who} {t}: {e:?}");
    }
}

/// The run of `tests/scenarios/NAME.osc`, which passes, with do.approach until 5.05 s and
/// do.both from there to 9.05 s, each of `want` following npc's change as
/// [`lanes_followed`] has it.
fn followed_after_until(
    name: &str,
    want: &[(&str, (i32, i32), f64)],
    by_hand: (&str, &[(f64, f64)]),
) -> crate::support::Run {
    let r = passes(name);
    let both = [("do.approach", 0.0, 5.05), ("do.both", 5.05, 9.05)];
    crate::runtime::phases(&r, &both);
    lanes_followed(&r, want, by_hand);
    r
}

/// lane_two_followed_runtime.osc: after the until at 5.05 s npc (-2 into -1) and truck (-3
/// into -2) change lanes at once over 4 s; ego, `lane(same_as: npc)` and `lane(left_of:
/// truck)`, follows both: y = -5.25 + 3.5·f at every step (-4.737437 m at 6.05 s, -3.5 m at
/// 7.05 s, -2.262563 m at 8.05 s, by hand), npc's, in -2 then -1; both held checks pass.
/// Before, with two lane relations, ego kept lane -2 and the held checks failed.
#[test]
fn two_lane_relations_whose_references_change_together_after_an_until_are_followed() {
    let r = followed_after_until(
        "held/lane_two_followed_runtime",
        &[
            ("npc", (-2, -1), -5.25),
            ("truck", (-3, -2), -8.75),
            ("ego", (-2, -1), -5.25),
        ],
        ("ego", &[(6.05, -4.737437), (7.05, -3.5), (8.05, -2.262563)]),
    );
    r.held("do.both.0/ego/1:check", (5.05, 9.05));
    r.held("do.both.0/ego/3:check", (5.05, 9.05));
}

/// lane_two_conflict_runtime.osc: after the until at 5.05 s npc changes from -2 into -1 and
/// truck from -1 into -2 at once; ego's `lane(same_as: npc)` and `lane(right_of: truck)` then
/// disagree (-1 and -3). ego follows the first relation, npc's (y = -5.25 + 3.5·f, -3.431295 m
/// at 7.10 s), and the held check of the second fails at 7.10 s, the first step past the
/// border (npc and ego in -1, truck in -2): an error record and a failed run.
#[test]
fn two_lane_relations_whose_references_change_in_disagreement_follow_the_first_and_fail_the_run() {
    let name = "held/lane_two_conflict_runtime";
    let want = "expected 'ego' in lane -3 of road 1, 1 lane to the right of 'truck''s lane -2 (lane(…) at ";
    let tail =
        "held/lane_two_conflict_runtime.osc:39:17), found it in lane -1 of road 1 at t = 7.100 s";
    fails(name, (want, tail), "do.both.0/ego/3:check", 7.15);
    // The frames up to the failure: the run stopped at 7.10 s, before the check's step.
    let r = run(name, 0, Some(7.1));
    let ego = r.at(7.1, "ego");
    assert!((ego.y + 3.431295).abs() < 1e-6 && ego.lane == -1, "{ego:?}");
    let truck = r.at(7.1, "truck");
    assert!(
        (truck.y + 3.568705).abs() < 1e-6 && truck.lane == -2,
        "{truck:?}"
    );
}

/// The chain of lane_chain_followed(_runtime).osc: npc's change, ego at npc's y, car one lane
/// to its right, van at ego's y.
const CHAIN: [(&str, (i32, i32), f64); 4] = [
    ("npc", (-2, -1), -5.25),
    ("ego", (-2, -1), -5.25),
    ("car", (-3, -2), -8.75),
    ("van", (-2, -1), -5.25),
];

/// lane_chain_followed_runtime.osc: after the until at 5.05 s npc changes from -2 into -1 over
/// 4 s; ego `lane(same_as: npc)`; car `lane(right_of: ego)`, whose invocation is written
/// before ego's, sees ego's new lane in the same step (planned after ego, and the engine steps
/// it after ego's following): y = -8.75 + 3.5·f at every step (-8.237437 m at
/// 6.05 s, -7.0 m at 7.05 s, -5.762563 m at 8.05 s, by hand), -3 then -2; van `lane(same_as:
/// ego)`, after it, at ego's y, -2 then -1. Every held check passes.
#[test]
fn a_chain_of_lane_relations_after_an_until_is_followed_in_the_same_step() {
    let r = followed_after_until(
        "held/lane_chain_followed_runtime",
        &CHAIN,
        ("car", &[(6.05, -8.237437), (7.05, -7.0), (8.05, -5.762563)]),
    );
    r.held("do.both.0/car/1:check", (5.05, 9.05));
    r.held("do.both.1/ego/1:check", (5.05, 9.05));
    r.held("do.both.3/van/1:check", (5.05, 9.05));
}

/// The engine resolves the entities a state check names once, when it builds the storyboard,
/// and reads them by id at every step after (engine `actions::check::CheckRefs`): a check that
/// names an entity the scenario does not declare is refused then, at the check's file, line
/// and column, before the run's first step. behind_held_runtime.osc's held check of
/// `position(59.75m, behind: lead)` (27:17) with lead renamed `ghost` in the lowered scenario
/// (the DSL's own check refuses an undeclared name in a `.osc`, so only a model built by
/// other means can hold one).
#[test]
fn a_state_check_naming_an_undeclared_entity_is_refused_when_the_engine_is_built() {
    let lowered = lower("held/behind_held_runtime", 0, None).unwrap_or_else(|e| panic!("{e}"));
    let mut scenario = lowered.scenario;
    let checks = scenario
        .storyboard
        .stories
        .iter_mut()
        .flat_map(|s| &mut s.acts)
        .flat_map(|a| &mut a.maneuver_groups)
        .flat_map(|g| &mut g.maneuvers)
        .flat_map(|m| &mut m.events)
        .flat_map(|e| &mut e.actions)
        .filter_map(|a| match &mut a.kind {
            scenario::ActionKind::Private(scenario::PrivateAction::Check(c)) => Some(c),
            _ => None,
        });
    let mut renamed = 0;
    for check in checks {
        if let Some((gap, _)) = check.gap.as_mut().filter(|g| g.0.entity_ref == "lead") {
            gap.entity_ref = "ghost".into();
            renamed += 1;
        }
    }
    assert_eq!(
        renamed, 1,
        "the one held check of ego's position behind lead"
    );
    let network = engine::load::road_network(&scenario).unwrap_or_else(|e| panic!("{e}"));
    let e = match engine::Engine::new(&scenario, network, crate::support::config()) {
        Ok(_) => panic!("built with a check naming 'ghost'"),
        Err(e) => e,
    };
    let pos = e.pos().map(|p| p.to_string()).unwrap_or_default();
    assert!(
        pos.ends_with("held/behind_held_runtime.osc:27:17"),
        "{pos}: {e}"
    );
    let want = "expected a declared entity for position(…) at ";
    let tail = "held/behind_held_runtime.osc:27:17, found 'ghost' at ";
    let text = e.to_string();
    assert!(text.starts_with(want) && text.contains(tail), "{text}");
}

/// lane_chain_followed.osc: the chain of lane_chain_followed_runtime.osc at a start the plan
/// knows (5.05 s): car `lane(right_of: ego)`, written before ego `lane(same_as: npc)`, is
/// planned after it and changes lane with it, y = -8.75 + 3.5·f at every step (-7.0 m at
/// 7.05 s, by hand); ego and van at npc's y. Before, the plan refused it (car in lane -3 where
/// -2 was asked at 9.05 s).
#[test]
fn a_chain_of_lane_relations_at_a_known_start_is_planned_from_its_head() {
    let r = passes("held/lane_chain_followed");
    lanes_followed(&r, &CHAIN, ("car", &[(7.05, -7.0)]));
}

/// lane_follow_engine_then_known.osc: ego follows npc's lanes in do.both [1, 5] s as the
/// engine's (npc under avoid_collisions(true)): at npc's y at every step, y = -5.25 + 3.5·f,
/// f = (1 − cos(π·τ/4))/2, τ = t − 1 (-4.737437 m at 2 s, -3.5 m at 3 s), in lane -1 from
/// 3.05 s and at -1.75 m at 5 s. Its later phase at 5 s, a time the plan sets, asks ego's lane
/// (lane(2)), which the engine sets from 1 s: an error at the invocation. Before 3293425b the
/// plan's track kept ego in lane -2 and passed its lane(2) while the engine ran ego in lane -1
/// (lane 3) to 7 s.
#[test]
fn a_later_phase_at_a_known_time_reading_the_lane_the_engine_sets_is_an_error() {
    let want = "expected this phase of `ego` to start on a run-time condition (until, wait), or to leave its lane alone, found it at 5.00 s reading `ego`'s lane at 5.00 s, which the engine sets from 1.00 s (a following of the lanes of an actor the engine moves, lane(…: x) at: all): the plan knows its speed and its place along its lane, not its lane at ";
    refused("lane_follow_engine_then_known", want, "34:9");
}

/// lane_follow_engine_then_speed.osc: the same following over [1, 5] s, then a later phase at
/// 5 s that leaves ego's lane alone, speed(15mps, at: end) over 2 s: it runs (before, refused
/// as every later phase at a time the plan sets): the engine moves each step at the speed at
/// its end, so x = x5 + 10·τ + 1.25·τ·(τ + dt), τ = t − 5, at every step (x5 + 11.3125 m at
/// 6 s, x5 + 25.125 m at 7 s), y = -1.75 m in lane -1 where the engine has it. x5, where the engine has ego at 5 s, is 100 m less what the followed change's
/// sideways motion cost along the road at 10 m/s: ∫ y'²/20 + y'⁴/8000 dt over 4 s, y' =
/// (3.5π/8)·sin(π·τ/4), = 1.889/10 + 3.569·1.5/8000 = 0.18959 m, x5 = 99.8104 m (the
/// engine's steps take each step's mean share: within 1e-3 m).
#[test]
fn a_later_phase_at_a_known_time_that_leaves_the_lane_the_engine_sets_alone_runs() {
    let r = passes("held/lane_follow_engine_then_speed");
    crate::support::phases_are(&r, &[("do.after", 5.0, 7.0)]);
    let x5 = r.at(5.0, "ego").x;
    assert!((x5 - 99.8104).abs() < 1e-3, "{x5}");
    for k in 0..=40 {
        let t = 5.0 + k as f64 * DT;
        let tau = t - 5.0;
        let ego = r.at(t, "ego");
        let s = x5 + 10.0 * tau + 1.25 * tau * (tau + DT);
        assert!(
            (ego.x - s).abs() < S_TOL && (ego.y + 1.75).abs() < S_TOL && ego.lane == -1,
            "ego at {t} s: {ego:?}, want x {s}, y -1.75 in lane -1"
        );
    }
}

/// lane_follow_known_then_engine.osc: ego's lane(same_as: npc) in two phases, npc's lane
/// change the plan's in do.known [1, 5] s (ego's LaneChangeAction over its span) and the
/// engine's in do.engine [5, 9] s (npc under avoid_collisions(true); ego's FollowLanes): ego
/// at npc's y at every step, y = -5.25 + 3.5·f(t − 1) to 5 s, then -1.75 − 3.5·f(t − 5),
/// f(τ) = (1 − cos(π·τ/4))/2 (by hand: -4.737437, -2.262563 m at 2, 4 s; -2.262563,
/// -4.737437 m at 6, 8 s), in one lane (the borders at 3 and 7 s, y = -3.5 m, aside); the
/// engine's held check over do.engine passes, and do.after (a run-time start at 9.05 s) finds
/// ego in lane 2 (-2) where the engine has it.
#[test]
fn a_lane_same_as_another_whose_changes_are_the_plans_then_the_engines_is_followed_in_both() {
    let r = passes("held/lane_follow_known_then_engine");
    crate::runtime::phases(
        &r,
        &[
            ("do.known", 1.0, 5.0),
            ("do.engine", 5.0, 9.0),
            ("do.after", 9.05, 11.05),
        ],
    );
    let f = |tau: f64| (1.0 - (std::f64::consts::PI * tau.clamp(0.0, 4.0) / 4.0).cos()) / 2.0;
    let y = |t: f64| match t <= 5.0 {
        true => -5.25 + 3.5 * f(t - 1.0),
        false => -1.75 - 3.5 * f(t - 5.0),
    };
    for k in 0..=160 {
        let t = 1.0 + k as f64 * DT;
        let (ego, npc) = (r.at(t, "ego"), r.at(t, "npc"));
        assert!((npc.y - y(t)).abs() < S_TOL, "npc {t}: {npc:?}");
        assert!((ego.y - y(t)).abs() < S_TOL, "ego {t}: {ego:?}");
        if (t - 3.0).abs() > DT / 2.0 && (t - 7.0).abs() > DT / 2.0 {
            let lane = if (3.0..7.0).contains(&t) { -1 } else { -2 };
            assert_eq!((ego.lane, npc.lane), (lane, lane), "{t}: {ego:?}");
        }
    }
    for (t, want) in [
        (2.0, -4.737437),
        (4.0, -2.262563),
        (6.0, -2.262563),
        (8.0, -4.737437),
    ] {
        assert!((r.at(t, "ego").y - want).abs() < 1e-6, "{t}");
    }
    r.held("do.engine.0/ego/2:check", (5.0, 9.0));
    let after = r.when("do.after/ego/1:check", "End");
    assert!(after.is_some_and(|t| (t - 9.05).abs() < T_TOL), "{after:?}");
}
