//! The kind of the error of writing `results.parquet` (parquet_file.rs).

/// Why the Parquet file could not be made.
#[derive(Debug, thiserror::Error)]
#[error("cannot write the results as Parquet: {0}")]
pub struct ParquetErrorKind(pub(crate) String);
