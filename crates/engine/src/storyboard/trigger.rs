//! Trigger evaluation, OpenSCENARIO 1.3 §7.6.1 "Triggers and condition groups".
//!
//! A trigger is the OR of its condition groups, a group the AND of its conditions:
//! T(t) = ⋁ₙ ⋀ₘ Conditionₙₘ(t). Each condition slot turns the runtime's raw value into the
//! condition's value by applying its edge ([`EdgeDetector`]) and then its delay ([`DelayLine`]).
//! Every condition of an evaluated trigger is sampled every step, with no short-circuit, so that
//! edges and delays see an unbroken series.

use super::delay::DelayLine;
use super::desc::TriggerDesc;
use super::edge::EdgeDetector;
use super::element::ConditionId;

/// One condition of a trigger with its edge and delay memory.
#[derive(Debug, Clone)]
struct ConditionSlot {
    id: ConditionId,
    edge: EdgeDetector,
    delay: DelayLine,
}

/// The runtime state of one trigger.
#[derive(Debug, Clone)]
pub(crate) struct TriggerState {
    groups: Vec<Vec<ConditionSlot>>,
}

impl TriggerState {
    /// Builds the state of a validated trigger description.
    pub(crate) fn new(desc: &TriggerDesc) -> Self {
        let groups = desc
            .condition_groups
            .iter()
            .map(|group| {
                group
                    .conditions
                    .iter()
                    .map(|c| ConditionSlot {
                        id: c.id,
                        edge: EdgeDetector::new(c.edge),
                        delay: DelayLine::new(c.delay),
                    })
                    .collect()
            })
            .collect();
        TriggerState { groups }
    }

    /// Forgets all previous values: the next evaluation is the first (edges return false,
    /// delays have no history).
    pub(crate) fn reset(&mut self) {
        for slot in self.groups.iter_mut().flatten() {
            slot.edge.reset();
            slot.delay.reset();
        }
    }

    /// Evaluates the trigger at `time`, asking `raw` for each condition's expression value in
    /// document order. `dt` is the step length (rounding slack of the delays).
    pub(crate) fn evaluate(
        &mut self,
        time: f64,
        dt: f64,
        mut raw: impl FnMut(ConditionId) -> bool,
    ) -> bool {
        let mut any_group = false;
        for group in &mut self.groups {
            let mut all_conditions = true;
            for slot in group.iter_mut() {
                let edged = slot.edge.update(raw(slot.id));
                all_conditions &= slot.delay.update(time, dt, edged);
            }
            any_group |= all_conditions;
        }
        any_group
    }
}

#[cfg(test)]
mod tests {
    use super::super::desc::{ConditionDesc, ConditionGroupDesc};
    use super::super::edge::ConditionEdge;
    use super::*;

    fn group(ids: &[u32]) -> ConditionGroupDesc {
        ConditionGroupDesc {
            conditions: ids
                .iter()
                .map(|&i| ConditionDesc::new("c", ConditionId(i), ConditionEdge::None, 0.0))
                .collect(),
        }
    }

    /// (c0 ∧ c1) ∨ c2 over all eight inputs: the truth table of §7.6.1.
    #[test]
    fn groups_are_ored_and_conditions_anded() {
        let desc = TriggerDesc {
            condition_groups: vec![group(&[0, 1]), group(&[2])],
        };
        let mut trigger = TriggerState::new(&desc);
        for bits in 0u32..8 {
            let value = |id: ConditionId| bits & (1 << id.0) != 0;
            let expected =
                (value(ConditionId(0)) && value(ConditionId(1))) || value(ConditionId(2));
            assert_eq!(
                trigger.evaluate(0.0, 0.1, value),
                expected,
                "bits {bits:03b}"
            );
        }
    }

    #[test]
    fn an_empty_trigger_never_fires() {
        let mut trigger = TriggerState::new(&TriggerDesc::default());
        assert!(!trigger.evaluate(0.0, 0.1, |_| true));
    }

    #[test]
    fn every_condition_is_sampled_without_short_circuit() {
        let desc = TriggerDesc {
            condition_groups: vec![group(&[0]), group(&[1, 2])],
        };
        let mut trigger = TriggerState::new(&desc);
        let mut asked = Vec::new();
        // Group 1 is true already; groups 2's conditions must still be asked, c1 false included.
        let fired = trigger.evaluate(0.0, 0.1, |id| {
            asked.push(id.0);
            id.0 != 1
        });
        assert!(fired);
        assert_eq!(asked, [0, 1, 2]);
    }
}
