//! `acceleration(a, faster_than/slower_than/same_as: x)` at: all (ASAM OpenSCENARIO DSL 2.1
//! §8.9 `acceleration`: the actor's acceleration relative to x's) where the plan cannot read
//! x's acceleration as one value: x's planned acceleration changes within the phase, or the
//! phase starts on a run-time condition. The engine follows x then: oscsim's
//! RelativeAccelerationAction (`scenario::LongitudinalAction::RelativeAcceleration`) sets the
//! actor's acceleration to x's ± a in every step of the phase, so its speed after τ s is
//! v₀ + (v_x − v_x₀) ± a·τ. `at: start` after a run-time start is x's acceleration as the
//! engine finds it over the phase's first step, ± a, held (as the plan reads x's first piece
//! at a known start). `at: end` after a run-time start ("this constraint holds at the end of
//! the phase", §8.9.1.1.1) is x's acceleration at the phase end ± a: the engine follows x
//! (as at: all), so the actor's acceleration is x's ± a in the phase's last step whatever x
//! does; with `track: actual` "the vehicle reacts to the behavior of the referenced vehicle"
//! (§8.9.1.1.3), and no constant acceleration chosen at the start could know x's at the end.
//! With `track: projected` (x projected from its state at the phase start, §8.9.1.1.3) it is
//! x's acceleration at the start, fixed, in every `at`: read by the plan at a known start, by
//! the engine over the phase's first step after a run-time one (as at: start).
//! So is the rate of a speed change beside it at: end after a run-time start
//! (`relative_rate_at_run_time`). At a known start the plan tracks the actor along x's pieces of constant
//! planned acceleration (a linear change per piece, each within the limits); after a run-time
//! start it does not know the actor's speed (as after any change the engine works out then).

use scenario::{LongitudinalAction, PrivateAction, SpeedChange};

use super::motion::{check_accel, check_speed};
use super::planner::Planner;
use super::types::Planned;
use crate::error::Error;
use crate::resolve::{Arg, At, Modifier};

/// The pieces of x's planned acceleration over a phase: (start, end, m/s²).
type Pieces = Vec<(f64, f64, f64)>;

impl Planner<'_> {
    /// An `acceleration(…, faster_than/slower_than/same_as: x)` at: all that the engine's
    /// RelativeAccelerationAction follows (x's acceleration ± a each step): where x's
    /// acceleration changes within the phase, or the phase starts at run time (there also
    /// at: end, followed to the end, and at: start, x's acceleration at the start held). Returns x, the
    /// value added to x's acceleration, and (at a known start) the pieces of x's planned
    /// acceleration over the phase (start, end, m/s²), from which the plan tracks the actor;
    /// `None` where the plan reads x's acceleration itself (`acceleration_value`).
    pub(super) fn followed_acceleration(
        &self,
        m: &Modifier,
        (t0, len): (Option<f64>, f64),
    ) -> Result<Option<(String, f64, Pieces)>, Error> {
        let Some((e, sign)) = [
            ("faster_than", 1.0),
            ("slower_than", -1.0),
            ("same_as", 0.0),
        ]
        .into_iter()
        .find_map(|(key, sign)| m.arg(key).map(|e| (e, sign))) else {
            return Ok(None);
        };
        // After a run-time start at: start is x's acceleration at the start, held, the
        // engine's to read then; at: end x's at the phase end, which the engine meets by
        // following x to the end (at every step, so at the last).
        // Projected: x's acceleration at the start, fixed: the plan reads it at a known start,
        // the engine over the phase's first step after a run-time one (as at: start).
        if !(m.at == At::All || t0.is_none()) || (m.projected && t0.is_some()) {
            return Ok(None);
        }
        let x = self.entity_of(e)?;
        let delta = sign
            * m.arg("acceleration")
                .map(Arg::number)
                .transpose()?
                .unwrap_or(0.0);
        let Some(t) = t0 else {
            return Ok(Some((x, delta, Vec::new())));
        };
        let Ok(pieces) = self.track(&x).acceleration_pieces(t, t + len) else {
            // acceleration_value names the moment x's acceleration is not constant.
            return Ok(None);
        };
        let changes = pieces.windows(2).any(|w| (w[1].2 - w[0].2).abs() > 1e-9);
        Ok(changes.then_some((x, delta, pieces)))
    }

    /// The engine's speed change to `v1` within the phase's `len` s at the rate of `q`, an
    /// `acceleration(a, faster_than/slower_than/same_as: x)`, in a phase that starts on a
    /// run-time condition (`t` `None`): oscsim's RelativeAccelerationAction with `to_speed`,
    /// the rate |x's acceleration ± a| as the engine reads it (at: start over the phase's first
    /// step, held; at: all and at: end in every step of the change), toward v1, ending there;
    /// not reached within `len` s, the run's error then. At: end is x's acceleration "at the
    /// end of the phase" (§8.9.1.1.1), which a change running from the phase start cannot read
    /// before it is there: the change reacts to x instead (§8.9.1.1.3, `track: actual`), its
    /// rate x's then ± a in each of its steps, so in its last step x's then, and x's at the end
    /// wherever x's acceleration holds over the change (the plan's reading at a known start).
    /// With `track: projected` x's acceleration as the engine finds it over the phase's first
    /// step, fixed (§8.9.1.1.3), as at: start. `None` for anything else (a start the plan
    /// knows, an acceleration of its own).
    pub(super) fn relative_rate_at_run_time(
        &self,
        q: Option<&Modifier>,
        t: Option<f64>,
        (v1, len): (f64, f64),
    ) -> Result<Option<PrivateAction>, Error> {
        let Some(q) = q.filter(|_| t.is_none()) else {
            return Ok(None);
        };
        let Some((x, delta, _)) = self.followed_acceleration(q, (t, len))? else {
            return Ok(None);
        };
        Ok(Some(PrivateAction::Longitudinal(
            LongitudinalAction::RelativeAcceleration {
                entity_ref: x,
                value: delta,
                continuous: q.at != At::Start && !q.projected,
                to_speed: Some(Box::new(SpeedChange {
                    what: format!("{}(…) at {}", q.name, q.site.at()),
                    speed: v1,
                    of: None,
                    within: len,
                })),
                transition: None,
                ends_at_target: false,
            },
        )))
    }

    /// Plans the engine's following of x's acceleration plus `delta` for `target` over the
    /// phase from `t` (`None`: a run-time start), as the action `name`; at a known start the
    /// actor's track gains, piece by piece, x's acceleration plus `delta`.
    pub(super) fn plan_followed_acceleration(
        &mut self,
        m: &Modifier,
        target: &str,
        (t, x, delta): (Option<f64>, String, f64),
        pieces: &[(f64, f64, f64)],
        name: String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        if let Some(t) = t {
            let mut v = self.track(target).at(t).1;
            for &(p0, p1, ax) in pieces {
                check_accel(m, ax + delta)?;
                v += (ax + delta) * (p1 - p0);
                check_speed(m, v)?;
                self.track_mut(target).ramp(p0, p1, v);
            }
            self.last_v.insert(target.to_string(), v);
        }
        out.push(Planned::with_phase(
            target,
            name,
            PrivateAction::Longitudinal(LongitudinalAction::RelativeAcceleration {
                entity_ref: x,
                value: delta,
                continuous: m.at != At::Start && !m.projected,
                to_speed: None,
                transition: None,
                ends_at_target: false,
            }),
            &m.site,
        ));
        Ok(())
    }
}
