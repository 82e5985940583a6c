//! The line between the plan and the run (ASAM OpenSCENARIO DSL 2.1 §7.3.9 `until`, `wait`;
//! §8.9 `at: start`): a phase that starts on a run-time condition starts at a moment the plan
//! does not know, so what the plan would check against its tracks at a known start is checked
//! by the engine when the phase starts (oscsim's state check, `scenario::StateCheck`; a
//! failure is an error record in the event log and a failed run, never a silent change).
//!
//! | at the start of a phase that starts on a run-time condition | done by |
//! | --- | --- |
//! | `lane(n [, from: left])` (at: start, all) | the engine's check: the actor in that driving lane |
//! | `position(d)` (at: start, all) | the engine's check: the actor at s = d (0.5 m) |
//! | `position(d, ahead_of/behind: x)` (at: start, all) | the engine's check: x at ∓d along the road (0.5 m) |
//! | `lateral(d, measure_by, side)` in its lane (at: start, all) | the engine's check: the offset from the lane's centre (1 cm) |
//!
//! The engine measures lanes and s on the road the actor is on, so on a plan over several
//! roads (`crate::road`) the lane and position checks are errors: the road the actor is on at
//! a run-time start is not known before the run.
//!
//! Lanes are numbered (and lane widths taken) where the plan last knows the actor: a road whose
//! lanes change between there and the run-time start may number them otherwise. Forms whose
//! value depends on another actor's planned lane or speed (`lane(same_as: x)`, `position(time:
//! t, …)`) are errors there: after a run-time start the plan does not know that actor's state.

use scenario::{PrivateAction, StateCheck};

use super::lateral;
use super::planner::Planner;
use super::types::{Planned, When, LATERAL_TOLERANCE, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Arg, ModKind, Modifier, Val};

impl Planner<'_> {
    /// The engine's check of `m` (a `lane`, `position` or `lateral` constraint at the start of
    /// a phase of `target` that starts on a run-time condition), as the action `name`.
    pub(super) fn start_check(
        &self,
        m: &Modifier,
        target: &str,
        name: String,
    ) -> Result<Planned, Error> {
        let t = self.last_known();
        let what = format!("{}(…) at {}", m.name, m.site.at());
        let relative = |key: &str| {
            m.site.err(
                K::Unsupported,
                format!("expected {}(…) without `{key}:` at the start of a phase that starts on a run-time condition, found it (the plan does not know the other actor's state then; not run yet)", m.name),
            )
        };
        let mut check = StateCheck {
            what,
            lane: None,
            s: None,
            offset: None,
            gap: None,
        };
        if matches!(m.kind, ModKind::Lane | ModKind::Position) && self.road.ids().len() > 1 {
            return Err(m.site.err(
                K::Unsupported,
                format!(
                    "expected {}(…) at the start of a phase that starts on a run-time condition on a plan over one road, found roads {} (the road the actor is on then is not known before the run)",
                    m.name,
                    self.road.ids().join(", ")
                ),
            ));
        }
        match m.kind {
            ModKind::Lane => {
                for key in ["same_as", "side_of", "left_of", "right_of"] {
                    if m.arg(key).is_some() {
                        return Err(relative(key));
                    }
                }
                let n = m
                    .arg("lane")
                    .map(Arg::number)
                    .transpose()?
                    .map_or(1, |x| x.round() as i64);
                let from_left = matches!(m.arg("from").map(Arg::eval).transpose()?, Some(Val::Enum(f)) if f == "left");
                let lane = self
                    .road
                    .numbered(n, from_left, self.s_at(target, t), self.walks(target))
                    .ok_or_else(|| {
                        m.site.err(
                            K::Unsatisfiable,
                            format!("expected a driving lane {n} on road {}, found none", self.road.id()),
                        )
                    })?;
                check.lane = Some((self.road.id().to_string(), lane));
            }
            ModKind::Position => {
                if m.arg("time").is_some() {
                    return Err(relative("time"));
                }
                let (x, sign, d) = self.position_target(m, target, t)?;
                match x {
                    // x − actor = −sign·d (ahead_of: the actor d ahead of x).
                    Some(x) => check.gap = Some((x, -sign * d, POSITION_TOLERANCE)),
                    None => check.s = Some((d, POSITION_TOLERANCE)),
                }
            }
            ModKind::Lateral => {
                if lateral::reference(m)?.is_some() {
                    return Err(relative("side_of"));
                }
                let s = self.s_at(target, t);
                let w = self.road.lane_width(self.track(target).lane(t), s);
                let o = lateral::lane_offset(m, w, self.width(target))?;
                check.offset = Some((o, LATERAL_TOLERANCE));
            }
            _ => {
                return Err(m.site.err(
                    K::Unsupported,
                    format!("expected lane, position or lateral at the start of a phase that starts on a run-time condition, found {}(…)", m.name),
                ))
            }
        }
        Ok(Planned {
            entity: target.to_string(),
            at: None,
            name,
            action: PrivateAction::Check(Box::new(check)),
            site: m.site.clone(),
        })
    }

    /// The latest moment the plan knows (s): the latest known start or end of a phase
    /// planned so far.
    fn last_known(&self) -> f64 {
        self.phases
            .iter()
            .flat_map(|p| [&p.start, &p.end])
            .filter_map(When::time)
            .fold(0.0, f64::max)
    }
}
