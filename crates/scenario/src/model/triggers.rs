//! Triggers and conditions (OpenSCENARIO 1.3 "Conditions and triggers", XSD
//! `Trigger`, `ConditionGroup`, `Condition`, `ByEntityCondition`, `TriggeringEntities`).
//! A trigger fires when any of its groups holds; a group holds when all its conditions do.

use crate::model::{ByValueCondition, ConditionEdge, EntityCondition, TriggeringEntitiesRule};
use crate::source::SourcePos;

/// A trigger (XSD `Trigger`): OR of condition groups.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Trigger {
    /// ConditionGroups.
    pub condition_groups: Vec<ConditionGroup>,
}

/// A condition group (XSD `ConditionGroup`): AND of conditions.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ConditionGroup {
    /// Conditions.
    pub conditions: Vec<Condition>,
}

/// A condition (XSD `Condition`).
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// `name`.
    pub name: String,
    /// `conditionEdge`.
    pub condition_edge: ConditionEdge,
    /// `delay`, s: the condition reports now what it evaluated `delay` ago.
    pub delay: f64,
    /// What it tests.
    pub kind: ConditionKind,
    /// Where the Condition starts.
    pub pos: SourcePos,
}

/// The kinds of condition (XSD `Condition` choice).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ConditionKind {
    /// ByEntityCondition.
    ByEntity {
        /// TriggeringEntities.
        triggering_entities: TriggeringEntities,
        /// EntityCondition.
        entity_condition: EntityCondition,
    },
    /// ByValueCondition.
    ByValue(ByValueCondition),
}

impl ConditionKind {
    /// A ByEntityCondition on one entity (`triggeringEntitiesRule="any"` of one EntityRef):
    /// the form every condition on a single actor takes.
    pub fn by_entity(entity: impl Into<String>, entity_condition: EntityCondition) -> Self {
        ConditionKind::ByEntity {
            triggering_entities: TriggeringEntities {
                rule: TriggeringEntitiesRule::Any,
                entity_refs: vec![entity.into()],
            },
            entity_condition,
        }
    }
}

/// Triggering entities (XSD `TriggeringEntities`).
#[derive(Debug, Clone, PartialEq)]
pub struct TriggeringEntities {
    /// `triggeringEntitiesRule`.
    pub rule: TriggeringEntitiesRule,
    /// EntityRef names.
    pub entity_refs: Vec<String>,
}
