//! Issue 34 class 3: every variant resolves its own files from its own parameter values
//! (OpenSCENARIO 1.3 §9.1: a parameter may stand in any attribute, `RoadNetwork/LogicFile`
//! and a catalog `Directory` included), shares a road network with the variants that name
//! the same file, and is refused — not failed — when its values break the scenario's own
//! ConstraintGroups.
//!
//! `files/roads.xosc` varies `files/road_choice.xosc` over two bundled roads
//! (straight_500m.xodr, straight_300m.xodr), two vehicle catalog directories (short: a 5 m
//! car, long: 9 m) and three speeds, 40 m/s breaking the `Speed` constraint
//! (greaterThan 0, lessOrEqual 30). Ego starts at s = 10 in lane -1 and the run stops when it
//! reaches the end of its road.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use batch::{run, summary, Options, Plan, StopReason, REFUSED_STOP};

fn file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files")
        .join(name)
}

/// Ego's reference point moves exactly v · 0.05 m per step (1 or 0.5 m: exact in binary), so
/// it reaches s = L in a step and the stop trigger fires then.
const TIME_TOL: f64 = 1e-9;

#[test]
fn each_variant_runs_on_the_road_its_parameters_name() {
    let plan = Plan::load(&file("roads.xosc")).unwrap();
    assert_eq!(plan.parameters, ["Road", "Catalogs", "Speed"]);
    let table = run(&plan, &Options::default(), &|_, _| {}).unwrap();
    assert_eq!(table.rows.len(), 12);
    for row in &table.rows {
        let (road, speed) = (&row.params[0], row.params[2].parse::<f64>().unwrap());
        if speed > 30.0 {
            assert!(row.refused(), "variant {}", row.variant);
            assert_eq!(row.stop_reason(), Some(REFUSED_STOP));
            let message = row.result.as_ref().unwrap_err();
            let at = format!("{}:11:5", file("road_choice.xosc").display());
            assert_eq!(
                *message,
                format!(
                    "refused by constraints: expected parameter Speed greaterThan 0 and \
                     lessOrEqual 30, found 40 at {at}"
                )
            );
            continue;
        }
        // The end of the road is L − 10 m ahead: (500 − 10) / v or (300 − 10) / v.
        let length = if road == "straight_500m.xodr" {
            500.0
        } else {
            300.0
        };
        let o = row
            .result
            .as_ref()
            .unwrap_or_else(|e| panic!("variant {}: {e}", row.variant));
        assert_eq!(o.stop, Some(StopReason::StopTrigger));
        let expected = (length - 10.0) / speed;
        assert!(
            (o.end_time - expected).abs() < TIME_TOL,
            "variant {} on {road} at {speed} m/s: ended at {}, expected {expected}",
            row.variant,
            o.end_time
        );
    }
    assert!(summary(&table)
        .starts_with("12 variants, 0 failed, 4 refused by constraints, 0 with a collision"));
}

#[test]
fn variants_get_their_own_catalogs_and_share_a_road_only_where_the_file_is_the_same() {
    let plan = Plan::load(&file("roads.xosc")).unwrap();
    let variant = |i: usize| {
        let params: Vec<(String, String)> = plan.variants[i].clone().into_iter().collect();
        plan.scenario.with_parameters(&params).unwrap()
    };
    let length = |s: &scenario::Scenario| match &s.entities.scenario_objects[0].entity_object {
        scenario::EntityObject::Vehicle(v) => v.bounding_box.length,
        other => panic!("expected a vehicle, found {other:?}"),
    };
    // Variants 0 (500 m road, short catalog), 3 (500 m, long), 6 (300 m, short).
    let (a, b, c) = (variant(0), variant(3), variant(6));
    assert_eq!((length(&a), length(&b), length(&c)), (5.0, 9.0, 5.0));
    let (na, nb, nc) = (
        plan.network_for(&a).unwrap(),
        plan.network_for(&b).unwrap(),
        plan.network_for(&c).unwrap(),
    );
    // One network per file: the template's road (the 500 m one) serves variants 0 and 3.
    assert!(Arc::ptr_eq(&na, &plan.network) && Arc::ptr_eq(&na, &nb));
    assert!(!Arc::ptr_eq(&na, &nc));
    assert_eq!(na.road("1").map(|r| r.length), Some(500.0));
    assert_eq!(nc.road("1").map(|r| r.length), Some(300.0));
}
