//! `oscsim batch DIST.xosc --out DIR`: every variant of a parameter value distribution, on all
//! cores or one shard of them; `oscsim batch X.osc --road R.xodr --seeds 1..1000 --out DIR`:
//! every seed of an OpenSCENARIO DSL scenario. Each finished variant is recorded in
//! `DIR/batch.journal` so that the same command run again goes on where a killed run stopped;
//! `oscsim batch merge DIR… --out DIR` joins shard outputs. The work is the batch crate's
//! (run.rs, resume.rs); this is argument handling and glue.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::Context;

/// Arguments of `oscsim batch`.
#[derive(clap::Args, Debug)]
#[command(
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    after_help = "Outputs in DIR: results.csv, results.parquet, report.html (and variants/NNNNN/ with --save).\n\
Variant numbers follow the distribution file, or the seeds in order (docs/batch.md). Sharding: --shard I/N, or the\n\
environment of a Slurm array task (SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_COUNT) or of a\n\
Kubernetes Indexed Job (JOB_COMPLETION_INDEX with --shards N).\n\
Each finished variant is recorded in DIR/batch.journal as it ends: the same command run again on\n\
the same DIR (after a kill, a pre-emption, a requeue) runs only the variants not yet recorded and\n\
writes the files an uninterrupted run writes. A DIR holding another sweep's results is refused.\n\
Exit status: 0 when every variant ran or was refused by the scenario's constraints, 100 + N\n\
when N variants failed (255 for 155 or more; their rows say why), 1 when the batch cannot run\n\
(loading, the output folder), 2 on a usage error."
)]
pub struct BatchArgs {
    #[command(subcommand)]
    merge: Option<BatchCommand>,
    /// The ParameterValueDistribution file (.xosc), or with --seeds an OpenSCENARIO DSL
    /// scenario (.osc).
    #[arg(required = true)]
    distribution: Option<PathBuf>,
    /// Run the DSL scenario once per seed, re-solving its constraints: A..B (inclusive) or a
    /// count N (the seeds 1..N). Each variant's engine runs with its seed too (`oscsim run
    /// X.osc --seed S` repeats it).
    #[arg(long, value_name = "A..B|N", conflicts_with = "seed")]
    seeds: Option<String>,
    /// The OpenDRIVE road network of the DSL scenario (default: the file its
    /// `map.set_map_file(…)` names).
    #[arg(long, value_name = "FILE.xodr")]
    road: Option<PathBuf>,
    /// Output folder.
    #[arg(long, required = true)]
    out: Option<PathBuf>,
    /// Worker threads (default: every core).
    #[arg(long)]
    jobs: Option<usize>,
    #[command(flatten)]
    step: crate::step_args::StepArgs,
    /// The entity measured against all others.
    #[arg(long, default_value = "Ego")]
    host: String,
    /// Run share I of N (0-based), e.g. 2/8.
    #[arg(long, value_name = "I/N")]
    shard: Option<String>,
    /// Number of shards when the share comes from JOB_COMPLETION_INDEX (Kubernetes).
    #[arg(long, value_name = "N")]
    shards: Option<u64>,
    /// Run only this variant (and print the equivalent `oscsim run` command).
    #[arg(long, value_name = "N")]
    only: Option<u64>,
    /// Keep per-variant outputs in DIR/variants/NNNNN/: csv, events, osi (comma-separated;
    /// osi: the trace `oscsim run --osi DIR` writes, recording time from SOURCE_DATE_EPOCH).
    #[arg(long, value_delimiter = ',', value_name = "KINDS")]
    save: Vec<String>,
    /// Wall-clock limit per variant in seconds: a variant still running after it is recorded
    /// as failed ("timed out") and the batch goes on.
    #[arg(long, value_name = "SECONDS", value_parser = positive_seconds)]
    variant_timeout: Option<f64>,
    /// Do not show the progress bar.
    #[arg(long)]
    quiet: bool,
}

/// A positive, finite number of seconds.
fn positive_seconds(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(s) if s.is_finite() && s > 0.0 => Ok(s),
        _ => Err(format!(
            "expected a positive number of seconds, found '{text}'"
        )),
    }
}

/// `oscsim batch merge`.
#[derive(clap::Subcommand, Debug)]
enum BatchCommand {
    /// Join the output folders of shards into what the unsharded batch writes.
    Merge {
        /// The shards' output folders.
        #[arg(required = true)]
        shards: Vec<PathBuf>,
        /// The merged output folder.
        #[arg(long)]
        out: PathBuf,
    },
}

/// Runs `oscsim batch`.
pub fn run(args: BatchArgs) -> anyhow::Result<ExitCode> {
    if let Some(BatchCommand::Merge { shards, out }) = &args.merge {
        let table = batch::merge(shards, out)?;
        println!("{}", batch::summary(&table));
        return Ok(exit_code(&table));
    }
    let (Some(distribution), Some(out)) = (&args.distribution, &args.out) else {
        anyhow::bail!("expected DIST.xosc and --out DIR");
    };
    let plan = match &args.seeds {
        Some(text) => {
            let seeds = batch::parse_seeds(text).map_err(|e| anyhow::anyhow!("--seeds: {e}"))?;
            let options = crate::load_args::options(args.road.as_deref(), None, &[], &args.step);
            batch::Plan::seeds(distribution, &options, seeds).inspect_err(|e| {
                if let batch::ErrorKind::Plan(batch::PlanErrorKind::Load(e)) = e.kind() {
                    crate::load_args::show(e);
                }
            })
        }
        None if load::is_dsl(distribution) => anyhow::bail!(
            "expected --seeds A..B (or a count) for the OpenSCENARIO DSL scenario {}, found none",
            distribution.display()
        ),
        None if args.road.is_some() => anyhow::bail!(
            "expected no --road for a ParameterValueDistribution (its ScenarioFile names its road network), found one"
        ),
        None => batch::Plan::load(distribution),
    }
    .with_context(|| format!("cannot run the batch of {}", distribution.display()))?;
    for w in &plan.warnings {
        eprintln!("warning: {w}");
    }
    let shard = batch::Shard::resolve(args.shard.as_deref(), args.shards, |k| {
        std::env::var(k).ok()
    })?;
    let save = batch::Save::from_kinds(&args.save).map_err(|e| anyhow::anyhow!("--save: {e}"))?;
    let options = batch::Options {
        seed: args.step.seed,
        dt: args.step.dt,
        duration: args.step.duration,
        max_time: args.step.max_time,
        traffic_model: args.step.config().traffic_model,
        vehicle_model: args.step.config().vehicle_model,
        stop_at_red_lights: args.step.stop_at_red_lights,
        host: args.host.clone(),
        jobs: args
            .jobs
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
        shard,
        only: args.only,
        save: save.any().then(|| (save, out.clone())),
        recording_time: crate::osi_args::source_date_epoch()?,
        variant_timeout: args.variant_timeout.map(std::time::Duration::from_secs_f64),
    };
    if let Some(v) = args.only {
        if v as usize >= plan.variants.len() {
            anyhow::bail!(
                "expected a variant number below {}, found {v}",
                plan.variants.len()
            );
        }
        match &plan.seeds {
            Some(seeds) => {
                let road = args
                    .road
                    .as_ref()
                    .map(|r| format!(" --road {}", r.display()))
                    .unwrap_or_default();
                println!(
                    "variant {v} alone: oscsim run {}{road} --seed {} --dt {}",
                    distribution.display(),
                    seeds.seeds[v as usize],
                    args.step.dt
                );
            }
            None => {
                let params: Vec<String> = plan.variants[v as usize]
                    .iter()
                    .map(|(k, x)| format!(" --param {k}={x}"))
                    .collect();
                println!(
                    "variant {v} alone: oscsim run {}{} --seed {} --dt {}",
                    plan.scenario.path.display(),
                    params.concat(),
                    batch::variant_seed(args.step.seed, v),
                    args.step.dt
                );
            }
        }
    }
    let bar = std::sync::OnceLock::new();
    let started = |resumed: usize, to_run: usize| {
        if resumed > 0 {
            println!(
                "resuming from {}: {resumed} variants recorded, {to_run} to run",
                out.join(batch::JOURNAL_FILE).display()
            );
        }
        if !args.quiet && std::io::stderr().is_terminal() {
            let b = indicatif::ProgressBar::new(to_run as u64);
            b.set_style(
                indicatif::ProgressStyle::with_template(
                    "{bar:40} {pos}/{len} variants, {per_sec}, ETA {eta}",
                )
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
            );
            let _ = bar.set(b);
        }
    };
    let wall = Instant::now();
    let finished = batch::run_durable(&plan, &options, out, &started, &|done, _| {
        if let Some(b) = bar.get() {
            b.set_position(done as u64);
        }
    })
    .with_context(|| format!("cannot run the batch of {}", distribution.display()))?;
    if let Some(b) = bar.get() {
        b.finish_and_clear();
    }
    let table = &finished.table;
    let ran = table.rows.len() - finished.resumed;
    let seconds = wall.elapsed().as_secs_f64();
    println!(
        "{}\n{} in {:.2} s ({ran} run, {:.1} variants/s on {} {}); results in {}",
        batch::summary(table),
        plan.distribution.display(),
        seconds,
        ran as f64 / seconds.max(1e-9),
        options.jobs,
        if options.jobs == 1 { "job" } else { "jobs" },
        out.display()
    );
    Ok(exit_code(table))
}

/// 0 when every variant ran (or was refused by the scenario's constraints), else 100 + the
/// number that failed, at most 255.
fn exit_code(table: &batch::Table) -> ExitCode {
    let failed = table.rows.iter().filter(|r| r.failed()).count();
    if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(u8::try_from(100 + failed).unwrap_or(u8::MAX))
    }
}
