//! `oscsim validate FILE...`: load each scenario with its catalogs and road network and
//! report OK or the error (file:line:col, element, what was expected, and the source lines
//! with the offending span marked, `snippet.rs`); exit status 1 when any file fails.
//! `--print` shows the resolved model, `--param NAME=VALUE` overrides a global parameter
//! (OpenSCENARIO 1.3 §9.1). A `.osc` file is checked as OpenSCENARIO DSL (`--syntax-only`:
//! parsed only); see `dsl.rs`.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use scenario::Scenario;

/// Arguments of `oscsim validate`.
#[derive(clap::Args, Debug)]
#[command(
    after_help = "Exit status: 0 when every file loads, 1 when any fails, 2 on a usage error."
)]
pub struct ValidateArgs {
    /// Scenario files (.xosc); a ParameterValueDistribution file loads its ScenarioFile.
    #[arg(required = true)]
    files: Vec<PathBuf>,
    /// Print the resolved scenario model of each file that loads.
    #[arg(long)]
    print: bool,
    /// Override a global parameter, NAME=VALUE (repeatable).
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = parse_param)]
    params: Vec<(String, String)>,
    /// Do not list warnings (deprecated forms, features newer than the declared version).
    #[arg(long)]
    quiet: bool,
    /// OpenSCENARIO DSL files (.osc): parse only and report every syntax error.
    #[arg(long)]
    syntax_only: bool,
}

/// Splits `NAME=VALUE`.
fn parse_param(text: &str) -> Result<(String, String), String> {
    match text.split_once('=') {
        Some((name, value)) if !name.trim().is_empty() => Ok((
            name.trim().trim_start_matches('$').to_owned(),
            value.to_owned(),
        )),
        _ => Err(format!("expected NAME=VALUE, found '{text}'")),
    }
}

/// Runs `oscsim validate`.
pub fn run(args: ValidateArgs) -> anyhow::Result<ExitCode> {
    let stdout = std::io::stdout();
    let all_ok = validate_all(&args, &mut stdout.lock())?;
    Ok(if all_ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// Validates every file of `args`, then, for more than one, a summary line; `true` when all
/// load.
fn validate_all(args: &ValidateArgs, out: &mut impl Write) -> anyhow::Result<bool> {
    let mut failed = 0;
    for file in &args.files {
        if !validate_file(file, args, out)? {
            failed += 1;
        }
    }
    if args.files.len() > 1 {
        writeln!(
            out,
            "{} of {} files loaded, {failed} failed",
            args.files.len() - failed,
            args.files.len()
        )?;
    }
    Ok(failed == 0)
}

/// Validates one file, writing its report to `out`; `true` when it loads.
fn validate_file(file: &Path, args: &ValidateArgs, out: &mut impl Write) -> anyhow::Result<bool> {
    let is_dsl = file.extension().is_some_and(|e| e == "osc");
    if is_dsl && args.syntax_only {
        return crate::dsl::validate_syntax(file, out);
    }
    if is_dsl {
        return crate::dsl::validate_file(file, out);
    }
    if args.syntax_only {
        writeln!(
            out,
            "FAIL {}\n  error: --syntax-only applies to OpenSCENARIO DSL files (.osc)",
            file.display()
        )?;
        return Ok(false);
    }
    let scenario = match Scenario::load_with_parameters(file, &args.params) {
        Ok(s) => s,
        Err(e) => {
            writeln!(out, "FAIL {}\n  error: {e}", file.display())?;
            if let Some(snippet) = crate::snippet::render(&e.to_string(), e.pos()) {
                write!(out, "{snippet}")?;
            }
            return Ok(false);
        }
    };
    let mut road_warnings = 0;
    if let Some(road) = &scenario.road_network.logic_file {
        match opendrive::RoadNetwork::from_file(road) {
            Ok(network) => road_warnings = network.warnings().len(),
            Err(e) => {
                writeln!(
                    out,
                    "FAIL {}\n  error: road network {}: {e}",
                    file.display(),
                    road.display()
                )?;
                return Ok(false);
            }
        }
    }
    let entities = scenario.entities.scenario_objects.len();
    let stories = scenario.storyboard.stories.len();
    let warnings = scenario.warnings.len() + road_warnings;
    writeln!(
        out,
        "OK   {} (OpenSCENARIO {}.{}, {entities} entities, {stories} stories, {warnings} warnings)",
        file.display(),
        scenario.file_header.rev_major,
        scenario.file_header.rev_minor,
    )?;
    if !args.quiet {
        for w in &scenario.warnings {
            writeln!(out, "  warning: {w}")?;
        }
    }
    if args.print {
        writeln!(out, "{scenario:#?}")?;
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn corpus(rel: &str) -> PathBuf {
        Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../../shared/corpus"
        ))
        .join(rel)
    }

    fn args(files: Vec<PathBuf>, print: bool, params: Vec<(String, String)>) -> ValidateArgs {
        ValidateArgs {
            files,
            print,
            params,
            quiet: false,
            syntax_only: false,
        }
    }

    fn report(path: PathBuf, print: bool, params: Vec<(String, String)>) -> (bool, String) {
        let a = args(vec![path.clone()], print, params);
        let mut out = Vec::new();
        let ok = validate_file(&path, &a, &mut out).unwrap();
        (ok, String::from_utf8(out).unwrap())
    }

    #[test]
    fn a_good_scenario_reports_ok_with_its_counts() {
        let (ok, text) = report(corpus("esmini/xosc/cut-in.xosc"), false, vec![]);
        assert!(ok, "{text}");
        // cut-in.xosc: FileHeader 1.1, two ScenarioObjects (Ego, OverTaker), one Story.
        assert!(text.starts_with("OK   "), "{text}");
        assert!(
            text.contains("(OpenSCENARIO 1.1, 2 entities, 1 stories,"),
            "{text}"
        );
    }

    #[test]
    fn a_broken_scenario_reports_the_missing_file_and_where_it_was_looked_for() {
        let (ok, text) = report(corpus("esmini/xosc/car_walk.xosc"), false, vec![]);
        assert!(!ok);
        assert!(text.starts_with("FAIL "), "{text}");
        assert!(text.contains("expected road network file 'c:/eknabe1/GIT/esmini_dev/resources/xodr/straight_500m.xodr', found no file at "), "{text}");
        assert!(text.contains("car_walk.xosc:10:"), "{text}");
        // The snippet: line 10 of the file with the LogicFile's filepath value marked (column
        // 30 to its closing quote, 59 characters), between lines 9 and 11.
        assert!(text.contains("car_walk.xosc:10:30]"), "{text}");
        assert!(text.contains(" 9 │     <RoadNetwork>\n"), "{text}");
        assert!(
            text.contains(" 10 │         <LogicFile filepath=\"c:/eknabe1/"),
            "{text}"
        );
        // The underline: the gutter's space, 29 characters before column 30, then 59 marks
        // with the label's ┬ in the middle (29 + 1 + 29).
        let marks = format!(
            "·{}{}┬{}\n",
            " ".repeat(1 + 29),
            "─".repeat(29),
            "─".repeat(29)
        );
        assert!(text.contains(&marks), "{text}");
        assert!(text.contains("╰── here"), "{text}");
    }

    #[test]
    fn print_shows_the_resolved_values() {
        let (ok, text) = report(corpus("esmini/xosc/cut-in.xosc"), true, vec![]);
        assert!(ok, "{text}");
        // AbsoluteTargetSpeed ${$EgoSpeed / 3.6} with EgoSpeed 108: 30 m/s.
        assert!(
            text.contains("Absolute(\n") && text.contains("30.0,"),
            "{text}"
        );
    }

    #[test]
    fn param_overrides_a_global_parameter() {
        let params = vec![("EgoSpeed".to_owned(), "72".to_owned())];
        let (ok, text) = report(corpus("esmini/xosc/cut-in.xosc"), true, params);
        assert!(ok, "{text}");
        // 72 km/h / 3.6 = 20 m/s.
        assert!(text.contains("20.0,"), "{text}");
        let bad = vec![("NoSuch".to_owned(), "1".to_owned())];
        let (ok, text) = report(corpus("esmini/xosc/cut-in.xosc"), false, bad);
        assert!(!ok);
        assert!(text.contains("found unknown 'NoSuch'"), "{text}");
    }

    #[test]
    fn several_files_end_with_a_summary_and_fail_if_one_fails() {
        let files = vec![
            corpus("esmini/xosc/cut-in.xosc"),
            corpus("esmini/xosc/auto_light.xosc"),
        ];
        let mut out = Vec::new();
        let ok = validate_all(&args(files, false, vec![]), &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(!ok);
        assert!(text.ends_with("1 of 2 files loaded, 1 failed\n"), "{text}");
    }

    #[test]
    fn param_syntax_is_checked() {
        assert_eq!(
            parse_param("$a=1 2"),
            Ok(("a".to_owned(), "1 2".to_owned()))
        );
        assert!(parse_param("novalue").is_err());
        assert!(parse_param("=3").is_err());
    }
}
