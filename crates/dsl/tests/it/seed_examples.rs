//! The seed's (ASAM OpenSCENARIO DSL 2.1 §8.7) code examples parse, check and resolve, and the
//! resolved values satisfy every `keep` of the example, for many seeds.

use std::path::PathBuf;

use dsl::{Resolution, Value};

fn file(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files/seed")
        .join(name)
}

fn resolved(name: &str, seed: u64) -> Resolution {
    let program = dsl::check(&file(name)).unwrap_or_else(|d| panic!("{name}:\n{d}"));
    program
        .resolve(seed)
        .unwrap_or_else(|d| panic!("{name} seed {seed}:\n{d}"))
}

fn get<'r>(r: &'r Resolution, path: &str) -> &'r Value {
    r.get(path).unwrap_or_else(|| panic!("no value at {path}"))
}

fn member(r: &Resolution, path: &str) -> String {
    match get(r, path) {
        Value::Enum { member, .. } => member.clone(),
        other => panic!("{path}: not an enum member: {other:?}"),
    }
}

fn int(r: &Resolution, path: &str) -> i64 {
    match get(r, path) {
        Value::Int(i) => *i,
        other => panic!("{path}: not an integer: {other:?}"),
    }
}

fn metres(r: &Resolution, path: &str) -> f64 {
    match get(r, path) {
        Value::Quantity { si, ty, .. } if ty == "length" => *si,
        other => panic!("{path}: not a length: {other:?}"),
    }
}

fn len(r: &Resolution, path: &str) -> usize {
    match get(r, path) {
        Value::List(items) => items.len(),
        other => panic!("{path}: not a list: {other:?}"),
    }
}

const SEEDS: std::ops::Range<u64> = 0..25;

#[test]
fn code_1_the_three_vehicles_satisfy_every_keep() {
    for seed in SEEDS {
        let r = resolved("vehicles.osc", seed);
        // Constrain vehicle to be a wide car.
        assert_eq!(member(&r, "my_wide_car.vehicle_category"), "car");
        assert!(metres(&r, "my_wide_car.bounding_box.width") >= 1.95);
        assert_eq!(member(&r, "my_wide_car.color"), "maroon");
        assert_eq!(len(&r, "my_wide_car.axles"), 2);
        assert_eq!(int(&r, "my_wide_car.axles[0].number_of_wheels"), 2);
        assert_eq!(int(&r, "my_wide_car.axles[1].number_of_wheels"), 2);
        assert_eq!(
            member(&r, "my_wide_car.intended_infrastructure[0]"),
            "driving"
        );
        // Constrain vehicle to be a motorcycle.
        assert_eq!(member(&r, "my_motorcycle.vehicle_category"), "vru_vehicle");
        assert_eq!(len(&r, "my_motorcycle.axles"), 2);
        assert_eq!(int(&r, "my_motorcycle.axles[0].number_of_wheels"), 1);
        assert_eq!(int(&r, "my_motorcycle.axles[1].number_of_wheels"), 1);
        assert_eq!(
            member(&r, "my_motorcycle.intended_infrastructure[0]"),
            "driving"
        );
        // Constrain vehicle to be a bicycle.
        assert_eq!(member(&r, "my_bicycle.vehicle_category"), "vru_vehicle");
        assert_eq!(len(&r, "my_bicycle.axles"), 2);
        assert_eq!(int(&r, "my_bicycle.axles[0].number_of_wheels"), 1);
        assert_eq!(int(&r, "my_bicycle.axles[1].number_of_wheels"), 1);
        assert_eq!(
            member(&r, "my_bicycle.intended_infrastructure[0]"),
            "biking"
        );
    }
}

#[test]
fn code_1_the_wide_car_is_sampled_within_its_default_range_above_the_hard_bound() {
    // The hard `width >= 1.95m` overrides oscsim's default [1.6m..2.1m]; sampling keeps to
    // the part of the default range that is left: [1.95m, 2.1m].
    let widths: Vec<f64> = SEEDS
        .map(|s| {
            metres(
                &resolved("vehicles.osc", s),
                "my_wide_car.bounding_box.width",
            )
        })
        .collect();
    assert!(
        widths.iter().all(|w| (1.95..=2.1).contains(w)),
        "{widths:?}"
    );
    assert!(
        widths.iter().any(|w| *w != widths[0]),
        "seeds vary the width"
    );
}

#[test]
fn code_2_the_building_has_its_pose_parameter() {
    for seed in SEEDS {
        let r = resolved("location.osc", seed);
        // position_3d and orientation_3d default to zero (nothing constrains my_pose).
        assert_eq!(metres(&r, "my_pose.position.x"), 0.0);
        assert!(
            matches!(get(&r, "my_building"), Value::Compound { ty, .. } if ty == "stationary_object")
        );
        assert!(matches!(get(&r, "my_building.pose"), Value::RunTime(_)));
    }
}

#[test]
fn code_3_prevent_collision_checks_and_resolves() {
    let r = resolved("prevent_collision.osc", 3);
    assert!(
        matches!(get(&r, "prevent_collision.ego"), Value::Compound { ty, .. } if ty == "vehicle")
    );
    assert!(
        matches!(get(&r, "prevent_collision.collision_time"), Value::RunTime(ty) if ty == "time")
    );
}

#[test]
fn code_4_every_vehicle_of_the_group_is_a_bus_or_a_truck() {
    let mut seen = std::collections::BTreeSet::new();
    for seed in SEEDS {
        let r = resolved("driving_alongside_group.osc", seed);
        let n = len(&r, "dut.driving_alongside_group.g.vehicles");
        // oscsim's default group size is [2..4].
        assert!((2..=4).contains(&n), "{n}");
        for i in 0..n {
            let c = member(
                &r,
                &format!("dut.driving_alongside_group.g.vehicles[{i}].vehicle_category"),
            );
            assert!(c == "bus" || c == "truck", "{c}");
            seen.insert(c);
        }
        assert!(
            matches!(get(&r, "dut.driving_alongside_group.r"), Value::RunTime(ty) if ty == "route")
        );
    }
    assert_eq!(seen.len(), 2, "both members are drawn over 25 seeds");
}

#[test]
fn resolution_is_reproducible_for_a_seed() {
    for name in ["vehicles.osc", "driving_alongside_group.osc"] {
        assert_eq!(resolved(name, 42).lines(), resolved(name, 42).lines());
        assert_ne!(resolved(name, 42).lines(), resolved(name, 43).lines());
    }
}
