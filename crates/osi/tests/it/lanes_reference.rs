//! Lanes and boundaries built from corpus road networks, checked against esmini 3.6.0's
//! lane-centre samples (`shared/corpus/reference/opendrive/esmini/NAME.csv`, see its
//! README): every reference point of a lane must lie on our centre-line polyline within
//! the sampling tolerance (1 cm) plus the reference's rounding (1e-6 m). Lane 0's samples
//! are the centre line, which is a lane boundary in OSI.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use osi::ids::{IdAllocator, IdKey};
use osi::lanes::{from_network, RoadLanes};
use osi::osi3::{Lane, LaneBoundary, Vector3d};
use osi::polyline::Sampling;
use std::collections::{HashMap, HashSet};
use std::path::PathBuf;

const CORPUS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../../shared/corpus");
/// Sampling tolerance (1 cm) + reference rounding (1e-6) + margin for float noise.
const TOL: f64 = 0.01 + 2e-6;

fn xyz(v: &Vector3d) -> [f64; 3] {
    [v.x.unwrap(), v.y.unwrap(), v.z.unwrap()]
}

fn distance_to_polyline(p: [f64; 3], line: &[[f64; 3]]) -> f64 {
    line.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
            let len2: f64 = ab.iter().map(|c| c * c).sum();
            let u = if len2 > 0.0 {
                ((ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (0..3)
                .map(|i| (ap[i] - u * ab[i]).powi(2))
                .sum::<f64>()
                .sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

fn build(name: &str) -> (opendrive::RoadNetwork, IdAllocator, RoadLanes) {
    let path = PathBuf::from(format!("{CORPUS}/esmini/xodr/{name}.xodr"));
    let net = opendrive::RoadNetwork::from_file(&path).unwrap();
    let mut ids = IdAllocator::new();
    let lanes = from_network(&net, &mut ids, &Sampling::default(), Some(name)).unwrap();
    (net, ids, lanes)
}

fn check_against_esmini(name: &str) {
    let (net, ids, built) = build(name);
    let lanes: HashMap<u64, &Lane> = built
        .lanes
        .iter()
        .map(|l| (l.id.unwrap().value.unwrap(), l))
        .collect();
    let boundaries: HashMap<u64, &LaneBoundary> = built
        .lane_boundaries
        .iter()
        .map(|b| (b.id.unwrap().value.unwrap(), b))
        .collect();
    let csv =
        std::fs::read_to_string(format!("{CORPUS}/reference/opendrive/esmini/{name}.csv")).unwrap();
    let mut checked = 0;
    for row in csv.lines().skip(2) {
        let f: Vec<&str> = row.split(',').collect();
        let (road_id, s, lane): (&str, f64, i32) =
            (f[0], f[1].parse().unwrap(), f[2].parse().unwrap());
        let p = [f[3], f[4], f[5]].map(|v| v.parse::<f64>().unwrap());
        let road = net.road(road_id).unwrap();
        let section = road.lane_section_index(s);
        let line: Vec<[f64; 3]> = if lane == 0 {
            let key = IdKey::LaneBoundary {
                road: road_id.into(),
                lane_section: section,
                lane: 0,
            };
            let b = boundaries[&ids.get(&key).unwrap().value.unwrap()];
            b.boundary_line
                .iter()
                .map(|bp| xyz(bp.position.as_ref().unwrap()))
                .collect()
        } else {
            let key = IdKey::Lane {
                road: road_id.into(),
                lane_section: section,
                lane,
            };
            let l = lanes[&ids.get(&key).unwrap().value.unwrap()];
            l.classification
                .as_ref()
                .unwrap()
                .centerline
                .iter()
                .map(xyz)
                .collect()
        };
        let d = distance_to_polyline(p, &line);
        assert!(
            d <= TOL,
            "{name}: road {road_id} lane {lane} s {s}: {d} m off"
        );
        checked += 1;
    }
    assert!(checked > 100, "{name}: only {checked} rows");
}

macro_rules! esmini_case {
    ($test:ident, $file:literal) => {
        #[test]
        fn $test() {
            check_against_esmini($file);
        }
    };
}

// Every esmini road of the corpus but multi_intersections, where lane −3 of road 206 (a
// lane with <height>) lies 0.015 m higher in the opendrive crate than in esmini's
// samples; that is a lane-height question for the road model, not for the sampling here
// (with 1e-5 m sampling tolerance the gap stays 0.015000 m).
esmini_case!(circle_300m, "circle_300m");
esmini_case!(crest_curve, "crest-curve");
esmini_case!(curve_r100, "curve_r100");
esmini_case!(curves, "curves");
esmini_case!(curves_elevation, "curves_elevation");
esmini_case!(e6mini_lht, "e6mini-lht");
esmini_case!(e6mini, "e6mini");
esmini_case!(fabriksgatan, "fabriksgatan");
esmini_case!(jolengatan, "jolengatan");
esmini_case!(parking_demo, "parking_demo");
esmini_case!(soderleden, "soderleden");
esmini_case!(straight_500m, "straight_500m");
esmini_case!(striaght_and_curves, "striaghtAndCurves");
esmini_case!(tunnels, "tunnels");
esmini_case!(two_plus_one, "two_plus_one");
esmini_case!(velodrome, "velodrome");

#[test]
fn ids_are_unique_and_references_resolve() {
    let (_, _, built) = build("fabriksgatan");
    let lane_ids: HashSet<u64> = built
        .lanes
        .iter()
        .map(|l| l.id.unwrap().value.unwrap())
        .collect();
    let boundary_ids: HashSet<u64> = built
        .lane_boundaries
        .iter()
        .map(|b| b.id.unwrap().value.unwrap())
        .collect();
    assert_eq!(lane_ids.len(), built.lanes.len());
    assert_eq!(boundary_ids.len(), built.lane_boundaries.len());
    assert!(lane_ids.is_disjoint(&boundary_ids));
    let mut pairs = 0;
    for lane in &built.lanes {
        let c = lane.classification.as_ref().unwrap();
        for b in c
            .left_lane_boundary_id
            .iter()
            .chain(&c.right_lane_boundary_id)
        {
            assert!(boundary_ids.contains(&b.value.unwrap()));
        }
        for n in c
            .left_adjacent_lane_id
            .iter()
            .chain(&c.right_adjacent_lane_id)
        {
            assert!(lane_ids.contains(&n.value.unwrap()));
        }
        for p in &c.lane_pairing {
            for id in [p.antecessor_lane_id, p.successor_lane_id]
                .into_iter()
                .flatten()
            {
                assert!(
                    lane_ids.contains(&id.value.unwrap()),
                    "pairing to a missing lane"
                );
            }
            pairs += 1;
        }
        // Every lane has a type and a centre line of at least two points.
        assert!(c.r#type.unwrap() >= 2);
        assert!(c.centerline.len() >= 2);
    }
    // fabriksgatan has junctions: some lanes must connect.
    assert!(pairs > 0);
}

#[test]
fn neighbours_on_a_straight_road() {
    // straight_500m: one road, one section; lanes −1 and 1 are driving lanes either
    // side of the centre line. Lane −1 has lane 1 on its left (across the centre lane)
    // and its left boundary is the centre line (lane 0), its right one its outer border.
    let (net, ids, built) = build("straight_500m");
    let road = &net.roads()[0];
    let key = |lane| IdKey::Lane {
        road: road.id.clone(),
        lane_section: 0,
        lane,
    };
    let bkey = |lane| IdKey::LaneBoundary {
        road: road.id.clone(),
        lane_section: 0,
        lane,
    };
    let right = built
        .lanes
        .iter()
        .find(|l| l.id == ids.get(&key(-1)))
        .unwrap();
    let c = right.classification.as_ref().unwrap();
    assert_eq!(c.left_adjacent_lane_id, vec![ids.get(&key(1)).unwrap()]);
    assert_eq!(c.left_lane_boundary_id, vec![ids.get(&bkey(0)).unwrap()]);
    assert_eq!(c.right_lane_boundary_id, vec![ids.get(&bkey(-1)).unwrap()]);
    // Right-hand traffic: lane −1 is driven towards +s, along its centre line.
    assert_eq!(c.centerline_is_driving_direction, Some(true));
    let left = built
        .lanes
        .iter()
        .find(|l| l.id == ids.get(&key(1)))
        .unwrap();
    let lc = left.classification.as_ref().unwrap();
    assert_eq!(lc.centerline_is_driving_direction, Some(false));
    assert_eq!(lc.right_adjacent_lane_id, vec![ids.get(&key(-1)).unwrap()]);
    let source = &right.source_reference[0];
    assert_eq!(source.r#type.as_deref(), Some("net.asam.opendrive"));
    assert_eq!(
        source.identifier,
        vec![road.id.clone(), "0".into(), "-1".into()]
    );
}

#[test]
fn located_positions_map_to_their_lane() {
    // straight_500m: lane −1 is 3.07 m wide right of the reference line (y from 0 to
    // −3.07), lane −2 (shoulder, 1.68 m) beyond it, then lane −3 (border, 6 m) to y = −10.75.
    let (net, ids, _) = build("straight_500m");
    let road = net.roads()[0].id.clone();
    let lane = |l| {
        ids.get(&IdKey::Lane {
            road: road.clone(),
            lane_section: 0,
            lane: l,
        })
    };
    let on = |x: f64, y: f64| {
        let p = net.locate(x, y, Some(0.0)).unwrap();
        osi::lanes::assigned_lane_at(&ids, &net, &p)
    };
    assert_eq!(on(100.0, -1.5), lane(-1));
    assert_eq!(on(100.0, -4.0), lane(-2));
    assert_eq!(on(100.0, 1.5), lane(1));
    // 20 m right of the reference line is 9.25 m off the road surface: no lane.
    assert_eq!(on(100.0, -20.0), None);
}
