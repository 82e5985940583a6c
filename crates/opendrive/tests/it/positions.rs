//! (road, s, t) and (road, lane, s, offset) → pose on small hand-made roads, against closed
//! forms written out in each test (OpenDRIVE 1.8 §8.3 reference-line frame, §9.5 arc, §10.5
//! elevation and superelevation, §11.4 lane offset, §11.6 lane width and height).

use std::f64::consts::{FRAC_PI_2, PI};
use std::path::Path;

use opendrive::{Pose, RoadNetwork};

/// A one-road network: `curve` on a 200 m geometry starting at the origin heading +x, with the
/// given extra road children and right lanes.
fn road(curve: &str, profiles: &str, right_lanes: &str) -> RoadNetwork {
    let text = format!(
        r#"<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="r" length="200" junction="-1">
  <planView><geometry s="0" x="0" y="0" hdg="0" length="200">{curve}</geometry></planView>
  {profiles}
  <lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
  <right>{right_lanes}</right></laneSection></lanes>
</road></OpenDRIVE>"#
    );
    RoadNetwork::from_str(&text, Path::new("positions.xodr")).unwrap_or_else(|e| panic!("{e}"))
}

const LANE_4M: &str =
    r#"<lane id="-1" type="driving"><width sOffset="0" a="4" b="0" c="0" d="0"/></lane>"#;

#[test]
fn lane_centre_on_a_quarter_circle() {
    // Arc κ = 0.01 (R = 100) turning left from (0, 0): centre of curvature (0, 100). At
    // s = 50π, φ = π/2; lane −1 (4 m) has its centre at t = −2, i.e. radius 102:
    // ((R + 2)·sin φ, R − (R + 2)·cos φ) = (102, 100), heading π/2.
    let net = road(r#"<arc curvature="0.01"/>"#, "", LANE_4M);
    let p = net
        .lane_pose("r", -1, 50.0 * PI, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    let expected = Pose {
        x: 102.0,
        y: 100.0,
        z: 0.0,
        h: FRAC_PI_2,
        p: 0.0,
        r: 0.0,
    };
    approx::assert_abs_diff_eq!(p, expected, epsilon = 1e-9);
    // 0.5 m left of the lane centre is t = −1.5: radius 101.5.
    let q = net
        .lane_pose("r", -1, 50.0 * PI, 0.5)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        (q.x - 101.5).abs() < 1e-9 && (q.y - 100.0).abs() < 1e-9,
        "{q:?}"
    );
    assert!((net.lane_width("r", -1, 10.0).unwrap_or(0.0) - 4.0).abs() < 1e-15);
}

#[test]
fn widening_lane_on_an_arc_has_the_true_tangent_heading() {
    // Lane −1 width w = 3 + 0.01·s on the arc κ = 0.01: t = −w/2, dt/ds = −0.005. The centre
    // curve's tangent is (1 − κt)·T + (dt/ds)·N, so h = s·κ + atan2(−0.005, 1 + 0.01·w/2).
    // At s = 100: w = 4, h = 1 + atan2(−0.005, 1.02).
    let lane =
        r#"<lane id="-1" type="driving"><width sOffset="0" a="3" b="0.01" c="0" d="0"/></lane>"#;
    let net = road(r#"<arc curvature="0.01"/>"#, "", lane);
    let p = net
        .lane_pose("r", -1, 100.0, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        (p.h - (1.0 + (-0.005_f64).atan2(1.02))).abs() < 1e-12,
        "{p:?}"
    );
    // The same direction from the positions themselves (central difference, error O(h²)).
    let a = net
        .lane_pose("r", -1, 100.0 - 1e-4, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    let b = net
        .lane_pose("r", -1, 100.0 + 1e-4, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(((b.y - a.y).atan2(b.x - a.x) - p.h).abs() < 1e-8);
    let span = net
        .lane_boundaries("r", -1, 100.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        span.inner.abs() < 1e-15
            && (span.outer + 4.0).abs() < 1e-12
            && (span.d_outer + 0.01).abs() < 1e-15
    );
}

#[test]
fn elevation_gives_z_and_pitch() {
    // z(s) = 1 + 0.05·s: at s = 20, z = 2 and pitch = −atan(0.05) (nose up on a climb is
    // negative pitch, OpenDRIVE 1.8 §8: positive pitch turns +x towards −z).
    let net = road(
        "<line/>",
        r#"<elevationProfile><elevation s="0" a="1" b="0.05" c="0" d="0"/></elevationProfile>"#,
        LANE_4M,
    );
    let p = net
        .road_pose("r", 20.0, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        (p.z - 2.0).abs() < 1e-12 && (p.p + 0.05_f64.atan()).abs() < 1e-15,
        "{p:?}"
    );
}

#[test]
fn superelevation_tilts_the_cross_section() {
    // Roll 0.1 rad (right side down) on a straight road: the point t = −2 (lane −1 centre) lies
    // at y = −2·cos 0.1, z = −2·sin 0.1 (t is measured in the tilted cross-section, §10.5).
    let net = road(
        "<line/>",
        r#"<lateralProfile><superelevation s="0" a="0.1" b="0" c="0" d="0"/></lateralProfile>"#,
        LANE_4M,
    );
    let p = net
        .lane_pose("r", -1, 50.0, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!((p.x - 50.0).abs() < 1e-12, "{p:?}");
    assert!(
        (p.y + 2.0 * 0.1_f64.cos()).abs() < 1e-12 && (p.z + 2.0 * 0.1_f64.sin()).abs() < 1e-12,
        "{p:?}"
    );
    assert!((p.r - 0.1).abs() < 1e-15);
}

#[test]
fn lane_offset_and_lane_height() {
    // A sidewalk −2 (2 m, height 0.15 m) beyond lane −1 (4 m): centre t = −4 − 1 = −5, z = 0.15.
    // With laneOffset 0.5 + 0.01·s every lane moves left; at s = 50 the offset is 1.0, so the
    // sidewalk centre is at t = −4.
    let lanes = format!(
        r#"{LANE_4M}<lane id="-2" type="sidewalk"><width sOffset="0" a="2" b="0" c="0" d="0"/><height sOffset="0" inner="0.15" outer="0.15"/></lane>"#
    );
    let net = road("<line/>", "", &lanes);
    let p = net
        .lane_pose("r", -2, 50.0, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        (p.y + 5.0).abs() < 1e-12 && (p.z - 0.15).abs() < 1e-12,
        "{p:?}"
    );
    let with_offset = {
        let text = format!(
            r#"<OpenDRIVE><header/><road id="r" length="200" junction="-1">
  <planView><geometry s="0" x="0" y="0" hdg="0" length="200"><line/></geometry></planView>
  <lanes><laneOffset s="0" a="0.5" b="0.01" c="0" d="0"/><laneSection s="0"><center><lane id="0" type="none"/></center>
  <right>{lanes}</right></laneSection></lanes></road></OpenDRIVE>"#
        );
        RoadNetwork::from_str(&text, Path::new("offset.xodr")).unwrap_or_else(|e| panic!("{e}"))
    };
    let q = with_offset
        .lane_pose("r", -2, 50.0, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        (q.y + 4.0).abs() < 1e-12 && (q.z - 0.15).abs() < 1e-12,
        "{q:?}"
    );
    // Lane 0 is the centre lane at the offset: t = 1.0.
    let c = with_offset
        .lane_pose("r", 0, 50.0, 0.0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!((c.y - 1.0).abs() < 1e-12);
    // Heading of the centre lane: atan(d offset/ds) = atan(0.01) on a straight road.
    assert!((c.h - 0.01_f64.atan()).abs() < 1e-15);
}

#[test]
fn network_can_be_shared_between_threads() {
    // Simulations run in parallel on one loaded network: it must be Send + Sync.
    fn shared<T: Send + Sync>(_: &T) {}
    let net = road("<line/>", "", LANE_4M);
    shared(&net);
    let p = std::thread::scope(|sc| sc.spawn(|| net.road_pose("r", 1.0, 0.0)).join());
    assert!(p.is_ok_and(|p| p.is_ok_and(|p| (p.x - 1.0).abs() < 1e-15)));
}

#[test]
fn round_trip_at_georeferenced_coordinates() {
    // UTM-sized coordinates (the OpenDRIVE 1.8 §9.6 example sits at x ≈ 6.8e5, y ≈ 5.4e6): f64
    // resolves about 1e-9 m there, and the round trip must still hold to 1e-6 m.
    let text = r#"<OpenDRIVE><header/><road id="g" length="65.65893957370" junction="-1"><planView>
<geometry s="0" x="6.804539427645e+05" y="5.422483642942e+06" hdg="5.287405485081e+00" length="6.565893957370e+01">
<paramPoly3 aU="0" bU="1" cU="-4.666602734948e-09" dU="-2.629787927644e-08" aV="0" bV="1.665334536938e-16"
 cV="-1.987729787588e-04" dV="-1.317158625579e-09" pRange="arcLength"/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>
<lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes>
</road></OpenDRIVE>"#;
    let net = RoadNetwork::from_str(text, Path::new("utm.xodr")).unwrap_or_else(|e| panic!("{e}"));
    for s in [0.0, 10.0, 33.3, 65.0] {
        let p = net
            .lane_pose("g", -1, s, 0.3)
            .unwrap_or_else(|e| panic!("{e}"));
        let found = net
            .locate(p.x, p.y, Some(p.h))
            .unwrap_or_else(|| panic!("not found"));
        let back = net
            .road_pose("g", found.s, found.t)
            .unwrap_or_else(|e| panic!("{e}"));
        assert!((back.x - p.x).hypot(back.y - p.y) < 1e-6, "{found:?}");
        assert!(
            (found.s - s).abs() < 1e-6 && found.lane_id == -1 && (found.offset - 0.3).abs() < 1e-6,
            "{found:?}"
        );
    }
}

#[test]
fn lane_heading_on_a_banked_curve_is_the_horizontal_tangent() {
    // Arc κ = 0.01 with roll growing 0 → 0.2 rad over 100 m and a widening lane: the heading
    // must equal the direction of the lane centre's horizontal track (central difference of
    // positions, O(h²) ≈ 1e-9 here).
    let lane =
        r#"<lane id="-1" type="driving"><width sOffset="0" a="3" b="0.02" c="0" d="0"/></lane>"#;
    let net = road(
        r#"<arc curvature="0.01"/>"#,
        r#"<lateralProfile><superelevation s="0" a="0" b="0.002" c="0" d="0"/></lateralProfile>"#,
        lane,
    );
    for s in [10.0, 50.0, 90.0] {
        let p = net
            .lane_pose("r", -1, s, 0.0)
            .unwrap_or_else(|e| panic!("{e}"));
        let a = net
            .lane_pose("r", -1, s - 1e-4, 0.0)
            .unwrap_or_else(|e| panic!("{e}"));
        let b = net
            .lane_pose("r", -1, s + 1e-4, 0.0)
            .unwrap_or_else(|e| panic!("{e}"));
        let track = (b.y - a.y).atan2(b.x - a.x);
        assert!((track - p.h).abs() < 1e-8, "s {s}: {} vs {}", p.h, track);
    }
}
