//! A fixture crate for `modules::module_folders` (read as tokens, never compiled).
mod a;
mod b;
