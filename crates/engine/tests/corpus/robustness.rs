//! Bad values that load fine never panic, hang or corrupt the runtime.
//!
//! Seven small scenarios (five of the corpus' `generated/xosc`, two of this crate's runtime
//! fixtures with numeric parameters, copied with their road files and the vehicle catalog into
//! `tests/files/robustness/`) have numeric attribute values replaced at random by NaN, ±inf,
//! 0, −1, ±1e300, 1.7e308, ±1e-300, integers beyond `i32`/`u32`/`i64` and expressions whose
//! value is not finite (`${0 / 0}`), and their global parameters overridden the same way
//! (`--param`). Each damaged scenario is loaded, built and run for at
//! most 300 steps of a step length drawn from 1 ms to 1e9 s (`EngineConfig::duration` = 300
//! steps; valid, if unusual, steps that move an entity far past its road's end in one step).
//! Whatever happens:
//!
//! - nothing panics (proptest reports a panic as a failure);
//! - nothing hangs: the case runs on a thread watched with a generous deadline (a hang
//!   detector, not a speed requirement: one case takes well under a second in debug);
//! - no frame carries a NaN or infinite pose, speed, velocity, acceleration, yaw rate or
//!   road coordinate: a value that would corrupt the state must be refused with an error;
//! - every error names the file and a line:column in it, except the step's overflow guard
//!   (finite extremes that combine into inf, runtime/finite.rs), which names the entity, the
//!   quantity and the time.

use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;

use engine::output::{EntityFrame, EventRecord, Frame, FrameSink};
use engine::{Engine, EngineConfig, ErrorKind};
use proptest::prelude::*;
use proptest::sample::Index;
use scenario::Scenario;

/// The scenarios, by file name in `tests/files/robustness/`.
const SCENARIOS: [(&str, &str); 7] = [
    (
        "one_action_example0.xosc",
        include_str!("../files/robustness/one_action_example0.xosc"),
    ),
    (
        "Stop_on_offroad0.xosc",
        include_str!("../files/robustness/Stop_on_offroad0.xosc"),
    ),
    (
        "trajectory_example0.xosc",
        include_str!("../files/robustness/trajectory_example0.xosc"),
    ),
    (
        "syncronize_straight_example0.xosc",
        include_str!("../files/robustness/syncronize_straight_example0.xosc"),
    ),
    (
        "trailer_example0.xosc",
        include_str!("../files/robustness/trailer_example0.xosc"),
    ),
    (
        "speed_shapes.xosc",
        include_str!("../files/robustness/speed_shapes.xosc"),
    ),
    (
        "speed_profile_modes.xosc",
        include_str!("../files/robustness/speed_profile_modes.xosc"),
    ),
];

/// The values written over numeric attributes and parameters.
const BAD_VALUES: [&str; 21] = [
    "${1e300 * 1e300}",
    "${0 / 0}",
    "${-1 / 0}",
    "${sqrt(-1)}",
    "NaN",
    "inf",
    "-inf",
    "0",
    "-0",
    "-1",
    "1e300",
    "-1e300",
    "1.7e308",
    "1e-300",
    "-1e-300",
    "2147483647",
    "2147483648",
    "-2147483649",
    "4294967296",
    "9223372036854775808",
    "1e20",
];

/// Step lengths (s) a run may take: valid values (finite, > 0) far from the usual 0.05 s.
const STEPS: [f64; 7] = [1e-3, 0.05, 0.37, 1.0, 10.0, 1e3, 1e9];

/// Steps of a run at most.
const MAX_STEPS: f64 = 300.0;

/// Deadline of one case: far beyond the ≈0.1–1 s a case takes in debug, so that only a hang
/// trips it.
const HANG_DEADLINE: Duration = Duration::from_secs(120);

fn fixture(name: &str) -> PathBuf {
    crate::corpus::fixture("robustness").join(name)
}

/// Byte ranges of the attribute values of `text` that read as numbers.
fn numeric_values(text: &str) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    let mut rest = 0;
    while let Some(open) = text[rest..].find("=\"") {
        let start = rest + open + 2;
        let Some(len) = text[start..].find('"') else {
            break;
        };
        let value = &text[start..start + len];
        if !value.is_empty() && value.parse::<f64>().is_ok() {
            out.push(start..start + len);
        }
        rest = start + len + 1;
    }
    out
}

/// Names of the global parameters (the first ParameterDeclarations block, before the
/// Storyboard), without a leading `$`.
fn global_parameters(text: &str) -> Vec<String> {
    let head = text.split("<Storyboard").next().unwrap_or("");
    head.split("<ParameterDeclaration ")
        .skip(1)
        .filter_map(|d| {
            let from = d.find("name=\"")? + 6;
            let len = d[from..].find('"')?;
            Some(d[from..from + len].trim_start_matches('$').to_owned())
        })
        .collect()
}

/// Checks every number of every frame; keeps the first that is not finite.
#[derive(Default)]
struct FiniteCheck {
    frames: usize,
    corrupt: Option<String>,
}

impl FrameSink for FiniteCheck {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        self.frames += 1;
        if self.corrupt.is_none() {
            self.corrupt = frame.objects().find_map(|e| non_finite(&e, frame.time));
        }
        Ok(())
    }
}

/// "NAME has QUANTITY = VALUE at t = TIME s" for the first number of `e` that is not finite.
fn non_finite(e: &EntityFrame<'_>, time: f64) -> Option<String> {
    let p = e.pose;
    let mut values = vec![
        ("x", p.x),
        ("y", p.y),
        ("z", p.z),
        ("h", p.h),
        ("p", p.p),
        ("r", p.r),
        ("speed", e.speed),
        ("vx", e.velocity.x),
        ("vy", e.velocity.y),
        ("vz", e.velocity.z),
        ("ax", e.acceleration.x),
        ("ay", e.acceleration.y),
        ("az", e.acceleration.z),
        ("yaw_rate", e.yaw_rate),
    ];
    if let Some(r) = e.road_position {
        values.extend([("s", r.s), ("t", r.t), ("offset", r.offset)]);
    }
    let (what, v) = values.into_iter().find(|(_, v)| !v.is_finite())?;
    Some(format!("{} has {what} = {v} at t = {time} s", e.name))
}

/// What became of one damaged scenario.
#[derive(Debug)]
enum Outcome {
    /// Refused while loading, building or running, with this message.
    Refused(String),
    /// Ran to its end.
    Ran,
    /// Stopped by the step's guard: finite extremes combined into a state that is not finite
    /// (runtime/finite.rs); the message names the entity, the quantity and the time.
    Overflow(String),
    /// A frame carried a non-finite number.
    Corrupt(String),
}

/// Loads `text` as `name` with `params`, builds and runs it at step `dt` for at most
/// [`MAX_STEPS`] steps; classifies the result.
fn run_case(name: &str, text: &str, params: &[(String, String)], dt: f64) -> Outcome {
    let path = fixture(name);
    let scenario = match Scenario::load_from_str(text, &path, params) {
        Ok(s) => s,
        Err(e) => return Outcome::Refused(e.to_string()),
    };
    let config = EngineConfig {
        dt,
        duration: Some(MAX_STEPS * dt),
        max_time: MAX_STEPS * dt,
        ..EngineConfig::default()
    };
    let network = match engine::load::road_network(&scenario) {
        Ok(n) => n,
        Err(e) => return Outcome::Refused(e.to_string()),
    };
    let mut engine = match Engine::new(&scenario, network, config) {
        Ok(e) => e,
        Err(e) => return Outcome::Refused(e.to_string()),
    };
    let mut frames = FiniteCheck::default();
    let mut events: Vec<EventRecord> = Vec::new();
    let result = engine.run(&mut frames, &mut events);
    if let Some(corrupt) = frames.corrupt {
        return Outcome::Corrupt(corrupt);
    }
    match result {
        Ok(_) => Outcome::Ran,
        Err(e) if matches!(e.kind(), ErrorKind::NonFinite { .. }) => {
            Outcome::Overflow(e.to_string())
        }
        Err(e) => Outcome::Refused(e.to_string()),
    }
}

/// Runs [`run_case`] on its own thread; a panic or a hang becomes a test failure that names
/// the damage.
fn run_watched(
    name: &'static str,
    text: String,
    params: Vec<(String, String)>,
    dt: f64,
    damage: String,
) {
    let (send, receive) = mpsc::channel();
    let worker = std::thread::spawn(move || {
        // The receiver is gone only when the watcher gave up on a hang; nothing to report to.
        let _ = send.send(run_case(name, &text, &params, dt));
    });
    let outcome = match receive.recv_timeout(HANG_DEADLINE) {
        Ok(outcome) => outcome,
        Err(mpsc::RecvTimeoutError::Timeout) => {
            panic!("{name} with {damage}: no result after {HANG_DEADLINE:?} (hang)")
        }
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            let message = match worker.join() {
                Err(payload) => payload
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                    .unwrap_or_default(),
                Ok(()) => String::new(),
            };
            panic!("{name} with {damage}: panicked: {message}")
        }
    };
    match outcome {
        Outcome::Ran => {}
        Outcome::Overflow(message) => assert!(
            message.starts_with("expected a finite ") && message.contains(" of entity '"),
            "{name} with {damage}: {message}"
        ),
        Outcome::Corrupt(what) => panic!("{name} with {damage}: corrupt state: {what}"),
        Outcome::Refused(message) => {
            assert!(
                names_a_place(&message),
                "{name} with {damage}: the error names no file:line:col: {message}"
            );
        }
    }
}

/// True if `message` names a scenario or road file followed by `:line:col`.
fn names_a_place(message: &str) -> bool {
    [".xosc:", ".xodr:"].iter().any(|ext| {
        message.match_indices(ext).any(|(at, m)| {
            let rest = &message[at + m.len()..];
            let mut parts = rest.splitn(2, ':');
            let line = parts.next().unwrap_or("");
            let col: String = parts
                .next()
                .unwrap_or("")
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            !line.is_empty() && line.chars().all(|c| c.is_ascii_digit()) && !col.is_empty()
        })
    })
}

#[test]
fn the_undamaged_scenarios_run_to_their_end() {
    for (name, text) in SCENARIOS {
        match run_case(name, text, &[], 0.05) {
            Outcome::Ran => {}
            other => panic!("{name}: {other:?}"),
        }
    }
}

#[test]
fn every_scenario_has_numbers_to_damage() {
    for (name, text) in SCENARIOS {
        assert!(numeric_values(text).len() >= 20, "{name}");
    }
    // The two runtime fixtures carry the numeric parameters.
    assert_eq!(
        global_parameters(SCENARIOS[5].1),
        [
            "Shape",
            "Dimension",
            "Value",
            "Mode",
            "V0",
            "Target",
            "MaxAcc"
        ]
    );
    assert_eq!(global_parameters(SCENARIOS[6].1), ["T2", "T3"]);
}

/// The frame check catches a non-finite number (so that the property can fail): a placed
/// entity of a real run (the undamaged one_action_example0) whose speed is NaN, then one whose
/// road s is infinite.
#[test]
fn the_frame_check_catches_a_nan() {
    #[derive(Default)]
    struct Damaged(Vec<Option<String>>);
    impl FrameSink for Damaged {
        fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
            let Some(e) = frame.objects().find(|e| e.road_position.is_some()) else {
                return Ok(());
            };
            if self.0.is_empty() {
                self.0.push(non_finite(&e, 0.5));
                let mut nan = e;
                nan.speed = f64::NAN;
                self.0.push(non_finite(&nan, 0.5));
                let mut far = e;
                let road = e.road_position.map(|r| opendrive::RoadPosition {
                    s: f64::INFINITY,
                    ..r.clone()
                });
                far.road_position = road.as_ref();
                self.0.push(non_finite(&far, 0.5));
                self.0.push(Some(e.name.to_owned()));
            }
            Ok(())
        }
    }
    let (name, text) = SCENARIOS[0];
    let scenario = Scenario::load_from_str(text, &fixture(name), &[]).expect("loads");
    let network = engine::load::road_network(&scenario).expect("its road");
    let config = EngineConfig {
        duration: Some(0.1),
        ..EngineConfig::default()
    };
    let mut engine = Engine::new(&scenario, network, config).expect("builds");
    let mut damaged = Damaged::default();
    engine.run(&mut damaged, &mut ()).expect("runs");
    let [ok, nan, far, Some(who)] = damaged.0.as_slice() else {
        panic!(
            "expected a frame with an entity on a road, found {:?}",
            damaged.0
        );
    };
    assert_eq!(ok, &None);
    assert_eq!(nan, &Some(format!("{who} has speed = NaN at t = 0.5 s")));
    assert_eq!(far, &Some(format!("{who} has s = inf at t = 0.5 s")));
}

#[test]
fn a_place_is_file_line_col() {
    assert!(names_a_place("expected x, found y at /a/b.xosc:12:7"));
    assert!(names_a_place("cannot load: bad at road.xodr:3:1 (x)"));
    assert!(!names_a_place("expected x, found y for dt"));
    assert!(!names_a_place("in /a/b.xosc: no such file"));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn damaged_numbers_are_run_or_refused(
        which in 0..SCENARIOS.len(),
        edits in proptest::collection::vec((any::<Index>(), 0..BAD_VALUES.len()), 1..=3),
        param in proptest::option::of((any::<Index>(), 0..BAD_VALUES.len())),
        dt in proptest::sample::select(&STEPS[..]),
    ) {
        let (name, original) = SCENARIOS[which];
        let ranges = numeric_values(original);
        let mut chosen: Vec<(std::ops::Range<usize>, &str)> = edits
            .iter()
            .map(|(at, v)| (ranges[at.index(ranges.len())].clone(), BAD_VALUES[*v]))
            .collect();
        // Replace from the back so that earlier ranges stay valid; one value per attribute.
        chosen.sort_by_key(|(r, _)| std::cmp::Reverse(r.start));
        chosen.dedup_by_key(|(r, _)| r.start);
        let mut text = original.to_owned();
        let mut damage = Vec::new();
        for (range, value) in &chosen {
            let line = original[..range.start].lines().count();
            damage.push(format!("line {line}: {:?} -> {value}", &original[range.clone()]));
            text.replace_range(range.clone(), value);
        }
        let globals = global_parameters(original);
        let params: Vec<(String, String)> = match param {
            Some((at, v)) if !globals.is_empty() => {
                let p = globals[at.index(globals.len())].clone();
                damage.push(format!("--param {p}={}", BAD_VALUES[v]));
                vec![(p, BAD_VALUES[v].to_owned())]
            }
            _ => Vec::new(),
        };
        damage.push(format!("dt {dt} s"));
        run_watched(name, text, params, dt, damage.join(", "));
    }
}
