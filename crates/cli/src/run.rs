//! `oscsim run SCENARIO.xosc`: run a scenario headless with a fixed step and write the
//! trajectory CSV (`--csv`) and the event log (`--events`, JSON lines). A progress bar shows on
//! a terminal; a summary line ends the run (simulated time, steps, wall time, why it stopped).
//!
//! Without `--duration` the run ends at the storyboard's stop trigger, or when every story has
//! completed and there is no stop trigger; `--max-time` (default 3600 s) caps every run.

use std::fs::File;
use std::io::{BufWriter, IsTerminal, Write as _};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::Context;
use engine::output::{CsvWriter, JsonlWriter, SignalsCsvWriter};
use engine::{Engine, EventRecord, EventSink, FrameSink};

/// Arguments of `oscsim run`.
#[derive(clap::Args, Debug)]
#[command(
    after_help = "Exit status: 0 when the run completes, 1 when loading or running fails, 2 on a usage error."
)]
pub struct RunArgs {
    /// The scenario: OpenSCENARIO 1.x (.xosc), or OpenSCENARIO DSL 2.x (.osc, with --road).
    scenario: PathBuf,
    /// The OpenDRIVE road network an OpenSCENARIO DSL scenario (.osc) runs on (default: the
    /// file its `map.set_map_file(…)` names).
    #[arg(long, value_name = "FILE.xodr")]
    road: Option<PathBuf>,
    /// The scenario of an OpenSCENARIO DSL file to run (default: the one scenario with a `do`
    /// that no other invokes).
    #[arg(long = "scenario", value_name = "NAME")]
    scenario_name: Option<String>,
    #[command(flatten)]
    step: crate::step_args::StepArgs,
    /// Threads the driver models' (`idm`, `mobil`) commands are worked out on in each step
    /// when 256 or more vehicles have one; any count gives the same outputs, bit for bit.
    #[arg(long, value_name = "N", default_value = "1")]
    jobs: std::num::NonZeroUsize,
    /// Override a global parameter, NAME=VALUE (repeatable).
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = name_value)]
    params: Vec<(String, String)>,
    /// Set a value for UserDefinedValueConditions from the start, NAME=VALUE (repeatable; a
    /// number is a double, true/false a boolean, anything else a string).
    #[arg(long = "value", value_name = "NAME=VALUE", value_parser = name_value)]
    values: Vec<(String, String)>,
    /// Values for UserDefinedValueConditions over time: a CSV file with the header
    /// time,name,value, one row per change.
    #[arg(long = "values", value_name = "FILE.csv")]
    values_file: Option<PathBuf>,
    /// Write trajectories here (long CSV: time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed).
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// Write the traffic signal states here (CSV: time,signal,state; one row per signal per
    /// frame).
    #[arg(long, value_name = "FILE.csv")]
    signals: Option<PathBuf>,
    /// Write the event log here (JSON lines, one storyboard transition per line).
    #[arg(long, value_name = "FILE.jsonl")]
    events: Option<PathBuf>,
    /// Write what the run sampled of an OpenSCENARIO DSL scenario's cover(…) and record(…)
    /// items here (CSV: item,value,unit,bucket; one row per sample, docs/dsl.md).
    #[arg(long, value_name = "FILE.csv")]
    coverage: Option<PathBuf>,
    /// Do not show the progress bar.
    #[arg(long)]
    quiet: bool,
    /// Write OSI 3.8.0 GroundTruth here: FILE.osi, FILE.mcap, or a directory (file named by
    /// the OSI convention; its UTC timestamp is the wall clock unless SOURCE_DATE_EPOCH is set).
    #[arg(long, value_name = "PATH")]
    osi: Option<PathBuf>,
    /// Host vehicle of the OSI ground truth (default: the entity named Ego, else none).
    #[arg(long, value_name = "NAME")]
    osi_host: Option<String>,
    /// Lanes and lane boundaries in the first OSI frame only, or in every frame.
    #[arg(long, value_enum, default_value_t = crate::osi_args::OsiStatic::First)]
    osi_static: crate::osi_args::OsiStatic,
    /// Write every Nth step to the OSI trace.
    #[arg(long, value_name = "N", default_value = "1")]
    osi_every: std::num::NonZeroU64,
    #[command(flatten)]
    replay: crate::run_record::ReplayArgs,
}

/// Splits `NAME=VALUE` (a leading `$` on the name is dropped).
pub(crate) fn name_value(text: &str) -> Result<(String, String), String> {
    text.split_once('=')
        .filter(|(n, _)| !n.trim().is_empty())
        .map(|(n, v)| (n.trim().trim_start_matches('$').to_owned(), v.to_owned()))
        .ok_or_else(|| format!("expected NAME=VALUE, found '{text}'"))
}

/// Creates `path` (and its parent folder) for writing.
fn create(path: &PathBuf) -> anyhow::Result<BufWriter<File>> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| {
            format!(
                "cannot create folder {} for {}",
                dir.display(),
                path.display()
            )
        })?;
    }
    let file = File::create(path).with_context(|| format!("cannot create {}", path.display()))?;
    Ok(BufWriter::new(file))
}

/// Event sink that forwards to an optional writer, counts records and prints errors.
struct Events {
    out: Option<JsonlWriter<BufWriter<File>>>,
    count: usize,
    /// The last error printed, so that a run failing on it does not print it twice.
    last_error: Option<String>,
    /// Errors logged by a run that went on (a route that could not be planned, a trajectory
    /// that could not be built, a condition that could not be evaluated).
    errors: usize,
    /// The replay's recording of the log (run_record.rs).
    record: Option<crate::run_record::Events>,
    /// The `emit`s the coverage sampler waits for (`--coverage`).
    emits: Option<load::Emits>,
}

impl EventSink for Events {
    fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
        self.count += 1;
        if let EventRecord::Error { message, .. } = record {
            eprintln!("error: {message}");
            self.last_error = Some(message.clone());
            self.errors += 1;
        }
        if let Some(r) = &mut self.record {
            r.event(record)?;
        }
        if let Some(e) = &mut self.emits {
            e.event(record)?;
        }
        self.out.as_mut().map_or(Ok(()), |o| o.event(record))
    }

    fn finish(&mut self) -> Result<(), engine::SinkError> {
        self.out.as_mut().map_or(Ok(()), |o| o.finish())
    }
}

/// Runs `oscsim run`.
pub fn run(args: RunArgs) -> anyhow::Result<ExitCode> {
    let config = engine::EngineConfig {
        controller_threads: args.jobs.get(),
        ..args.step.config()
    };
    let wall = Instant::now();
    let options = crate::load_args::options(
        args.road.as_deref(),
        args.scenario_name.as_deref(),
        &args.params,
        &args.step,
    );
    let loaded = crate::load_args::load(&args.scenario, &options)?;
    if !args.quiet {
        // What the loader accepted but the schema does not (an empty ObjectController, a
        // deprecated form): the run goes on, the author should know.
        for w in &loaded.scenario.warnings {
            eprintln!("warning: {w}");
        }
    }
    let mut engine = Engine::new(
        &loaded.scenario,
        std::sync::Arc::clone(&loaded.network),
        config,
    )
    .with_context(|| format!("cannot run {}", args.scenario.display()))?;
    for (name, text) in &args.values {
        engine.set_user_value(name, engine::user_values::parse_value(text));
    }
    if let Some(path) = &args.values_file {
        engine.schedule_user_values(&engine::user_values::read_csv(path)?);
    }
    let mut frames: Vec<Box<dyn FrameSink>> = Vec::new();
    if let Some(path) = &args.csv {
        frames.push(Box::new(CsvWriter::new(create(path)?)));
    }
    if let Some(path) = &args.signals {
        frames.push(Box::new(SignalsCsvWriter::new(create(path)?)));
    }
    if let Some(path) = &args.osi {
        let options = crate::osi_args::OsiOptions {
            path: path.clone(),
            host: args.osi_host.clone(),
            static_data: args.osi_static,
            every: args.osi_every,
        };
        frames.push(Box::new(crate::osi_args::create(&engine, &options)?));
    }
    let record = crate::run_record::RunRecord::new(&args.replay, args.csv.as_deref());
    frames.extend(record.frame_sink());
    let sampler = args.coverage.as_ref().map(|path| {
        if loaded.coverage.is_empty() && !args.quiet {
            eprintln!(
                "warning: {} has no cover(…) or record(…) items; {} holds the header alone",
                args.scenario.display(),
                path.display()
            );
        }
        load::Sampler::new(&loaded.coverage, &loaded.network)
    });
    let emits = sampler.as_ref().map(load::Sampler::emits);
    let mut frames = (frames, sampler);
    let mut events = Events {
        out: args
            .events
            .as_ref()
            .map(create)
            .transpose()?
            .map(JsonlWriter::new),
        count: 0,
        last_error: None,
        errors: 0,
        record: record.event_sink(),
        emits,
    };
    let end = config.end_time();
    let bar = (!args.quiet && std::io::stderr().is_terminal()).then(|| {
        let bar = indicatif::ProgressBar::new((end * 1000.0) as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let reason = loop {
        let step = match engine.step(&mut frames, &mut events) {
            Ok(step) => step,
            Err(e) => {
                let failed = format!(
                    "run of {} failed at t = {:.3} s",
                    args.scenario.display(),
                    engine.time()
                );
                // An action's error was printed as the event log received it: name it once.
                return Err(if events.last_error.as_deref() == Some(&e.to_string()) {
                    anyhow::anyhow!("{failed} (the error above)")
                } else {
                    anyhow::Error::new(e).context(failed)
                });
            }
        };
        if let Some(bar) = &bar {
            if engine.steps() % 20 == 0 {
                bar.set_position((engine.time() * 1000.0) as u64);
                bar.set_message(format!("t = {:.1} s", engine.time()));
            }
        }
        if let Some(reason) = step {
            break reason;
        }
    };
    frames
        .finish()
        .context("cannot finish the CSV or the OSI trace")?;
    events.finish().context("cannot write the event log")?;
    drop(events.record.take());
    let (frames, sampler) = frames;
    drop(frames);
    if let (Some(path), Some(sampler)) = (&args.coverage, sampler) {
        let text = crate::run_coverage::to_csv(&loaded.coverage, &sampler.finish());
        let mut file = create(path)?;
        file.write_all(text.as_bytes())
            .and_then(|()| file.flush())
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    record.finish(
        &loaded,
        &args.scenario,
        &args.params,
        &config,
        args.csv.as_deref(),
        args.events.as_deref(),
    )?;
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    println!(
        "{}: simulated {:.3} s in {} steps ({} events), wall time {:.3} s; stopped because {}",
        args.scenario.display(),
        engine.time(),
        engine.steps(),
        events.count,
        wall.elapsed().as_secs_f64(),
        reason
    );
    if events.errors > 0 {
        // The outputs are complete, but the scenario did not run as written: a failed run.
        eprintln!(
            "error: the run logged {} error(s) (above, and in the event log); exit status 1",
            events.errors
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}
