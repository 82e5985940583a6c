//! Bad positions give errors that name what was expected, what was found and where the
//! position was written (never a panic).

use crate::condition_support;

use condition_support::{at, corpus_road, relative_road_to, FakeWorld};
use engine::position::resolve;
use scenario::PositionKind;

fn message(kind: PositionKind, w: &FakeWorld) -> String {
    resolve(&at(kind), w).unwrap_err().to_string()
}

#[test]
fn error_messages_name_expectation_finding_and_place() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 100.0, true);
    let lane = |road: &str, lane: &str, s: f64| PositionKind::Lane {
        road_id: road.into(),
        lane_id: lane.into(),
        s,
        offset: None,
        orientation: None,
    };
    assert_eq!(
        message(lane("9", "-1", 10.0), &w),
        "expected an existing road, found road id \"9\" at test.xosc:7:9"
    );
    assert_eq!(
        message(lane("1", "left", 10.0), &w),
        "expected an integer lane id, found \"left\" at test.xosc:7:9"
    );
    assert_eq!(
        message(lane("1", "-1", 600.0), &w),
        "expected s in [0, 500] on road \"1\", found 600 at test.xosc:7:9"
    );
    assert_eq!(
        message(
            PositionKind::RelativeLane {
                entity_ref: "Ego".into(),
                d_lane: -5,
                ds: Some(0.0),
                ds_lane: None,
                offset: None,
                orientation: None,
            },
            &w
        ),
        "expected lane -6 (lane -1 + dLane -5) on road \"1\" at s = 100, found no such lane at test.xosc:7:9"
    );
    assert_eq!(
        message(relative_road_to("Nobody", 1.0, 0.0).kind, &w),
        "expected a placed entity named \"Nobody\", found none at test.xosc:7:9"
    );
    assert_eq!(
        message(
            PositionKind::World {
                x: f64::NAN,
                y: 0.0,
                z: None,
                h: None,
                p: None,
                r: None
            },
            &w
        ),
        "expected a finite x, found NaN at test.xosc:7:9"
    );
    assert_eq!(
        message(
            PositionKind::Road {
                road_id: "1".into(),
                s: 1.0,
                t: 0.0,
                orientation: Some(scenario::Orientation {
                    h: f64::INFINITY,
                    p: 0.0,
                    r: 0.0,
                    reference: None,
                }),
            },
            &w
        ),
        "expected a finite Orientation h, found inf at test.xosc:7:9"
    );
}

#[test]
fn entity_off_every_road_cannot_anchor_a_road_position() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    // 100 m north of a road whose surface is at most 10.75 m wide on either side.
    w.place(
        "Far",
        opendrive::Pose {
            x: 50.0,
            y: 100.0,
            ..Default::default()
        },
    );
    assert_eq!(
        resolve(&relative_road_to("Far", 1.0, 0.0), &w)
            .unwrap_err()
            .to_string(),
        "expected entity \"Far\" on a road, found it off every road at test.xosc:7:9"
    );
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]

    /// Any lane position or relative lane position, sensible or not, resolves or errors: no
    /// panic, no hang (dsLane walks at most the road's length).
    #[test]
    fn lane_positions_never_panic(
        road in proptest::sample::select(vec!["0", "1", "7", ""]),
        lane in -6i32..6,
        s in -1e3f64..1e4,
        offset in -50f64..50.0,
        d_lane in -8i32..8,
        ds in -2e3f64..2e3,
        along_lane in proptest::bool::ANY,
    ) {
        let mut w = FakeWorld::new(corpus_road("esmini/xodr/curve_r100.xodr"));
        w.place_on_lane("Ego", "0", -1, 300.0, true);
        let _ = resolve(&at(PositionKind::Lane {
            road_id: road.into(),
            lane_id: lane.to_string(),
            s,
            offset: Some(offset),
            orientation: None,
        }), &w);
        let _ = resolve(&at(PositionKind::RelativeLane {
            entity_ref: "Ego".into(),
            d_lane,
            ds: (!along_lane).then_some(ds),
            ds_lane: along_lane.then_some(ds),
            offset: Some(offset),
            orientation: None,
        }), &w);
        let _ = resolve(&relative_road_to("Ego", ds, offset), &w);
    }
}
