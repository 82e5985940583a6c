//! `oscsim batch X.osc --road R.xodr --seeds …` with coverage (ASAM OpenSCENARIO DSL 2.1
//! §7.3.12) over `files/covered_cut_in.osc`: two cover items, one with range/every buckets
//! (Ego's start speed in km/h) and one over an enum (the side the overtaker starts on), and a
//! record whose expression has no value at its event. Over 500 seeds the per-bucket hits of
//! coverage.csv equal the count `scripts/coverage_count.py` makes from results.csv alone; the
//! holes are listed; shards merged equal the single run byte for byte. `oscsim run --coverage`
//! writes the samples of the batch row of its seed. And the bad inputs.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel)
}

fn scenario() -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/covered_cut_in.osc");
    p.display().to_string()
}

fn road() -> String {
    repo("examples/roads/highway.xodr").display().to_string()
}

fn scratch(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_coverage")
        .join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

fn oscsim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args(args)
        .output()
        .expect("oscsim starts")
}

fn ok(args: &[&str]) -> Output {
    let out = oscsim(args);
    assert!(
        out.status.success(),
        "{args:?}: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn text(dir: &Path, file: &str) -> String {
    std::fs::read_to_string(dir.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

#[test]
fn five_hundred_seeds_count_their_buckets_as_the_table_does_and_shards_merge_exactly() {
    let dir = scratch("seeds500");
    let single = dir.join("single");
    let (s, r, out) = (scenario(), road(), single.display().to_string());
    let run = ok(&[
        "batch", &s, "--road", &r, "--seeds", "500", "--out", &out, "--quiet", "--jobs", "2",
    ]);
    let summary = String::from_utf8_lossy(&run.stdout).to_string();
    // 8 buckets: 6 of start_speed (2 of them holes), left and right.
    assert!(
        summary.contains("coverage: 6 of 8 buckets hit (75.0 %) over 2 cover item(s)"),
        "{summary}"
    );

    // The count of an independent script, from results.csv alone.
    let script = Command::new("python3")
        .arg(repo("scripts/coverage_count.py"))
        .arg(single.join("results.csv"))
        .args(["start_speed=range:60:120:10", "side=members:left,right"])
        .output()
        .expect("python3 runs");
    assert!(
        script.status.success(),
        "{}",
        String::from_utf8_lossy(&script.stderr)
    );
    let counted = String::from_utf8(script.stdout).expect("UTF-8");
    // coverage.csv without its bucket labels: item,low,high,hits (a member in `low`).
    let coverage = text(&single, "coverage.csv");
    let mut lines = coverage.lines();
    assert_eq!(lines.next(), Some("item,bucket,low,high,hits"));
    let ours: Vec<String> = lines
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            if c[2].is_empty() {
                format!("{},{},,{}", c[0], c[1], c[4])
            } else {
                format!("{},{},{},{}", c[0], c[2], c[3], c[4])
            }
        })
        .collect();
    assert_eq!(ours, counted.lines().collect::<Vec<_>>());
    // Every seed counted once per item: 500 samples of each.
    let hits = |item: &str| -> u64 {
        ours.iter()
            .filter(|l| l.starts_with(&format!("{item},")))
            .map(|l| {
                l.rsplit(',')
                    .next()
                    .and_then(|h| h.parse::<u64>().ok())
                    .expect("hits")
            })
            .sum()
    };
    assert_eq!((hits("start_speed"), hits("side")), (500, 500));
    // The holes, in coverage.csv (0 hits) and named in the report: 72 to 108 km/h never
    // reaches [60..70) or [110..120].
    assert!(
        coverage.contains("start_speed,[60..70),60,70,0\n"),
        "{coverage}"
    );
    assert!(
        coverage.contains("start_speed,[110..120],110,120,0\n"),
        "{coverage}"
    );
    let report = text(&single, "report.html");
    assert!(
        report.contains("holes: [60..70), [110..120]"),
        "the report lists the holes"
    );
    assert_eq!(report.matches("<h3>cover(").count(), 2, "a chart per item");
    // The record has no value at its event where the overtaker, ahead and faster, recedes:
    // `no value` (never a crash); where it cut in too close, a time to collision ≥ 0 s.
    let results = text(&single, "results.csv");
    let header: Vec<&str> = results.lines().next().expect("header").split(',').collect();
    let ttc = header
        .iter()
        .position(|c| *c == "record:ttc_at_end")
        .expect("the record's column");
    let cells: Vec<&str> = results
        .lines()
        .skip(1)
        .filter_map(|l| l.split(',').nth(ttc))
        .collect();
    assert_eq!(cells.len(), 500);
    let none = cells.iter().filter(|c| **c == "no value").count();
    assert!(none > 250, "{none} of 500 without value");
    assert!(cells
        .iter()
        .all(|c| *c == "no value" || c.parse::<f64>().is_ok_and(|t| t >= 0.0)));

    // Two shards, merged: the single run's files, byte for byte.
    let mut shards = Vec::new();
    for i in 0..2 {
        let d = dir.join(format!("shard{i}")).display().to_string();
        ok(&[
            "batch",
            &s,
            "--road",
            &r,
            "--seeds",
            "500",
            "--shard",
            &format!("{i}/2"),
            "--out",
            &d,
            "--quiet",
        ]);
        shards.push(d);
    }
    let merged = dir.join("merged").display().to_string();
    let mut args = vec!["batch", "merge"];
    args.extend(shards.iter().map(String::as_str));
    args.extend(["--out", &merged]);
    ok(&args);
    for f in [
        "results.csv",
        "results.parquet",
        "report.html",
        "coverage.csv",
    ] {
        assert!(
            std::fs::read(single.join(f)).ok() == std::fs::read(dir.join("merged").join(f)).ok(),
            "{f} differs"
        );
    }
}

#[test]
fn bad_inputs_are_errors_never_crashes() {
    let dir = scratch("bad").display().to_string();
    let (s, r) = (scenario(), road());
    // --seeds on an XML scenario, which has no constraints.
    let xml = repo("examples/scenarios/cut_in_highway.xosc")
        .display()
        .to_string();
    let out = oscsim(&["batch", &xml, "--seeds", "1..10", "--out", &dir]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("expected an OpenSCENARIO DSL scenario (.osc) whose constraints the seeds re-solve, found an XML scenario"), "{err}");
    assert!(err.contains("cut_in_highway.xosc:1:1"), "{err}");
    // A DSL scenario without --seeds, an empty range, --seed beside --seeds.
    let out = oscsim(&["batch", &s, "--road", &r, "--out", &dir]);
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("expected --seeds"),
        "{out:?}"
    );
    let out = oscsim(&["batch", &s, "--road", &r, "--seeds", "9..3", "--out", &dir]);
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("--seeds: expected A..B"),
        "{out:?}"
    );
    let out = oscsim(&[
        "batch", &s, "--road", &r, "--seeds", "5", "--seed", "3", "--out", &dir,
    ]);
    assert_eq!(out.status.code(), Some(2), "a usage error");
    // A cover of something the runtime cannot sample: an error at its place (line 36, the
    // appended line; column 30, `ego` after `    cover(weird, expression: `) before any run.
    let bad = Path::new(&dir).join("bad_cover.osc");
    let text = std::fs::read_to_string(scenario()).expect("reads")
        + "    cover(weird, expression: ego.bounding_box, unit: m)\n";
    std::fs::write(&bad, text).expect("writes");
    let out = oscsim(&[
        "batch",
        &bad.display().to_string(),
        "--road",
        &r,
        "--seeds",
        "3",
        "--out",
        &dir,
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("expected a value the runtime samples") && err.contains("bad_cover.osc:36:30"),
        "{err}"
    );
}

/// `oscsim run X.osc --coverage FILE.csv` writes the samples of one run: the cells of the batch
/// row of the same seed (an independent path: the batch's results table), each cover sample
/// with the bucket a hand computation gives (10 km/h buckets from 60: ⌊v/10⌋·10), the record
/// `no value` or a number with no bucket.
#[test]
fn oscsim_run_writes_the_samples_of_the_batch_row_of_its_seed() {
    let dir = scratch("run");
    let (s, r) = (scenario(), road());
    let out = dir.join("batch").display().to_string();
    ok(&[
        "batch", &s, "--road", &r, "--seeds", "1..6", "--out", &out, "--quiet",
    ]);
    let results = text(&dir.join("batch"), "results.csv");
    let mut lines = results.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let col = |name: &str| header.iter().position(|c| *c == name).expect(name);
    let mut no_values = 0;
    for line in lines {
        let row: Vec<&str> = line.split(',').collect();
        let seed = row[col("seed")];
        let csv = dir.join(format!("seed{seed}.csv"));
        ok(&[
            "run",
            &s,
            "--road",
            &r,
            "--seed",
            seed,
            "--coverage",
            &csv.display().to_string(),
            "--quiet",
        ]);
        let speed = row[col("cover:start_speed")];
        let v: f64 = speed.parse().expect("a speed in km/h");
        let low = (v / 10.0).floor() * 10.0;
        let ttc = row[col("record:ttc_at_end")];
        no_values += usize::from(ttc == "no value");
        let expected = format!(
            "item,value,unit,bucket\n\
             cover:start_speed,{speed},kph,[{low}..{})\n\
             cover:side,{side},,{side}\n\
             record:ttc_at_end,{ttc},s,\n",
            low + 10.0,
            side = row[col("cover:side")],
        );
        assert_eq!(std::fs::read_to_string(&csv).expect("written"), expected);
    }
    assert!(no_values > 0, "a seed whose record has no value");

    // An XML scenario has no items: the header alone, and a warning.
    let xml = repo("examples/scenarios/cut_in_highway.xosc")
        .display()
        .to_string();
    let csv = dir.join("xml.csv");
    let out = ok(&[
        "run",
        &xml,
        "--duration",
        "0.5",
        "--coverage",
        &csv.display().to_string(),
    ]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("no cover(…) or record(…) items"));
    assert_eq!(
        std::fs::read_to_string(&csv).expect("written"),
        "item,value,unit,bucket\n"
    );
}
