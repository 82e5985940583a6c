//! The OpenSCENARIO DSL 2.x front end (ASAM OpenSCENARIO DSL 2.1, compatible with 2.0).
//!
//! | module | implements |
//! | --- | --- |
//! | `syntax` | lexer, parser and lossless concrete syntax tree with spans; canonical formatting (language reference: lexical structure, grammar) |
//! | `semantics` | name resolution, types and physical units, the standard library, constraint solving; the front door (`check`, `CheckedProgram::resolve`) and the crate's one `Error` |
//!
//! Every fallible front-door function returns [`Error`]: its [`kind`](Error::kind) says whether
//! the program did not check or did not resolve with a seed, and holds every error as
//! [`Diagnostics`]; [`Error::pos`] is the first one's `FILE:LINE:COL`.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod semantics;
pub mod syntax;

pub use semantics::program::{
    check, check_source, check_source_with, source_pos, CheckedProgram, Diagnostics, Error,
    ErrorKind, Source,
};
pub use semantics::resolve::{Resolution, Value};
pub use source::SourcePos;
