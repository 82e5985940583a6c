//! The batch crate's integration tests, one binary (issue 33: one test binary per crate where
//! that costs nothing); each module is one former test file.

mod alks_sweep;
mod grid;
mod plan;
mod road_choice;
mod seeds;
