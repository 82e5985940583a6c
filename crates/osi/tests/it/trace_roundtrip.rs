//! Traces written and read back: `.osi` (OSI 3.8 §2.2.6.1.1) and `.mcap`
//! (§2.2.6.1.2), compared field by field with the frames written, and each moving
//! object compared with the entity state it was made from (hand formulas in
//! `common/mod.rs`).
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use crate::common;

use approx::assert_relative_eq;
use osi::osi3::moving_object::Type as MovingType;
use osi::osi3::GroundTruth;
use osi::trace::{
    read_mcap, read_osi, McapTraceInfo, McapTraceWriter, OsiFileWriter, TraceFile, TraceFormat,
    TraceOptions, TraceWriter,
};
use std::num::NonZeroU64;

const FRAMES: usize = 40;
const VEHICLES: usize = 3;
const TOL: f64 = 1e-9;

/// Checks each frame against the scene's closed form.
fn check_against_entity_state(frames: &[GroundTruth]) {
    let lane_ids: Vec<u64> = frames[0]
        .lane
        .iter()
        .map(|l| l.id.as_ref().and_then(|i| i.value).unwrap())
        .collect();
    assert_eq!(lane_ids.len(), 2);
    let first_ids: Vec<_> = frames[0].moving_object.iter().map(|m| m.id).collect();
    for (k, gt) in frames.iter().enumerate() {
        let t = common::frame_time(k);
        assert_eq!(gt.moving_object.len(), VEHICLES + 1);
        // Ids are stable: the same object order and ids in every frame.
        let ids: Vec<_> = gt.moving_object.iter().map(|m| m.id).collect();
        assert_eq!(ids, first_ids, "frame {k}");
        assert_eq!(gt.host_vehicle_id, first_ids[0]);
        for (i, mo) in gt.moving_object.iter().take(VEHICLES).enumerate() {
            assert_eq!(mo.r#type, Some(MovingType::Vehicle as i32));
            let base = mo.base.as_ref().unwrap();
            let p = base.position.as_ref().unwrap();
            // Bounding-box centre = reference point + (1.4, 0, 0.75) at yaw 0.
            let x = 6.4 + 30.0 * i as f64 + common::vehicle_speed(i) * t;
            assert_relative_eq!(p.x.unwrap(), x, epsilon = TOL);
            assert_relative_eq!(p.y.unwrap(), -1.75, epsilon = TOL);
            assert_relative_eq!(p.z.unwrap(), 0.75, epsilon = TOL);
            let v = base.velocity.as_ref().unwrap();
            assert_relative_eq!(v.x.unwrap(), common::vehicle_speed(i), epsilon = TOL);
            assert_relative_eq!(v.y.unwrap(), 0.0, epsilon = TOL);
            let rear = mo
                .vehicle_attributes
                .as_ref()
                .and_then(|a| a.bbcenter_to_rear.as_ref())
                .unwrap();
            assert_relative_eq!(rear.x.unwrap(), -1.4, epsilon = TOL);
            assert_relative_eq!(rear.z.unwrap(), -0.75, epsilon = TOL);
            // Lane: lane −1 of road 0, an id of the first frame's lanes.
            let lanes = &mo
                .moving_object_classification
                .as_ref()
                .unwrap()
                .assigned_lane_id;
            assert_eq!(lanes.len(), 1);
            assert_eq!(lanes[0].value, Some(lane_ids[0]));
            #[allow(deprecated)] // checks that the deprecated field stays empty
            let old_lanes = &mo.assigned_lane_id;
            assert!(old_lanes.is_empty());
            let source = &mo.source_reference[0];
            assert_eq!(source.r#type.as_deref(), Some("net.asam.openscenario"));
            assert_eq!(
                source.identifier,
                vec!["Vehicle".to_string(), common::vehicle_name(i)]
            );
        }
        let walker = &gt.moving_object[VEHICLES];
        assert_eq!(walker.r#type, Some(MovingType::Pedestrian as i32));
        assert!(walker.pedestrian_attributes.is_some());
        let p = walker.base.as_ref().unwrap().position.as_ref().unwrap();
        // Pedestrian: reference (60, −6 + 1.5 t, 0), centre 0.9 m up.
        assert_relative_eq!(p.y.unwrap(), -6.0 + 1.5 * t, epsilon = TOL);
        assert_relative_eq!(p.z.unwrap(), 0.9, epsilon = TOL);
        // Unique ids across objects, lanes and boundaries of the frame.
        let mut all: Vec<u64> = gt
            .moving_object
            .iter()
            .filter_map(|m| m.id.as_ref()?.value)
            .chain(
                gt.stationary_object
                    .iter()
                    .filter_map(|s| s.id.as_ref()?.value),
            )
            .chain(gt.lane.iter().filter_map(|l| l.id.as_ref()?.value))
            .chain(gt.lane_boundary.iter().filter_map(|b| b.id.as_ref()?.value))
            .collect();
        let n = all.len();
        all.sort_unstable();
        all.dedup();
        assert_eq!(all.len(), n, "frame {k} repeats an id");
    }
}

#[test]
fn osi_file_round_trip() {
    let tmp = common::temp_dir("osi-round-trip");
    let dir = tmp.path();
    let path = dir.join("sample.osi");
    let frames = common::frames(FRAMES, VEHICLES);
    let mut writer = OsiFileWriter::create(&path).unwrap();
    for gt in &frames {
        writer.write(gt).unwrap();
    }
    writer.finish().unwrap();
    assert_eq!(writer.frames(), FRAMES as u64);

    let back = read_osi(&path).unwrap();
    assert_eq!(back, frames);
    check_against_entity_state(&back);

    // The file is exactly the frames, each after its 4-byte little-endian length.
    let bytes = std::fs::read(&path).unwrap();
    let first_len = u32::from_le_bytes(bytes[0..4].try_into().unwrap()) as usize;
    assert_eq!(first_len, prost::Message::encoded_len(&frames[0]));
    let total: usize = frames
        .iter()
        .map(|f| 4 + prost::Message::encoded_len(f))
        .sum();
    assert_eq!(bytes.len(), total);
}

#[test]
fn mcap_round_trip_with_osi_layout() {
    let tmp = common::temp_dir("mcap-round-trip");
    let dir = tmp.path();
    let path = dir.join("sample.mcap");
    let frames = common::frames(FRAMES, VEHICLES);
    let info = McapTraceInfo {
        creation_time: Some("2026-11-21T06:00:00Z".into()),
        description: Some("sample".into()),
        data_sources: Some("sample.xosc".into()),
    };
    let mut writer = McapTraceWriter::create(&path, &info).unwrap();
    for gt in &frames {
        writer.write(gt).unwrap();
    }
    writer.finish().unwrap();

    let trace = read_mcap(&path).unwrap();
    // OSI 3.8 §2.2.6.1.2: metadata net.asam.osi.trace with the five mandatory keys.
    for key in [
        "version",
        "min_osi_version",
        "max_osi_version",
        "min_protobuf_version",
        "max_protobuf_version",
    ] {
        assert!(trace.trace_metadata.contains_key(key), "{key}");
    }
    assert_eq!(trace.trace_metadata["min_osi_version"], "3.8.0");
    assert_eq!(
        trace.trace_metadata["creation_time"],
        "2026-11-21T06:00:00Z"
    );
    assert_eq!(
        trace.channel_metadata["net.asam.osi.trace.channel.osi_version"],
        "3.8.0"
    );
    assert!(trace
        .channel_metadata
        .contains_key("net.asam.osi.trace.channel.protobuf_version"));
    assert_eq!(trace.schema_encoding, "protobuf");
    assert_eq!(trace.message_encoding, "protobuf");
    assert_eq!(
        trace.schema_data,
        osi::schema::GROUND_TRUTH_FILE_DESCRIPTOR_SET
    );
    assert_eq!(trace.frames.len(), FRAMES);
    for (k, frame) in trace.frames.iter().enumerate() {
        // publish_time = the GroundTruth timestamp in ns = k · 50 ms.
        assert_eq!(frame.publish_time, k as u64 * common::STEP_NANOS);
        assert_eq!(frame.log_time, frame.publish_time);
        // Sequence counts from 1 (OSI 3.8 §2.2.6.1.2: 0 means "no reliable sequence").
        assert_eq!(frame.sequence, k as u32 + 1);
    }
    let back: Vec<GroundTruth> = trace.frames.into_iter().map(|f| f.ground_truth).collect();
    assert_eq!(back, frames);
    check_against_entity_state(&back);
}

#[test]
fn trace_file_in_a_directory_is_named_by_the_convention_and_thinned() {
    let tmp = common::temp_dir("trace-file-dir");
    let dir = tmp.path();
    let frames = common::frames(5, 1);
    for (format, ext) in [(TraceFormat::Osi, "osi"), (TraceFormat::Mcap, "mcap")] {
        let options = TraceOptions {
            scenario_name: "cut in".into(),
            directory_format: format,
            every: NonZeroU64::new(2).unwrap(),
            start_unix_seconds: 1_629_299_142,
            mcap_info: McapTraceInfo::default(),
        };
        let mut trace = TraceFile::create(dir, options).unwrap();
        for gt in &frames {
            trace.offer(gt).unwrap();
        }
        let path = trace.finish().unwrap();
        // Frames 0, 2, 4 of 5 offered: 3 frames.
        let expected = format!("20210818T150542Z_gt_380_0135_3_cut-in.{ext}");
        assert_eq!(path, dir.join(expected));
        let back = common::read_back(&path);
        assert_eq!(
            back,
            vec![frames[0].clone(), frames[2].clone(), frames[4].clone()]
        );
    }
    // No part file is left behind.
    let left: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".part"))
        .collect();
    assert!(left.is_empty());
}
