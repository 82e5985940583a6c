//! Transition shapes and dimensions of OpenSCENARIO 1.3 §7.7.2 "TransitionDynamics"
//! (XSD `DynamicsShape`, `DynamicsDimension`): how an action moves a value from its start to
//! its target.
//!
//! A shape maps progress p ∈ [0, 1] to the fraction f(p) of the change done:
//! `linear` f = p; `cubic` f = 3p² − 2p³; `sinusoidal` f = (1 − cos πp) / 2 (both with zero
//! slope at p = 0 and p = 1); `step` f = 1 at once, taking no time (semantics-pitfalls #8).
//!
//! The dimension says what drives p: elapsed `time` over the given duration, travelled
//! `distance` over the given distance, or a `rate` (unit/s). The standard defines `rate` only
//! for the linear shape; for cubic and sinusoidal oscsim reads it as the peak rate (the ALKS
//! reading, pitfall 8), so the duration is |Δ| · max f′ / rate with max f′ = 1.5 (cubic) and
//! π/2 (sinusoidal).

use scenario::{DynamicsDimension, DynamicsShape, TransitionDynamics};

/// f(p) and f′(p) of `shape` at progress `p` (clamped to [0, 1]).
pub fn shape_value(shape: DynamicsShape, p: f64) -> (f64, f64) {
    let p = p.clamp(0.0, 1.0);
    match shape {
        DynamicsShape::Linear => (p, 1.0),
        DynamicsShape::Cubic => (3.0 * p * p - 2.0 * p * p * p, 6.0 * p - 6.0 * p * p),
        DynamicsShape::Sinusoidal => {
            let a = std::f64::consts::PI * p;
            ((1.0 - a.cos()) / 2.0, std::f64::consts::FRAC_PI_2 * a.sin())
        }
        _ => (1.0, 0.0),
    }
}

/// ∫₀ᵖ f(q) dq of `shape` (p ≥ 0; f = 1 beyond p = 1): the share of a transition's change that
/// a quantity integrating the transitioned value has gathered (a speed, of an acceleration).
/// Closed forms: linear p²/2, cubic p³ − p⁴/2, sinusoidal (p − sin(πp)/π)/2; each is ½ at
/// p = 1 (f(p) + f(1 − p) = 1); `step` gives p.
pub fn shape_integral(shape: DynamicsShape, p: f64) -> f64 {
    let q = p.clamp(0.0, 1.0);
    let inside = match shape {
        DynamicsShape::Linear => q * q / 2.0,
        DynamicsShape::Cubic => q * q * q - q * q * q * q / 2.0,
        DynamicsShape::Sinusoidal => {
            (q - (std::f64::consts::PI * q).sin() / std::f64::consts::PI) / 2.0
        }
        _ => return p.max(0.0),
    };
    inside + (p - 1.0).max(0.0)
}

/// The largest slope f′ of `shape` over [0, 1].
pub fn peak_slope(shape: DynamicsShape) -> f64 {
    match shape {
        DynamicsShape::Cubic => 1.5,
        DynamicsShape::Sinusoidal => std::f64::consts::FRAC_PI_2,
        _ => 1.0,
    }
}

/// What drives a transition's progress, with its total.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Span {
    /// Progress = elapsed time / this duration (s).
    Time(f64),
    /// Progress = travelled distance / this distance (m).
    Distance(f64),
    /// Done at once (step shape, or a zero-length span).
    Instant,
}

/// A transition of one value by `delta` under `dynamics`: its span.
pub fn span(dynamics: &TransitionDynamics, delta: f64) -> Span {
    if dynamics.dynamics_shape == DynamicsShape::Step {
        return Span::Instant;
    }
    let v = dynamics.value.abs();
    let span = match dynamics.dynamics_dimension {
        DynamicsDimension::Time => Span::Time(v),
        DynamicsDimension::Distance => Span::Distance(v),
        DynamicsDimension::Rate if v > 0.0 => {
            Span::Time(delta.abs() * peak_slope(dynamics.dynamics_shape) / v)
        }
        _ => Span::Instant,
    };
    match span {
        Span::Time(t) | Span::Distance(t) if !(t.is_finite() && t > 0.0) => Span::Instant,
        s => s,
    }
}

/// Progress p ∈ [0, 1] of a transition along its span after `elapsed` s and `travelled` m
/// (for a lateral transition, metres along the road: actions::lane_change).
pub fn progress(span: Span, elapsed: f64, travelled: f64) -> f64 {
    match span {
        Span::Instant => 1.0,
        Span::Time(t) => (elapsed / t).min(1.0),
        Span::Distance(d) => (travelled / d).min(1.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed forms against a midpoint sum of f over [0, p].
    #[test]
    fn shape_integral_is_the_integral_of_the_shape() {
        const TOL: f64 = 1e-9;
        for shape in [
            DynamicsShape::Linear,
            DynamicsShape::Cubic,
            DynamicsShape::Sinusoidal,
        ] {
            for p in [0.0, 0.25, 0.5, 1.0, 1.75] {
                let n = 200_000;
                let h = p / n as f64;
                let sum: f64 = (0..n)
                    .map(|i| shape_value(shape, (i as f64 + 0.5) * h).0 * h)
                    .sum();
                let got = shape_integral(shape, p);
                assert!((got - sum).abs() < TOL, "{shape:?} {p}: {got} vs {sum}");
            }
            // Half of the change's time at p = 1, for every shape.
            assert!((shape_integral(shape, 1.0) - 0.5).abs() < TOL);
        }
    }
}
