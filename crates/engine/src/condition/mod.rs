//! Conditions at runtime: the raw value of every OpenSCENARIO 1.3 §7.6 condition
//! (ByValueCondition and ByEntityCondition); edges and delay are the storyboard's job.
//!
//! | module | implements |
//! | --- | --- |
//! | `context` | `ConditionContext`: what a condition may ask the runtime |
//! | `state` | `ConditionState`: memory of the duration conditions, keyed by condition id |

mod context;
mod state;

pub use context::ConditionContext;
pub use state::{ConditionState, ConditionStates};
