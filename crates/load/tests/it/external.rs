//! External methods bound by a Rust host (`load::Bindings`, `load::Host`): checked at load,
//! read in a condition before each step, called when the step logs the call
//! (dsl_runtime's tests/scenarios/external_value.osc, worked by hand in its comment).

use crate::repo;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use engine::{Engine, EngineConfig, EventRecord};
use serde_json::{json, Value};

/// Event times are step times.
const T_TOL: f64 = 1e-9;

fn options(bindings: Option<load::Bindings>) -> load::Options {
    load::Options {
        road: Some(repo("crates/dsl_runtime/tests/roads/straight.xodr")),
        bindings,
        ..load::Options::default()
    }
}

/// ego's road s in each frame.
#[derive(Default)]
struct EgoS(Vec<(f64, f64)>);

impl engine::FrameSink for EgoS {
    fn frame(&mut self, frame: &engine::Frame<'_>) -> Result<(), engine::SinkError> {
        let s = frame
            .objects()
            .find(|e| e.name == "ego")
            .and_then(|e| e.road_position)
            .map_or(f64::NAN, |p| p.s);
        self.0.push((frame.time, s));
        Ok(())
    }
}

const SCENARIO: &str = "crates/dsl_runtime/tests/scenarios/external_value.osc";

#[test]
fn bound_closures_end_an_until_and_run_at_their_call() {
    let ticks = Arc::new(AtomicU64::new(0));
    let calls: Arc<Mutex<Vec<Vec<Value>>>> = Arc::default();
    let mut bindings = load::Bindings::default();
    let t = Arc::clone(&ticks);
    bindings.bind("ticks", move |_| {
        Ok(json!(t.fetch_add(1, Ordering::SeqCst) + 1))
    });
    let c = Arc::clone(&calls);
    bindings.bind("log_speed", move |args| {
        c.lock().map_err(|e| e.to_string())?.push(args.to_vec());
        Ok(Value::Null)
    });
    let loaded = load::load(&repo(SCENARIO), &options(Some(bindings))).expect("loads");
    let host = loaded.host().expect("every external is bound");
    let mut engine = Engine::new(
        &loaded.scenario,
        loaded.network.clone(),
        EngineConfig::default(),
    )
    .expect("builds");
    let mut events: Vec<EventRecord> = Vec::new();
    let mut frames = EgoS::default();
    let reason = host
        .run(&mut engine, &mut frames, &mut events)
        .expect("runs");
    assert_eq!(reason, engine::StopReason::StoriesComplete);
    // The call ran once, with the arguments written (20 m/s in SI units), logged at 2.0 s.
    assert_eq!(
        *calls.lock().expect("not poisoned"),
        [vec![json!("ego"), json!(20.0)]]
    );
    let logged: Vec<f64> = events
        .iter()
        .filter_map(|r| match r {
            EventRecord::CustomCommand {
                time, command_type, ..
            } if command_type == "call" => Some(*time),
            _ => None,
        })
        .collect();
    assert_eq!(logged.len(), 1);
    assert!((logged[0] - 2.0).abs() < T_TOL, "{logged:?}");
    // ticks() ran before every step, and before the last call of `step`, which finds the
    // stories complete and moves nothing (not counted in `steps`).
    let steps = engine.steps();
    assert_eq!(ticks.load(Ordering::SeqCst), steps + 1);
    let at = |t: f64| {
        frames
            .0
            .iter()
            .find(|(time, _)| (time - t).abs() < T_TOL)
            .map(|(_, s)| *s)
            .expect("a frame")
    };
    assert!((at(2.0) - 70.0).abs() < 1e-6, "s(2) = {}", at(2.0));
    assert!((at(3.0) - 89.5).abs() < 1e-6, "s(3) = {}", at(3.0));
}

#[test]
fn an_unbound_external_method_is_refused_at_load_at_its_place() {
    let mut only_call = load::Bindings::default();
    only_call.bind("log_speed", |_| Ok(Value::Null));
    for (bindings, method, place) in [
        (
            load::Bindings::default(),
            "log_speed",
            "external_value.osc:20:9",
        ),
        (only_call, "ticks", "external_value.osc:19:19"),
    ] {
        let e = load::load(&repo(SCENARIO), &options(Some(bindings)))
            .expect_err("refused")
            .to_string();
        assert!(
            e.contains(&format!(
                "expected a function bound to external method `{method}`"
            )) && e.ends_with(place),
            "{e}"
        );
    }
    // Without bindings the host binds later (the Python package's Simulation.bind).
    assert!(load::load(&repo(SCENARIO), &options(None)).is_ok());
}

#[test]
fn a_failing_closure_ends_the_step_with_its_method_and_time() {
    // ticks() is 41 from the start: the first drive ends in the first step (0 s), the call
    // runs in it and its function fails there.
    let mut bindings = load::Bindings::default();
    bindings.bind("ticks", |_| Ok(json!(41)));
    bindings.bind("log_speed", |_| Err("no logger".to_string()));
    let loaded = load::load(&repo(SCENARIO), &options(Some(bindings))).expect("loads");
    let host = loaded.host().expect("bound");
    let mut engine = Engine::new(
        &loaded.scenario,
        loaded.network.clone(),
        EngineConfig::default(),
    )
    .expect("builds");
    let e = host
        .run(&mut engine, &mut (), &mut ())
        .expect_err("the call fails")
        .to_string();
    assert!(
        e.contains("external method `log_speed` failed at 0.000 s: no logger"),
        "{e}"
    );
}
