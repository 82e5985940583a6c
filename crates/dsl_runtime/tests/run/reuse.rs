//! Scenarios that invoke scenarios (ASAM OpenSCENARIO DSL 2.1 §7.3.9 behavior invocation):
//! parameters, phase paths, each invocation's own actors, the entry point. Every expectation
//! is worked by hand in the scenario file's comment.

use super::support::{error, run, Run};

/// Positions on the straight road: exact up to float round-off.
const S_TOL: f64 = 1e-6;
/// Phase times are step times.
const T_TOL: f64 = 1e-9;

fn close(a: (f64, f64), b: (f64, f64)) -> bool {
    (a.0 - b.0).abs() < T_TOL && (a.1 - b.1).abs() < T_TOL
}

/// Each phase of `r` at `path` runs over the interval given with it.
fn phases_are(r: &Run, want: &[(&str, (f64, f64))]) {
    for (path, want) in want {
        let got = r.phase(path);
        assert!(close(got, *want), "{path}: {got:?}, expected {want:?}");
    }
}

#[test]
fn a_scenario_invoked_twice_in_serial_and_once_in_parallel() {
    let r = run("reuse_serial_parallel", 0, None);
    phases_are(
        &r,
        &[
            ("do.start", (0.0, 1.0)),
            ("do.round_one", (1.0, 5.0)),
            ("do.round_one.quick", (1.0, 3.0)),
            ("do.round_one.slow", (3.0, 5.0)),
            ("do.round_two", (5.0, 8.0)),
            ("do.round_two.quick", (5.0, 7.0)),
            ("do.round_two.slow", (7.0, 8.0)),
            ("do.together", (8.0, 12.0)),
            ("do.together.0", (8.0, 12.0)),
            ("do.together.0.quick", (8.0, 10.0)),
            ("do.together.0.slow", (10.0, 12.0)),
            ("do.together.1", (8.0, 11.0)),
            ("do", (0.0, 12.0)),
        ],
    );
    for (t, s, v) in [
        (1.0, 110.0, 10.0),
        (3.0, 150.0, 20.0),
        (5.0, 160.0, 5.0),
        (7.0, 190.0, 15.0),
        (8.0, 200.0, 10.0),
        (10.0, 240.0, 20.0),
        (12.0, 264.0, 12.0),
    ] {
        let ego = r.at(t, "ego");
        assert!((ego.s - s).abs() < S_TOL, "ego at {t} s: s = {}", ego.s);
        assert!(
            (ego.speed - v).abs() < S_TOL,
            "ego at {t} s: v = {}",
            ego.speed
        );
        assert_eq!(ego.lane, -2);
    }
    for (t, s) in [(8.0, 330.0), (11.0, 420.0), (12.0, 450.0)] {
        let npc = r.at(t, "npc");
        assert!((npc.s - s).abs() < S_TOL, "npc at {t} s: s = {}", npc.s);
        assert_eq!(npc.lane, -1);
    }
}

#[test]
fn one_of_over_two_invocations_draws_from_the_seed_and_reruns_identically() {
    let mut drawn = std::collections::BTreeSet::new();
    for seed in 0..8 {
        let r = run("reuse_one_of", seed, None);
        let again = run("reuse_one_of", seed, None);
        assert_eq!(
            format!("{:?} {:?} {:?}", r.frames, r.events, r.commands),
            format!("{:?} {:?} {:?}", again.frames, again.events, again.commands),
            "seed {seed}: the same run twice"
        );
        let names: Vec<&str> = r.frames[0].1.iter().map(|o| o.name.as_str()).collect();
        let (member, lead, s4) = if r.when("do.pick.slow", "Start").is_some() {
            ("slow", "do.pick.slow.lead", 70.0)
        } else {
            ("fast", "do.pick.fast.lead", 140.0)
        };
        assert_eq!(
            names,
            ["ego", lead],
            "seed {seed}: only the drawn member's car"
        );
        assert!(close(r.phase(&format!("do.pick.{member}")), (0.0, 4.0)));
        let car = r.at(4.0, lead);
        assert!(
            (car.s - s4).abs() < S_TOL,
            "seed {seed}: {lead} at s = {}",
            car.s
        );
        assert_eq!(car.lane, -3);
        drawn.insert(member);
    }
    assert_eq!(drawn.len(), 2, "eight seeds draw both members: {drawn:?}");
}

#[test]
fn invocation_errors_name_the_place() {
    let msg = error("err_reuse_unknown_parameter");
    assert!(
        msg.contains("has no parameter `speed`")
            && msg.contains("err_reuse_unknown_parameter.osc:10:25"),
        "{msg}"
    );
    let msg = error("err_reuse_recursive");
    assert!(
        msg.contains("recursive invocation: `ping` invokes `pong` invokes `ping`")
            && msg.contains("err_reuse_recursive.osc:6:9"),
        "{msg}"
    );
    let msg = error("err_reuse_two_entries");
    assert!(
        msg.contains("found several: `first` at ")
            && msg.contains("err_reuse_two_entries.osc:7:1, `second` at ")
            && msg.contains("err_reuse_two_entries.osc:11:1; name one with --scenario NAME")
            && msg.contains("at ")
            && msg.ends_with("err_reuse_two_entries.osc:7:1"),
        "{msg}"
    );
    let msg = error("err_reuse_parameter_keep");
    assert!(
        msg.contains("this constraint conflicts with 1 other(s) at ")
            && msg.contains("err_reuse_parameter_keep.osc:5:9")
            && msg.contains("conflicting constraint at ")
            && msg.contains("err_reuse_parameter_keep.osc:11:34"),
        "{msg}"
    );
}

/// every(…) and elapsed(…) in an invoked scenario's handlers count from the invocation's start,
/// at a start the plan knows (1 s) and after a run-time one (3.35 s): reuse_on_timed.osc, every
/// moment by hand there.
#[test]
fn timers_in_an_invoked_scenarios_handlers_count_from_the_invocations_start() {
    let r = run("reuse_on_timed", 0, None);
    phases_are(
        &r,
        &[
            ("do.ego_part.first", (1.0, 3.0)),
            ("do.ego_part.close", (3.0, 3.35)),
            ("do.ego_part.second", (3.35, 5.35)),
        ],
    );
    // The steps k·dt from a to b, both included.
    let steps = |a: f64, b: f64| -> Vec<f64> {
        let n = ((b - a) / super::support::DT).round() as usize;
        (0..=n).map(|k| a + k as f64 * super::support::DT).collect()
    };
    for (invocation, tick, half, late) in [
        (
            "do.ego_part.first",
            vec![1.0, 2.0],
            vec![1.25, 2.75],
            steps(2.5, 2.95),
        ),
        (
            "do.ego_part.second",
            vec![3.35, 4.35],
            vec![3.60, 5.10],
            steps(4.85, 5.30),
        ),
    ] {
        for (handler, event, want) in [(0, "tick", tick), (1, "half", half), (2, "late", late)] {
            let by = format!("{invocation}.on.{handler}/emit {invocation}.{event}");
            let got = r.emissions(&by, &format!("{invocation}.{event}"));
            assert!(
                got.len() == want.len()
                    && got.iter().zip(&want).all(|(g, w)| (g - w).abs() < T_TOL),
                "{by}: {got:?}, expected {want:?}"
            );
        }
    }
    // Nothing else is emitted: 2 + 2 + 10 per invocation.
    let all = r.commands.iter().filter(|c| c.2 == "emit").count();
    assert_eq!(all, 28);
    for (t, s) in [(3.35, 167.0), (5.35, 207.0)] {
        let ego = r.at(t, "ego");
        assert!((ego.s - s).abs() < S_TOL, "ego at {t} s: s = {}", ego.s);
    }
}

/// `wait @tick` inside an invoked scenario whose own handler emits tick every 1 s from 0.5 s
/// after the invocation's start, a run-time one at 3.35 s: reuse_on_wait.osc, by hand there.
#[test]
fn a_wait_in_an_invoked_scenario_on_its_handlers_timer_counts_from_the_invocations_start() {
    let r = run("reuse_on_wait", 0, None);
    phases_are(
        &r,
        &[
            ("do.ego_part.close", (1.0, 3.35)),
            ("do.ego_part.inner", (3.35, 5.85)),
            ("do.ego_part.inner.w1", (3.35, 3.85)),
            ("do.ego_part.inner.w2", (3.85, 4.85)),
            ("do.ego_part.inner.go", (4.85, 5.85)),
        ],
    );
    let by = "do.ego_part.inner.on.0/emit do.ego_part.inner.tick";
    let got = r.emissions(by, "do.ego_part.inner.tick");
    let want = [3.85, 4.85];
    assert!(
        got.len() == want.len() && got.iter().zip(want).all(|(g, w)| (g - w).abs() < T_TOL),
        "{by}: {got:?}, expected {want:?}"
    );
    let ego = r.at(4.85, "ego");
    assert!(
        (ego.s - 197.0).abs() < S_TOL,
        "ego at 4.85 s: s = {}",
        ego.s
    );
}

#[test]
fn the_entry_point_can_be_named() {
    let options = |name: &str| dsl_runtime::Options {
        seed: 0,
        dt: super::support::DT,
        open_end: false,
        scenario: Some(name.to_string()),
    };
    let osc = super::support::path("tests/scenarios/err_reuse_two_entries.osc");
    let road = super::support::path("tests/roads/straight.xodr");
    let lowered = dsl_runtime::load(&osc, Some(&road), &options("second")).expect("plans");
    let names: Vec<&str> = lowered
        .scenario
        .entities
        .scenario_objects
        .iter()
        .map(|o| o.name.as_str())
        .collect();
    assert_eq!(names, ["npc"]);
    assert_eq!(lowered.phases.last().map(|p| p.end), Some(Some(2.0)));
    let msg = dsl_runtime::load(&osc, Some(&road), &options("third"))
        .expect_err("no scenario third")
        .to_string();
    assert!(
        msg.starts_with("expected a scenario `third` with a `do` (--scenario), found none; scenarios with a `do`: `cruise` at ")
            && msg.ends_with("err_reuse_two_entries.osc:1:1"),
        "{msg}"
    );
}

#[test]
fn a_scenario_declared_on_an_actor_drives_that_actor() {
    let r = run("reuse_actor_behavior", 0, None);
    assert!(close(r.phase("do.brake"), (1.0, 4.0)));
    assert!(close(r.phase("do.brake.0"), (1.0, 2.0)));
    assert!(close(r.phase("do.brake.1"), (2.0, 4.0)));
    for (t, s, v) in [(1.0, 120.0, 20.0), (2.0, 130.0, 10.0), (4.0, 150.0, 10.0)] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.s - s).abs() < S_TOL && (ego.speed - v).abs() < S_TOL,
            "{t}: {ego:?}"
        );
    }
}

/// `on` handlers of a scenario invoked twice in serial (reuse_on.osc): each invocation's
/// handlers read its own parameter and actor, emit its own events, and fire only while the
/// invocation runs.
/// The handlers of an invocation the plan never starts never run (reuse_on_cut.osc: the
/// serial's own 2 s end stops it before `late` starts; ego at 120 m at 2 s, by hand).
#[test]
fn on_handlers_of_an_invocation_that_never_starts_never_run() {
    let r = run("reuse_on_cut", 0, None);
    phases_are(&r, &[("do.start", (0.0, 2.0)), ("do", (0.0, 2.0))]);
    assert!(r.commands.iter().all(|c| c.2 != "emit"), "{:?}", r.commands);
    assert!((r.at(2.0, "ego").s - 120.0).abs() < S_TOL);
}

#[test]
fn on_handlers_of_an_invoked_scenario_fire_only_while_their_invocation_runs() {
    let r = run("reuse_on", 0, None);
    phases_are(
        &r,
        &[
            ("do.round_one", (1.0, 5.0)),
            ("do.round_two", (5.0, 9.0)),
            ("do.tail", (9.0, 11.0)),
        ],
    );
    for (invocation, t) in [("do.round_one", 1.85), ("do.round_two", 6.50)] {
        for (handler, event) in [(0, "fast"), (1, "echo")] {
            let by = format!("{invocation}.on.{handler}/emit {invocation}.{event}");
            let got = r.emissions(&by, &format!("{invocation}.{event}"));
            assert!(
                got.len() == 1 && (got[0] - t).abs() < T_TOL,
                "{by}: {got:?}, expected [{t}]"
            );
        }
    }
    // No other emission, in or outside the invocations.
    let all: Vec<&(f64, String, String, String)> =
        r.commands.iter().filter(|c| c.2 == "emit").collect();
    assert_eq!(all.len(), 4, "{all:?}");
    for (t, s) in [
        (1.0, 110.0),
        (3.0, 140.25),
        (5.0, 170.0),
        (7.0, 200.25),
        (9.0, 230.0),
    ] {
        let ego = r.at(t, "ego");
        assert!((ego.s - s).abs() < S_TOL, "ego at {t} s: s = {}", ego.s);
    }
}

/// A composition's with: block: its `until` ends the composition, its `keep` constrains the
/// scenario (composition_with.osc, by hand: top = 12 m/s for every seed; first [0, 2] s,
/// second [2, 3.55] s).
#[test]
fn a_compositions_with_block_ends_it_and_constrains_the_scenario() {
    for seed in 0..3 {
        let r = run("composition_with", seed, None);
        phases_are(
            &r,
            &[
                ("do.first", (0.0, 2.0)),
                ("do.second", (2.0, 3.55)),
                ("do.second.0", (2.0, 3.55)),
            ],
        );
        assert!((r.at(1.0, "ego").speed - 12.0).abs() < 1e-9, "seed {seed}");
        assert!((r.at(2.0, "ego").s - 124.0).abs() < S_TOL, "seed {seed}");
        let v = |t: f64| 12.0 + 2.0 * (t - 2.0);
        let s = 124.0 + crate::support::stepped(v, 2.0, 3.55);
        assert!((r.at(3.55, "ego").s - s).abs() < 1e-6, "seed {seed}");
    }
    let e = error("err_composition_with_modifier");
    assert!(
        e.contains(
            "expected `until` or `keep` in the with: of a composition, found the modifier `speed`"
        ) && e.contains("err_composition_with_modifier.osc:10:13"),
        "{e}"
    );
}
