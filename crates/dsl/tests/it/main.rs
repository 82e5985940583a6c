//! The dsl crate's integration tests, one binary (issue 33); each module is one former test
//! file, `support` their shared helpers.

mod domain_model;
mod seed_examples;
mod semantics;
mod semantics_proptest;
mod support;
mod syntax;
mod syntax_ast;
mod syntax_robustness;
