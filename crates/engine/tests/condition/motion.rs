//! Motion conditions (OpenSCENARIO 1.3 §7.6.3: Speed, RelativeSpeed, Acceleration,
//! StandStill, TraveledDistance) and triggeringEntitiesRule any / all.

use crate::condition_support;

use condition_support::{by_entity, corpus_road, eval, eval_at, FakeWorld};
use engine::condition::ConditionState;
use engine::domain::Vector3;
use scenario::{DirectionalDimension, EntityCondition, Rule};

fn world() -> FakeWorld {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 50.0, true);
    w.place_on_lane("Lead", "1", -1, 80.0, true);
    w
}

fn speed(value: f64, rule: Rule, direction: Option<DirectionalDimension>) -> EntityCondition {
    EntityCondition::Speed {
        value,
        rule,
        direction,
    }
}

#[test]
fn speed_without_direction_is_the_signed_speed() {
    let mut w = world();
    // Reversing at 2 m/s while drifting left at 0.5 m/s: speed −2 (the corpus' light-state
    // catalog switches reversing lights on at "SpeedCondition lessThan −0.01"); longitudinal
    // component −2, lateral 0.5.
    w.entity_mut("Ego").speed = -2.0;
    w.entity_mut("Ego").velocity = Vector3::new(-2.0, 0.5, 0.0);
    let ego = |c| by_entity(&["Ego"], false, c);
    assert!(eval(&w, &ego(speed(-0.01, Rule::LessThan, None))));
    assert!(eval(&w, &ego(speed(-2.0, Rule::EqualTo, None))));
    assert!(eval(
        &w,
        &ego(speed(
            -2.0,
            Rule::EqualTo,
            Some(DirectionalDimension::Longitudinal)
        ))
    ));
    assert!(eval(
        &w,
        &ego(speed(
            0.5,
            Rule::EqualTo,
            Some(DirectionalDimension::Lateral)
        ))
    ));
    // A stand-still threshold uses |speed|: −2 m/s is not standing still.
    assert!(!eval(
        &w,
        &ego(EntityCondition::StandStill { duration: 0.0 })
    ));
}

#[test]
fn relative_speed_is_triggering_minus_reference() {
    let mut w = world();
    w.set_speed("Ego", 20.0);
    w.set_speed("Lead", 15.0);
    let rel = |value, rule| {
        by_entity(
            &["Ego"],
            false,
            EntityCondition::RelativeSpeed {
                entity_ref: "Lead".into(),
                value,
                rule,
                direction: None,
            },
        )
    };
    // 20 − 15 = +5: the triggering entity is the faster one.
    assert!(eval(&w, &rel(5.0, Rule::EqualTo)));
    assert!(!eval(&w, &rel(-5.0, Rule::EqualTo)));
    // Longitudinal component in Ego's axes, both heading along +x: also +5.
    let c = by_entity(
        &["Ego"],
        false,
        EntityCondition::RelativeSpeed {
            entity_ref: "Lead".into(),
            value: 5.0,
            rule: Rule::EqualTo,
            direction: Some(DirectionalDimension::Longitudinal),
        },
    );
    assert!(eval(&w, &c));
}

#[test]
fn acceleration_is_signed() {
    let mut w = world();
    // Braking at 6 m/s²: −6 with or without direction="longitudinal", 0 laterally.
    w.entity_mut("Ego").acceleration = Vector3::new(-6.0, 0.0, 0.0);
    let acc = |value, rule, direction| {
        by_entity(
            &["Ego"],
            false,
            EntityCondition::Acceleration {
                value,
                rule,
                direction,
            },
        )
    };
    assert!(eval(&w, &acc(-6.0, Rule::EqualTo, None)));
    assert!(eval(
        &w,
        &acc(0.0, Rule::EqualTo, Some(DirectionalDimension::Lateral))
    ));
    assert!(eval(
        &w,
        &acc(
            -5.0,
            Rule::LessThan,
            Some(DirectionalDimension::Longitudinal)
        )
    ));
}

#[test]
fn stand_still_needs_its_duration_without_a_break() {
    let mut w = world();
    let c = by_entity(
        &["Ego"],
        false,
        EntityCondition::StandStill { duration: 1.0 },
    );
    let mut state = ConditionState::new();
    // Standing from t = 0: held 0, 0.5, then 1.0 s at t = 1.0.
    assert!(!eval_at(&mut w, 0.0, &c, &mut state));
    assert!(!eval_at(&mut w, 0.5, &c, &mut state));
    assert!(eval_at(&mut w, 1.0, &c, &mut state));
    // Moving at t = 1.5 breaks it; standing again from t = 2.0 needs until t = 3.0.
    w.set_speed("Ego", 2.0);
    assert!(!eval_at(&mut w, 1.5, &c, &mut state));
    w.set_speed("Ego", 0.0);
    assert!(!eval_at(&mut w, 2.0, &c, &mut state));
    assert!(!eval_at(&mut w, 2.95, &c, &mut state));
    assert!(eval_at(&mut w, 3.0, &c, &mut state));
}

#[test]
fn traveled_distance_and_triggering_rules() {
    let mut w = world();
    w.entity_mut("Ego").odometer = 120.0;
    w.entity_mut("Lead").odometer = 80.0;
    let travelled = |names: &[&str], all| {
        by_entity(
            names,
            all,
            EntityCondition::TraveledDistance { value: 100.0 },
        )
    };
    assert!(eval(&w, &travelled(&["Ego"], false)));
    assert!(!eval(&w, &travelled(&["Lead"], false)));
    // any: Ego has; all: Lead has not.
    assert!(eval(&w, &travelled(&["Ego", "Lead"], false)));
    assert!(!eval(&w, &travelled(&["Ego", "Lead"], true)));
    w.entity_mut("Lead").odometer = 100.0;
    assert!(eval(&w, &travelled(&["Ego", "Lead"], true)));
    // An EntitySelection stands for its members (OpenSCENARIO 1.3 §7.2.2).
    w.selections
        .insert("Cars".into(), vec!["Ego".into(), "Lead".into()]);
    w.entity_mut("Lead").odometer = 99.0;
    assert!(eval(&w, &travelled(&["Cars"], false)));
    assert!(!eval(&w, &travelled(&["Cars"], true)));
}
