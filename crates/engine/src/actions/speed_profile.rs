//! SpeedProfileAction (OpenSCENARIO 1.3 §7.7.2.1 "LongitudinalAction", XSD `SpeedProfileAction`,
//! 1.2+): a series of speed targets, each reached `time` seconds after the previous one, or,
//! without a time, as soon as the acceleration limit allows.
//!
//! The model documentation of `followingMode` defines the two modes:
//! - `position`: "strictly linear interpolation between speed target values", ignoring the
//!   dynamic constraints (`FollowingMode.position`); a target with time 0 is a jump.
//! - `follow`: "apply jerk (change rate of acceleration/deceleration) and other optional
//!   constraints … resulting in a smoother speed profile curve. For mode=follow the acceleration
//!   is zero at the start and end of the profile."
//!
//! `follow` is planned here as the position-mode lines with rounded corners: each segment's
//! slope is clamped to [−maxDeceleration, maxAcceleration], and the change from one slope to the
//! next is a ramp of constant jerk (maxAccelerationRate when the acceleration rises,
//! maxDecelerationRate when it falls), centred on the two lines' crossing, so the speed joins
//! both lines tangentially. A ramp that would begin before the previous one has ended (always
//! the first one, which starts from acceleration 0 at the action's start) begins when that one
//! ends instead, and the motion lands on the next line shifted later in time. The last ramp
//! brings the acceleration to 0 exactly at the last target speed. Where the standard is silent
//! (where the corner sits, what happens at the start) this is esmini's convention, whose
//! speed-profile.xosc reference it reproduces. Without a jerk limit the corners stay sharp.
//!
//! Limits: DynamicConstraints "has precedence over any Performance settings" (model
//! documentation of SpeedProfileAction), so each limit is the action's where given, else the
//! vehicle's Performance, else 5 m/s² for accelerations and none for jerk and speed. (esmini
//! instead truncates the action's limits at the Performance; the two agree whenever the action
//! asks for less than the vehicle can do, as in every corpus scenario.)

use scenario::{DynamicConstraints, FollowingMode, LongitudinalAction, Performance, SourcePos};

use super::Part;
use crate::error::Error;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;

/// Acceleration (m/s²) used when neither the action nor the vehicle gives one.
const DEFAULT_ACCELERATION: f64 = 5.0;
/// Times (s), speeds (m/s) and slopes (m/s²) closer than this are the same: the workspace's
/// 1e-9 tolerance.
const EPS: f64 = crate::tolerance::TIME;

/// A running SpeedProfileAction on one actor: pieces of constant jerk, in time order.
#[derive(Debug, Clone)]
pub(crate) struct ProfileState {
    pieces: Vec<Piece>,
    /// Upper speed bound (m/s): maxSpeed in `follow`, none in `position`.
    max_speed: f64,
}

/// v(t) = v + a·(t − t0) + j·(t − t0)²/2 from `t0` until the next piece's `t0`; the last piece,
/// at the final speed with a = j = 0, starts when the profile ends.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    t0: f64,
    v: f64,
    a: f64,
    j: f64,
}

impl Piece {
    fn speed(&self, t: f64) -> f64 {
        let d = t - self.t0;
        self.v + self.a * d + 0.5 * self.j * d * d
    }
}

/// A straight line v(t) = v + k·(t − t0) of the speed over time.
#[derive(Debug, Clone, Copy)]
struct Line {
    t0: f64,
    v: f64,
    k: f64,
}

impl Line {
    fn speed(&self, t: f64) -> f64 {
        self.v + self.k * (t - self.t0)
    }
}

/// The limits in force: the action's DynamicConstraints, else the vehicle's Performance.
#[derive(Debug, Clone, Copy)]
struct Limits {
    acceleration: f64,
    deceleration: f64,
    acceleration_rate: Option<f64>,
    deceleration_rate: Option<f64>,
    max_speed: f64,
}

/// The first usable (finite, positive) value of `values`.
fn first_positive(values: &[Option<f64>]) -> Option<f64> {
    values
        .iter()
        .flatten()
        .copied()
        .find(|v| v.is_finite() && *v > 0.0)
}

impl Limits {
    fn new(c: Option<DynamicConstraints>, perf: Option<Performance>) -> Limits {
        let c = c.unwrap_or_default();
        Limits {
            acceleration: first_positive(&[c.max_acceleration, perf.map(|p| p.max_acceleration)])
                .unwrap_or(DEFAULT_ACCELERATION),
            deceleration: first_positive(&[c.max_deceleration, perf.map(|p| p.max_deceleration)])
                .unwrap_or(DEFAULT_ACCELERATION),
            acceleration_rate: first_positive(&[
                c.max_acceleration_rate,
                perf.and_then(|p| p.max_acceleration_rate),
            ]),
            deceleration_rate: first_positive(&[
                c.max_deceleration_rate,
                perf.and_then(|p| p.max_deceleration_rate),
            ]),
            max_speed: first_positive(&[c.max_speed, perf.map(|p| p.max_speed)])
                .unwrap_or(f64::INFINITY),
        }
    }

    /// The acceleration limit for a change of speed by `dv`.
    fn for_change(&self, dv: f64) -> f64 {
        if dv >= 0.0 {
            self.acceleration
        } else {
            self.deceleration
        }
    }
}

/// Starts the action: plans the profile from the current speed.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &LongitudinalAction,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let LongitudinalAction::SpeedProfile {
        entity_ref: reference,
        following_mode,
        dynamic_constraints,
        entries,
    } = action
    else {
        return Err(Error::unsupported("this LongitudinalAction", pos));
    };
    // XSD SpeedProfileEntry@time: "Range: [0..inf[".
    if let Some((index, time)) = entries
        .iter()
        .enumerate()
        .find_map(|(i, x)| x.time.filter(|t| *t < 0.0).map(|t| (i, t)))
    {
        return Err(Error::at(
            "a SpeedProfileEntry time of 0 s or more",
            format!("time {time} in SpeedProfileEntry {}", index + 1),
            pos,
        ));
    }
    // Relative entries are offsets from the reference's speed when the action starts.
    let base = match reference {
        Some(name) => world.entity(entity_ref(world, name, pos)?).speed,
        None => 0.0,
    };
    let e = world.entity(actor);
    let limits = Limits::new(*dynamic_constraints, e.performance);
    let targets: Vec<(Option<f64>, f64)> =
        entries.iter().map(|x| (x.time, base + x.speed)).collect();
    let vertices = schedule(now, e.speed, &targets, &limits);
    let mut state = match following_mode {
        FollowingMode::Follow => ProfileState {
            pieces: plan_follow(&vertices, &limits),
            max_speed: limits.max_speed,
        },
        _ => ProfileState {
            pieces: plan_position(&vertices),
            max_speed: f64::INFINITY,
        },
    };
    Ok(match step(world, actor, &mut state, now, 0.0) {
        ActionStatus::Running => Part::Profile(state),
        done => Part::Done(done),
    })
}

/// The profile's vertices (time, speed), starting at (`now`, `v0`): each target `time` seconds
/// after the previous one (times are checked ≥ 0 and the reader admits only finite numbers),
/// or, without a time, after |Δv| / the acceleration limit.
fn schedule(now: f64, v0: f64, targets: &[(Option<f64>, f64)], limits: &Limits) -> Vec<(f64, f64)> {
    let mut vertices = vec![(now, v0)];
    let (mut t, mut v) = (now, v0);
    for &(time, target) in targets {
        t += match time {
            Some(d) => d,
            _ => (target - v).abs() / limits.for_change(target - v),
        };
        v = target;
        vertices.push((t, v));
    }
    vertices
}

/// `position`: straight lines between the vertices; a vertex at the same time as the previous
/// one is a jump.
fn plan_position(vertices: &[(f64, f64)]) -> Vec<Piece> {
    let mut pieces = Vec::with_capacity(vertices.len());
    for w in vertices.windows(2) {
        let ((t0, v0), (t1, v1)) = (w[0], w[1]);
        if t1 - t0 > EPS {
            pieces.push(Piece {
                t0,
                v: v0,
                a: (v1 - v0) / (t1 - t0),
                j: 0.0,
            });
        }
    }
    if let Some(&(t, v)) = vertices.last() {
        pieces.push(Piece {
            t0: t,
            v,
            a: 0.0,
            j: 0.0,
        });
    }
    pieces
}

/// `follow`: the position lines with slopes within the acceleration limits, joined by ramps of
/// constant jerk (see the module doc); acceleration 0 at the start and at the end.
fn plan_follow(vertices: &[(f64, f64)], limits: &Limits) -> Vec<Piece> {
    let Some(&(t_start, v_start)) = vertices.first() else {
        return Vec::new();
    };
    let &(t_end, v_end) = vertices.last().unwrap_or(&(t_start, v_start));
    // The lines to follow: one per segment, then the final speed held.
    let mut lines: Vec<Line> = vertices
        .windows(2)
        .map(|w| {
            let ((t0, v0), (t1, v1)) = (w[0], w[1]);
            let dv = v1 - v0;
            let k = if dv.abs() <= EPS {
                0.0
            } else if t1 - t0 > EPS {
                dv / (t1 - t0)
            } else {
                dv.signum() * limits.for_change(dv)
            };
            Line {
                t0,
                v: v0,
                k: k.clamp(-limits.deceleration, limits.acceleration),
            }
        })
        .collect();
    lines.push(Line {
        t0: t_end,
        v: v_end,
        k: 0.0,
    });
    // Acceleration 0 at the start: the motion starts on the level line of the current speed.
    let mut current = Line {
        t0: t_start,
        v: v_start,
        k: 0.0,
    };
    let mut pieces = vec![Piece {
        t0: t_start,
        v: v_start,
        a: 0.0,
        j: 0.0,
    }];
    let count = lines.len();
    for (index, next) in lines.into_iter().enumerate() {
        let dk = next.k - current.k;
        if dk.abs() <= EPS {
            continue;
        }
        let jerk = if dk > 0.0 {
            limits.acceleration_rate
        } else {
            limits.deceleration_rate
        };
        let ramp = jerk.map_or(0.0, |j| dk.abs() / j);
        // The lines cross at t_x; a ramp centred there is tangent to both.
        let t_x = (current.v - current.k * current.t0 - next.v + next.k * next.t0) / dk;
        let begin = t_x - 0.5 * ramp;
        if begin >= current.t0 - EPS {
            let begin = begin.max(current.t0);
            ramp_to(&mut pieces, &mut current, begin, ramp, next.k);
        } else if index + 1 < count {
            // Late: start now and land on the next line shifted later in time.
            let begin = current.t0;
            ramp_to(&mut pieces, &mut current, begin, ramp, next.k);
        } else {
            land_late(&mut pieces, &mut current, v_end, limits);
        }
    }
    if current.k != 0.0 || (current.v - v_end).abs() > EPS {
        land_late(&mut pieces, &mut current, v_end, limits);
    }
    // Hold the final speed from where the motion reached it, not before the last vertex.
    pieces.push(Piece {
        t0: current.t0.max(t_end),
        v: v_end,
        a: 0.0,
        j: 0.0,
    });
    pieces
}

/// A ramp of constant jerk from `current`'s slope to `k` over `ramp` seconds from `begin`; the
/// motion continues on the line of slope `k` it lands on.
fn ramp_to(pieces: &mut Vec<Piece>, current: &mut Line, begin: f64, ramp: f64, k: f64) {
    let v = current.speed(begin);
    let dk = k - current.k;
    if ramp > 0.0 {
        pieces.push(Piece {
            t0: begin,
            v,
            a: current.k,
            j: dk / ramp,
        });
    }
    *current = Line {
        t0: begin + ramp,
        v: v + ramp * (current.k + 0.5 * dk),
        k,
    };
    pieces.push(Piece {
        t0: current.t0,
        v: current.v,
        a: k,
        j: 0.0,
    });
}

/// Reaches `v_end` with acceleration 0 from the end of `current`'s last ramp when the jerk limit
/// leaves too little room: a steeper ramp that still lands on `v_end` if the motion heads there,
/// else a straight change at the acceleration limit (a corner the jerk limit cannot round).
fn land_late(pieces: &mut Vec<Piece>, current: &mut Line, v_end: f64, limits: &Limits) {
    let (t0, v, k) = (current.t0, current.v, current.k);
    let dv = v_end - v;
    let duration = if k != 0.0 && dv * k > 0.0 {
        let ramp = 2.0 * dv / k;
        pieces.push(Piece {
            t0,
            v,
            a: k,
            j: -k / ramp,
        });
        ramp
    } else if dv.abs() > EPS {
        let limit = limits.for_change(dv);
        pieces.push(Piece {
            t0,
            v,
            a: dv.signum() * limit,
            j: 0.0,
        });
        dv.abs() / limit
    } else {
        0.0
    };
    *current = Line {
        t0: t0 + duration,
        v: v_end,
        k: 0.0,
    };
    pieces.push(Piece {
        t0: current.t0,
        v: v_end,
        a: 0.0,
        j: 0.0,
    });
}

impl ProfileState {
    /// When the profile reaches its last speed (s).
    fn end(&self) -> f64 {
        self.pieces.last().map_or(f64::NEG_INFINITY, |p| p.t0)
    }

    /// True when the profile is complete by `t`: its last stretch of motion is in the step that
    /// ends at `t` (the timing of the other fixed-time transitions, see `actions::status`).
    pub(crate) fn completes_by(&self, t: f64) -> bool {
        t >= self.end() - EPS
    }

    /// The planned speed at time `t`.
    fn speed(&self, t: f64) -> f64 {
        let piece = self
            .pieces
            .iter()
            .take_while(|p| p.t0 <= t + EPS)
            .last()
            .or(self.pieces.first());
        piece.map_or(0.0, |p| p.speed(t.max(p.t0)))
    }
}

/// Sets the speed at the step's end, `now + dt`.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut ProfileState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    let t = now + dt;
    if s.pieces.is_empty() {
        return ActionStatus::Ended;
    }
    let v = s.speed(t);
    world.entity_mut(actor).speed = v.clamp(-s.max_speed, s.max_speed);
    if s.completes_by(t) {
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}
