//! Conditions at runtime: the raw value of every OpenSCENARIO 1.3 §7.6 condition
//! (ByValueCondition and ByEntityCondition), measured through the OpenSCENARIO 2.0 §8.7
//! methods of `domain`; edges and delay are the storyboard's job. Written by hand: the
//! semantics are the standard's own.
//!
//! | module | implements |
//! | --- | --- |
//! | `context` | `ConditionContext`: what a condition may ask the runtime |
//! | `state` | `ConditionState`: memory of the duration conditions, keyed by condition id |
//! | `registry` | `UserValueRegistry`: the external values UserDefinedValueCondition reads |
//! | `error` | `ConditionError`, `ConditionErrorKind` |
//! | `rule` | XSD `Rule` on numbers (with the equalTo tolerance) and typed values |
//! | `by_value` | SimulationTime, Parameter, Variable, UserDefinedValue, StoryboardElementState, TimeOfDay, TrafficSignal, TrafficSignalController |
//! | `target` | what a distance is measured to: an entity or a position, with or without its box |
//! | `measure` | distances: freespace, coordinateSystem, relativeDistanceType; their rates |
//! | `road_distance` | the road and lane coordinate distances of `measure` |
//! | `motion` | Speed, RelativeSpeed, Acceleration, StandStill, TraveledDistance |
//! | `road_state` | EndOfRoad, Offroad, Collision |
//! | `spacing` | Distance, RelativeDistance, ReachPosition, TimeHeadway, TimeToCollision |
//! | `clearance` | RelativeClearance |
//! | `angle` | Angle, RelativeAngle |
//! | `mark` | oscsim's marks a state check notes: TraveledSinceMark, GapReachedSinceMark (no XML form) |
//! | `place` | oscsim's PlaceReached: a place along the plan's roads reached (no XML form) |
//! | `refs` | `ConditionRefs`: a condition's entities, selections, mark and position resolved once, when the storyboard is built |
//! | `by_entity` | TriggeringEntities any / all, dispatch of EntityCondition |
//! | `evaluate` | `evaluate`: the front door |

mod angle;
mod by_entity;
mod by_value;
mod clearance;
mod context;
mod error;
mod evaluate;
mod mark;
mod measure;
mod motion;
mod place;
mod refs;
mod registry;
mod road_distance;
mod road_state;
mod rule;
mod spacing;
mod state;
mod target;

pub use context::ConditionContext;
pub use error::{ConditionError, ConditionErrorKind};
pub use evaluate::evaluate;
pub(crate) use evaluate::evaluate_resolved;
pub(crate) use mark::place_error;
pub use mark::{Mark, MarkId, Projection};
pub(crate) use mark::{MarkIds, Marks};
pub(crate) use measure::distance as measured_distance;
pub use motion::{DURATION_TOLERANCE, STAND_STILL_SPEED};
pub use refs::SelectionId;
pub(crate) use refs::{ConditionRefs, Names, RefError};
pub use registry::UserValueRegistry;
pub use road_state::END_OF_ROAD_TOLERANCE;
pub use rule::{compare, EQUAL_TOLERANCE};
pub use state::{ConditionState, ConditionStates};
pub(crate) use target::Target as MeasureTarget;
