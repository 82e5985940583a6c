//! The typed OpenSCENARIO 1.3 model, one file per chapter of the standard.

mod actions;
mod common;
mod conditions;
mod entities;
mod enums;
mod environment;
mod positions;
mod routing;
mod scenario;
mod storyboard;
mod triggers;

pub use actions::*;
pub use common::*;
pub use conditions::*;
pub use entities::*;
pub use enums::*;
pub use environment::*;
pub use positions::*;
pub use routing::*;
pub use scenario::*;
pub use storyboard::*;
pub use triggers::*;
