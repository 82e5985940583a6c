//! `oscsim run` on bad input: a missing scenario, malformed XML, an output path that cannot
//! be created, a step length of 0, a parameter set to NaN, a run that fails half-way. Each
//! exits with status 1 (invalid input or failed run, `oscsim --help`), prints no panic, and
//! its error names the file at fault (and, for a scenario, the line:column).

use std::path::{Path, PathBuf};
use std::process::Output;

/// A scenario of the engine's robustness fixtures (`crates/engine/tests/files/robustness`).
fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../engine/tests/files/robustness/cases")
        .join(name)
}

/// A fresh folder for this test's files.
fn scratch(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_errors")
        .join(test);
    // Left-overs of an earlier run may or may not be there.
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    dir
}

/// Runs `oscsim` with `args`.
fn oscsim(args: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("cannot start oscsim: {e}"))
}

/// The run failed with status 1 and no panic; its stderr contains each of `parts`.
fn assert_fails(out: &Output, parts: &[&str]) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    for part in parts {
        assert!(stderr.contains(part), "{stderr}\n  lacks {part}");
    }
    stderr
}

fn text(path: &Path) -> &str {
    path.to_str().expect("test paths are UTF-8")
}

#[test]
fn missing_scenario_file_is_named() {
    let dir = scratch("missing");
    let missing = dir.join("none.xosc");
    let out = oscsim(&["run", text(&missing)]);
    assert_fails(
        &out,
        &[&format!("cannot read scenario file {}", missing.display())],
    );
}

/// The FileHeader element is not closed: line 4 starts `</OpenSCENARIO>` where an attribute
/// or `/>` was expected.
#[test]
fn malformed_xml_is_named_with_line_and_column() {
    let dir = scratch("malformed");
    let file = dir.join("malformed.xosc");
    std::fs::write(
        &file,
        "<?xml version=\"1.0\"?>\n<OpenSCENARIO>\n  <FileHeader revMajor=\"1\" revMinor=\"3\"\n</OpenSCENARIO>\n",
    )
    .expect("scratch file");
    let out = oscsim(&["run", text(&file)]);
    assert_fails(
        &out,
        &[
            "expected well-formed XML",
            &format!("{}:4:1", file.display()),
        ],
    );
}

/// An output path below a regular file cannot be created (whoever runs the test, root
/// included): `--csv` and `--events` name the folder and the file; nothing is written.
#[test]
fn output_path_that_cannot_be_created_is_named() {
    let dir = scratch("unwritable");
    let blocker = dir.join("a_file");
    std::fs::write(&blocker, "not a folder").expect("scratch file");
    let scenario = fixture("speed_param.xosc");
    for flag in ["--csv", "--events"] {
        let target = blocker.join("out.txt");
        let out = oscsim(&["run", text(&scenario), flag, text(&target)]);
        assert_fails(
            &out,
            &[&format!(
                "cannot create folder {} for {}",
                blocker.display(),
                target.display()
            )],
        );
    }
    let target = blocker.join("gt.osi");
    let out = oscsim(&["run", text(&scenario), "--osi", text(&target)]);
    assert_fails(
        &out,
        &[&format!("cannot create folder {}", blocker.display())],
    );
}

#[test]
fn step_length_zero_is_refused() {
    let out = oscsim(&["run", text(&fixture("speed_param.xosc")), "--dt", "0"]);
    assert_fails(
        &out,
        &["expected a finite step length > 0 s, found 0 for dt"],
    );
}

/// `--param Speed=NaN`: refused where $Speed is first used, AbsoluteTargetSpeed@value at
/// line 41, column 64 of the scenario.
#[test]
fn parameter_set_to_nan_is_refused_at_its_use() {
    let scenario = fixture("speed_param.xosc");
    let out = oscsim(&["run", text(&scenario), "--param", "Speed=NaN"]);
    assert_fails(
        &out,
        &[
            "expected a double for AbsoluteTargetSpeed@value, found 'NaN'",
            &format!("{}:41:64", scenario.display()),
        ],
    );
}

/// A TeleportAction relative to a deleted entity at t = 1 s: the run fails there with the
/// RelativeObjectPosition's place (line 88, column 31); the CSV keeps the frames of the 21
/// times until then (t = 0, 0.05, …, 1.0) and its header.
#[test]
fn run_failing_half_way_names_the_element_and_keeps_the_frames() {
    let dir = scratch("half_way");
    // Lead is deleted at 0.5 s; a TeleportAction at 1 s to a RelativeObjectPosition of Lead
    // (line 88, column 31) fails then. (A LanePosition past a road's end is refused at load
    // since issue 16 class 2.)
    let scenario = fixture("deleted_relative_position.xosc");
    let csv = dir.join("out.csv");
    let out = oscsim(&["run", text(&scenario), "--csv", text(&csv)]);
    let stderr = assert_fails(
        &out,
        &[
            "failed at t = 1.000 s",
            "expected a placed entity named \"Lead\", found none",
            &format!("{}:88:31", scenario.display()),
        ],
    );
    // The action's error is printed once (as the event log gets it), the failure refers to it.
    assert_eq!(stderr.matches("found none").count(), 1, "{stderr}");
    let written = std::fs::read_to_string(&csv).expect("the CSV exists");
    // Frames at 0.000, 0.050, …, 1.000: 21 times.
    let mut times: Vec<&str> = written
        .lines()
        .skip(1)
        .filter_map(|l| l.split(',').next())
        .collect();
    times.dedup();
    assert_eq!(times.len(), 21, "{written}");
    assert!(written
        .lines()
        .last()
        .is_some_and(|l| l.starts_with("1.000,")));
}

/// A run that goes on past a runtime error (a route whose waypoints are not connected:
/// engine test routing_drive::unconnected_waypoints_are_reported_and_the_entity_drives_on)
/// writes its complete outputs but exits with status 1, naming the error and its place.
#[test]
fn run_that_logs_a_runtime_error_completes_and_exits_with_one() {
    let dir = scratch("logged_error");
    let scenario = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../engine/tests/files/routing/two_junctions.xosc"
    ));
    let events = dir.join("events.jsonl");
    let out = oscsim(&[
        "run",
        text(&scenario),
        "--param",
        "ToRoad=1",
        "--param",
        "ToS=5",
        "--events",
        text(&events),
    ]);
    let stderr = assert_fails(
        &out,
        &[
            "expected a path through the road network",
            ":65:71",
            "logged 1 error",
        ],
    );
    assert_eq!(stderr.matches("expected a path").count(), 1, "{stderr}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("stopped because"), "{stdout}");
    let log = std::fs::read_to_string(&events).expect("the event log");
    assert_eq!(log.matches("\"kind\":\"error\"").count(), 1, "{log}");
}

/// `--value` and `--values` feed UserDefinedValueConditions; a bad values file is refused with
/// its file:line:col before the run starts.
#[test]
fn user_values_from_the_command_line_and_a_file() {
    let dir = scratch("user_values");
    let scenario = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../engine/tests/files/runtime/user_values.xosc");
    let scenario = scenario.to_str().unwrap();
    let series = dir.join("values.csv");
    std::fs::write(&series, "time,name,value\n2.0,Mode,go\n3.0,Speed,12.5\n").unwrap();
    let log = dir.join("events.jsonl");
    let out = oscsim(&[
        "run",
        scenario,
        "--quiet",
        "--value",
        "Armed=true",
        "--values",
        series.to_str().unwrap(),
        "--events",
        log.to_str().unwrap(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let log = std::fs::read_to_string(&log).unwrap();
    // Armed from the start, Mode at 2 s, Speed 12.5 > 10 at 3 s (each Event sets a monitor).
    for line in [
        r#"{"time":0.000,"element":"ArmedSeen","kind":"monitor","value":true}"#,
        r#"{"time":2.000,"element":"ModeGoSeen","kind":"monitor","value":true}"#,
        r#"{"time":3.000,"element":"FastSeen","kind":"monitor","value":true}"#,
    ] {
        assert!(log.lines().any(|l| l == line), "{line} missing from\n{log}");
    }
    std::fs::write(&series, "time,name,value\n2.0,Mode,go\n1.0,Speed,12.5\n").unwrap();
    let out = oscsim(&[
        "run",
        scenario,
        "--quiet",
        "--values",
        series.to_str().unwrap(),
    ]);
    assert_fails(
        &out,
        &[
            "expected times in non-decreasing order, found '1.0' at",
            "values.csv:3:1",
        ],
    );
}
