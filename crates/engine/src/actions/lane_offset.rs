//! LaneOffsetAction (OpenSCENARIO 1.3 §7.7.2.2, XSD `LaneOffsetAction`): move the actor to an
//! offset from its lane's centre (absolute, or relative to a reference entity's offset) with a
//! shape whose duration follows from `maxLateralAcc`.
//!
//! The peak lateral acceleration of a change Δ over duration T is Δ·π²/(2T²) for sinusoidal
//! and 6Δ/T² for cubic, so T = π·√(Δ/(2a)) and T = √(6Δ/a). A linear change has unbounded
//! acceleration at its ends whatever its duration, and the standard gives it none; oscsim
//! takes the cubic's, T = √(6Δ/a), as esmini does (TransitionDynamics::
//! GetTargetParamValByPrimPrimPeak), so that the two agree. Without `maxLateralAcc`
//! a = 0.5 m/s², esmini's default too (a gentle, comfortable value).
//! `continuous="true"` keeps the action running (holding the offset) until it is replaced. A
//! relative target is read once, at the start: with `continuous="true"` the offset is not
//! kept relative to a reference that moves on (the 1.0 model documentation's "continuously
//! kept lane offset"; not done).

use scenario::{
    DynamicsDimension, DynamicsShape, LaneOffsetTarget, LateralAction, SourcePos,
    TransitionDynamics,
};

use super::lane_change::begin;
use super::Part;
use crate::error::Error;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::world::entity::EntityId;

/// Lateral acceleration (m/s²) when the action gives none.
const DEFAULT_MAX_LATERAL_ACC: f64 = 0.5;

/// Starts the action.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &LateralAction,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let LateralAction::LaneOffset {
        continuous,
        dynamics_shape,
        max_lateral_acc,
        target,
    } = action
    else {
        return Err(Error::unsupported("this LateralAction", pos));
    };
    let offset = match target {
        LaneOffsetTarget::Absolute(v) => *v,
        LaneOffsetTarget::Relative {
            entity_ref: name,
            value,
        } => {
            let r = world.entity(entity_ref(world, name, pos)?);
            r.road_position.as_ref().map_or(0.0, |rp| rp.offset) + value
        }
        _ => return Err(Error::unsupported("this LaneOffsetTarget", pos)),
    };
    let e = world.entity(actor);
    let Some(track) = &e.track else {
        return Err(Error::at(
            "an actor on a lane",
            format!("'{}' off the road", e.name),
            pos,
        ));
    };
    let lane = e
        .road_position
        .as_ref()
        .map_or(track.lane_id, |rp| rp.lane_id);
    let current = e
        .road_position
        .as_ref()
        .map_or(track.offset, |rp| rp.offset);
    let a = max_lateral_acc
        .filter(|a| *a > 0.0)
        .unwrap_or(DEFAULT_MAX_LATERAL_ACC);
    let delta = (offset - current).abs();
    let duration = match dynamics_shape {
        DynamicsShape::Sinusoidal => std::f64::consts::PI * (delta / (2.0 * a)).sqrt(),
        DynamicsShape::Cubic | DynamicsShape::Linear => (6.0 * delta / a).sqrt(),
        _ => 0.0,
    };
    let dynamics = TransitionDynamics {
        dynamics_shape: *dynamics_shape,
        dynamics_dimension: DynamicsDimension::Time,
        value: duration,
        following_mode: None,
    };
    begin(world, actor, lane, offset, &dynamics, now, *continuous, pos)
}
