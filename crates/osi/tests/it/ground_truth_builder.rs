//! The run-level GroundTruth assembly on a corpus road (scene and closed forms in
//! `common/road_scene.rs`): traces written through `TraceFile` and read back, each
//! MovingObject compared with the entity state it came from; host vehicle and static
//! data rules.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use crate::common;

use approx::assert_relative_eq;
use common::road_scene;
use osi::ground_truth::StaticData;
use osi::osi3::GroundTruth;
use osi::trace::{McapTraceInfo, TraceFile, TraceFormat, TraceOptions};
use std::num::NonZeroU64;

const FRAMES: u64 = 50;
const TOL: f64 = 1e-9;

fn run(static_data: StaticData, host: Option<&str>) -> Vec<GroundTruth> {
    let (net, mut b) = road_scene::builder(static_data);
    b.set_host(host);
    (0..FRAMES)
        .map(|k| road_scene::frame(&net, &mut b, k))
        .collect()
}

fn id(gt: &GroundTruth, name: &str) -> u64 {
    gt.moving_object
        .iter()
        .find(|m| m.source_reference[0].identifier[1] == name)
        .and_then(|m| m.id?.value)
        .unwrap()
}

fn check(frames: &[GroundTruth]) {
    assert_eq!(frames.len() as u64, FRAMES);
    // Lanes of the first frame, by (road, lane) from their OpenDRIVE source reference.
    let lane_of = |lane: &str| {
        frames[0]
            .lane
            .iter()
            .find(|l| l.source_reference[0].identifier[2] == lane)
            .and_then(|l| l.id?.value)
            .unwrap()
    };
    let (lane_right, lane_left) = (lane_of("-1"), lane_of("1"));
    for (k, gt) in frames.iter().enumerate() {
        let t = k as f64 * 0.1;
        assert_eq!(gt.version, Some(osi::version::interface_version()));
        let ts = gt.timestamp.unwrap();
        assert_eq!(
            ts.seconds.unwrap() as u64 * 1_000_000_000 + u64::from(ts.nanos.unwrap()),
            k as u64 * road_scene::STEP_NANOS
        );
        assert_eq!(
            gt.host_vehicle_id.and_then(|h| h.value),
            Some(id(gt, "Ego"))
        );
        let expected = [
            (
                "Ego",
                [11.4 + 20.0 * t, -1.535, 0.75],
                [20.0, 0.0, 0.0],
                lane_right,
            ),
            (
                "Target",
                [398.6 - 15.0 * t, 1.535, 0.75],
                [-15.0, 0.0, 0.0],
                lane_left,
            ),
        ];
        for (name, p, v, lane) in expected {
            let mo = gt
                .moving_object
                .iter()
                .find(|m| m.source_reference[0].identifier[1] == name)
                .unwrap();
            let base = mo.base.as_ref().unwrap();
            let pos = base.position.unwrap();
            assert_relative_eq!(pos.x.unwrap(), p[0], epsilon = TOL);
            assert_relative_eq!(pos.y.unwrap(), p[1], epsilon = TOL);
            assert_relative_eq!(pos.z.unwrap(), p[2], epsilon = TOL);
            let vel = base.velocity.unwrap();
            assert_relative_eq!(vel.x.unwrap(), v[0], epsilon = TOL);
            assert_relative_eq!(vel.y.unwrap(), v[1], epsilon = TOL);
            let lanes = &mo
                .moving_object_classification
                .as_ref()
                .unwrap()
                .assigned_lane_id;
            assert_eq!(
                lanes.iter().map(|l| l.value.unwrap()).collect::<Vec<_>>(),
                [lane]
            );
            assert_eq!(
                mo.id.unwrap().value.unwrap(),
                id(&frames[0], name),
                "stable id"
            );
        }
    }
}

#[test]
fn traces_on_a_corpus_road_match_the_entity_states() {
    let frames = run(StaticData::First, None);
    assert!(!frames[0].lane.is_empty() && !frames[0].lane_boundary.is_empty());
    assert!(frames[1..]
        .iter()
        .all(|f| f.lane.is_empty() && f.lane_boundary.is_empty()));
    assert!(frames[0]
        .proj_string
        .as_deref()
        .unwrap()
        .starts_with("+proj=utm"));
    assert_eq!(
        frames[0].map_reference.as_deref(),
        Some("straight_500m.xodr")
    );
    check(&frames);

    let tmp = common::temp_dir("builder-traces");
    let dir = tmp.path();
    for format in [TraceFormat::Osi, TraceFormat::Mcap] {
        let options = TraceOptions {
            scenario_name: "road_scene".into(),
            directory_format: format,
            every: NonZeroU64::new(1).unwrap(),
            start_unix_seconds: 0,
            mcap_info: McapTraceInfo::default(),
        };
        let mut trace = TraceFile::create(dir, options).unwrap();
        for gt in &frames {
            trace.offer(gt).unwrap();
        }
        let path = trace.finish().unwrap();
        let back = common::read_back(&path);
        assert_eq!(back, frames);
        check(&back);
    }
}

#[test]
fn static_every_repeats_the_lanes() {
    let frames = run(StaticData::Every, None);
    assert!(frames.iter().all(|f| f.lane == frames[0].lane));
    assert!(!frames[FRAMES as usize - 1].lane.is_empty());
}

#[test]
fn host_vehicle_by_name_or_none() {
    let frames = run(StaticData::First, Some("Target"));
    assert_eq!(
        frames[3].host_vehicle_id.and_then(|h| h.value),
        Some(id(&frames[3], "Target"))
    );
    let frames = run(StaticData::First, Some("Nobody"));
    assert!(frames.iter().all(|f| f.host_vehicle_id.is_none()));
}

#[test]
fn header_offset_becomes_proj_frame_offset() {
    // A one-road network whose header carries <geoReference> and <offset>; OSI 3.8
    // GroundTruth.proj_frame_offset takes x, y, z as position and hdg as yaw.
    let xodr = r#"<?xml version="1.0"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="6">
    <geoReference><![CDATA[+proj=utm +zone=32 +ellps=WGS84]]></geoReference>
    <offset x="500000.0" y="5400000.0" z="12.5" hdg="0.25"/>
  </header>
  <road id="7" length="50" junction="-1">
    <planView><geometry s="0" x="0" y="0" hdg="0" length="50"><line/></geometry></planView>
    <lanes><laneSection s="0">
      <center><lane id="0" type="none" level="false"/></center>
      <right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
    </laneSection></lanes>
  </road>
</OpenDRIVE>"#;
    let net = opendrive::RoadNetwork::from_str(xodr, std::path::Path::new("offset.xodr")).unwrap();
    let mut b = osi::ground_truth::GroundTruthBuilder::new(StaticData::First);
    b.set_road_network(
        &net,
        Some("offset.xodr"),
        &osi::polyline::Sampling::default(),
    )
    .unwrap();
    b.set_model_reference(Some("scene.osgb"));
    let gt = b.begin_frame(0).finish();
    let offset = gt.proj_frame_offset.unwrap();
    let p = offset.position.unwrap();
    assert_eq!(
        (p.x, p.y, p.z),
        (Some(500000.0), Some(5400000.0), Some(12.5))
    );
    assert_eq!(offset.yaw, Some(0.25));
    assert_eq!(
        gt.proj_string.as_deref(),
        Some("+proj=utm +zone=32 +ellps=WGS84")
    );
    assert_eq!(gt.model_reference.as_deref(), Some("scene.osgb"));
    // One lane (−1) with two boundaries (centre line, outer border); 50 m straight at
    // ≤ 10 m steps: 6 points each.
    assert_eq!(gt.lane.len(), 1);
    assert_eq!(gt.lane_boundary.len(), 2);
    let centre = &gt.lane[0].classification.as_ref().unwrap().centerline;
    assert_eq!(centre.len(), 6);
    assert_relative_eq!(centre[5].x.unwrap(), 50.0, epsilon = 1e-12);
    assert_relative_eq!(centre[5].y.unwrap(), -1.75, epsilon = 1e-12);
}
