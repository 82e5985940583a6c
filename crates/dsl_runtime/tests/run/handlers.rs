//! `on` handlers (ASAM OpenSCENARIO DSL 2.1 §7.3.10): `emit` in a handler makes the event occur
//! whenever the handler's event does; `call` runs an external method of the host then. Expectations in the scenario files.

use crate::support::{run, DT};

/// Event times are step times.
const T_TOL: f64 = 1e-9;

#[test]
fn on_handler_emits_an_event_others_wait_on() {
    let r = run("on_emit", 0, None);
    let (_, e) = r.phase("do.npc_part.0");
    assert!((e - 1.10).abs() < T_TOL, "until @quick ended at {e}");
    let (s, e) = r.phase("do.npc_part.1");
    assert!(
        (s - 1.10).abs() < T_TOL && (e - 2.10).abs() < T_TOL,
        "[{s}, {e}]"
    );
    assert!((r.at(1.10, "npc").s - 25.5).abs() < 1e-6);
    assert!((r.at(2.10, "npc").s - 25.5).abs() < 1e-6);
    // The handler's emission is in the event log, once (speed stays above 15 m/s: no new rise).
    let quick = r.emissions("on.0/emit quick", "quick");
    assert!(
        quick.len() == 1 && (quick[0] - 1.10).abs() < T_TOL,
        "{quick:?}"
    );
}

#[test]
fn call_of_an_undefined_method_is_an_error() {
    crate::along::refused(
        "err_on_call",
        "expected a method with an implementation in `call` (def note(…) is external … or is expression …), found `note` undefined",
        "8:14",
    );
}

/// `call` in a `do` and in an `on` handler: a `customCommand` of type `call` in the event log
/// at the moment it runs, its content the method and its arguments as JSON values
/// (call_external.osc: 2.0 s and 2.05 s).
#[test]
fn calls_of_external_methods_are_commands_in_the_event_log_when_they_run() {
    let lowered = crate::support::lower("call_external", 0, None).expect("plans");
    let methods: Vec<&str> = lowered.calls.iter().map(|c| c.method.as_str()).collect();
    assert_eq!(methods, ["log_speed", "note"]);
    assert_eq!(
        (lowered.calls[0].pos.line, lowered.calls[0].pos.col),
        (19, 9)
    );
    let r = crate::support::run_scenario("call_external", &lowered.scenario, 0, None);
    let calls: Vec<(f64, &str, &str)> = r
        .commands
        .iter()
        .filter(|(_, _, ty, _)| ty == "call")
        .map(|(t, el, _, c)| (*t, el.as_str(), c.as_str()))
        .collect();
    assert_eq!(calls.len(), 2, "{calls:?}");
    assert!((calls[0].0 - 2.0).abs() < T_TOL, "{calls:?}");
    assert_eq!(
        (calls[0].1, calls[0].2),
        (
            "do.1/call log_speed(\"ego\", 20.0)",
            "log_speed(\"ego\", 20.0)"
        )
    );
    assert!((calls[1].0 - 2.05).abs() < T_TOL, "{calls:?}");
    assert_eq!(calls[1].2, "note(1.0, true)");
    // ego is where the plan has it when the first call runs: 50 + 10 · 2 = 70 m.
    assert!((r.at(2.0, "ego").s - 70.0).abs() < 1e-6);
}

/// `call` with named arguments: the host receives them in the method's declaration order,
/// defaults filled in (call_named.osc, by hand: `log("ego", 20.0, 3.0, true)` at 1.0 s, the
/// handler's `note(2.0, true)` at 1.05 s).
#[test]
fn named_arguments_of_a_call_reach_the_host_in_declaration_order_with_defaults() {
    let lowered = crate::support::lower("call_named", 0, None).expect("plans");
    let r = crate::support::run_scenario("call_named", &lowered.scenario, 0, None);
    let calls: Vec<(f64, &str)> = r
        .commands
        .iter()
        .filter(|(_, _, ty, _)| ty == "call")
        .map(|(t, _, _, c)| (*t, c.as_str()))
        .collect();
    assert_eq!(calls.len(), 2, "{calls:?}");
    assert!((calls[0].0 - 1.0).abs() < T_TOL, "{calls:?}");
    assert_eq!(calls[0].1, "log(\"ego\", 20.0, 3.0, true)");
    assert!((calls[1].0 - 1.05).abs() < T_TOL, "{calls:?}");
    assert_eq!(calls[1].1, "note(2.0, true)");
}

/// Named arguments of a `call` that name no parameter, give one twice, or come before a
/// positional one: errors at the argument, before the run.
#[test]
fn bad_named_arguments_of_a_call_are_errors_at_the_argument() {
    crate::along::refused(
        "err_call_named_unknown",
        "log() has no parameter `speed` (parameters: name, v)",
        "9:25",
    );
    crate::along::refused(
        "err_call_named_twice",
        "parameter `name` of log() is given twice",
        "9:31",
    );
    crate::along::refused(
        "err_call_positional_after_named",
        "expected a named argument `name: value`, found a positional argument after a named one",
        "9:31",
    );
}

/// `on every(2s, offset: 1s): emit tick`: tick at 1, 3, 5 s (and 7 s, after the run); the third
/// wait on it ends at 1 + 2·2 = 5 s (on_every.osc).
#[test]
fn on_every_emits_at_each_period_from_the_offset() {
    let r = run("on_every", 0, None);
    let (s1, e1) = r.phase("do.ticks.w1");
    let (s2, e2) = r.phase("do.ticks.w2");
    let (s3, e3) = r.phase("do.ticks.w3");
    assert!(
        s1.abs() < T_TOL && (e1 - 1.0).abs() < T_TOL,
        "w1 [{s1}, {e1}]"
    );
    assert!(
        (s2 - 1.0).abs() <= DT + T_TOL && (e2 - 3.0).abs() < T_TOL,
        "w2 [{s2}, {e2}]"
    );
    assert!(
        (s3 - 3.0).abs() <= DT + T_TOL && (e3 - 5.0).abs() < T_TOL,
        "w3 [{s3}, {e3}]"
    );
    assert!((r.at(5.0, "ego").s - 70.0).abs() < 1e-6);
    // The event log: one emit line per emission, with the emitter and the event's name.
    let ticks = r.emissions("on.0/emit tick", "tick");
    assert_eq!(ticks.len(), 3, "{ticks:?}");
    for (t, want) in ticks.iter().zip([1.0, 3.0, 5.0]) {
        assert!((t - want).abs() < T_TOL, "tick at {t}, expected {want}");
    }
    let done = r.emissions("do.ticks.emit_done/emit done", "done");
    assert_eq!(done.len(), 1, "{done:?}");
    assert!((done[0] - 5.0).abs() <= DT + T_TOL, "done at {}", done[0]);
    // The wait after the emit starts on the emit's completion, seen a step later: [5.05, 6.55].
    let (s, e) = r.phase("do.ticks.4");
    assert!(
        (s - 5.05).abs() < T_TOL && (e - 6.55).abs() < T_TOL,
        "[{s}, {e}]"
    );
}

/// every(…) in wait and until counts from the phase's start; only its first occurrence
/// matters there (wait_every.osc).
#[test]
fn every_in_wait_and_until_ends_at_the_first_occurrence() {
    let r = run("wait_every", 0, None);
    let (s, e) = r.phase("do.0");
    assert!(
        s.abs() < T_TOL && (e - 2.0).abs() < T_TOL,
        "do.0 [{s}, {e}]"
    );
    let (s, e) = r.phase("do.1");
    assert!(
        (s - 2.0).abs() < T_TOL && (e - 3.5).abs() < T_TOL,
        "do.1 [{s}, {e}]"
    );
    let (s, _) = r.phase("do.2");
    assert!((s - 3.5).abs() < T_TOL, "do.2 starts at {s}");
    let (s, e) = r.phase("do.3");
    assert!(
        (s - 3.5).abs() < T_TOL && (e - 4.0).abs() < T_TOL,
        "do.3 [{s}, {e}]"
    );
    let (s, _) = r.phase("do.4");
    assert!((s - 4.0).abs() <= DT + T_TOL, "do.4 starts at {s}");
    assert!((r.at(2.0, "ego").s - 40.0).abs() < 1e-6);
    assert!((r.at(4.0, "ego").s - 60.0).abs() < 1e-6);
}

/// elapsed(…) declared as an event (the wait's context) and in an on handler (the run's, true at
/// every step from then on) (elapsed_event.osc).
#[test]
fn elapsed_in_events_counts_from_the_context_start() {
    let r = run("elapsed_event", 0, None);
    let (s, e) = r.phase("do.1");
    assert!(
        (s - 1.5).abs() < T_TOL && (e - 2.5).abs() < T_TOL,
        "do.1 [{s}, {e}]"
    );
    let (s, e) = r.phase("do.2");
    for (t, want) in [(s, 2.5), (e, 3.5)] {
        assert!((t - want).abs() < T_TOL, "do.2 [{s}, {e}]");
    }
    assert!((r.at(1.5, "ego").s - 35.0).abs() < 1e-6);
    let past = r.emissions("on.0/emit past", "past");
    assert_eq!(past.len(), 10, "{past:?}");
    for (i, t) in past.iter().enumerate() {
        let want = 3.0 + DT * i as f64;
        assert!(
            (t - want).abs() < T_TOL,
            "emission {i} at {t}, expected {want}"
        );
    }
}

#[test]
fn every_errors_name_the_argument() {
    crate::along::refused(
        "err_until_every",
        "expected an offset above 0 s in until every(…)",
        "8:15",
    );
    crate::along::refused(
        "err_every_period",
        "expected a period above 0 s in every(…)",
        "6:14",
    );
}

/// An external method read in a condition (external_value.osc): a UserDefinedValueCondition
/// on the value `ticks()`, listed with its place among the scenario's externals after the
/// calls (the host sets it each step: load::Host, tested in the load crate).
#[test]
fn an_external_methods_result_in_until_is_a_value_the_host_sets() {
    let lowered = crate::support::lower("external_value", 0, None).expect("plans");
    let found: Vec<(&str, Option<&str>, u32, u32)> = lowered
        .calls
        .iter()
        .map(|c| (c.method.as_str(), c.value.as_deref(), c.pos.line, c.pos.col))
        .collect();
    assert_eq!(
        found,
        [
            ("log_speed", None, 20, 9),
            ("ticks", Some("ticks()"), 19, 19)
        ]
    );
    let until =
        lowered
            .scenario
            .storyboard
            .stories
            .iter()
            .flat_map(|s| &s.acts)
            .filter_map(|a| a.stop_trigger.as_ref())
            .flat_map(|t| &t.condition_groups)
            .flat_map(|g| &g.conditions)
            .find_map(|c| match &c.kind {
                scenario::ConditionKind::ByValue(
                    scenario::ByValueCondition::UserDefinedValue { name, rule, value },
                ) => Some((name.clone(), *rule, value.clone())),
                _ => None,
            });
    assert_eq!(
        until,
        Some((
            "ticks()".to_string(),
            scenario::Rule::GreaterThan,
            "40".to_string()
        ))
    );
}

/// An external method's result where the plan needs it before the run is an error at the
/// call (err_external_value.osc).
#[test]
fn an_external_methods_result_outside_a_condition_is_an_error_at_the_call() {
    let e = match crate::support::lower("err_external_value", 0, None) {
        Ok(_) => panic!("planned"),
        Err(e) => e.to_string(),
    };
    assert!(
        e.contains("expected a constant value, found the result of external method `sensor_speed`, which the host gives only while the scenario runs")
            && e.ends_with("err_external_value.osc:7:15"),
        "{e}"
    );
}

/// `call` of a method defined by an expression: an instant phase with no command, in a `do`
/// and in a handler; nothing for the host to bind (call_expression.osc, by hand: do.1 at 1.0 s,
/// ego at 110 m then and 130 m at 2 s).
#[test]
fn a_call_of_a_method_defined_by_an_expression_does_nothing_but_take_its_moment() {
    let lowered = crate::support::lower("call_expression", 0, None).expect("plans");
    assert!(lowered.calls.is_empty(), "{:?}", lowered.calls);
    let r = crate::support::run_scenario("call_expression", &lowered.scenario, 0, None);
    assert!(r.commands.iter().all(|c| c.2 != "call"), "{:?}", r.commands);
    let (s, _) = r.phase("do.1");
    assert!((s - 1.0).abs() < T_TOL, "do.1 at {s}");
    let (s, e) = r.phase("do.2");
    assert!(
        (s - 1.0).abs() < T_TOL && (e - 2.0).abs() < T_TOL,
        "[{s}, {e}]"
    );
    assert!((r.at(1.0, "ego").s - 110.0).abs() < 1e-6);
    assert!((r.at(2.0, "ego").s - 130.0).abs() < 1e-6);
}
