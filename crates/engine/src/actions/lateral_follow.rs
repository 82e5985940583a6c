//! oscsim's lane change beside a moving entity (`scenario::LaneChangeTarget::Beside` with
//! `follow`, no XML form): the OpenSCENARIO DSL runtime's `lateral(d, side_of/left_of/right_of:
//! x, at: end, track: actual)` over a phase of duration T that starts on a run-time condition
//! (ASAM OpenSCENARIO DSL 2.1 §8.9 `lateral`, §8.9.1.1.3: with `actual` "the vehicle reacts to
//! the behavior of the referenced vehicle"). No 1.x action follows another entity's t over a
//! duration: a LateralDistanceAction has none, a LaneChangeAction's target is read at its start.
//!
//! The actor's t over the phase is a blend from its own t at the start, t₀, to the target
//! t_x(τ) + d, where x's t moves: t(τ) = (1 − f)·t₀ + f·(t_x(τ) + d), f the transition's shape
//! at τ/T (the DSL runtime gives a sinusoid, f = (1 − cos(π·τ/T))/2, or a shape's own). At τ = T it is x's t then plus d exactly, and a still x gives the sinusoidal
//! lane change of the projected form. Each step the part runs after every other action (the
//! second pass of the action stage, as the RelativeAccelerationAction), so x's own lateral
//! action has set where x's lane track puts x at the step's end, and that is the t_x(τ) the
//! blend reads: no step of lag. The target is written on the actor's lane track as the lane of
//! its side of the road holding it and the offset from that lane's centre (past the outermost
//! lane, that lane and a larger offset), so the default controller's blend of the two lanes
//! gives t(τ); its slope, for the heading, is the blend's rate plus f times x's lateral speed.
//! x off the actor's road (on a plan over several roads: off a road of the plan whose
//! reference line joins the actor's continuously, so that t is one measure), or no driving
//! lane at the target when the action starts, fails it: an error record and a failed run.
//!
//! With a rate (the DSL runtime's `lateral(d, side_of/left_of/right_of: x, at: end, shape: s)`
//! with `track: actual` after a run-time start, §8.9.1.1.4: the shape's lateral dynamics, its
//! `rate_peak` the peak lateral speed) the blend takes the transition's own shape f (linear
//! for a constant profile, sinusoidal for a smooth one) over T = |t_x(0) + d − t₀|·f′max / rate,
//! x read as the action starts, and then holds x's t plus d at every step (as a step shape,
//! below) until the phase's Act stops it: the modifier holds at the phase's end.
//!
//! With a step shape (the DSL runtime's `lateral(d, side_of/left_of/right_of: x)` at: all
//! while x moves sideways, §8.9.1.1.1 "at: all": the constraint holds throughout the phase)
//! there is no transition: the actor's t is t_x(τ) + d at every step's end (f = 1), its slope
//! x's lateral speed, and the action holds until the phase's Act stops it (it never ends of
//! itself). The actor is beside x as it starts (the runtime places or checks it so).

use opendrive::{Road, LENGTH_EPSILON};
use scenario::{DynamicsDimension, DynamicsShape, PlanRoads, SourcePos, TransitionDynamics};

use super::lane_change::{check_failed, same_measure, side_lane, step_speed};
use super::Part;
use crate::error::Error;
use crate::position::lane_at;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;
use crate::world::lane_track::{Blend, LaneTrack};
use crate::world::shapes::{peak_slope, shape_value};

/// A running lane change beside a moving entity on one actor.
#[derive(Debug, Clone)]
pub(crate) struct FollowState {
    /// The entity followed.
    entity: EntityId,
    /// The plan's roads: x may be on another of them where t compares (`same_measure`).
    roads: PlanRoads,
    /// The actor's t minus the entity's at the end (m, + left).
    dt: f64,
    /// The duration T (s).
    duration: f64,
    start_time: f64,
    /// The actor's t at the start (m).
    t0: f64,
    /// No transition: x's t plus `dt` at every step, until the action is stopped (a step
    /// shape).
    holds: bool,
    /// The transition's shape.
    shape: DynamicsShape,
    /// At a rate: after the transition, hold as `holds` until the action is stopped.
    then_holds: bool,
    /// The target at the previous step's end (m): x's lateral speed is its change.
    last_target: f64,
}

impl FollowState {
    /// True when the blend reaches its end by `t`.
    pub(crate) fn completes_by(&self, t: f64) -> bool {
        !self.holds
            && !self.then_holds
            && t - self.start_time >= self.duration - crate::tolerance::TIME
    }
}

/// Starts following `name` at `dt` from it over the transition's time on `actor` at `now`
/// (a step shape: at every step, until stopped).
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    (name, dt, what, roads): (&str, f64, &str, &PlanRoads),
    dynamics: &TransitionDynamics,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let holds = dynamics.dynamics_shape == DynamicsShape::Step;
    let rate = dynamics.dynamics_dimension == DynamicsDimension::Rate;
    let value = dynamics.value;
    // Over a time (the DSL runtime gives the phase's duration) or at a rate.
    if !(holds || value > 0.0 && value.is_finite()) {
        return Err(Error::at(
            if rate {
                "a rate above 0 m/s"
            } else {
                "a duration above 0 s"
            },
            format!("{value}"),
            pos,
        ));
    }
    let fail = check_failed(what, now);
    let x = entity_ref(world, name, pos)?;
    let target = target_t(world, actor, (x, roads), dt).map_err(|(e, f)| fail(e, f))?;
    let e = world.entity(actor);
    let Some(ta) = &e.track else {
        return Err(fail(
            format!("'{}' on a lane", e.name),
            "it off every road".into(),
        ));
    };
    let road = world.network.road_at(ta.road);
    if side_lane(road, ta, target).is_none() {
        return Err(fail(
            format!(
                "a driving lane of road {} at t = {target:.3} m, s = {:.3} m ({dt:.3} m from '{name}')",
                ta.road_id, ta.s
            ),
            "none".into(),
        ));
    }
    let (from_lane, from_offset) = lane_at(road, ta.s, ta.t).unwrap_or((ta.lane_id, ta.offset));
    let t0 = ta.t;
    let (shape, duration) = match (holds, rate) {
        (false, true) => (
            dynamics.dynamics_shape,
            (target - t0).abs() * peak_slope(dynamics.dynamics_shape) / value,
        ),
        _ => (dynamics.dynamics_shape, value),
    };
    let net = world.network.clone();
    let e = world.entity_mut(actor);
    if let Some(track) = &mut e.track {
        aim(net.road_at(track.road), track, target);
        track.blend = Some(Blend {
            from_lane,
            from_offset,
            weight: if holds { 1.0 } else { 0.0 },
            weight_per_m: 0.0,
        });
    }
    Ok(Part::LateralFollow(FollowState {
        entity: x,
        roads: roads.clone(),
        dt,
        duration,
        start_time: now,
        t0,
        holds,
        shape,
        then_holds: rate && !holds,
        last_target: target,
    }))
}

/// Sets the blend for the step's end, `now + dt`, towards x's t there plus the distance asked.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut FollowState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    let Ok(target) = target_t(world, actor, (s.entity, &s.roads), s.dt) else {
        // x left the actor's road: the blend holds its last target.
        return ActionStatus::Running;
    };
    let p = if s.duration > 0.0 {
        ((now + dt - s.start_time) / s.duration).min(1.0)
    } else {
        1.0
    };
    // No transition (or one over): at x's t plus d, held until stopped.
    let holding = s.holds || (s.then_holds && p >= 1.0);
    let (f, df) = if holding {
        (1.0, 0.0)
    } else {
        shape_value(s.shape, p)
    };
    let net = world.network.clone();
    let e = world.entity_mut(actor);
    let speed = step_speed(e);
    let Some(track) = &mut e.track else {
        return ActionStatus::Ended;
    };
    aim(net.road_at(track.road), track, target);
    let x_rate = if dt > 0.0 {
        (target - s.last_target) / dt
    } else {
        0.0
    };
    s.last_target = target;
    if p >= 1.0 && !holding {
        track.blend = None;
        return ActionStatus::Ended;
    }
    // The lateral speed of t(τ) = (1 − f)·t₀ + f·target: f′/T·(target − t₀) + f·target′.
    let lateral = if holding {
        x_rate
    } else {
        df / s.duration * (target - s.t0) + f * x_rate
    };
    let sin = if speed * dt > LENGTH_EPSILON {
        (lateral / speed).clamp(-1.0, 1.0)
    } else {
        0.0
    };
    if let Some(b) = &mut track.blend {
        b.weight = f;
        let span = target - s.t0;
        b.weight_per_m = if span.abs() > LENGTH_EPSILON {
            sin.asin().tan() / span
        } else {
            0.0
        };
    }
    ActionStatus::Running
}

/// x's t where its lane track puts it at the step's end (its blend, if it has one), plus `dt`;
/// an error (expected, found) when x is off the actor's road (or off a road of the plan's
/// `roads` whose t compares with the actor's).
fn target_t(
    world: &World,
    actor: EntityId,
    (x, roads): (EntityId, &PlanRoads),
    dt: f64,
) -> Result<f64, (String, String)> {
    let (a, o) = (world.entity(actor), world.entity(x));
    let (Some(ta), Some(tx)) = (&a.track, &o.track) else {
        return Err((
            format!("'{}' and '{}' on a lane", a.name, o.name),
            "one of them off every road".into(),
        ));
    };
    same_measure(world, roads, (ta, tx), (&a.name, &o.name))?;
    let road = world.network.road_at(tx.road);
    let center = |lane: i32| road.lane_span(lane, tx.s).map(|sp| sp.center()).ok();
    let to = center(tx.lane_id).map_or(tx.t, |c| c + tx.offset);
    let t = match &tx.blend {
        Some(b) => match center(b.from_lane) {
            Some(c) => (1.0 - b.weight) * (c + b.from_offset) + b.weight * to,
            None => to,
        },
        None => to,
    };
    Ok(t + dt)
}

/// Writes target `t` on `track`: the lane of its side holding it and the offset, else its
/// lane and the offset from that lane's centre.
fn aim(road: &Road, track: &mut LaneTrack, t: f64) {
    match side_lane(road, track, t) {
        Some((lane, offset)) => {
            track.lane_id = lane;
            track.offset = offset;
        }
        None => {
            if let Ok(sp) = road.lane_span(track.lane_id, track.s) {
                track.offset = t - sp.center();
            }
        }
    }
}
