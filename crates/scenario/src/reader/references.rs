//! Checks of names the storyboard refers to (OpenSCENARIO 1.3, "Conditions" and
//! "Actions": StoryboardElementStateCondition, VariableAction, VariableCondition), run once
//! the storyboard is read.
//!
//! * StoryboardElementStateCondition: the reference — a name, optionally prefixed with the
//!   `::`-separated names of enclosing elements ([`crate::names`], OpenSCENARIO 1.1 User Guide
//!   §1.4.5, 1.3 "Naming" / "References") — must designate exactly one element of its type.
//!   It is looked for from where it is written outwards: in the subtree of the element whose
//!   trigger holds the condition (an Event, an Act; the Storyboard for its stop trigger), then
//!   in each enclosing element's, the innermost scope with a match deciding. A Maneuver taken
//!   from a catalog into several ManeuverGroups (esmini's synchronize.xosc) thus watches its own
//!   Events. The reader then writes the reference in its absolute form `::Story::…::Name`.
//! * VariableAction/VariableCondition must name a declared variable, SetMonitorAction a
//!   declared monitor.

use crate::error::{Error, ErrorKind, Result};
use crate::model::{
    ActionKind, ByValueCondition, ConditionKind, GlobalAction, MonitorDeclaration, Storyboard,
    StoryboardElementType, Trigger, VariableDeclaration,
};
use crate::names::{join_path, QualifiedName, SEPARATOR};

/// One storyboard element: type, name, parent (index into [`Tree::elements`]).
struct Element {
    kind: StoryboardElementType,
    name: String,
    parent: Option<usize>,
}

/// The storyboard's elements in depth-first document order, and the owner of each trigger in
/// the order of [`triggers_mut`] (`None`: the Storyboard's stop trigger).
#[derive(Default)]
struct Tree {
    elements: Vec<Element>,
    owners: Vec<Option<usize>>,
}

impl Tree {
    fn of(storyboard: &Storyboard) -> Self {
        let mut tree = Tree::default();
        if storyboard.stop_trigger.is_some() {
            tree.owners.push(None);
        }
        for story in &storyboard.stories {
            let s = tree.add(StoryboardElementType::Story, &story.name, None);
            for act in &story.acts {
                let a = tree.add(StoryboardElementType::Act, &act.name, Some(s));
                for trigger in [&act.start_trigger, &act.stop_trigger] {
                    if trigger.is_some() {
                        tree.owners.push(Some(a));
                    }
                }
                for group in &act.maneuver_groups {
                    let g = tree.add(StoryboardElementType::ManeuverGroup, &group.name, Some(a));
                    for m in &group.maneuvers {
                        let mi = tree.add(StoryboardElementType::Maneuver, &m.name, Some(g));
                        for e in &m.events {
                            let ei = tree.add(StoryboardElementType::Event, &e.name, Some(mi));
                            if e.start_trigger.is_some() {
                                tree.owners.push(Some(ei));
                            }
                            for action in &e.actions {
                                tree.add(StoryboardElementType::Action, &action.name, Some(ei));
                            }
                        }
                    }
                }
            }
        }
        tree
    }

    fn add(&mut self, kind: StoryboardElementType, name: &str, parent: Option<usize>) -> usize {
        self.elements.push(Element {
            kind,
            name: name.to_owned(),
            parent,
        });
        self.elements.len() - 1
    }

    /// The names from the Story down to element `i`.
    fn path(&self, i: usize) -> Vec<&str> {
        let mut path = Vec::new();
        let mut at = Some(i);
        while let Some(k) = at {
            path.push(self.elements[k].name.as_str());
            at = self.elements[k].parent;
        }
        path.reverse();
        path
    }

    /// True if `ancestor` is `i` or encloses it.
    fn within(&self, i: usize, ancestor: usize) -> bool {
        let mut at = Some(i);
        while let Some(k) = at {
            if k == ancestor {
                return true;
            }
            at = self.elements[k].parent;
        }
        false
    }

    /// The elements of type `t` that `reference`, written in a trigger of `owner`, designates:
    /// those whose name path ends with the reference, looked for in the owner's subtree first,
    /// then in each enclosing element's, then in the whole storyboard (the innermost scope with
    /// a match decides, so a Maneuver taken from a catalog several times refers to its own
    /// Events).
    fn designated(
        &self,
        owner: Option<usize>,
        t: StoryboardElementType,
        reference: &str,
    ) -> Vec<usize> {
        let q = QualifiedName::parse(reference);
        let matching: Vec<usize> = (0..self.elements.len())
            .filter(|&i| self.elements[i].kind == t && q.matches(&self.path(i)))
            .collect();
        let mut scope = owner;
        while let Some(s) = scope {
            let inside: Vec<usize> = matching
                .iter()
                .copied()
                .filter(|&i| self.within(i, s))
                .collect();
            if !inside.is_empty() {
                return inside;
            }
            scope = self.elements[s].parent;
        }
        matching
    }
}

/// The storyboard's triggers in the order of [`Tree::owners`].
fn triggers_mut(storyboard: &mut Storyboard) -> Vec<&mut Trigger> {
    let mut triggers: Vec<&mut Trigger> = storyboard.stop_trigger.iter_mut().collect();
    for story in &mut storyboard.stories {
        for act in &mut story.acts {
            triggers.extend(
                act.start_trigger
                    .iter_mut()
                    .chain(act.stop_trigger.iter_mut()),
            );
            for m in act
                .maneuver_groups
                .iter_mut()
                .flat_map(|g| &mut g.maneuvers)
            {
                triggers.extend(m.events.iter_mut().filter_map(|e| e.start_trigger.as_mut()));
            }
        }
    }
    triggers
}

/// Resolves every StoryboardElementStateCondition's reference ([`Tree::designated`]) and
/// writes it in its absolute form (`::Story::Act::…::Name`), which designates the same element
/// from anywhere, so that the runtime needs no scope. A reference designating none, or several
/// in its innermost scope, is an error at the condition's place; so is one whose element has a
/// sibling of the same type and name (its absolute form would designate both).
fn resolve_element_refs(storyboard: &mut Storyboard) -> Result<()> {
    let tree = Tree::of(storyboard);
    for (trigger, owner) in triggers_mut(storyboard).into_iter().zip(&tree.owners) {
        for c in trigger
            .condition_groups
            .iter_mut()
            .flat_map(|g| &mut g.conditions)
        {
            let ConditionKind::ByValue(ByValueCondition::StoryboardElementState {
                storyboard_element_type: t,
                storyboard_element_ref: reference,
                ..
            }) = &mut c.kind
            else {
                continue;
            };
            let found = tree.designated(*owner, *t, reference);
            let same_path = |i: usize| {
                let path = tree.path(i);
                (0..tree.elements.len())
                    .filter(|&k| tree.elements[k].kind == *t && tree.path(k) == path)
                    .collect::<Vec<_>>()
            };
            let unique = match found.as_slice() {
                [one] => same_path(*one),
                _ => found.clone(),
            };
            let kind = match unique.as_slice() {
                [one] => {
                    *reference = format!("{SEPARATOR}{}", join_path(&tree.path(*one)));
                    continue;
                }
                [] => ErrorKind::UnknownStoryboardElement {
                    element_type: *t,
                    name: reference.clone(),
                },
                several => ErrorKind::AmbiguousStoryboardElement {
                    element_type: *t,
                    name: reference.clone(),
                    candidates: several.iter().map(|&i| join_path(&tree.path(i))).collect(),
                },
            };
            return Err(Error::new(kind, c.pos.clone()));
        }
    }
    Ok(())
}

/// Resolves every StoryboardElementStateCondition ([`resolve_element_refs`]); checks every
/// VariableCondition, VariableAction and SetMonitorAction.
pub(crate) fn check_references(
    storyboard: &mut Storyboard,
    variables: &[VariableDeclaration],
    monitors: &[MonitorDeclaration],
) -> Result<()> {
    resolve_element_refs(storyboard)?;
    let variable = |name: &str| variables.iter().any(|v| v.name == name);
    let mut triggers: Vec<&Trigger> = storyboard.stop_trigger.iter().collect();
    let mut actions: Vec<_> = storyboard.init.actions.iter().collect();
    for story in &storyboard.stories {
        for act in &story.acts {
            triggers.extend(act.start_trigger.iter().chain(act.stop_trigger.iter()));
            for m in act.maneuver_groups.iter().flat_map(|g| &g.maneuvers) {
                for e in &m.events {
                    triggers.extend(e.start_trigger.iter());
                    actions.extend(e.actions.iter());
                }
            }
        }
    }
    for c in triggers
        .iter()
        .flat_map(|t| &t.condition_groups)
        .flat_map(|g| &g.conditions)
    {
        match &c.kind {
            ConditionKind::ByValue(ByValueCondition::Variable { variable_ref, .. })
                if !variable(variable_ref) =>
            {
                return Err(Error::new(
                    ErrorKind::UnknownVariable {
                        name: variable_ref.clone(),
                    },
                    c.pos.clone(),
                ));
            }
            _ => {}
        }
    }
    for a in actions {
        match &a.kind {
            ActionKind::Global(GlobalAction::Variable { variable_ref, .. })
                if !variable(variable_ref) =>
            {
                let name = variable_ref.clone();
                return Err(Error::new(
                    ErrorKind::UnknownVariable { name },
                    a.pos.clone(),
                ));
            }
            ActionKind::Global(GlobalAction::SetMonitor { monitor_ref, .. })
                if !monitors.iter().any(|m| &m.name == monitor_ref) =>
            {
                let name = monitor_ref.clone();
                return Err(Error::new(
                    ErrorKind::UnknownMonitor { name },
                    a.pos.clone(),
                ));
            }
            _ => {}
        }
    }
    Ok(())
}
