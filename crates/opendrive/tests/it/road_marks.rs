//! `<roadMark>` records (OpenDRIVE 1.8 §11.8) read from the bundled highway and from text.

use std::path::Path;

use opendrive::{ErrorKind, RoadMarkColor, RoadMarkLaneChange, RoadMarkType, RoadNetwork};

#[test]
fn highway_marks_are_read_with_their_dash_pattern() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/roads/highway.xodr"
    ));
    let net = RoadNetwork::from_file(path).unwrap_or_else(|e| panic!("{e}"));
    let section = &net
        .road("0")
        .expect("road 0 is in highway.xodr")
        .lane_sections[0];
    // highway.xodr road 0, laneSection s=0: centre lane solid 0.2 m; lane -1 broken with
    // <line length="3" space="9" width="0.15">; lane -3 (outermost right) solid.
    let centre = &section.center.road_marks;
    assert_eq!(centre.len(), 1);
    assert_eq!(centre[0].mark_type, RoadMarkType::Solid);
    assert_eq!(centre[0].color, RoadMarkColor::Standard);
    assert_eq!(centre[0].width, Some(0.2));
    assert!(!centre[0].bold);
    let broken = &section.lane(-1).expect("lane -1").road_marks[0];
    assert_eq!(broken.mark_type, RoadMarkType::Broken);
    assert_eq!(broken.lines.len(), 1);
    assert_eq!(broken.lines[0].length, 3.0);
    assert_eq!(broken.lines[0].space, 9.0);
    assert_eq!(broken.lines[0].width, Some(0.15));
    let edge = &section.lane(-3).expect("lane -3").road_marks[0];
    assert_eq!(edge.mark_type, RoadMarkType::Solid);
}

const ROAD: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="1" length="100" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none">
MARKS
</lane></center></laneSection></lanes></road></OpenDRIVE>"#;

fn load(marks: &str) -> Result<RoadNetwork, opendrive::Error> {
    RoadNetwork::from_str(&ROAD.replace("MARKS", marks), Path::new("marks.xodr"))
}

#[test]
fn marks_are_sorted_by_s_offset_and_unknown_values_kept() {
    let net = load(
        r#"<roadMark sOffset="60" type="solid solid" color="yellow" weight="bold"/>
           <roadMark sOffset="0" type="zigzag" color="pink"/>"#,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let marks = &net.road("1").expect("road 1").lane_sections[0]
        .center
        .road_marks;
    assert_eq!(marks[0].s_offset, 0.0);
    assert_eq!(marks[0].mark_type, RoadMarkType::Other("zigzag".into()));
    assert_eq!(marks[0].color, RoadMarkColor::Other("pink".into()));
    assert_eq!(marks[1].s_offset, 60.0);
    assert_eq!(marks[1].mark_type, RoadMarkType::SolidSolid);
    assert_eq!(marks[1].color, RoadMarkColor::Yellow);
    assert!(marks[1].bold);
    assert_eq!(marks[1].width, None);
}

#[test]
fn a_negative_dash_length_is_an_error_at_its_attribute() {
    let err = load(r#"<roadMark sOffset="0" type="broken"><type name="b"><line length="-3" space="9"/></type></roadMark>"#)
        .expect_err("a dash of -3 m is refused");
    assert!(
        matches!(err.kind(), ErrorKind::InvalidValue { attribute, .. } if attribute == "length")
    );
    // The MARKS line is the fifth line of ROAD.
    let text = err.to_string();
    assert!(text.contains("marks.xodr:5:"), "{text}");
}

#[test]
fn names_read_back_as_parsed() {
    for text in [
        "none",
        "solid",
        "broken",
        "solid solid",
        "solid broken",
        "broken solid",
        "broken broken",
        "botts dots",
        "grass",
        "curb",
        "custom",
        "edge",
        "zigzag",
    ] {
        assert_eq!(RoadMarkType::parse(text).name(), text);
    }
    for text in ["driving", "shoulder", "onRamp", "HOV", "special1"] {
        assert_eq!(opendrive::LaneType::parse(text).name(), text);
    }
}

/// A road with three right lanes whose borders carry `MARK1` (lane −1's outer border, between
/// −1 and −2) and `MARK2` (between −2 and −3), and the centre line `MARK0`.
const THREE_LANES: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="1" length="100" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none">MARK0</lane></center><right>
<lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>MARK1</lane>
<lane id="-2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>MARK2</lane>
<lane id="-3" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
</right></laneSection></lanes></road></OpenDRIVE>"#;

fn section(marks: [&str; 3]) -> opendrive::LaneSection {
    let text = THREE_LANES
        .replace("MARK0", marks[0])
        .replace("MARK1", marks[1])
        .replace("MARK2", marks[2]);
    let net =
        RoadNetwork::from_str(&text, Path::new("three.xodr")).unwrap_or_else(|e| panic!("{e}"));
    net.road("1").expect("road 1").lane_sections[0].clone()
}

/// OpenDRIVE 1.8 §11.8: `laneChange` allows a change "in the indicated direction, taking into
/// account that lanes are numbered in ascending order from right to left": on lane −1's outer
/// border, `increase` lets −2 → −1 (towards the larger id) and refuses −1 → −2.
#[test]
fn lane_change_attribute_gives_the_direction() {
    let s = section([
        "",
        r#"<roadMark sOffset="0" type="solid" laneChange="increase"/>"#,
        r#"<roadMark sOffset="0" type="broken" laneChange="none"/>"#,
    ]);
    assert!(s.permits_lane_change(-2, -1, 10.0));
    assert!(!s.permits_lane_change(-1, -2, 10.0));
    // `none` wins over the broken paint.
    assert!(!s.permits_lane_change(-2, -3, 10.0));
    assert!(!s.permits_lane_change(-3, -2, 10.0));
    assert_eq!(
        s.lane(-1).expect("lane -1").road_marks[0].lane_change,
        Some(RoadMarkLaneChange::Increase)
    );
}

/// Without `laneChange` the paint decides (oscsim's reading, RoadMark::permits_lane_change):
/// broken crosses both ways, solid neither; `solid broken` on lane −1's border has its solid
/// line on the inside (lane −1's side), so −2 → −1 (from the broken side) is allowed and
/// −1 → −2 is not; a mark applies from its sOffset on.
#[test]
fn paint_decides_without_the_attribute() {
    let s = section([
        "",
        r#"<roadMark sOffset="0" type="solid broken"/>"#,
        r#"<roadMark sOffset="0" type="broken"/><roadMark sOffset="50" type="solid"/>"#,
    ]);
    assert!(s.permits_lane_change(-2, -1, 10.0));
    assert!(!s.permits_lane_change(-1, -2, 10.0));
    assert!(s.permits_lane_change(-2, -3, 49.9));
    assert!(s.permits_lane_change(-3, -2, 49.9));
    assert!(!s.permits_lane_change(-2, -3, 50.0));
    assert!(!s.permits_lane_change(-3, -2, 50.0));
    // `broken solid` the other way round.
    let s = section(["", r#"<roadMark sOffset="0" type="broken solid"/>"#, ""]);
    assert!(s.permits_lane_change(-1, -2, 10.0));
    assert!(!s.permits_lane_change(-2, -1, 10.0));
    // No mark at all: permitted.
    assert!(s.permits_lane_change(-2, -3, 10.0));
}

#[test]
fn an_unknown_lane_change_value_is_an_error_at_its_attribute() {
    let err = load(r#"<roadMark sOffset="0" type="broken" laneChange="left"/>"#)
        .expect_err("laneChange=left is refused");
    assert!(
        matches!(err.kind(), ErrorKind::InvalidValue { attribute, found, .. }
            if attribute == "laneChange" && found == "left")
    );
    let text = err.to_string();
    assert!(text.contains("marks.xodr:5:"), "{text}");
    assert!(text.contains("increase, decrease, both or none"), "{text}");
}
