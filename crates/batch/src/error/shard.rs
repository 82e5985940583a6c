//! The kind of a shard selection's error (shard.rs).

/// Why a shard could not be determined.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("expected {expected}, found '{found}' in {source_name}")]
pub struct ShardErrorKind {
    /// What was expected.
    pub expected: &'static str,
    /// What was found.
    pub found: String,
    /// Where: `--shard`, an environment variable's name.
    pub source_name: String,
}
