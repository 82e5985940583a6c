//! EndOfRoad, Offroad (with durations) and Collision (OpenSCENARIO 1.3 §7.6.3) on esmini's
//! straight_500m.xodr: one road "1", 500 m along +x, with no predecessor or successor, its
//! surface reaching 1.535 + 1.535 + 1.68 + 6 = 10.75 m to either side of the reference line.

use crate::condition_support;

use condition_support::{by_entity, corpus_road, eval, eval_at, FakeWorld};
use engine::condition::ConditionState;
use opendrive::Pose;
use scenario::{CollisionTarget, EntityCondition, ObjectType};

fn world() -> FakeWorld {
    FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"))
}

#[test]
fn end_of_road_holds_after_its_duration_at_an_unlinked_end() {
    let mut w = world();
    let c = by_entity(
        &["Ego"],
        false,
        EntityCondition::EndOfRoad { duration: 1.0 },
    );
    let mut state = ConditionState::new();
    // s = 499 facing +s: 1 m before the end, not at it.
    w.place_on_lane("Ego", "1", -1, 499.0, true);
    assert!(!eval_at(&mut w, 0.0, &c, &mut state));
    // At s = 500: at the end from t = 0.5, so true from t = 1.5.
    w.place_on_lane("Ego", "1", -1, 500.0, true);
    assert!(!eval_at(&mut w, 0.5, &c, &mut state));
    assert!(!eval_at(&mut w, 1.0, &c, &mut state));
    assert!(eval_at(&mut w, 1.5, &c, &mut state));
    // The same point facing −s looks down the road: not at its end.
    w.place_on_lane("Ego", "1", -1, 500.0, false);
    assert!(!eval_at(&mut w, 2.0, &c, &mut state));
    // s = 0 facing −s is the other unlinked end; duration 0 holds at once.
    w.place_on_lane("Ego", "1", 1, 0.0, false);
    let c0 = by_entity(
        &["Ego"],
        false,
        EntityCondition::EndOfRoad { duration: 0.0 },
    );
    assert!(eval(&w, &c0));
}

#[test]
fn offroad_beyond_the_road_surface() {
    let mut w = world();
    let c = by_entity(&["Ego"], false, EntityCondition::Offroad { duration: 0.0 });
    // y = −10 is on the outer border lane (surface to −10.75): on the road.
    w.place(
        "Ego",
        Pose {
            x: 100.0,
            y: -10.0,
            ..Pose::default()
        },
    );
    assert!(!eval(&w, &c));
    // y = −11 is 0.25 m beyond the surface.
    w.place(
        "Ego",
        Pose {
            x: 100.0,
            y: -11.0,
            ..Pose::default()
        },
    );
    assert!(eval(&w, &c));
}

#[test]
fn offroad_on_a_lane_of_type_none() {
    // esmini's jolengatan.xodr, road "1": lane −1 driving 3.57 m, lane −2 border 1.68 m,
    // lane −3 of type none 6 m. t = −5 is on the border lane (on the road); t = −6.25 lies
    // 1 m into the `none` lane: off the road (OpenDRIVE 1.8 §11.3).
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/jolengatan.xodr"));
    let c = by_entity(&["Ego"], false, EntityCondition::Offroad { duration: 0.0 });
    for (t, off) in [(-5.0, false), (-6.25, true)] {
        let mut pose = w.network.road_pose("1", 100.0, t).unwrap();
        pose.h = 0.0;
        w.place("Ego", pose);
        assert_eq!(eval(&w, &c), off, "t = {t}");
    }
}

#[test]
fn collision_with_an_entity_or_a_type() {
    let mut w = world();
    // Car boxes span [x − 0.85, x + 3.65]: cars at x = 50 and x = 54 give [49.15, 53.65] and
    // [53.15, 57.65], which overlap over [53.15, 53.65].
    w.place_on_lane("Ego", "1", -1, 50.0, true);
    w.place_on_lane("Other", "1", -1, 54.0, true);
    w.place_as(
        "Walker",
        ObjectType::Pedestrian,
        Pose {
            x: 200.0,
            y: -1.535,
            ..Pose::default()
        },
    );
    let with = |target| by_entity(&["Ego"], false, EntityCondition::Collision(target));
    assert!(eval(&w, &with(CollisionTarget::EntityRef("Other".into()))));
    assert!(eval(
        &w,
        &with(CollisionTarget::ByType(ObjectType::Vehicle))
    ));
    assert!(!eval(
        &w,
        &with(CollisionTarget::ByType(ObjectType::Pedestrian))
    ));
    assert!(!eval(
        &w,
        &with(CollisionTarget::EntityRef("Walker".into()))
    ));
    // Other at x = 55: boxes [49.15, 53.65] and [54.15, 58.65], 0.5 m apart.
    w.place_on_lane("Other", "1", -1, 55.0, true);
    assert!(!eval(&w, &with(CollisionTarget::EntityRef("Other".into()))));
}
