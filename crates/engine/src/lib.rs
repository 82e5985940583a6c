//! The oscsim runtime: entity state, storyboard, actions, conditions, controllers and the
//! physical-object domain model of OpenSCENARIO 2.0 §8.7.
//!
//! | module | implements |
//! | --- | --- |
//! | `domain` | OpenSCENARIO 2.0 §8.7 physical-object actors and their measurement methods |
//! | `storyboard` | OpenSCENARIO 1.3 §7.2.1 / §8.3–8.4 storyboard state machine and triggers |
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod condition;
pub mod domain;
pub mod position;
pub mod storyboard;
