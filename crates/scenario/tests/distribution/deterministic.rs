//! Deterministic parameter value distributions (OpenSCENARIO 1.3 §9.5): counts and values of
//! the cross product, worked out by hand.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use scenario::distribution::DistributionPlan;

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files/distribution")
        .join(name)
}

fn load(name: &str) -> DistributionPlan {
    DistributionPlan::load(&fixture(name)).unwrap_or_else(|e| panic!("{e}"))
}

fn run(pairs: &[(&str, &str)]) -> BTreeMap<String, String> {
    pairs
        .iter()
        .map(|(k, v)| ((*k).to_owned(), (*v).to_owned()))
        .collect()
}

#[test]
fn esmini_cut_in_parameter_set_is_the_cross_product() {
    // The file (with a UTF-8 BOM) has, in document order:
    //   ValueSetDistribution: 2 sets {Host=car_blue, Target=car_yellow}, {Target=van_red}
    //   EgoSpeed: DistributionSet {70.0, 110.0}
    //   TargetSpeedFactor: DistributionRange 1.1 … 1.5 by 0.2 = {1.1, 1.3, 1.5}
    // → 2 · 2 · 3 = 12 runs, the first distribution varying slowest.
    let plan = load("cut-in_parameter_set.xosc");
    assert_eq!(plan.scenario_file, fixture("cut-in.xosc"));
    assert_eq!(plan.runs.len(), 12);
    let mut expected = Vec::new();
    for set in [
        &[("HostVehicle", "car_blue"), ("TargetVehicle", "car_yellow")][..],
        &[("TargetVehicle", "van_red")],
    ] {
        for speed in ["70.0", "110.0"] {
            for factor in ["1.1", "1.3", "1.5"] {
                let mut pairs = set.to_vec();
                pairs.push(("EgoSpeed", speed));
                pairs.push(("TargetSpeedFactor", factor));
                expected.push(run(&pairs));
            }
        }
    }
    assert_eq!(plan.runs, expected);
}

#[test]
fn ranges_include_a_reached_upper_limit_only() {
    // Offset: 0 … 1 by 0.25 = {0, 0.25, 0.5, 0.75, 1} (5 values, 1 reached exactly).
    // Gap: 0 … 1 by 0.3 = {0, 0.3, 0.6, 0.9} (4 values; 1.2 > 1). 0.3·3 = 0.8999999999999999
    // in doubles, written 0.9 after the 12-digit rounding.
    // → 5 · 4 = 20 runs; the relative ScenarioFile resolves against the fixture folder.
    let plan = load("ranges.xosc");
    assert_eq!(plan.scenario_file, fixture("../scenarios/straight.xosc"));
    assert_eq!(plan.runs.len(), 20);
    let offsets: Vec<&str> = plan
        .runs
        .iter()
        .step_by(4)
        .map(|r| r["Offset"].as_str())
        .collect();
    assert_eq!(offsets, ["0", "0.25", "0.5", "0.75", "1"]);
    let gaps: Vec<&str> = plan.runs[..4].iter().map(|r| r["Gap"].as_str()).collect();
    assert_eq!(gaps, ["0", "0.3", "0.6", "0.9"]);
    assert_eq!(plan.runs[19], run(&[("Offset", "1"), ("Gap", "0.9")]));
}

#[test]
fn no_distribution_gives_one_run_with_the_defaults() {
    let plan = load("empty_deterministic.xosc");
    // An absolute ScenarioFile stays as written.
    assert_eq!(plan.scenario_file, PathBuf::from("/abs/scenario.xosc"));
    assert_eq!(plan.runs, vec![BTreeMap::new()]);
}

#[test]
fn a_range_of_one_value_and_a_set_in_document_order() {
    // Range 5 … 5 by 1 = {5}; then the set {a, b, c}: 1 · 3 = 3 runs.
    let text = r#"<OpenSCENARIO><FileHeader/><ParameterValueDistribution>
        <ScenarioFile filepath="s.xosc"/>
        <Deterministic>
          <DeterministicSingleParameterDistribution parameterName="P">
            <DistributionRange stepWidth="1"><Range lowerLimit="5" upperLimit="5"/></DistributionRange>
          </DeterministicSingleParameterDistribution>
          <DeterministicSingleParameterDistribution parameterName="Q">
            <DistributionSet><Element value="a"/><Element value="b"/><Element value="c"/></DistributionSet>
          </DeterministicSingleParameterDistribution>
        </Deterministic></ParameterValueDistribution></OpenSCENARIO>"#;
    let plan = DistributionPlan::from_text(text, Path::new("dir/d.xosc"))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(plan.scenario_file, PathBuf::from("dir/s.xosc"));
    let expected: Vec<_> = ["a", "b", "c"]
        .iter()
        .map(|q| run(&[("P", "5"), ("Q", q)]))
        .collect();
    assert_eq!(plan.runs, expected);
}
