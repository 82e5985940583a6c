//! Read access to element states, for `StoryboardElementStateCondition` (OpenSCENARIO 1.3
//! §8.1 states, §8.2 transitions, class `StoryboardElementStateCondition`).
//!
//! A state is a lasting property; a transition is an instant. [`StateView::transition_happened`]
//! counts a transition as happening during the step in which it took place and during the whole
//! next step. The second step matters because elements are visited in document order: an element
//! that observes one visited later in the same step would otherwise never see its transitions.
//! A rising-edge condition on a transition therefore fires once, in the step of the transition or
//! the next.
//!
//! Names are not unique in OpenSCENARIO files (esmini's `acc-test.xosc` has two Events named
//! `EgoSpeedEvent`); [`StateView::find`] returns the first in document order and
//! [`StateView::find_all`] all of them. A condition's reference may carry `::`-separated
//! prefixes (OpenSCENARIO 1.1 User Guide §1.4.5, 1.3 "Naming"); [`StateView::find_ref`]
//! matches it against the elements' name paths.

use scenario::names::QualifiedName;

use super::element::{ElementId, ElementKind};
use super::state::{ElementState, StoryboardElementState, Transition};
use super::tree::{Node, Status};

/// A read-only view of the storyboard's element states at one moment of a step.
#[derive(Debug, Clone, Copy)]
pub struct StateView<'a> {
    pub(crate) nodes: &'a [Node],
    pub(crate) status: &'a [Status],
    /// Index of the current step (the first step is 0).
    pub(crate) step: u64,
}

impl<'a> StateView<'a> {
    /// Number of elements (ids are `0..len`).
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Always false: a storyboard has at least its root and Init.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// All element ids, in document order.
    pub fn ids(&self) -> impl Iterator<Item = ElementId> {
        (0..self.nodes.len()).map(|i| ElementId(i as u32))
    }

    /// The first element named `name`, in document order.
    pub fn find(&self, name: &str) -> Option<ElementId> {
        self.find_all(name).next()
    }

    /// All elements named `name`, in document order.
    pub fn find_all<'n>(&self, name: &'n str) -> impl Iterator<Item = ElementId> + 'n
    where
        'a: 'n,
    {
        let nodes = self.nodes;
        self.ids().filter(move |id| nodes[id.index()].name == name)
    }

    /// The elements of `kind` that `reference` designates: a name, optionally prefixed with
    /// the names of enclosing elements separated by `::` (`Maneuver::Event`), matched against
    /// each element's name path from its Story down (`scenario::names`: unique-suffix
    /// matching, a leading `::` for the whole path). In document order.
    pub fn find_ref(&self, kind: ElementKind, reference: &str) -> Vec<ElementId> {
        let q = QualifiedName::parse(reference);
        let last = q.parts.last().copied().unwrap_or_default();
        self.find_all(last)
            .filter(|&id| self.kind(id) == kind && q.matches(&self.name_path(id)))
            .collect()
    }

    /// The element of `kind` that `reference` designates ([`find_ref`](Self::find_ref));
    /// none if it designates none or several.
    pub fn find_kind(&self, kind: ElementKind, reference: &str) -> Option<ElementId> {
        match self.find_ref(kind, reference).as_slice() {
            [one] => Some(*one),
            _ => None,
        }
    }

    /// The names of the element and its enclosing storyboard elements, outermost (the Story)
    /// first; the root and Init are not storyboard elements and have no part in it.
    pub fn name_path(&self, id: ElementId) -> Vec<&'a str> {
        let mut path = Vec::new();
        let mut at = Some(id);
        while let Some(e) = at {
            if !matches!(self.kind(e), ElementKind::Storyboard | ElementKind::Init) {
                path.push(self.name(e));
            }
            at = self.parent(e);
        }
        path.reverse();
        path
    }

    /// The element's current state. Panics if `id` is not from this storyboard.
    pub fn state(&self, id: ElementId) -> ElementState {
        self.status[id.index()].state
    }

    /// The element's kind.
    pub fn kind(&self, id: ElementId) -> ElementKind {
        self.nodes[id.index()].kind
    }

    /// The element's name.
    pub fn name(&self, id: ElementId) -> &'a str {
        &self.nodes[id.index()].name
    }

    /// The element's parent (none for the storyboard).
    pub fn parent(&self, id: ElementId) -> Option<ElementId> {
        self.nodes[id.index()].parent
    }

    /// The element's children in document order.
    pub fn children(&self, id: ElementId) -> &'a [ElementId] {
        &self.nodes[id.index()].children
    }

    /// Number of executions (start plus skip transitions, §8.4.2.1) since the element's parent
    /// last started it.
    pub fn executions(&self, id: ElementId) -> u32 {
        self.status[id.index()].executions
    }

    /// True if `transition` of the element happened in this step (so far) or in the previous
    /// step (see the module documentation).
    pub fn transition_happened(&self, id: ElementId, transition: Transition) -> bool {
        self.status[id.index()]
            .last(transition)
            .is_some_and(|step| step + 1 >= self.step)
    }

    /// The value of a StoryboardElementStateCondition on the element: it is in the state, or
    /// the transition happened (see [`transition_happened`](Self::transition_happened)).
    pub fn is(&self, id: ElementId, state: StoryboardElementState) -> bool {
        match state {
            StoryboardElementState::State(s) => self.state(id) == s,
            StoryboardElementState::Transition(t) => self.transition_happened(id, t),
        }
    }

    /// The step in which `transition` of the element last happened (the first step is 0).
    pub fn last_transition_step(&self, id: ElementId, transition: Transition) -> Option<u64> {
        self.status[id.index()].last(transition)
    }

    /// Index of the current step (of the last step once a step has returned).
    pub fn step(&self) -> u64 {
        self.step
    }
}
