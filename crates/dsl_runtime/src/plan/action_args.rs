//! Reading a §8.8 action's arguments (ASAM OpenSCENARIO DSL 2.1 §8.8.2.18 `dynamic_profile`,
//! the `rate_profile`/`rate_peak`/`duration` triple several actions share) and the transition
//! dynamics and end they lower to. Shared by the speed, lateral and position actions.

use scenario::{DynamicsDimension, DynamicsShape, StoryboardElementState, TransitionDynamics};

use super::planner::Planner;
use super::types::When;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Invoke, Phase, Val};

/// A rate profile (§8.8.2.18 `dynamic_profile`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Profile {
    /// `none`: "no specific dynamic profile".
    None,
    /// `constant`: a constant rate.
    Constant,
    /// `smooth`: a smooth (sinusoidal) change.
    Smooth,
    /// `asap`: "as soon as possible".
    Asap,
}

impl Planner<'_> {
    /// When an action of phase `p` that lasts `span` s from `t0` ends: at t0 + span when the
    /// plan knows t0, else when its engine Event `event` completes (or, without one, `span` s
    /// after the phase starts).
    pub(super) fn ends(&self, t0: Option<f64>, span: f64, event: &str, p: &Phase) -> When {
        match (t0, event) {
            (Some(t), _) => When::At(t + span),
            (None, "") => self.after(&p.path, &p.site, &When::Pending, span),
            (None, e) => When::Dyn(scenario::Trigger {
                condition_groups: vec![scenario::ConditionGroup {
                    conditions: vec![crate::trigger::event_state(
                        e,
                        StoryboardElementState::CompleteState,
                        p.site.pos.clone(),
                    )],
                }],
            }),
        }
    }
}

/// Dynamics over `time` s.
pub(super) fn timed(shape: DynamicsShape, time: f64) -> TransitionDynamics {
    TransitionDynamics {
        dynamics_shape: shape,
        dynamics_dimension: DynamicsDimension::Time,
        value: time,
        following_mode: None,
    }
}

/// Dynamics of a change by `delta` at the peak rate `rate` of a shape whose peak slope is
/// `slope`, and how long it lasts.
pub(super) fn rate(
    shape: DynamicsShape,
    rate: f64,
    delta: f64,
    slope: f64,
) -> (TransitionDynamics, f64) {
    (
        TransitionDynamics {
            dynamics_shape: shape,
            dynamics_dimension: DynamicsDimension::Rate,
            value: rate,
            following_mode: None,
        },
        delta.abs() * slope / rate,
    )
}

/// The error of a missing mandatory argument.
pub(super) fn missing(p: &Phase, inv: &Invoke, param: &str) -> Error {
    p.site.err(
        K::Argument,
        format!(
            "expected a {param} in {}(…) (a mandatory argument), found none",
            inv.action
        ),
    )
}

/// The number `param` of `inv`, if given.
pub(super) fn number(inv: &Invoke, param: &str) -> Result<Option<f64>, Error> {
    arg(&inv.args, param).map(|a| a.number()).transpose()
}

/// The number `param` of `inv`, if given, which must be above 0.
pub(super) fn positive(inv: &Invoke, param: &str) -> Result<Option<f64>, Error> {
    match arg(&inv.args, param) {
        None => Ok(None),
        Some(a) => match a.number()? {
            x if x > 0.0 => Ok(Some(x)),
            x => Err(a.site.err(
                K::Argument,
                format!("expected a {param} above 0, found {x}"),
            )),
        },
    }
}

/// The `rate_profile` of `inv` (`none` when not given).
pub(super) fn profile(inv: &Invoke) -> Result<Profile, Error> {
    let Some(a) = arg(&inv.args, "rate_profile") else {
        return Ok(Profile::None);
    };
    match a.eval()? {
        Val::Enum(m) if m == "none" => Ok(Profile::None),
        Val::Enum(m) if m == "constant" => Ok(Profile::Constant),
        Val::Enum(m) if m == "smooth" => Ok(Profile::Smooth),
        Val::Enum(m) if m == "asap" => Ok(Profile::Asap),
        _ => Err(a.site.err(
            K::Argument,
            "expected none, constant, smooth or asap, found another value",
        )),
    }
}
