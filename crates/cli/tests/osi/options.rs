//! `oscsim run` options of the OSI output (`--osi-every`, `--osi-static`, `--osi-host`,
//! directory mode), determinism of the trace bytes, and bad input, all on esmini's
//! `cut-in.xosc` (two vehicles, Ego and OverTaker) run for 6 s at dt = 0.05 s: 121 frames.

use crate::osi_common;

use std::path::PathBuf;

use osi::trace::read_osi;
use osi_common::{corpus, oscsim, oscsim_ok, out_dir, DURATION};

/// Frames of the 6 s run: t = 0, 0.05, …, 6.0.
const FRAMES: usize = 121;

fn cut_in() -> PathBuf {
    corpus("esmini/xosc/cut-in.xosc")
}

fn s(p: &std::path::Path) -> &str {
    p.to_str().expect("UTF-8 temp path")
}

/// Nanoseconds of a frame's timestamp.
fn nanos(gt: &osi::osi3::GroundTruth) -> i64 {
    let ts = gt.timestamp.expect("timestamp set");
    ts.seconds.unwrap_or(0) * 1_000_000_000 + i64::from(ts.nanos.unwrap_or(0))
}

#[test]
fn every_third_step_keeps_frames_0_3_6() {
    let dir = out_dir("osi_every");
    let path = dir.join("every.osi");
    oscsim_ok(&cut_in(), &["--osi", s(&path), "--osi-every", "3"]);
    let trace = read_osi(&path).expect("trace reads back");
    // Steps 0, 3, …, 120: ⌈121 / 3⌉ = 41 frames, 0.15 s apart.
    assert_eq!(trace.len(), 41);
    assert_eq!((DURATION / 0.05).round() as usize + 1, FRAMES);
    for (k, gt) in trace.iter().enumerate() {
        assert_eq!(nanos(gt), k as i64 * 150_000_000, "frame {k}");
    }
}

#[test]
fn static_every_repeats_the_lanes_in_every_frame() {
    let dir = out_dir("osi_static");
    let first = dir.join("first.osi");
    let every = dir.join("every.osi");
    oscsim_ok(&cut_in(), &["--osi", s(&first)]);
    oscsim_ok(&cut_in(), &["--osi", s(&every), "--osi-static", "every"]);
    let first = read_osi(&first).expect("trace reads back");
    let every = read_osi(&every).expect("trace reads back");
    assert_eq!(every.len(), FRAMES);
    assert!(!first[0].lane.is_empty() && !first[0].lane_boundary.is_empty());
    assert!(first[1..]
        .iter()
        .all(|gt| gt.lane.is_empty() && gt.lane_boundary.is_empty()));
    for gt in &every {
        assert_eq!(gt.lane, first[0].lane);
        assert_eq!(gt.lane_boundary, first[0].lane_boundary);
    }
}

#[test]
fn host_is_ego_by_default_the_named_entity_or_none() {
    let dir = out_dir("osi_host");
    let host_of = |extra: &[&str], name: &str| {
        let path = dir.join(format!("{name}.osi"));
        let mut args = vec!["--osi", s(&path)];
        args.extend_from_slice(extra);
        let out = oscsim_ok(&cut_in(), &args);
        let warned = String::from_utf8_lossy(&out.stderr).contains("names no entity");
        assert_eq!(warned, name == "none", "warning only for an unknown host");
        let trace = read_osi(&path).expect("trace reads back");
        let id_of = |who: &str| {
            trace[0]
                .moving_object
                .iter()
                .find(|o| o.source_reference[0].identifier[1] == who)
                .and_then(|o| o.id)
        };
        (trace[0].host_vehicle_id, id_of("Ego"), id_of("OverTaker"))
    };
    let (host, ego, _) = host_of(&[], "default");
    assert!(ego.is_some());
    assert_eq!(host, ego);
    let (host, _, overtaker) = host_of(&["--osi-host", "OverTaker"], "named");
    assert!(overtaker.is_some());
    assert_eq!(host, overtaker);
    let (host, _, _) = host_of(&["--osi-host", "Nobody"], "none");
    assert_eq!(host, None);
}

#[test]
fn directory_gets_the_osi_convention_name_and_identical_bytes() {
    // SOURCE_DATE_EPOCH=0 (set by the helper) pins the timestamp to 1970-01-01T00:00:00Z;
    // OSI 3.8 §2.2.6.2: <timestamp>_<type>_<osi version>_<protobuf version>_<frames>_<name>.osi.
    let dir = out_dir("osi_directory");
    let out = oscsim_ok(&cut_in(), &["--osi", s(&dir)]);
    let expected = format!(
        "19700101T000000Z_gt_380_{}_{FRAMES}_cut-in.osi",
        osi::version::PROTOBUF_VERSION.replace('.', "")
    );
    let names: Vec<String> = std::fs::read_dir(&dir)
        .expect("output folder readable")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, std::slice::from_ref(&expected));
    assert!(String::from_utf8_lossy(&out.stdout).contains(&expected));
    // A second run of the same inputs writes the same bytes, .osi and .mcap.
    for ext in ["osi", "mcap"] {
        let a = dir.join(format!("a.{ext}"));
        let b = dir.join(format!("b.{ext}"));
        oscsim_ok(&cut_in(), &["--osi", s(&a)]);
        oscsim_ok(&cut_in(), &["--osi", s(&b)]);
        let (a, b) = (std::fs::read(a), std::fs::read(b));
        assert_eq!(
            a.expect("trace a"),
            b.expect("trace b"),
            "deterministic .{ext}"
        );
    }
}

#[test]
fn bad_osi_options_fail_with_a_message() {
    let dir = out_dir("osi_bad");
    // --osi-every 0 is a usage error (exit 2, clap names the argument).
    let path = dir.join("zero.osi");
    let out = oscsim(&cut_in(), &["--osi", s(&path), "--osi-every", "0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--osi-every"));
    // An unknown --osi-static value is a usage error too.
    let out = oscsim(&cut_in(), &["--osi", s(&path), "--osi-static", "sometimes"]);
    assert_eq!(out.status.code(), Some(2));
    // A trace whose folder is a file cannot be created: exit 1 naming the path.
    let blocker = dir.join("file");
    std::fs::write(&blocker, b"x").expect("temp folder writable");
    let target = blocker.join("trace.osi");
    let out = oscsim(&cut_in(), &["--osi", s(&target)]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(s(&blocker)),
        "error names the path: {stderr}"
    );
    // A bad SOURCE_DATE_EPOCH is refused, not ignored.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args([
            "run",
            s(&cut_in()),
            "--quiet",
            "--duration",
            "0.1",
            "--osi",
            s(&dir),
        ])
        .env("SOURCE_DATE_EPOCH", "yesterday")
        .output()
        .expect("oscsim starts");
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr)
        .contains("expected Unix seconds in SOURCE_DATE_EPOCH, found 'yesterday'"));
}
