//! Bad input with exact expectations: a step length that is not a finite positive number, a
//! parameter set to NaN, a TeleportAction to a place that does not exist, references to a
//! deleted entity, a Trajectory of one vertex, a road network with no road, a missing and a
//! malformed road file. Each is refused with an error that says what was expected and what
//! was found, and names the file and the line:column of the element at fault (the test looks
//! the element up at that place in the fixture); nothing panics, and no frame before the
//! error carries a NaN. Fixtures: `tests/files/robustness/cases/` (each says its case in a
//! comment), on `straight_500m.xodr` (road "1", 500 m, lanes −3…3).

use crate::runtime_support;

use std::path::PathBuf;

use engine::{Engine, EngineConfig, EventRecord};
use runtime_support::Recorder;

/// A fixture of `tests/files/robustness/cases/`.
fn case(name: &str) -> PathBuf {
    crate::corpus::fixture("robustness/cases").join(format!("{name}.xosc"))
}

/// The name of the element that the 1-based `line`:`col` of `file` lies in (or starts).
fn element_at(file: &std::path::Path, line: usize, col: usize) -> String {
    let text = std::fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let row_start: usize = text
        .split_inclusive('\n')
        .take(line - 1)
        .map(str::len)
        .sum();
    let at = row_start
        + text[row_start..]
            .char_indices()
            .nth(col - 1)
            .map_or(0, |(i, _)| i);
    let open = text[..=at]
        .rfind('<')
        .expect("an element before the position");
    text[open + 1..]
        .chars()
        .take_while(char::is_ascii_alphanumeric)
        .collect()
}

/// Asserts that `message` contains `at` (`NAME.xosc:LINE:COL`), that this place in `file`
/// is element `element`, and that `message` contains each of `parts`.
fn assert_names(
    message: &str,
    file: &std::path::Path,
    at: (usize, usize),
    element: &str,
    parts: &[&str],
) {
    let place = format!(
        "{}:{}:{}",
        file.file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default(),
        at.0,
        at.1
    );
    assert!(message.contains(&place), "{message}\n  lacks {place}");
    assert_eq!(element_at(file, at.0, at.1), element, "{message}");
    for part in parts {
        assert!(message.contains(part), "{message}\n  lacks {part}");
    }
}

/// Every number of every recorded frame is finite.
fn assert_finite(frames: &Recorder) {
    for r in &frames.0 {
        let mut values = vec![r.x, r.y, r.z, r.h, r.speed, r.velocity.0, r.velocity.1];
        if let Some((_, _, s, t, offset)) = &r.road {
            values.extend([*s, *t, *offset]);
        }
        assert!(values.iter().all(|v| v.is_finite()), "{r:?}");
    }
}

/// Loads `name`, which must be refused; the message.
fn load_error(name: &str, params: &[(&str, &str)]) -> String {
    let params: Vec<(String, String)> = params
        .iter()
        .map(|(k, v)| ((*k).to_owned(), (*v).to_owned()))
        .collect();
    match Engine::load(&case(name), &params, EngineConfig::default()) {
        Ok(_) => panic!("{name} {params:?} loads"),
        Err(e) => e.to_string(),
    }
}

/// Loads and runs `name`, whose run must fail; the message, the frames and the event log.
fn run_error(name: &str) -> (String, Recorder, Vec<EventRecord>) {
    let mut engine = Engine::load(&case(name), &[], EngineConfig::default())
        .unwrap_or_else(|e| panic!("{name} does not load: {e}"));
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    let error = engine
        .run(&mut frames, &mut events)
        .expect_err("the run must fail");
    (error.to_string(), frames, events)
}

/// The run fails at `time` with an error at `at` in element `element`; the message contains
/// `parts`, the event log carries the same message at `time`, and the frames until then are
/// finite.
fn assert_run_fails(name: &str, time: f64, at: (usize, usize), element: &str, parts: &[&str]) {
    let (message, frames, events) = run_error(name);
    assert_names(&message, &case(name), at, element, parts);
    let logged = events.iter().find_map(|e| match e {
        EventRecord::Error { time, message, .. } => Some((*time, message.clone())),
        _ => None,
    });
    let (logged_time, logged_message) = logged.expect("the error is in the event log");
    assert!((logged_time - time).abs() < 1e-9, "logged at {logged_time}");
    assert_eq!(logged_message, message);
    assert_finite(&frames);
    // The frames end at the failing step's start; a failing Init writes none (there is no
    // initial state).
    match frames.0.last() {
        Some(last) => assert!(
            (last.time - time).abs() < 1e-9,
            "last frame at {}",
            last.time
        ),
        None => assert!(time.abs() < 1e-9, "no frame before the error at {time}"),
    }
}

/// Loads `name` with `params` and runs it to its end, which must succeed with every frame
/// finite; the frames and the event log.
fn run_ok(name: &str, params: &[(&str, &str)]) -> (Recorder, Vec<EventRecord>) {
    let params: Vec<(String, String)> = params
        .iter()
        .map(|(k, v)| ((*k).to_owned(), (*v).to_owned()))
        .collect();
    let mut engine = Engine::load(&case(name), &params, EngineConfig::default())
        .unwrap_or_else(|e| panic!("{name} does not load: {e}"));
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    engine
        .run(&mut frames, &mut events)
        .unwrap_or_else(|e| panic!("{name} fails: {e}"));
    assert_finite(&frames);
    (frames, events)
}

/// Time of the stop transition of storyboard element `name`, if it had one.
fn stop_time(events: &[EventRecord], name: &str) -> Option<f64> {
    events.iter().find_map(|e| match e {
        EventRecord::Transition(r)
            if r.name == name && r.transition == engine::storyboard::Transition::Stop =>
        {
            Some(r.time)
        }
        _ => None,
    })
}

/// `EngineConfig::validate`: dt must be finite and > 0, duration and cap finite and ≥ 0. The
/// message names the setting (a setting has no place in a file).
#[test]
fn step_length_zero_negative_or_not_finite_is_refused() {
    for (dt, shown) in [
        (0.0, "0"),
        (-0.05, "-0.05"),
        (f64::NAN, "NaN"),
        (f64::INFINITY, "inf"),
    ] {
        let config = EngineConfig {
            dt,
            ..EngineConfig::default()
        };
        let expected = format!("expected a finite step length > 0 s, found {shown} for dt");
        let e = config.validate().expect_err("refused");
        assert_eq!(e.to_string(), expected);
        // Engine::load checks it too, before it reads a file.
        match Engine::load(&case("speed_param"), &[], config) {
            Err(e) if matches!(e.kind(), engine::ErrorKind::Config { .. }) => {
                assert_eq!(e.to_string(), expected);
            }
            other => panic!("dt = {dt}: {other:?}"),
        }
    }
    let bad_duration = EngineConfig {
        duration: Some(f64::NAN),
        ..EngineConfig::default()
    };
    assert_eq!(
        bad_duration.validate().expect_err("refused").to_string(),
        "expected a finite duration >= 0 s, found NaN for duration"
    );
    let bad_cap = EngineConfig {
        max_time: -1.0,
        ..EngineConfig::default()
    };
    assert_eq!(
        bad_cap.validate().expect_err("refused").to_string(),
        "expected a finite time >= 0 s, found -1 for max_time"
    );
}

/// `--param Speed=NaN` (or ±inf): the first use of $Speed, the Init SpeedAction's
/// AbsoluteTargetSpeed@value at line 41, column 64, refuses it; no engine exists to be
/// corrupted.
#[test]
fn speed_parameter_set_to_nan_or_inf_is_refused_where_it_is_used() {
    for value in ["NaN", "inf", "-inf"] {
        let message = load_error("speed_param", &[("Speed", value)]);
        assert_names(
            &message,
            &case("speed_param"),
            (41, 64),
            "AbsoluteTargetSpeed",
            &[&format!(
                "expected a double for AbsoluteTargetSpeed@value, found '{value}' at "
            )],
        );
    }
}

/// A LanePosition at s = 600 on the 500 m road 1 (nothing connected at its end), teleported
/// to at t = 1 s: refused at load (`position::check`, issue 16 class 2).
#[test]
fn teleport_beyond_the_end_of_the_road_is_refused() {
    let message = load_error("teleport_s_beyond_road", &[]);
    assert_names(
        &message,
        &case("teleport_s_beyond_road"),
        (57, 31),
        "LanePosition",
        &["expected s in [0, 500] on road \"1\", found 600 at "],
    );
}

/// A LanePosition on lane −7 of road 1 (lanes −3…3), teleported to at t = 1 s: refused at
/// load.
#[test]
fn teleport_to_a_lane_that_does_not_exist_is_refused() {
    let message = load_error("teleport_missing_lane", &[]);
    assert_names(
        &message,
        &case("teleport_missing_lane"),
        (57, 31),
        "LanePosition",
        &["expected an existing lane, found lane -7 on road \"1\" at s = 100 at "],
    );
}

/// Lead is deleted at t = 0.5 s. A RelativeObjectPosition of Lead at t = 1 s is refused by
/// the position (at the RelativeObjectPosition).
#[test]
fn position_relative_to_a_deleted_entity_is_refused() {
    assert_run_fails(
        "deleted_relative_position",
        1.0,
        (88, 31),
        "RelativeObjectPosition",
        &["expected a placed entity named \"Lead\", found none at "],
    );
}

/// Lead is deleted at t = 0.5 s. An action started at t = 1 s that refers to Lead — a
/// RelativeTargetSpeed, a LongitudinalDistanceAction, a RelativeTargetLane, a
/// SynchronizeAction master — is refused at the Action: Lead has no speed or place any more.
/// (Before, each used Lead's last state: Ego stopped 10 m behind a vehicle that was gone.)
#[test]
fn actions_referring_to_a_deleted_entity_are_refused() {
    for name in [
        "deleted_relative_speed",
        "deleted_distance",
        "deleted_lane_change",
        "deleted_synchronize",
    ] {
        assert_run_fails(
            name,
            1.0,
            (85, 15),
            "Action",
            &["expected a placed entity named \"Lead\", found none (deleted, or not yet placed) at "],
        );
    }
}

/// Lead (20 m/s) is deleted at t = 2 s while Ego runs, from t = 1 s, a continuous
/// SpeedAction to Lead's speed (linear over 2 s from 10 m/s), a SynchronizeAction with Lead
/// as master, a continuous LongitudinalDistanceAction 10 m behind Lead (maxAcceleration
/// 3 m/s²) or a continuous LateralDistanceAction. Lead has no speed, place or arrival any
/// more: the action stops (its stop transition is logged at 2.05 s, the step that sees it)
/// and Ego keeps its speed.
/// - following: 15 m/s at t = 2 s, x(2) = 60 + Σ_{k=1..20} 0.05 · (10 + 0.25 k) = 72.625 m,
///   x(5) = 72.625 + 3 · 15 = 117.625 m (before: Ego braked to 0 behind nothing, 83.5 m);
/// - keeping distance: Lead far ahead, Ego gains 3 m/s² · 0.05 s = 0.15 m/s per step, 13 m/s
///   at t = 2 s, x(2) = 60 + Σ_{k=1..20} 0.05 · (10 + 0.15 k) = 71.575 m, x(5) = 71.575 +
///   3 · 13 = 110.575 m (before: it closed in on Lead's last place, 12.3 m/s at 118.8 m);
/// - synchronising, keeping a lateral distance: the speed and lateral place at the stop
///   hold.
#[test]
fn actions_following_an_entity_that_is_deleted_stop() {
    for (name, expected) in [
        ("deleted_while_following", Some((15.0, 117.625))),
        ("deleted_while_keeping_distance", Some((13.0, 110.575))),
        ("deleted_while_synchronizing", None),
        ("deleted_while_keeping_lateral_distance", None),
    ] {
        let (frames, events) = run_ok(name, &[]);
        let stopped = stop_time(&events, "Action");
        assert!(
            stopped.is_some_and(|t| (t - 2.05).abs() < 1e-9),
            "{name}: {stopped:?}"
        );
        // From the stop on, Ego's speed and lateral place hold.
        let at_stop = frames.at("Ego", 2.0).speed;
        let end = frames.at("Ego", 5.0);
        assert!((end.speed - at_stop).abs() < 1e-9, "{name}: {end:?}");
        assert!(
            (end.y - frames.at("Ego", 2.05).y).abs() < 1e-9,
            "{name}: {end:?}"
        );
        if let Some((v, x)) = expected {
            assert!((at_stop - v).abs() < 1e-9, "{name}: {at_stop}");
            assert!((end.x - x).abs() < 1e-9, "{name}: {end:?}");
        }
    }
}

/// A ParameterModifyAction / VariableModifyAction whose double result overflows (1e308 +
/// 1e308 = 2e308 and 1e10 · 1e300 = 1e310, both beyond f64::MAX ≈ 1.8e308) is refused at
/// its Action, as a non-finite declared value or expression result is at load; the value
/// keeps what it was (before, it became inf, and NaN after a further · 0).
#[test]
fn parameter_or_variable_modified_beyond_the_largest_double_is_refused() {
    assert_run_fails(
        "parameter_overflow",
        1.0,
        (55, 15),
        "Action",
        &["expected a finite value of parameter 'Big', found 1e308 + 1e308 = inf at "],
    );
    assert_run_fails(
        "variable_overflow",
        1.0,
        (57, 15),
        "Action",
        &["expected a finite value of variable 'Huge', found 1e10 * 1e300 = inf at "],
    );
    let mut engine =
        Engine::load(&case("parameter_overflow"), &[], EngineConfig::default()).expect("loads");
    let _ = engine.run(&mut Recorder::default(), &mut Vec::new());
    assert_eq!(
        engine.parameter("Big").and_then(|v| v.as_f64()),
        Some(1e308)
    );
}

/// Lead, off the road at (100, 50) where nothing stops it, jumps to 1e300 m/s at t = 0.5 s;
/// at t = 1 s Ego's SpeedAction to 1e10 times Lead's speed would be 1e310 m/s, beyond
/// f64::MAX ≈ 1.8e308: refused at its Action.
#[test]
fn relative_target_speed_beyond_the_largest_double_is_refused() {
    assert_run_fails(
        "relative_speed_overflow",
        1.0,
        (77, 15),
        "Action",
        &["expected a finite target speed, found inf m/s at "],
    );
}

/// The same with Lead's jump at t = 2 s: Ego's continuous SpeedAction started at t = 1 s
/// towards 1e10 · 0 = 0 m/s, linearly over 2 s (10 → 5 m/s by t = 2 s); when the target
/// overflows the action stops (its stop transition in the log, in the step that ends at
/// 2.05 s) and Ego keeps its 5 m/s: x(5) = x(2) + 3 · 5 = 67.375 + 15 = 82.375 m, with
/// x(2) = 60 + Σ_{k=1..20} 0.05 · (10 − 0.25 k) = 60 + 0.05 · (200 − 52.5) = 67.375 m.
#[test]
fn relative_target_speed_overflowing_later_stops_the_action() {
    let (frames, events) = run_ok("relative_speed_overflow", &[("LeadAt", "2")]);
    let stopped = stop_time(&events, "Action");
    assert!(
        stopped.is_some_and(|t| (t - 2.05).abs() < 1e-9),
        "{stopped:?}"
    );
    let end = frames.at("Ego", 5.0);
    assert!((end.speed - 5.0).abs() < 1e-9, "{end:?}");
    assert!((end.x - 82.375).abs() < 1e-9, "{end:?}");
}

/// Lead jumps from rest to 1.7e308 m/s at t = 2 s: a finite speed, but the acceleration of
/// the step, 1.7e308 / 0.05 = 3.4e309 m/s², is beyond f64::MAX. The step's guard
/// (runtime/finite.rs) refuses the step that ends at 2.05 s before its frame is written: the
/// frames end at t = 2 s, the error names Lead, the quantity and the time, and is logged.
#[test]
fn state_overflowing_from_finite_extremes_is_refused_before_its_frame() {
    let path = case("relative_speed_overflow");
    let params = [
        ("LeadAt".to_owned(), "2".to_owned()),
        ("LeadSpeed".to_owned(), "1.7e308".to_owned()),
    ];
    let mut engine = Engine::load(&path, &params, EngineConfig::default()).expect("loads");
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    let error = engine
        .run(&mut frames, &mut events)
        .expect_err("the overflow is refused");
    let expected = "expected a finite acceleration x of entity 'Lead' at t = 2.050 s, found inf \
                    (an overflow of extreme values)";
    assert_eq!(error.to_string(), expected);
    assert!(matches!(error.kind(), engine::ErrorKind::NonFinite { .. }));
    assert!(events.iter().any(|e| matches!(
        e,
        EventRecord::Error { time, element, message }
            if (*time - 2.05).abs() < 1e-9 && element == "Lead" && message == expected
    )));
    assert_finite(&frames);
    let last = frames.0.last().map_or(f64::NAN, |r| r.time);
    assert!((last - 2.0).abs() < 1e-9, "last frame at {last}");
}

/// A Polyline of one vertex is no trajectory (XSD `Polyline`: a line needs two vertices).
/// The FollowTrajectoryAction (its Action element) is skipped with the error in the event
/// log (the runtime's rule for a trajectory that cannot be built, actions/mod.rs),
/// and Ego drives on at 10 m/s on its lane: x(5 s) = 50 + 10 · 5 = 100 m.
#[test]
fn trajectory_of_one_vertex_is_refused_and_logged() {
    let path = case("trajectory_one_vertex");
    let (frames, events) = run_ok("trajectory_one_vertex", &[]);
    let message = events
        .iter()
        .find_map(|e| match e {
            EventRecord::Error { time, message, .. } if (*time - 1.0).abs() < 1e-9 => {
                Some(message.clone())
            }
            _ => None,
        })
        .expect("the error is logged at t = 1 s");
    assert_names(
        &message,
        &path,
        (54, 15),
        "Action",
        &["expected at least 2 vertices in Polyline of trajectory \"One\", found 1 at "],
    );
    let end = frames.at("Ego", 5.0);
    assert!((end.x - 100.0).abs() < 1e-9, "{end:?}");
    assert!((end.speed - 10.0).abs() < 1e-9, "{end:?}");
}

/// A road network without roads: an Init TeleportAction to a LanePosition on road 1 is
/// refused at load, at the LanePosition.
#[test]
fn lane_position_on_an_empty_road_network_is_refused() {
    let message = load_error("empty_road_lane", &[]);
    assert_names(
        &message,
        &case("empty_road_lane"),
        (34, 25),
        "LanePosition",
        &["expected an existing road, found road id \"1\" at "],
    );
}

/// A road network without roads: Ego at a WorldPosition drives off-road, with no road
/// position. Speed 10 m/s, at t = 1 s linearly to 20 m/s over 2 s (0.25 m/s per step); each
/// step moves by its end speed times dt, so from x(1) = 50 + 10 = 60 the ramp covers
/// Σ_{k=1..40} 0.05 · (10 + 0.25 k) = 0.05 · (400 + 0.25 · 820) = 30.25 m, and the last 2 s at
/// 20 m/s 40 m: x(5) = 130.25 m.
#[test]
fn world_position_on_an_empty_road_network_drives_off_road() {
    let (frames, _) = run_ok("empty_road_world", &[]);
    assert!(frames.0.iter().all(|r| r.road.is_none()));
    let end = frames.at("Ego", 5.0);
    assert!((end.x - 130.25).abs() < 1e-9, "{end:?}");
    assert!((end.y + 1.5).abs() < 1e-9, "{end:?}");
    assert!((end.speed - 20.0).abs() < 1e-9, "{end:?}");
}

/// A lane that runs in a loop of two 1 mm roads (`loop.xodr`): at 30–40 m/s a step of
/// 0.05 s would pass 1500–2000 roads. The lane follower takes at most 16 road hops per step
/// (runtime/lanes.rs), so every step ends: the run reaches its stop trigger at t = 5 s with
/// the entity on lane −1 of road 1 or 2, inside the loop's 2 mm, every number finite, and
/// its speed where the SpeedAction took it (40 m/s).
#[test]
fn lane_looping_through_millimetre_roads_never_hangs() {
    let mut engine = Engine::load(&case("lane_loop"), &[], EngineConfig::default()).expect("loads");
    let mut frames = Recorder::default();
    let reason = engine.run(&mut frames, &mut Vec::new()).expect("runs");
    assert_eq!(reason, engine::StopReason::StopTrigger);
    assert_eq!(engine.steps(), 100);
    assert_finite(&frames);
    for r in &frames.0 {
        let (road, lane, ..) = r.road.as_ref().expect("on the road");
        assert!(road == "1" || road == "2", "{r:?}");
        assert_eq!(*lane, -1, "{r:?}");
        assert!((-1e-9..=0.002 + 1e-9).contains(&r.x), "{r:?}");
    }
    assert!((frames.at("Ego", 5.0).speed - 40.0).abs() < 1e-9);
}

/// LogicFile names `nowhere.xodr`, which does not exist: the message names the file and the
/// LogicFile@filepath of the scenario (line 10, column 26).
#[test]
fn missing_road_file_is_named() {
    let message = load_error("missing_road", &[]);
    assert_names(
        &message,
        &case("missing_road"),
        (10, 26),
        "LogicFile",
        &["expected road network file 'nowhere.xodr', found no file at "],
    );
}

/// `malformed.xodr` closes a `<lane>` with `</lanes>` at line 32, column 21: the road
/// crate's message names that place in the road file.
#[test]
fn malformed_road_file_is_named_with_its_place() {
    let message = load_error("malformed_road", &[]);
    assert!(
        message.contains("malformed XML: expected 'lane' tag, not 'lanes' at "),
        "{message}"
    );
    let road = case("malformed_road").with_file_name("malformed.xodr");
    assert!(message.contains("malformed.xodr:32:21"), "{message}");
    assert_eq!(
        std::fs::read_to_string(&road)
            .expect("fixture")
            .lines()
            .nth(31)
            .map(|l| l.trim()),
        Some("</lanes>")
    );
}
