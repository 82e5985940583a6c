//! `oscsim dsl …`: tools for OpenSCENARIO DSL 2.x files (`.osc`), and the checks behind
//! `oscsim validate FILE.osc` (names, types, units, modifiers, constraints) and
//! `oscsim validate --syntax-only`. Glue only: parsing, checking, solving, diagnostics and
//! formatting live in the `dsl` crate. `oscsim dsl resolve FILE.osc --seed N` prints the value the
//! constraint solver chose for every field (`path = value`, numbers in SI units).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Context;
use clap::Subcommand;

/// `oscsim dsl` subcommands.
#[derive(Subcommand, Debug)]
pub enum DslCommand {
    /// Print an .osc file in canonical format (4-space blocks, one space around operators,
    /// comments and blank lines kept); idempotent.
    #[command(
        after_help = "Exit status: 0 formatted (or already formatted with --check), 1 syntax \
                            errors or, with --check, a file not in canonical format, 2 usage error."
    )]
    Fmt(FmtArgs),
    /// Check an .osc file and print the values the constraint solver chose for every field of
    /// every global, top-level field and scenario (`path = value`, numbers in SI units).
    #[command(
        after_help = "Exit status: 0 resolved, 1 invalid file or unsatisfiable constraints, 2 usage error."
    )]
    Resolve(ResolveArgs),
}

/// Arguments of `oscsim dsl resolve`.
#[derive(clap::Args, Debug)]
pub struct ResolveArgs {
    /// The OpenSCENARIO DSL file.
    file: PathBuf,
    /// Seed of the sampling of values the constraints leave free (same seed, same values).
    #[arg(long, default_value_t = 0)]
    seed: u64,
}

/// Arguments of `oscsim dsl fmt`.
#[derive(clap::Args, Debug)]
pub struct FmtArgs {
    /// OpenSCENARIO DSL files.
    #[arg(required = true)]
    files: Vec<PathBuf>,
    /// Rewrite the files in place instead of printing them.
    #[arg(long, conflicts_with = "check")]
    write: bool,
    /// Print nothing; exit 1 when a file is not in canonical format.
    #[arg(long)]
    check: bool,
}

/// Runs an `oscsim dsl` subcommand.
pub fn run(command: DslCommand) -> anyhow::Result<ExitCode> {
    match command {
        DslCommand::Fmt(args) => fmt(&args, &mut std::io::stdout().lock()),
        DslCommand::Resolve(args) => resolve(&args, &mut std::io::stdout().lock()),
    }
}

fn resolve(args: &ResolveArgs, out: &mut impl Write) -> anyhow::Result<ExitCode> {
    match dsl::check(&args.file).and_then(|p| p.resolve(args.seed)) {
        Ok(r) => {
            for line in r.lines() {
                writeln!(out, "{line}")?;
            }
            Ok(ExitCode::SUCCESS)
        }
        Err(e) => {
            write_diagnostics(e.diagnostics(), out)?;
            Ok(ExitCode::from(1))
        }
    }
}

/// `oscsim validate FILE.osc`: the full check (imports, names, types and units, arguments,
/// modifiers, constraints solved once); `OK` or `FAIL` with every error; `true` when it checks.
pub fn validate_file(file: &Path, out: &mut impl Write) -> anyhow::Result<bool> {
    match dsl::check(file) {
        Ok(p) => {
            let files = p.files().len() - p.model.library_files as usize;
            writeln!(
                out,
                "OK   {} (OpenSCENARIO DSL, {files} file(s), {} constraints)",
                file.display(),
                p.templates.len()
            )?;
            Ok(true)
        }
        Err(e) => {
            let d = e.diagnostics();
            writeln!(out, "FAIL {} ({} errors)", file.display(), d.items.len())?;
            write_diagnostics(d, out)?;
            Ok(false)
        }
    }
}

/// Writes every semantic error as a report with its source lines and labelled spans (the
/// other constraints of a conflict labelled too); lines are not wrapped below 160 columns, so a
/// message stays on one line for tools that grep it.
pub fn write_diagnostics(d: &dsl::Diagnostics, out: &mut impl Write) -> anyhow::Result<()> {
    let handler =
        miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor())
            .with_width(160);
    for report in d.reports() {
        let mut text = String::new();
        handler.render_report(&mut text, report.as_ref())?;
        write!(out, "{text}")?;
    }
    Ok(())
}

fn read(file: &Path) -> anyhow::Result<String> {
    std::fs::read_to_string(file).with_context(|| format!("cannot read {}", file.display()))
}

/// Writes every syntax error of `source` as a report with the source line and a labelled span.
fn write_errors(
    file: &Path,
    source: &str,
    errors: &[dsl::syntax::SyntaxError],
    out: &mut impl Write,
) -> anyhow::Result<()> {
    let handler =
        miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor());
    let name = file.display().to_string();
    for error in errors {
        let report = error.to_report(&name, source);
        let mut text = String::new();
        handler.render_report(&mut text, report.as_ref())?;
        write!(out, "{text}")?;
    }
    Ok(())
}

fn fmt(args: &FmtArgs, out: &mut impl Write) -> anyhow::Result<ExitCode> {
    let mut ok = true;
    for file in &args.files {
        let source = read(file)?;
        match dsl::syntax::format(&source) {
            Ok(formatted) if args.check => {
                if formatted != source {
                    writeln!(out, "{} is not in canonical format", file.display())?;
                    ok = false;
                }
            }
            Ok(formatted) if args.write => {
                if formatted != source {
                    std::fs::write(file, formatted)
                        .with_context(|| format!("cannot write {}", file.display()))?;
                }
            }
            Ok(formatted) => write!(out, "{formatted}")?,
            Err(errors) => {
                write_errors(file, &source, &errors, out)?;
                ok = false;
            }
        }
    }
    Ok(if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `oscsim validate --syntax-only FILE.osc`: parses the file and writes `OK` or `FAIL` with
/// every syntax error; `true` when it parses cleanly.
pub fn validate_syntax(file: &Path, out: &mut impl Write) -> anyhow::Result<bool> {
    let source = match read(file) {
        Ok(s) => s,
        Err(e) => {
            writeln!(out, "FAIL {}\n  error: {e:#}", file.display())?;
            return Ok(false);
        }
    };
    let parse = dsl::syntax::parse(&source);
    if parse.errors().is_empty() {
        let items = parse.tree().items().count();
        writeln!(
            out,
            "OK   {} (OpenSCENARIO DSL, syntax only, {items} top-level statements)",
            file.display()
        )?;
        return Ok(true);
    }
    writeln!(
        out,
        "FAIL {} ({} syntax errors)",
        file.display(),
        parse.errors().len()
    )?;
    write_errors(file, &source, parse.errors(), out)?;
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `text` written as `name` in a folder of its own, which is removed with it when the
    /// returned `TempDir` drops (keep it bound, e.g. `_dir`, until the test ends).
    fn temp_file(name: &str, text: &str) -> (tempfile::TempDir, PathBuf) {
        let dir = tempfile::Builder::new()
            .prefix("oscsim-cli-dsl-")
            .tempdir()
            .unwrap();
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        (dir, path)
    }

    #[test]
    fn validate_syntax_reports_every_error_with_its_line() {
        let (_dir, path) = temp_file("two_errors.osc", "struct s:\n    x: = 1\n    keep(y >)\n");
        let mut out = Vec::new();
        assert!(!validate_syntax(&path, &mut out).unwrap());
        let text = String::from_utf8(out).unwrap();
        assert!(
            text.starts_with(&format!("FAIL {} (2 syntax errors)\n", path.display())),
            "{text}"
        );
        assert!(text.contains("expected a type, found `=`"), "{text}");
        assert!(
            text.contains(&format!("[{}:2:8]", path.display())),
            "{text}"
        );
        assert!(text.contains("expected expression, found `)`"), "{text}");
        assert!(
            text.contains(&format!("[{}:3:13]", path.display())),
            "{text}"
        );

        let (_dir, path) = temp_file("fine.osc", "struct s:\n    x: int\nglobal g: int\n");
        let mut out = Vec::new();
        assert!(validate_syntax(&path, &mut out).unwrap());
        assert_eq!(
            String::from_utf8(out).unwrap(),
            format!(
                "OK   {} (OpenSCENARIO DSL, syntax only, 2 top-level statements)\n",
                path.display()
            )
        );
    }

    #[test]
    fn fmt_prints_checks_and_rewrites() {
        let (_dir, path) = temp_file("messy.osc", "struct   s :\n  x:int=1+2\n");
        let canonical = "struct s:\n    x: int = 1 + 2\n";
        let args = |write, check| FmtArgs {
            files: vec![path.clone()],
            write,
            check,
        };

        let mut out = Vec::new();
        assert_eq!(
            fmt(&args(false, false), &mut out).unwrap(),
            ExitCode::SUCCESS
        );
        assert_eq!(String::from_utf8(out).unwrap(), canonical);

        let mut out = Vec::new();
        assert_eq!(
            fmt(&args(false, true), &mut out).unwrap(),
            ExitCode::from(1)
        );
        assert_eq!(
            String::from_utf8(out).unwrap(),
            format!("{} is not in canonical format\n", path.display())
        );

        assert_eq!(
            fmt(&args(true, false), &mut Vec::new()).unwrap(),
            ExitCode::SUCCESS
        );
        assert_eq!(std::fs::read_to_string(&path).unwrap(), canonical);
        assert_eq!(
            fmt(&args(false, true), &mut Vec::new()).unwrap(),
            ExitCode::SUCCESS
        );
    }
}
