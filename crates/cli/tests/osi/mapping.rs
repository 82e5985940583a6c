//! The OSI mapping of every entity kind, on the bundled `tests/files/osi_mapping.xosc`
//! (a 200 m straight road along +x with lanes 1 and -1 of 3.5 m; see the file's comment),
//! against values worked out by hand from the scenario and road files:
//!
//! - Ego: reference point on lane -1 (centre t = -1.75) at s = 20, heading 0, 10 m/s
//!   (step-shaped SpeedAction); BoundingBox/Center (1.4, 0, 0.75), so the OSI position at
//!   time t is (20 + 10·t + 1.4, -1.75, 0.75); bbcenter_to_rear = -Center.
//! - Dog (animal) at world (40, -12), heading π/2, centre (0, 0, 0.3): position
//!   (40, -12, 0.3); off the road (the road ends at t = -3.5), so no assigned lane.
//! - Chair (wheelchair) on lane 1 at s = 80: OSI counts a wheelchair as a vehicle.
//! - Tree (MiscObject tree) at (100, -15), centre (0, 0, 4): stationary at (100, -15, 4).
//! - Pylon (ExternalObjectReference "pylon"): the road's `<object>` 0.4 × 0.4 × 1.0 m at
//!   s = 60, t = -5, i.e. world (60, -5); box centre half its height up: (60, -5, 0.5).

use crate::osi_common;

use std::path::{Path, PathBuf};

use osi::osi3::moving_object::vehicle_classification::Type as VehicleType;
use osi::osi3::moving_object::Type as MovingType;
use osi::osi3::stationary_object::classification::Type as StationaryType;
use osi::osi3::{GroundTruth, MovingObject, StationaryObject, Vector3d};
use osi::trace::read_osi;
use osi_common::{assert_close, object_ids, oscsim_ok, out_dir, xyz};

/// Hand values are exact decimals; the engine's f64 arithmetic stays within 1e-9 m of them.
const TOLERANCE: f64 = 1e-9;

fn files() -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files")).to_path_buf()
}

fn run(scenario: &Path, test: &str) -> (Vec<GroundTruth>, String) {
    let trace = out_dir(test).join("trace.osi");
    let out = oscsim_ok(
        scenario,
        &["--osi", trace.to_str().expect("UTF-8 temp path")],
    );
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (read_osi(&trace).expect("trace reads back"), stderr)
}

fn assert_xyz(what: &str, v: Option<Vector3d>, expected: [f64; 3]) {
    assert_close(what, xyz(v), expected, TOLERANCE);
}

fn moving<'a>(gt: &'a GroundTruth, name: &str) -> &'a MovingObject {
    gt.moving_object
        .iter()
        .find(|o| o.source_reference[0].identifier[1] == name)
        .unwrap_or_else(|| panic!("moving object {name} in the frame"))
}

fn stationary<'a>(gt: &'a GroundTruth, name: &str) -> &'a StationaryObject {
    gt.stationary_object
        .iter()
        .find(|o| o.source_reference[0].identifier[1] == name)
        .unwrap_or_else(|| panic!("stationary object {name} in the frame"))
}

/// (road id, lane id) of the Lane with OSI id `id` (source_reference [road, s, lane]).
fn lane_of(gt: &GroundTruth, id: u64) -> (String, String) {
    let lane = gt
        .lane
        .iter()
        .find(|l| l.id.and_then(|i| i.value) == Some(id))
        .expect("assigned lane id names a lane of the first frame");
    let ident = &lane.source_reference[0].identifier;
    (ident[0].clone(), ident[2].clone())
}

fn assigned(o: &MovingObject) -> Vec<u64> {
    o.moving_object_classification
        .as_ref()
        .expect("classification set")
        .assigned_lane_id
        .iter()
        .filter_map(|i| i.value)
        .collect()
}

#[test]
fn every_entity_kind_maps_to_its_osi_object() {
    let scenario = files().join("osi_mapping.xosc");
    let (trace, _) = run(&scenario, "osi_mapping_kinds");
    // 0 … 2 s at 0.05 s.
    assert_eq!(trace.len(), 41);
    let (first, last) = (&trace[0], &trace[40]);
    assert!(first
        .map_reference
        .as_deref()
        .is_some_and(|m| m.ends_with("osi_mapping.xodr")));

    let ego = moving(first, "Ego");
    assert_eq!(ego.r#type, Some(MovingType::Vehicle as i32));
    let class = ego.vehicle_classification.as_ref().expect("vehicle class");
    assert_eq!(class.r#type, Some(VehicleType::Car as i32));
    assert_eq!(ego.model_reference.as_deref(), Some("car_red.osgb"));
    let rgb = ego.color_description.and_then(|c| c.rgb).expect("colour");
    assert_eq!(
        (rgb.red, rgb.green, rgb.blue),
        (Some(1.0), Some(0.0), Some(0.0))
    );
    let reference = &ego.source_reference[0];
    assert_eq!(reference.r#type.as_deref(), Some("net.asam.openscenario"));
    assert_eq!(reference.reference.as_deref(), scenario.to_str());
    let base = ego.base.as_ref().expect("base");
    assert_xyz("Ego at 0 s", base.position, [21.4, -1.75, 0.75]);
    let rear = ego.vehicle_attributes.as_ref().expect("vehicle attributes");
    assert_xyz(
        "bbcenter_to_rear",
        rear.bbcenter_to_rear,
        [-1.4, 0.0, -0.75],
    );
    assert_eq!(lane_of(first, assigned(ego)[0]), ("1".into(), "-1".into()));
    let base = moving(last, "Ego").base.as_ref().expect("base");
    assert_xyz("Ego at 2 s", base.position, [41.4, -1.75, 0.75]);
    // Velocity of the box centre = the reference point's (no yaw rate on a straight lane).
    // (Frame 0 carries the engine's initial velocity, measured only from the first step on.)
    assert_xyz("Ego velocity at 2 s", base.velocity, [10.0, 0.0, 0.0]);
    assert_eq!(first.host_vehicle_id, ego.id, "Ego is the default host");

    let dog = moving(first, "Dog");
    assert_eq!(dog.r#type, Some(MovingType::Animal as i32));
    assert_eq!(dog.source_reference[0].identifier, ["Pedestrian", "Dog"]);
    assert_xyz(
        "Dog",
        dog.base.as_ref().expect("base").position,
        [40.0, -12.0, 0.3],
    );
    assert!(assigned(dog).is_empty(), "off the road: no lane");

    let chair = moving(first, "Chair");
    assert_eq!(chair.r#type, Some(MovingType::Vehicle as i32));
    let class = chair
        .vehicle_classification
        .as_ref()
        .expect("vehicle class");
    assert_eq!(class.r#type, Some(VehicleType::Wheelchair as i32));
    assert_eq!(
        chair.source_reference[0].identifier,
        ["Pedestrian", "Chair"]
    );
    assert_eq!(lane_of(first, assigned(chair)[0]), ("1".into(), "1".into()));

    let tree = stationary(first, "Tree");
    assert_eq!(tree.source_reference[0].identifier, ["MiscObject", "Tree"]);
    assert_eq!(tree.model_reference.as_deref(), Some("oak.osgb"));
    let class = tree.classification.as_ref().expect("classification");
    assert_eq!(class.r#type, Some(StationaryType::Tree as i32));
    assert_xyz(
        "Tree",
        tree.base.as_ref().expect("base").position,
        [100.0, -15.0, 4.0],
    );

    let pylon = stationary(first, "Pylon");
    assert_eq!(
        pylon.source_reference[0].identifier,
        ["ExternalObjectReference", "Pylon"]
    );
    let base = pylon.base.as_ref().expect("base");
    assert_xyz("Pylon", base.position, [60.0, -5.0, 0.5]);
    let d = base.dimension.expect("dimension");
    assert_eq!(
        (d.length, d.width, d.height),
        (Some(0.4), Some(0.4), Some(1.0))
    );

    // Every frame: the same five objects with the same ids.
    for gt in &trace {
        assert_eq!(object_ids(gt), object_ids(first));
    }
}

#[test]
fn external_object_without_a_box_is_left_out_with_a_warning() {
    // The same scenario on a road whose object "pylon" has a height but no length or width.
    let dir = out_dir("osi_mapping_unboxed_files");
    let text = std::fs::read_to_string(files().join("osi_mapping.xosc")).expect("bundled file");
    let scenario = dir.join("unboxed.xosc");
    std::fs::write(&scenario, text).expect("temp folder writable");
    let road = std::fs::read_to_string(files().join("osi_mapping.xodr")).expect("bundled file");
    let road = road.replace(
        r#"length="0.4" width="0.4" height="1.0""#,
        r#"height="1.0""#,
    );
    std::fs::write(dir.join("osi_mapping.xodr"), road).expect("temp folder writable");
    let (trace, stderr) = run(&scenario, "osi_mapping_unboxed");
    assert!(
        stderr.contains("ExternalObjectReference 'Pylon' has no bounding box"),
        "warning on stderr: {stderr}"
    );
    assert_eq!(stderr.matches("warning: OSI").count(), 1, "warned once");
    for gt in &trace {
        assert_eq!(gt.stationary_object.len(), 1, "only the Tree");
        assert_eq!(gt.moving_object.len(), 3);
    }
}
