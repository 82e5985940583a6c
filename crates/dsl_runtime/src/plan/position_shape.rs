//! `position(d, at: end, shape: s)` and `distance(d, shape: s)` with a `common_position_shape`
//! (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.4 parameter `shape`, §8.9.1.2: the shape gives the
//! position over the phase, "measured from the start of the scenario phase"; its `target`,
//! `rate_profile` and `rate_peak` "provide a complete set of constraints to resolve the target
//! shape"). The position along the lane rises from where the actor is at the phase start by
//! Δ (`distance`: d along the lane; `position`: to s = d, Δ along the lane), and its rate is the
//! speed, so the shape is the speed profile that covers Δ:
//!
//! | rate_profile | speed | duration T |
//! | --- | --- | --- |
//! | `constant` | `rate_peak` from the start (a step from v₀), held | Δ / rate_peak |
//! | `smooth` | two halves v₀ → v_m → v₀, each the engine's sinusoidal change (acceleration 0 at the start, the middle and the end) | 2Δ / (v₀ + v_m) |
//! | `none` | the same two halves, linear: the profile of `position(…, at: end)` without a shape | 2Δ / (v₀ + v_m) |
//!
//! v_m, the speed at the middle, is `rate_peak` (the peak when above v₀); a half's mean speed is
//! (v₀ + v_m)/2 for either shape, so they cover Δ in the same T. Without `rate_peak`, T is the
//! phase's duration (v_m = 2Δ/T − v₀, the rate Δ/T); with both, they must agree. The change
//! ends at T: a phase without an end of its own ends then, one with an end must end then (the
//! actor is at the position at the phase's end, `at: end`). `asap` ("as soon as possible") is
//! an error: it fixes no speed the position rises at. The plan knows the distance only at a
//! start it knows: after a run-time condition an error.

use scenario::{DynamicsShape, SpeedTarget};

use super::motion::{check_speed, speed_action};
use super::planner::Planner;
use super::shape_relative::place_reference;
use super::speed_actions::Slot;
use super::types::{Planned, When};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{ModKind, Modifier};
use crate::road::LENGTH_STEP;

/// How far a duration from `rate_peak` may differ from the phase's and still agree (s).
const DURATION_TOLERANCE: f64 = 1e-6;

impl Planner<'_> {
    /// Plans the shaped `position(…, at: end)` or `distance(…)` `m` of `slot`'s actor: `value`
    /// its s or distance, `profile` and `peak` the shape's `rate_profile` and `rate_peak` (m/s,
    /// `None` when not given). Returns when the change ends.
    pub(super) fn plan_position_shape(
        &mut self,
        m: &Modifier,
        slot: Slot<'_>,
        (value, profile, peak): (f64, &str, Option<f64>),
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Slot {
            target,
            t0,
            len,
            out,
            ..
        } = slot;
        let Some(t) = t0 else {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected a phase start the plan knows for `{}(…)` with a common_position_shape (the distance to cover is measured from where the plan has the actor then), found one after a run-time condition", m.name),
            ));
        };
        let (lane, s0) = (self.lane_now(target, t), self.s_at(target, t));
        let v0 = self.track(target).at(t).1;
        let delta = match m.kind {
            ModKind::Distance => value,
            _ => self.road.lane_distance(lane, s0, value),
        };
        if delta <= 0.0 {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` to move forward along its lane in `{}(…)`'s shape, found {delta:.2} m to cover from s = {s0:.2} m", m.name),
            ));
        }
        let len = len.filter(|l| *l > 0.0);
        let agree = |from_peak: f64| -> Result<f64, Error> {
            match len {
                Some(l) if (l - from_peak).abs() > DURATION_TOLERANCE => Err(m.site.err(
                    K::Unsatisfiable,
                    format!("expected the shape's rate_peak to cover {delta:.2} m in the phase's {l:.2} s, found it takes {from_peak:.2} s (give one of them)"),
                )),
                _ => Ok(from_peak),
            }
        };
        let no_rate = || {
            m.site.err(
                K::Unsatisfiable,
                format!("expected a rate_peak in `{}(…)`'s common_position_shape or a phase duration, found neither (nothing fixes how fast the position rises)", m.name),
            )
        };
        let span = match profile {
            "constant" => {
                let (v, span) = match (peak, len) {
                    (Some(v), _) if v > 0.0 => (v, agree(delta / v)?),
                    (_, Some(l)) => (delta / l, l),
                    _ => return Err(no_rate()),
                };
                check_speed(m, v)?;
                out.retain(|a| !(a.entity == target && a.name.ends_with(":speed")));
                out.push(Planned {
                    entity: target.to_string(),
                    at: None,
                    name: name("position_shape"),
                    action: speed_action(DynamicsShape::Step, 0.0, SpeedTarget::Absolute(v)),
                    site: m.site.clone(),
                });
                self.track_mut(target).ramp(t, t, v);
                self.last_v.insert(target.to_string(), v);
                span
            }
            "smooth" | "none" => {
                let span = match (peak, len) {
                    (Some(vm), _) if v0 + vm > 0.0 => agree(2.0 * delta / (v0 + vm))?,
                    (_, Some(l)) => l,
                    _ => return Err(no_rate()),
                };
                let shape = if profile == "smooth" {
                    DynamicsShape::Sinusoidal
                } else {
                    DynamicsShape::Linear
                };
                let names = (name("position_shape.1"), name("position_shape.2"));
                self.two_halves(m, target, (t, span, shape), (v0, delta, v0), names, out)?;
                span
            }
            other => return Err(profile_error(m, other)),
        };
        Ok(Some(When::At(t + span)))
    }

    /// The s a shaped `position(d, ahead_of/behind: x, at: end)` of `target` asks for in a
    /// phase without a duration, starting at `t0`: the shape's own timing sets the end T, and
    /// x's s then ± d is the place (`track: actual` x's planned s at t0 + T; `projected` its s
    /// at t0 + its speed then × T). T solves T = k·Δ(T), Δ(T) the distance along the actor's
    /// lane to x's place at T and k the time per metre of the profile (`constant`: 1 /
    /// rate_peak; `smooth`, `none`: 2 / (v₀ + rate_peak)): the first root, bracketed on a
    /// scan of [`SCAN_STEP`] s and bisected. Where x moves slower than the profile's mean
    /// speed T − k·Δ(T) rises, one root; with x as fast or faster, none within
    /// [`SOLVE_HORIZON`]: an error naming both, at once where g is shown linear and falling
    /// (a `projected` x past the roads' end: [`bracket`]). `None` without a reference.
    pub(super) fn shaped_place_at_rate(
        &self,
        m: &Modifier,
        (target, t0): (&str, Option<f64>),
        d: f64,
        (profile, peak): (&str, Option<f64>),
    ) -> Result<Option<f64>, Error> {
        let Some((e, sign)) = place_reference(m) else {
            return Ok(None);
        };
        let x = self.entity_of(e)?;
        let Some(t) = t0 else {
            // plan_position_shape's refusal: the distance is measured from the plan's place.
            return Ok(Some(d));
        };
        let (lane, s0) = (self.lane_now(target, t), self.s_at(target, t));
        let v0 = self.track(target).at(t).1;
        let peak = peak.filter(|v| *v > 0.0);
        let k = match (profile, peak) {
            ("constant", Some(v)) => 1.0 / v,
            ("smooth" | "none", Some(v)) => 2.0 / (v0 + v),
            ("constant" | "smooth" | "none", None) => {
                return Err(m.site.err(
                    K::Unsatisfiable,
                    format!("expected a rate_peak in `{}(…)`'s common_position_shape relative to `{x}` in a phase without a duration (its timing sets the end where `{x}`'s place is read), found none", m.name),
                ))
            }
            (other, _) => return Err(profile_error(m, other)),
        };
        let (sx0, vx0) = (self.s_at(&x, t), self.track(&x).at(t).1);
        let place = |span: f64| {
            sign * d
                + if m.projected {
                    sx0 + vx0 * span
                } else {
                    self.s_at(&x, t + span)
                }
        };
        let g = |span: f64| span - k * self.road.lane_distance(lane, s0, place(span));
        if g(0.0) >= 0.0 {
            // Nothing ahead to cover: plan_position_shape's refusal names the distance.
            return Ok(Some(place(0.0)));
        }
        // g's tail, where it is linear (see `Linear`): `projected` x's place is sx0 + vx0·span,
        // and lane_distance counts 1 m per m of s on the steps that end past the roads
        // (`PlanRoad::lane_distance`), the same steps before them for every place past
        // the roads' end + one step; in +s, where its steps start at s0 whatever the place.
        let end = self.road.length() + LENGTH_STEP;
        let tail = |span: f64, g_span: f64| -> Option<Linear> {
            if !m.projected || self.road.is_against() {
                return None;
            }
            let here = place(span);
            if here <= end.max(s0) {
                return None;
            }
            let there = place(SOLVE_HORIZON);
            let steps = (there - s0).abs() / LENGTH_STEP + 4.0;
            let scale = SOLVE_HORIZON
                + (span - g_span).abs()
                + k * ((there - here).abs() + d.abs() + sx0.abs() + (vx0 * SOLVE_HORIZON).abs());
            Some(Linear {
                slope: 1.0 - k * vx0 + 4.0 * f64::EPSILON * (1.0 + (k * vx0).abs()),
                err: steps * f64::EPSILON * scale,
            })
        };
        let Some((lo, hi)) = bracket(&g, &tail) else {
            let (side, v_mean) = (if sign > 0.0 { "ahead of" } else { "behind" }, 1.0 / k);
            return Err(e.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` to reach its place {d} m {side} `{x}` at the rate of `{}(…)`'s shape (a mean {v_mean:.2} m/s), found `{x}` moving away as fast: no end within {SOLVE_HORIZON} s where the profile covering the distance to `{x}`'s place then takes that long", m.name),
            ));
        };
        let (mut a, mut b) = (lo, hi);
        for _ in 0..BISECTIONS {
            let mid = (a + b) / 2.0;
            if g(mid) < 0.0 {
                a = mid;
            } else {
                b = mid;
            }
        }
        Ok(Some(place(b)))
    }
}

/// The refusal of a `rate_profile` other than constant, smooth or none.
fn profile_error(m: &Modifier, other: &str) -> Error {
    m.site.err(
        K::Unsatisfiable,
        format!("expected rate_profile constant, smooth or none in `{}(…)`'s common_position_shape, found {other} (as soon as possible fixes no speed the position rises at)", m.name),
    )
}

/// g from a span on: linear in the span with a slope at most `slope`, each value computed
/// within `err` of the linear one (the rounding of its sums; k·Δ there is span − g, Δ the
/// lane's length, which exceeds the s covered on a bend).
struct Linear {
    slope: f64,
    err: f64,
}

/// The first step of the scan of `g` from 0 to [`SOLVE_HORIZON`] by [`SCAN_STEP`] at whose
/// end g ≥ 0 (`g(0)` < 0): (its start, its end), `None` when no step's end reaches 0.
/// Where `tail` shows g linear from a step's end on, with a slope ≤ 0 and g there below
/// −2·err, no later end reaches 0 either (each is at most g there + 2·err): `None` at
/// once, the answer of the whole scan without the evaluations after (3,600 s of a reference
/// moving away as fast as the profile's mean, each one a sum over the lane from the actor
/// to the place); a root found is found by the same evaluations as without `tail`.
fn bracket(
    g: &dyn Fn(f64) -> f64,
    tail: &dyn Fn(f64, f64) -> Option<Linear>,
) -> Option<(f64, f64)> {
    let mut lo = 0.0;
    loop {
        let next = lo + SCAN_STEP;
        if next > SOLVE_HORIZON {
            return None;
        }
        let here = g(next);
        if here >= 0.0 {
            return Some((lo, next));
        }
        if let Some(l) = tail(next, here) {
            if l.slope <= 0.0 && here + 2.0 * l.err < 0.0 {
                return None;
            }
        }
        lo = next;
    }
}

/// How far the end of a shaped position relative to another actor is searched (s).
const SOLVE_HORIZON: f64 = 3600.0;
/// The scan that brackets its first root (s).
const SCAN_STEP: f64 = 0.5;
/// Halvings of the bracket: 0.5 s / 2⁶⁰, below f64's resolution of the end.
const BISECTIONS: usize = 60;

#[cfg(test)]
mod tests {
    use super::*;

    /// g of err_position_shape_unreachable.osc with a lead at `vx`: ego from s = 50 m at a
    /// mean 20 m/s (k = 1/20) to 20 m behind lead's projected 150 + vx·T, off the roads (1 m
    /// of lane per m of s).
    fn g_of(vx: f64) -> impl Fn(f64) -> f64 {
        move |span: f64| span - (-20.0 + (150.0 + vx * span) - 50.0) / 20.0
    }

    /// Its tail: linear everywhere (no road), slope 1 − vx/20, as the planner bounds it.
    fn tail_of(vx: f64) -> impl Fn(f64, f64) -> Option<Linear> {
        move |_, _| {
            Some(Linear {
                slope: 1.0 - vx / 20.0 + 4.0 * f64::EPSILON * (1.0 + vx / 20.0),
                err: 1e-9,
            })
        }
    }

    fn never(_: f64, _: f64) -> Option<Linear> {
        None
    }

    #[test]
    fn the_tail_answers_as_the_whole_scan() {
        // The fixture, vx = 30: g(T) = T − (80 + 30T)/20 = −4 − 0.5T, no root (the full
        // scan's None), and the tail says so at the first step.
        let calls = std::cell::Cell::new(0);
        let g = g_of(30.0);
        let counted = |s: f64| {
            calls.set(calls.get() + 1);
            g(s)
        };
        assert_eq!(bracket(&g, &never), None);
        assert_eq!(bracket(&counted, &tail_of(30.0)), None);
        assert_eq!(calls.get(), 1);
        // vx = 20: g = −4 throughout, slope 0: no root either way.
        assert_eq!(bracket(&g_of(20.0), &never), None);
        assert_eq!(bracket(&g_of(20.0), &tail_of(20.0)), None);
        // A late root: vx = 20(1 − 1/750) makes g = T/750 − 4, 0 at T = 3000 s; slope > 0,
        // so the tail proves nothing and the scan brackets it in (2999.5, 3000] either way
        // (g(3000) is 0 up to rounding of the sum: the same bits both ways).
        let vx = 20.0 * (1.0 - 1.0 / 750.0);
        let full = bracket(&g_of(vx), &never).expect("a root by 3000 s");
        assert!((full.1 - 3000.0).abs() <= SCAN_STEP, "{full:?}");
        assert_eq!(bracket(&g_of(vx), &tail_of(vx)), Some(full));
        // g below 0 by less than 2·err at the step: the tail must not answer.
        let tiny = |_: f64| -1e-9;
        let loose = |_: f64, _: f64| {
            Some(Linear {
                slope: -1.0,
                err: 1e-9,
            })
        };
        let calls = std::cell::Cell::new(0);
        let counted = |s: f64| {
            calls.set(calls.get() + 1);
            tiny(s)
        };
        assert_eq!(bracket(&counted, &loose), None);
        assert_eq!(calls.get(), 7200);
    }
}
