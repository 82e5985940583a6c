//! Shared helpers of the `osi_*` tests: run the `oscsim` binary with `--osi`, and run the
//! same scenario in-process to record what the engine reports at every step.

#![allow(dead_code)] // each test file uses its own subset

use std::path::{Path, PathBuf};
use std::process::Output;

use engine::output::{Frame, FrameSink};
use engine::runtime::EntityKind;
use engine::{Engine, EngineConfig};
use osi::osi3::GroundTruth;
use osi::trace::read_osi;

/// Simulated seconds the tests run (short: debug builds).
pub const DURATION: f64 = 6.0;

/// A scenario of the shared corpus.
pub fn corpus(relative: &str) -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
    .join(relative)
}

/// A fresh, empty folder for one test's output.
pub fn out_dir(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(test);
    // The folder may not exist yet; any other failure shows in the create below.
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("CARGO_TARGET_TMPDIR is writable");
    dir
}

/// Runs `oscsim run SCENARIO --duration DURATION --quiet EXTRA…` with the clock pinned.
pub fn oscsim(scenario: &Path, extra: &[&str]) -> Output {
    oscsim_for(scenario, DURATION, extra)
}

/// Runs `oscsim run SCENARIO --duration SECONDS --quiet EXTRA…` with the clock pinned.
pub fn oscsim_for(scenario: &Path, seconds: f64, extra: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .arg("run")
        .arg(scenario)
        .args(["--duration", &seconds.to_string(), "--quiet"])
        .args(extra)
        .env("SOURCE_DATE_EPOCH", "0")
        .output()
        .expect("the oscsim binary built by cargo starts")
}

/// Like [`oscsim`], and asserts the run succeeded.
pub fn oscsim_ok(scenario: &Path, extra: &[&str]) -> Output {
    let out = oscsim(scenario, extra);
    assert!(
        out.status.success(),
        "oscsim failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Runs `scenario` for `seconds` with `--osi` and `--events` into the folder of `test`, asserts
/// the run succeeded; returns the decoded trace and the event log's text.
pub fn traced_run(test: &str, scenario: &Path, seconds: f64) -> (Vec<GroundTruth>, String) {
    let dir = out_dir(test);
    let trace = dir.join("trace.osi");
    let events = dir.join("events.jsonl");
    let out = oscsim_for(
        scenario,
        seconds,
        &[
            "--osi",
            trace.to_str().expect("the target dir path is UTF-8"),
            "--events",
            events.to_str().expect("the target dir path is UTF-8"),
        ],
    );
    assert!(
        out.status.success(),
        "oscsim failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let trace = read_osi(&trace).expect("the trace reads back");
    let events = std::fs::read_to_string(events).expect("the event log was written");
    (trace, events)
}

/// One entity at one step, as the engine reports it.
#[derive(Debug, Clone)]
pub struct State {
    /// Entity name.
    pub name: String,
    /// Kind.
    pub kind: EntityKind,
    /// Reference point x, y, z (m) and heading, pitch, roll (rad).
    pub pose: [f64; 6],
    /// Bounding-box centre relative to the reference point, entity frame (m).
    pub bbox_centre: [f64; 3],
    /// Velocity of the reference point, world frame (m/s).
    pub velocity: [f64; 3],
    /// Acceleration of the reference point, world frame (m/s²).
    pub acceleration: [f64; 3],
    /// Yaw rate (rad/s).
    pub yaw_rate: f64,
    /// Length, width, height (m).
    pub dimension: [f64; 3],
    /// Road id and lane id when the reference point is on the road surface.
    pub lane: Option<(String, i32)>,
}

/// Every frame of the run: (time, entity states).
#[derive(Default)]
struct Recorder(Vec<(f64, Vec<State>)>);

impl FrameSink for Recorder {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        let states = frame
            .objects()
            .map(|e| {
                let c = e.bounding_box.center();
                State {
                    name: e.name.to_owned(),
                    kind: e.kind,
                    pose: [e.pose.x, e.pose.y, e.pose.z, e.pose.h, e.pose.p, e.pose.r],
                    bbox_centre: [c.x, c.y, c.z],
                    velocity: [e.velocity.x, e.velocity.y, e.velocity.z],
                    acceleration: [e.acceleration.x, e.acceleration.y, e.acceleration.z],
                    yaw_rate: e.yaw_rate,
                    dimension: [
                        e.bounding_box.length(),
                        e.bounding_box.width(),
                        e.bounding_box.height(),
                    ],
                    lane: e
                        .road_position
                        .filter(|p| p.distance <= 1e-9)
                        .map(|p| (p.road_id.clone(), p.lane_id)),
                }
            })
            .collect();
        self.0.push((frame.time, states));
        Ok(())
    }
}

/// Runs `scenario` in-process for [`DURATION`] s with the binary's defaults.
pub fn engine_frames(scenario: &Path) -> Vec<(f64, Vec<State>)> {
    engine_frames_for(scenario, DURATION).expect("the corpus scenario loads and runs")
}

/// Runs `scenario` in-process for `seconds` with the binary's defaults; the error says why
/// it does not load or run.
pub fn engine_frames_for(scenario: &Path, seconds: f64) -> Result<Vec<(f64, Vec<State>)>, String> {
    let config = EngineConfig {
        duration: Some(seconds),
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(scenario, &[], config).map_err(|e| e.to_string())?;
    let mut recorder = Recorder::default();
    engine
        .run(&mut recorder, &mut ())
        .map_err(|e| e.to_string())?;
    Ok(recorder.0)
}

/// R(h, p, r)·v with R = Rz(h)·Ry(p)·Rx(r), each factor written out and multiplied here
/// (OpenSCENARIO 1.3 §6.3 and OSI both use z-y'-x'' Tait-Bryan angles).
pub fn rotate(h: f64, p: f64, r: f64, v: [f64; 3]) -> [f64; 3] {
    let rx = [
        [1.0, 0.0, 0.0],
        [0.0, r.cos(), -r.sin()],
        [0.0, r.sin(), r.cos()],
    ];
    let ry = [
        [p.cos(), 0.0, p.sin()],
        [0.0, 1.0, 0.0],
        [-p.sin(), 0.0, p.cos()],
    ];
    let rz = [
        [h.cos(), -h.sin(), 0.0],
        [h.sin(), h.cos(), 0.0],
        [0.0, 0.0, 1.0],
    ];
    let apply = |m: [[f64; 3]; 3], v: [f64; 3]| {
        [0, 1, 2].map(|i| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2])
    };
    apply(rz, apply(ry, apply(rx, v)))
}

/// `[x, y, z]` of a set OSI vector.
pub fn xyz(v: Option<osi::osi3::Vector3d>) -> [f64; 3] {
    let v = v.expect("the vectors this crate writes are set");
    [v.x, v.y, v.z].map(|c| c.expect("all three components are set"))
}

/// Asserts each component of `found` within `tolerance` of `expected`.
pub fn assert_close(what: &str, found: [f64; 3], expected: [f64; 3], tolerance: f64) {
    for k in 0..3 {
        assert!(
            (found[k] - expected[k]).abs() < tolerance,
            "{what}: expected {expected:?}, found {found:?}"
        );
    }
}

/// Ids of the frame's moving then stationary objects.
pub fn object_ids(gt: &osi::osi3::GroundTruth) -> Vec<Option<osi::osi3::Identifier>> {
    gt.moving_object
        .iter()
        .map(|o| o.id)
        .chain(gt.stationary_object.iter().map(|o| o.id))
        .collect()
}
