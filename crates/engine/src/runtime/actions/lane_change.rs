//! LaneChangeAction (OpenSCENARIO 1.3 §7.7.2.2 "LateralAction", XSD `LaneChangeAction`): move
//! the actor into a target lane (absolute lane id, or lanes to the left of a reference entity's
//! lane as seen in its direction of travel) at `targetLaneOffset` from its centre, along a
//! transition shape over time, distance or lateral rate.
//!
//! The lateral position during the change is a blend of the two lanes' centres at the current
//! s, t = (1 − f)·(centre(from) + offset₀) + f·(centre(to) + offset₁), so lane width changes
//! along the way are followed; the default controller turns it into a pose (heading = road
//! heading + slope of the lateral motion). The state [`LateralState`] is shared with
//! LaneOffsetAction, which blends within one lane.

use scenario::{LaneChangeTarget, LateralAction, SourcePos, TransitionDynamics};

use super::speed::entity_ref;
use super::Part;
use crate::runtime::entity::{Blend, EntityId};
use crate::runtime::error::RuntimeError;
use crate::runtime::lanes::{lane_at, lane_shift};
use crate::runtime::shapes::{progress, shape_value, span, Span};
use crate::runtime::world::World;
use crate::storyboard::ActionStatus;
use scenario::DynamicsShape;

/// A running lateral transition on one actor.
#[derive(Debug, Clone)]
pub(crate) struct LateralState {
    pub shape: DynamicsShape,
    pub span: Span,
    pub start_time: f64,
    pub start_odometer: f64,
    /// Keep running after the transition (continuous LaneOffsetAction).
    pub continuous: bool,
}

impl LateralState {
    /// True when a fixed-time transition that does not hold its target reaches its end by `t`.
    pub(crate) fn completes_by(&self, t: f64) -> bool {
        !self.continuous && matches!(self.span, Span::Time(d) if t - self.start_time >= d - 1e-9)
    }
}

/// Starts a lane change: sets the track's target lane and offset and a blend from the current.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &LateralAction,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, RuntimeError> {
    let LateralAction::LaneChange {
        target_lane_offset,
        dynamics,
        target,
    } = action
    else {
        return Err(RuntimeError::unsupported("this LateralAction", pos));
    };
    let lane = match target {
        LaneChangeTarget::Absolute(id) => id.trim().parse::<i32>().map_err(|_| {
            RuntimeError::at("an OpenDRIVE lane id (integer)", format!("'{id}'"), pos)
        })?,
        LaneChangeTarget::Relative {
            entity_ref: name,
            value,
        } => {
            let reference = world.entity(entity_ref(world, name, pos)?);
            let (Some(rp), Some(track)) = (&reference.road_position, &reference.track) else {
                return Err(RuntimeError::at(
                    "a reference entity on a lane",
                    format!("'{name}' off the road"),
                    pos,
                ));
            };
            lane_shift(rp.lane_id, *value, track.direction)
        }
        _ => return Err(RuntimeError::unsupported("this LaneChangeTarget", pos)),
    };
    begin(
        world,
        actor,
        lane,
        target_lane_offset.unwrap_or(0.0),
        dynamics,
        now,
        false,
        pos,
    )
}

/// Starts a blend of `actor` from where it is to (`lane`, `offset`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn begin(
    world: &mut World,
    actor: EntityId,
    lane: i32,
    offset: f64,
    dynamics: &TransitionDynamics,
    now: f64,
    continuous: bool,
    pos: &SourcePos,
) -> Result<Part, RuntimeError> {
    let net = &world.network;
    let e = world.entity(actor);
    let Some(track) = &e.track else {
        return Err(RuntimeError::at(
            "an actor on a lane",
            format!("'{}' off the road", e.name),
            pos,
        ));
    };
    let road = net.road(&track.road_id).ok_or_else(|| {
        RuntimeError::at("the actor's road", format!("road '{}'", track.road_id), pos)
    })?;
    // A lane beyond the road's outermost lane (a scenario driving off the road) is reached as
    // that many lane widths outside the outermost lane on its side.
    let (lane, offset) = match road.lane_span(lane, track.s) {
        Ok(_) => (lane, offset),
        Err(_) => {
            let section = road.lane_section_at(track.s);
            let outer = if lane > 0 {
                section.left.last().map(|l| l.id)
            } else {
                section.right.last().map(|l| l.id)
            };
            let outer = outer
                .filter(|&o| o != 0 && o.signum() == lane.signum())
                .ok_or_else(|| {
                    RuntimeError::at(
                        "a target lane on a side of the road that has lanes",
                        format!(
                            "lane {lane} on road '{}' at s={:.3}",
                            track.road_id, track.s
                        ),
                        pos,
                    )
                })?;
            let width = road.lane_span(outer, track.s).map_or(0.0, |sp| sp.width());
            let extra = f64::from(lane.abs() - outer.abs()) * width * f64::from(lane.signum());
            (outer, offset + extra)
        }
    };
    let span_to = road.lane_span(lane, track.s).map_err(|e| {
        RuntimeError::at(
            "a target lane that exists at the actor's position",
            e.to_string(),
            pos,
        )
    })?;
    let (from_lane, from_offset) =
        lane_at(road, track.s, track.t).unwrap_or((track.lane_id, track.offset));
    let delta = span_to.center() + offset - track.t;
    let span = span(dynamics, delta);
    let odometer = e.odometer;
    let e = world.entity_mut(actor);
    if let Some(track) = &mut e.track {
        track.lane_id = lane;
        track.offset = offset;
        track.blend = (span != Span::Instant).then_some(Blend {
            from_lane,
            from_offset,
            weight: 0.0,
            weight_per_m: 0.0,
        });
    }
    if span == Span::Instant && !continuous {
        return Ok(Part::Done(ActionStatus::Ended));
    }
    Ok(Part::Lateral(LateralState {
        shape: dynamics.dynamics_shape,
        span,
        start_time: now,
        start_odometer: odometer,
        continuous,
    }))
}

/// Sets the blend weight for the step's end, `now + dt`.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut LateralState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    let e = world.entity_mut(actor);
    let travelled = e.odometer - s.start_odometer + e.speed.abs() * dt;
    let (p, dp_ds) = progress(s.span, now + dt - s.start_time, travelled, e.speed);
    let (f, df) = shape_value(s.shape, p);
    let Some(track) = &mut e.track else {
        return ActionStatus::Ended;
    };
    if p >= 1.0 {
        track.blend = None;
        return if s.continuous {
            ActionStatus::Running
        } else {
            ActionStatus::Ended
        };
    }
    if let Some(b) = &mut track.blend {
        b.weight = f;
        b.weight_per_m = df * dp_ds;
    }
    ActionStatus::Running
}

/// A lateral action stopped midway: the actor keeps the lateral position it has, in the lane
/// that holds it.
pub(crate) fn abandon(world: &mut World, actor: EntityId) {
    let net = &world.network;
    let e = &mut world.entities[actor.index()];
    let Some(track) = &mut e.track else {
        return;
    };
    if track.blend.take().is_some() {
        if let Some((lane, offset)) = net
            .road(&track.road_id)
            .and_then(|r| lane_at(r, track.s, track.t))
        {
            track.lane_id = lane;
            track.offset = offset;
        }
    }
}
