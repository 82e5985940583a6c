//! `oscsim view RUN -o replay.html` and `oscsim plot RUN -o DIR`: glue over the replay crate.
//! RUN is what `oscsim run` wrote (the trajectory CSV, with its `NAME.run.json` manifest beside
//! it, or the manifest) or a scenario (`.xosc`), which is run first, in memory.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Context;
use replay::{OpenOptions, Run};

/// Which run to show, and how to run a scenario.
#[derive(clap::Args, Debug)]
pub struct RunInput {
    /// The run: a trajectory CSV written by `oscsim run --csv` (its NAME.run.json beside it), the
    /// NAME.run.json itself, or a scenario (.xosc, or .osc with --road), which is run first.
    run: PathBuf,
    /// Running an OpenSCENARIO DSL scenario (.osc): its OpenDRIVE road network (default: the
    /// file its `map.set_map_file(…)` names).
    #[arg(long, value_name = "FILE.xodr")]
    road: Option<PathBuf>,
    /// For a CSV without a manifest (e.g. esmini's): the scenario it is a run of.
    #[arg(long, value_name = "FILE.xosc")]
    scenario: Option<PathBuf>,
    /// The event log to show, instead of the one the manifest names.
    #[arg(long, value_name = "FILE.jsonl")]
    events: Option<PathBuf>,
    /// Running a scenario: override a global parameter, NAME=VALUE (repeatable).
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = crate::run::name_value)]
    params: Vec<(String, String)>,
    /// Running a scenario: the step flags of `oscsim run`.
    #[command(flatten)]
    step: crate::step_args::StepArgs,
}

impl RunInput {
    /// Opens the run, or runs the scenario.
    fn open(&self) -> anyhow::Result<Run> {
        let is_scenario = load::is_dsl(&self.run)
            || self
                .run
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("xosc"));
        if is_scenario {
            let config = self.step.config();
            let options =
                crate::load_args::options(self.road.as_deref(), None, &self.params, &self.step);
            Run::simulate(&self.run, &options, config)
                .inspect_err(|e| {
                    if let replay::ErrorKind::Load(e) = e.kind() {
                        crate::load_args::show(e);
                    }
                })
                .with_context(|| format!("cannot run {}", self.run.display()))
        } else {
            let options = OpenOptions {
                scenario: self.scenario.clone(),
                events: self.events.clone(),
            };
            Run::open(&self.run, &options)
                .with_context(|| format!("cannot open the run {}", self.run.display()))
        }
    }
}

/// Arguments of `oscsim view`.
#[derive(clap::Args, Debug)]
pub struct ViewArgs {
    #[command(flatten)]
    input: RunInput,
    /// Write the replay page here.
    #[arg(short, long, value_name = "FILE.html")]
    output: PathBuf,
}

/// Runs `oscsim view`.
pub fn view(args: ViewArgs) -> anyhow::Result<ExitCode> {
    let run = args.input.open()?;
    replay::html::write(&run, &args.output)?;
    println!("{}: replay written to {}", run.title, args.output.display());
    Ok(ExitCode::SUCCESS)
}

/// Arguments of `oscsim plot`.
#[derive(clap::Args, Debug)]
pub struct PlotArgs {
    #[command(flatten)]
    input: RunInput,
    /// Write the charts into this folder.
    #[arg(short, long, value_name = "DIR")]
    output: PathBuf,
    /// The host of the distance and time-to-collision chart (default: Ego, else the first
    /// entity).
    #[arg(long, value_name = "NAME")]
    host: Option<String>,
    /// Write SVG only.
    #[arg(long)]
    no_png: bool,
}

/// Runs `oscsim plot`.
pub fn plot(args: PlotArgs) -> anyhow::Result<ExitCode> {
    let run = args.input.open()?;
    let options = replay::plot::PlotOptions {
        host: args.host,
        png: !args.no_png,
        ..Default::default()
    };
    let files = replay::plot::plot(&run, &args.output, &options)?;
    for f in files {
        println!("{}", f.display());
    }
    Ok(ExitCode::SUCCESS)
}
