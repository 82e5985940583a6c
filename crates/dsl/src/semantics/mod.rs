//! Semantics of the OpenSCENARIO DSL 2.1: resolution, types and units, standard library,
//! constraints.
//!
//! | module | implements |
//! | --- | --- |
//! | `units` | physical types, units, dimensions over SI base units (§7.3.4) |
//! | `solver` | constraint solving for `keep` (§7.3.6): interval propagation, defaults, seeded sampling |
//! | `stdlib` | the standard library `osc.standard` as shipped `.osc` source (chapter 8) |

pub mod solver;
pub mod stdlib;
pub mod units;
