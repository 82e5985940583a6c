//! Source positions: where in which file something was written, shown as `file:line:col`.
//!
//! The one position type of the workspace. Every reader — OpenDRIVE road files
//! (`opendrive`), OpenSCENARIO 1.x XML scenarios, catalogs and parameter value distributions
//! (`scenario`), OpenSCENARIO DSL 2.x files (`dsl`) — reports places as a [`SourcePos`], and
//! turns byte offsets into 1-based line and column with one [`LineIndex`].
//!
//! Lines end at `\n`, `\r\n` or a lone `\r` (XML 1.0 §2.11 end-of-line handling; the DSL
//! lexer reads the same three). Columns count characters (Unicode scalar values), as
//! roxmltree's `TextPos` does, not bytes.
//!
//! No dependencies: every other crate may use it without the dependency graph gaining a
//! second direction.
//!
//! | module | job |
//! | --- | --- |
//! | `pos` | [`SourcePos`]: a file and a 1-based line and column, shown as `file:line:col` |
//! | `line_index` | [`LineIndex`]: byte offset → line:col by a binary search over the line starts |

#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod line_index;
mod pos;

pub use line_index::LineIndex;
pub use pos::SourcePos;
