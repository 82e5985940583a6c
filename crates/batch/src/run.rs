//! Running the variants of a [`Plan`]: on a rayon pool of `jobs` threads, each variant an
//! independent engine with its own seed (seed.rs), the rows collected by variant number, so
//! the table is the same for any number of jobs.
//!
//! A variant that fails — its parameters make the scenario invalid, a runtime error stops it,
//! it passes its wall-clock limit or panics (guard.rs) — gives a row with its error message;
//! the batch goes on. [`run_each`] hands each row to the caller as its variant ends (the
//! journal's append, resume.rs).
//! A variant whose values break the scenario's own ConstraintGroups is refused, not failed
//! (its message starts with [`REFUSED`]).

use std::fs::File;
use std::io::BufWriter;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use engine::output::JsonlWriter;
use engine::storyboard::{ElementKind, Transition};
use engine::{Engine, EngineConfig, EventRecord, EventSink, FrameSink};
use rayon::prelude::*;

use crate::error::{Error, RunErrorKind};
use crate::guard::{contain, timeout_message, Deadline};
use crate::metrics::Observer;
use crate::plan::Plan;
use crate::save::{commit, discard, staging_dir, Outputs, Save};
use crate::seed::variant_seed;
use crate::shard::Shard;
use crate::table::{Outcome, Row, Table, REFUSED};

/// How to run a batch.
#[derive(Debug, Clone)]
pub struct Options {
    /// The batch's seed; each variant's is derived from it (seed.rs).
    pub seed: u64,
    /// Step length, s.
    pub dt: f64,
    /// Simulated seconds per variant (default: until the storyboard ends).
    pub duration: Option<f64>,
    /// Cap on simulated seconds per variant.
    pub max_time: f64,
    /// The driver model of spawned traffic without a controller of its own
    /// ([`engine::EngineConfig::traffic_model`]).
    pub traffic_model: Option<engine::runtime::TrafficModel>,
    /// The driver model of the scenario's vehicles without an ObjectController
    /// ([`engine::EngineConfig::vehicle_model`]).
    pub vehicle_model: Option<engine::runtime::TrafficModel>,
    /// Vehicles stop at red lights ([`engine::EngineConfig::stop_at_red_lights`]).
    pub stop_at_red_lights: bool,
    /// The entity measured against the others (metrics.rs).
    pub host: String,
    /// Worker threads (at least 1).
    pub jobs: usize,
    /// This process's share of the variants.
    pub shard: Shard,
    /// Run only this variant (if it is in the shard).
    pub only: Option<u64>,
    /// Per-variant outputs, under this folder.
    pub save: Option<(Save, PathBuf)>,
    /// The recording time of saved OSI traces, Unix seconds (the cli: `SOURCE_DATE_EPOCH`);
    /// `None` takes the clock (save.rs).
    pub recording_time: Option<i64>,
    /// Wall-clock limit per variant; a variant past it is a failed row (guard.rs).
    pub variant_timeout: Option<Duration>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            seed: engine::runtime::DEFAULT_SEED,
            dt: engine::runtime::DEFAULT_DT,
            duration: None,
            max_time: engine::runtime::DEFAULT_MAX_TIME,
            traffic_model: None,
            vehicle_model: None,
            stop_at_red_lights: false,
            host: "Ego".into(),
            jobs: 1,
            shard: Shard::ALL,
            only: None,
            save: None,
            recording_time: None,
            variant_timeout: None,
        }
    }
}

/// The variant numbers this process runs, ascending.
pub fn selected(plan: &Plan, options: &Options) -> Vec<u64> {
    (0..plan.variants.len() as u64)
        .filter(|&v| options.shard.contains(v) && options.only.is_none_or(|o| o == v))
        .collect()
}

/// Runs the selected variants of `plan`; `progress(done, total)` is called after each.
pub fn run(
    plan: &Plan,
    options: &Options,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Table, Error> {
    run_variants(plan, options, &selected(plan, options), progress)
}

/// Runs the variants numbered `variants` of `plan` (each below `plan.variants.len()`; the
/// options' shard and `only` are not consulted), rows in the order given: the work of one
/// task of a driver that hands out its own shares (the Python package's Ray backend).
/// `progress(done, total)` is called after each.
pub fn run_variants(
    plan: &Plan,
    options: &Options,
    variants: &[u64],
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Table, Error> {
    run_each(plan, options, variants, &|_, done, total| {
        progress(done, total);
        Ok(())
    })
}

/// [`run_variants`], handing each row to `each(row, done, total)` as its variant ends (on the
/// worker thread that ran it); an error from `each` stops the batch with that error.
pub fn run_each(
    plan: &Plan,
    options: &Options,
    variants: &[u64],
    each: &(dyn Fn(&Row, usize, usize) -> Result<(), Error> + Sync),
) -> Result<Table, Error> {
    let count = plan.variants.len();
    if let Some(&variant) = variants.iter().find(|&&v| v >= count as u64) {
        return Err(RunErrorKind::NoSuchVariant { variant, count }.into());
    }
    let total = variants.len();
    let done = AtomicUsize::new(0);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs.max(1))
        .build()
        .map_err(|e| RunErrorKind::Threads {
            jobs: options.jobs,
            message: e.to_string(),
        })?;
    let rows: Vec<Row> = pool.install(|| {
        variants
            .par_iter()
            .map(|&v| {
                let (params, result) = guarded_variant(plan, options, v);
                let row = Row {
                    variant: v,
                    params,
                    result,
                };
                each(&row, done.fetch_add(1, Ordering::Relaxed) + 1, total)?;
                Ok(row)
            })
            .collect::<Result<_, Error>>()
    })?;
    Ok(Table {
        rows,
        ..empty_table(plan)
    })
}

/// The table of `plan` with its columns and no rows: the varied parameters, and the
/// scenario's monitors in name order.
pub fn empty_table(plan: &Plan) -> Table {
    let monitors = plan
        .scenario
        .monitor_declarations
        .iter()
        .map(|m| m.name.clone())
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    Table {
        parameters: plan.parameters.clone(),
        monitors,
        coverage: plan.coverage.iter().map(crate::coverage::column).collect(),
        buckets: crate::coverage::definitions(&plan.coverage),
        rows: Vec::new(),
    }
}

/// Runs variant `v` with its panics contained and its saved outputs put in place or, when it
/// timed out or panicked, discarded (guard.rs, save.rs): its row values and its outcome, or
/// the message of what failed. A panic before its row values are known (while a seed
/// re-solves the scenario) leaves the values the plan knows (the seed).
fn guarded_variant(
    plan: &Plan,
    options: &Options,
    v: u64,
) -> (Vec<String>, Result<Outcome, String>) {
    let mut params = None;
    let result = contain(|| run_variant(plan, options, v, &mut params));
    let result = match &options.save {
        Some((_, root)) => discard(root, v).and(result),
        None => result,
    };
    (params.unwrap_or_else(|| plan.values(v as usize)), result)
}

/// Counts Event starts and forwards records to an optional event log and to the coverage
/// sampler (its `emit` events).
struct Events {
    started: u64,
    log: Option<JsonlWriter<BufWriter<File>>>,
    emits: load::Emits,
}

impl EventSink for Events {
    fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
        if let EventRecord::Transition(t) = record {
            if t.kind == ElementKind::Event && t.transition == Transition::Start {
                self.started += 1;
            }
        }
        self.emits.event(record)?;
        self.log.as_mut().map_or(Ok(()), |l| l.event(record))
    }

    fn finish(&mut self) -> Result<(), engine::SinkError> {
        self.log.as_mut().map_or(Ok(()), |l| l.finish())
    }
}

/// Variant `v`'s row values (a distribution's parameters; a seed and the values its
/// resolution gave) and scenario, or the message of why it cannot run; and the seed of its
/// engine's random streams: a distribution's variant seed (seed.rs), a batch of seeds' own
/// seed, so that `oscsim run X.osc --seed S` repeats variant S.
fn variant_scenario(
    plan: &Plan,
    options: &Options,
    v: u64,
) -> (Vec<String>, Result<Variant, String>, u64) {
    match &plan.seeds {
        None => {
            // Only the parameters the scenario declares (the others are the plan's warnings).
            let params: Vec<(String, String)> = plan.variants[v as usize]
                .iter()
                .filter(|(k, _)| crate::plan::declares(&plan.scenario, k))
                .map(|(k, x)| (k.clone(), x.clone()))
                .collect();
            // The variant from the scenario's files kept at the first load: no file is read.
            let scenario = plan
                .scenario
                .with_parameters(&params)
                .map(|scenario| Variant {
                    scenario,
                    coverage: Vec::new(),
                })
                .map_err(|e| match e.kind() {
                    scenario::ErrorKind::ConstraintViolated { .. } => format!("{REFUSED}{e}"),
                    _ => e.to_string(),
                });
            (
                plan.values(v as usize),
                scenario,
                variant_seed(options.seed, v),
            )
        }
        Some(seeds) => {
            let seed = seeds.seeds[v as usize];
            let mut row = vec![seed.to_string()];
            match seeds.source.load(seed) {
                Ok(loaded) => {
                    row.extend(loaded.resolved.into_iter().map(|(_, value)| value));
                    let variant = Variant {
                        scenario: loaded.scenario,
                        coverage: loaded.coverage,
                    };
                    (row, Ok(variant), seed)
                }
                Err(e) => {
                    row.resize(plan.parameters.len(), String::new());
                    (row, Err(e.to_string()), seed)
                }
            }
        }
    }
}

/// A variant ready to run: its scenario and coverage items.
struct Variant {
    scenario: scenario::Scenario,
    coverage: Vec<load::CoverItem>,
}

/// Runs variant `v`: the outcome, or the message of what failed; its row values (above) in
/// `params` as soon as they are known. The wall-clock limit counts from here.
fn run_variant(
    plan: &Plan,
    options: &Options,
    v: u64,
    params: &mut Option<Vec<String>>,
) -> Result<Outcome, String> {
    let deadline = options
        .variant_timeout
        .map(|limit| Deadline::new(Instant::now(), limit));
    let (values, variant, seed) = variant_scenario(plan, options, v);
    *params = Some(values);
    run_scenario(plan, options, v, &variant?, seed, deadline)
}

/// Runs the scenario of variant `v` with engine seed `seed` on the plan's road network (read
/// once for the whole batch), sampling its coverage items. Its saved outputs are written in
/// its staging folder and put in place when the run ends, unless it timed out.
fn run_scenario(
    plan: &Plan,
    options: &Options,
    v: u64,
    variant: &Variant,
    seed: u64,
    mut deadline: Option<Deadline>,
) -> Result<Outcome, String> {
    let scenario = &variant.scenario;
    let config = EngineConfig {
        dt: options.dt,
        duration: options.duration,
        max_time: options.max_time,
        seed,
        traffic_model: options.traffic_model,
        vehicle_model: options.vehicle_model,
        stop_at_red_lights: options.stop_at_red_lights,
        // A batch runs its variants on threads of its own (Options::jobs).
        ..EngineConfig::default()
    };
    // A batch of seeds runs on the DSL scenario's road network, read once; a distribution's
    // variant on the network its own values name, read once for every variant naming it.
    let network = match &plan.seeds {
        Some(_) => Arc::clone(&plan.network),
        None => plan.network_for(scenario).map_err(|e| e.to_string())?,
    };
    let mut engine =
        Engine::new(scenario, Arc::clone(&network), config).map_err(|e| e.to_string())?;
    let mut observer = Observer::new(&network, &options.host);
    let mut outputs = match &options.save {
        Some((save, root)) => {
            // What a killed run of this variant left.
            discard(root, v)?;
            Outputs::create(
                *save,
                &staging_dir(root, v),
                &engine,
                &options.host,
                options.recording_time,
            )?
        }
        None => Outputs::default(),
    };
    let mut sampler = load::Sampler::new(&variant.coverage, &plan.network);
    let mut events = Events {
        started: 0,
        log: outputs.events.take(),
        emits: sampler.emits(),
    };
    let run = {
        let mut sinks: Vec<&mut dyn FrameSink> = vec![&mut observer, &mut sampler];
        if let Some(d) = deadline.as_mut() {
            sinks.push(d);
        }
        if let Some(t) = outputs.trajectories.as_mut() {
            sinks.push(t);
        }
        if let Some(o) = outputs.osi.as_mut() {
            sinks.push(o);
        }
        let mut frames = Fanout(sinks);
        engine
            .run(&mut frames, &mut events)
            .map_err(|e| format!("{e} (at t = {:.3} s)", engine.time()))
    };
    if let (Some(limit), Some(d)) = (options.variant_timeout, &deadline) {
        if d.expired {
            // Its outputs stay in the staging folder, which the caller removes.
            return Err(timeout_message(limit));
        }
    }
    // Written and closed (a failed run's writers flush as they drop), then put in place.
    drop((outputs, events.log.take()));
    if let Some((_, root)) = &options.save {
        commit(root, v)?;
    }
    let reason = run?;
    let m = observer.measures;
    // The samples in the plan's column order (a seed's items are the plan's).
    let mut sampled: Vec<(String, Vec<load::Sample>)> = variant
        .coverage
        .iter()
        .map(crate::coverage::column)
        .zip(sampler.finish())
        .collect();
    let samples = plan
        .coverage
        .iter()
        .map(|item| {
            let column = crate::coverage::column(item);
            sampled
                .iter_mut()
                .find(|(c, _)| *c == column)
                .map(|(_, s)| std::mem::take(s))
                .unwrap_or_default()
        })
        .collect();
    Ok(Outcome {
        stop: Some(reason),
        end_time: engine.time(),
        collision: m.collision,
        first_collision_time: m.first_collision_time,
        min_ttc: m.min_ttc,
        min_headway: m.min_headway,
        min_gap: m.min_gap,
        events_started: events.started,
        monitors: engine.monitors(),
        samples,
    }
    .quantized())
}

/// Feeds several borrowed sinks.
struct Fanout<'a>(Vec<&'a mut dyn FrameSink>);

impl FrameSink for Fanout<'_> {
    fn frame(&mut self, frame: &engine::Frame<'_>) -> Result<(), engine::SinkError> {
        self.0.iter_mut().try_for_each(|s| s.frame(frame))
    }

    fn finish(&mut self) -> Result<(), engine::SinkError> {
        self.0.iter_mut().try_for_each(|s| s.finish())
    }
}
