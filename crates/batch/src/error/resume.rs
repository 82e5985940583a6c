//! The kinds of the errors of a sweep going on from its journal (resume.rs).

/// Why a durable batch could not run or finish.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ResumeErrorKind {
    /// The folder holds another sweep's journal.
    #[error("expected the journal of this sweep ({expected}) or none in {dir}, found that of {found}: choose another --out, or remove the folder to start over")]
    OtherSweep {
        /// The output folder.
        dir: String,
        /// This sweep: digest and selection.
        expected: String,
        /// The journal's.
        found: String,
    },
    /// The folder holds results but no journal (an older oscsim's, or `batch merge`'s).
    #[error("expected an empty folder or one with a batch journal, found {found} without {journal} in {dir}: choose another --out, or remove the folder to start over")]
    Unjournaled {
        /// The journal's file name (`journal::JOURNAL_FILE`).
        journal: &'static str,
        /// The output folder.
        dir: String,
        /// What it holds.
        found: String,
    },
    /// A whole journal record that is not a row of this table.
    #[error("expected a results row ({expected}), found {found} in record {record} of {path}")]
    BadRecord {
        /// The journal.
        path: String,
        /// 1-based record number (the header is record 1).
        record: usize,
        /// What was expected.
        expected: String,
        /// What was found.
        found: String,
    },
    /// A file the sweep's digest reads could not be read.
    #[error("{0}")]
    Inputs(String),
}
