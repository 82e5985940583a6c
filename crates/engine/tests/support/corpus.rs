//! Where the engine's tests find their inputs: the shared corpus beside the repository
//! (`../shared/corpus/`, described by its README) and this crate's fixtures (`tests/files/`).
//! Every test target includes this one module; the area helpers build on it.

#![allow(dead_code)] // each test target uses a different part

use std::path::PathBuf;

/// A file or folder of the shared corpus, by its path below `shared/corpus/`.
pub fn corpus(rel: &str) -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
    .join(rel)
}

/// A file or folder of this crate's fixtures, by its path below `tests/files/`.
pub fn fixture(rel: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files")).join(rel)
}
