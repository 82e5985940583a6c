//! The load crate's integration tests, one binary (issue 33: one test binary per crate where
//! that costs nothing); each module is one former test file.

use std::path::{Path, PathBuf};

mod external;
mod front_door;

/// `rel` from the repository's root.
fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel)
}
