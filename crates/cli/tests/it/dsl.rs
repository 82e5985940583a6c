//! `oscsim validate FILE.osc` and `oscsim dsl resolve FILE.osc --seed N` on the seed's examples
//! and on a file with errors.

use std::path::{Path, PathBuf};
use std::process::Output;

fn dsl_file(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../dsl/tests/files")
        .join(rel)
}

fn oscsim(args: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("cannot start oscsim: {e}"))
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn validate_accepts_the_seed_examples() {
    for f in ["seed/vehicles.osc", "seed/driving_alongside_group.osc"] {
        let path = dsl_file(f);
        let out = oscsim(&["validate", path.to_str().unwrap_or_default()]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}{}",
            text(&out.stdout),
            text(&out.stderr)
        );
        assert!(
            text(&out.stdout).starts_with("OK   "),
            "{}",
            text(&out.stdout)
        );
    }
}

#[test]
fn validate_reports_every_error_with_its_position_and_snippet() {
    let path = dsl_file("semantics/err_several_in_one_pass.osc");
    let out = oscsim(&["validate", path.to_str().unwrap_or_default()]);
    let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(1), "{stdout}{stderr}");
    assert!(
        stdout.starts_with("FAIL ") && stdout.contains("(4 errors)"),
        "{stdout}"
    );
    // The four errors of the file, in source order, each with its position and source line.
    let mut at = 0;
    for (msg, pos) in [
        ("expected length for field `x`, found time", ":1:13]"),
        ("unknown type `lenght`", ":2:4]"),
        ("`vehicle` has no field `colour`", ":4:10]"),
        (
            "cannot add length and time: dimensions m and s differ",
            ":5:11]",
        ),
    ] {
        let found = stdout[at..].find(msg).map(|i| i + at);
        assert!(found.is_some(), "{msg} (in order) in\n{stdout}");
        at = found.unwrap_or(at);
        assert!(
            stdout.contains(&format!("err_several_in_one_pass.osc{pos}")),
            "{stdout}"
        );
    }
    assert!(stdout.contains(" 5 │ keep(x == 1m + 1s)"), "{stdout}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn resolve_prints_the_chosen_values_reproducibly() {
    let path = dsl_file("seed/vehicles.osc");
    let p = path.to_str().unwrap_or_default();
    let a = oscsim(&["dsl", "resolve", p, "--seed", "3"]);
    let b = oscsim(&["dsl", "resolve", p, "--seed", "3"]);
    assert_eq!(a.status.code(), Some(0), "{}", text(&a.stderr));
    assert_eq!(a.stdout, b.stdout);
    let stdout = text(&a.stdout);
    // The wide car's keeps: category car, colour maroon, two axles of two wheels.
    for line in [
        "my_wide_car.vehicle_category = car",
        "my_wide_car.color = maroon",
        "my_wide_car.axles.size() = 2",
        "my_wide_car.axles[1].number_of_wheels = 2",
        "my_bicycle.intended_infrastructure[0] = biking",
    ] {
        assert!(
            stdout.lines().any(|l| l == line),
            "{line} missing in\n{stdout}"
        );
    }
}

#[test]
fn resolve_of_unsatisfiable_constraints_names_both_and_fails() {
    let path = dsl_file("semantics/err_unsat_bounds.osc");
    let p = path.to_str().unwrap_or_default();
    let out = oscsim(&["dsl", "resolve", p, "--seed", "1"]);
    let stdout = text(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    // The first constraint is the error's position; the second is labelled in the snippet.
    assert!(stdout.contains("err_unsat_bounds.osc:2:1]"), "{stdout}");
    assert!(
        stdout.contains(" 2 │ keep(x > 5m)") && stdout.contains(" 3 │ keep(x < 2m)"),
        "{stdout}"
    );
    assert!(stdout.contains("╰── conflicting constraint"), "{stdout}");
}

fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel)
}

#[test]
fn run_dsl_scenario_writes_the_same_outputs_as_an_xml_one() {
    let tmp = tempfile::Builder::new()
        .prefix("oscsim_dsl_run_")
        .tempdir()
        .expect("temp dir");
    let dir = tmp.path();
    let (csv, events) = (dir.join("t.csv"), dir.join("e.jsonl"));
    let osc = repo("examples/scenarios/cut_in_highway.osc");
    let road = repo("examples/roads/highway.xodr");
    let out = oscsim(&[
        "run",
        osc.to_str().unwrap_or_default(),
        "--road",
        road.to_str().unwrap_or_default(),
        "--duration",
        "10",
        "--quiet",
        "--csv",
        csv.to_str().unwrap_or_default(),
        "--events",
        events.to_str().unwrap_or_default(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    let csv_text = std::fs::read_to_string(&csv).unwrap_or_default();
    assert!(csv_text.starts_with("time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed\n"));
    // 10 s at 0.05 s: 201 frames of two vehicles.
    assert_eq!(csv_text.lines().count(), 1 + 201 * 2);
    let log = std::fs::read_to_string(&events).unwrap_or_default();
    // One line per phase start and end, named by the phase path.
    for line in [
        r#"{"time":5.650,"element":"do.cut_in","kind":"act","from":"standbyState","transition":"start","to":"runningState"}"#,
        r#"{"time":7.650,"element":"do.cut_in","kind":"act","from":"runningState","transition":"stop","to":"completeState"}"#,
    ] {
        assert!(log.lines().any(|l| l == line), "{line} not in\n{log}");
    }
}

#[test]
fn run_dsl_scenario_needs_a_road_and_reports_plan_errors_with_positions() {
    let osc = repo("examples/scenarios/cut_in_highway.osc");
    let out = oscsim(&["run", osc.to_str().unwrap_or_default()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains(
            "expected a road network (--road FILE.xodr, or map.set_map_file(\"FILE.xodr\") in the scenario), found none at "
        ) && text(&out.stderr).contains("cut_in_highway.osc:1:1"),
        "{}",
        text(&out.stderr)
    );
    let bad = repo("crates/dsl_runtime/tests/scenarios/err_no_end.osc");
    let road = repo("crates/dsl_runtime/tests/roads/straight.xodr");
    let out = oscsim(&[
        "run",
        bad.to_str().unwrap_or_default(),
        "--road",
        road.to_str().unwrap_or_default(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("expected a way for phase `do.0` to end")
            && text(&out.stderr).contains("err_no_end.osc:5:9"),
        "{}",
        text(&out.stderr)
    );
}

/// Bad input of scenario reuse and of `call` through `oscsim run` (issue 28): exit status 1 and
/// the error's place on stderr (the scenarios' comments say what is wrong where).
#[test]
fn run_dsl_scenario_reports_invocation_and_call_errors_with_positions() {
    let road = repo("crates/dsl_runtime/tests/roads/straight.xodr");
    for (name, message, place) in [
        (
            "err_reuse_unknown_parameter",
            "has no parameter `speed`",
            "err_reuse_unknown_parameter.osc:10:25",
        ),
        (
            "err_reuse_recursive",
            "recursive invocation: `ping` invokes `pong` invokes `ping`",
            "err_reuse_recursive.osc:6:9",
        ),
        (
            "err_reuse_two_entries",
            "name one with --scenario NAME",
            "err_reuse_two_entries.osc:7:1",
        ),
        // The command line binds no external method: `call log_speed(…)` (line 19) cannot run.
        (
            "call_external",
            "expected a host binding for external method `log_speed` (the Python package's Simulation.bind), found none at ",
            "call_external.osc:19:9",
        ),
    ] {
        let osc = repo(&format!("crates/dsl_runtime/tests/scenarios/{name}.osc"));
        let out = oscsim(&[
            "run",
            osc.to_str().unwrap_or_default(),
            "--road",
            road.to_str().unwrap_or_default(),
            "--quiet",
        ]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {err}");
        assert!(err.contains(message) && err.contains(place), "{name}: {err}");
    }
}
