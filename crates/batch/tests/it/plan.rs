//! Loading a batch: bad distributions are refused with file:line:col before any variant runs,
//! and stochastic distributions give the same variants on every run.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use std::path::{Path, PathBuf};

use batch::Plan;

/// A folder with following.xosc and its road, and a distribution file `name` with `body` inside
/// `<ParameterValueDistribution>` (the body starts on line 4).
fn distribution(name: &str, body: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("batch_plan")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let files = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files");
    for f in ["following.xosc", "straight_500m.xodr"] {
        std::fs::copy(files.join(f), dir.join(f)).unwrap();
    }
    let path = dir.join("dist.xosc");
    let text = format!(
        "<OpenSCENARIO>\n<FileHeader revMajor=\"1\" revMinor=\"3\" date=\"2026-11-26T12:00:00\" description=\"\" author=\"\"/>\n<ParameterValueDistribution>\n{body}\n</ParameterValueDistribution>\n</OpenSCENARIO>\n"
    );
    std::fs::write(&path, text).unwrap();
    path
}

fn error(name: &str, body: &str) -> String {
    let path = distribution(name, body);
    let message = Plan::load(&path).unwrap_err().to_string();
    // Messages name the file by the path it was opened with; compare from the file name on.
    message.replace(&path.display().to_string(), "dist.xosc")
}

const SET_P: &str = "<DeterministicSingleParameterDistribution parameterName=\"{P}\"><DistributionSet><Element value=\"1\"/></DistributionSet></DeterministicSingleParameterDistribution>";

/// A varied parameter the scenario does not declare is a warning, not an error (OpenSCENARIO
/// XML 1.3 §9.3: a distribution's value replaces a ParameterDeclaration's, so a name none has
/// replaces nothing; ASAM's own 1.3 EndOfTrafficJamParameterSet varies one its scenario no
/// longer declares). Its values stay in the results table and change nothing: the variant runs
/// as the template does with its declared values (here EgoSpeed set to its declared 25).
#[test]
fn an_undeclared_parameter_is_a_warning_at_its_distribution_and_varies_nothing() {
    let body = format!(
        "<ScenarioFile filepath=\"following.xosc\"/>\n<Deterministic>\n  {}\n</Deterministic>",
        SET_P.replace("{P}", "Speed")
    );
    let path = distribution("undeclared", &body);
    let plan = Plan::load(&path).unwrap();
    assert_eq!(plan.parameters, ["Speed"]);
    assert_eq!(plan.warnings.len(), 1);
    let w = plan.warnings[0]
        .to_string()
        .replace(&path.display().to_string(), "dist.xosc");
    assert_eq!(
        w,
        "the scenario declares no global parameter 'Speed' (EgoSpeed, TargetSpeed, Gap): its values vary nothing at dist.xosc:6:3"
    );
    let declared = format!(
        "<ScenarioFile filepath=\"following.xosc\"/>\n<Deterministic>\n  {}\n</Deterministic>",
        SET_P.replace("{P}", "EgoSpeed").replace("\"1\"", "\"25\"")
    );
    let template = Plan::load(&distribution("declared_default", &declared)).unwrap();
    assert!(template.warnings.is_empty());
    let options = batch::Options::default();
    let a = batch::run(&plan, &options, &|_, _| {}).unwrap();
    let b = batch::run(&template, &options, &|_, _| {}).unwrap();
    assert_eq!(a.rows[0].params, ["1"]);
    let (a, b) = (
        a.rows[0].result.as_ref().unwrap(),
        b.rows[0].result.as_ref().unwrap(),
    );
    assert_eq!(a.stop, b.stop);
    assert_eq!(a.end_time.to_bits(), b.end_time.to_bits());
    assert_eq!(
        a.first_collision_time.map(f64::to_bits),
        b.first_collision_time.map(f64::to_bits)
    );
}

#[test]
fn a_missing_scenario_file_is_refused_at_its_element() {
    let body = format!(
        "<ScenarioFile filepath=\"nowhere.xosc\"/>\n<Deterministic>{}</Deterministic>",
        SET_P.replace("{P}", "Gap")
    );
    let e = error("missing", &body);
    assert!(
        e.starts_with("expected an existing ScenarioFile, found none at "),
        "{e}"
    );
    assert!(
        e.ends_with("nowhere.xosc (ScenarioFile at dist.xosc:4:1)"),
        "{e}"
    );
}

#[test]
fn empty_sets_and_bad_step_widths_are_refused_with_their_positions() {
    let empty = "<ScenarioFile filepath=\"following.xosc\"/>\n<Deterministic><DeterministicSingleParameterDistribution parameterName=\"Gap\"><DistributionSet/></DeterministicSingleParameterDistribution></Deterministic>";
    assert_eq!(
        error("empty", empty),
        "expected <Element> in <DistributionSet>, found none at dist.xosc:5:78"
    );
    for (name, width) in [("zero_step", "0"), ("negative_step", "-2")] {
        let body = format!(
            "<ScenarioFile filepath=\"following.xosc\"/>\n<Deterministic><DeterministicSingleParameterDistribution parameterName=\"Gap\"><DistributionRange stepWidth=\"{width}\"><Range lowerLimit=\"0\" upperLimit=\"1\"/></DistributionRange></DeterministicSingleParameterDistribution></Deterministic>"
        );
        assert_eq!(
            error(name, &body),
            format!("expected a number > 0 for DistributionRange@stepWidth, found '{width}' at dist.xosc:5:97")
        );
    }
}

/// 2000 draws of NormalDistribution(expectedValue 25, variance 4) with randomSeed 42. The
/// sample mean of n draws has standard error σ/√n = 2/√2000 = 0.0447: within 4 standard errors
/// (0.179) of 25 unless a 1-in-15,000 event. The sample variance has standard error
/// σ²·√(2/(n−1)) = 4·0.0316 = 0.1265: the sample standard deviation lies within
/// √(4 ± 4·0.1265)… i.e. 2 ± 0.13 at 4 standard errors.
#[test]
fn a_seeded_normal_distribution_repeats_and_has_its_moments() {
    let body = "<ScenarioFile filepath=\"following.xosc\"/>\n<Stochastic numberOfTestRuns=\"2000\" randomSeed=\"42\"><StochasticDistribution parameterName=\"EgoSpeed\"><NormalDistribution expectedValue=\"25\" variance=\"4\"/></StochasticDistribution></Stochastic>";
    let path = distribution("normal", body);
    let plan = Plan::load(&path).unwrap();
    let again = Plan::load(&path).unwrap();
    assert_eq!(plan.variants, again.variants, "same seed, same variants");
    let draws: Vec<f64> = (0..plan.variants.len())
        .map(|i| plan.values(i)[0].parse().unwrap())
        .collect();
    assert_eq!(draws.len(), 2000);
    let mean = draws.iter().sum::<f64>() / 2000.0;
    let sd = (draws.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 1999.0).sqrt();
    assert!((mean - 25.0).abs() < 0.179, "mean {mean}");
    assert!((sd - 2.0).abs() < 0.13, "sd {sd}");
}
