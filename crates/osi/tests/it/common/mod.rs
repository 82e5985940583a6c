//! A small synthetic scene shared by the tests, the benchmark and the sample-trace
//! example: a straight two-lane road along +x, vehicles driving along it at constant
//! speed, a pedestrian crossing, a parked-car-sized obstacle.
//!
//! Everything is chosen so the expected OSI values can be written out by hand:
//! vehicle i's reference point is at x = 5 + 30 i + v_i t, y = −1.75 (centre of lane −1),
//! z = 0, yaw 0, speed v_i = 20 + i m/s; its bounding-box centre is 1.4 m ahead of and
//! 0.75 m above the reference point, so base.position = (6.4 + 30 i + v_i t, −1.75, 0.75).
#![allow(dead_code)] // each test binary uses a different part

pub mod road_scene;

use osi::entity::{moving_object, stationary_object, EntityInfo, EntityKind, MiscObjectInfo};
use osi::ids::{IdAllocator, IdKey};
use osi::osi3::lane::classification::Type as LaneType;
use osi::osi3::lane::Classification as LaneClassification;
use osi::osi3::lane_boundary::boundary_point::Dash;
use osi::osi3::lane_boundary::classification::Type as BoundaryType;
use osi::osi3::lane_boundary::{BoundaryPoint, Classification as BoundaryClassification};
use osi::osi3::{GroundTruth, Identifier, Lane, LaneBoundary, Timestamp, Vector3d};
use osi::rigid_body::RigidBodyState;

/// Step of the sample (s), as integer nanoseconds so timestamps are exact.
pub const STEP_NANOS: u64 = 50_000_000;
/// Lane width (m).
pub const LANE_WIDTH: f64 = 3.5;
/// Road length (m).
pub const ROAD_LENGTH: f64 = 400.0;

/// Name of vehicle i: "Ego" for 0, "Car1", "Car2", … after.
pub fn vehicle_name(i: usize) -> String {
    if i == 0 {
        "Ego".to_string()
    } else {
        format!("Car{i}")
    }
}

/// Speed of vehicle i (m/s).
pub fn vehicle_speed(i: usize) -> f64 {
    20.0 + i as f64
}

/// Time of frame k (s).
pub fn frame_time(k: usize) -> f64 {
    (k as u64 * STEP_NANOS) as f64 * 1e-9
}

fn v3(x: f64, y: f64, z: f64) -> Vector3d {
    Vector3d {
        x: Some(x),
        y: Some(y),
        z: Some(z),
    }
}

/// Lanes −1 and 1 of road "0" and their three boundaries (t = −3.5, 0, 3.5), sampled
/// every 10 m, ids from `ids`.
pub fn lanes(ids: &mut IdAllocator) -> (Vec<Lane>, Vec<LaneBoundary>) {
    let key_lane = |lane| IdKey::Lane {
        road: "0".into(),
        lane_section: 0,
        lane,
    };
    let key_boundary = |lane| IdKey::LaneBoundary {
        road: "0".into(),
        lane_section: 0,
        lane,
    };
    let samples: Vec<f64> = (0..=40).map(|k| k as f64 * 10.0).collect();
    let mut boundaries = Vec::new();
    for (lane, t, kind) in [
        (-1, -LANE_WIDTH, BoundaryType::SolidLine),
        (0, 0.0, BoundaryType::DashedLine),
        (1, LANE_WIDTH, BoundaryType::SolidLine),
    ] {
        boundaries.push(LaneBoundary {
            id: Some(ids.id(key_boundary(lane))),
            boundary_line: samples
                .iter()
                .map(|&x| BoundaryPoint {
                    position: Some(v3(x, t, 0.0)),
                    width: Some(0.12),
                    height: Some(0.0),
                    dash: Some(Dash::Continue as i32),
                })
                .collect(),
            classification: Some(BoundaryClassification {
                r#type: Some(kind as i32),
                ..Default::default()
            }),
            ..Default::default()
        });
    }
    let right = ids.id(key_lane(-1));
    let left = ids.id(key_lane(1));
    let lane = |id: Identifier, t: f64, forward: bool, l: &Identifier, r: &Identifier| Lane {
        id: Some(id),
        classification: Some(LaneClassification {
            r#type: Some(LaneType::Driving as i32),
            centerline: samples.iter().map(|&x| v3(x, t, 0.0)).collect(),
            centerline_is_driving_direction: Some(forward),
            left_lane_boundary_id: vec![*l],
            right_lane_boundary_id: vec![*r],
            ..Default::default()
        }),
        ..Default::default()
    };
    let b = |lane| ids.get(&key_boundary(lane)).expect("boundary made above");
    let lanes = vec![
        lane(right, -LANE_WIDTH / 2.0, true, &b(0), &b(-1)),
        lane(left, LANE_WIDTH / 2.0, false, &b(1), &b(0)),
    ];
    (lanes, boundaries)
}

/// The scene at frame k with `vehicles` vehicles, lanes only when `with_lanes`.
pub fn frame(ids: &mut IdAllocator, k: usize, vehicles: usize, with_lanes: bool) -> GroundTruth {
    let t = frame_time(k);
    let nanos = k as u64 * STEP_NANOS;
    let (lanes, boundaries) = lanes(ids);
    let lane_right = ids
        .get(&IdKey::Lane {
            road: "0".into(),
            lane_section: 0,
            lane: -1,
        })
        .expect("lane made above");
    let mut gt = GroundTruth {
        version: Some(osi::version::interface_version()),
        timestamp: Some(Timestamp {
            seconds: Some((nanos / 1_000_000_000) as i64),
            nanos: Some((nanos % 1_000_000_000) as u32),
        }),
        map_reference: Some("straight_500m.xodr".into()),
        ..Default::default()
    };
    if with_lanes {
        gt.lane = lanes;
        gt.lane_boundary = boundaries;
    }
    for i in 0..vehicles {
        let name = vehicle_name(i);
        let category = if i % 3 == 2 { "truck" } else { "car" };
        let info = EntityInfo {
            name: &name,
            kind: EntityKind::Vehicle { category },
            scenario_file: Some("sample.xosc"),
            model3d: Some("car_white.osgb"),
            color: osi::color::from_color_type("white").expect("known colour"),
            trailer: None,
            lights: None,
            role: None,
        };
        let state = RigidBodyState {
            reference_point: [5.0 + 30.0 * i as f64 + vehicle_speed(i) * t, -1.75, 0.0],
            velocity: [vehicle_speed(i), 0.0, 0.0],
            bbox_centre: [1.4, 0.0, 0.75],
            dimension: [4.5, 1.8, 1.5],
            ..Default::default()
        };
        let mo = moving_object(ids, &info, &state, &[lane_right]).expect("valid sample");
        gt.moving_object.push(mo);
    }
    // Pedestrian crossing the road at x = 60 along +y at 1.5 m/s, from y = −6.
    let walker = RigidBodyState {
        reference_point: [60.0, -6.0 + 1.5 * t, 0.0],
        orientation: [std::f64::consts::FRAC_PI_2, 0.0, 0.0],
        velocity: [0.0, 1.5, 0.0],
        bbox_centre: [0.0, 0.0, 0.9],
        dimension: [0.5, 0.6, 1.8],
        ..Default::default()
    };
    gt.moving_object
        .push(moving_object(ids, &walker_info("sample.xosc"), &walker, &[]).expect("valid sample"));
    let obstacle = MiscObjectInfo {
        name: "Obstacle",
        category: Some("obstacle"),
        scenario_file: Some("sample.xosc"),
        model3d: None,
        color: None,
        position: [200.0, 1.75, 0.5],
        orientation: [0.0, 0.0, 0.0],
        dimension: [2.0, 1.0, 1.0],
    };
    gt.stationary_object
        .push(stationary_object(ids, &obstacle, &[]).expect("valid sample"));
    gt.host_vehicle_id = gt.moving_object.first().and_then(|m| m.id);
    gt
}

/// Frames 0..n; lanes in the first frame only (OSI allows static data once).
pub fn frames(n: usize, vehicles: usize) -> Vec<GroundTruth> {
    let mut ids = IdAllocator::new();
    (0..n)
        .map(|k| frame(&mut ids, k, vehicles, k == 0))
        .collect()
}

/// A fresh empty directory of its own under the system temp dir for one test, removed with
/// everything in it when the returned value drops (at the test's end, also when it fails).
pub fn temp_dir(test: &str) -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix(&format!("oscsim-osi-{test}-"))
        .tempdir()
        .expect("temp dir is writable")
}

/// The pedestrian "Walker" of both scenes, 0.5 × 0.6 × 1.8 m.
pub fn walker_info(scenario_file: &'static str) -> EntityInfo<'static> {
    EntityInfo {
        name: "Walker",
        kind: EntityKind::Pedestrian {
            category: "pedestrian",
        },
        scenario_file: Some(scenario_file),
        model3d: None,
        color: None,
        trailer: None,
        lights: None,
        role: None,
    }
}

/// The frames of a trace file, `.osi` or `.mcap`.
pub fn read_back(path: &std::path::Path) -> Vec<GroundTruth> {
    match osi::trace::TraceFormat::from_path(path) {
        osi::trace::TraceFormat::Osi => osi::trace::read_osi(path).expect("trace reads back"),
        osi::trace::TraceFormat::Mcap => osi::trace::read_mcap(path)
            .expect("trace reads back")
            .frames
            .into_iter()
            .map(|f| f.ground_truth)
            .collect(),
    }
}
