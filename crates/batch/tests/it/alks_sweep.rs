//! Issue 34 class 3 on the field's own distributions: the 15 ALKS (UN R157) variation files
//! published by ASAM (`files/alks/`, MPL-2.0, see its README). Eight of them vary the road
//! file (`RoadNetwork/LogicFile filepath="$Road"`, five roads), two the catalog an entity
//! comes from (`catalogName="$TargetBlocking_Catalog"`), and several include value
//! combinations their template's ConstraintGroups refuse ("It is exepected that these
//! combinations are discarded by a scenario generator by comparing the values to the
//! constraints", 4.4_1's variation file).
//!
//! The variant counts are the products of the distributions written in each file (a
//! DistributionRange lowerLimit..upperLimit by stepWidth has (upper − lower) / step + 1
//! values). No variant fails: a sample of each distribution — the first variant of each road
//! and catalog, and every k-th — runs 0.5 s, each either running or refused.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use batch::{run_variants, Options, Plan};

fn alks(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files/alks")
        .join(format!("ALKS_Scenario_{name}.xosc"))
}

/// Every variation file with its variant count, worked out from the file: roads (5), speeds
/// 5..60 by 5 (12), models (5), the value sets as written.
const DISTRIBUTIONS: [(&str, usize); 15] = [
    ("4.1_1_FreeDriving_Variation", 12),               // 12 speeds
    ("4.1_2_SwervingLeadVehicle_Variation", 300),      // 5 roads × 12 × 5 models
    ("4.1_3_SideVehicle_Variation", 1200),             // 12 × 5 × 5 offsets × 2 lanes × 2
    ("4.2_1_FullyBlockingTarget_Variation", 360),      // 5 × 12 × 6 targets
    ("4.2_2_PartiallyBlockingTarget_Variation", 6120), // 5 × 12 × 6 × 17 offsets −2..2
    ("4.2_3_CrossingPedestrian_Variation", 120),       // 5 × 12 × 2 lanes
    ("4.2_4_MultipleBlockingTargets_Variation", 1800), // 5 × 12 × 6 × 5
    ("4.3_1_FollowLeadVehicleComfortable_Variation", 2400), // 5 × 12 × 5 × 8 offsets
    ("4.3_2_FollowLeadVehicleEmergencyBrake_Variation", 1400), // 5 × 1 × 5 × 7 sets × 8
    (
        "4.3_2_FollowLeadVehicleEmergencyBrake_Variation_Reference",
        3000,
    ), // 5 × 12 × 5 × 1 × 10
    ("4.4_1_CutInNoCollision_Variation", 52500),       // 5 speeds × 5 × 2 × 5 × 7 × 6 × 5
    ("4.5_1_CutOutFullyBlocking_Variation", 8640),     // 12 × 2 × 10 × 6 × 6
    ("4.5_2_CutOutMultipleBlockingTargets_Variation", 43200), // 12 × 2 × 10 × 6 × 6 × 5
    ("4.6_1_ForwardDetectionRange_Variation", 6),      // 2 targets × 3 offsets
    ("4.6_2_LateralDetectionRange_Variation", 2),      // 2 sets
];

/// Variants run per distribution, at most (plus the first of each road and catalog).
const SAMPLE: usize = 24;

#[test]
fn every_alks_distribution_plans_with_its_variant_count() {
    for (name, count) in DISTRIBUTIONS {
        let plan = Plan::load(&alks(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(plan.variants.len(), count, "{name}");
    }
}

#[test]
fn no_variant_of_any_alks_distribution_fails_on_a_file() {
    let options = Options {
        duration: Some(0.5),
        ..Options::default()
    };
    let mut roads_seen = BTreeSet::new();
    for (name, count) in DISTRIBUTIONS {
        let plan = Plan::load(&alks(name)).unwrap();
        // The first variant of each road and each catalog, then every k-th.
        let mut picked = BTreeSet::new();
        let mut firsts = BTreeSet::new();
        for (i, v) in plan.variants.iter().enumerate() {
            let key = (
                v.get("Road").cloned(),
                v.get("TargetBlocking_Catalog").cloned(),
            );
            if firsts.insert(key) {
                picked.insert(i as u64);
            }
            if let Some(road) = v.get("Road") {
                roads_seen.insert(road.clone());
            }
        }
        picked.extend((0..count as u64).step_by(count.div_ceil(SAMPLE)));
        let picked: Vec<u64> = picked.into_iter().collect();
        let table = run_variants(&plan, &options, &picked, &|_, _| {}).unwrap();
        for row in &table.rows {
            if let Err(e) = &row.result {
                assert!(row.refused(), "{name} variant {}: {e}", row.variant);
            }
        }
    }
    // The five roads of the variation files, each loaded by some variant.
    assert_eq!(roads_seen.len(), 5, "{roads_seen:?}");
}

#[test]
fn the_templates_constraints_refuse_what_4_3_1_varies_outside_them() {
    // LeadVehicle_Init_LateralOffset_m runs −1.75..1.75 by 0.5 (8 values); its constraint is
    // greaterThan −1.75 and lessOrEqual 1.75, so −1.75 is refused: 2400 / 8 = 300 variants.
    let plan = Plan::load(&alks("4.3_1_FollowLeadVehicleComfortable_Variation")).unwrap();
    let refused: Vec<usize> = (0..plan.variants.len())
        .filter(|&i| {
            let params: Vec<(String, String)> = plan.variants[i].clone().into_iter().collect();
            plan.scenario
                .with_parameters(&params)
                .is_err_and(|e| matches!(e.kind(), scenario::ErrorKind::ConstraintViolated { .. }))
        })
        .collect();
    assert_eq!(refused.len(), 300);
    assert!(refused
        .iter()
        .all(|&i| plan.variants[i]["LeadVehicle_Init_LateralOffset_m"] == "-1.75"));
}
