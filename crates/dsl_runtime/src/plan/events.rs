//! Conditions of the plan (ASAM OpenSCENARIO DSL 2.1 §7.3.10 events and event conditions):
//! a condition read by `crate::resolve` as a storyboard trigger in its event context, and a
//! phase's own end (`duration`, `until`).

use scenario::{ConditionGroup, StoryboardElementState, Trigger};

use super::planner::{unlocated, EventCtx, Planner};
use super::types::When;
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Cond, Kind, Object, Phase, Timed};
use crate::trigger::{act_state, elapsed_since, every_from_start, every_since, sim_time};

impl Planner<'_> {
    /// A condition as a trigger, used in event context `ectx`; `depth` counts nested event
    /// definitions (a declared event's context is that of the place it is used).
    pub(super) fn condition(
        &self,
        c: &Result<Cond, Error>,
        depth: usize,
        ectx: EventCtx<'_>,
    ) -> Result<Trigger, Error> {
        let c = c.as_ref().map_err(Clone::clone)?;
        Ok(Trigger {
            condition_groups: self.groups(c, depth, ectx)?,
        })
    }

    /// The OR-ed condition groups of `c`.
    fn groups(
        &self,
        c: &Cond,
        depth: usize,
        ectx: EventCtx<'_>,
    ) -> Result<Vec<ConditionGroup>, Error> {
        match c {
            Cond::Or(a, b) => {
                let mut g = self.groups(a, depth, ectx)?;
                g.extend(self.groups(b, depth, ectx)?);
                Ok(g)
            }
            Cond::And(a, b) => {
                let (ga, gb) = (self.groups(a, depth, ectx)?, self.groups(b, depth, ectx)?);
                let mut out = Vec::new();
                for x in &ga {
                    for y in &gb {
                        let mut c = x.conditions.clone();
                        c.extend(y.conditions.iter().cloned());
                        out.push(ConditionGroup { conditions: c });
                    }
                }
                Ok(out)
            }
            Cond::Event(name, site) => match name.as_deref().and_then(|n| self.event(n, depth, ectx)) {
                Some(groups) => groups,
                None => Err(site.err(
                    K::Condition,
                    "expected an event of the scenario that an emit raises or that has a condition, found none",
                )),
            },
            Cond::Measured {
                condition,
                actors,
                sampled,
                ..
            } => {
                for (path, site) in actors {
                    if !path.as_ref().is_some_and(|p| self.index.contains_key(p)) {
                        return Err(match path {
                            Some(p) if self.objects.get(p).is_some_and(|o| o == &Some(Object::Unlocated)) => unlocated(p, site),
                            _ => site.err(
                                K::UnknownActor,
                                "expected a physical object of the scenario, found another expression",
                            ),
                        });
                    }
                }
                // A sampled value is read at its event's occurrences only (§7.3.10.5): the
                // comparison AND each of the event's condition groups, the event in the
                // context of the scenario that declares the variable (the run's).
                let Some(event) = sampled else {
                    return Ok(vec![ConditionGroup {
                        conditions: vec![(**condition).clone()],
                    }]);
                };
                let mut groups = self.groups(event, depth + 1, EventCtx::Run)?;
                for g in &mut groups {
                    g.conditions.insert(0, (**condition).clone());
                }
                Ok(groups)
            }
            Cond::Timed(tm, site) => self.timed(*tm, site, ectx),
        }
    }

    /// The condition groups of an occurrence of event `name` (`None`: no such event): a phase
    /// emits it, or one of its conditions holds.
    fn event(
        &self,
        name: &str,
        depth: usize,
        ectx: EventCtx<'_>,
    ) -> Option<Result<Vec<ConditionGroup>, Error>> {
        let emits = self.emits.get(name);
        let specs = self.events.get(name);
        if emits.is_none() && specs.is_none() {
            return None;
        }
        let mut groups: Vec<ConditionGroup> = emits
            .into_iter()
            .flatten()
            .map(|(path, site)| ConditionGroup {
                conditions: vec![act_state(
                    path,
                    StoryboardElementState::StartTransition,
                    0.0,
                    site.pos.clone(),
                )],
            })
            .collect();
        for (spec, site, handler) in specs.into_iter().flatten() {
            if depth > 16 {
                return Some(Err(site.err(
                    K::Condition,
                    "expected events defined without a cycle, found one defined through itself",
                )));
            }
            // A handler's event keeps its own context wherever it is waited on; a declared
            // event takes the context of the place it is used.
            let ectx = handler.unwrap_or(ectx);
            match self.condition(spec, depth + 1, ectx) {
                Ok(t) => groups.extend(t.condition_groups),
                Err(e) => return Some(Err(e)),
            }
        }
        Some(Ok(groups))
    }

    /// The condition groups of `every(…)` or `elapsed(…)` (written at `site`) in `ectx`.
    fn timed(
        &self,
        tm: Timed,
        site: &Site,
        ectx: EventCtx<'_>,
    ) -> Result<Vec<ConditionGroup>, Error> {
        // The first moment the event occurs, after the context's start.
        let first = match tm {
            Timed::Every(ev) => ev.offset,
            Timed::Elapsed(d) => d,
        };
        match ectx {
            EventCtx::Run => Ok(vec![ConditionGroup {
                conditions: vec![match tm {
                    Timed::Every(ev) => every_from_start(
                        ev.period,
                        ev.offset,
                        self.settings.dt,
                        site.pos.clone(),
                    ),
                    // True from d on (§7.3.10.4), so a handler on it emits at every step.
                    Timed::Elapsed(d) => {
                        sim_time(d, scenario::Rule::GreaterOrEqual, site.pos.clone())
                    }
                }],
            }]),
            // From the invocation's start t0 (§7.3.10.4: the event context of an `on`
            // directive is its scenario's instance, which lives from the invocation's start):
            // at a start the plan knows, the run's clock from t0; after a run-time one, the
            // engine's clock from the step in which the invocation's Act starts (its handlers'
            // Acts start in that step, after it, so a point at t0 is seen).
            EventCtx::Invocation(within) => {
                let pos = site.pos.clone();
                let dt = self.settings.dt;
                let t0 = self
                    .phases
                    .iter()
                    .find(|ph| ph.path == within)
                    .and_then(|ph| ph.start.time());
                Ok(vec![ConditionGroup {
                    conditions: vec![match (tm, t0) {
                        (Timed::Every(ev), Some(t0)) => {
                            every_from_start(ev.period, t0 + ev.offset, dt, pos)
                        }
                        (Timed::Elapsed(d), Some(t0)) => {
                            sim_time(t0 + d, scenario::Rule::GreaterOrEqual, pos)
                        }
                        (Timed::Every(ev), None) => {
                            every_since(Some(within), ev.period, ev.offset, dt, pos)
                        }
                        (Timed::Elapsed(d), None) => elapsed_since(within, d, dt, pos),
                    }],
                }])
            }
            // Only the first occurrence can end a wait or an until.
            EventCtx::Phase { until: true, .. } if first <= 0.0 => Err(site.err(
                K::Value,
                "expected a time above 0 s in the event of an until, found 0 s (its first occurrence is the start of the phase, which would end it at once)",
            )),
            EventCtx::Phase {
                path,
                site: at,
                start,
                ..
            } => Ok(self.after(path, at, start, first).groups()),
        }
    }

    /// The own end of `p` (duration, until), given its start.
    pub(super) fn own_end(&self, p: &Phase, start: &When) -> Result<Option<When>, Error> {
        let mut end = None;
        if let Some(d) = p.duration {
            end = Some(self.after(&p.path, &p.site, start, d));
        }
        if let Some(u) = &p.until {
            let ectx = EventCtx::Phase {
                path: &p.path,
                site: &p.site,
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
