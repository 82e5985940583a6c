//! LaneChangeAction (OpenSCENARIO 1.3 §7.7.2.2 "LateralAction", XSD `LaneChangeAction`): move
//! the actor into a target lane (absolute lane id, or lanes to the left of a reference entity's
//! lane as seen in its direction of travel) at `targetLaneOffset` from its centre, along a
//! transition shape over time, distance or lateral rate. Progress p runs on the clock for
//! `time` and `rate` (the rate read as the peak lateral speed, [`crate::world::shapes`]) and
//! on the distance travelled along the road for `distance` (not the longer path the entity
//! drives: at 3.5 m over 50 m the two differ by 0.15 m). The model documentation of
//! LaneChangeAction: "Time and distance are measured between the start position and the end
//! position of the action"; between two road positions oscsim reads that distance along the
//! road, as esmini does (LatLaneChangeAction steps the shape by the longitudinal part of each
//! step).
//!
//! The lateral position during the change is a blend of the two lanes' centres at the current
//! s, t = (1 − f)·(centre(from) + offset₀) + f·(centre(to) + offset₁), so lane width changes
//! along the way are followed; the default controller turns it into a pose (heading = road
//! heading + slope of the lateral motion). The state [`LateralState`] is shared with
//! LaneOffsetAction, which blends within one lane. oscsim's lane change that arrives at a place
//! along the road (`LateralAction::LaneChangeAt`, no XML form) is one in the distance
//! dimension whose distance, along the actor's lane to the place, is measured at its start (on
//! a plan over several roads across their joints, `position::RoadChain`, the place in the
//! plan's s).

use opendrive::LENGTH_EPSILON;
use opendrive::{Direction, Road};
use scenario::{
    DynamicsDimension, LaneChangeAt, LaneChangeTarget, LateralAction, PlanRoads, SourcePos,
    TransitionDynamics,
};

use super::Part;
use crate::error::{Error, ErrorKind};
use crate::position::{lane_arc_length, lane_at, RoadChain};
use crate::store::targets::{entity_ref, target_lane};
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::{Entity, EntityId};
use crate::world::lane_track::{Blend, LaneTrack};
use crate::world::shapes::{progress, shape_value, span, Span};
use scenario::DynamicsShape;

/// A running lateral transition on one actor.
#[derive(Debug, Clone)]
pub(crate) struct LateralState {
    pub shape: DynamicsShape,
    pub span: Span,
    pub start_time: f64,
    /// The lateral change Δt (m) from the start to the target, as measured at the start.
    pub delta: f64,
    /// Distance (m) travelled along the road since the start (drives a distance span).
    pub along: f64,
    /// The previous step of a distance span as it was foreseen, checked against the move.
    pub foreseen: Option<Foreseen>,
    /// Keep running after the transition (continuous LaneOffsetAction).
    pub continuous: bool,
    /// oscsim's target offset in the lane's width (`lane_offset::start_in_width`), re-read at
    /// each step.
    pub in_width: Option<InWidth>,
}

/// A target offset k·W + c from the lane's centre in the lane's width W where the actor is at
/// each step's end ([`scenario::OffsetInWidth`]), and the target of the step before (its
/// change is the target's lateral speed, for the heading).
#[derive(Debug, Clone, Copy)]
pub(crate) struct InWidth {
    pub per_width: f64,
    pub offset: f64,
    pub last: f64,
}

/// A step of a distance span as foreseen before the default controller moved the entity: the
/// odometer reading and lateral share at its start and the part along the road assumed.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Foreseen {
    odometer: f64,
    share: f64,
    along: f64,
}

impl LateralState {
    /// True when a fixed-time transition that does not hold its target reaches its end by `t`.
    pub(crate) fn completes_by(&self, t: f64) -> bool {
        !self.continuous
            && matches!(self.span, Span::Time(d) if t - self.start_time >= d - crate::tolerance::TIME)
    }
}

/// Starts a lane change: sets the track's target lane and offset and a blend from the current.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &LateralAction,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let LateralAction::LaneChange {
        target_lane_offset,
        dynamics,
        target,
    } = action
    else {
        return Err(Error::unsupported("this LateralAction", pos));
    };
    let (lane, offset) = match target {
        LaneChangeTarget::Beside {
            entity_ref,
            t,
            what,
            roads,
            ..
        } => beside(world, actor, (entity_ref, *t, what, roads), now, pos)?,
        _ => (
            target_lane(world, target, pos)?,
            target_lane_offset.unwrap_or(0.0),
        ),
    };
    begin(world, actor, lane, offset, dynamics, now, false, pos)
}

/// Starts oscsim's lane change that arrives at a place along the road
/// (`LateralAction::LaneChangeAt`): over the distance along the actor's lane from its s now to
/// `at.s`, measured now; a place not ahead of it along its direction of travel fails the
/// action (an error record and a failed run).
pub(crate) fn start_at(
    world: &mut World,
    actor: EntityId,
    at: &LaneChangeAt,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let fail = check_failed(&at.what, now);
    let e = world.entity(actor);
    let Some(track) = &e.track else {
        return Err(fail(
            format!("'{}' on a lane", e.name),
            "it off every road".into(),
        ));
    };
    let chain = RoadChain::new(&world.network, &at.roads);
    let length = if chain.is_chain() {
        // On a plan over several roads: the plan's s, measured along the direction of travel,
        // and the lane's length across the roads' joints (the lane ids are the same on each).
        let Some(here) = chain.s_of(&track.road_id, track.s) else {
            return Err(fail(
                format!("'{}' on {}", e.name, chain.describe()),
                format!("it on road {}", track.road_id),
            ));
        };
        let length = chain
            .lane_length(&track.road_id, track.lane_id, (here, at.s))
            .filter(|_| at.s > here);
        let Some(length) = length else {
            return Err(fail(
                format!(
                    "s = {:.3} m of {} (the plan's s) ahead of '{}' along its lane",
                    at.s,
                    chain.describe(),
                    e.name
                ),
                format!(
                    "it at s = {here:.3} m (s = {:.3} m of road {})",
                    track.s, track.road_id
                ),
            ));
        };
        length
    } else {
        let forward = track.direction == Direction::Forward;
        let ahead = if forward {
            at.s > track.s
        } else {
            at.s < track.s
        };
        let length = lane_arc_length(&world.network, &track.road_id, track.lane_id, track.s, at.s)
            .filter(|_| ahead);
        let Some(length) = length else {
            return Err(fail(
                format!(
                    "s = {:.3} m of road {} ahead of '{}' along its lane",
                    at.s, track.road_id, e.name
                ),
                format!("it at s = {:.3} m", track.s),
            ));
        };
        length
    };
    let dynamics = TransitionDynamics {
        dynamics_shape: at.shape,
        dynamics_dimension: DynamicsDimension::Distance,
        value: length,
        following_mode: None,
    };
    let lane = target_lane(world, &at.target, pos)?;
    let offset = at.target_lane_offset.unwrap_or(0.0);
    begin(world, actor, lane, offset, &dynamics, now, false, pos)
}

/// The lane and offset of oscsim's target beside an entity (`LaneChangeTarget::Beside`): the
/// lane of `actor`'s road on its side (its direction of travel) holding t = the reference's
/// t now + `dt`, and the offset from its centre there. The reference off the actor's road (or
/// off a road of the plan's `roads` whose t compares with the actor's, `RoadChain::
/// lateral_compares`), or no driving lane at that t, fails the action (`what` names the
/// constraint).
fn beside(
    world: &World,
    actor: EntityId,
    (name, dt, what, roads): (&str, f64, &str, &PlanRoads),
    now: f64,
    pos: &SourcePos,
) -> Result<(i32, f64), Error> {
    let fail = check_failed(what, now);
    let x = world.entity(entity_ref(world, name, pos)?);
    let e = world.entity(actor);
    let (Some(tx), Some(ta)) = (&x.track, &e.track) else {
        return Err(fail(
            format!("'{}' and '{name}' on a lane", e.name),
            "one of them off every road".into(),
        ));
    };
    same_measure(world, roads, (ta, tx), (&e.name, name))
        .map_err(|(expected, found)| fail(expected, found))?;
    let t = tx.t + dt;
    let road = world
        .network
        .road(&ta.road_id)
        .ok_or_else(|| Error::at("the actor's road", format!("road '{}'", ta.road_id), pos))?;
    // A lane of the actor's side of the road (its direction of travel), holding t.
    side_lane(road, ta, t).ok_or_else(|| {
        fail(
            format!(
                "a driving lane of road {} at t = {t:.3} m, s = {:.3} m ({dt:.3} m from '{name}')",
                ta.road_id, ta.s
            ),
            "none".into(),
        )
    })
}

/// Whether the reference's t (`tx`, entity `name`) compares with the actor's (`ta`): on the
/// same road, or on two of the plan's `roads` whose reference lines join continuously
/// (`RoadChain::lateral_compares`); else (expected, found) for the error record.
pub(super) fn same_measure(
    world: &World,
    roads: &PlanRoads,
    (ta, tx): (&LaneTrack, &LaneTrack),
    (actor, name): (&str, &str),
) -> Result<(), (String, String)> {
    let chain = RoadChain::new(&world.network, roads);
    chain
        .lateral_compares(&ta.road_id, &tx.road_id)
        .map_err(|why| match chain.is_chain() {
            true => (
                why,
                format!(
                    "'{name}' on road {} and '{actor}' on road {}",
                    tx.road_id, ta.road_id
                ),
            ),
            false => (
                format!("'{name}' on road {} beside '{actor}'", ta.road_id),
                format!("it on road {}", tx.road_id),
            ),
        })
}

/// The lane of `track`'s side of `road` holding `t` at its s, and the offset there.
pub(super) fn side_lane(road: &Road, track: &LaneTrack, t: f64) -> Option<(i32, f64)> {
    lane_at(road, track.s, t).filter(|(lane, offset)| {
        lane.signum() == track.lane_id.signum()
            && road
                .lane_span(*lane, track.s)
                .is_ok_and(|sp| offset.abs() <= sp.width() / 2.0 + LENGTH_EPSILON)
    })
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
) -> Result<Part, Error> {
    let net = &world.network;
    let track = lane_track(world.entity(actor), pos)?;
    let road = net
        .road(&track.road_id)
        .ok_or_else(|| Error::at("the actor's road", format!("road '{}'", track.road_id), pos))?;
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
                    Error::at(
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
        Error::at(
            "a target lane that exists at the actor's position",
            e.to_string(),
            pos,
        )
    })?;
    let (from_lane, from_offset) =
        lane_at(road, track.s, track.t).unwrap_or((track.lane_id, track.offset));
    let delta = span_to.center() + offset - track.t;
    let span = span(dynamics, delta);
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
        delta,
        along: 0.0,
        foreseen: None,
        continuous,
        in_width: None,
    }))
}

/// Sets the blend weight for the step's end, `now + dt`, and its rate per metre along the
/// lane: (Δt·dw/ds) is the slope tan θ of the path against the lane there, from which the
/// default controller takes the heading (θ off the lane) and the step's part along the road
/// (cos θ of it; the speed is the speed along the path).
///
/// Under a `time` span the lateral speed is Δ·f′(p)/T, so sin θ = Δ·f′(p)/(T·v): the heading
/// of a car that changes lane at 5 m/s by 3.5 m in 2 s (sinusoidal, peak lateral speed
/// 3.5·π/4 = 2.75 m/s) peaks at asin(0.550) = 0.582 rad, not atan(0.550) = 0.503 rad. esmini
/// takes the same angle, atan2(lateral step, longitudinal step), but from the lateral speed at
/// the step's start, so its heading lags the motion by one step.
///
/// A `time` span runs on the clock. A `distance` span runs on the distance travelled along the
/// road (§7.7.2 DynamicsDimension `distance`; for a lateral transition the lateral position is
/// then a function of the longitudinal one): the step's part along the road is found with the
/// default controller's rule (see [`along_road`]) from the share at the step's start, which
/// the controller left in `lateral_slope`, and the share the step ends with.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut LateralState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    // A target in the lane's width moves with the width where the actor ends the step.
    let target_rate = match (s.in_width.as_mut(), s.span) {
        (Some(w), Span::Time(t)) => {
            let (_, df) = shape_value(s.shape, progress(s.span, now + dt - s.start_time, 0.0));
            let share = s.delta * df / t;
            aim_in_width(world, actor, w, (dt, share)).map_or(0.0, |(delta, rate)| {
                s.delta = delta;
                rate
            })
        }
        _ => 0.0,
    };
    let e = world.entity_mut(actor);
    let speed = step_speed(e);
    if let Span::Distance(d) = s.span {
        if let Some(f) = s.foreseen.take() {
            // The path the controller drove (odometer), along the road at the mean share of
            // the step (controller::default), replaces what was assumed: a SpeedAction
            // stepped after this action changes the speed the controller moves with.
            let mean = (0.5 * (f.share + e.lateral_slope)).clamp(-1.0, 1.0);
            s.along += (e.odometer - f.odometer).abs() * (1.0 - mean * mean).sqrt() - f.along;
        }
        let along = along_road(s, d, speed * dt, e.lateral_slope);
        s.foreseen = Some(Foreseen {
            odometer: e.odometer,
            share: e.lateral_slope,
            along,
        });
        s.along += along;
    }
    let p = progress(s.span, now + dt - s.start_time, s.along);
    let (f, df) = shape_value(s.shape, p);
    // The path's slope tan θ against the lane at the step's end.
    let tan = match s.span {
        Span::Instant => 0.0,
        Span::Time(t) => {
            // sin θ = lateral speed Δ·f′/T over the speed (at most 1: sideways, where tan θ
            // stays finite in f64); no heading change at a standstill.
            let sin = if speed * dt > LENGTH_EPSILON {
                match s.in_width {
                    // The target's own rate adds to the blend's (its weight f).
                    Some(_) => (s.delta * df / t + f * target_rate) / speed,
                    None => s.delta * df / (t * speed),
                }
                .clamp(-1.0, 1.0)
            } else {
                0.0
            };
            sin.asin().tan()
        }
        Span::Distance(d) => s.delta * df / d,
    };
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
        b.weight_per_m = if s.delta.abs() > LENGTH_EPSILON {
            tan / s.delta
        } else {
            0.0
        };
    }
    ActionStatus::Running
}

/// Writes the target offset of `w` on `actor`'s lane track for the step's end: k·W + c, W the
/// width of its lane at the s it ends the step at, foreseen at the speed it moves with and the
/// mean of the sideways shares at the step's start and end (`lateral`, the blend's lateral
/// speed at the end with the target of the step before; the target's own rate and the lane's
/// centre's slope against the road, 2.5·10⁻⁵ of the step on `widening.xodr`, neglected).
/// Returns the change in t from the blend's start place to the target (the Δ of the slope) and
/// the target's rate over the step; `None` off the road.
fn aim_in_width(
    world: &mut World,
    actor: EntityId,
    w: &mut InWidth,
    (dt, lateral): (f64, f64),
) -> Option<(f64, f64)> {
    let net = world.network.clone();
    let e = world.entity_mut(actor);
    // Along the road: the step's length at the mean of its sideways shares at the start and
    // at the end (the blend's lateral speed then), as the default controller moves it.
    let speed = step_speed(e);
    let end = if speed * dt > LENGTH_EPSILON {
        (lateral / speed).clamp(-1.0, 1.0)
    } else {
        0.0
    };
    let mean = (0.5 * (e.lateral_slope + end)).clamp(-1.0, 1.0);
    let along = speed * dt * (1.0 - mean * mean).sqrt();
    let track = e.track.as_mut()?;
    let ahead = match track.direction {
        Direction::Forward => along,
        _ => -along,
    };
    let (road, s_end) = (net.road_at(track.road), track.s + ahead);
    let to = road.lane_span(track.lane_id, s_end).ok()?;
    let target = w.per_width * to.width() + w.offset;
    track.offset = target;
    let rate = if dt > 0.0 {
        (target - w.last) / dt
    } else {
        0.0
    };
    w.last = target;
    // Δt from the blend's start place (its lane's centre and offset) to the target, at s_end.
    let delta = match &track.blend {
        Some(b) => {
            let from = road.lane_span(b.from_lane, s_end).ok()?.center() + b.from_offset;
            to.center() + target - from
        }
        None => 0.0,
    };
    Some((delta, rate))
}

/// `e`'s lane track, which a lateral action moves; off the road an error at `pos`.
pub(super) fn lane_track<'a>(e: &'a Entity, pos: &SourcePos) -> Result<&'a LaneTrack, Error> {
    e.track.as_ref().ok_or_else(|| {
        Error::at(
            "an actor on a lane",
            format!("'{}' off the road", e.name),
            pos,
        )
    })
}

/// The failure of the constraint `what` at `time`: an error record and a failed run, from the
/// state expected and the state found.
pub(super) fn check_failed(what: &str, time: f64) -> impl Fn(String, String) -> Error + '_ {
    move |expected, found| {
        Error::new(ErrorKind::CheckFailed {
            what: what.to_string(),
            expected,
            found,
            time,
        })
    }
}

/// The speed the default controller moves `e` with in this step (controller::default).
pub(super) fn step_speed(e: &Entity) -> f64 {
    if e.lateral_first {
        e.start_speed
    } else {
        e.speed
    }
    .abs()
}

/// The part along the road of a step of `length` m of a distance span `d`, from the lateral
/// share sin θ₀ = `x0` the step starts with.
///
/// The default controller moves a step of length ℓ whose lateral share goes from x₀ to x₁ by
/// ℓ·√(1 − x̄²) along the road, x̄ = (x₀ + x₁)/2 (controller::default). At the step's end the
/// path's slope against the road is tan θ = Δ·f′(p)/d, p = (along + ℓ·√(1 − x̄²))/d, and
/// x₁ = sin θ, so x₁ depends on the step it ends: a fixed point, contracting by about
/// ℓ·x̄·Δ·|f″|/(2d²) (2·10⁻⁴ for 3.5 m over 50 m in 0.5 m steps), so five rounds leave it at
/// rounding level.
fn along_road(s: &LateralState, d: f64, length: f64, x0: f64) -> f64 {
    let along = |x1: f64| {
        let mean = (0.5 * (x0 + x1)).clamp(-1.0, 1.0);
        length * (1.0 - mean * mean).sqrt()
    };
    let tan_at = |a: f64| {
        let (_, df) = shape_value(s.shape, ((s.along + a) / d).min(1.0));
        s.delta * df / d
    };
    let mut a = along(x0);
    for _ in 0..5 {
        a = along(tan_at(a).atan().sin());
    }
    a
}
