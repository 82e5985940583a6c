//! The dynamic limits of a distance action and the law that approaches the wanted distance
//! within them (OpenSCENARIO 1.3 XSD `DynamicConstraints`: maxAcceleration, maxDeceleration,
//! maxAccelerationRate, maxDecelerationRate (1.2+), maxSpeed; `Performance` of a vehicle).
//!
//! The standard says what the limits are, not how the distance is reached: the element
//! "assigns either unlimited dynamics (if omitted) or limited maxAcceleration/maxDeceleration/
//! maxSpeed to the action", each the most "the distance controller is allowed to use". oscsim
//! reads an attribute left out as no limit from the action; a vehicle's Performance still
//! bounds longitudinal motion (semantics-pitfalls #9: the entity's own limits hold whatever
//! the action allows; unlike SpeedProfileAction's, the distance actions' text gives their
//! DynamicConstraints no precedence over Performance), and has nothing to say laterally.
//!
//! The approach is a critically damped spring on the distance error u (m, positive when the
//! actor must move forward / to the left) with the actor's speed relative to the reference w
//! (m/s): a = k·u − 2·√k·w, then clamped to the limits. This is esmini's law (its
//! LongDistanceAction: "damped spring model with critical/optimal damping factor"), including
//! its stiffness k = 0.4 /m × the `tension` limit (1/s²), so that corpus runs compare. With an
//! unlimited tension the spring is infinitely stiff: the step removes the error at once
//! ("dead-beat": v' = v_ref + u/dt), within the other limits.

use scenario::DynamicConstraints;

use crate::world::entity::Entity;

/// Spring constant per m/s² of the tension limit (1/m): k = 0.4 × limit (esmini's value).
pub(crate) const STIFFNESS_PER_LIMIT: f64 = 0.4;

/// The limits one distance action works within; `f64::INFINITY` where nothing limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Limits {
    /// Largest acceleration (m/s², ≥ 0).
    pub acceleration: f64,
    /// Largest deceleration (m/s², ≥ 0).
    pub deceleration: f64,
    /// Largest growth of the acceleration (m/s³).
    pub acceleration_rate: f64,
    /// Largest growth of the deceleration (m/s³).
    pub deceleration_rate: f64,
    /// Largest speed (m/s).
    pub speed: f64,
}

impl Limits {
    /// The limits of a DynamicConstraints element alone (lateral motion: a vehicle's
    /// Performance is longitudinal).
    pub fn from_constraints(c: &DynamicConstraints) -> Limits {
        let limit = |v: Option<f64>| v.map_or(f64::INFINITY, f64::abs);
        Limits {
            acceleration: limit(c.max_acceleration),
            deceleration: limit(c.max_deceleration),
            acceleration_rate: limit(c.max_acceleration_rate),
            deceleration_rate: limit(c.max_deceleration_rate),
            speed: limit(c.max_speed),
        }
    }

    /// The limits of a DynamicConstraints element, each also bounded by the actor's
    /// Performance when it has one (longitudinal motion).
    pub fn longitudinal(c: &DynamicConstraints, actor: &Entity) -> Limits {
        let own = Limits::from_constraints(c);
        let Some(p) = actor.performance else {
            return own;
        };
        let rate = |v: Option<f64>| v.map_or(f64::INFINITY, f64::abs);
        Limits {
            acceleration: own.acceleration.min(p.max_acceleration.abs()),
            deceleration: own.deceleration.min(p.max_deceleration.abs()),
            acceleration_rate: own.acceleration_rate.min(rate(p.max_acceleration_rate)),
            deceleration_rate: own.deceleration_rate.min(rate(p.max_deceleration_rate)),
            speed: own.speed.min(p.max_speed.abs()),
        }
    }
}

/// The spring's acceleration (m/s²) for error `u` (m) and relative speed `w` (m/s) with
/// stiffness from `tension` (m/s²), before any clamping; over a step of `dt` s (> 0).
pub(crate) fn spring(u: f64, w: f64, tension: f64, dt: f64) -> f64 {
    if tension.is_finite() {
        let k = STIFFNESS_PER_LIMIT * tension;
        k * u - 2.0 * k.sqrt() * w
    } else {
        (u / dt - w) / dt
    }
}

/// `acc` after the jerk limits, from the previous step's acceleration `last` over `dt`: the
/// acceleration falls by at most `deceleration_rate`·dt and rises by at most
/// `acceleration_rate`·dt per step (the XSD names the rates of acceleration and deceleration;
/// oscsim applies each to the direction the acceleration moves in).
pub(crate) fn limit_jerk(acc: f64, last: f64, limits: &Limits, dt: f64) -> f64 {
    if acc < last {
        acc.max(last - limits.deceleration_rate * dt)
    } else {
        acc.min(last + limits.acceleration_rate * dt)
    }
}

/// The acceleration bounds (lowest, highest; m/s²) that still let the jerk limits bring the
/// acceleration back to 0 before the speed `v` (m/s) leaves [0, `limits.speed`] over steps of
/// `dt` s. Ramping an acceleration a down to 0 at the rate J takes a/J s and adds a²/(2J) m/s
/// (continuous), a²/(2J) + a·dt/2 in steps of dt (a the step-wise ramp's first value); the
/// bound solves a²/(2J) + a·dt = room, which covers both. Without a rate limit there is no
/// bound (the acceleration may change at once, and the speed clamp does it). Clamping the speed afterwards would change the acceleration at once,
/// against the jerk limits; within these bounds the clamp has nothing to do.
pub(crate) fn speed_room(v: f64, limits: &Limits, dt: f64) -> (f64, f64) {
    let bound = |room: f64, rate: f64| {
        let room = room.max(0.0);
        if rate.is_finite() && rate > 0.0 {
            rate * (-dt + (dt * dt + 2.0 * room / rate).sqrt())
        } else {
            f64::INFINITY
        }
    };
    (
        -bound(v, limits.acceleration_rate),
        bound(limits.speed - v, limits.deceleration_rate),
    )
}
