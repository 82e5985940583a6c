//! `oscsim batch` survives being killed (issue 32): a batch process SIGKILLed at several points
//! of its run and started again on the same `--out` ends with results.csv, results.parquet,
//! report.html and the saved variant folders byte for byte those of an uninterrupted run, for
//! a whole batch, for a shard and for a sweep of DSL seeds with coverage; a folder of another
//! sweep is refused; slow and failing variants are failed rows and the others complete.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

fn file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../batch/tests/files")
        .join(name)
}

fn scratch(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_batch_resume")
        .join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn command(args: &[&str]) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_oscsim"));
    cmd.args(args).env("SOURCE_DATE_EPOCH", "1764158400");
    cmd
}

fn oscsim(args: &[&str]) -> Output {
    command(args).output().expect("oscsim starts")
}

fn text(out: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// The rows the journal in `dir` holds (its records less the header), 0 before it exists.
fn recorded(dir: &Path) -> usize {
    match batch::read_journal(&dir.join(batch::JOURNAL_FILE)) {
        Ok(c) => c.records.len() - 1,
        Err(_) => 0,
    }
}

/// Starts `args`, waits until the journal in `dir` holds at least `rows` rows and SIGKILLs
/// the process (std's `Child::kill` is SIGKILL on Unix). Returns the rows recorded after the
/// kill. Panics if the batch ended before (the kill would not have been mid-run).
fn kill_at(args: &[&str], dir: &Path, rows: usize) -> usize {
    let mut child: Child = command(args)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("oscsim starts");
    let start = Instant::now();
    while recorded(dir) < rows {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the batch ended before {rows} rows were recorded"
        );
        assert!(start.elapsed() < Duration::from_secs(300), "no progress");
        std::thread::sleep(Duration::from_millis(2));
    }
    assert!(child.try_wait().unwrap().is_none(), "ended before the kill");
    child.kill().unwrap();
    child.wait().unwrap();
    recorded(dir)
}

/// Every file under `dir`, relative, sorted.
fn files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.push(p.strip_prefix(dir).unwrap().to_path_buf());
            }
        }
    }
    out.sort();
    out
}

/// The two folders hold the same files with the same bytes, the journals aside (their records
/// are in the order the variants finished).
fn assert_same_files(a: &Path, b: &Path) {
    let keep = |f: &PathBuf| f != Path::new(batch::JOURNAL_FILE);
    let (fa, fb): (Vec<_>, Vec<_>) = (
        files(a).into_iter().filter(keep).collect(),
        files(b).into_iter().filter(keep).collect(),
    );
    assert_eq!(fa, fb, "the files of {} and {}", a.display(), b.display());
    for f in &fa {
        assert!(
            std::fs::read(a.join(f)).unwrap() == std::fs::read(b.join(f)).unwrap(),
            "{} differs",
            f.display()
        );
    }
}

/// Kills the batch `args` (with `--out dir`) once the journal holds `points[k]` rows, k = 0, 1,
/// 2, with half a record appended after the second kill as an interrupted append leaves it,
/// then lets it finish; returns the final run's output. Each run goes on from the rows the
/// last one recorded.
fn kill_three_times_then_finish(args: &[&str], dir: &Path, points: [usize; 3]) -> Output {
    let mut last = 0;
    for (k, at) in points.into_iter().enumerate() {
        let now = kill_at(args, dir, at);
        assert!(now >= at && now >= last, "kill {k}: {now} rows");
        if k == 1 {
            // Half of a record: its 8-byte head and a few bytes of its payload.
            use std::io::Write as _;
            let mut j = std::fs::OpenOptions::new()
                .append(true)
                .open(dir.join(batch::JOURNAL_FILE))
                .unwrap();
            j.write_all(&[60, 0, 0, 0, 1, 2, 3, 4, b'7', b'7', b','])
                .unwrap();
        }
        last = now;
    }
    let out = oscsim(args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains(&format!(": {last} variants recorded, ")),
        "{stdout}"
    );
    out
}

/// Runs `args(root/whole)` uninterrupted, then `args(root/killed)` killed at `points` and
/// finished (kill_three_times_then_finish), and checks both folders hold the same files;
/// returns the killed run's folder.
fn uninterrupted_then_killed(
    root: &Path,
    args: &dyn Fn(&Path) -> Vec<String>,
    points: [usize; 3],
) -> PathBuf {
    let (whole, killed) = (root.join("whole"), root.join("killed"));
    let a = args(&whole);
    let out = oscsim(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let b = args(&killed);
    let b: Vec<&str> = b.iter().map(String::as_str).collect();
    kill_three_times_then_finish(&b, &killed, points);
    assert_same_files(&whole, &killed);
    killed
}

#[test]
fn a_batch_killed_three_times_ends_with_the_files_of_an_uninterrupted_run() {
    let root = scratch("whole");
    let grid = file("resume_grid.xosc");
    let grid = grid.to_str().unwrap();
    let (whole, killed) = (root.join("whole"), root.join("killed"));
    let args = |out: &Path| -> Vec<String> {
        [
            "batch",
            grid,
            "--out",
            out.to_str().unwrap(),
            "--jobs",
            "2",
            "--save",
            "csv,events",
            "--quiet",
        ]
        .map(str::to_owned)
        .to_vec()
    };
    let uninterrupted = args(&whole);
    let uninterrupted: Vec<&str> = uninterrupted.iter().map(String::as_str).collect();
    let out = oscsim(&uninterrupted);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let resumed = args(&killed);
    let resumed: Vec<&str> = resumed.iter().map(String::as_str).collect();
    let out = kill_three_times_then_finish(&resumed, &killed, [1, 40, 110]);
    assert!(
        String::from_utf8_lossy(&out.stdout).starts_with("resuming from "),
        "{}",
        text(&out)
    );
    // 192 variants, each with trajectories.csv and events.jsonl, no .partial folder left.
    assert_eq!(files(&killed).len(), 4 + 192 * 2);
    assert_same_files(&whole, &killed);
    assert_eq!(recorded(&killed), 192);

    // Run again when finished: nothing runs, the same files.
    let out = oscsim(&resumed);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains(": 192 variants recorded, 0 to run"),
        "{}",
        text(&out)
    );
    assert_same_files(&whole, &killed);
}

#[test]
fn a_shard_killed_three_times_ends_with_the_files_of_an_uninterrupted_shard() {
    let root = scratch("shard");
    let grid = file("resume_grid.xosc");
    let grid = grid.to_str().unwrap();
    // Shard 1 of 2: the 96 odd variants.
    let args = |out: &Path| -> Vec<String> {
        [
            "batch",
            grid,
            "--out",
            out.to_str().unwrap(),
            "--shard",
            "1/2",
            "--jobs",
            "2",
            "--quiet",
        ]
        .map(str::to_owned)
        .to_vec()
    };
    let killed = uninterrupted_then_killed(&root, &args, [1, 25, 60]);
    let csv = std::fs::read_to_string(killed.join("results.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 96);
    assert!(csv
        .lines()
        .skip(1)
        .all(|l| l.split(',').next().unwrap().parse::<u64>().unwrap() % 2 == 1));
}

/// A batch of seeds of a DSL scenario with cover items (files/covered_cut_in.osc) resumes as a
/// distribution does: its journal rows carry the coverage samples, so the resumed folder has the
/// results.csv, results.parquet, report.html and coverage.csv of an uninterrupted run, byte for
/// byte. Another seed range of the same length, in the same folder, is another sweep.
#[test]
fn a_seed_sweep_killed_three_times_ends_with_the_files_and_coverage_of_an_uninterrupted_run() {
    let root = scratch("seeds");
    let osc = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/covered_cut_in.osc");
    let road = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/roads/highway.xodr");
    let args = |out: &Path, seeds: &str| -> Vec<String> {
        [
            "batch",
            osc.to_str().unwrap(),
            "--road",
            road.to_str().unwrap(),
            "--seeds",
            seeds,
            "--out",
            out.to_str().unwrap(),
            "--jobs",
            "2",
            "--quiet",
        ]
        .map(str::to_owned)
        .to_vec()
    };
    let killed = uninterrupted_then_killed(&root, &|out| args(out, "200"), [1, 30, 90]);
    let coverage = std::fs::read_to_string(killed.join("coverage.csv")).unwrap();
    assert!(
        coverage.starts_with("item,bucket,low,high,hits\n"),
        "{coverage}"
    );
    // Every seed's row, each with the start speed it sampled (a number: Ego is in the scene
    // at the end).
    let csv = std::fs::read_to_string(killed.join("results.csv")).unwrap();
    let table = batch::Table::from_csv(&csv, "results.csv").unwrap();
    assert_eq!(table.rows.len(), 200);
    let speed = table
        .coverage
        .iter()
        .position(|c| c == "cover:start_speed")
        .expect("the start_speed column");
    for row in &table.rows {
        let o = row.result.as_ref().unwrap();
        assert!(
            matches!(o.samples[speed].as_slice(), [load::Sample::Number(_)]),
            "variant {}: {:?}",
            row.variant,
            o.samples[speed]
        );
    }

    // Seeds 2..201: 200 variants too, but another sweep.
    let other = args(&killed, "2..201");
    let out = oscsim(&other.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("expected the journal of this sweep (sweep "),
        "{}",
        text(&out)
    );
    assert_same_files(&root.join("whole"), &killed);
}

/// A folder holding one sweep's journal refuses another sweep (other options, another
/// distribution, another shard), and a folder of results without a journal refuses any; the
/// files there stay as they were.
#[test]
fn a_folder_of_another_sweep_is_refused() {
    let root = scratch("other");
    let grid = file("grid.xosc");
    let grid = grid.to_str().unwrap();
    let dir = root.join("out");
    let dir_s = dir.to_str().unwrap();
    let out = oscsim(&["batch", grid, "--out", dir_s, "--quiet"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let before = std::fs::read(dir.join("results.csv")).unwrap();
    let other_dist = file("resume_grid.xosc");
    for args in [
        vec!["batch", grid, "--out", dir_s, "--seed", "2", "--quiet"],
        vec!["batch", grid, "--out", dir_s, "--dt", "0.1", "--quiet"],
        vec!["batch", grid, "--out", dir_s, "--shard", "0/2", "--quiet"],
        vec![
            "batch",
            other_dist.to_str().unwrap(),
            "--out",
            dir_s,
            "--quiet",
        ],
    ] {
        let out = oscsim(&args);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {}", text(&out));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains("expected the journal of this sweep (sweep ")
                && stderr.contains(&format!("or none in {dir_s}, found that of sweep ")),
            "{args:?}: {stderr}"
        );
    }
    assert_eq!(std::fs::read(dir.join("results.csv")).unwrap(), before);
    assert_eq!(recorded(&dir), 24);

    // Merged shards (results without a journal) are refused as a batch's folder.
    let merged = root.join("merged");
    let out = oscsim(&["batch", "merge", dir_s, "--out", merged.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let out = oscsim(&["batch", grid, "--out", merged.to_str().unwrap(), "--quiet"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains(&format!(
            "expected an empty folder or one with a batch journal, found results.csv, results.parquet, report.html without batch.journal in {}",
            merged.display()
        )),
        "{}",
        text(&out)
    );
}

/// guarded_dist.xosc (crates/batch/tests/files): variant 1 runs far past a 2 s
/// `--variant-timeout`, variant 2's run fails at t = 1 s (a teleport to lane -1 + dLane -9,
/// which road 1 does not have); 0, 3 and 4 stop after 5, 4 and 3 s (stop triggers
/// "time > 4.99", "> 3.99", "> 2.99" fire at the first step past them). Their measures by hand:
/// Target's reference point starts 85 − 50 = 35 m ahead of Ego's, both at Speed, so the gap
/// is 35 − 5 = 30 m bumper to bumper and the headway 35 m / Speed (1.75 s at 20 m/s, 3.5 s at
/// 10 m/s) until Target jumps 150 m ahead at 1 s. Two failed: exit status 100 + 2.
#[test]
fn slow_and_failing_variants_are_failed_rows_and_the_others_complete() {
    let dir = scratch("guarded");
    let dist = file("guarded_dist.xosc");
    let out = oscsim(&[
        "batch",
        dist.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--max-time",
        "2000000",
        "--variant-timeout",
        "2",
        "--jobs",
        "2",
        "--quiet",
    ]);
    assert_eq!(out.status.code(), Some(102), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stdout).starts_with("5 variants, 2 failed"),
        "{}",
        text(&out)
    );
    let csv = std::fs::read_to_string(dir.join("results.csv")).unwrap();
    let table = batch::Table::from_csv(&csv, "results.csv").unwrap();
    assert_eq!(table.parameters, ["Speed", "StopTime", "DLane"]);
    // (variant, end time s, headway s); the CSV keeps 1e-6, times 1e-3.
    const TOL: f64 = 1e-6;
    for (v, end, headway) in [(0, 5.0, 1.75), (3, 4.0, 3.5), (4, 3.0, 1.75)] {
        let o = table.rows[v]
            .result
            .as_ref()
            .unwrap_or_else(|e| panic!("variant {v}: {e}"));
        assert_eq!(o.stop, Some(batch::StopReason::StopTrigger), "variant {v}");
        assert!(
            (o.end_time - end).abs() < TOL,
            "variant {v}: {}",
            o.end_time
        );
        assert!(
            (o.min_headway.unwrap() - headway).abs() < TOL,
            "variant {v}: {:?}",
            o.min_headway
        );
        assert!(
            (o.min_gap.unwrap() - 30.0).abs() < TOL,
            "variant {v}: {:?}",
            o.min_gap
        );
        // Jump started once (the storyboard's one Event).
        assert_eq!(o.events_started, 1, "variant {v}");
    }
    assert_eq!(
        table.rows[1].result,
        Err("timed out: ran longer than the variant timeout of 2 s (wall clock)".to_owned())
    );
    let failed = table.rows[2].result.as_ref().unwrap_err();
    assert!(
        failed.starts_with("expected lane -10 (lane -1 + dLane -9) on road \"1\"")
            && failed.ends_with("(at t = 1.000 s)"),
        "{failed}"
    );
}

/// `oscsim batch merge` refuses a shard that was killed (naming how far it got) and shards of
/// different sweeps; once the killed shard has been run again, the merge gives the unsharded
/// run's files.
#[test]
fn merge_refuses_an_unfinished_shard_and_another_sweeps() {
    let root = scratch("merge");
    let grid = file("resume_grid.xosc");
    let grid = grid.to_str().unwrap();
    let dir = |name: &str| root.join(name).to_str().unwrap().to_owned();
    let (whole, s0, s1, other, merged) = (
        dir("whole"),
        dir("s0"),
        dir("s1"),
        dir("other"),
        dir("merged"),
    );
    for args in [
        vec!["batch", grid, "--out", &whole, "--quiet"],
        vec!["batch", grid, "--out", &s0, "--shard", "0/2", "--quiet"],
        vec![
            "batch", grid, "--out", &other, "--shard", "1/2", "--seed", "7", "--quiet",
        ],
    ] {
        let out = oscsim(&args);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", text(&out));
    }
    let shard1 = [
        "batch", grid, "--out", &s1, "--shard", "1/2", "--jobs", "1", "--quiet",
    ];
    let done = kill_at(&shard1, Path::new(&s1), 10);
    let refused = |args: &[&str], expected: &str| {
        let out = oscsim(args);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {}", text(&out));
        assert!(
            String::from_utf8_lossy(&out.stderr).contains(expected),
            "{args:?}: {}",
            text(&out)
        );
    };
    refused(
        &["batch", "merge", &s0, &s1, "--out", &merged],
        &format!("expected a finished shard, found {done} of its 96 variants recorded in {s1}/batch.journal: run its command again to finish it"),
    );
    refused(
        &["batch", "merge", &s0, &other, "--out", &merged],
        &format!("expected shards of one sweep, found the journal of another in {other}/batch.journal (the first is {s0}/batch.journal)"),
    );
    let out = oscsim(&shard1);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let out = oscsim(&["batch", "merge", &s0, &s1, "--out", &merged]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    for f in ["results.csv", "results.parquet", "report.html"] {
        assert!(
            std::fs::read(root.join("whole").join(f)).unwrap()
                == std::fs::read(root.join("merged").join(f)).unwrap(),
            "{f} differs"
        );
    }
}
