//! Global and user-defined actions (OpenSCENARIO 1.3 §7.7.1, §7.7.3) and controller actions
//! (§7.7.2.5), and the event log's JSON lines.

use crate::runtime_support;

use engine::output::{EventSink, JsonlWriter};
use engine::{Engine, EngineConfig, EventRecord};
use runtime_support::{file, run, run_with};
use scenario::expr::Value;

/// global_actions.xosc at t = 1 s: Gap (double 10) + 5 = 15; Count (int 1) := 7.
#[test]
fn parameter_modify_and_variable_set_change_values() {
    let (engine, _, _) = run("global_actions.xosc");
    assert_eq!(engine.parameter("Gap"), Some(Value::Double(15.0)));
    assert_eq!(engine.variable("Count"), Some(Value::Int(7)));
}

/// The CustomCommandAction is recorded with its type and content, and its JSON line escapes
/// the quotes of the content.
#[test]
fn custom_command_is_recorded_in_the_event_log() {
    let (_, _, events) = run("global_actions.xosc");
    let command = events
        .iter()
        .find(|e| matches!(e, EventRecord::CustomCommand { .. }))
        .expect("a custom command record");
    let EventRecord::CustomCommand {
        time,
        element,
        command_type,
        content,
    } = command
    else {
        unreachable!("matched above");
    };
    assert!((time - 1.0).abs() < 1e-9);
    assert_eq!(element, "CommandAction");
    assert_eq!(command_type, "log");
    assert_eq!(content, "hello, \"world\"");
    let mut out = JsonlWriter::new(Vec::new());
    out.event(command).expect("writes");
    assert_eq!(
        String::from_utf8(out.into_inner()).expect("utf-8"),
        "{\"time\":1.000,\"element\":\"CommandAction\",\"kind\":\"customCommand\",\
         \"type\":\"log\",\"content\":\"hello, \\\"world\\\"\"}\n"
    );
}

/// A controller that is not one of oscsim's models (no `model` property) is recorded in the
/// event log as assigned with model `none`, saying that the default controller keeps its
/// domains; the action still ends and the default controller keeps driving (engine module
/// `controller`).
#[test]
fn other_controllers_are_kept_off_clearly() {
    let (_, frames, events) = run("global_actions.xosc");
    let (element, model, note) = events
        .iter()
        .find_map(|e| match e {
            EventRecord::Controller {
                controller,
                element,
                model,
                note,
                ..
            } if controller == "ACC" => Some((element.clone(), model.clone(), note.clone())),
            _ => None,
        })
        .expect("a controller record");
    assert_eq!(
        (element.as_str(), model.as_str()),
        ("ControllerAction", "none")
    );
    assert!(
        note.contains("'ACC' (no model property) is not an oscsim controller model"),
        "{note}"
    );
    assert!(
        note.contains("the default controller keeps its domains"),
        "{note}"
    );
    // 20 m/s under the default controller from s = 20: s = 20 + 20·t.
    let row = frames.at("Ego", 4.0);
    assert!((row.x - 100.0).abs() < 1e-9, "x = {}", row.x);
}

/// A transition's JSON line: the issue's six keys, the standard's state names and the short
/// transition name compare_run.py reads.
#[test]
fn transition_json_line_has_the_issue_layout() {
    let (_, _, events) = run("global_actions.xosc");
    let start = events
        .iter()
        .find(|e| matches!(e, EventRecord::Transition(t) if t.name == "Modify"))
        .expect("the Modify event starts");
    let mut out = JsonlWriter::new(Vec::new());
    out.event(start).expect("writes");
    assert_eq!(
        String::from_utf8(out.into_inner()).expect("utf-8"),
        "{\"time\":1.000,\"element\":\"Modify\",\"kind\":\"event\",\"from\":\"standbyState\",\
         \"transition\":\"start\",\"to\":\"runningState\"}\n"
    );
}

/// ConstraintGroups hold at run time as at load (parameter_constraints.xosc): Limit must lie in
/// [0, 40] or equal 100. The ParameterSetAction of t = 1 s (30) meets the first group; with
/// Step = 5 the ParameterModifyAction of t = 2 s gives 30 + 5 = 35, which meets it too, and
/// the run ends normally at t = 3 s.
#[test]
fn parameter_values_that_meet_their_constraints_are_set() {
    let (engine, _, events) = run_with(
        &file("parameter_constraints.xosc"),
        &[("Step", "5")],
        EngineConfig::default(),
    );
    assert_eq!(engine.parameter("Limit"), Some(Value::Double(35.0)));
    assert!(!events
        .iter()
        .any(|e| matches!(e, EventRecord::Error { .. })));
}

/// A host program's `Engine::set_parameter` meets the same ConstraintGroups
/// (parameter_constraints.xosc: Limit in [0, 40] or equal to 100, declared 10): 100 meets the
/// second group and is set; 40.5 is above the first group's bound and not 100, so it is refused
/// and Limit keeps 100; text that is no double is refused as not of the declared type; an
/// undeclared name changes nothing.
#[test]
fn set_parameter_from_the_host_meets_the_constraint_groups() {
    let path = file("parameter_constraints.xosc");
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    assert_eq!(engine.parameter("Limit"), Some(Value::Double(10.0)));
    assert_eq!(
        engine.set_parameter("Limit", &Value::Int(100)).ok(),
        Some(true)
    );
    assert_eq!(engine.parameter("Limit"), Some(Value::Double(100.0)));

    let err = engine
        .set_parameter("Limit", &Value::Double(40.5))
        .expect_err("40.5 is in neither group");
    assert!(
        matches!(err.kind(), engine::ErrorKind::ParameterValue { name, .. } if name == "Limit")
    );
    assert_eq!(
        err.to_string(),
        "expected parameter Limit greaterOrEqual 0 and lessOrEqual 40 or equalTo 100, found 40.5"
    );
    assert_eq!(engine.parameter("Limit"), Some(Value::Double(100.0)));

    let err = engine
        .set_parameter("Limit", &Value::String("fast".into()))
        .expect_err("not a double");
    assert!(
        err.to_string()
            .starts_with("expected a value of type double, found 'fast'"),
        "{err}"
    );
    assert_eq!(engine.parameter("Limit"), Some(Value::Double(100.0)));
    assert_eq!(
        engine.set_parameter("NoSuch", &Value::Int(1)).ok(),
        Some(false)
    );
}

/// With the declared Step = 20 the ParameterModifyAction of t = 2 s would give 30 + 20 = 50,
/// in neither group: the run fails at that Action (`<Action name="AddStep">`, line 69,
/// column 15) with the message a declared value breaking the constraints gets at load, and
/// Limit keeps 30.
#[test]
fn a_parameter_value_that_breaks_its_constraints_is_a_run_error_at_the_action() {
    let path = file("parameter_constraints.xosc");
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    let err = engine
        .run(&mut (), &mut Vec::new())
        .expect_err("the constraint is broken");
    let message = err.to_string();
    let expected = format!(
        "expected parameter Limit greaterOrEqual 0 and lessOrEqual 40 or equalTo 100, found 50 at {}:69:15",
        path.display()
    );
    assert!(message.starts_with(&expected), "{message}");
    assert_eq!(engine.parameter("Limit"), Some(Value::Double(30.0)));
}
