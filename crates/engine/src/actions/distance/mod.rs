//! LongitudinalDistanceAction and LateralDistanceAction (OpenSCENARIO 1.3 §7.7.2.1
//! "LongitudinalAction" and §7.7.2.2 "LateralAction"; XSD `LongitudinalDistanceAction`,
//! `LateralDistanceAction`, `DynamicConstraints`): keep a distance (longitudinally also a time
//! gap) to a reference entity, once or continuously.
//!
//! | module | implements |
//! | --- | --- |
//! | `gauge` | the signed distance along one axis in the action's `coordinateSystem`, with `freespace` |
//! | `law` | the limits from DynamicConstraints and Performance, and the approach law |
//! | `longitudinal` | LongitudinalDistanceAction: distance / timeGap, displacement, speed control |
//! | `lateral` | LateralDistanceAction: distance, displacement, lateral motion on the lane |

mod gauge;
mod lateral;
mod law;
mod longitudinal;

pub(crate) use lateral::{start_lateral, step_lateral, LateralState};
pub(crate) use longitudinal::{start_longitudinal, step_longitudinal, LongitudinalState};
