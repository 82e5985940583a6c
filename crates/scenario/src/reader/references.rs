//! Checks of names the storyboard refers to (OpenSCENARIO 1.3, "Conditions" and
//! "Actions": StoryboardElementStateCondition, VariableAction, VariableCondition):
//! a StoryboardElementStateCondition must name a storyboard element of its type,
//! VariableAction/VariableCondition a declared variable, SetMonitorAction a declared monitor. Run once the storyboard is read.

use std::collections::HashSet;

use crate::error::{Error, ErrorKind, Result};
use crate::model::{
    ActionKind, ByValueCondition, ConditionKind, GlobalAction, MonitorDeclaration, Storyboard,
    StoryboardElementType, Trigger, VariableDeclaration,
};

/// Names of the storyboard's elements, by type.
#[derive(Default)]
struct Names<'s> {
    by_type: HashSet<(StoryboardElementType, &'s str)>,
}

impl<'s> Names<'s> {
    fn of(storyboard: &'s Storyboard) -> Self {
        let mut names = Names::default();
        let mut add = |t, n: &'s str| {
            names.by_type.insert((t, n));
        };
        for story in &storyboard.stories {
            add(StoryboardElementType::Story, &story.name);
            for act in &story.acts {
                add(StoryboardElementType::Act, &act.name);
                for group in &act.maneuver_groups {
                    add(StoryboardElementType::ManeuverGroup, &group.name);
                    for m in &group.maneuvers {
                        add(StoryboardElementType::Maneuver, &m.name);
                        for e in &m.events {
                            add(StoryboardElementType::Event, &e.name);
                            for a in &e.actions {
                                add(StoryboardElementType::Action, &a.name);
                            }
                        }
                    }
                }
            }
        }
        names
    }
}

/// Checks every StoryboardElementStateCondition, VariableCondition and VariableAction.
pub(crate) fn check_references(
    storyboard: &Storyboard,
    variables: &[VariableDeclaration],
    monitors: &[MonitorDeclaration],
) -> Result<()> {
    let names = Names::of(storyboard);
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
            ConditionKind::ByValue(ByValueCondition::StoryboardElementState {
                storyboard_element_type,
                storyboard_element_ref,
                ..
            }) if !names
                .by_type
                .contains(&(*storyboard_element_type, storyboard_element_ref.as_str())) =>
            {
                return Err(Error::new(
                    ErrorKind::UnknownStoryboardElement {
                        element_type: *storyboard_element_type,
                        name: storyboard_element_ref.clone(),
                    },
                    c.pos.clone(),
                ));
            }
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
