//! The oscsim runtime: entity state, storyboard, actions, conditions, controllers and the
//! physical-object domain model of OpenSCENARIO 2.0 §8.7.
#![forbid(unsafe_code)]
#![deny(missing_docs)]
