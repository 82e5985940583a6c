//! `oscsim batch`: shards in separate processes merge into the unsharded outputs byte for byte,
//! any `--jobs` gives the same files, Slurm's environment picks the shard, and the corpus's
//! cut-in_parameter_set.xosc runs as a batch.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn grid() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../batch/tests/files/grid.xosc")
}

fn scratch(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_batch")
        .join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn oscsim(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_oscsim"));
    cmd.args(args);
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd.output().expect("oscsim starts");
    assert!(
        out.status.success(),
        "{args:?}: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn read(dir: &Path, file: &str) -> Vec<u8> {
    std::fs::read(dir.join(file)).unwrap_or_else(|e| panic!("{}: {e}", dir.join(file).display()))
}

const OUTPUTS: [&str; 3] = ["results.csv", "results.parquet", "report.html"];

#[test]
fn three_shard_processes_merge_into_the_unsharded_files() {
    let root = scratch("shards");
    let grid = grid();
    let grid = grid.to_str().unwrap();
    let whole = root.join("whole");
    oscsim(
        &[
            "batch",
            grid,
            "--out",
            whole.to_str().unwrap(),
            "--jobs",
            "1",
            "--quiet",
        ],
        &[],
    );
    let mut parts = Vec::new();
    for i in 0..3 {
        let dir = root.join(format!("shard{i}"));
        // Shard 1 takes its share from a Slurm array task's environment (ids 10–12, min 10).
        if i == 1 {
            let env = [
                ("SLURM_ARRAY_TASK_ID", "11"),
                ("SLURM_ARRAY_TASK_MIN", "10"),
                ("SLURM_ARRAY_TASK_COUNT", "3"),
            ];
            oscsim(
                &["batch", grid, "--out", dir.to_str().unwrap(), "--quiet"],
                &env,
            );
        } else {
            let share = format!("{i}/3");
            oscsim(
                &[
                    "batch",
                    grid,
                    "--out",
                    dir.to_str().unwrap(),
                    "--shard",
                    &share,
                    "--quiet",
                ],
                &[],
            );
        }
        parts.push(dir);
    }
    // Each shard holds variants i, i + 3, …: 8 of the 24.
    let rows = |dir: &Path| {
        String::from_utf8(read(dir, "results.csv"))
            .unwrap()
            .lines()
            .count()
            - 1
    };
    assert!(parts.iter().all(|p| rows(p) == 8));
    let merged = root.join("merged");
    let mut args = vec!["batch", "merge"];
    let names: Vec<String> = parts
        .iter()
        .rev()
        .map(|p| p.display().to_string())
        .collect();
    args.extend(names.iter().map(String::as_str));
    args.extend(["--out", merged.to_str().unwrap()]);
    oscsim(&args, &[]);
    for f in OUTPUTS {
        assert!(
            read(&whole, f) == read(&merged, f),
            "{f} differs after merging"
        );
    }
}

#[test]
fn one_or_two_jobs_write_the_same_files() {
    let root = scratch("jobs");
    let grid = grid();
    for jobs in ["1", "2"] {
        let dir = root.join(jobs);
        oscsim(
            &[
                "batch",
                grid.to_str().unwrap(),
                "--out",
                dir.to_str().unwrap(),
                "--jobs",
                jobs,
                "--quiet",
            ],
            &[],
        );
    }
    for f in OUTPUTS {
        assert!(
            read(&root.join("1"), f) == read(&root.join("2"), f),
            "{f} differs between --jobs 1 and 2"
        );
    }
}

/// esmini's cut-in_parameter_set.xosc: a ValueSetDistribution of two vehicle pairs × EgoSpeed
/// 70, 110 × TargetSpeedFactor 1.1, 1.3, 1.5 = 12 variants, each of which runs to its stop.
#[test]
fn the_corpus_parameter_set_runs_as_a_batch() {
    let dist = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/corpus/esmini/xosc/cut-in_parameter_set.xosc");
    let dir = scratch("corpus");
    let out = oscsim(
        &[
            "batch",
            dist.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
            "--quiet",
        ],
        &[],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.starts_with("12 variants, 0 failed"), "{stdout}");
    let csv = String::from_utf8(read(&dir, "results.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    assert_eq!(
        header,
        "variant,HostVehicle,TargetVehicle,EgoSpeed,TargetSpeedFactor,stop_reason,end_time,collision,first_collision_time,min_ttc,min_headway,min_gap,events_started,error"
    );
    assert_eq!(csv.lines().count(), 13);
}

#[test]
fn only_one_variant_prints_how_to_run_it_alone() {
    let dir = scratch("only");
    let grid = grid();
    let out = oscsim(
        &[
            "batch",
            grid.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
            "--only",
            "17",
            "--quiet",
        ],
        &[],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    // Variant 17 = (EgoSpeed 30, TargetSpeed 10, Gap 20): 17 / 8 = 2, (17 / 4) % 2 = 0, 17 % 4 = 1.
    assert!(
        stdout.contains("--param EgoSpeed=30 --param Gap=20 --param TargetSpeed=10 --seed "),
        "{stdout}"
    );
    let csv = String::from_utf8(read(&dir, "results.csv")).unwrap();
    assert_eq!(csv.lines().count(), 2);
    assert!(
        csv.lines().nth(1).unwrap().starts_with("17,30,10,20,"),
        "{csv}"
    );
}

/// The single `.osi` file in `dir`: its name and bytes.
fn only_trace(dir: &Path) -> (String, Vec<u8>) {
    let names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".osi"))
        .collect();
    assert_eq!(names.len(), 1, "{}: {names:?}", dir.display());
    let bytes = read(dir, &names[0]);
    (names[0].clone(), bytes)
}

/// `--save osi` (issue 15): each variant's OSI trace in DIR/variants/NNNNN/ is, name and bytes,
/// what `oscsim run SCENARIO --param … --osi DIR` writes for that variant (the command
/// `--only` prints), with the same SOURCE_DATE_EPOCH; 1 s at dt 0.05 is 1 / 0.05 + 1 = 21
/// frames.
#[test]
fn saved_osi_traces_are_those_of_oscsim_run() {
    let root = scratch("save_osi");
    let grid = grid();
    let epoch = [("SOURCE_DATE_EPOCH", "1764158400")];
    let out = root.join("batch");
    oscsim(
        &[
            "batch",
            grid.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--duration",
            "1",
            "--jobs",
            "2",
            "--save",
            "csv,osi",
            "--quiet",
        ],
        &epoch,
    );
    // Every variant's trace: 21 frames, Ego and Target in each.
    for v in 0..24 {
        let dir = out.join(format!("variants/{v:05}"));
        let (name, bytes) = only_trace(&dir);
        // OSI 3.8 §2.2.6.2: <time>_gt_<osi>_<protobuf>_<frames>_<scenario>.osi (versions without
        // their dots), the time being
        // SOURCE_DATE_EPOCH 1764158400 = 2025-11-26T12:00:00Z.
        assert_eq!(name, "20251126T120000Z_gt_380_0135_21_following.osi");
        let frames = osi::trace::read_osi_bytes(&bytes, &dir).expect("decodes");
        assert_eq!(frames.len(), 21, "variant {v}");
        assert!(frames.iter().all(|f| f.moving_object.len() == 2));
        assert!(dir.join("trajectories.csv").is_file());
    }
    // Variant 17 = (EgoSpeed 30, TargetSpeed 10, Gap 20) (see the --only test): at t = 1 s Ego's
    // box centre is at x = 50 + 30 + 1.4 = 81.4, Target's at 50 + 20 + 5 + 10 + 1.4 = 86.4.
    let (_, bytes) = only_trace(&out.join("variants/00017"));
    let frames = osi::trace::read_osi_bytes(&bytes, &out).expect("decodes");
    let x = |k: usize| {
        frames[20].moving_object[k]
            .base
            .as_ref()
            .and_then(|b| b.position?.x)
            .unwrap()
    };
    assert!(
        (x(0) - 81.4).abs() < 1e-9 && (x(1) - 86.4).abs() < 1e-9,
        "{} {}",
        x(0),
        x(1)
    );

    // The same variant by `oscsim run`, as `--only 17` prints it.
    let only = oscsim(
        &[
            "batch",
            grid.to_str().unwrap(),
            "--out",
            root.join("only").to_str().unwrap(),
            "--only",
            "17",
            "--quiet",
        ],
        &[],
    );
    let stdout = String::from_utf8_lossy(&only.stdout);
    let command = stdout
        .lines()
        .find_map(|l| l.strip_prefix("variant 17 alone: oscsim "))
        .unwrap_or_else(|| panic!("{stdout}"));
    let run_dir = root.join("run");
    std::fs::create_dir_all(&run_dir).unwrap();
    let mut args: Vec<&str> = command.split(' ').collect();
    args.extend([
        "--duration",
        "1",
        "--quiet",
        "--osi",
        run_dir.to_str().unwrap(),
    ]);
    oscsim(&args, &epoch);
    assert_eq!(
        only_trace(&run_dir),
        only_trace(&out.join("variants/00017"))
    );
}
