//! Source positions: where in which file a model element was written.
//!
//! The type and the offset → `line:col` index are the workspace's one position type, from
//! the `oscsim-source` crate; re-exported here so that `scenario::SourcePos` stays the path
//! users write.

pub(crate) use ::source::LineIndex;
pub use ::source::SourcePos;
