//! Two vehicles and a pedestrian on the corpus road `esmini/xodr/straight_500m.xodr`
//! (one road, id "1", reference line along +x from the origin, lanes ±1 3.07 m wide, so
//! their centres lie at y = ∓1.535), fed through [`GroundTruthBuilder`] as the engine
//! will. Closed forms at time t (s):
//! - "Ego" on lane −1 at s = 10 + 20 t, yaw 0: reference (10 + 20 t, −1.535, 0),
//!   bounding-box centre 1.4 m ahead and 0.75 m up: (11.4 + 20 t, −1.535, 0.75),
//!   velocity (20, 0, 0);
//! - "Target" on lane 1 at s = 400 − 15 t, yaw π (driving towards −s): reference
//!   (400 − 15 t, 1.535, 0), centre (398.6 − 15 t, 1.535, 0.75), velocity (−15, 0, 0);
//! - "Walker" (pedestrian) standing at (250, −6, 0), centre 0.9 m up, on no lane.

use osi::entity::{EntityInfo, EntityKind};
use osi::ground_truth::GroundTruthBuilder;
use osi::lanes::assigned_lane_at;
use osi::osi3::GroundTruth;
use osi::polyline::Sampling;
use osi::rigid_body::RigidBodyState;
use std::f64::consts::PI;

/// The corpus road file.
pub const ROAD: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/corpus/esmini/xodr/straight_500m.xodr"
);

/// Step between frames (ns): 0.1 s.
pub const STEP_NANOS: u64 = 100_000_000;

/// Loads the road into a builder.
pub fn builder(
    static_data: osi::ground_truth::StaticData,
) -> (opendrive::RoadNetwork, GroundTruthBuilder) {
    let net =
        opendrive::RoadNetwork::from_file(std::path::Path::new(ROAD)).expect("corpus road loads");
    let mut b = GroundTruthBuilder::new(static_data);
    b.set_road_network(&net, Some("straight_500m.xodr"), &Sampling::default())
        .expect("corpus road samples");
    (net, b)
}

/// The frame at step k.
pub fn frame(net: &opendrive::RoadNetwork, b: &mut GroundTruthBuilder, k: u64) -> GroundTruth {
    let t = (k * STEP_NANOS) as f64 * 1e-9;
    let ego_s = 10.0 + 20.0 * t;
    let target_s = 400.0 - 15.0 * t;
    let ego_pose = net.lane_pose("1", -1, ego_s, 0.0).expect("on the road");
    let target_pose = net.lane_pose("1", 1, target_s, 0.0).expect("on the road");
    let car = |name, color| EntityInfo {
        name,
        kind: EntityKind::Vehicle { category: "car" },
        scenario_file: Some("road_scene.xosc"),
        model3d: Some("car_white.osgb"),
        color,
        trailer: None,
        lights: None,
        role: None,
    };
    let mut f = b.begin_frame(k * STEP_NANOS);
    // Lanes as the engine finds them: locate the reference point on the road network.
    let lane_at = |f: &osi::ground_truth::FrameBuilder<'_>, x, y, h| {
        let position = net.locate(x, y, Some(h)).expect("on the road");
        assigned_lane_at(f.ids(), net, &position).expect("lane built")
    };
    let ego_lane = lane_at(&f, ego_pose.x, ego_pose.y, ego_pose.h);
    let target_lane = lane_at(&f, target_pose.x, target_pose.y, PI);
    let ego = RigidBodyState {
        reference_point: [ego_pose.x, ego_pose.y, ego_pose.z],
        orientation: [ego_pose.h, 0.0, 0.0],
        velocity: [20.0, 0.0, 0.0],
        bbox_centre: [1.4, 0.0, 0.75],
        dimension: [4.5, 1.8, 1.5],
        ..Default::default()
    };
    f.add_entity(
        &car(
            "Ego",
            osi::color::from_color_type("white").expect("white is an OSI colour type"),
        ),
        &ego,
        &[ego_lane],
    )
    .expect("valid entity");
    let target = RigidBodyState {
        reference_point: [target_pose.x, target_pose.y, target_pose.z],
        orientation: [PI, 0.0, 0.0],
        velocity: [-15.0, 0.0, 0.0],
        bbox_centre: [1.4, 0.0, 0.75],
        dimension: [4.5, 1.8, 1.5],
        ..Default::default()
    };
    f.add_entity(
        &car("Target", osi::color::from_rgb(0.8, 0.1, 0.1).ok()),
        &target,
        &[target_lane],
    )
    .expect("valid entity");
    let walker = RigidBodyState {
        reference_point: [250.0, -6.0, 0.0],
        bbox_centre: [0.0, 0.0, 0.9],
        dimension: [0.5, 0.6, 1.8],
        ..Default::default()
    };
    f.add_entity(&super::walker_info("road_scene.xosc"), &walker, &[])
        .expect("valid entity");
    f.finish().clone()
}
