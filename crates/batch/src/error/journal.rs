//! The kinds of a journal's errors (journal.rs: `batch.journal`, read after any kill).

/// Why a journal could not be read or written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum JournalErrorKind {
    /// Reading, writing or syncing failed.
    #[error("cannot {what} {path}: {message}")]
    Io {
        /// What was being done.
        what: &'static str,
        /// The file.
        path: String,
        /// The I/O error.
        message: String,
    },
    /// The file does not start with the journal's magic bytes (`OSCSIMJ1`), or has no whole
    /// first record.
    #[error(
        "expected an oscsim batch journal ({magic} and a header record), found {found} at {path}"
    )]
    NotAJournal {
        /// The file.
        path: String,
        /// What it starts with.
        found: String,
        /// The magic bytes a journal starts with (`journal::MAGIC`).
        magic: String,
    },
    /// A record too long to be one (longer than `journal::MAX_RECORD`, 64 MiB) was offered.
    #[error("expected a journal record of at most {max} bytes, found {len} bytes")]
    TooLong {
        /// Its length.
        len: usize,
        /// The longest record (`journal::MAX_RECORD`).
        max: usize,
    },
}
