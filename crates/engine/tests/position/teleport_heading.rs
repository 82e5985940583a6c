//! The heading of an entity placed by a TeleportAction onto a lane whose width changes
//! (OpenSCENARIO 1.3 §7.4 LanePosition: with no Orientation the entity is aligned with the
//! lane's driving direction), and kept by the default controller afterwards (§7.5.1: it
//! keeps its lane). Fixture `files/position/teleport_widening.xosc` on `widening.xodr`:
//! lanes 1 and −1 of width w(s) = 3 + 0.04·s (OpenDRIVE 1.8 §11.5.1), laneOffset 0.
//!
//! Hand computation. A lane centre at lateral position t(s) on a reference line of heading
//! θ(s) and curvature κ runs along p′(s) = (1 − κ·t)·T + t′·N (the normal N turns with
//! N′ = −κ·T), so its heading is θ + atan2(t′, 1 − κ·t). Lane −1's centre is
//! t = −w/2 = −(3 + 0.04·s)/2, t′ = −0.02; lane 1's is t = +w/2, t′ = +0.02, driven
//! towards −s (heading + π).
//!
//! * Road "1", a line along +x (θ = 0, κ = 0): lane −1 heads atan(−0.02) = −0.0199973…,
//!   lane 1 heads π + atan(0.02) everywhere; lane −1's centre is y = −(3 + 0.04·x)/2.
//! * Road "2", an arc of κ = 0.01 heading 0 at s = 0, at s = 40: θ = 0.4, w = 4.6,
//!   t = ∓2.3. Lane −1: 0.4 + atan2(−0.02, 1 + 0.023) = 0.380452…; lane 1:
//!   0.4 + atan2(0.02, 1 − 0.023) + π.
//!
//! Counting the lane's slope twice (the entity's heading relative to the reference line
//! taken as relative to the lane) would give atan(−0.02) + atan(−0.02) ≈ −0.04 from the
//! first step on.

use crate::runtime_support;

use std::f64::consts::PI;
use std::path::PathBuf;

use engine::EngineConfig;
use runtime_support::{run_with, Recorder};

/// Tolerance of headings and positions computed in closed form (rad, m): the engine's
/// curvature is a finite difference of headings, exact on an arc up to rounding.
const TOL: f64 = 1e-9;

fn fixture() -> PathBuf {
    crate::corpus::fixture("position").join("teleport_widening.xosc")
}

/// a − b wrapped to (−π, π].
fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(2.0 * PI);
    if d > PI {
        d - 2.0 * PI
    } else {
        d
    }
}

/// Every frame of `name` heads `expected` (rad).
fn heads(frames: &Recorder, name: &str, expected: f64) {
    let rows: Vec<_> = frames.0.iter().filter(|r| r.name == name).collect();
    // 1 s at the default dt of 0.05 s: the frame at t = 0 and twenty more.
    assert!(rows.len() >= 21, "{name}: {} frames", rows.len());
    for r in rows {
        let d = angle_diff(r.h, expected);
        assert!(
            d.abs() < TOL,
            "{name} at t = {}: heading {} (expected {expected}, off by {d})",
            r.time,
            r.h
        );
    }
}

#[test]
fn teleport_onto_a_widening_lane_keeps_the_lane_centre_heading() {
    let (_, frames, _) = run_with(&fixture(), &[], EngineConfig::default());
    heads(&frames, "Right", (-0.02_f64).atan());
    heads(&frames, "Left", PI + 0.02_f64.atan());
    heads(&frames, "ArcRight", 0.4 + (-0.02_f64).atan2(1.023));
    heads(&frames, "ArcLeft", 0.4 + 0.02_f64.atan2(0.977) + PI);
    // The moving entity stays on lane −1's centre: y = −(3 + 0.04·x)/2 on road "1".
    let end = frames.at("Right", 1.0);
    assert!(end.x > 25.0, "Right moved to x = {}", end.x);
    assert!(
        (end.y + (3.0 + 0.04 * end.x) / 2.0).abs() < TOL,
        "y = {}",
        end.y
    );
}
