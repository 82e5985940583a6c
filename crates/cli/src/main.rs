//! `oscsim`: run OpenSCENARIO scenarios on OpenDRIVE road networks, headless and deterministic.
//!
//! Exit status: 0 on success, 1 when the input is invalid or a run fails (or completes but logs
//! runtime errors), 2 on a usage error.
//!
//! Glue only: each subcommand's flags, turned into calls of the library crates.
//!
//! | module | job |
//! | --- | --- |
//! | `load_args` | the front door (`load` crate) with the flags of either language; DSL check errors as snippets |
//! | `run` | `oscsim run`: a scenario run headless; trajectory CSV, event log, progress, summary |
//! | `step_args` | the stepping flags `run` and `batch` share, turned into the engine's configuration |
//! | `osi_args` | the `--osi*` flags: the trace's folder, `SOURCE_DATE_EPOCH` |
//! | `run_coverage` | `run --coverage`: the samples of a DSL scenario's cover/record items in one run |
//! | `run_record` | what `run` records for the replay: the run manifest, the HTML page |
//! | `validate` | `oscsim validate`: load and report OK or the error with its source lines |
//! | `snippet` | source snippets of an error's file position, rendered by miette |
//! | `batch_cmd` | `oscsim batch` and `oscsim batch merge`: glue over the batch crate |
//! | `view` | `oscsim view` and `oscsim plot`: glue over the replay crate |
//! | `road` | `oscsim road …`: inspect an OpenDRIVE network |
//! | `dsl` | `oscsim dsl …` and the checks behind `oscsim validate FILE.osc` |

mod batch_cmd;
mod dsl;
mod load_args;
mod osi_args;
mod road;
mod run;
mod run_coverage;
mod run_record;
mod snippet;
mod step_args;
mod validate;
mod view;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Command-line arguments of `oscsim`.
#[derive(Parser, Debug)]
#[command(name = "oscsim", version, about, long_about = None,
    after_help = "Exit status: 0 success, 1 invalid input or failed run (or runtime errors \
                  logged), 2 usage error.")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Inspect an OpenDRIVE road network.
    Road(road::RoadArgs),
    /// Load scenarios with their road networks and catalogs and report errors.
    Validate(validate::ValidateArgs),
    /// Run a scenario headless and write trajectories and the event log.
    Run(Box<run::RunArgs>),
    /// OpenSCENARIO DSL 2.x tools (`.osc` files).
    #[command(subcommand)]
    Dsl(dsl::DslCommand),
    /// Run every variant of a parameter value distribution; `batch merge` joins shard outputs.
    Batch(Box<batch_cmd::BatchArgs>),
    /// Write a run (or a scenario, run first) as one self-contained HTML replay.
    View(view::ViewArgs),
    /// Draw SVG and PNG charts of a run (or a scenario, run first): trajectories, speeds,
    /// distances and time to collision from the host.
    Plot(view::PlotArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Road(args) => road::run(args),
        Command::Validate(args) => validate::run(args),
        Command::Run(args) => run::run(*args),
        Command::Dsl(command) => dsl::run(command),
        Command::Batch(args) => batch_cmd::run(*args),
        Command::View(args) => view::view(args),
        Command::Plot(args) => view::plot(args),
    };
    match result {
        Ok(code) => code,
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::from(1)
        }
    }
}
