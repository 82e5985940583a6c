//! `oscsim.BatchPlan`, `BatchJournal` and `merge_results`: the variants of a
//! ParameterValueDistribution file (OpenSCENARIO 1.3 §9.5), or the seeds of an OpenSCENARIO
//! DSL scenario, run from Python, for the drivers of `oscsim.batch` (in-process or
//! as Ray tasks). The work is the batch crate's — the same plan, runs, table and files as
//! `oscsim batch` — so a table put together from shares run anywhere is the one the command
//! line writes, byte for byte.
//!
//! Tables cross the boundary as the text of `results.csv`: that is what travels between Ray
//! workers and the driver, and the table keeps its numbers as written (batch's table.rs), so
//! nothing is lost on the way.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::{guard, positioned, OscsimError, ScenarioError};

/// A ParameterValueDistribution file expanded into numbered variants and checked against its
/// ScenarioFile, the scenario and road network loaded once. Immutable; share it between
/// threads.
#[pyclass(frozen, module = "oscsim")]
pub struct BatchPlan {
    inner: Arc<batch::Plan>,
}

#[pymethods]
impl BatchPlan {
    /// Loads the distribution file `path` and the scenario it names; or, with `seeds` (a list
    /// of seeds, or the text of `oscsim batch --seeds`: `"A..B"` or a count `"N"`), the
    /// OpenSCENARIO DSL scenario `path` on the road network `road` (default: the file its
    /// `map.set_map_file(…)` names), one variant per seed, its constraints re-solved. Raises
    /// `ScenarioError` (with the message's file:line:col; `file`, `line`, `column` set where
    /// the error is in the distribution file, the scenario or its road network) when the plan
    /// cannot run, `ValueError` for a bad seeds text.
    #[new]
    #[pyo3(signature = (path, *, seeds = None, road = None))]
    fn new(
        py: Python<'_>,
        path: PathBuf,
        seeds: Option<&Bound<'_, PyAny>>,
        road: Option<PathBuf>,
    ) -> PyResult<Self> {
        let seeds = match seeds {
            None => None,
            Some(s) => Some(match s.extract::<String>() {
                Ok(text) => batch::parse_seeds(&text)
                    .map_err(|e| pyo3::exceptions::PyValueError::new_err(format!("seeds: {e}")))?,
                Err(_) => s.extract::<Vec<u64>>()?,
            }),
        };
        guard(|| {
            let plan = match seeds {
                Some(seeds) => {
                    let options = load::Options {
                        road,
                        ..load::Options::default()
                    };
                    batch::Plan::seeds(&path, &options, seeds)
                }
                None => batch::Plan::load(&path),
            };
            plan.map(|p| BatchPlan { inner: Arc::new(p) }).map_err(|e| {
                let place = match e.kind() {
                    batch::ErrorKind::Plan(batch::PlanErrorKind::RoadNetwork(r)) => r.into(),
                    _ => e.pos().as_ref().into(),
                };
                let message = format!("cannot run the batch of {}: {e}", path.display());
                positioned::<ScenarioError>(py, message, place)
            })
        })
    }

    /// The distribution file.
    #[getter]
    fn distribution(&self) -> String {
        self.inner.distribution.display().to_string()
    }

    /// The ScenarioFile it names.
    #[getter]
    fn scenario(&self) -> String {
        self.inner.scenario.path.display().to_string()
    }

    /// How many variants the distribution has (numbered 0 … n − 1, docs/batch.md).
    #[getter]
    fn variant_count(&self) -> usize {
        self.inner.variants.len()
    }

    /// The varied parameters, in column order.
    #[getter]
    fn parameters(&self) -> Vec<String> {
        self.inner.parameters.clone()
    }

    /// What the plan found but runs anyway, each "message at file:line:col" (a varied parameter
    /// the scenario does not declare: its values vary nothing).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.inner
            .warnings
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    /// Variant `i`'s parameter values by name (as text, as the distribution gives them).
    fn variant<'py>(&self, py: Python<'py>, i: usize) -> PyResult<Bound<'py, PyDict>> {
        let values = self.inner.variants.get(i).ok_or_else(|| {
            pyo3::exceptions::PyIndexError::new_err(format!(
                "expected a variant number below {}, found {i}",
                self.inner.variants.len()
            ))
        })?;
        let d = PyDict::new(py);
        for (k, v) in values {
            d.set_item(k, v)?;
        }
        Ok(d)
    }

    /// Runs the variants numbered `variants` (default: all) on `jobs` threads with the
    /// options of `oscsim batch` and returns their rows as the text of a `results.csv` (rows
    /// in the order given). A failing variant is a row with its error, as on the command line;
    /// `variant_timeout` (s) is `--variant-timeout`. `save` (`csv`, `events`, `osi`:
    /// `oscsim batch --save`) keeps each variant's outputs in `out_dir/variants/NNNNN/`, OSI
    /// traces with `recording_time` (Unix seconds; default the clock) as their recording
    /// time. With `journal` (opened with the same options), each row is recorded there as its
    /// variant ends, as `oscsim batch --out` does. The interpreter's lock is released while
    /// the variants run.
    #[pyo3(signature = (variants = None, *, seed = engine::runtime::DEFAULT_SEED,
        dt = engine::runtime::DEFAULT_DT, duration = None,
        max_time = engine::runtime::DEFAULT_MAX_TIME, host = "Ego".to_owned(), jobs = 1,
        save = Vec::new(), out_dir = None, recording_time = None, variant_timeout = None,
        journal = None))]
    #[allow(clippy::too_many_arguments)] // the keyword options of `oscsim batch`
    fn run(
        &self,
        py: Python<'_>,
        variants: Option<Vec<u64>>,
        seed: u64,
        dt: f64,
        duration: Option<f64>,
        max_time: f64,
        host: String,
        jobs: usize,
        save: Vec<String>,
        out_dir: Option<PathBuf>,
        recording_time: Option<i64>,
        variant_timeout: Option<f64>,
        journal: Option<Bound<'_, BatchJournal>>,
    ) -> PyResult<String> {
        guard(|| {
            let options = options(
                seed,
                dt,
                duration,
                max_time,
                host,
                jobs,
                save,
                out_dir,
                recording_time,
                variant_timeout,
            )?;
            let variants =
                variants.unwrap_or_else(|| (0..self.inner.variants.len() as u64).collect());
            let plan = Arc::clone(&self.inner);
            let journal = journal.as_ref().map(Bound::get);
            py.detach(move || {
                batch::run_each(&plan, &options, &variants, &|row, _, _| {
                    journal.map_or(Ok(()), |j| j.add(row).map(drop))
                })
            })
            .map(|t| t.to_csv())
            .map_err(|e| match e.kind() {
                batch::ErrorKind::Run(batch::RunErrorKind::NoSuchVariant { .. }) => {
                    pyo3::exceptions::PyIndexError::new_err(e.to_string())
                }
                _ => OscsimError::new_err(e.to_string()),
            })
        })
    }

    fn __repr__(&self) -> String {
        format!("BatchPlan({:?})", self.distribution())
    }
}

/// The batch options of the keyword arguments shared by `run` and `BatchJournal`
/// (`ValueError` for a dt, a timeout or a save kind that cannot be).
#[allow(clippy::too_many_arguments)] // the keyword options of `oscsim batch`
fn options(
    seed: u64,
    dt: f64,
    duration: Option<f64>,
    max_time: f64,
    host: String,
    jobs: usize,
    save: Vec<String>,
    out_dir: Option<PathBuf>,
    recording_time: Option<i64>,
    variant_timeout: Option<f64>,
) -> PyResult<batch::Options> {
    let invalid = |m: String| pyo3::exceptions::PyValueError::new_err(m);
    if !(dt.is_finite() && dt > 0.0) {
        return Err(invalid(format!(
            "expected a positive finite dt, found {dt}"
        )));
    }
    let variant_timeout = match variant_timeout {
        Some(s) if s.is_finite() && s > 0.0 => Some(Duration::from_secs_f64(s)),
        Some(s) => {
            return Err(invalid(format!(
                "expected a positive number of seconds for variant_timeout, found {s}"
            )))
        }
        None => None,
    };
    let save = batch::Save::from_kinds(&save).map_err(|e| invalid(format!("save: {e}")))?;
    let save = match (save.any(), out_dir) {
        (false, _) => None,
        (true, Some(dir)) => Some((save, dir)),
        (true, None) => {
            return Err(invalid(
                "expected an out_dir for the saved outputs, found none".to_owned(),
            ))
        }
    };
    Ok(batch::Options {
        seed,
        dt,
        duration,
        max_time,
        host,
        jobs: jobs.max(1),
        save,
        recording_time,
        variant_timeout,
        ..batch::Options::default()
    })
}

/// The journal of a batch run from Python, what `oscsim batch --out` keeps (docs/batch.md):
/// `out_dir/batch.journal` opened for the sweep of `plan` with these options (the variants an
/// earlier run recorded in `done`), rows recorded as they come (`BatchPlan.run(...,
/// journal=…)` as each variant ends; a Ray driver's `record` as each task's share comes back),
/// the results files written by `finish`. Raises `OscsimError` when `out_dir` holds another
/// sweep's results.
#[pyclass(frozen, module = "oscsim")]
pub struct BatchJournal {
    state: Mutex<JournalState>,
}

struct JournalState {
    resumed: batch::Resumed,
    out_dir: PathBuf,
    /// Rows recorded by this driver, by variant.
    added: BTreeMap<u64, batch::Row>,
}

#[pymethods]
impl BatchJournal {
    #[new]
    #[pyo3(signature = (plan, out_dir, *, seed = engine::runtime::DEFAULT_SEED,
        dt = engine::runtime::DEFAULT_DT, duration = None,
        max_time = engine::runtime::DEFAULT_MAX_TIME, host = "Ego".to_owned(),
        save = Vec::new(), recording_time = None, variant_timeout = None))]
    #[allow(clippy::too_many_arguments)] // the keyword options of `oscsim batch`
    fn new(
        plan: &BatchPlan,
        out_dir: PathBuf,
        seed: u64,
        dt: f64,
        duration: Option<f64>,
        max_time: f64,
        host: String,
        save: Vec<String>,
        recording_time: Option<i64>,
        variant_timeout: Option<f64>,
    ) -> PyResult<Self> {
        guard(|| {
            let options = options(
                seed,
                dt,
                duration,
                max_time,
                host,
                1,
                save,
                Some(out_dir.clone()),
                recording_time,
                variant_timeout,
            )?;
            let columns = batch::empty_table(&plan.inner);
            let resumed = batch::Sweep::of(&plan.inner, &options, &columns)
                .map_err(|e| batch::Error::from(batch::ResumeErrorKind::Inputs(e)))
                .and_then(|sweep| batch::open_journal(&out_dir, &sweep, &columns))
                .map_err(|e| OscsimError::new_err(e.to_string()))?;
            Ok(BatchJournal {
                state: Mutex::new(JournalState {
                    resumed,
                    out_dir,
                    added: BTreeMap::new(),
                }),
            })
        })
    }

    /// The variant numbers recorded so far, ascending.
    #[getter]
    fn done(&self) -> Vec<u64> {
        let state = self.lock();
        let mut done: Vec<u64> = state.resumed.table.rows.iter().map(|r| r.variant).collect();
        done.extend(state.added.keys());
        done.sort_unstable();
        done
    }

    /// Records the rows of `csv` (the text of a share's `results.csv`) that are not recorded
    /// yet, each appended to the journal; returns how many were new. A row already recorded
    /// (a share handed back twice) is not counted again.
    fn record(&self, csv: &str) -> PyResult<usize> {
        guard(|| {
            let state = self.lock();
            let share = batch::Table::from_csv(csv, "a share's results")
                .map_err(|e| OscsimError::new_err(e.to_string()))?;
            let columns = &state.resumed.table;
            if share.parameters != columns.parameters
                || share.monitors != columns.monitors
                || share.coverage != columns.coverage
            {
                return Err(OscsimError::new_err(format!(
                    "expected a share with the columns {}, found {}",
                    columns.header(),
                    share.header()
                )));
            }
            drop(state);
            let mut new = 0;
            for row in &share.rows {
                if self
                    .add(row)
                    .map_err(|e| OscsimError::new_err(e.to_string()))?
                {
                    new += 1;
                }
            }
            Ok(new)
        })
    }

    /// Syncs the journal and writes `results.csv`, `results.parquet` and `report.html` of
    /// every recorded row into `out_dir`; returns the text of `results.csv`.
    fn finish(&self, py: Python<'_>) -> PyResult<String> {
        guard(|| {
            let state = self.lock();
            let mut table = state.resumed.table.clone();
            table.rows.extend(state.added.values().cloned());
            table.rows.sort_by_key(|r| r.variant);
            let out_dir = state.out_dir.clone();
            state
                .resumed
                .journal
                .sync()
                .map_err(|e| OscsimError::new_err(e.to_string()))?;
            drop(state);
            py.detach(move || batch::write_outputs(&out_dir, &table).map(|()| table.to_csv()))
                .map_err(|e| OscsimError::new_err(e.to_string()))
        })
    }
}

impl BatchJournal {
    /// Records `row` unless its variant is recorded; whether it was new.
    fn add(&self, row: &batch::Row) -> Result<bool, batch::Error> {
        let mut state = self.lock();
        if state.resumed.has(row.variant) || state.added.contains_key(&row.variant) {
            return Ok(false);
        }
        state.resumed.record(row)?;
        state.added.insert(row.variant, row.clone());
        Ok(true)
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, JournalState> {
        // A panic while the lock was held (turned into InternalError by `guard`) left whole
        // records only (journal.rs): the state is still usable.
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }
}

/// Joins the `results.csv` texts of disjoint shares of one batch into the table of the
/// whole (rows by variant number) and returns its text; with `out_dir`, writes
/// `results.csv`, `results.parquet` and `report.html` there — and `coverage.csv`, counted
/// with the buckets of `plan`'s cover items (a `BatchPlan` of a DSL scenario with coverage) —
/// the files `oscsim batch` writes. Raises `OscsimError` for shares of different batches, a
/// variant in two shares or a text that is not a results table (naming the share, `part K`,
/// and its line).
#[pyfunction]
#[pyo3(signature = (parts, out_dir = None, plan = None))]
pub fn merge_results(
    py: Python<'_>,
    parts: Vec<String>,
    out_dir: Option<PathBuf>,
    plan: Option<PyRef<'_, BatchPlan>>,
) -> PyResult<String> {
    let buckets = plan
        .map(|p| batch::coverage_definitions(&p.inner.coverage))
        .unwrap_or_default();
    guard(|| {
        py.detach(move || {
            let tables = parts
                .iter()
                .enumerate()
                .map(|(k, text)| {
                    let name = format!("part {k}");
                    batch::Table::from_csv(text, &name).map(|t| (t, name))
                })
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| e.to_string())?;
            let mut table = batch::merge_tables(tables).map_err(|e| e.to_string())?;
            table.buckets = buckets;
            if let Some(dir) = &out_dir {
                batch::write_outputs(dir, &table).map_err(|e| e.to_string())?;
            }
            Ok(table.to_csv())
        })
        .map_err(|message: String| OscsimError::new_err(message))
    })
}

/// The summary `oscsim batch` prints (variants, failures, collisions, the worst min_ttc and
/// its variant) of the table in `csv`, the text of a `results.csv`.
#[pyfunction]
pub fn summary(csv: &str) -> PyResult<String> {
    guard(|| {
        batch::Table::from_csv(csv, "results.csv")
            .map(|t| batch::summary(&t))
            .map_err(|e| OscsimError::new_err(e.to_string()))
    })
}
