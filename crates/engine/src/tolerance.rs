//! The engine's numeric tolerances, named once: what counts as the same time, speed, length,
//! heading change or value when floating-point round-off is all that separates two numbers.
//! Every comparison "within round-off" in the engine uses one of these (or a constant defined
//! from one of them beside the rule it serves); tests compare against closed forms at their
//! own named tolerances.
//!
//! Why these sizes: the engine runs in f64 (relative resolution 1.1e-16) and its time is
//! step · dt, one rounding. An elapsed time (a difference of two such times) at 10⁵ s is off
//! by at most two half-ulps there, 1.5e-11 s; 1e-9 s absorbs that with room and stays far
//! below any step the engine accepts. Lengths and speeds follow the same reasoning on metres
//! and m/s; OpenDRIVE lengths share opendrive's [`LENGTH_EPSILON`](opendrive::LENGTH_EPSILON).

/// Times closer than this (s) are the same time: the round-off of summed steps, e.g. an
/// action of duration d ends at the step whose elapsed time reaches d − `TIME`.
pub const TIME: f64 = 1e-9;

/// Speeds closer than this (m/s) are the same speed (a target speed reached, a speed limited).
pub const SPEED: f64 = 1e-9;

/// Lengths closer than this (m) are the same length (opendrive's `LENGTH_EPSILON`).
pub const LENGTH: f64 = opendrive::LENGTH_EPSILON;

/// A heading change (rad) below this over one move is a straight line: the arc's sagitta is
/// then below `TURN` · distance.
pub const TURN: f64 = 1e-9;

/// Relative (and, below 1, absolute) tolerance of equality between condition values:
/// |a − b| ≤ `VALUE` · max(1, |a|, |b|).
pub const VALUE: f64 = 1e-9;

/// A fraction of the step: a time within `STEP_FRACTION` · dt of a step's time belongs to that
/// step, at any dt (the end of the run, values scheduled from outside).
pub const STEP_FRACTION: f64 = 1e-6;

#[cfg(test)]
mod tests {
    use super::*;

    /// Elapsed times of step-multiple durations, (s + j)·dt − s·dt against j·dt, for starts up
    /// to 10⁵ s at dt = 0.05 s: all within `TIME` (the worst, 1.2e-11 s, found by the same
    /// loop in Python).
    #[test]
    fn time_separates_round_off_from_a_step() {
        let dt = 0.05_f64;
        for start in (0..2_000_000u32).step_by(1013) {
            for j in [1u32, 7, 46, 200, 999] {
                let s = f64::from(start);
                let elapsed = (s + f64::from(j)) * dt - s * dt;
                assert!((elapsed - f64::from(j) * dt).abs() < TIME, "{start} + {j}");
            }
        }
    }
}
