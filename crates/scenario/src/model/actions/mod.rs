//! Actions (OpenSCENARIO 1.3 §7.7): private, global, traffic, appearance.

mod appearance;
mod global;
mod private;
mod traffic;

pub use appearance::*;
pub use global::*;
pub use private::*;
pub use traffic::*;
