//! The C side of the C API, compiled with the system C compiler (`cc`, or `$CC`) against
//! `include/oscsim.h` and linked to the `liboscsim` this build made:
//!
//! - `examples/c/run_scenario.c` runs the bundled cut-in scenario, in XML and in the DSL (with
//!   `--road` and `--seed`, through `oscsim_scenario_load`), and prints the final positions;
//!   they equal the last frame of the trajectory CSV that `oscsim run --csv` writes (the
//!   engine's `CsvWriter`, run here through the library for the same scenario);
//! - `tests/c/boundary.c`: a malformed scenario gives `OSCSIM_STATUS_LOAD` with file:line:col in
//!   the message, panics give `OSCSIM_STATUS_PANIC`, and the C program lives on.

use std::path::{Path, PathBuf};
use std::process::Command;

use engine::output::CsvWriter;
use engine::{Engine, EngineConfig};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The folder of the `liboscsim` this test links against: `target/<profile>/deps/`, where
/// cargo leaves the library when it builds it for the tests (or the profile folder above).
fn lib_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test knows its path");
    let deps = exe.parent().expect("tests run from target/<profile>/deps");
    let has_lib =
        |d: &Path| d.join("liboscsim.so").is_file() || d.join("liboscsim.dylib").is_file();
    let found = [Some(deps), deps.parent()]
        .into_iter()
        .flatten()
        .find(|d| has_lib(d))
        .map(Path::to_path_buf);
    found.unwrap_or_else(|| panic!("no liboscsim in {} or above", deps.display()))
}

/// Compiles `source` into `name` in the test's scratch folder.
fn compile(source: &Path, name: &str) -> PathBuf {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let lib = lib_dir();
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_owned());
    let status = Command::new(cc)
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"])
        .arg("-I")
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("include"))
        .arg(source)
        .arg("-L")
        .arg(&lib)
        .arg("-loscsim")
        .arg(format!("-Wl,-rpath,{}", lib.display()))
        .arg("-o")
        .arg(&out)
        .status()
        .expect("a C compiler (cc) runs");
    assert!(status.success(), "{} does not compile", source.display());
    out
}

fn run(program: &Path, args: &[&Path]) -> (bool, String, String) {
    let out = Command::new(program)
        .args(args)
        .output()
        .expect("the compiled program runs");
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8 output");
    (out.status.success(), text(out.stdout), text(out.stderr))
}

/// The last frame of the trajectory CSV of `oscsim run --csv` for `scenario` loaded with
/// `options` (default dt 0.05 s; the engine's seed that of the options, as `--seed` sets both):
/// "time,T" then "name,x,y,z,h" per entity.
fn last_frame(scenario: &Path, options: &load::Options) -> Vec<String> {
    let loaded = load::load(scenario, options).expect("loads");
    let config = EngineConfig {
        seed: options.seed,
        ..EngineConfig::default()
    };
    let mut engine = Engine::new(&loaded.scenario, loaded.network.clone(), config).expect("builds");
    let mut csv = CsvWriter::new(Vec::new());
    engine.run(&mut csv, &mut ()).expect("runs");
    let csv = String::from_utf8(csv.into_inner()).expect("UTF-8 CSV");
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let last_time = rows.last().expect("frames")[0];
    // Columns: time,id,name,x,y,z,h,…; positions with 6 decimals, time with 3.
    let mut expected = vec![format!("time,{last_time}")];
    for r in rows.iter().filter(|r| r[0] == last_time) {
        expected.push(format!("{},{},{},{},{}", r[2], r[3], r[4], r[5], r[6]));
    }
    expected
}

#[test]
fn c_example_prints_the_final_positions_of_oscsim_run() {
    let scenario = repo().join("examples/scenarios/cut_in_highway.xosc");
    let program = compile(&repo().join("examples/c/run_scenario.c"), "run_scenario");
    let (ok, stdout, stderr) = run(&program, &[&scenario]);
    assert!(ok, "run_scenario failed: {stderr}");
    let got: Vec<&str> = stdout.lines().collect();
    assert_eq!(got, last_frame(&scenario, &load::Options::default()));
    // Both entities of the cut-in, and a run that got somewhere (the scenario stops after
    // the cut-in at well over 5 s).
    assert_eq!(got.len(), 3);
    let last_time = got[0].trim_start_matches("time,");
    assert!(last_time.parse::<f64>().expect("a time") > 5.0);
}

#[test]
fn c_example_loads_the_dsl_cut_in_with_its_road_and_seed() {
    let scenario = repo().join("examples/scenarios/cut_in_highway.osc");
    let road = repo().join("examples/roads/highway.xodr");
    let program = compile(
        &repo().join("examples/c/run_scenario.c"),
        "run_scenario_osc",
    );
    let (ok, stdout, stderr) = run(
        &program,
        &[
            &scenario,
            Path::new("--road"),
            &road,
            Path::new("--seed"),
            Path::new("7"),
        ],
    );
    assert!(ok, "run_scenario failed: {stderr}");
    let got: Vec<&str> = stdout.lines().collect();
    let options = load::Options {
        road: Some(road.clone()),
        seed: 7,
        ..load::Options::default()
    };
    assert_eq!(got, last_frame(&scenario, &options));
    // ego and overtaker, after the DSL plan's phases (get ahead, 2 s cut-in, 0.5 s, 4.25 s).
    assert_eq!(got.len(), 3, "{stdout}");
    let last_time: f64 = got[0].trim_start_matches("time,").parse().expect("a time");
    assert!(last_time > 6.75, "{stdout}");
    // Without the road, the DSL file names none: a load error at the file's start.
    let (ok, _, stderr) = run(&program, &[&scenario]);
    assert!(!ok);
    assert!(
        stderr.contains(&format!("{}:1:1", scenario.display())),
        "{stderr}"
    );
}

#[test]
fn errors_and_panics_are_status_codes_and_the_c_program_lives() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let good = repo().join("examples/scenarios/cut_in_highway.xosc");
    let text = std::fs::read_to_string(&good).expect("the bundled scenario reads");
    // A dynamics shape the XSD does not have, where the first dynamicsShape is; the road
    // network by its absolute path, since the copy lives elsewhere.
    let road = repo().join("examples/roads/highway.xodr");
    let bad_text = text
        .replacen("dynamicsShape=\"", "dynamicsShape=\"wobbly", 1)
        .replace("../roads/highway.xodr", &road.display().to_string());
    let offset = bad_text.find("wobbly").expect("replaced");
    let line = bad_text[..offset].matches('\n').count() + 1;
    let line_start = bad_text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let column = bad_text[line_start..offset].chars().count() + 1;
    let bad = dir.join("malformed.xosc");
    std::fs::write(&bad, &bad_text).expect("the scratch folder is writable");

    let program = compile(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/c/boundary.c"),
        "boundary",
    );
    let (ok, stdout, stderr) = run(&program, &[&bad, &good]);
    assert!(ok, "boundary checks failed:\n{stdout}{stderr}");
    assert!(!stdout.contains("FAILED"), "{stdout}");
    assert!(stdout.trim_end().ends_with("alive"), "{stdout}");
    let message = stdout
        .lines()
        .find_map(|l| l.strip_prefix("message "))
        .expect("the load error's message");
    let place = format!("{}:{line}:{column}", bad.display());
    assert!(message.contains(&place), "expected {place} in {message:?}");
    assert!(message.contains("wobbly"), "{message}");
}
