//! The replay crate's integration tests, one binary (issue 33); each module is one former test
//! file.

mod road_drawing;
mod run_files;
