//! Positions at runtime: OpenSCENARIO 1.3 §6.3 coordinate systems and the ten `Position`
//! forms resolved to a world pose and a road position.
//!
//! | module | implements |
//! | --- | --- |
//! | `query` | `EntityQuery` / `EntityView`: the runtime's read-only answers about entities |

mod query;

pub use query::{EntityQuery, EntityView};
