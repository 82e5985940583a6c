//! RelativeClearance, Angle and RelativeAngle (OpenSCENARIO 1.3 §7.6.3) on esmini's
//! straight_500m.xodr (road "1" along +x, heading 0; lane −1 driven towards +x, lane 1
//! towards −x).

use crate::condition_support;

use condition_support::{by_entity, corpus_road, eval, FakeWorld};
use scenario::{AngleType, CoordinateSystem, EntityCondition};

fn clearance(
    opposite_lanes: bool,
    ranges: Vec<(Option<i32>, Option<i32>)>,
    forward: f64,
    backward: f64,
) -> scenario::Condition {
    by_entity(
        &["Ego"],
        false,
        EntityCondition::RelativeClearance {
            opposite_lanes,
            distance_forward: Some(forward),
            distance_backward: Some(backward),
            free_space: false,
            relative_lane_ranges: ranges,
            entity_refs: vec![],
        },
    )
}

#[test]
fn relative_clearance_counts_lanes_from_the_triggering_entity() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 100.0, true);
    // Oncoming car one lane to Ego's left (lane 1), 10 m ahead.
    w.place_on_lane("Other", "1", 1, 110.0, false);
    // Opposite lanes not considered: the range 1..1 names only lane 1, driven the other way,
    // so the area does not exist and the condition is false although Other is not counted
    // (issue 34 class 4; XSD: "evaluates to true, if the specified area exists and is free").
    assert!(!eval(
        &w,
        &clearance(false, vec![(Some(1), Some(1))], 20.0, 0.0)
    ));
    // Opposite lanes counted: lane +1 (left) within 20 m ahead is occupied.
    assert!(!eval(
        &w,
        &clearance(true, vec![(Some(1), Some(1))], 20.0, 0.0)
    ));
    // Only 5 m ahead looked at: clear.
    assert!(eval(
        &w,
        &clearance(true, vec![(Some(1), Some(1))], 5.0, 0.0)
    ));
    // Only the lane to the right (−1 relative): clear.
    assert!(eval(
        &w,
        &clearance(true, vec![(Some(-1), Some(-1))], 20.0, 0.0)
    ));
    // A car 10 m behind in Ego's own lane, with 15 m looked at backwards: occupied.
    w.place_on_lane("Other", "1", -1, 90.0, true);
    assert!(!eval(
        &w,
        &clearance(false, vec![(Some(0), Some(0))], 0.0, 15.0)
    ));
    assert!(eval(
        &w,
        &clearance(false, vec![(Some(0), Some(0))], 0.0, 5.0)
    ));
    // The area must exist: straight_500m has lanes −3 … 3, so from lane −1 three lanes to the
    // right (relative −3: lane −4) is no area, and the condition is false although empty.
    w.place_on_lane("Other", "1", 1, 400.0, false);
    assert!(eval(
        &w,
        &clearance(true, vec![(Some(-2), Some(-2))], 10.0, 10.0)
    ));
    assert!(!eval(
        &w,
        &clearance(true, vec![(Some(-3), Some(-3))], 10.0, 10.0)
    ));
}

#[test]
fn relative_clearance_with_free_space_counts_the_whole_box() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 100.0, true);
    // Other's reference point is on lane −2 (the shoulder, t from −3.07 to −4.75) at
    // t = −3.5; its 1.8 m wide box reaches t = −2.6, inside lane −1 (t from 0 to −3.07).
    let mut pose = w.network.road_pose("1", 105.0, -3.5).unwrap();
    pose.h = 0.0;
    w.place("Other", pose);
    let own_lane = |free_space| {
        by_entity(
            &["Ego"],
            false,
            EntityCondition::RelativeClearance {
                opposite_lanes: false,
                distance_forward: Some(20.0),
                distance_backward: Some(0.0),
                free_space,
                relative_lane_ranges: vec![(Some(0), Some(0))],
                entity_refs: vec![],
            },
        )
    };
    assert!(
        eval(&w, &own_lane(false)),
        "reference point on lane −2: lane −1 clear"
    );
    assert!(
        !eval(&w, &own_lane(true)),
        "box reaches into lane −1: occupied"
    );
}

fn angle(angle: f64, cs: Option<CoordinateSystem>) -> scenario::Condition {
    by_entity(
        &["Ego"],
        false,
        EntityCondition::Angle {
            angle_type: AngleType::Heading,
            angle,
            angle_tolerance: 0.01,
            coordinate_system: cs,
        },
    )
}

#[test]
fn angle_in_world_road_and_lane_frames() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    // Ego on lane 1 heading π + 0.1 (its driving direction π, turned 0.1 left).
    w.place_on_lane("Ego", "1", 1, 100.0, false);
    w.entity_mut("Ego").pose.h = std::f64::consts::PI + 0.1;
    // World: π + 0.1 ≡ −π + 0.1 (angles compare modulo 2π).
    assert!(eval(&w, &angle(-std::f64::consts::PI + 0.1, None)));
    // Road: minus the reference line's heading 0: still π + 0.1.
    assert!(eval(
        &w,
        &angle(std::f64::consts::PI + 0.1, Some(CoordinateSystem::Road))
    ));
    // Lane: minus the lane's driving direction π: 0.1 (pitfall 15).
    assert!(eval(&w, &angle(0.1, Some(CoordinateSystem::Lane))));
    assert!(!eval(&w, &angle(0.12, Some(CoordinateSystem::Lane))));
    // RelativeAngle to a car heading π − 0.2: (π + 0.1) − (π − 0.2) = 0.3.
    w.place_on_lane("Other", "1", 1, 150.0, false);
    w.entity_mut("Other").pose.h = std::f64::consts::PI - 0.2;
    let rel = by_entity(
        &["Ego"],
        false,
        EntityCondition::RelativeAngle {
            entity_ref: "Other".into(),
            angle_type: AngleType::Heading,
            angle: 0.3,
            angle_tolerance: 1e-9,
            coordinate_system: None,
        },
    );
    assert!(eval(&w, &rel));
}

#[test]
fn angle_relative_to_a_followed_trajectory() {
    use condition_support::{at, here};
    use scenario::{PositionKind, Shape, Trajectory, Vertex};
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 100.0, true);
    w.entity_mut("Ego").pose.h = 0.9;
    // A polyline from (0, 0) to (200, 200): heading π/4 everywhere; Ego heads 0.9, so its
    // heading relative to the trajectory is 0.9 − π/4.
    let vertex = |v: f64| Vertex {
        time: None,
        position: at(PositionKind::World {
            x: v,
            y: v,
            z: Some(0.0),
            h: None,
            p: None,
            r: None,
        }),
    };
    let shape = Trajectory {
        name: "Diagonal".into(),
        closed: false,
        shape: Shape::Polyline(vec![vertex(0.0), vertex(200.0)]),
        catalog: None,
    };
    let expected = 0.9 - std::f64::consts::FRAC_PI_4;
    let c = angle(expected, Some(CoordinateSystem::Trajectory));
    // No trajectory followed: no such frame, false.
    assert!(!eval(&w, &c));
    w.entity_mut("Ego").trajectory = Some(engine::trajectory::build(&shape, &w, &here()).unwrap());
    assert!(eval(&w, &c));
    assert!(!eval(
        &w,
        &angle(expected + 0.02, Some(CoordinateSystem::Trajectory))
    ));
}
