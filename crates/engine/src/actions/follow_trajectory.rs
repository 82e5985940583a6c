//! FollowTrajectoryAction (OpenSCENARIO 1.3 §6.9 "Trajectories", XSD `FollowTrajectoryAction`,
//! `TimeReference`, `TrajectoryFollowingMode`): move the actor along a trajectory (built by the
//! `trajectory` module). With a Timing time reference the trajectory's times drive the motion
//! and the action holds both domains; without one it holds the lateral domain only and the
//! actor keeps its own speed along the trajectory (semantics-pitfalls #7).
//!
//! The actor starts at `initialDistanceOffset` along the trajectory (default 0, its start; with
//! Timing and no offset, where the trajectory's clock says). The XSD bounds the offset by the
//! trajectory's arc length; an offset past the end by no more than rounding (1 cm, or 10⁻⁴ of
//! the length) means the end, since authors write lengths rounded (issue 16 class 8); a
//! larger or negative one stops the action with an error at its place. its position is the trajectory
//! point's, its heading the tangent's, or the vertex headings' of a six-dimensional Polyline
//! (§6.9). The action ends at the end of an open trajectory, or at the last time of a timed
//! one; the actor then drives on under the default controller from where it stands, at the
//! speed it arrived with.
//!
//! TrajectoryFollowingMode `position` follows the path and its times exactly. `follow`
//! observes the actor's dynamic constraints: on a timed trajectory it tracks the timed arc
//! length of the speed-continuous reading of the times within its Performance (see
//! `trajectory::FollowLimits`), waits at the end until the last time and leaves with that
//! reading's final speed; a vehicle whose axles
//! bound its curvature steers onto and along an open trajectory by pure pursuit from its own
//! pose (see `trajectory::Pursuit`; forwards only, reverse gear is followed exactly); the
//! action then ends when the actor reaches the trajectory's end, early or late. Entities
//! without such constraints follow as in `position`.
//!
//! oscsim's FollowTrajectoryAction timed at another entity's speed (`scenario::
//! TrajectoryAtSpeed`, no XML form; [`at_speed`]) runs as this action once its times are each
//! shifted by the point's distance over that entity's speed when it starts.
//!
//! A negative speed without a Timing time reference drives the trajectory in reverse gear: the
//! actor still travels from the trajectory's start towards its end, at |speed|, facing against
//! the tangent (heading = tangent + π). The standard does not say what a negative speed means
//! on a trajectory; this is esmini's reading, which the reversing manoeuvres of the corpus
//! (parking_demo.xosc: a ClothoidSpline starting at the car's heading + π) are written for.

use opendrive::normalize_angle;
use scenario::{FollowingMode, SourcePos, Timing};

use super::Part;
use crate::error::{Error, ErrorKind};
use crate::position::PositionErrorKind;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::trajectory::{
    build_for_actor, FollowLimits, Pursuit, Trajectory, TrajectoryClock, TrajectoryError,
    TrajectoryErrorKind,
};
use crate::world::entity::EntityId;

/// A running FollowTrajectoryAction on one actor.
#[derive(Debug, Clone)]
pub(crate) struct TrajectoryState {
    trajectory: Box<Trajectory>,
    clock: Option<TrajectoryClock>,
    /// The actor's Performance limits in `follow` mode (`None`: followed exactly).
    limits: Option<FollowLimits>,
    /// The steering of a curvature-limited vehicle in `follow` mode on an open trajectory
    /// (`None`: on the trajectory) and its own pose [x, y, h] while it steers.
    pursuit: Option<Pursuit>,
    /// In `follow` mode on a timed trajectory, the speed-continuous reading of its times from
    /// the actor's speed at the start (`Trajectory::continuous_speeds`): the reference tracked.
    reference: Option<Vec<(f64, f64)>>,
    pose: [f64; 3],
    /// Arc length reached (steering: of the trajectory point nearest to the actor).
    s: f64,
    /// Speed along the trajectory in the last step (m/s) and the time it reached `s`.
    speed: f64,
    at: f64,
}

/// Tolerance (s, m) of reaching a trajectory's last time or its end: round-off of s and t
/// summed over a run's steps.
const END_EPSILON: f64 = crate::tolerance::TIME;

impl TrajectoryState {
    /// The clock when the motion is timed: a Timing time reference and a shape with times.
    /// With Timing but no times on the shape the actor keeps its own speed, as without one.
    fn timed(&self) -> Option<&TrajectoryClock> {
        self.clock.as_ref().filter(|_| self.trajectory.has_times())
    }

    /// The simulation time at which a timed trajectory's last time is reached.
    fn end_time(&self) -> Option<f64> {
        let clock = self.timed()?;
        let (_, last) = self.trajectory.time_range()?;
        Some(clock.simulation_time(last))
    }

    /// True when the motion up to `step_end` reaches the end of the trajectory (the action
    /// then ends in this step, as fixed-time transitions do): a timed trajectory at its last
    /// time (closed or not: the times say where the actor is, and they end there), an untimed
    /// open one at its last point. An untimed closed trajectory has no end.
    pub(crate) fn completes_by(&self, step_end: f64) -> bool {
        let dt = step_end - self.at;
        if let Some(pursuit) = self.pursuit {
            let v = self
                .timed_speed(self.speed, self.at, dt)
                .unwrap_or(self.speed);
            let (_, s) = pursuit.advance(&self.trajectory, self.pose, self.s, v.abs() * dt);
            return s >= self.trajectory.length() - END_EPSILON && !self.waits(step_end);
        }
        if let (Some(v), Some(_)) = (self.timed_speed(self.speed, self.at, dt), self.limits) {
            return self.s + v * dt >= self.trajectory.length() - END_EPSILON
                && !self.waits(step_end);
        }
        if let Some(end) = self.end_time() {
            return step_end >= end - END_EPSILON;
        }
        if self.trajectory.closed() {
            return false;
        }
        let next = self.s + self.speed.abs() * dt;
        next >= self.trajectory.length() - END_EPSILON
    }

    /// In `follow` mode on the continuous reference, an actor at the trajectory's end before
    /// its last time waits there until that time: the action lasts as long as the times say,
    /// and a reference still on its way cannot take the actor beyond the end
    /// (bicycle_fall_over: at rest on the last vertex from 3.5 s to 4 s).
    fn waits(&self, step_end: f64) -> bool {
        self.reference.is_some()
            && self
                .end_time()
                .is_some_and(|end| step_end < end - END_EPSILON)
    }

    /// At the end of a `follow` trajectory tracked on its continuous reference, the actor
    /// leaves with the reference's final speed, as far as its Performance lets it change speed
    /// in one step (bicycle_fall_over: the timed vertices end at rest, so the cyclist stops at
    /// its last vertex instead of rolling on at its last step's 0.25 m/s).
    fn arrive(&self, world: &mut World, actor: EntityId, dt: f64) {
        let (Some(speeds), Some(clock)) = (&self.reference, self.timed()) else {
            return;
        };
        let Some(&(_, last)) = speeds.last() else {
            return;
        };
        let e = world.entity_mut(actor);
        let wanted = last * clock.rate();
        e.speed = match self.limits {
            Some(l) => wanted.clamp(e.speed - l.deceleration * dt, e.speed + l.acceleration * dt),
            None => wanted,
        };
    }

    /// In `follow` mode on a timed trajectory, the speed for the step from `now` over `dt`
    /// from speed `v0`: towards the timed arc length within the Performance limits, or
    /// without usable limits the speed that reaches it. `None` in `position` mode or untimed.
    fn timed_speed(&self, v0: f64, now: f64, dt: f64) -> Option<f64> {
        if self.limits.is_none() && self.pursuit.is_none() {
            return None;
        }
        let clock = self.timed()?;
        let at = |t| {
            match &self.reference {
                Some(speeds) => self
                    .trajectory
                    .s_at_simulation_time_continuous(clock, speeds, t),
                None => self.trajectory.s_at_simulation_time(clock, t),
            }
            .unwrap_or(self.s)
        };
        Some(match self.limits {
            Some(l) => l.tracking_speed(v0, self.s, at(now), at(now + dt), dt),
            None if dt > 0.0 => ((at(now + dt) - self.s) / dt).max(0.0),
            None => v0,
        })
    }
}

impl TrajectoryState {
    /// Arc length (m) from the actor's place on the trajectory to the trajectory point
    /// nearest (x, y); 0 when that point is behind it. A SynchronizeAction measures its
    /// actor's remaining distance with it (synchronize.rs).
    pub(crate) fn remaining_to(&self, x: f64, y: f64) -> f64 {
        (self.trajectory.closest(x, y).point.s - self.s).max(0.0)
    }
}

/// What a FollowTrajectoryAction asks for (XSD `FollowTrajectoryAction`).
pub(crate) struct Request<'a> {
    /// The trajectory (TrajectoryRef, resolved).
    pub trajectory: &'a scenario::Trajectory,
    /// TimeReference: `None`, or Timing.
    pub timing: Option<&'a Timing>,
    /// TrajectoryFollowingMode/@followingMode.
    pub following_mode: FollowingMode,
    /// @initialDistanceOffset (m).
    pub initial_distance_offset: Option<f64>,
}

/// oscsim's FollowTrajectoryAction timed at another entity's speed
/// (`scenario::TrajectoryAtSpeed`, no XML form), as the trajectory it follows from `now`: each
/// point's time plus its distance over the entity's speed v now. The entity missing or
/// standing (no v to cover the distances at) fails the action: an error record and a failed
/// run, as oscsim's state check.
pub(crate) fn at_speed(
    world: &World,
    a: &scenario::TrajectoryAtSpeed,
    now: f64,
) -> Result<scenario::Trajectory, Error> {
    let fail = |found: String| {
        Error::new(ErrorKind::CheckFailed {
            what: a.what.clone(),
            expected: format!("'{}' moving (its speed times the headways)", a.entity_ref),
            found,
            time: now,
        })
    };
    let v = match world.id(&a.entity_ref) {
        Some(id) => world.entity(id).speed,
        None => return Err(fail("no such entity".into())),
    };
    if v <= crate::tolerance::SPEED {
        return Err(fail(format!("it at {v:.3} m/s")));
    }
    let mut trajectory = a.trajectory.clone();
    let mut distances = a.distances.iter();
    let mut shift = |time: &mut Option<f64>| {
        if let (Some(t), Some(d)) = (time.as_mut(), distances.next()) {
            *t += d / v;
        }
    };
    match &mut trajectory.shape {
        scenario::Shape::Polyline(vertices) => {
            vertices.iter_mut().for_each(|p| shift(&mut p.time));
        }
        scenario::Shape::Nurbs(n) => {
            n.control_points.iter_mut().for_each(|p| shift(&mut p.time));
        }
        _ => {}
    }
    Ok(trajectory)
}

/// Starts the action at simulation time `now`.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    request: Request<'_>,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let Request {
        trajectory,
        timing,
        following_mode,
        initial_distance_offset,
    } = request;
    let to_error = |e| Error::new(ErrorKind::Trajectory(e));
    // A ClothoidSpline whose first segment has no PositionStart starts at the actor (1.3 XSD
    // `ClothoidSplineSegment`: positionStart is optional).
    let actor_pose = world.entity(actor).pose;
    // The shape's error as the trajectory's, a point's as that position's.
    let trajectory = build_for_actor(trajectory, &*world, Some(&actor_pose), pos).map_err(|e| {
        match e.kind() {
            PositionErrorKind::Trajectory(shape) => to_error(shape.clone()),
            _ => Error::new(ErrorKind::Position(e)),
        }
    })?;
    let clock = timing
        .map(|t| TrajectoryClock::new(t, now, pos))
        .transpose()
        .map_err(to_error)?;
    // initialDistanceOffset (default 0: the trajectory's start), or with Timing the arc length
    // the trajectory's own clock gives for now.
    let length = trajectory.length();
    let initial_distance_offset = initial_distance_offset
        .map(|d| within_length(d, length))
        .transpose()
        .map_err(|found| {
            to_error(TrajectoryError::new(
                TrajectoryErrorKind::InitialDistanceOffset { found, length },
                pos,
            ))
        })?;
    let s = match (initial_distance_offset, clock.as_ref()) {
        (Some(d), _) => d,
        (None, Some(c)) => trajectory.s_at_simulation_time(c, now).unwrap_or(0.0),
        (None, None) => 0.0,
    };
    // "The time that would be taken to reach this point is deducted from all calculated
    // waypoint time values" (FollowTrajectoryAction/@initialDistanceOffset).
    let clock = match (clock, initial_distance_offset) {
        (Some(c), Some(_)) => {
            let skipped = trajectory.time_at(s).zip(trajectory.time_at(0.0));
            Some(c.skipping(skipped.map_or(0.0, |(at_s, at_0)| at_s - at_0)))
        }
        (c, _) => c,
    };
    let limits = match following_mode {
        FollowingMode::Follow => world
            .entity(actor)
            .performance
            .and_then(|p| FollowLimits::new(p.max_acceleration, p.max_deceleration, p.max_speed)),
        _ => None,
    };
    // An entity that no action has placed yet (an Init FollowTrajectoryAction without a
    // TeleportAction, bicycle_fall_over.xosc) has no position to steer from: the trajectory
    // gives its first one, at the start point, in every following mode.
    let unplaced = !world.entity(actor).placed;
    if unplaced {
        place(world, actor, &trajectory, s, false, false);
    }
    // A vehicle whose axles bound its curvature steers onto and along an open trajectory in
    // `follow` mode, driving forwards (reverse gear is followed exactly).
    let entity = world.entity(actor);
    let pursuit = match following_mode {
        FollowingMode::Follow if !trajectory.closed() && entity.speed >= 0.0 => {
            entity.max_curvature.and_then(Pursuit::new)
        }
        _ => None,
    };
    let pose = [entity.pose.x, entity.pose.y, entity.pose.h];
    // `follow` tracks a reference it can drive: the timed vertices reached on time with a
    // speed that changes linearly between them, from the actor's own (the linear reading's
    // speed jumps at every vertex). esmini reads timed polylines in `follow` mode the same
    // way (bicycle_fall_over: 10 m/s braking to rest over the vertex interval 2.5 .. 3.5 s).
    let reference = match (following_mode, clock.as_ref()) {
        (FollowingMode::Follow, Some(c)) if limits.is_some() || pursuit.is_some() => {
            trajectory.continuous_speeds(c, entity.speed)
        }
        _ => None,
    };
    let s = match pursuit {
        Some(p) => {
            trajectory
                .closest_near(pose[0], pose[1], s, p.look_ahead())
                .point
                .s
        }
        None => s,
    };
    let mut state = TrajectoryState {
        trajectory: Box::new(trajectory),
        clock,
        limits,
        pursuit,
        reference,
        pose,
        s,
        speed: entity.speed,
        at: now,
    };
    let reversing = state.clock.is_none() && state.speed < 0.0;
    if state.pursuit.is_none() {
        place(world, actor, &state.trajectory, s, false, reversing);
    }
    // Measured at once: the frame of the start shows the road position of the new pose.
    let pose = world.entity(actor).pose;
    world.entity_mut(actor).road_position = world.network.locate(pose.x, pose.y, Some(pose.h));
    Ok(match step(world, actor, &mut state, now, 0.0) {
        ActionStatus::Running => Part::Trajectory(state),
        done => Part::Done(done),
    })
}

/// How far an initialDistanceOffset may lie past the trajectory's end and still mean its end
/// (m): an author writes the length rounded (90 for a computed 89.99868 m, issue 16), so
/// 1 cm, or 10⁻⁴ of the length on long trajectories.
pub(crate) const OFFSET_ROUNDING_TOLERANCE: f64 = 0.01;

/// `offset` as an arc length on a trajectory of `length` m: within [0, length] as given, past
/// the end by no more than rounding ([`OFFSET_ROUNDING_TOLERANCE`], or 10⁻⁴ × length) the
/// end; else `Err(offset)`. The XSD gives the range [0..arcLength(trajectory)]
/// (FollowTrajectoryAction/@initialDistanceOffset, OpenSCENARIO 1.3).
fn within_length(offset: f64, length: f64) -> Result<f64, f64> {
    let rounding = OFFSET_ROUNDING_TOLERANCE.max(1e-4 * length);
    if (0.0..=length).contains(&offset) {
        Ok(offset)
    } else if offset > length && offset <= length + rounding {
        Ok(length)
    } else {
        Err(offset)
    }
}

/// Puts `actor` at arc length `s` of the trajectory, facing along the tangent, or as the
/// trajectory's vertices say where it states orientations (§6.9), and turned by π when
/// `reversing`; `hold` marks the pose as set for the step, so the controller takes
/// measurements without moving the actor again.
fn place(
    world: &mut World,
    actor: EntityId,
    trajectory: &Trajectory,
    s: f64,
    hold: bool,
    reversing: bool,
) {
    let p = trajectory.eval(s);
    let heading = trajectory.orientation_at(s).unwrap_or(p.heading);
    let e = world.entity_mut(actor);
    e.pose.x = p.x;
    e.pose.y = p.y;
    e.pose.z = p.z;
    e.pose.h = if reversing {
        normalize_angle(heading + std::f64::consts::PI)
    } else {
        heading
    };
    e.track = None;
    e.held = hold;
    e.placed = true;
}

/// Advances the actor to the step's end, `now + dt`.
///
/// Timed, the actor is where the clock says; its speed is the distance of the step over dt
/// (at the action's start, dt = 0, the speed of the interval ahead), and once the last time
/// has passed it keeps the speed it arrived with: the standard does not stop an entity at the
/// end of a timed trajectory, and esmini 3.6.0 drives on at that speed too
/// (lane-change_clothoid_spline_based_trajectory, trajectory-test). Untimed, the actor
/// travels its own speed along the trajectory.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    st: &mut TrajectoryState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    if let Some(pursuit) = st.pursuit {
        return steer(world, actor, st, pursuit, now, dt);
    }
    let length = st.trajectory.length();
    let t = now + dt;
    let reversing = st.timed().is_none() && world.entity(actor).speed < 0.0;
    // The arc length reached by t, the distance travelled on the trajectory, the travel past
    // its end within this step, and whether the trajectory is over by t.
    let (s, moved, beyond, over) = match (st.timed().copied(), st.end_time(), st.limits) {
        (Some(_), Some(_), Some(_)) => {
            // `follow`: towards the timed arc length within the Performance limits; over at
            // the trajectory's end, early or late.
            let v0 = world.entity(actor).speed;
            let mut v = st.timed_speed(v0, now, dt).unwrap_or(v0);
            let s = st.s + v * dt;
            let over = s >= length - END_EPSILON && !st.waits(t);
            if !over && s > length && dt > 0.0 {
                // Waiting at the end: the step's motion stops there.
                v = (length - st.s) / dt;
            }
            world.entity_mut(actor).speed = v;
            let s = st.s + v * dt;
            let beyond = (s - length).max(0.0);
            (s.min(length), v * dt - beyond, beyond, over)
        }
        (Some(clock), Some(end), None) => {
            let s = st
                .trajectory
                .s_at_simulation_time(&clock, t)
                .unwrap_or(st.s);
            let arrival = st.trajectory.arrival_speed(&clock).unwrap_or(0.0);
            let speed = if dt <= 0.0 {
                st.trajectory
                    .speed_at_simulation_time(&clock, t)
                    .unwrap_or(0.0)
            } else if t <= end + END_EPSILON {
                (s - st.s) / dt
            } else {
                arrival
            };
            world.entity_mut(actor).speed = speed;
            let beyond = (t - end).max(0.0) * arrival;
            (s, (s - st.s).abs(), beyond, t >= end - END_EPSILON)
        }
        _ => {
            let travel = world.entity(actor).speed.abs() * dt;
            let s = st.s + travel;
            if st.trajectory.closed() {
                (s.rem_euclid(length), travel, 0.0, false)
            } else {
                let beyond = (s - length).max(0.0);
                (
                    s.min(length),
                    travel - beyond,
                    beyond,
                    s >= length - END_EPSILON,
                )
            }
        }
    };
    let s = s.clamp(0.0, length);
    st.s = s;
    st.speed = world.entity(actor).speed;
    st.at = t;
    place(world, actor, &st.trajectory, s, true, reversing);
    world.entity_mut(actor).odometer += moved;
    if over && dt > 0.0 {
        // The rest of the step's travel goes on straight along the trajectory's end tangent;
        // then the default controller takes over from there (backwards when reversing).
        let along = if reversing { -beyond } else { beyond };
        let e = world.entity_mut(actor);
        e.pose.x += along * e.pose.h.cos();
        e.pose.y += along * e.pose.h.sin();
        e.odometer += beyond;
        st.arrive(world, actor, dt);
        world.release_to_road(actor, true);
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}

/// One step of a steering vehicle in `follow` mode (see `trajectory::Pursuit`): its own pose
/// along the pursuit arc, at the timed speed (see `TrajectoryState::timed_speed`) or its own;
/// over when the trajectory point nearest to it is the end.
fn steer(
    world: &mut World,
    actor: EntityId,
    st: &mut TrajectoryState,
    pursuit: Pursuit,
    now: f64,
    dt: f64,
) -> ActionStatus {
    let v0 = world.entity(actor).speed;
    let waiting = st.reference.is_some() && st.s >= st.trajectory.length() - END_EPSILON;
    let v = match st.timed_speed(v0, now, dt) {
        // At the end before the last time: it waits there (`TrajectoryState::waits`).
        Some(_) if waiting => 0.0,
        Some(v) => v,
        None => v0,
    };
    if st.timed().is_some() {
        world.entity_mut(actor).speed = v;
    }
    let distance = v.abs() * dt;
    let (pose, s) = pursuit.advance(&st.trajectory, st.pose, st.s, distance);
    st.pose = pose;
    st.s = s;
    st.speed = v;
    st.at = now + dt;
    let z = st.trajectory.eval(s).z;
    let e = world.entity_mut(actor);
    e.pose.x = pose[0];
    e.pose.y = pose[1];
    e.pose.z = z;
    e.pose.h = pose[2];
    e.track = None;
    e.held = true;
    e.placed = true;
    e.odometer += distance;
    if dt > 0.0 && s >= st.trajectory.length() - END_EPSILON && !st.waits(now + dt) {
        st.arrive(world, actor, dt);
        world.release_to_road(actor, true);
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}
