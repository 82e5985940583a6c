//! `Actors/@selectTriggeringEntities` (OpenSCENARIO 1.3 §7.3.1 "ManeuverGroups and Actors"):
//! which entities made the parent Act's start trigger fire.
//!
//! The standard: "entities become actors if … [their] states … are used by the logical
//! expressions in Conditions, the Conditions using the states evaluate to true, [and are]
//! contained in ConditionGroups that evaluate to true", the condition groups being those of the
//! parent Act; with EntityRefs the actors are the union. oscsim reads this as: the
//! TriggeringEntities of the Act's ByEntityConditions for which the EntityCondition held, over
//! the condition groups whose conditions were all true, as each condition's value reached the
//! trigger when the Act started.
//!
//! Each condition reports its raw value, and a ByEntityCondition the entities it held for, at
//! every evaluation ([`TriggerReports::note`]), under its `ConditionId`, the dense index the
//! runtime gives every condition when it builds the storyboard (no hash per evaluation). A condition's `delay` shifts its value in time
//! (storyboard::delay): the trigger fires on the value of `delay` seconds before, so the
//! entities are taken from the report of that step too (the nearest report, as the delay line
//! rounds to the nearest step). An Act's start trigger is evaluated only until the Act starts,
//! so the newest report of its conditions is the one of the firing step. Only the conditions
//! of such Acts are kept, and only as far back as their delay reaches.
//!
//! The group test uses the raw values: a condition with a `falling` edge fires while its raw
//! value is false; if so no group counts as true and every group's entities are taken (a falling
//! condition holds for no entity then, so it adds none).

use std::cell::RefCell;
use std::collections::VecDeque;

use crate::storyboard::ConditionId;
use crate::world::EntityId;

/// A condition of an Act's start trigger: its runtime handle and its `delay` (s).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ConditionRef {
    /// The condition's handle: the index of its reports.
    pub id: ConditionId,
    /// Its `delay`, s.
    pub delay: f64,
}

/// One evaluation of a condition.
#[derive(Debug, Clone, PartialEq)]
struct Report {
    time: f64,
    value: bool,
    held: Vec<EntityId>,
}

/// The reports of the watched conditions, written while conditions are evaluated (they see the
/// world read-only, hence the cell).
#[derive(Debug, Clone, Default)]
pub(crate) struct TriggerReports {
    /// Per condition id: `Some` with the longest delay it is used with when its reports are
    /// kept (ids past the end are not).
    watched: Vec<Option<f64>>,
    /// Per condition id (as `watched`): its reports, oldest first.
    history: RefCell<Vec<VecDeque<Report>>>,
}

impl TriggerReports {
    /// Keeps the reports of condition `c` from now on.
    pub(crate) fn watch(&mut self, c: &ConditionRef) {
        let i = c.id.0 as usize;
        if self.watched.len() <= i {
            self.watched.resize(i + 1, None);
            self.history.get_mut().resize_with(i + 1, VecDeque::new);
        }
        let delay = self.watched[i].get_or_insert(c.delay);
        *delay = delay.max(c.delay);
    }

    /// Records an evaluation of condition `id` at simulation `time`: its raw `value` and the
    /// triggering entities it `held` for.
    pub(crate) fn note(&self, id: ConditionId, time: f64, value: bool, held: &[EntityId]) {
        let i = id.0 as usize;
        let Some(&Some(delay)) = self.watched.get(i) else {
            return;
        };
        let mut history = self.history.borrow_mut();
        // `watch` sized both alike.
        let Some(reports) = history.get_mut(i) else {
            return;
        };
        reports.push_back(Report {
            time,
            value,
            held: held.to_vec(),
        });
        // A report is needed while it may be the nearest to `now − delay` of a later lookup:
        // the front goes once the next one is itself no later than that.
        // (1e-9 s: the rounding of summed steps.)
        while reports.len() > 1 && reports[1].time <= time - delay + crate::tolerance::TIME {
            reports.pop_front();
        }
    }

    /// The report of `c` whose time is nearest to its newest report's time minus `c.delay`;
    /// `None` if the condition was never evaluated or has no report that old (then its delayed
    /// value was false).
    fn delayed(reports: &VecDeque<Report>, c: &ConditionRef) -> Option<Report> {
        let newest = reports.back()?;
        let target = newest.time - c.delay;
        let step = reports
            .len()
            .checked_sub(2)
            .map_or(0.0, |i| newest.time - reports[i].time);
        let nearest = reports
            .iter()
            .min_by(|a, b| (a.time - target).abs().total_cmp(&(b.time - target).abs()))?;
        (nearest.time <= target + 0.5 * step).then(|| nearest.clone())
    }

    /// The triggering entities of a start trigger with these condition `groups` (module doc),
    /// each once, in the order of the conditions.
    pub(crate) fn entities(&self, groups: &[Vec<ConditionRef>]) -> Vec<EntityId> {
        let history = self.history.borrow();
        let report = |c: &ConditionRef| {
            history
                .get(c.id.0 as usize)
                .and_then(|r| Self::delayed(r, c))
        };
        let firing: Vec<&Vec<ConditionRef>> = groups
            .iter()
            .filter(|g| g.iter().all(|c| report(c).is_some_and(|r| r.value)))
            .collect();
        let chosen = if firing.is_empty() {
            groups.iter().collect()
        } else {
            firing
        };
        let mut ids: Vec<EntityId> = Vec::new();
        for c in chosen.into_iter().flatten() {
            for n in report(c).map(|r| r.held).unwrap_or_default() {
                if !ids.contains(&n) {
                    ids.push(n);
                }
            }
        }
        ids
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(id: u32, delay: f64) -> ConditionRef {
        ConditionRef {
            id: ConditionId(id),
            delay,
        }
    }

    /// A condition with delay 0.2 s at dt 0.1 s: the entities come from the report 0.2 s
    /// before the newest, and only reports that may still be needed are kept.
    #[test]
    fn delayed_condition_selects_the_entities_of_its_delayed_value() {
        let c = at(1, 0.2);
        let mut reports = TriggerReports::default();
        reports.watch(&c);
        // Entities A, B, C: ids 0, 1, 2.
        let (a, b, c_) = (EntityId(0), EntityId(1), EntityId(2));
        reports.note(c.id, 0.0, true, &[a]);
        reports.note(c.id, 0.1, true, &[a, b]);
        reports.note(c.id, 0.2, false, &[]);
        // At 0.2 the value of 0.0 reaches the trigger: A.
        assert_eq!(reports.entities(&[vec![c.clone()]]), [a]);
        reports.note(c.id, 0.3, false, &[]);
        assert_eq!(reports.entities(&[vec![c.clone()]]), [a, b]);
        assert_eq!(
            reports.history.borrow()[c.id.0 as usize].len(),
            3,
            "0.0 dropped"
        );
        // An unwatched condition keeps nothing.
        let other = at(2, 0.0);
        reports.note(other.id, 0.3, true, &[c_]);
        assert!(reports.entities(&[vec![other]]).is_empty());
    }

    /// Two groups: only the one whose conditions all hold gives its entities; when none
    /// holds, every group does.
    #[test]
    fn only_true_groups_select_unless_none_is_true() {
        let (a, b, c) = (at(1, 0.0), at(2, 0.0), at(3, 0.0));
        let mut reports = TriggerReports::default();
        for x in [&a, &b, &c] {
            reports.watch(x);
        }
        // Entities A, B: ids 0, 1.
        let (ea, eb) = (EntityId(0), EntityId(1));
        reports.note(a.id, 1.0, true, &[ea]);
        reports.note(b.id, 1.0, true, &[eb]);
        reports.note(c.id, 1.0, false, &[]);
        let groups = [vec![a.clone()], vec![b.clone(), c.clone()]];
        assert_eq!(reports.entities(&groups), [ea]);
        reports.note(a.id, 1.1, false, &[]);
        reports.note(b.id, 1.1, true, &[eb]);
        reports.note(c.id, 1.1, false, &[]);
        assert_eq!(reports.entities(&groups), [eb]);
    }
}
