//! Per-condition memory for the conditions that must hold for a `duration`
//! (OpenSCENARIO 1.3 §7.6.3: EndOfRoadCondition, OffroadCondition, StandStillCondition).
//!
//! Each such condition remembers, per triggering entity, the simulation time since which its
//! instantaneous predicate has held without interruption. The runtime keeps one
//! [`ConditionState`] per condition in a [`ConditionStates`] store keyed by the storyboard's
//! [`ConditionId`] and passes it to every evaluation of that condition.

use std::collections::{BTreeMap, HashMap};

use crate::storyboard::ConditionId;
use crate::world::EntityId;

/// The memory of one condition: for each triggering entity (by id), the simulation time (s) since
/// which its predicate has held without a break.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ConditionState {
    since: BTreeMap<EntityId, f64>,
}

impl ConditionState {
    /// An empty memory (nothing has held yet).
    pub fn new() -> Self {
        Self::default()
    }

    /// Records the predicate's value `holds` for `entity` at time `now` and returns for how
    /// long (s) it has held without a break, `None` if it does not hold now.
    pub fn held_for(&mut self, entity: EntityId, holds: bool, now: f64) -> Option<f64> {
        if !holds {
            self.since.remove(&entity);
            return None;
        }
        let start = *self.since.entry(entity).or_insert(now);
        Some(now - start)
    }

    /// Forgets everything (for a condition whose trigger is re-armed).
    pub fn clear(&mut self) {
        self.since.clear();
    }
}

/// The runtime's store of [`ConditionState`]s, one per condition that has been evaluated.
#[derive(Debug, Clone, Default)]
pub struct ConditionStates {
    states: HashMap<ConditionId, ConditionState>,
}

impl ConditionStates {
    /// An empty store.
    pub fn new() -> Self {
        Self::default()
    }

    /// The memory of condition `id`, created empty on first use.
    pub fn get_mut(&mut self, id: ConditionId) -> &mut ConditionState {
        self.states.entry(id).or_default()
    }
}
