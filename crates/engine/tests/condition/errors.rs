//! Condition errors name what was expected, what was found and where the condition (or the
//! position inside it) was written; nothing panics.

use crate::condition_support;

use condition_support::{at, by_entity, corpus_road, eval_error, measure, FakeWorld};
use scenario::{EntityCondition, PositionKind, Rule};

fn relative_distance(entity: &str, m: scenario::DistanceMeasure) -> scenario::Condition {
    by_entity(
        &["Ego"],
        false,
        EntityCondition::RelativeDistance {
            entity_ref: entity.into(),
            value: 1.0,
            rule: Rule::LessThan,
            measure: m,
        },
    )
}

#[test]
fn error_messages() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 50.0, true);
    assert_eq!(
        eval_error(
            &w,
            &by_entity(
                &["Ghost"],
                false,
                EntityCondition::TraveledDistance { value: 1.0 }
            )
        ),
        "expected a placed entity named \"Ghost\", found none at test.xosc:7:9"
    );
    assert_eq!(
        eval_error(&w, &relative_distance("Ghost", measure(false, None, None))),
        "expected a placed entity named \"Ghost\", found none at test.xosc:7:9"
    );
    w.place_on_lane("Lead", "1", -1, 80.0, true);
    // A bad position inside the condition: its own place, then the condition's.
    let c = by_entity(
        &["Ego"],
        false,
        EntityCondition::ReachPosition {
            position: at(PositionKind::Road {
                road_id: "7".into(),
                s: 1.0,
                t: 0.0,
                orientation: None,
            }),
            tolerance: 1.0,
        },
    );
    assert_eq!(
        eval_error(&w, &c),
        "expected an existing road, found road id \"7\" at test.xosc:7:9 (in condition at test.xosc:7:9)"
    );
}
