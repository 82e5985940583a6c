//! The kinds of the errors of running the variants (run.rs).

/// Why the batch as a whole could not run (a variant's own failure is a row, not this).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunErrorKind {
    /// The worker pool could not be started.
    #[error("cannot start {jobs} worker threads: {message}")]
    Threads {
        /// The threads asked for.
        jobs: usize,
        /// The pool builder's error.
        message: String,
    },
    /// A variant number that the plan does not have ([`run_variants`](crate::run_variants)).
    #[error("expected a variant number below {count}, found {variant}")]
    NoSuchVariant {
        /// The number asked for.
        variant: u64,
        /// How many variants the plan has.
        count: usize,
    },
}
