//! The element store: building it from a [`StoryboardDesc`] (OpenSCENARIO 1.3 §7.2.1 tree,
//! §7.6 triggers) and the per-element runtime status.
//!
//! Elements are stored flat in depth-first document order (storyboard first, then Init and its
//! actions, then each story's subtree); [`ElementId`] is the index. Triggers live in a separate
//! list so that evaluating one can borrow the element states for `StoryboardElementStateCondition`
//! while the trigger's own edge and delay memory is updated.

use super::desc::{
    ActDesc, ActionDesc, EventDesc, ManeuverDesc, ManeuverGroupDesc, StoryDesc, StoryboardDesc,
    TriggerDesc,
};
use super::element::{ActionId, ElementId, ElementKind};
use super::error::{ErrorKind, StoryboardError, TriggerRole};
use super::priority::Priority;
use super::state::{ElementState, Transition};
use super::trigger::TriggerState;

/// The fixed description of one element.
#[derive(Debug, Clone)]
pub(crate) struct Node {
    pub(crate) kind: ElementKind,
    pub(crate) name: String,
    pub(crate) parent: Option<ElementId>,
    pub(crate) children: Vec<ElementId>,
    /// Index into the storyboard's triggers.
    pub(crate) start_trigger: Option<usize>,
    /// Index into the storyboard's triggers.
    pub(crate) stop_trigger: Option<usize>,
    /// Events and ManeuverGroups: `maximumExecutionCount`; 1 for the other kinds.
    pub(crate) maximum_execution_count: u32,
    /// Events: `priority`; `Parallel` (unused) for the other kinds.
    pub(crate) priority: Priority,
    /// Actions: the runtime's handle.
    pub(crate) action: Option<ActionId>,
}

/// The changing status of one element.
#[derive(Debug, Clone)]
pub(crate) struct Status {
    pub(crate) state: ElementState,
    /// Start plus skip transitions since the parent last (re)started it (§8.4.2.1).
    pub(crate) executions: u32,
    /// Per transition (indexed by [`Transition::index`]): the step in which it last happened.
    pub(crate) last_step: [Option<u64>; 4],
}

impl Status {
    pub(crate) const INITIAL: Status = Status {
        state: ElementState::Init,
        executions: 0,
        last_step: [None; 4],
    };

    /// The step in which `transition` last happened.
    pub(crate) fn last(&self, transition: Transition) -> Option<u64> {
        self.last_step[transition.index()]
    }
}

/// Collects nodes and triggers while walking the description.
#[derive(Default)]
struct Builder {
    nodes: Vec<Node>,
    triggers: Vec<TriggerState>,
}

impl Builder {
    fn add(
        &mut self,
        kind: ElementKind,
        name: &str,
        parent: Option<ElementId>,
    ) -> Result<ElementId, StoryboardError> {
        let Ok(index) = u32::try_from(self.nodes.len()) else {
            return Err(StoryboardError::new(ErrorKind::TooManyElements {
                found: self.nodes.len(),
            }));
        };
        let id = ElementId(index);
        self.nodes.push(Node {
            kind,
            name: name.to_owned(),
            parent,
            children: Vec::new(),
            start_trigger: None,
            stop_trigger: None,
            maximum_execution_count: 1,
            priority: Priority::Parallel,
            action: None,
        });
        if let Some(parent) = parent {
            self.nodes[parent.index()].children.push(id);
        }
        Ok(id)
    }

    /// Checks and stores a trigger of element `owner`; returns its index.
    fn trigger(
        &mut self,
        desc: &TriggerDesc,
        owner: ElementId,
        role: TriggerRole,
    ) -> Result<usize, StoryboardError> {
        let node = &self.nodes[owner.index()];
        let element = || format!("{} '{}'", node.kind, node.name);
        for (index, group) in desc.condition_groups.iter().enumerate() {
            if group.conditions.is_empty() {
                return Err(StoryboardError::new(ErrorKind::EmptyConditionGroup {
                    element: element(),
                    trigger: role,
                    group: index + 1,
                }));
            }
            for condition in &group.conditions {
                if !(condition.delay.is_finite() && condition.delay >= 0.0) {
                    return Err(StoryboardError::new(ErrorKind::InvalidDelay {
                        element: element(),
                        trigger: role,
                        condition: condition.name.clone(),
                        found: condition.delay,
                        origin: condition.origin.clone(),
                    }));
                }
            }
        }
        self.triggers.push(TriggerState::new(desc));
        Ok(self.triggers.len() - 1)
    }

    /// [`trigger`](Self::trigger) for an optional trigger.
    fn optional_trigger(
        &mut self,
        desc: &Option<TriggerDesc>,
        owner: ElementId,
        role: TriggerRole,
    ) -> Result<Option<usize>, StoryboardError> {
        desc.as_ref()
            .map(|desc| self.trigger(desc, owner, role))
            .transpose()
    }

    fn action(&mut self, desc: &ActionDesc, parent: ElementId) -> Result<(), StoryboardError> {
        let id = self.add(ElementKind::Action, &desc.name, Some(parent))?;
        self.nodes[id.index()].action = Some(desc.id);
        Ok(())
    }

    fn story(&mut self, desc: &StoryDesc, parent: ElementId) -> Result<(), StoryboardError> {
        let id = self.add(ElementKind::Story, &desc.name, Some(parent))?;
        desc.acts.iter().try_for_each(|act| self.act(act, id))
    }

    fn act(&mut self, desc: &ActDesc, parent: ElementId) -> Result<(), StoryboardError> {
        let id = self.add(ElementKind::Act, &desc.name, Some(parent))?;
        self.nodes[id.index()].start_trigger =
            self.optional_trigger(&desc.start_trigger, id, TriggerRole::Start)?;
        self.nodes[id.index()].stop_trigger =
            self.optional_trigger(&desc.stop_trigger, id, TriggerRole::Stop)?;
        desc.maneuver_groups
            .iter()
            .try_for_each(|group| self.maneuver_group(group, id))
    }

    fn maneuver_group(
        &mut self,
        desc: &ManeuverGroupDesc,
        parent: ElementId,
    ) -> Result<(), StoryboardError> {
        let id = self.add(ElementKind::ManeuverGroup, &desc.name, Some(parent))?;
        self.nodes[id.index()].maximum_execution_count = desc.maximum_execution_count;
        desc.maneuvers
            .iter()
            .try_for_each(|maneuver| self.maneuver(maneuver, id))
    }

    fn maneuver(&mut self, desc: &ManeuverDesc, parent: ElementId) -> Result<(), StoryboardError> {
        let id = self.add(ElementKind::Maneuver, &desc.name, Some(parent))?;
        desc.events
            .iter()
            .try_for_each(|event| self.event(event, id))
    }

    fn event(&mut self, desc: &EventDesc, parent: ElementId) -> Result<(), StoryboardError> {
        let id = self.add(ElementKind::Event, &desc.name, Some(parent))?;
        let node = &mut self.nodes[id.index()];
        node.maximum_execution_count = desc.maximum_execution_count;
        node.priority = desc.priority;
        self.nodes[id.index()].start_trigger =
            self.optional_trigger(&desc.start_trigger, id, TriggerRole::Start)?;
        desc.actions
            .iter()
            .try_for_each(|action| self.action(action, id))
    }
}

/// The element store of `desc` (module doc): its nodes and triggers, and the ids of the
/// storyboard and its Init.
///
/// Fails if a condition's delay is negative or not finite, or a condition group is empty.
pub(super) fn build(desc: &StoryboardDesc) -> Result<Built, StoryboardError> {
    let mut builder = Builder::default();
    let root = builder.add(ElementKind::Storyboard, &desc.name, None)?;
    builder.nodes[root.index()].stop_trigger =
        builder.optional_trigger(&desc.stop_trigger, root, TriggerRole::Stop)?;
    let init = builder.add(ElementKind::Init, "Init", Some(root))?;
    for action in &desc.init_actions {
        builder.action(action, init)?;
    }
    for story in &desc.stories {
        builder.story(story, root)?;
    }
    Ok(Built {
        nodes: builder.nodes,
        triggers: builder.triggers,
        root,
        init,
    })
}

/// What [`build`] makes of a storyboard's description.
pub(super) struct Built {
    /// The elements, in depth-first document order.
    pub(super) nodes: Vec<Node>,
    /// The triggers the elements refer to.
    pub(super) triggers: Vec<TriggerState>,
    /// The storyboard element.
    pub(super) root: ElementId,
    /// Its Init.
    pub(super) init: ElementId,
}
