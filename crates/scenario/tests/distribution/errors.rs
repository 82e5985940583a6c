//! Bad distribution files never panic or hang: each case asserts the exact message with
//! file:line:col (1-based) of the element or attribute at fault.

use std::path::Path;

use scenario::distribution::{DistributionErrorKind, DistributionPlan, MAX_ATTEMPTS, MAX_RUNS};

const FILE: &str = "bad.xosc";

/// Wraps `body` (the content of `<ParameterValueDistribution>`) so that it starts on row 3.
/// Columns below are 1-based character counts of the element's `<` or the attribute's name
/// on its row (counted with Python's `str.index(...) + 1` on the row's text).
fn wrap(body: &str) -> String {
    format!("<OpenSCENARIO><FileHeader/>\n<ParameterValueDistribution><ScenarioFile filepath=\"s.xosc\"/>\n{body}\n</ParameterValueDistribution></OpenSCENARIO>")
}

fn error_of(text: &str) -> String {
    match DistributionPlan::from_text(text, Path::new(FILE)) {
        Ok(plan) => panic!("expected an error, got {} runs", plan.runs.len()),
        Err(e) => e.to_string(),
    }
}

/// One case: the name, the file text, the exact message.
macro_rules! error_case {
    ($name:ident, $text:expr, $message:expr) => {
        #[test]
        fn $name() {
            assert_eq!(error_of(&$text), $message);
        }
    };
}

error_case!(
    not_well_formed,
    "<OpenSCENARIO>\n  <FileHeader>\n</OpenSCENARIO>",
    "expected well-formed XML, found expected 'FileHeader' tag, not 'OpenSCENARIO' at bad.xosc:3:1"
);
error_case!(
    wrong_root,
    "<OpenDRIVE/>",
    "expected <OpenSCENARIO>, found <OpenDRIVE> at bad.xosc:1:1"
);
error_case!(
    a_scenario_not_a_distribution,
    "<OpenSCENARIO>\n<FileHeader/>\n  <ParameterDeclarations/>\n</OpenSCENARIO>",
    "expected <FileHeader> or <ParameterValueDistribution>, found <ParameterDeclarations> at bad.xosc:3:3"
);
error_case!(
    no_distribution,
    "<OpenSCENARIO><FileHeader/></OpenSCENARIO>",
    "expected <ParameterValueDistribution> in <OpenSCENARIO>, found none at bad.xosc:1:1"
);
error_case!(
    missing_filepath,
    "<OpenSCENARIO><ParameterValueDistribution>\n <ScenarioFile/><Deterministic/></ParameterValueDistribution></OpenSCENARIO>",
    "expected attribute filepath on <ScenarioFile>, found none at bad.xosc:2:2"
);
error_case!(
    missing_definition,
    "<OpenSCENARIO><ParameterValueDistribution><ScenarioFile filepath=\"s\"/></ParameterValueDistribution></OpenSCENARIO>",
    "expected <Deterministic> in <ParameterValueDistribution>, found none at bad.xosc:1:15"
);
error_case!(
    unknown_deterministic_child,
    wrap("<Deterministic><DistributionSet/></Deterministic>"),
    "expected <DeterministicSingleParameterDistribution> or <DeterministicMultiParameterDistribution>, found <DistributionSet> at bad.xosc:3:16"
);
error_case!(
    missing_parameter_name,
    wrap("<Deterministic><DeterministicSingleParameterDistribution><DistributionSet><Element value=\"1\"/></DistributionSet></DeterministicSingleParameterDistribution></Deterministic>"),
    "expected attribute parameterName on <DeterministicSingleParameterDistribution>, found none at bad.xosc:3:16"
);
error_case!(
    empty_distribution_set,
    wrap("<Deterministic><DeterministicSingleParameterDistribution parameterName=\"P\"><DistributionSet/></DeterministicSingleParameterDistribution></Deterministic>"),
    "expected <Element> in <DistributionSet>, found none at bad.xosc:3:76"
);
error_case!(
    zero_step_width,
    wrap("<Deterministic><DeterministicSingleParameterDistribution parameterName=\"P\"><DistributionRange stepWidth=\"0\"><Range lowerLimit=\"0\" upperLimit=\"1\"/></DistributionRange></DeterministicSingleParameterDistribution></Deterministic>"),
    "expected a number > 0 for DistributionRange@stepWidth, found '0' at bad.xosc:3:95"
);
error_case!(
    step_width_not_a_number,
    wrap("<Deterministic><DeterministicSingleParameterDistribution parameterName=\"P\"><DistributionRange stepWidth=\"$step\"><Range lowerLimit=\"0\" upperLimit=\"1\"/></DistributionRange></DeterministicSingleParameterDistribution></Deterministic>"),
    "expected a number > 0 for DistributionRange@stepWidth, found '$step' at bad.xosc:3:95"
);
error_case!(
    inverted_range,
    wrap("<Stochastic numberOfTestRuns=\"1\"><StochasticDistribution parameterName=\"P\"><UniformDistribution><Range lowerLimit=\"2\" upperLimit=\"1\"/></UniformDistribution></StochasticDistribution></Stochastic>"),
    "expected a number ≥ lowerLimit for Range@upperLimit, found '1' at bad.xosc:3:119"
);
error_case!(
    negative_variance,
    wrap("<Stochastic numberOfTestRuns=\"1\"><StochasticDistribution parameterName=\"P\"><NormalDistribution expectedValue=\"0\" variance=\"-1\"/></StochasticDistribution></Stochastic>"),
    "expected a number ≥ 0 for NormalDistribution@variance, found '-1' at bad.xosc:3:114"
);
error_case!(
    negative_test_runs,
    wrap("<Stochastic numberOfTestRuns=\"-3\"><StochasticDistribution parameterName=\"P\"><PoissonDistribution expectedValue=\"1\"/></StochasticDistribution></Stochastic>"),
    "expected an unsignedInt for Stochastic@numberOfTestRuns, found '-3' at bad.xosc:3:13"
);
error_case!(
    zero_weights,
    wrap("<Stochastic numberOfTestRuns=\"1\"><StochasticDistribution parameterName=\"P\"><ProbabilityDistributionSet><Element value=\"a\" weight=\"0\"/></ProbabilityDistributionSet></StochasticDistribution></Stochastic>"),
    "expected weights with a positive, finite sum for ProbabilityDistributionSet@weight, found '0' at bad.xosc:3:76"
);
error_case!(
    user_defined_deterministic,
    wrap("<Deterministic><DeterministicSingleParameterDistribution parameterName=\"P\"><UserDefinedDistribution type=\"sobol\">x</UserDefinedDistribution></DeterministicSingleParameterDistribution></Deterministic>"),
    "expected a distribution oscsim can sample, found <UserDefinedDistribution> of type 'sobol' at bad.xosc:3:76"
);
error_case!(
    user_defined_stochastic,
    wrap("<Stochastic numberOfTestRuns=\"1\"><StochasticDistribution parameterName=\"P\"><UserDefinedDistribution type=\"kde\"/></StochasticDistribution></Stochastic>"),
    "expected a distribution oscsim can sample, found <UserDefinedDistribution> of type 'kde' at bad.xosc:3:76"
);
error_case!(
    parameter_in_two_distributions,
    wrap("<Deterministic>\n<DeterministicSingleParameterDistribution parameterName=\"P\"><DistributionSet><Element value=\"1\"/></DistributionSet></DeterministicSingleParameterDistribution>\n<DeterministicMultiParameterDistribution><ValueSetDistribution><ParameterValueSet><ParameterAssignment parameterRef=\"P\" value=\"2\"/></ParameterValueSet></ValueSetDistribution></DeterministicMultiParameterDistribution></Deterministic>"),
    "expected each parameter in one distribution only, found 'P' again at bad.xosc:5:1"
);
error_case!(
    stochastic_parameter_twice,
    wrap("<Stochastic numberOfTestRuns=\"1\">\n<StochasticDistribution parameterName=\"P\"><PoissonDistribution expectedValue=\"1\"/></StochasticDistribution>\n<StochasticDistribution parameterName=\"P\"><PoissonDistribution expectedValue=\"2\"/></StochasticDistribution></Stochastic>"),
    "expected each parameter in one distribution only, found 'P' again at bad.xosc:5:1"
);
error_case!(
    range_with_too_many_steps,
    wrap("<Deterministic><DeterministicSingleParameterDistribution parameterName=\"P\"><DistributionRange stepWidth=\"1e-9\"><Range lowerLimit=\"0\" upperLimit=\"1\"/></DistributionRange></DeterministicSingleParameterDistribution></Deterministic>"),
    format!("expected at most {MAX_RUNS} parameter sets, found 1000000001 at bad.xosc:3:16")
);
error_case!(
    unreachable_truncation,
    wrap("<Stochastic numberOfTestRuns=\"1\"><StochasticDistribution parameterName=\"P\"><NormalDistribution expectedValue=\"0\" variance=\"1\"><Range lowerLimit=\"50\" upperLimit=\"60\"/></NormalDistribution></StochasticDistribution></Stochastic>"),
    format!("expected a Range the distribution reaches, found no sample inside it in {MAX_ATTEMPTS} draws at bad.xosc:3:34")
);

#[test]
fn cross_product_too_large() {
    // Three sets of 100 values: 100³ = 10⁶ > MAX_RUNS, refused at the third distribution
    // (row 6 = 3 + its index 2 + the opening row of <Deterministic>).
    let values: String = (0..100)
        .map(|i| format!("<Element value=\"{i}\"/>"))
        .collect();
    let single = |name: &str| {
        format!("<DeterministicSingleParameterDistribution parameterName=\"{name}\"><DistributionSet>{values}</DistributionSet></DeterministicSingleParameterDistribution>")
    };
    let body = format!(
        "<Deterministic>\n{}\n{}\n{}</Deterministic>",
        single("A"),
        single("B"),
        single("C")
    );
    let message = error_of(&wrap(&body));
    assert_eq!(
        message,
        format!("expected at most {MAX_RUNS} parameter sets, found 1000000 at bad.xosc:6:1")
    );
}

#[test]
fn too_many_stochastic_runs() {
    let body = "<Stochastic numberOfTestRuns=\"4000000000\"><StochasticDistribution parameterName=\"P\"><PoissonDistribution expectedValue=\"1\"/></StochasticDistribution></Stochastic>";
    let message = error_of(&wrap(body));
    assert_eq!(
        message,
        format!("expected at most {MAX_RUNS} parameter sets, found 4000000000 at bad.xosc:3:13")
    );
}

#[test]
fn missing_file_names_the_file() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/distribution/no_such_file.xosc");
    let err = DistributionPlan::load(&path).expect_err("missing file");
    assert!(matches!(err.kind(), DistributionErrorKind::Io { .. }));
    assert_eq!(err.file(), path);
    assert!(
        err.to_string()
            .starts_with("expected a readable file, found "),
        "{err}"
    );
    assert!(
        err.to_string()
            .ends_with(&format!(" at {}:1:1", path.display())),
        "{err}"
    );
}

proptest::proptest! {
    /// Any prefix of a valid file, and any single byte replaced, gives a plan or an error with a
    /// position inside the text — never a panic.
    #[test]
    fn damaged_files_never_panic(cut in 0usize..2000, at in 0usize..2000, byte in proptest::sample::select(b"<>/\"= x0-".to_vec())) {
        let text = std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/distribution/stochastic_all.xosc"),
        ).unwrap_or_default();
        let mut bytes = text.into_bytes();
        bytes.truncate(cut.min(bytes.len()));
        if let Some(b) = bytes.get_mut(at) {
            *b = byte;
        }
        let damaged = String::from_utf8_lossy(&bytes).into_owned();
        if let Err(e) = DistributionPlan::from_text(&damaged, Path::new(FILE)) {
            let rows = damaged.lines().count().max(1) as u32;
            proptest::prop_assert!(e.pos().line >= 1 && e.pos().line <= rows + 1, "{e}");
        }
    }
}
