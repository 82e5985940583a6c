//! Conditions of the plan (ASAM OpenSCENARIO DSL 2.1 §7.3.10 events and event conditions):
//! a DSL condition or event as a storyboard trigger in its event context, and a phase's own
//! end (`duration`, `until`).

use dsl::semantics::hir::{Expr, Span};
use scenario::{ConditionGroup, StoryboardElementState, Trigger};

use super::{Planner, When};
use crate::condition::{act_state, every_from_start, sim_time, trigger, Names, Timed};
use crate::error::{Error, ErrorKind as K};
use crate::phase::{Kind, Phase};

/// Where an event specification is used: what its event context starts with (ASAM
/// OpenSCENARIO DSL 2.1 §7.3.10.4).
#[derive(Debug, Clone, Copy)]
pub(super) enum EventCtx<'w> {
    /// An `on` handler of the scenario: the start of the run.
    Run,
    /// The `wait` or `until` of a phase: the phase's start.
    Phase {
        path: &'w str,
        span: Span,
        start: &'w When,
        until: bool,
    },
}

impl Planner<'_, '_> {
    /// A DSL condition as a trigger, used in event context `ectx`; `depth` counts nested event
    /// definitions (a declared event's context is that of the place it is used).
    pub(super) fn condition(
        &self,
        e: &Expr,
        depth: usize,
        ectx: EventCtx<'_>,
    ) -> Result<Trigger, Error> {
        let index = &self.index;
        let entity = |path: &str| index.contains_key(path).then(|| path.to_string());
        let event = |name: &str| -> Option<Result<Vec<ConditionGroup>, Error>> {
            let emits = self.emits.get(name);
            let specs = self.events.get(name);
            if emits.is_none() && specs.is_none() {
                return None;
            }
            // The event occurs when a phase emits it or one of its conditions holds.
            let mut groups: Vec<ConditionGroup> = emits
                .into_iter()
                .flatten()
                .map(|(path, span)| ConditionGroup {
                    conditions: vec![act_state(
                        path,
                        StoryboardElementState::StartTransition,
                        0.0,
                        self.ctx.files.pos(*span),
                    )],
                })
                .collect();
            for (spec, handler) in specs.into_iter().flatten() {
                if depth > 16 {
                    return Some(Err(self.ctx.files.err(
                        K::Condition,
                        spec.span,
                        "expected events defined without a cycle, found one defined through itself",
                    )));
                }
                // A handler's event counts from the run's start wherever it is waited on; a
                // declared event takes the context of the place it is used.
                let ectx = if *handler { EventCtx::Run } else { ectx };
                match self.condition(spec, depth + 1, ectx) {
                    Ok(t) => groups.extend(t.condition_groups),
                    Err(e) => return Some(Err(e)),
                }
            }
            Some(Ok(groups))
        };
        let timed = |tm: Timed, span: Span| -> Result<Vec<ConditionGroup>, Error> {
            // The first moment the event occurs, after the context's start.
            let first = match tm {
                Timed::Every(ev) => ev.offset,
                Timed::Elapsed(d) => d,
            };
            match ectx {
                EventCtx::Run => Ok(vec![ConditionGroup {
                    conditions: vec![match tm {
                        Timed::Every(ev) => {
                            every_from_start(ev, self.settings.dt, self.ctx.files.pos(span))
                        }
                        // True from d on (§7.3.10.4), so a handler on it emits at every step.
                        Timed::Elapsed(d) => sim_time(
                            d,
                            scenario::Rule::GreaterOrEqual,
                            self.ctx.files.pos(span),
                        ),
                    }],
                }]),
                // Only the first occurrence can end a wait or an until.
                EventCtx::Phase { until: true, .. } if first <= 0.0 => Err(self.ctx.files.err(
                    K::Value,
                    span,
                    "expected a time above 0 s in the event of an until, found 0 s (its first occurrence is the start of the phase, which would end it at once)",
                )),
                EventCtx::Phase {
                    path,
                    span: at,
                    start,
                    ..
                } => Ok(self.after(path, at, start, first).groups()),
            }
        };
        trigger(
            self.ctx,
            e,
            &Names {
                entity: &entity,
                event: &event,
                timed: &timed,
            },
        )
    }

    /// The own end of `p` (duration, until), given its start.
    pub(super) fn own_end(&self, p: &Phase<'_>, start: &When) -> Result<Option<When>, Error> {
        let mut end = None;
        if let Some(d) = p.duration {
            end = Some(self.after(&p.path, p.span, start, d));
        }
        if let Some(u) = p.until {
            let ectx = EventCtx::Phase {
                path: &p.path,
                span: p.span,
                start,
                until: !matches!(p.kind, Kind::Wait),
            };
            let w = When::Dyn(self.condition(u, 0, ectx)?);
            end = Some(match end {
                Some(e) => e.or(w),
                None => w,
            });
        }
        Ok(end)
    }
}
