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

#[test]
fn an_undeclared_parameter_is_refused_at_its_distribution() {
    let body = format!(
        "<ScenarioFile filepath=\"following.xosc\"/>\n<Deterministic>\n  {}\n</Deterministic>",
        SET_P.replace("{P}", "Speed")
    );
    assert_eq!(
        error("undeclared", &body),
        "expected a global parameter of the scenario (EgoSpeed, TargetSpeed, Gap), found 'Speed' at dist.xosc:6:3"
    );
    // batch::Error: kind() names the stage and its own kind, pos() the distribution's element
    // (line 6, column 3 of the file as written by `distribution`, as in the message).
    let e = Plan::load(&distribution("undeclared_kind", &body)).unwrap_err();
    assert!(matches!(
        e.kind(),
        batch::ErrorKind::Plan(batch::PlanErrorKind::UndeclaredParameter { name, .. }) if name == "Speed"
    ));
    let pos = e.pos().expect("the distribution's element");
    assert_eq!((pos.line, pos.col), (6, 3));
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
