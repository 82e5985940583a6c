//! A parallel's members aligned to its `overlap:` argument (ASAM OpenSCENARIO DSL 2.1 §7.3.9
//! composition operators; the kinds in `resolve::overlap`): when each member starts, and a
//! check, once the members are planned, that their ends keep the kind's relation.
//!
//! Every member starts with the parallel, which meets `start`, `initial` (no member before the
//! first), `any` (they share the start) and the starts of `equal`, `final`, `inside`, `full`;
//! `end` starts each member that has a duration of its own (and no `until`) so that it ends
//! where the longest does, or the parallel's own duration: D − d after the parallel's start.
//! The kinds that relate ends (`equal`, `end`, `final`, `inside`, `full`) are checked on the
//! members' own ends, not cut by the parallel's own end: a member without an end of its own
//! ends with the parallel, so it meets any of them; two ends the plan knows must keep the
//! relation (1 µs), else an error at the argument naming both durations; an end at run time
//! (an `until`) beside another end the relation ties it to is an error too, as the plan cannot
//! make them keep it. `final` and `inside` end the parallel with its first member when that
//! member has an end of its own (every other ends no later).

use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Overlap, OverlapArg, Phase};

use super::types::When;

/// Two ends the plan knows that differ by less are one moment (s).
const END_TOL: f64 = 1e-6;

/// Whether `kind` relates the members' ends (they are then planned with their own ends).
pub(super) fn relates_ends(kind: Overlap) -> bool {
    matches!(
        kind,
        Overlap::Equal | Overlap::End | Overlap::Final | Overlap::Inside | Overlap::Full
    )
}

/// When each member of parallel `p` (in written order) starts, the parallel starting at
/// `start`.
pub(super) fn starts(p: &Phase, overlap: &OverlapArg, start: &When) -> Result<Vec<When>, Error> {
    let fixed = |c: &Phase| c.until.is_none().then_some(c.duration).flatten();
    if overlap.kind != Overlap::End || p.children.iter().all(|c| fixed(c).is_none()) {
        return Ok(vec![start.clone(); p.children.len()]);
    }
    let longest = p
        .children
        .iter()
        .filter_map(fixed)
        .fold(f64::NEG_INFINITY, f64::max);
    let total = p.duration.unwrap_or(longest);
    if let Some(c) = p.children.iter().find(|c| c.until.is_some()) {
        return Err(overlap.site.err(
            K::Unsatisfiable,
            format!(
                "expected the members of this parallel to end together (overlap: end), found `{}` ends at run time (its until) beside members of fixed durations: the plan cannot start them so that they end with it",
                c.path
            ),
        ));
    }
    p.children
        .iter()
        .map(|c| match fixed(c) {
            Some(d) if d > total + END_TOL => Err(overlap.site.err(
                K::Unsatisfiable,
                format!(
                    "expected the members of this parallel to end together (overlap: end) within its {total:.3} s, found `{}` lasts {d:.3} s",
                    c.path
                ),
            )),
            Some(d) => Ok(delayed(start, total - d)),
            None => Ok(start.clone()),
        })
        .collect()
}

/// `w` later by `d` s (a run-time start: each of its conditions delayed).
fn delayed(w: &When, d: f64) -> When {
    match w {
        When::At(t) => When::At(t + d),
        When::Dyn(trigger) if d > 0.0 => {
            let mut t = trigger.clone();
            for g in &mut t.condition_groups {
                for c in &mut g.conditions {
                    c.delay += d;
                }
            }
            When::Dyn(t)
        }
        other => other.clone(),
    }
}

/// One planned member: the phase, its start and its own end.
pub(super) type Member<'p> = (&'p Phase, When, When);

/// Checks the members' own ends (`members` in written order) against the kind, the parallel's
/// own end `own` (its duration or until) standing for the end of the members that end with it;
/// returns the parallel's end when the kind fixes it (`final`, `inside`: the first member's).
pub(super) fn check_ends(
    overlap: &OverlapArg,
    own: Option<&When>,
    members: &[Member<'_>],
) -> Result<Option<When>, Error> {
    let has_end = |w: &When| matches!(w, When::At(_) | When::Dyn(_));
    let first = &members[0];
    let ended: Vec<&Member<'_>> = members.iter().filter(|m| has_end(&m.2)).collect();
    let others: Vec<&Member<'_>> = ended
        .iter()
        .copied()
        .filter(|m| !std::ptr::eq(m.0, first.0))
        .collect();
    match overlap.kind {
        Overlap::Equal | Overlap::End => match own.filter(|o| has_end(o)) {
            // Every member ends with the parallel's own end.
            Some(o) => {
                for m in &ended {
                    match (m.1.time(), m.2.time(), o.time()) {
                        (Some(t0), Some(e), Some(end)) if (e - end).abs() > END_TOL => {
                            return Err(overlap.site.err(
                                K::Unsatisfiable,
                                format!(
                                    "expected every member of this parallel to end with it (overlap: {}), found `{}` lasts {:.3} s where the parallel lasts {:.3} s",
                                    overlap.kind.name(),
                                    m.0.path,
                                    e - t0,
                                    end - t0
                                ),
                            ))
                        }
                        (Some(_), Some(_), Some(_)) => {}
                        _ => return Err(run_time(overlap, m.0, "the parallel's own end")),
                    }
                }
                Ok(None)
            }
            // Or with each other.
            None => {
                together(overlap, &ended)?;
                Ok(None)
            }
        },
        // The first member ends last; without an end of its own it ends with the parallel,
        // after every other.
        Overlap::Final | Overlap::Inside if has_end(&first.2) => {
            for m in &others {
                let what = format!(
                    "`{}` to end no later than the first member `{}`",
                    m.0.path, first.0.path
                );
                tied(overlap, m, first, |e, e0| e <= e0 + END_TOL, &what)?;
            }
            Ok(Some(match own {
                Some(o) => first.2.clone().or(o.clone()),
                None => first.2.clone(),
            }))
        }
        // The first member ends first.
        Overlap::Full if has_end(&first.2) => {
            for m in &others {
                let what = format!(
                    "the first member `{}` to end no later than `{}`",
                    first.0.path, m.0.path
                );
                tied(overlap, m, first, |e, e0| e + END_TOL >= e0, &what)?;
            }
            Ok(None)
        }
        // Without an end of its own the first member ends with the parallel, when the last
        // member with an end does: every other member with an end must end then too.
        Overlap::Full => {
            together(overlap, &others)?;
            Ok(None)
        }
        Overlap::Final | Overlap::Inside | Overlap::Start | Overlap::Initial | Overlap::Any => {
            Ok(None)
        }
    }
}

/// Checks that `members` end together, each with the next.
fn together(overlap: &OverlapArg, members: &[&Member<'_>]) -> Result<(), Error> {
    for w in members.windows(2) {
        tied(
            overlap,
            w[0],
            w[1],
            |a, b| (a - b).abs() <= END_TOL,
            "the members of this parallel to end together",
        )?;
    }
    Ok(())
}

/// Checks `holds` on the ends of `a` and `b`, both known to the plan; otherwise an error
/// (expecting `what`) naming both durations, or naming the one that ends at run time.
fn tied(
    overlap: &OverlapArg,
    a: &Member<'_>,
    b: &Member<'_>,
    holds: impl Fn(f64, f64) -> bool,
    what: &str,
) -> Result<(), Error> {
    match (a.1.time(), a.2.time(), b.1.time(), b.2.time()) {
        (Some(_), Some(ea), Some(_), Some(eb)) if holds(ea, eb) => Ok(()),
        (Some(sa), Some(ea), Some(sb), Some(eb)) => Err(overlap.site.err(
            K::Unsatisfiable,
            format!(
                "expected {what} (overlap: {}), found `{}` lasts {:.3} s (to {ea:.3} s) and `{}` {:.3} s (to {eb:.3} s)",
                overlap.kind.name(),
                a.0.path,
                ea - sa,
                b.0.path,
                eb - sb
            ),
        )),
        (_, None, _, _) => Err(run_time(overlap, a.0, &format!("`{}`", b.0.path))),
        _ => Err(run_time(overlap, b.0, &format!("`{}`", a.0.path))),
    }
}

/// The error of member `m`, whose end is the engine's, tied by the kind to `other`'s end.
fn run_time(overlap: &OverlapArg, m: &Phase, other: &str) -> Error {
    overlap.site.err(
        K::Unsatisfiable,
        format!(
            "expected ends the plan knows under overlap: {}, found `{}` ends at run time beside {other}: the plan cannot keep them in that relation",
            overlap.kind.name(),
            m.path
        ),
    )
}
