//! `acceleration(a, faster_than/slower_than/same_as: x)` at: all (ASAM OpenSCENARIO DSL 2.1
//! §8.9 `acceleration`: the actor's acceleration relative to x's) where the plan cannot read
//! x's acceleration as one value: x's planned acceleration changes within the phase, or the
//! phase starts on a run-time condition. The engine follows x then: oscsim's
//! RelativeAccelerationAction (`scenario::LongitudinalAction::RelativeAcceleration`) sets the
//! actor's acceleration to x's ± a in every step of the phase, so its speed after τ s is
//! v₀ + (v_x − v_x₀) ± a·τ. `at: start` after a run-time start is x's acceleration as the
//! engine finds it over the phase's first step, ± a, held (as the plan reads x's first piece
//! at a known start). At a known start the plan tracks the actor along x's pieces of constant
//! planned acceleration (a linear change per piece, each within the limits); after a run-time
//! start it does not know the actor's speed (as after any change the engine works out then).

use scenario::{LongitudinalAction, PrivateAction};

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
    /// at: start, x's acceleration at the start held). Returns x, the
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
        // at: start after a run-time start: x's acceleration at the start, held, is the
        // engine's to read then; at: end is x's at a moment not yet come.
        let runtime_start = m.at == At::Start && t0.is_none();
        if !(m.at == At::All || runtime_start) || m.projected {
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
                continuous: m.at == At::All,
            }),
            &m.site,
        ));
        Ok(())
    }
}
