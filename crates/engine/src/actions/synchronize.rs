//! SynchronizeAction (OpenSCENARIO 1.3 §7.7.2 private actions, "SynchronizeAction", XSD
//! `SynchronizeAction`, `FinalSpeed`, `SteadyState`): the actor reaches its target position at
//! the moment the master entity reaches its own, optionally with a final speed (absolute, or
//! relative to the master's speed) that it holds over a steady-state stretch (a distance, or a
//! time at the final speed) before the target.
//!
//! Each step re-plans from the current state (a receding horizon):
//! - the master's time to arrival is T = (d_m − tol_m) / v_m, its remaining distance over its
//!   speed; a master at rest gives no arrival time and the actor keeps its speed;
//! - without a final speed the actor takes the constant acceleration that covers its remaining
//!   distance s in T, a = 2·(s − v₀·T) / T²;
//! - with a final speed v₁ it follows the two-phase profile of constant acceleration ±a that
//!   covers s in T and ends at v₁ (first towards a peak or trough speed v_x, then towards v₁,
//!   see [`profile_speed`]); where that trough would need a negative speed, the actor brakes
//!   to a stop, waits, and starts in time to arrive;
//! - with a steady state the profile plans to reach v₁ at the steady-state distance d_ss (or
//!   after T − t_ss, t_ss = d_ss / v₁) and then holds v₁.
//!
//! The actor's Performance bounds every step (maxAcceleration, maxDeceleration, maxSpeed);
//! speeds stay ≥ 0 (the action never reverses). Remaining distances are measured along the
//! path the entity travels: for an actor that follows a trajectory (a FollowTrajectoryAction
//! without a time reference holds the lateral domain and leaves the speed to this action:
//! a pedestrian crossing the road, issue 16 class 5), the arc length along the trajectory to
//! the point nearest the target; otherwise along the roads: |Δs| on one road, the shortest
//! chain of linked roads (`domain::road_path`) between two; only off road, or with no linked
//! path, in a straight line.
//!
//! The action ends when the actor is within `targetTolerance` of its target, the master within
//! `targetToleranceMaster` of its own, either of them has passed its target (its remaining
//! distance grows), or the master arrives within this step; the actor then takes the final
//! speed. This is the end rule of esmini's implementation, which the corpus references were
//! recorded with; the standard only says the action ends when the synchronisation is reached.
//! Target positions are resolved once, at the start.

use opendrive::Pose;
use scenario::{FinalSpeed, SourcePos, SpeedTargetValueType, SteadyState, SynchronizeAction};

use super::Part;
use crate::domain::shortest_road_path;
use crate::error::{Error, ErrorKind};
use crate::position::resolve;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;

/// Distances (m), speeds (m/s) and times (s) below this count as zero.
const SMALL: f64 = crate::tolerance::LENGTH;

/// A resolved target: where it is and, when on a road, the road and s.
#[derive(Debug, Clone)]
struct Target {
    pose: Pose,
    road: Option<(String, f64)>,
}

/// The final speed rule (XSD `FinalSpeed`).
#[derive(Debug, Clone, Copy)]
enum Final {
    Absolute(f64),
    Delta(f64),
    Factor(f64),
}

/// The steady state before the target (XSD group `SteadyState`).
#[derive(Debug, Clone, Copy)]
enum Steady {
    /// TargetDistanceSteadyState, m.
    Distance(f64),
    /// TargetTimeSteadyState, s.
    Time(f64),
}

/// A running SynchronizeAction on one actor.
#[derive(Debug, Clone)]
pub(crate) struct SyncState {
    master: EntityId,
    master_target: Target,
    target: Target,
    tolerance_master: f64,
    tolerance: f64,
    final_speed: Option<Final>,
    steady_state: Option<Steady>,
    /// The steady state has been entered: the actor holds the final speed.
    steady: bool,
    /// The profile's peak (or trough) has been passed: the last phase, a line, runs.
    last_phase: bool,
    /// Remaining distances of the last step (m), to see a target passed.
    last_distance: f64,
    last_master_distance: f64,
    /// The actor's remaining distance along the trajectory it follows, when it follows one
    /// (set before each step by the action table, `set_along_path`).
    along_path: Option<f64>,
}

/// Resolves `position` of the action at `pos` to a [`Target`].
fn target(world: &World, position: &scenario::Position) -> Result<Target, Error> {
    let resolved = resolve(position, world).map_err(|e| Error::new(ErrorKind::Position(e)))?;
    Ok(Target {
        pose: resolved.pose,
        road: resolved.road_position.map(|rp| (rp.road_id, rp.s)),
    })
}

/// Remaining distance (m) of entity `id` to `target`: |Δs| on a shared road, the shortest
/// path along the roads' reference lines between two roads, else (off road, or no linked
/// path) the straight line.
fn remaining(world: &World, id: EntityId, target: &Target) -> f64 {
    let e = world.entity(id);
    if let (Some((road, s)), Some(rp)) = (&target.road, &e.road_position) {
        if *road == rp.road_id {
            return (s - rp.s).abs();
        }
        if let Some(path) = shortest_road_path(&world.network, &rp.road_id, rp.s, road, *s) {
            return path.length;
        }
    }
    (target.pose.x - e.pose.x).hypot(target.pose.y - e.pose.y)
}

/// Starts the action on `actor`.
pub(crate) fn start(
    world: &mut World,
    action: &SynchronizeAction,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let master = entity_ref(world, &action.master_entity_ref, pos)?;
    let (final_speed, steady_state) = match &action.final_speed {
        None => (None, None),
        Some(FinalSpeed::Absolute {
            value,
            steady_state,
        }) => (Some(Final::Absolute(*value)), *steady_state),
        Some(FinalSpeed::RelativeToMaster {
            value,
            speed_target_value_type,
            steady_state,
        }) => {
            let rule = match speed_target_value_type {
                SpeedTargetValueType::Delta => Final::Delta(*value),
                _ => Final::Factor(*value),
            };
            (Some(rule), *steady_state)
        }
        Some(_) => return Err(Error::unsupported("this FinalSpeed", pos)),
    };
    let steady_state = match steady_state {
        None => None,
        Some(SteadyState::Distance(d)) => Some(Steady::Distance(d)),
        Some(SteadyState::Time(t)) => Some(Steady::Time(t)),
        Some(_) => return Err(Error::unsupported("this SteadyState", pos)),
    };
    let state = SyncState {
        master,
        master_target: target(world, &action.target_position_master)?,
        target: target(world, &action.target_position)?,
        tolerance_master: action.target_tolerance_master.unwrap_or(0.0).max(0.0),
        tolerance: action.target_tolerance.unwrap_or(0.0).max(0.0),
        final_speed,
        steady_state,
        steady: false,
        last_phase: false,
        last_distance: f64::INFINITY,
        last_master_distance: f64::INFINITY,
        along_path: None,
    };
    Ok(Part::Synchronize(state))
}

impl SyncState {
    /// Where the actor's target is, in world x and y.
    pub(crate) fn target_point(&self) -> (f64, f64) {
        (self.target.pose.x, self.target.pose.y)
    }

    /// The actor's remaining distance along the trajectory it follows now (`None`: it
    /// follows none; its lane or a straight line counts then).
    pub(crate) fn set_along_path(&mut self, remaining: Option<f64>) {
        self.along_path = remaining;
    }

    /// The final speed now (m/s), if the action has one.
    fn final_speed(&self, world: &World) -> Option<f64> {
        let v_master = world.entity(self.master).speed;
        self.final_speed.map(|rule| match rule {
            Final::Absolute(v) => v,
            Final::Delta(d) => v_master + d,
            Final::Factor(f) => v_master * f,
        })
    }
}

/// Sets the actor's speed for the step from `now` to `now + dt`.
pub(crate) fn step(world: &mut World, actor: EntityId, s: &mut SyncState, dt: f64) -> ActionStatus {
    // A master that left the scenario (DeleteEntityAction) has no arrival to synchronise
    // with: the action stops and the actor keeps its speed (refused at the start, `entity_ref`).
    if !world.entity(s.master).placed {
        return ActionStatus::Stopped;
    }
    let distance = s
        .along_path
        .unwrap_or_else(|| remaining(world, actor, &s.target));
    let master_distance = remaining(world, s.master, &s.master_target);
    let passed =
        distance > s.last_distance + SMALL || master_distance > s.last_master_distance + SMALL;
    s.last_distance = distance;
    s.last_master_distance = master_distance;
    let v_final = s.final_speed(world);
    let v_master = world.entity(s.master).speed;
    let mut dist = (distance - s.tolerance).max(SMALL);
    let mut time = if v_master > SMALL {
        (master_distance - s.tolerance_master).max(SMALL) / v_master
    } else {
        f64::INFINITY
    };
    let done = distance <= s.tolerance + SMALL
        || master_distance <= s.tolerance_master + SMALL
        || passed
        || time < dt;
    let e = world.entity(actor);
    let v0 = e.speed;
    let wanted = if done {
        v_final.unwrap_or(v0)
    } else if let Some(v1) = v_final {
        if let (Some(ss), false) = (s.steady_state, s.steady) {
            let d_ss = match ss {
                Steady::Distance(d) => d,
                Steady::Time(t) => t * v1,
            };
            let t_ss = if v1 > SMALL { d_ss / v1 } else { 0.0 };
            if dist - d_ss <= SMALL || time - t_ss <= SMALL {
                s.steady = true;
            } else {
                dist -= d_ss;
                time -= t_ss;
            }
        }
        if s.steady {
            v1
        } else {
            let (v, last_phase) = profile_speed(dist, time, v0, v1, dt, s.last_phase);
            s.last_phase = last_phase;
            v
        }
    } else if time.is_finite() {
        // Constant acceleration covering `dist` in `time`: dist = v0·T + a·T²/2.
        v0 + 2.0 * (dist - v0 * time) / (time * time) * dt
    } else {
        v0
    };
    let e = world.entity_mut(actor);
    let bounded = match e.performance {
        None => wanted,
        Some(perf) => {
            let decel = perf.max_deceleration.abs();
            // Braking envelope: never faster than the speed from which maxDeceleration still
            // brings the actor to the final speed at its target, v² = v₁² + 2·b·s.
            let envelope = match (done, v_final) {
                (false, Some(v1)) if decel > SMALL => (v1 * v1 + 2.0 * decel * dist).sqrt(),
                _ => f64::INFINITY,
            };
            wanted
                .min(envelope.max(v0 - decel * dt))
                .clamp(v0 - decel * dt, v0 + perf.max_acceleration.abs() * dt)
        }
    };
    e.speed = bounded.max(0.0).min(e.max_speed());
    if done {
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}

/// The speed after `dt` (m/s) on the profile that covers `dist` (m) in `time` (s), starting at
/// `v0` and ending at `v1` (m/s), with constant acceleration a up to a peak (or trough) speed
/// v_x at time x, then −a down (or up) to v1.
///
/// With y = time − x the two phases give v_x − v0 = a·x, v_x − v1 = a·y, so
/// a = (2·v_x − v0 − v1) / time, and the distance dist = (2·v_x² − v0² − v1²) / (2·a). Putting
/// a in: 2·time·v_x² − 4·dist·v_x + 2·dist·(v0 + v1) − time·(v0² + v1²) = 0, whose roots are
/// v_x = dist/time ± √(((dist − v0·time)² + (dist − v1·time)²) / 2) / time. The peak (+) is
/// taken when the average speed needed exceeds (v0 + v1)/2, else the trough (−). A trough
/// below 0 cannot be driven without reversing: the actor then brakes to a stop at the rate
/// (v0² + v1²) / (2·dist) (stop, then restart at the same rate, covers dist) and waits at rest
/// until the trough reaches 0.
///
/// Once the peak is passed (`last_phase`, returned for the next step) the actor stays on the
/// last phase, the line of constant acceleration to v1 over the time left, whose speed now is
/// 2·dist/time − v1: re-solving for a peak there would, with the rounding of each step, flip
/// between peak and trough. Returns the speed and whether the last phase runs.
pub(crate) fn profile_speed(
    dist: f64,
    time: f64,
    v0: f64,
    v1: f64,
    dt: f64,
    last_phase: bool,
) -> (f64, bool) {
    if !time.is_finite() {
        return (v0, last_phase);
    }
    let average = dist / time;
    let line = (2.0 * average - v1).max(0.0);
    if last_phase {
        return (line, true);
    }
    let spread = (((dist - v0 * time).powi(2) + (dist - v1 * time).powi(2)) / 2.0).sqrt() / time;
    let vx = if average >= 0.5 * (v0 + v1) {
        average + spread
    } else {
        average - spread
    };
    if vx < -SMALL {
        if v0 <= SMALL {
            return (0.0, false);
        }
        let rate = (v0 * v0 + v1 * v1) / (2.0 * dist);
        return ((v0 - rate * dt).max(0.0), false);
    }
    let a = (2.0 * vx - v0 - v1) / time;
    if a.abs() <= SMALL {
        return (v0, false);
    }
    let x = ((vx - v0) / a).clamp(0.0, time);
    if dt <= x {
        (v0 + a * dt, false)
    } else {
        (line, true)
    }
}

#[cfg(test)]
mod tests {
    use super::profile_speed;

    const DT: f64 = 0.05;

    /// On the line: 100 m in 10 s from 10 to 10 m/s needs no acceleration.
    #[test]
    fn on_the_line_keeps_the_speed() {
        let (v, _) = profile_speed(100.0, 10.0, 10.0, 10.0, DT, false);
        assert!((v - 10.0).abs() < 1e-12, "{v}");
    }

    /// Peak: 300 m in 20 s from 5 to 20 m/s; v_x = 15 + √25000 / 20 = 22.90569 m/s and
    /// a = (2·v_x − 25) / 20 = 1.040569 m/s², so after one step v = 5 + a·dt.
    #[test]
    fn peak_profile_accelerates_at_the_closed_form_rate() {
        let a = (2.0 * (15.0 + 25_000f64.sqrt() / 20.0) - 25.0) / 20.0;
        let (v, last) = profile_speed(300.0, 20.0, 5.0, 20.0, DT, false);
        assert!((v - (5.0 + a * DT)).abs() < 1e-12, "{v}");
        assert!(!last);
    }

    /// Trough below zero: 20 m in 100 s from 10 to 10 m/s. Stop-and-go covers 20 m at the rate
    /// (10² + 10²) / (2·20) = 5 m/s², so one step brakes by 0.25 m/s; at rest it waits.
    #[test]
    fn negative_trough_brakes_to_a_stop_and_waits() {
        let (v, _) = profile_speed(20.0, 100.0, 10.0, 10.0, DT, false);
        assert!((v - 9.75).abs() < 1e-12, "{v}");
        let (v, _) = profile_speed(20.0, 100.0, 0.0, 10.0, DT, false);
        assert!(v.abs() < 1e-12, "{v}");
    }

    /// Last phase: the speed is the line's, 2·s/t − v1 = 2·50/4 − 20 = 5 m/s.
    #[test]
    fn last_phase_follows_the_line() {
        let (v, last) = profile_speed(50.0, 4.0, 6.0, 20.0, DT, true);
        assert!((v - 5.0).abs() < 1e-12, "{v}");
        assert!(last);
    }

    /// A master at rest gives no arrival time: the speed is kept.
    #[test]
    fn no_arrival_time_keeps_the_speed() {
        let (v, _) = profile_speed(50.0, f64::INFINITY, 7.0, 20.0, DT, false);
        assert!((v - 7.0).abs() < 1e-12, "{v}");
    }
}
