//! Scheduling one phase and its members (ASAM OpenSCENARIO DSL 2.1 §7.3.9 composition
//! semantics): when it starts and ends, and the storyboard phases it becomes (see the parent
//! module's doc for the rules).

use scenario::{ConditionGroup, StoryboardElementState, Trigger};

use super::planner::{no_end, Planner};
use super::types::{PhasePlan, When};
use crate::error::Error;
use crate::resolve::{arg, At, Invoke, Kind, ModKind, Phase};
use crate::trigger::act_state;

impl Planner<'_> {
    pub(super) fn schedule(
        &mut self,
        p: &Phase,
        start: When,
        inherit: Option<When>,
        cap: Option<When>,
        len_hint: Option<f64>,
    ) -> Result<When, Error> {
        let own = self.own_end(p, &start)?;
        // The latest end: an enclosing composition's own end (duration, until) stops its
        // running member too.
        let capped = |w: When| match (&cap, w) {
            // Filled in with the enclosing parallel's end, which is capped itself.
            (_, When::Pending) => When::Pending,
            (Some(c), w) => w.or(c.clone()),
            (None, w) => w,
        };
        let first_index = self.phases.len();
        let end = match &p.kind {
            Kind::Invoke(_) | Kind::Wait => {
                let mut actions = Vec::new();
                let mut persist = Vec::new();
                let mut after = Vec::new();
                let mut derived = None;
                if let Kind::Invoke(inv) = &p.kind {
                    let cap = own.as_ref().or(inherit.as_ref()).and_then(When::time);
                    let len = p.duration.or(len_hint);
                    let ms = &inv.modifiers;
                    let t0 = start.time();
                    derived = self.in_actor_view(inv, ms, |s| {
                        let derived = s.plan_invoke(
                            p,
                            inv,
                            ms,
                            t0,
                            cap,
                            len,
                            &mut actions,
                            &mut persist,
                            &mut after,
                        )?;
                        // A read of a lane the engine sets, by this phase (`lane_only`).
                        s.lane_blind_error()?;
                        Ok(derived)
                    })?;
                }
                // An invocation's own `duration:` argument is the action's duration (§8.8:
                // `osc_action.duration`), so the phase lasts it: an action that completes
                // sooner (`assign_position`, `assign_speed`: at once) leaves its actor going
                // on as it left it until then; one that would complete later is cut there.
                let derived = match &p.kind {
                    Kind::Invoke(inv) if arg(&inv.args, "duration").is_some() => None,
                    _ => derived,
                };
                let end = match (own, derived, inherit) {
                    // An action that ends on its own ends its phase then, unless the phase's
                    // own end comes first.
                    (Some(o), d, i) => d
                        .map_or(o.clone(), |d| o.or(d))
                        .or(i.unwrap_or(When::Pending)),
                    (None, Some(d), i) => d.or(i.unwrap_or(When::Pending)),
                    (None, None, Some(i)) => i,
                    (None, None, None) if self.settings.open_end => When::Never,
                    (None, None, None) => return Err(no_end(p)),
                };
                let end = capped(end);
                // An action that ends as it starts (assign_speed): its Act completes in its
                // first step, with its actions.
                let instant = matches!(p.kind, Kind::Invoke(_))
                    && matches!((&start, &end), (When::At(a), When::At(b)) if a == b);
                self.phases.push(PhasePlan {
                    path: p.path.clone(),
                    site: p.site.clone(),
                    start,
                    end: end.clone(),
                    actions,
                    persist,
                    after,
                    hold: !instant,
                    command: None,
                });
                return Ok(end);
            }
            Kind::Emit(event) => return Ok(self.instant(p, start, Some(("emit", event.clone())))),
            // A method defined by an expression has no side effect: no command to the host.
            Kind::Call(c) => {
                let command = c.external.then(|| ("call", c.content.clone()));
                return Ok(self.instant(p, start, command));
            }
            Kind::Serial | Kind::OneOf(_) => {
                let mut cur = start.clone();
                let n = p.children.len();
                let own_cap = match (&own, &cap) {
                    (Some(o), Some(c)) => Some(o.clone().or(c.clone())),
                    (o, c) => o.clone().or(c.clone()),
                };
                for (i, c) in p.children.iter().enumerate() {
                    // Members that would start when the serial has ended never run.
                    if let (When::At(t), Some(When::At(end))) = (&cur, &own_cap) {
                        if i > 0 && *t >= *end {
                            break;
                        }
                    }
                    let inh = if i + 1 == n {
                        match (&own, &inherit) {
                            (Some(o), Some(i)) => Some(o.clone().or(i.clone())),
                            (Some(o), None) => Some(o.clone()),
                            (None, i) => i.clone(),
                        }
                    } else {
                        None
                    };
                    let hint = match p.kind {
                        Kind::OneOf(_) => p.duration.or(len_hint),
                        _ => None,
                    };
                    if let (Kind::Serial, Some(before)) = (&p.kind, i.checked_sub(1)) {
                        self.serial_before
                            .insert(c.path.clone(), p.children[before].path.clone());
                    }
                    cur = self.schedule(c, cur.clone(), inh, own_cap.clone(), hint)?;
                    // After a run-time end, the next member starts on the state of the one that
                    // ended (and only while this serial runs, which its own end may stop).
                    let mut ended = vec![act_state(
                        &c.path,
                        StoryboardElementState::CompleteState,
                        0.0,
                        c.site.pos.clone(),
                    )];
                    if i + 1 < n {
                        if matches!(own_cap, Some(When::Dyn(_))) {
                            ended.push(act_state(
                                &p.path,
                                StoryboardElementState::RunningState,
                                0.0,
                                p.site.pos.clone(),
                            ));
                        }
                        cur = match cur {
                            When::At(t) => When::At(t),
                            When::Dyn(_) => When::Dyn(Trigger {
                                condition_groups: vec![ConditionGroup { conditions: ended }],
                            }),
                            When::Never | When::Pending => return Err(no_end(c)),
                        };
                    } else if matches!(cur, When::Dyn(_)) {
                        // Ends with its last member: on that member's state (its condition
                        // could hold before the member runs).
                        ended.truncate(1);
                        cur = When::Dyn(Trigger {
                            condition_groups: vec![ConditionGroup { conditions: ended }],
                        });
                    }
                }
                capped(match own {
                    Some(o) => o,
                    None => cur,
                })
            }
            Kind::Parallel(overlap) => {
                // Members planned (and written) first: those whose motion others refer to, and
                // those that end on their own, so that members ending with the parallel see
                // their end in the same step.
                let levels = relative_levels(&p.children);
                let mut order: Vec<(usize, &Phase)> = p.children.iter().enumerate().collect();
                order.sort_by_key(|&(i, c)| (levels[i], c.duration.is_none() && c.until.is_none()));
                // `overlap:` (plan::overlap): when each member starts; a kind that relates the
                // ends plans each member with its own end, checked below.
                let starts = match overlap {
                    Some(o) => super::overlap::starts(p, o, &start)?,
                    None => vec![start.clone(); p.children.len()],
                };
                let own_ends = overlap
                    .as_ref()
                    .is_some_and(|o| super::overlap::relates_ends(o.kind));
                let inh = match (&own, &inherit) {
                    _ if own_ends => Some(When::Pending),
                    (Some(o), Some(i)) => Some(o.clone().or(i.clone())),
                    (Some(o), None) => Some(o.clone()),
                    (None, _) => Some(When::Pending),
                };
                let own_cap = match (&own, &cap) {
                    _ if own_ends => cap.clone(),
                    (Some(o), Some(c)) => Some(o.clone().or(c.clone())),
                    (o, c) => o.clone().or(c.clone()),
                };
                let mut ends = Vec::new();
                let mut members = vec![None; p.children.len()];
                for (i, c) in order {
                    let e = self.schedule(
                        c,
                        starts[i].clone(),
                        inh.clone(),
                        own_cap.clone(),
                        p.duration.or(len_hint),
                    )?;
                    members[i] = Some((c, starts[i].clone(), e.clone()));
                    ends.push((c, e));
                }
                let fixed = match overlap {
                    Some(o) => {
                        // Every member was planned (members[i] set in the loop above).
                        let members: Vec<_> = members.into_iter().flatten().collect();
                        super::overlap::check_ends(o, own.as_ref(), &members)?
                    }
                    None => None,
                };
                capped(match fixed.or(own) {
                    Some(o) => o,
                    None => {
                        let with_end: Vec<&(&Phase, When)> =
                            ends.iter().filter(|(_, e)| *e != When::Pending).collect();
                        if with_end.iter().any(|(_, e)| *e == When::Never) {
                            When::Never
                        } else if with_end.is_empty() {
                            match inherit {
                                Some(i) => i,
                                None if self.settings.open_end => When::Never,
                                None => return Err(no_end(p)),
                            }
                        } else if with_end.iter().all(|(_, e)| matches!(e, When::At(_))) {
                            When::At(
                                with_end
                                    .iter()
                                    .filter_map(|(_, e)| e.time())
                                    .fold(f64::NEG_INFINITY, f64::max),
                            )
                        } else {
                            When::Dyn(Trigger {
                                condition_groups: vec![ConditionGroup {
                                    conditions: with_end
                                        .iter()
                                        .map(|(c, _)| {
                                            act_state(
                                                &c.path,
                                                StoryboardElementState::CompleteState,
                                                0.0,
                                                c.site.pos.clone(),
                                            )
                                        })
                                        .collect(),
                                }],
                            })
                        }
                    }
                })
            }
        };
        // Members that end with this composition.
        if end != When::Pending {
            for ph in &mut self.phases[first_index..] {
                if ph.end == When::Pending {
                    ph.end = end.clone();
                }
            }
        }
        self.phases.push(PhasePlan {
            path: p.path.clone(),
            site: p.site.clone(),
            start,
            end: end.clone(),
            actions: Vec::new(),
            persist: Vec::new(),
            after: Vec::new(),
            hold: true,
            command: None,
        });
        Ok(end)
    }

    /// An instant phase with its `command`, if any: its Act starts and, with nothing to do but
    /// the command, completes in its step. Returns its end (its start).
    fn instant(&mut self, p: &Phase, start: When, command: Option<(&'static str, String)>) -> When {
        self.phases.push(PhasePlan {
            path: p.path.clone(),
            site: p.site.clone(),
            start: start.clone(),
            end: When::Never,
            actions: Vec::new(),
            persist: Vec::new(),
            after: Vec::new(),
            hold: false,
            command,
        });
        start
    }
}

/// The keys of the order in which a parallel plans its `members` (a stable sort: members of
/// one key keep their written order): [`relative_end`], raised past each member with a
/// nonzero key whose actor (or the actor of an invocation in it) a relation in the member
/// refers to, so that a chain is planned from its head whatever the written order: car
/// `lane(right_of: ego)` after ego `lane(same_as: npc)`, whose lane changes car's relation
/// reads (`held_relation`). A cycle keeps the order of the last round (rounds stop at the
/// members' count).
fn relative_levels(members: &[Phase]) -> Vec<usize> {
    let mut level: Vec<usize> = members.iter().map(|c| relative_end(c).into()).collect();
    let (mut actors, mut refs) = (Vec::new(), Vec::new());
    for c in members {
        let (mut a, mut r) = (Vec::new(), Vec::new());
        invocations(c, &mut |inv| {
            a.push(inv.actor.as_str());
            for m in &inv.modifiers {
                r.extend(REFERENCES.iter().filter_map(|k| m.arg(k)?.path.as_deref()));
            }
        });
        actors.push(a);
        refs.push(r);
    }
    let n = members.len();
    for _ in 0..n {
        let mut raised = false;
        for i in 0..n {
            for j in 0..n {
                let follows = refs[i].iter().any(|x| actors[j].contains(x));
                if i != j && level[j] > 0 && level[i] <= level[j] && follows {
                    level[i] = level[j] + 1;
                    raised = true;
                }
            }
        }
        if !raised {
            break;
        }
    }
    level
}

/// The arguments of a modifier that name another actor it relates the actor to.
const REFERENCES: [&str; 8] = [
    "same_as",
    "side_of",
    "left_of",
    "right_of",
    "ahead_of",
    "behind",
    "faster_than",
    "slower_than",
];

/// Calls `f` with each invocation in `p` (`p` itself, or its members at any depth).
fn invocations<'a>(p: &'a Phase, f: &mut dyn FnMut(&'a Invoke)) {
    match &p.kind {
        Kind::Invoke(inv) => f(inv),
        _ => p.children.iter().for_each(|c| invocations(c, f)),
    }
}

/// 1 for an invocation with a `position(…, at: end)`, a `lateral(…)` beside another actor at:
/// end or all (x's sideways moves in the phase, `lateral_follow`), a speed at the end relative to another actor (`speed(same_as/faster_than/
/// slower_than: x, at: end)`, `change_speed` so: read where the plan has that actor at the
/// end), or an acceleration relative to another actor (`acceleration(…, same_as/faster_than/
/// slower_than: x)`, any `at`: x's pieces of planned acceleration over the phase; planned
/// before x, x read as keeping its speed and the actor kept its own, issue 27), else 0: the
/// order in which a parallel plans its members (a stable sort: members of one key keep their
/// written order).
fn relative_end(p: &Phase) -> u8 {
    let any_of =
        |m: &crate::resolve::Modifier, keys: &[&str]| keys.iter().any(|k| m.arg(k).is_some());
    let relative = |m: &crate::resolve::Modifier| match m.kind {
        ModKind::Position => {
            m.at != At::Start && any_of(m, &["ahead_of", "behind"]) || m.at == At::End
        }
        // x's lane over the phase (`held_relation`).
        ModKind::Lane => {
            m.at == At::All && any_of(m, &["same_as", "side_of", "left_of", "right_of"])
        }
        ModKind::Lateral => m.at != At::Start && any_of(m, &["side_of", "left_of", "right_of"]),
        ModKind::Speed | ModKind::ChangeSpeed => {
            (m.at == At::End || m.kind == ModKind::ChangeSpeed)
                && any_of(m, &["same_as", "faster_than", "slower_than"])
        }
        ModKind::Acceleration => any_of(m, &["same_as", "faster_than", "slower_than"]),
        _ => false,
    };
    matches!(&p.kind, Kind::Invoke(inv) if inv.modifiers.iter().any(relative)) as u8
}
