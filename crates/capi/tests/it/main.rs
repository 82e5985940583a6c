//! The C API's integration tests, one binary (issue 33); each module is one former test file.

mod c_example;
mod control;
mod header;
mod osi;
