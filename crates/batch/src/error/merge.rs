//! The kinds of the errors of merging shards and writing the results files (merge.rs).

/// Why shard outputs could not be merged or outputs written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum MergeErrorKind {
    /// A file could not be read, written or copied.
    #[error("{what} {path}: {message}")]
    Io {
        /// What was being done.
        what: &'static str,
        /// The path.
        path: String,
        /// The I/O error.
        message: String,
    },
    /// Shards whose journals name different sweeps (other inputs or options).
    #[error("expected shards of one sweep, found the journal of another in {other} (the first is {first})")]
    DifferentSweeps {
        /// The first shard's journal.
        first: String,
        /// The shard that differs.
        other: String,
    },
    /// A shard whose journal lacks some of its variants (it was stopped).
    #[error("expected a finished shard, found {recorded} of its {variants} variants recorded in {journal}: run its command again to finish it")]
    Unfinished {
        /// The shard's journal.
        journal: String,
        /// Variants recorded.
        recorded: usize,
        /// Variants of its selection.
        variants: usize,
    },
    /// Shards of different batches: other parameters or monitors.
    #[error(
        "expected shards of one batch with the header of {first}, found another header in {other}"
    )]
    DifferentBatches {
        /// The first shard's file.
        first: String,
        /// The shard that differs.
        other: String,
    },
    /// Two shards ran the same variant.
    #[error("expected disjoint shards, found variant {variant} in {first} and in {other}")]
    Overlap {
        /// The variant.
        variant: u64,
        /// One shard's file.
        first: String,
        /// The other's.
        other: String,
    },
}
