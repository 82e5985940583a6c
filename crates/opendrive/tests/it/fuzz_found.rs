//! Inputs the fuzzers found (fuzz/, docs/robustness.md), kept as regression tests: each test is
//! named after the bug; its input is in `tests/files/fuzz/` as the fuzzer wrote it, or written
//! out here where a few lines show the bug.

use std::path::Path;

use opendrive::RoadNetwork;

/// One straight road of `length` metres along +x with one 3 m lane either side.
fn straight_road(length: &str) -> String {
    format!(
        r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" junction="-1" length="{length}">
<planView><geometry s="0" x="0" y="0" hdg="0" length="{length}"><line/></geometry></planView>
<lanes><laneSection s="0">
<left><lane id="1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"#
    )
}

/// A road 37015911468935081 m long (a digit the fuzzer changed in `37.15911468935081`) was cut
/// into 10 m pieces for the spatial index: 3.7e15 pieces, a hang and then memory exhaustion.
/// Geometries over 100 km now get longer pieces (at most 10 000 each).
#[test]
fn road_length_4e16_hangs_index() {
    let text = straight_road("37015911468935081");
    let net = RoadNetwork::from_str(&text, Path::new("long.xodr")).unwrap();
    // The box spans the road: x from 0 to its length, y from −3 to 3 m (plus margins).
    let [x0, y0, x1, y1] = net.bounding_box().unwrap();
    assert!(x0 <= 0.0 && x1 >= 3.701_591_146_893_508e16, "{x0} {x1}");
    assert!(y0 <= -3.0 && y1 >= 3.0, "{y0} {y1}");
    // Halfway along, the lane −1 centre is 1.5 m right of the reference line.
    let p = net.lane_pose("1", -1, 1.85e16, 0.0).unwrap();
    assert_eq!(p.x, 1.85e16);
    assert!((p.y + 1.5).abs() < 1e-9, "{}", p.y);
    // Located back onto lane −1 of road 1.
    let found = net.locate(1.85e16, -1.5, None).unwrap();
    assert_eq!((found.road_id.as_str(), found.lane_id), ("1", -1));

    // The fuzzer's file (six roads, one of them that long) loads too.
    let found = include_str!("../files/fuzz/road_length_4e16_hangs_index.xodr");
    let net = RoadNetwork::from_str(found, Path::new("found.xodr")).unwrap();
    assert_eq!(net.roads().len(), 6);
}
