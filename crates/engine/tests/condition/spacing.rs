//! Distance, RelativeDistance, ReachPosition, TimeHeadway and TimeToCollision
//! (OpenSCENARIO 1.3 §6.4, §7.6.3), hand-computed on esmini's straight_500m.xodr.
//!
//! Set-up: road "1" along +x; lane −1's centre at y = −1.535 (driven towards +x), lane 1's at
//! y = +1.535 (towards −x). Cars have a 4.5 m × 1.8 m box whose centre is 1.4 m ahead of the
//! rear axle, so a car heading +x at x spans [x − 0.85, x + 3.65].
//! Ego at x = 50 and Lead at x = 80, both on lane −1 heading +x:
//! reference points 30 m apart; boxes [49.15, 53.65] and [79.15, 83.65], gap 25.5 m.

use crate::condition_support;

use condition_support::{at, by_entity, corpus_road, eval, measure, FakeWorld};
use scenario::{
    CoordinateSystem, DistanceMeasure, EntityCondition, PositionKind, RelativeDistanceType, Rule,
    TimeToCollisionTarget,
};

use CoordinateSystem::{Entity, Road};
use RelativeDistanceType::{EuclidianDistance, Lateral, Longitudinal};

fn world() -> FakeWorld {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 50.0, true);
    w.place_on_lane("Lead", "1", -1, 80.0, true);
    w
}

fn rel_distance(m: DistanceMeasure, value: f64) -> scenario::Condition {
    by_entity(
        &["Ego"],
        false,
        EntityCondition::RelativeDistance {
            entity_ref: "Lead".into(),
            value,
            rule: Rule::EqualTo,
            measure: m,
        },
    )
}

#[test]
fn relative_distance_in_each_measure() {
    let mut w = world();
    for (m, d) in [
        (measure(false, None, None), 30.0),
        (measure(false, Some(Entity), Some(Longitudinal)), 30.0),
        (measure(true, Some(Entity), Some(Longitudinal)), 25.5),
        (measure(true, None, Some(EuclidianDistance)), 25.5),
        (measure(false, Some(Road), Some(Longitudinal)), 30.0),
        (measure(true, Some(Road), Some(Longitudinal)), 25.5),
    ] {
        assert!(eval(&w, &rel_distance(m, d)), "{m:?} should give {d}");
        assert!(
            !eval(&w, &rel_distance(m, d + 0.01)),
            "{m:?} should not give {}",
            d + 0.01
        );
    }
    // Lead on lane 1 beside Ego (same x): lateral 3.07 between reference points; the boxes
    // (1.8 m wide) leave 3.07 − 1.8 = 1.27 m. Euclidean between the points: 3.07.
    w.place_on_lane("Lead", "1", 1, 50.0, true);
    for (m, d) in [
        (measure(false, Some(Entity), Some(Lateral)), 3.07),
        (measure(true, Some(Entity), Some(Lateral)), 1.27),
        (measure(false, Some(Road), Some(Lateral)), 3.07),
        (measure(false, None, None), 3.07),
    ] {
        assert!(eval(&w, &rel_distance(m, d)), "{m:?} should give {d}");
    }
}

#[test]
fn distance_to_a_position_and_reach_position() {
    let w = world();
    let target = || {
        at(PositionKind::World {
            x: 100.0,
            y: -1.535,
            z: Some(0.0),
            h: None,
            p: None,
            r: None,
        })
    };
    let c = by_entity(
        &["Ego"],
        false,
        EntityCondition::Distance {
            position: target(),
            value: 50.0,
            rule: Rule::LessOrEqual,
            measure: measure(false, None, None),
        },
    );
    assert!(eval(&w, &c));
    // Freespace: from Ego's front (53.65) to the point: 46.35.
    let c = by_entity(
        &["Ego"],
        false,
        EntityCondition::Distance {
            position: target(),
            value: 46.35,
            rule: Rule::EqualTo,
            measure: measure(true, None, None),
        },
    );
    assert!(eval(&w, &c));
    let reach = |tolerance| {
        by_entity(
            &["Ego"],
            false,
            EntityCondition::ReachPosition {
                position: target(),
                tolerance,
            },
        )
    };
    assert!(!eval(&w, &reach(49.9)));
    assert!(eval(&w, &reach(50.0)));
}

fn headway(value: f64, m: DistanceMeasure) -> scenario::Condition {
    by_entity(
        &["Ego"],
        false,
        EntityCondition::TimeHeadway {
            entity_ref: "Lead".into(),
            value,
            rule: Rule::EqualTo,
            measure: m,
        },
    )
}

#[test]
fn time_headway_is_measured_by_the_trailing_triggering_entity() {
    let mut w = world();
    w.set_speed("Ego", 10.0);
    // Lead's speed does not enter (1.3 text). 30 m at 10 m/s: 3 s; freespace 25.5 m: 2.55 s.
    w.set_speed("Lead", 50.0);
    assert!(eval(&w, &headway(3.0, measure(false, None, None))));
    assert!(eval(&w, &headway(2.55, measure(true, None, None))));
    assert!(eval(
        &w,
        &headway(3.0, measure(false, Some(Road), Some(Longitudinal)))
    ));
    // Pitfall 12: the reference behind gives no headway at all (not 3 s, not −3 s).
    w.place_on_lane("Lead", "1", -1, 20.0, true);
    for value in [3.0, -3.0] {
        assert!(!eval(&w, &headway(value, measure(false, None, None))));
    }
    // A standing triggering entity never reaches the reference: no headway.
    w.place_on_lane("Lead", "1", -1, 80.0, true);
    w.set_speed("Ego", 0.0);
    assert!(!eval(&w, &headway(3.0, measure(false, None, None))));
}

#[test]
fn time_headway_along_a_lane_driven_towards_minus_s() {
    let mut w = world();
    // Both on lane 1 heading −x: Ego at x = 80, Lead at x = 50 ahead of it in its travel.
    w.place_on_lane("Ego", "1", 1, 80.0, false);
    w.place_on_lane("Lead", "1", 1, 50.0, false);
    w.set_speed("Ego", 10.0);
    assert!(eval(
        &w,
        &headway(3.0, measure(false, Some(Road), Some(Longitudinal)))
    ));
    assert!(eval(&w, &headway(3.0, measure(false, None, None))));
}

fn ttc(value: f64, rule: Rule, m: DistanceMeasure) -> scenario::Condition {
    by_entity(
        &["Ego"],
        false,
        EntityCondition::TimeToCollision {
            target: TimeToCollisionTarget::EntityRef("Lead".into()),
            value,
            rule,
            measure: m,
        },
    )
}

#[test]
fn time_to_collision_uses_the_closing_speed() {
    let mut w = world();
    w.set_speed("Ego", 20.0);
    w.set_speed("Lead", 10.0);
    // Closing at 10 m/s: reference points 30 m → 3 s; boxes 25.5 m → 2.55 s (exact box TTC).
    assert!(eval(
        &w,
        &ttc(3.0, Rule::EqualTo, measure(false, None, None))
    ));
    assert!(eval(
        &w,
        &ttc(
            3.0,
            Rule::EqualTo,
            measure(false, Some(Entity), Some(Longitudinal))
        )
    ));
    assert!(eval(
        &w,
        &ttc(2.55, Rule::EqualTo, measure(true, None, None))
    ));
    // Moving apart: no TTC, whatever the rule (1.3: "evaluates to false").
    w.set_speed("Lead", 25.0);
    for rule in [Rule::LessThan, Rule::GreaterThan] {
        assert!(!eval(&w, &ttc(3.0, rule, measure(false, None, None))));
        assert!(!eval(&w, &ttc(3.0, rule, measure(true, None, None))));
    }
}

#[test]
fn oncoming_traffic_in_the_next_lane_has_no_box_collision() {
    // Pitfall 11 (esmini #569, #617): Lead on lane 1 at x = 150 coming towards Ego at
    // 10 m/s, Ego at 10 m/s on lane −1. The boxes pass 1.27 m apart: no collision, so the
    // freespace TTC condition is false however large its threshold.
    let mut w = world();
    w.place_on_lane("Lead", "1", 1, 150.0, false);
    w.set_speed("Ego", 10.0);
    w.set_speed("Lead", 10.0);
    assert!(!eval(
        &w,
        &ttc(1000.0, Rule::LessThan, measure(true, None, None))
    ));
    // Laterally they do not close either.
    assert!(!eval(
        &w,
        &ttc(
            1000.0,
            Rule::LessThan,
            measure(false, Some(Entity), Some(Lateral))
        )
    ));
}

#[test]
fn assigned_route_distance_runs_along_the_route() {
    use engine::domain::{Route, RouteStretch};
    use scenario::RoutingAlgorithm;
    let mut w = world();
    // Ego's route runs the whole road towards −s; Ego on lane 1 at x = 80 heading −x, Lead at
    // x = 50 on lane 1: 30 m further along the route (route s 420 vs 450).
    w.place_on_lane("Ego", "1", 1, 80.0, false);
    w.place_on_lane("Lead", "1", 1, 50.0, false);
    let route = Route::new(
        &w.network,
        vec![RouteStretch {
            road_id: "1".into(),
            lane_id: None,
            s_start: 500.0,
            s_end: 0.0,
        }],
    )
    .unwrap();
    w.entity_mut("Ego").route = Some(route);
    let on_route = |freespace| DistanceMeasure {
        routing_algorithm: Some(RoutingAlgorithm::AssignedRoute),
        ..measure(freespace, Some(Road), Some(Longitudinal))
    };
    assert!(eval(&w, &rel_distance(on_route(false), 30.0)));
    // Boxes: Ego's front reaches 3.65 m ahead of its reference point, Lead's rear 0.85 m
    // behind its own: 30 − 3.65 − 0.85 = 25.5.
    assert!(eval(&w, &rel_distance(on_route(true), 25.5)));
}

#[test]
fn lane_distance_runs_along_the_lane_centre() {
    // curve_r100.xodr: the arc from s = 500 to 657.08 has radius 100 about (500, 100); lane
    // −1's centre (t = −1.535) has radius 101.535. Ego at s = 500 and Lead at s = 550 on lane
    // −1: 50 m along the reference line, 101.535 · 0.5 = 50.7675 m along the lane centre.
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/curve_r100.xodr"));
    w.place_on_lane("Ego", "0", -1, 500.0, true);
    w.place_on_lane("Lead", "0", -1, 550.0, true);
    let lane = measure(false, Some(CoordinateSystem::Lane), Some(Longitudinal));
    let road = measure(false, Some(Road), Some(Longitudinal));
    assert!(eval(&w, &rel_distance(road, 50.0)));
    // Simpson's rule is exact for the constant integrand of an arc (up to round-off).
    assert!(eval(&w, &rel_distance(lane, 50.7675)));
    assert!(!eval(&w, &rel_distance(lane, 50.0)));
}

#[test]
fn trajectory_distance_runs_along_the_followed_trajectory() {
    use scenario::{Shape, Trajectory, Vertex};
    let mut w = world();
    // Ego follows a polyline along lane −1's centre (y = −1.535) from x = 0 to 500: its s/t
    // frame is the road's here, so Lead 30 m ahead is 30 (boxes 25.5), and on lane 1 beside
    // it 3.07 to the left.
    let vertex = |x: f64| Vertex {
        time: None,
        position: at(PositionKind::World {
            x,
            y: -1.535,
            z: Some(0.0),
            h: None,
            p: None,
            r: None,
        }),
    };
    let shape = Trajectory {
        name: "T".into(),
        closed: false,
        shape: Shape::Polyline(vec![vertex(0.0), vertex(500.0)]),
        catalog: None,
    };
    let path = engine::trajectory::build(&shape, &w, &condition_support::here()).unwrap();
    w.entity_mut("Ego").trajectory = Some(path);
    let on = |free, ty| measure(free, Some(CoordinateSystem::Trajectory), Some(ty));
    assert!(eval(&w, &rel_distance(on(false, Longitudinal), 30.0)));
    assert!(eval(&w, &rel_distance(on(true, Longitudinal), 25.5)));
    w.place_on_lane("Lead", "1", 1, 50.0, true);
    assert!(eval(&w, &rel_distance(on(false, Lateral), 3.07)));
    // Without a trajectory there is no such frame: false, not an error.
    w.entity_mut("Ego").trajectory = None;
    assert!(!eval(&w, &rel_distance(on(false, Lateral), 3.07)));
}

#[test]
fn road_distance_across_linked_roads_and_lanes() {
    // Pitfall 14: a road distance needs a path between the two positions. On
    // road_link_unequal_number_of_lanes0.xodr road 1 (100 m along +x) ends where road 2
    // starts; Ego on road 1 lane −1 at s = 90, Lead on road 2 lane −2 at s = 10 (another lane):
    // 10 + 10 = 20 m along the roads, whatever the lanes (the path runs along roads, not lanes).
    let mut w = FakeWorld::new(corpus_road(
        "generated/xodr/road_link_unequal_number_of_lanes0.xodr",
    ));
    w.place_on_lane("Ego", "1", -1, 90.0, true);
    w.place_on_lane("Lead", "2", -2, 10.0, true);
    assert!(eval(
        &w,
        &rel_distance(measure(false, Some(Road), Some(Longitudinal)), 20.0)
    ));
    // Lateral: lane −1 centre t = −1.5, lane −2 centre t = −4.5: Lead 3 m to the right, |−3|.
    assert!(eval(
        &w,
        &rel_distance(measure(false, Some(Road), Some(Lateral)), 3.0)
    ));
}

#[test]
fn overlapping_boxes_are_at_distance_zero() {
    // Pitfall 13 (§6.4: distances are ≥ 0; boxes that overlap are 0 apart in every freespace
    // measure): Lead 3 m ahead of Ego, boxes [49.15, 53.65] and [52.15, 56.65] overlap.
    let mut w = world();
    w.place_on_lane("Lead", "1", -1, 53.0, true);
    for m in [
        measure(true, None, None),
        measure(true, Some(Entity), Some(Longitudinal)),
        measure(true, Some(Road), Some(Longitudinal)),
        measure(true, Some(CoordinateSystem::Lane), Some(Longitudinal)),
    ] {
        assert!(eval(&w, &rel_distance(m, 0.0)), "{m:?} should give 0");
    }
    // Without freespace the reference points stay 3 m apart.
    assert!(eval(&w, &rel_distance(measure(false, None, None), 3.0)));
    // Touching boxes have collided: TTC 0 in every freespace measure, even standing still.
    for m in [
        measure(true, None, None),
        measure(true, Some(Entity), Some(Longitudinal)),
        measure(true, Some(Road), Some(Longitudinal)),
    ] {
        assert!(
            eval(&w, &ttc(0.0, Rule::EqualTo, m)),
            "{m:?} should give TTC 0"
        );
    }
}
