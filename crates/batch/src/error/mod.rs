//! [`Error`], the one error of the batch crate: planning a sweep, running it, its journal,
//! resuming it, its results files and merging shards. Its [`kind`](Error::kind) is the
//! `#[non_exhaustive]` [`ErrorKind`], one variant per stage, each holding that stage's own
//! kinds; the errors of the crates below (`scenario`, `opendrive`, `load`) stay typed inside,
//! and [`Error::pos`] is the file position where the error has one (the distribution file,
//! the scenario, its road network, a line of a shard's `results.csv`).
//!
//! Messages follow the project's form "expected X, found Y at file:line:col". The kinds are
//! defined here, one file per stage, so that the stages import the error and the error none
//! of the stages (no module cycle).

use std::path::Path;
use std::sync::Arc;

use scenario::SourcePos;

mod csv;
mod journal;
mod merge;
mod parquet;
mod plan;
mod resume;
mod run;
mod shard;

pub use csv::CsvErrorKind;
pub use journal::JournalErrorKind;
pub use merge::MergeErrorKind;
pub use parquet::ParquetErrorKind;
pub use plan::PlanErrorKind;
pub use resume::ResumeErrorKind;
pub use run::RunErrorKind;
pub use shard::ShardErrorKind;

/// An error of the batch crate.
#[derive(Debug, thiserror::Error)]
#[error("{kind}")]
pub struct Error {
    kind: Box<ErrorKind>,
}

impl Error {
    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// Where in a file, if the error has a place: the distribution file's element, the
    /// scenario's (through `scenario`, `load`), the road network's (`opendrive`), or the line
    /// of a `results.csv` (column 1).
    pub fn pos(&self) -> Option<SourcePos> {
        match &*self.kind {
            ErrorKind::Plan(p) => match p {
                PlanErrorKind::Distribution(d) => Some(d.pos().clone()),
                PlanErrorKind::MissingScenario { pos, .. } | PlanErrorKind::Seeds { pos, .. } => {
                    Some(pos.clone())
                }
                PlanErrorKind::Scenario(s) => Some(s.pos().clone()),
                PlanErrorKind::Load(l) => l.pos(),
                PlanErrorKind::RoadNetwork(r) => r.pos().cloned(),
                _ => None,
            },
            ErrorKind::Csv(c) => Some(SourcePos::new(
                Arc::from(Path::new(&c.file)),
                u32::try_from(c.line).unwrap_or(u32::MAX),
                1,
            )),
            _ => None,
        }
    }
}

/// The kinds of [`Error`]: which stage failed, with that stage's own kind.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The distribution file or the scenario could not be planned into variants (plan.rs).
    #[error(transparent)]
    Plan(PlanErrorKind),
    /// The variants could not run (run.rs).
    #[error(transparent)]
    Run(RunErrorKind),
    /// A shard selection that is not one (shard.rs).
    #[error(transparent)]
    Shard(ShardErrorKind),
    /// A `results.csv` that is not a results table (table.rs).
    #[error(transparent)]
    Csv(CsvErrorKind),
    /// The Parquet writer failed (parquet_file.rs).
    #[error(transparent)]
    Parquet(ParquetErrorKind),
    /// The journal could not be read or written (journal.rs).
    #[error(transparent)]
    Journal(JournalErrorKind),
    /// Shards could not be merged, or the results files not written (merge.rs).
    #[error(transparent)]
    Merge(MergeErrorKind),
    /// A sweep could not go on from its journal (resume.rs).
    #[error(transparent)]
    Resume(ResumeErrorKind),
}

macro_rules! from_kind {
    ($($variant:ident($kind:ty)),* $(,)?) => {$(
        impl From<$kind> for Error {
            fn from(kind: $kind) -> Self {
                Error { kind: Box::new(ErrorKind::$variant(kind)) }
            }
        }
    )*};
}

from_kind!(
    Plan(PlanErrorKind),
    Run(RunErrorKind),
    Shard(ShardErrorKind),
    Csv(CsvErrorKind),
    Parquet(ParquetErrorKind),
    Journal(JournalErrorKind),
    Merge(MergeErrorKind),
    Resume(ResumeErrorKind),
);
