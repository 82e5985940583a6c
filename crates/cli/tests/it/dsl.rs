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

/// `oscsim run OSC --road ROAD ARGS… --quiet` writing the trajectory CSV `csv` and the event
/// log `events`.
fn run_to(osc: &Path, road: &Path, args: &[&str], (csv, events): (&Path, &Path)) -> Output {
    let mut all = vec![
        "run",
        osc.to_str().unwrap_or_default(),
        "--road",
        road.to_str().unwrap_or_default(),
    ];
    all.extend_from_slice(args);
    all.extend_from_slice(&[
        "--quiet",
        "--csv",
        csv.to_str().unwrap_or_default(),
        "--events",
        events.to_str().unwrap_or_default(),
    ]);
    oscsim(&all)
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
    let out = run_to(&osc, &road, &["--duration", "10"], (&csv, &events));
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

/// A mandatory lane lost where its lane links end, through `oscsim run` (engine
/// controller/mobil.rs "Across roads", OpenDRIVE 1.8 §11.5 lane linkage): the scenario and map
/// `tests/files/mandatory_lane_lost.{osc,xodr}` (worked in the scenario's comment). One member
/// of random traffic at its drawn speed v_m in lane -2 of road 1 (200 m long), from 1 s handed
/// lane -3 of road 1 as its mandatory lane, which a solid mark keeps it out of on road 1 and
/// whose links lead onto no lane of road 2. The controller's note is logged at the step that
/// starts with the member on road 2, the first frame there: t = dt·⌈(200 − s_0)/(v_m·dt)⌉, by
/// hand from the frame at 0 s (s_0 = s + v_m·t on a free road at its desired speed):
/// - seed 1: s_0 = 163.356089 m, v_m = 12.868149 m/s: 36.643911/12.868149 = 2.8476 s; s =
///   199.386906 m (road 1) at 2.80 s, 200.030314 m (road 2's s 0.030314) at 2.85 s;
/// - seed 3: s_0 = 94.130857 m, v_m = 14.333618 m/s: 105.869143/14.333618 = 7.3861 s; s =
///   199.482949 m at 7.35 s, 200.199630 m at 7.40 s;
/// - seed 6: s_0 = 176.088380 m, v_m = 12.520011 m/s: 23.911620/12.520011 = 1.9099 s; s =
///   199.876401 m at 1.90 s, 200.502401 m at 1.95 s.
///
/// Exactly one such record in the run, for `g.vehicles[0]`, at the action that gave the lane;
/// the member in lane -2 at every frame, on road 2 too, and at 12 s at road 2's s = s_0 +
/// 12·v_m − 200 (117.773877, 66.134273, 126.328512 m).
#[test]
fn run_dsl_scenario_logs_a_mandatory_lane_lost_where_its_links_end() {
    let files = repo("crates/cli/tests/files");
    let (osc, road) = (
        files.join("mandatory_lane_lost.osc"),
        files.join("mandatory_lane_lost.xodr"),
    );
    let tmp = tempfile::Builder::new()
        .prefix("oscsim_mandatory_lost_")
        .tempdir()
        .expect("temp dir");
    let member = "g.vehicles[0]";
    // seed, s_0, v_m (the frame at 0 s), the record's time, road 2's s at 12 s.
    for (seed, s0, v, at, s_end) in [
        (1, 163.356089, 12.868149, 2.85, 117.773877),
        (3, 94.130857, 14.333618, 7.40, 66.134273),
        (6, 176.088380, 12.520011, 1.95, 126.328512),
    ] {
        let (csv, events) = (
            tmp.path().join(format!("t{seed}.csv")),
            tmp.path().join(format!("e{seed}.jsonl")),
        );
        let out = run_to(&osc, &road, &["--seed", &seed.to_string()], (&csv, &events));
        assert_eq!(
            out.status.code(),
            Some(0),
            "seed {seed}: {}",
            text(&out.stderr)
        );
        // The member's frames: time, road, lane, s, speed (the header's columns 0, 9, 10, 13,
        // 14).
        let frames: Vec<(f64, String, i32, f64, f64)> = std::fs::read_to_string(&csv)
            .unwrap_or_default()
            .lines()
            .skip(1)
            .map(|l| l.split(',').collect::<Vec<_>>())
            .filter(|c| c.get(2) == Some(&member))
            .map(|c| {
                let num = |i: usize| c.get(i).and_then(|x| x.parse::<f64>().ok());
                (
                    num(0).unwrap_or(f64::NAN),
                    c.get(9).map_or(String::new(), |r| (*r).to_owned()),
                    c.get(10).and_then(|x| x.parse().ok()).unwrap_or(0),
                    num(13).unwrap_or(f64::NAN),
                    num(14).unwrap_or(f64::NAN),
                )
            })
            .collect();
        // 12 s at 0.05 s: 241 frames, the first on road 1 where the hand computation starts.
        assert_eq!(frames.len(), 241, "seed {seed}");
        let (t0, road0, lane0, s_0, v_0) = &frames[0];
        assert_eq!((*t0, road0.as_str(), *lane0), (0.0, "1", -2), "seed {seed}");
        assert!((s_0 - s0).abs() < 1e-6, "seed {seed}: s_0 = {s_0}");
        assert!((v_0 - v).abs() < 1e-6, "seed {seed}: v_m = {v_0}");
        // The first frame on road 2 is the hand-computed one; the member keeps lane -2 at
        // every frame, on road 2 too (the mandatory lane holds: no change of its own).
        let first_on_2 = frames.iter().find(|f| f.1 == "2").map(|f| f.0);
        assert!(
            first_on_2.is_some_and(|t| (t - at).abs() < 1e-9),
            "seed {seed}: first frame on road 2 at {first_on_2:?}"
        );
        for (t, r, lane, _, _) in &frames {
            assert_eq!(*lane, -2, "seed {seed}: lane at {t} s on road {r}");
        }
        let (t_end, road_end, _, s_last, _) = &frames[frames.len() - 1];
        assert_eq!((*t_end, road_end.as_str()), (12.0, "2"), "seed {seed}");
        assert!((s_last - s_end).abs() < 1e-5, "seed {seed}: s = {s_last}");
        // Exactly one record of the lane lost, at that step, for the member, naming the lane,
        // the road and its lane section.
        let log = std::fs::read_to_string(&events).unwrap_or_default();
        let lost: Vec<serde_json::Value> = log
            .lines()
            .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
            .filter(|r| r["note"].as_str().is_some_and(|n| n.contains(" lost: ")))
            .collect();
        assert_eq!(lost.len(), 1, "seed {seed}: {log}");
        let r = &lost[0];
        assert_eq!(r["kind"], "controller", "seed {seed}: {r}");
        assert_eq!(r["entity"], member, "seed {seed}: {r}");
        assert_eq!(
            r["element"], "do.right/g.vehicles[0]/1:lane",
            "seed {seed}: {r}"
        );
        assert!(
            r["time"].as_f64().is_some_and(|t| (t - at).abs() < 1e-9),
            "seed {seed}: {r}"
        );
        assert_eq!(
            r["note"],
            "mandatory lane -3 lost: its lane links lead onto no lane of road \"2\" (lane section 1) where the entity is; it makes no change towards it there",
            "seed {seed}"
        );
    }
}
