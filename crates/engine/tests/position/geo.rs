//! GeoPosition (OpenSCENARIO 1.3 XSD `GeoPosition`, latitudeDeg/longitudeDeg in WGS 84) through
//! the road network's georeference (OpenDRIVE 1.8 §8.5: PROJ string, then `<offset>`).
//!
//! Expected x, y come from an independent implementation: pyproj 3.7.2 on PROJ 9.5.1,
//! `pyproj.Proj(GEOREFERENCE)(lon, lat)`, not from oscsim's projection crate. The two agree to
//! about 0.1 mm (PROJ's `utm` is the extended transverse Mercator; proj4rs follows it); the
//! issue asks for 1 cm.

use crate::condition_support;

use condition_support::{at, corpus_road, orientation, FakeWorld};
use engine::position::{resolve, PositionErrorKind};
use opendrive::{GeoTransform, RoadNetwork};
use scenario::PositionKind;

/// The 1 cm of the issue.
const GEO_TOL: f64 = 0.01;

fn geo(latitude_deg: f64, longitude_deg: f64) -> scenario::Position {
    at(PositionKind::Geo {
        latitude_deg,
        longitude_deg,
        altitude: None,
        vertical_road_selection: None,
        orientation: None,
    })
}

fn offset_network() -> RoadNetwork {
    let path = crate::corpus::fixture("position/geo_utm32_offset.xodr");
    RoadNetwork::from_file(&path).expect("fixture loads")
}

/// esmini's straight_500m.xodr carries a UTM zone 32 PROJ string (with `+lat_0`/`+lon_0` that
/// `+proj=utm` ignores, and a vertical `+geoidgrids` that does not change x/y) and no offset.
/// pyproj with that string (without the grid file) maps (lat 48.001°, lon 9.01°) to
/// (500745.94061772135, 5316411.418666103).
#[test]
fn a_geo_position_lands_where_pyproj_projects_it() {
    let w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    let r = resolve(&geo(48.001, 9.01), &w).unwrap();
    assert!(
        (r.pose.x - 500_745.940_617_721_35).abs() < GEO_TOL,
        "x {}",
        r.pose.x
    );
    assert!(
        (r.pose.y - 5_316_411.418_666_103).abs() < GEO_TOL,
        "y {}",
        r.pose.y
    );
}

/// With an offset (691600, 5334700) and hdg 0.1 (§8.5: world = R(hdg)·local + offset), local =
/// R(−hdg)·(world − offset). Munich's Marienplatz (48.137154°, 11.576124°) projects (pyproj,
/// UTM 32, WGS 84) to world (691650.3668499767, 5334754.246572778); world − offset =
/// (50.3668499767, 54.246572778); with cos 0.1 = 0.99500416528, sin 0.1 = 0.09983341665:
/// x = 50.36685·0.99500 + 54.24657·0.09983 = 55.53084622,
/// y = −50.36685·0.09983 + 54.24657·0.99500 = 48.94727115.
#[test]
fn the_header_offset_is_undone_after_the_projection() {
    let w = FakeWorld::new(offset_network());
    let mut p = geo(48.137154, 11.576124);
    if let PositionKind::Geo { orientation: o, .. } = &mut p.kind {
        *o = orientation(0.25, true);
    }
    let r = resolve(&p, &w).unwrap();
    assert!(
        (r.pose.x - 55.530_846_220_529_59).abs() < GEO_TOL,
        "x {}",
        r.pose.x
    );
    assert!(
        (r.pose.y - 48.947_271_146_885_33).abs() < GEO_TOL,
        "y {}",
        r.pose.y
    );
    // The orientation is absolute in the network's frame; z on no road is 0.
    assert!((r.pose.h - 0.25).abs() < 1e-12 && r.pose.z.abs() < 1e-12);
    // And back: to_geo inverts to_local to well under a millimetre (1e-8° ≈ 1.1 mm).
    let t = GeoTransform::new(offset_network().header()).unwrap();
    let (lat, lon) = t.to_geo(r.pose.x, r.pose.y).unwrap();
    assert!(
        (lat - 48.137154).abs() < 1e-9 && (lon - 11.576124).abs() < 1e-9,
        "{lat} {lon}"
    );
}

#[test]
fn geo_positions_without_a_georeference_or_with_a_relative_orientation_are_refused() {
    let w = FakeWorld::new(corpus_road("esmini/xodr/fabriksgatan.xodr"));
    let e = resolve(&geo(48.0, 9.0), &w).unwrap_err();
    assert!(matches!(e.kind(), PositionErrorKind::Geo(_)));
    assert_eq!(
        e.to_string(),
        "expected a <geoReference> in the road network's header, found none at test.xosc:7:9"
    );
    let w = FakeWorld::new(offset_network());
    let mut p = geo(48.137154, 11.576124);
    if let PositionKind::Geo { orientation: o, .. } = &mut p.kind {
        *o = orientation(0.25, false);
    }
    let e = resolve(&p, &w).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("expected an absolute Orientation for a GeoPosition"),
        "{e}"
    );
}

/// A Route whose waypoints are GeoPositions: local (20, −1.75) and (150, −1.75) on
/// geo_utm32_offset.xodr's road 1 (lane −1's centre), turned into latitude/longitude by pyproj's
/// inverse UTM 32 after the offset (world = R(0.1)·local + (691600, 5334700)):
/// (48.13667785658217°, 11.575692959093892°) and (48.13675554215784°, 11.577435663980932°).
/// The route runs along lane −1 from s = 20 to s = 150: 130 m.
#[test]
fn route_waypoints_may_be_geo_positions() {
    use engine::position::EntityQuery;
    use engine::routing::plan_route;
    use scenario::{Route, RouteStrategy, Waypoint};
    let w = FakeWorld::new(offset_network());
    let waypoint = |lat, lon| Waypoint {
        route_strategy: RouteStrategy::Shortest,
        position: geo(lat, lon),
    };
    let route = Route {
        name: "Geo".into(),
        closed: false,
        waypoints: vec![
            waypoint(48.136_677_856_582_17, 11.575_692_959_093_892),
            waypoint(48.136_755_542_157_84, 11.577_435_663_980_932),
        ],
        catalog: None,
    };
    let planned =
        plan_route(&route, &w, &w.routing_options(), &condition_support::here()).expect("plans");
    let first = &planned.waypoints()[0].lane;
    assert_eq!((first.road_id.as_str(), first.lane_id), ("1", -1));
    assert!(
        (first.s - 20.0).abs() < GEO_TOL && first.offset.abs() < GEO_TOL,
        "{first:?}"
    );
    let end = planned.waypoints()[1].path_s;
    assert!((end - 130.0).abs() < GEO_TOL, "route length {end}");
}
