//! Runs a DSL scenario of `tests/scenarios` on `tests/roads/straight.xodr` through the engine
//! and keeps every frame and every storyboard transition.

use std::path::PathBuf;

use engine::{Engine, EngineConfig, EventRecord, EventSink, Frame, FrameSink};

/// One entity in one frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Obj {
    pub name: String,
    pub x: f64,
    pub y: f64,
    /// Heading (rad).
    pub h: f64,
    pub s: f64,
    /// OpenDRIVE road id ("" off every road).
    pub road: String,
    pub lane: i32,
    pub speed: f64,
    /// Its pose (the frame's, with z, pitch and roll) and bounding box, as the OpenSCENARIO
    /// 2.0 §8.7.2 physical_object the engine's domain methods take.
    pub object: engine::domain::PhysicalObject,
}

/// A run.
pub struct Run {
    /// (time, entities).
    pub frames: Vec<(f64, Vec<Obj>)>,
    /// (time, element, transition).
    pub events: Vec<(f64, String, String)>,
    /// The event log's `customCommand` lines: (time, element, type, content).
    pub commands: Vec<(f64, String, String, String)>,
    /// The event log's controller lines: (time, entity, note).
    pub controllers: Vec<(f64, String, String)>,
}

struct Frames(Vec<(f64, Vec<Obj>)>);

impl FrameSink for Frames {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        let objs = frame
            .objects()
            .map(|o| Obj {
                name: o.name.to_string(),
                x: o.pose.x,
                y: o.pose.y,
                h: o.pose.h,
                s: o.road_position.map_or(f64::NAN, |r| r.s),
                road: o.road_position.map_or(String::new(), |r| r.road_id.clone()),
                lane: o.road_position.map_or(0, |r| r.lane_id),
                speed: o.speed,
                object: engine::domain::PhysicalObject::new(o.bounding_box, o.pose),
            })
            .collect();
        self.0.push((frame.time, objs));
        Ok(())
    }
}

struct Events(
    Vec<(f64, String, String)>,
    Vec<(f64, String, String, String)>,
    Vec<(f64, String, String)>,
);

impl EventSink for Events {
    fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
        match record {
            EventRecord::Transition(t) => {
                self.0
                    .push((t.time, t.name.clone(), format!("{:?}", t.transition)))
            }
            EventRecord::CustomCommand {
                time,
                element,
                command_type,
                content,
            } => self.1.push((
                *time,
                element.clone(),
                command_type.clone(),
                content.clone(),
            )),
            EventRecord::Controller {
                time, entity, note, ..
            } => self.2.push((*time, entity.clone(), note.clone())),
            _ => {}
        }
        Ok(())
    }
}

pub fn path(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(rel)
}

pub const DT: f64 = 0.05;

/// Plans `tests/scenarios/NAME.osc` with `seed`.
pub fn lower(
    name: &str,
    seed: u64,
    duration: Option<f64>,
) -> Result<dsl_runtime::Lowered, dsl_runtime::Error> {
    lower_at(
        &format!("tests/scenarios/{name}.osc"),
        "tests/roads/straight.xodr",
        seed,
        duration,
    )
}

/// Plans the `.osc` at `osc` (relative to the crate) on `road`.
pub fn lower_at(
    osc: &str,
    road: &str,
    seed: u64,
    duration: Option<f64>,
) -> Result<dsl_runtime::Lowered, dsl_runtime::Error> {
    let options = dsl_runtime::Options {
        seed,
        dt: DT,
        open_end: duration.is_some(),
        scenario: None,
    };
    dsl_runtime::load(&path(osc), Some(&path(road)), &options)
}

/// Plans and runs `tests/scenarios/NAME.osc`.
pub fn run(name: &str, seed: u64, duration: Option<f64>) -> Run {
    let lowered = lower(name, seed, duration).unwrap_or_else(|e| panic!("{name}: {e}"));
    run_scenario(name, &lowered.scenario, seed, duration)
}

/// Lowers `tests/scenarios/NAME.osc` on `tests/roads/ROAD.xodr` with seed 0 and runs it.
pub fn run_on(name: &str, road: &str) -> Run {
    let lowered = lower_at(
        &format!("tests/scenarios/{name}.osc"),
        &format!("tests/roads/{road}.xodr"),
        0,
        None,
    )
    .unwrap_or_else(|e| panic!("{name}: {e}"));
    run_scenario(name, &lowered.scenario, 0, None)
}

/// The engine's configuration of these runs (step [`DT`]).
pub fn config() -> EngineConfig {
    EngineConfig {
        dt: DT,
        max_time: 120.0,
        ..EngineConfig::default()
    }
}

/// Runs a scenario model.
pub fn run_scenario(
    name: &str,
    scenario: &scenario::Scenario,
    seed: u64,
    duration: Option<f64>,
) -> Run {
    let config = EngineConfig {
        dt: DT,
        duration,
        max_time: 120.0,
        seed,
        ..EngineConfig::default()
    };
    let network = engine::load::road_network(scenario).unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut engine =
        Engine::new(scenario, network, config).unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut frames = Frames(Vec::new());
    let mut events = Events(Vec::new(), Vec::new(), Vec::new());
    loop {
        match engine.step(&mut frames, &mut events) {
            Ok(Some(_)) => break,
            Ok(None) => {}
            Err(e) => panic!("{name}: {e}"),
        }
    }
    Run {
        frames: frames.0,
        events: events.0,
        commands: events.1,
        controllers: events.2,
    }
}

impl Run {
    /// `name` in the frame at time `t` (within half a step).
    pub fn at(&self, t: f64, name: &str) -> &Obj {
        let (_, objs) = self
            .frames
            .iter()
            .find(|(ft, _)| (ft - t).abs() < DT / 2.0)
            .unwrap_or_else(|| panic!("no frame at {t}"));
        objs.iter()
            .find(|o| o.name == name)
            .unwrap_or_else(|| panic!("no {name} at {t}"))
    }

    /// Time of the first `transition` ("Start", "End", "Stop") of element `name`.
    pub fn when(&self, name: &str, transition: &str) -> Option<f64> {
        self.events
            .iter()
            .find(|(_, n, tr)| n == name && tr == transition)
            .map(|(t, _, _)| *t)
    }

    /// Asserts that the engine's check `name`, held over its phase (§8.9.1.1.1 `at: all`:
    /// "holds throughout the phase"), started at `t0` and ran until its phase's Act stopped it
    /// at `t1`: it never ended of itself (a failure ends it, and the run with it).
    pub fn held(&self, name: &str, (t0, t1): (f64, f64)) {
        let (s, e) = self.phase(name);
        assert!(
            (s - t0).abs() < 1e-9 && (e - t1).abs() < 1e-9 && self.when(name, "End").is_none(),
            "{name}: [{s}, {e}], expected held over [{t0}, {t1}]"
        );
    }

    /// Start and end (stop) time of the phase `path`.
    pub fn phase(&self, path: &str) -> (f64, f64) {
        let start = self
            .when(path, "Start")
            .unwrap_or_else(|| panic!("{path} never started"));
        let end = self
            .when(path, "Stop")
            .or_else(|| self.when(path, "End"))
            .unwrap_or_else(|| panic!("{path} never ended"));
        (start, end)
    }

    /// The times of the event log's emissions of `event` (CustomCommandAction type `emit`)
    /// by element `by`.
    pub fn emissions(&self, by: &str, event: &str) -> Vec<f64> {
        self.commands
            .iter()
            .filter(|(_, el, ty, content)| el == by && ty == "emit" && content == event)
            .map(|(t, ..)| *t)
            .collect()
    }

    /// The time of the last frame.
    pub fn last_time(&self) -> f64 {
        self.frames.last().map_or(0.0, |f| f.0)
    }
}

/// The error message of a scenario that must not plan.
pub fn error(name: &str) -> String {
    match lower(name, 0, None) {
        Ok(_) => panic!("{name} planned"),
        Err(e) => e.to_string(),
    }
}

/// The error message of `tests/scenarios/NAME.osc` on `tests/roads/ROAD.xodr`, which must not
/// plan.
pub fn error_on(name: &str, road: &str) -> String {
    match lower_at(
        &format!("tests/scenarios/{name}.osc"),
        &format!("tests/roads/{road}.xodr"),
        0,
        None,
    ) {
        Ok(_) => panic!("{name}: planned"),
        Err(e) => e.to_string(),
    }
}

/// The run of `tests/scenarios/NAME.osc` on `tests/roads/ROAD.xodr` to its first error
/// ([`run_to_error`]): its error (`None`: it ends) and the event log's error records.
pub fn run_to_error_on(name: &str, road: &str) -> (Option<String>, Vec<(f64, String, String)>) {
    let lowered = lower_at(
        &format!("tests/scenarios/{name}.osc"),
        &format!("tests/roads/{road}.xodr"),
        0,
        None,
    )
    .unwrap_or_else(|e| panic!("{name}: {e}"));
    run_to_error(&lowered.scenario)
}

/// The distance the engine covers from `a` to `b` s when the speed at time t is `v(t)`: it
/// sets each step's speed at the step's end and moves with it, Σ v(tₖ)·dt over the step ends
/// tₖ in (a, b].
pub fn stepped(v: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let n = ((b - a) / DT).round() as usize;
    (1..=n).map(|k| v(a + k as f64 * DT) * DT).sum()
}

/// Runs a scenario model until it ends or fails: the run's error (`None`: it ended) and the
/// event log's error records (time, element, message).
pub fn run_to_error(scenario: &scenario::Scenario) -> (Option<String>, Vec<(f64, String, String)>) {
    struct Errors(Vec<(f64, String, String)>);
    impl EventSink for Errors {
        fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
            if let EventRecord::Error {
                time,
                element,
                message,
            } = record
            {
                self.0.push((*time, element.clone(), message.clone()));
            }
            Ok(())
        }
    }
    let config = EngineConfig {
        dt: DT,
        max_time: 120.0,
        ..EngineConfig::default()
    };
    let network = engine::load::road_network(scenario).expect("road network");
    let mut engine = Engine::new(scenario, network, config).expect("engine");
    let mut frames = Frames(Vec::new());
    let mut errors = Errors(Vec::new());
    loop {
        match engine.step(&mut frames, &mut errors) {
            Ok(Some(_)) => return (None, errors.0),
            Ok(None) => {}
            Err(e) => return (Some(e.to_string()), errors.0),
        }
    }
}

/// Lowers the `.osc` at `osc` (relative to the crate) on `road` with seed 0 and asserts that
/// its run fails with one error record, at `time` by the element `element`, whose message is
/// the run's error, starting with `want` and ending with `tail` (the path between them is the
/// machine's).
pub fn fails_once(osc: &str, road: &str, (want, tail): (&str, &str), (time, element): (f64, &str)) {
    let lowered = lower_at(osc, road, 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    assert!(error.starts_with(want) && error.ends_with(tail), "{error}");
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - time).abs() < 1e-9, "{records:?}");
    assert_eq!(records[0].1, element);
    assert_eq!(records[0].2, error);
}

/// Asserts that each phase `(name, start, end)` of `r` runs from start to end (1e-9 s: phase
/// ends are step times).
pub fn phases_are(r: &Run, want: &[(&str, f64, f64)]) {
    for &(phase, t0, t1) in want {
        let (s, e) = r.phase(phase);
        assert!(
            (s - t0).abs() < 1e-9 && (e - t1).abs() < 1e-9,
            "{phase} [{s}, {e}], want [{t0}, {t1}]"
        );
    }
}
