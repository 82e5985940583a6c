//! The opendrive crate's integration tests, one binary (issue 33); each module is one former
//! test file, `common` their shared helpers.

mod common;
mod errors;
mod fuzz_found;
mod graph_route;
mod mark_stretches;
mod positions;
mod properties;
mod reference_lanes;
mod reference_lookup;
mod road_marks;
mod signals;
