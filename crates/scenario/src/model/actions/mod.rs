//! Actions (OpenSCENARIO 1.3, "Actions"): private, global, traffic, appearance.

mod appearance;
mod global;
mod private;
mod traffic;

pub use appearance::*;
pub use global::*;
pub use private::*;
pub use traffic::*;
