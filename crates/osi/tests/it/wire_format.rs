//! The bytes on the wire and the schema, checked against sources outside this crate: the
//! protobuf encoding rules (varints, tags = field number << 3 | wire type) applied by
//! hand, the seed's list of the twelve MovingObject fields (OSI 3.8 osi_object.proto),
//! and Cargo.lock for the protobuf implementation's version.

use osi::osi3::{GroundTruth, Identifier, MovingObject, Timestamp};
use prost::Message;
use prost_types::field_descriptor_proto::{Label, Type};
use prost_types::FileDescriptorSet;

#[test]
fn ground_truth_bytes_by_hand() {
    let gt = GroundTruth {
        version: Some(osi::version::interface_version()),
        timestamp: Some(Timestamp {
            seconds: Some(1),
            nanos: Some(500_000_000),
        }),
        moving_object: vec![MovingObject {
            id: Some(Identifier { value: Some(300) }),
            ..Default::default()
        }],
        ..Default::default()
    };
    #[rustfmt::skip]
    let expected: &[u8] = &[
        // version = 1, length-delimited (tag 0x0A), 6 bytes: major 3, minor 8, patch 0.
        0x0A, 0x06, 0x08, 0x03, 0x10, 0x08, 0x18, 0x00,
        // timestamp = 2 (tag 0x12), 8 bytes: seconds 1; nanos 500000000 = varint
        // 80 CA B5 EE 01 (groups of 7 bits from the low end: 0, 74, 53, 110, 1).
        0x12, 0x08, 0x08, 0x01, 0x10, 0x80, 0xCA, 0xB5, 0xEE, 0x01,
        // moving_object = 5 (tag 0x2A), 5 bytes: id = 1 (tag 0x0A), 3 bytes:
        // value 300 = varint AC 02.
        0x2A, 0x05, 0x0A, 0x03, 0x08, 0xAC, 0x02,
    ];
    assert_eq!(gt.encode_to_vec(), expected);
    assert_eq!(GroundTruth::decode(expected).unwrap(), gt);
}

fn message<'a>(set: &'a FileDescriptorSet, name: &str) -> &'a prost_types::DescriptorProto {
    set.file
        .iter()
        .filter(|f| f.package() == "osi3")
        .flat_map(|f| f.message_type.iter())
        .find(|m| m.name() == name)
        .unwrap_or_else(|| panic!("osi3.{name} in the descriptor set"))
}

#[test]
fn schema_has_the_seeds_moving_object_fields() {
    let set = FileDescriptorSet::decode(osi::schema::GROUND_TRUTH_FILE_DESCRIPTOR_SET).unwrap();
    let mo = message(&set, "MovingObject");
    // From the seed (osi3::MovingObject, OSI 3.x): name, number, repeated?, type name.
    let seed = [
        ("id", 1, false, ".osi3.Identifier"),
        ("base", 2, false, ".osi3.BaseMoving"),
        ("type", 3, false, ".osi3.MovingObject.Type"),
        ("assigned_lane_id", 4, true, ".osi3.Identifier"),
        (
            "vehicle_attributes",
            5,
            false,
            ".osi3.MovingObject.VehicleAttributes",
        ),
        (
            "vehicle_classification",
            6,
            false,
            ".osi3.MovingObject.VehicleClassification",
        ),
        ("model_reference", 7, false, ""),
        ("future_trajectory", 8, true, ".osi3.StatePoint"),
        (
            "moving_object_classification",
            9,
            false,
            ".osi3.MovingObject.MovingObjectClassification",
        ),
        ("source_reference", 10, true, ".osi3.ExternalReference"),
        ("color_description", 11, false, ".osi3.ColorDescription"),
        (
            "pedestrian_attributes",
            12,
            false,
            ".osi3.MovingObject.PedestrianAttributes",
        ),
    ];
    assert_eq!(mo.field.len(), seed.len());
    for (name, number, repeated, type_name) in seed {
        let f = mo.field.iter().find(|f| f.name() == name).unwrap();
        assert_eq!(f.number(), number, "{name}");
        let label = if repeated {
            Label::Repeated
        } else {
            Label::Optional
        };
        assert_eq!(f.label(), label, "{name}");
        assert_eq!(f.type_name(), type_name, "{name}");
    }
    let model_reference = mo
        .field
        .iter()
        .find(|f| f.name() == "model_reference")
        .unwrap();
    assert_eq!(model_reference.r#type(), Type::String);
    // The seed's Type enum: UNKNOWN 0, OTHER 1, VEHICLE 2, PEDESTRIAN 3, ANIMAL 4.
    let enum_type = &mo.enum_type[0];
    let values: Vec<(&str, i32)> = enum_type
        .value
        .iter()
        .map(|v| (v.name(), v.number()))
        .collect();
    assert_eq!(
        values,
        [
            ("TYPE_UNKNOWN", 0),
            ("TYPE_OTHER", 1),
            ("TYPE_VEHICLE", 2),
            ("TYPE_PEDESTRIAN", 3),
            ("TYPE_ANIMAL", 4)
        ]
    );
}

#[test]
fn schema_is_proto2_with_imports_and_no_source_info() {
    let set = FileDescriptorSet::decode(osi::schema::GROUND_TRUTH_FILE_DESCRIPTOR_SET).unwrap();
    let names: Vec<&str> = set.file.iter().map(|f| f.name()).collect();
    // Dependencies first, as protoc --include_imports writes them.
    assert_eq!(names.last(), Some(&"osi_groundtruth.proto"));
    for file in [
        "osi_version.proto",
        "osi_common.proto",
        "osi_lane.proto",
        "osi_object.proto",
        "osi_trafficlight.proto",
        "osi_trafficsign.proto",
    ] {
        assert!(names.contains(&file), "{file}");
    }
    for f in &set.file {
        // descriptor.proto: `syntax` is "proto3" for proto3 files and unset (or "proto2")
        // for proto2 ones, as protoc writes it.
        assert!(matches!(f.syntax(), "" | "proto2"), "{}", f.name());
        assert!(f.source_code_info.is_none());
    }
    let gt = message(&set, "GroundTruth");
    let numbers: Vec<(&str, i32)> = gt.field.iter().map(|f| (f.name(), f.number())).collect();
    for expected in [
        ("version", 1),
        ("timestamp", 2),
        ("host_vehicle_id", 3),
        ("stationary_object", 4),
        ("moving_object", 5),
        ("traffic_sign", 6),
        ("traffic_light", 7),
        ("lane_boundary", 9),
        ("lane", 10),
        ("proj_string", 14),
        ("map_reference", 15),
        ("model_reference", 16),
    ] {
        assert!(numbers.contains(&expected), "{expected:?}");
    }
}

#[test]
fn protobuf_version_is_the_locked_prost() {
    let lock =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../Cargo.lock")).unwrap();
    let entry = lock
        .split("[[package]]")
        .find(|p| p.contains("name = \"prost\"\n"))
        .unwrap();
    assert!(
        entry.contains(&format!("version = \"{}\"", osi::version::PROTOBUF_VERSION)),
        "Cargo.lock prost entry: {entry}"
    );
}
