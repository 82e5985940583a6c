//! Bad input never panics: each fixture `tests/files/NAME.xodr` must fail to load with exactly
//! the message in `tests/files/NAME.err` (kind, attribute or element, what was expected, and
//! `file:row:col`). Query errors on a loaded network follow.

use std::path::Path;

use opendrive::{ErrorKind, RoadNetwork};

fn files() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files"))
}

/// Loads `NAME.xodr` (named by its bare file name in messages) and returns the error text.
fn load_error(name: &str) -> String {
    let text = std::fs::read_to_string(files().join(format!("{name}.xodr")))
        .unwrap_or_else(|e| panic!("fixture {name}: {e}"));
    match RoadNetwork::from_str(&text, Path::new(&format!("{name}.xodr"))) {
        Ok(_) => panic!("{name}.xodr loaded but should fail"),
        Err(e) => {
            assert!(
                e.pos().is_some_and(|p| p.line >= 1 && p.col >= 1),
                "{name}: no position in {e}"
            );
            e.to_string()
        }
    }
}

macro_rules! error_case {
    ($name:ident) => {
        #[test]
        fn $name() {
            let name = stringify!($name);
            let expected = std::fs::read_to_string(files().join(format!("{name}.err")))
                .unwrap_or_else(|e| panic!("expected-error file {name}.err: {e}"));
            assert_eq!(load_error(name), expected.trim_end());
        }
    };
}

error_case!(malformed_xml);
error_case!(missing_attribute);
error_case!(bad_number);
error_case!(negative_length);
error_case!(zero_road_length);
error_case!(nan_value);
error_case!(infinite_value);
error_case!(unknown_road);
error_case!(unknown_junction);
error_case!(unknown_connecting_road);
error_case!(empty_plan_view);
error_case!(lane_section_beyond_end);
error_case!(not_opendrive);
error_case!(missing_curve);
error_case!(bad_lane_id);
error_case!(bad_contact_point);

#[test]
fn valid_minimal_fixture_loads() {
    // The base the failing fixtures are cut from must itself load, so each failure above is
    // due to its one change.
    let net = RoadNetwork::from_file(&files().join("valid_minimal.xodr"))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(net.roads().len(), 1);
    assert!(net.warnings().is_empty());
}

#[test]
fn unknown_lane_in_a_lane_link_is_a_warning_with_position() {
    // Junction lane links naming a missing lane occur in the corpus (road_merge0.xodr), so they
    // load with a warning that carries the position; the lane graph ignores the link.
    let net = RoadNetwork::from_file(&files().join("unknown_lane_link.xodr"))
        .unwrap_or_else(|e| panic!("{e}"));
    let w: Vec<String> = net.warnings().iter().map(ToString::to_string).collect();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].starts_with(
            "expected an existing lane of road 1 for `to` of <laneLink>, found \"-3\" at "
        ) && w[0].ends_with("unknown_lane_link.xodr:26:37"),
        "{}",
        w[0]
    );
}

#[test]
fn geometry_gap_is_a_warning_with_position() {
    // The second line starts at (50, 0.5) where the first ends at (50, 0): a 0.5 m gap.
    let net = RoadNetwork::from_file(&files().join("geometry_gap.xodr"))
        .unwrap_or_else(|e| panic!("{e}"));
    let w: Vec<String> = net.warnings().iter().map(ToString::to_string).collect();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].starts_with("expected a start within 0.001 m of the previous geometry's end in <geometry>, found a gap of 0.5000 m at ")
            && w[0].ends_with("geometry_gap.xodr:10:13"),
        "{}",
        w[0]
    );
}

#[test]
fn missing_file_is_an_io_error_naming_the_file() {
    let err = RoadNetwork::from_file(Path::new("no/such/file.xodr"))
        .err()
        .map(|e| e.to_string());
    let err = err.unwrap_or_default();
    assert!(
        err.starts_with("cannot read file: ") && err.contains("no/such/file.xodr"),
        "{err}"
    );
}

#[test]
fn queries_on_unknown_roads_lanes_and_s_fail_cleanly() {
    let net = RoadNetwork::from_file(&files().join("valid_minimal.xodr"))
        .unwrap_or_else(|e| panic!("{e}"));
    let e = net.road_pose("9", 1.0, 0.0).err().map(|e| e.kind().clone());
    assert_eq!(e, Some(ErrorKind::NoSuchRoad("9".into())));
    let e = net.lane_pose("1", 2, 1.0, 0.0).err().map(|e| e.to_string());
    assert_eq!(
        e.as_deref(),
        Some("expected an existing lane, found lane 2 on road \"1\" at s = 1")
    );
    let e = net.road_pose("1", 100.5, 0.0).err().map(|e| e.to_string());
    assert_eq!(
        e.as_deref(),
        Some("expected s in [0, 100] on road \"1\", found 100.5")
    );
    assert!(net.road_pose("1", f64::NAN, 0.0).is_err());
    assert!(net.lane_width("1", -1, f64::INFINITY).is_err());
    assert!(net.locate(f64::NAN, 0.0, None).is_none());
    assert!(net.locate_on_road("9", 0.0, 0.0).is_none());
    // s within S_TOLERANCE past the end is clamped onto the end: (100, −1.75).
    let p = net
        .lane_pose("1", -1, 100.0 + 5e-7, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!((p.x - 100.0).abs() < 1e-12 && (p.y + 1.75).abs() < 1e-12);
}

#[test]
fn truncated_and_garbage_input_never_panics() {
    // Every prefix of a valid file either loads or fails with a positioned error.
    let text = std::fs::read_to_string(files().join("valid_minimal.xodr")).unwrap_or_default();
    for cut in (0..text.len()).step_by(7) {
        if let Err(e) = RoadNetwork::from_str(&text[..cut], Path::new("cut.xodr")) {
            assert!(e.pos().is_some(), "{e}");
        }
    }
    for junk in [
        "",
        "<",
        "<OpenDRIVE/>",
        "\u{0}\u{1}",
        "<?xml version=\"1.0\"?><OpenDRIVE><road/></OpenDRIVE>",
    ] {
        let _ = RoadNetwork::from_str(junk, Path::new("junk.xodr"));
    }
}
