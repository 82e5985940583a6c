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
//!
//! oscsim's offset change in the lane's width (`LateralAction::OffsetInWidth`, no XML form; the
//! DSL runtime's `lateral(d, measure_by: …, at: end)` from a border of the lane over a phase
//! that starts on a run-time condition, ASAM OpenSCENARIO DSL 2.1 §8.9: "at: end" the
//! constraint holds at the end of the phase) aims at k·W + c from the lane's centre, W the
//! lane's width where the actor is (in its own lane, or in the target lane of a lane change
//! beside it): read at each step's end (`lane_change::step`), the
//! sinusoid's target moves with the width, t(τ) = centre(s) + (1 − f)·o₀ + f·(k·W(s) + c),
//! so at the end the offset is the one the lane's width there asks for. A 1.x LaneOffsetAction
//! reads its target once, and the plan cannot know where a run-time phase ends.

use scenario::{
    DynamicsDimension, DynamicsShape, LaneOffsetTarget, LateralAction, OffsetInWidth, SourcePos,
    TransitionDynamics,
};

use super::lane_change::{begin, lane_track, InWidth};
use super::Part;
use crate::error::Error;
use crate::store::targets::{entity_ref, target_lane};
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
    let track = lane_track(e, pos)?;
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

/// Starts oscsim's offset change in the lane's width `w` (`LateralAction::OffsetInWidth`) on
/// `actor` at `now`: a change within its own lane (or into `w`'s target lane, a lane change)
/// over the duration, from where it is, to k·W + c from that lane's centre with its width W
/// where the actor is (then at each step, `lane_change::step`).
pub(crate) fn start_in_width(
    world: &mut World,
    actor: EntityId,
    w: &OffsetInWidth,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    if !(w.duration > 0.0 && w.duration.is_finite()) {
        return Err(Error::at(
            "a duration above 0 s",
            format!("{} s", w.duration),
            pos,
        ));
    }
    let track = lane_track(world.entity(actor), pos)?;
    let lane = match &w.lane {
        Some(target) => target_lane(world, target, pos)?,
        None => track.lane_id,
    };
    let width = world
        .network
        .road_at(track.road)
        .lane_span(lane, track.s)
        .map_err(|err| Error::at("the target lane at the actor's s", err.to_string(), pos))?
        .width();
    let offset = w.per_width * width + w.offset;
    let dynamics = TransitionDynamics {
        dynamics_shape: w.shape,
        dynamics_dimension: DynamicsDimension::Time,
        value: w.duration,
        following_mode: None,
    };
    let mut part = begin(world, actor, lane, offset, &dynamics, now, false, pos)?;
    if let Part::Lateral(state) = &mut part {
        state.in_width = Some(InWidth {
            per_width: w.per_width,
            offset: w.offset,
            last: offset,
        });
    }
    Ok(part)
}
