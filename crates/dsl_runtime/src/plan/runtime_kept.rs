//! What the plan keeps by construction at a known start, checked by the engine in a phase
//! that starts on a run-time condition, where the actor's state is the run's (ASAM
//! OpenSCENARIO DSL 2.1 §8.9.9 `yaw`, §8.9.10 `orientation` relative to the road; §8.9
//! `keep_position`): a failure is an error record and a failed run, never a silent pass.
//!
//! | modifier | done by |
//! | --- | --- |
//! | `yaw(ψ)`, `orientation(yaw: ψ)` relative to the road | the engine's check of the actor's heading minus the road's where it is, at the start (at: start, all) and the end (at: end, all) (`start_yaws`) |
//! | `keep_position()` | the engine's check that the actor stands at the start (`standing_check`) |
//! | `assign_orientation(target)` (§8.8.2.5) | the same check, before the TeleportAction (`plan::position_actions`) |

use scenario::{HeadingCheck, HeadingFrom, StateCheck};

use super::planner::Planner;
use super::runtime::phase_start_check;
use super::types::{Planned, HEADING_TOLERANCE, SPEED_TOLERANCE};
use crate::error::{Error, Site};
use crate::resolve::{Arg, At, ModKind, Modifier, Val};

impl Planner<'_> {
    /// The engine's checks of the yaws relative to the road (§8.9.9 `relative_to_road`, the
    /// default measure of `yaw(…)` and `orientation(…)`: "actor yaw relative to road s-axis")
    /// that `mods` ask of `target` in a phase that starts on a run-time condition: the plan
    /// has checked each is the yaw the actor keeps (`check_orientation`: 0 along its lane, π
    /// against s, or its first phase's), but the actor's heading then is the run's (a line or
    /// a lane change cut short by an `until` leaves it turned), so the engine checks it at the
    /// phase start (at: start, all; as the action `name("check")`) and at the phase end (at:
    /// end, all; in `after`, as `name("yaw").end`), within `HEADING_TOLERANCE` (the engine's heading check, `StateCheck::heading` from the road's s-axis, as `heading` writes for the other measures). Within the phase
    /// the actor turns only with a lateral movement, which the plan refuses beside at: all.
    pub(super) fn start_yaws(
        &self,
        mods: &[Modifier],
        target: &str,
        name: &mut dyn FnMut(&str) -> String,
        (out, after): (&mut Vec<Planned>, &mut Vec<Planned>),
    ) -> Result<(), Error> {
        for m in mods.iter().filter(|m| m.kind == ModKind::Orientation) {
            let (measure, angle) = match m.name.as_str() {
                "yaw" => ("measure_by", "angle"),
                _ => ("measured_by", "yaw"),
            };
            let road = match m.arg(measure).map(Arg::eval).transpose()? {
                Some(Val::Enum(by)) => by == "relative_to_road",
                _ => true,
            };
            let Some(e) = m
                .arg(angle)
                .filter(|_| road && m.arg("relative_to").is_none())
            else {
                continue;
            };
            let angle = e.number()?;
            let check = StateCheck {
                heading: Some(HeadingCheck {
                    from: HeadingFrom::Road,
                    angle,
                    tolerance: HEADING_TOLERANCE,
                    measure: format!("relative_to_road {angle:.4} rad"),
                }),
                ..StateCheck::default()
            };
            if m.at != At::End {
                let what = (m.name.as_str(), &m.site);
                out.push(phase_start_check(
                    target,
                    what,
                    check.clone(),
                    name("check"),
                ));
            }
            if m.at != At::Start {
                let n = format!("{}.end", name("yaw"));
                after.push(self.end_check(m, target, n, check));
            }
        }
        Ok(())
    }
}

/// The engine's check that `target` stands when a phase of it that starts on a run-time
/// condition starts, for `what` written at `site`: `keep_position()` (§8.8 "keeps its
/// position": nothing beside it moves the actor, `check_keeps`, so one standing then stands
/// throughout) or `assign_orientation` (a moving actor would drive on crabwise), as the action
/// `name`. The plan's speed where it last knows the actor is not the actor's after a gap
/// action or a `change_acceleration` (it records the speed a held braking would reach), nor a
/// member of random traffic's (its driver model's), so a moving actor is an error record and a
/// failed run, never a silent pass, and a standing one is never refused.
pub(super) fn standing_check(target: &str, (what, site): (&str, &Site), name: String) -> Planned {
    let check = StateCheck {
        speed: Some((None, 0.0, SPEED_TOLERANCE)),
        ..StateCheck::default()
    };
    phase_start_check(target, (what, site), check, name)
}
