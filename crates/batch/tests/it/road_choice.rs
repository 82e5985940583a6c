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
//!
//! The equivalents of ASAM's EndOfTrafficJamParameterSet and
//! SlowPrecedingVehicleStochasticParameterSet (`files/asam_*_set.xosc`) sweep the engine's
//! EndOfTrafficJam equivalent over two roads and over drawn speeds.

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

/// The equivalent of ASAM's EndOfTrafficJamParameterSet (`files/asam_end_of_traffic_jam_set.xosc`
/// over the engine's `asam_end_of_traffic_jam.xosc`): both roads run to the stop trigger
/// (SimulationTime > 40: 40.05 s). Ego (27.778 m/s, no controller model: the default controller
/// drives it) runs into A1 (22.222 m/s, braking at 5 m/s² to 19.444 m/s from 4.55 s), on either
/// road in its lane: Ego's front x + 3.75 (box centre 1.5, length 4.5) meets A1's rear
/// x_A1 − 0.85 when 1003.75 + 27.778·t = 1313.4794 + 19.444·(t − 5.15) − 0.85, t = 25.047 s
/// (A1 at 1313.4794 m at 5.15 s: engine field test asam_traffic_jams): the first frame with
/// the boxes overlapping is 25.05 s.
#[test]
fn the_end_of_traffic_jam_parameter_set_sweeps_both_roads() {
    let plan = Plan::load(&file("asam_end_of_traffic_jam_set.xosc")).unwrap();
    assert_eq!(plan.parameters, ["Road_Logics", "Road_SceneGraph"]);
    assert!(plan.warnings.is_empty());
    both_roads_run_into_a1(&plan);
}

/// ASAM's 1.3 pair: its EndOfTrafficJam no longer declares Road_SceneGraph, which its
/// parameter set still assigns. The assignment is a warning at its ParameterValueSet (it
/// replaces no ParameterDeclaration, OpenSCENARIO XML 1.3 §9.3) and the sweep runs as the 1.2
/// pair does (the declared Road_SceneGraph is used nowhere: the same two runs, by hand above).
#[test]
fn the_1_3_end_of_traffic_jam_parameter_set_warns_of_its_undeclared_scene_graph_and_runs() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("asam_1_3_end_of_traffic_jam");
    std::fs::create_dir_all(&dir).unwrap();
    let field = Path::new(env!("CARGO_MANIFEST_DIR")).join("../engine/tests/files/field");
    for road in ["rq31_straight.xodr", "rq36_straight.xodr"] {
        std::fs::copy(field.join(road), dir.join(road)).unwrap();
    }
    let scenario = std::fs::read_to_string(field.join("asam_end_of_traffic_jam.xosc")).unwrap();
    let declaration = "    <ParameterDeclaration name=\"Road_SceneGraph\" parameterType=\"string\" value=\"rq31_straight.osgb\"/>\n";
    assert!(scenario.contains(declaration));
    std::fs::write(
        dir.join("asam_end_of_traffic_jam.xosc"),
        // The 1.3 scenario: neither the declaration nor its SceneGraphFile.
        scenario
            .replace(declaration, "")
            .replace("<SceneGraphFile filepath=\"$Road_SceneGraph\"/>", ""),
    )
    .unwrap();
    let set = std::fs::read_to_string(file("asam_end_of_traffic_jam_set.xosc")).unwrap();
    let set = set.replace(
        "../../../engine/tests/files/field/asam_end_of_traffic_jam.xosc",
        "asam_end_of_traffic_jam.xosc",
    );
    std::fs::write(dir.join("set.xosc"), &set).unwrap();
    let plan = Plan::load(&dir.join("set.xosc")).unwrap();
    assert_eq!(plan.parameters, ["Road_Logics", "Road_SceneGraph"]);
    assert_eq!(plan.warnings.len(), 1, "{:?}", plan.warnings);
    let w = &plan.warnings[0];
    assert!(
        w.message.starts_with(
            "the scenario declares no global parameter 'Road_SceneGraph' (Road_Logics, Ego_Speed"
        ),
        "{w}"
    );
    // The first ParameterValueSet's DeterministicMultiParameterDistribution, line 11.
    assert_eq!(w.pos.line, 11, "{w}");
    both_roads_run_into_a1(&plan);
}

/// Both variants of the EndOfTrafficJam set run to the stop trigger with Ego into A1 (above).
fn both_roads_run_into_a1(plan: &Plan) {
    let table = run(plan, &Options::default(), &|_, _| {}).expect("the batch runs");
    assert_eq!(table.rows.len(), 2);
    for row in &table.rows {
        let o = row
            .result
            .as_ref()
            .unwrap_or_else(|e| panic!("variant {}: {e}", row.variant));
        assert_eq!(o.stop, Some(StopReason::StopTrigger));
        assert!((o.end_time - 40.05).abs() < TIME_TOL, "{}", o.end_time);
        let first = o.first_collision_time.expect("Ego runs into A1");
        assert!((first - 25.05).abs() < TIME_TOL, "{first}");
    }
    assert!(summary(&table).starts_with("2 variants, 0 failed"));
}

/// The equivalent of ASAM's SlowPrecedingVehicleStochasticParameterSet
/// (`files/asam_stochastic_set.xosc`): 100 runs, Ego_Speed from the weighted set (weights 1, 3,
/// 5, 10, 10, 5, 1 of 35), A1_Speed1 normal (22.222, σ = √10) within [15, 30]; every variant
/// runs, and the plan is the same on every load (randomSeed 1).
#[test]
fn the_stochastic_parameter_set_draws_within_its_distributions_and_runs() {
    let plan = Plan::load(&file("asam_stochastic_set.xosc")).unwrap();
    assert_eq!(plan.parameters, ["Ego_Speed", "A1_Speed1"]);
    assert_eq!(plan.variants.len(), 100);
    let again = Plan::load(&file("asam_stochastic_set.xosc")).unwrap();
    assert_eq!(plan.variants, again.variants);
    let value =
        |v: &std::collections::BTreeMap<String, String>, k: &str| -> f64 { v[k].parse().unwrap() };
    let set = [10.0, 22.0, 25.0, 27.0, 28.0, 40.0, 60.0];
    let mut common = 0;
    let mut sum = 0.0;
    for v in &plan.variants {
        let ego = value(v, "Ego_Speed");
        assert!(set.iter().any(|s| (s - ego).abs() < 1e-12), "{ego}");
        if ego == 27.0 || ego == 28.0 {
            common += 1;
        }
        let a1 = value(v, "A1_Speed1");
        assert!((15.0..=30.0).contains(&a1), "{a1}");
        sum += a1;
    }
    // 27 or 28 with probability 20/35: 57.1 of 100 expected, σ = √(100·0.571·0.429) = 4.95;
    // within 4σ. The mean of the truncated normal (cut at −2.28σ and +2.46σ) is 0.033 above
    // 22.222, the sample mean's σ is √10/10 = 0.32: within 4σ.
    assert!((37..=77).contains(&common), "{common}");
    assert!((sum / 100.0 - 22.222).abs() < 1.3, "{}", sum / 100.0);
    let table = run(&plan, &Options::default(), &|_, _| {}).unwrap();
    assert!(
        summary(&table).starts_with("100 variants, 0 failed"),
        "{}",
        summary(&table)
    );
}
