//! The storyboard's [`ConditionSource`] over the world: the raw value of each condition
//! (OpenSCENARIO 1.3 §7.6), before the edge and delay the storyboard applies, from
//! [`crate::condition::evaluate`] with the world as its [`ConditionContext`], the names each
//! condition holds resolved when the storyboard was built (`runtime::build`,
//! condition/refs.rs), and one memory per condition.
//!
//! A condition that cannot be evaluated (a measurement oscsim does not support, a value of the
//! wrong type) reads false; its error is written once to the event log, naming the condition's
//! file position, and the run goes on.
//!
//! [`ConditionContext`]: crate::condition::ConditionContext

use std::cell::RefCell;

use super::trigger_view::TriggerView;
use crate::condition::{evaluate_resolved, ConditionErrorKind, ConditionRefs, ConditionStates};
use crate::output::EventRecord;
use crate::store::{ConditionWorld, World};
use crate::storyboard::{ConditionId, ConditionSource, StateView};

/// The [`ConditionSource`] of one step.
pub(crate) struct Conditions<'a> {
    pub world: &'a RefCell<World>,
    pub conditions: &'a [scenario::Condition],
    /// Per condition: its names, resolved when the storyboard was built (condition/refs.rs).
    pub refs: &'a [ConditionRefs],
    pub states: &'a mut ConditionStates,
    /// Per condition: its failure has been logged.
    pub reported: &'a mut Vec<bool>,
    pub log: &'a RefCell<Vec<EventRecord>>,
    /// The world as this step's triggers see it (runtime/trigger_view.rs).
    pub view: &'a RefCell<TriggerView>,
}

impl ConditionSource for Conditions<'_> {
    fn value(&mut self, id: ConditionId, time: f64, storyboard: &StateView<'_>) -> bool {
        let index = id.0 as usize;
        let (Some(condition), Some(refs)) = (self.conditions.get(index), self.refs.get(index))
        else {
            return false;
        };
        let mut world = self.world.borrow_mut();
        let state = self.states.get_mut(id);
        let result = self.view.borrow_mut().evaluate(&mut world, |world| {
            let ctx = ConditionWorld {
                world,
                storyboard: *storyboard,
                condition: id,
            };
            evaluate_resolved(condition, refs, &ctx, state)
        });
        match result {
            Ok(v) => v,
            Err(e) => {
                if !self.reported[index] {
                    self.reported[index] = true;
                    let record = match e.kind() {
                        ConditionErrorKind::Unsupported { .. } => EventRecord::Unsupported {
                            time,
                            element: condition.name.clone(),
                            message: format!("{e} (the condition reads false)"),
                        },
                        _ => EventRecord::Error {
                            time,
                            element: condition.name.clone(),
                            message: format!("{e} (the condition reads false)"),
                        },
                    };
                    self.log.borrow_mut().push(record);
                }
                false
            }
        }
    }
}
