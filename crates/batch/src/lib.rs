//! Variation at scale (OpenSCENARIO 1.3 §9.5 "Parameter value distributions"): run every
//! variant of a ParameterValueDistribution file and tabulate what happened in each; or every
//! seed of an OpenSCENARIO DSL scenario, its constraints re-solved per seed.
//!
//! | module | job |
//! | --- | --- |
//! | `error` | `Error`, the crate's one error: `kind()` (which stage, its own kinds), `pos()` (the file position, where there is one) |
//! | `plan` | the distribution file → numbered variants, checked against the ScenarioFile; or the seeds of a DSL scenario |
//! | `seed` | each variant's random seed from the batch seed and its number |
//! | `shard` | disjoint shares for several processes: `--shard I/N`, Slurm arrays, Kubernetes Indexed Jobs |
//! | `coverage` | the cover items' buckets, hits and holes; `coverage.csv` (§7.3.12) |
//! | `metrics` | collision, time to collision, headway and gap of the host, by the §8.7 methods |
//! | `run` | the variants on a rayon pool, results by variant number |
//! | `guard` | a variant's wall-clock limit (`--variant-timeout`) and its panics, each a failed row |
//! | `save` | per-variant outputs: trajectories, event log, OSI trace (`--save csv,events,osi`), renamed into place whole |
//! | `journal` | `batch.journal`: each finished variant's record, appended as it ends, readable after any kill |
//! | `sweep` | what identifies a sweep: a digest of its inputs and options, its selection, its columns |
//! | `resume` | a batch that goes on from its journal when run again, never mixing two sweeps |
//! | `table` | the results table and `results.csv` |
//! | `parquet_file` | `results.parquet` |
//! | `merge` | shard outputs joined into what one unsharded run writes |
//! | `report` | the summary and `report.html` |
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod coverage;
mod error;
mod guard;
mod journal;
mod merge;
mod metrics;
mod parquet_file;
mod plan;
mod report;
mod resume;
mod run;
mod save;
mod seed;
mod shard;
mod sweep;
mod table;

pub use coverage::{
    column as coverage_column, count as count_coverage, definitions as coverage_definitions,
    ItemCoverage,
};
pub use engine::StopReason;
pub use error::{
    CsvErrorKind, Error, ErrorKind, JournalErrorKind, MergeErrorKind, ParquetErrorKind,
    PlanErrorKind, ResumeErrorKind, RunErrorKind, ShardErrorKind,
};
pub use journal::{read as read_journal, Contents as JournalContents, Journal, JOURNAL_FILE};
pub use merge::{merge, merge_tables, write_outputs};
pub use metrics::{Measures, Observer};
pub use parquet_file::to_parquet;
pub use plan::{parse_seeds, Plan, Seeds, MAX_SEEDS};
pub use report::{report_html, summary};
pub use resume::{open as open_journal, run_durable, Finished, Resumed};
pub use run::{empty_table, run, run_each, run_variants, selected, Options};
pub use save::{variant_dir, Save};
pub use seed::variant_seed;
pub use shard::Shard;
pub use sweep::Sweep;
pub use table::{
    quantize, quantize_time, BucketDef, CoverDef, Outcome, Row, Table, FIXED_COLUMNS, REFUSED,
    REFUSED_STOP,
};
