//! The front door: [`evaluate`] gives the raw value of one `scenario::Condition`
//! (OpenSCENARIO 1.3 §7.6.1 "Condition"); `conditionEdge` and `delay` are applied by the
//! storyboard, not here. [`evaluate`] resolves the condition's names through the context at
//! each call; the runtime resolves them once, when it builds the storyboard, and calls
//! [`evaluate_resolved`] (condition/refs.rs).

use scenario::{Condition, ConditionKind};

use super::refs::{ConditionRefs, Names, RefError, SelectionId};
use super::{
    by_entity, by_value, ConditionContext, ConditionError, ConditionErrorKind, ConditionState,
    MarkId,
};
use crate::world::EntityId;

/// The raw value of `condition` now, read from `ctx`. `state` is this condition's memory
/// (the runtime keeps one per condition, e.g. in a [`ConditionStates`](super::ConditionStates)
/// store keyed by its `ConditionId`); only the duration conditions use it.
///
/// Errors name the condition's file, line and column: an unknown entity, parameter, variable
/// or storyboard element, a value of the wrong type, a position that cannot be resolved, or
/// a measurement oscsim does not support. A measurement that merely has no answer now (an
/// entity off the roads for a road distance, objects not closing for a TTC) is false, not an
/// error. The condition's names are resolved through `ctx` first
/// ([`ConditionContext::entity_id`], [`ConditionContext::selection_id`],
/// [`ConditionContext::mark_id`]): one that names nothing is an unknown entity; the
/// condition's position is resolved as far as it can be too (an entity-free one that does not
/// resolve is its position error).
pub fn evaluate<C: ConditionContext + ?Sized>(
    condition: &Condition,
    ctx: &C,
    state: &mut ConditionState,
) -> Result<bool, ConditionError> {
    match ConditionRefs::resolve(condition, &mut Context(ctx)) {
        Ok(refs) => evaluate_resolved(condition, &refs, ctx, state),
        Err(e) => {
            ctx.note_triggering(&condition.pos, false, &[]);
            let kind = match e {
                RefError::Unresolved(u) => ConditionErrorKind::UnknownEntity(u.name),
                RefError::Position(p) => ConditionErrorKind::Position(p),
            };
            Err(ConditionError::new(kind, &condition.pos))
        }
    }
}

/// [`evaluate`] with the condition's names resolved before (`refs`, from
/// [`ConditionRefs::resolve`] on the same context's names): no name is looked up.
pub(crate) fn evaluate_resolved<C: ConditionContext + ?Sized>(
    condition: &Condition,
    refs: &ConditionRefs,
    ctx: &C,
    state: &mut ConditionState,
) -> Result<bool, ConditionError> {
    let result = dispatch(condition, refs, ctx, state);
    // A ByEntityCondition reports its value and entities itself; the others report their
    // value here, and a failed evaluation reads false ([`ConditionContext::note_triggering`]).
    match (&condition.kind, &result) {
        (ConditionKind::ByEntity { .. }, Ok(_)) => {}
        (_, r) => ctx.note_triggering(&condition.pos, matches!(r, Ok(true)), &[]),
    }
    result
}

/// The raw value of `condition` by its kind.
fn dispatch<C: ConditionContext + ?Sized>(
    condition: &Condition,
    refs: &ConditionRefs,
    ctx: &C,
    state: &mut ConditionState,
) -> Result<bool, ConditionError> {
    match &condition.kind {
        ConditionKind::ByValue(c) => by_value::evaluate(c, ctx, &condition.pos),
        ConditionKind::ByEntity {
            triggering_entities,
            entity_condition,
        } => by_entity::evaluate(
            triggering_entities,
            entity_condition,
            refs,
            ctx,
            state,
            &condition.pos,
        ),
        _ => Err(ConditionError::new(
            ConditionErrorKind::Unsupported {
                expected: "ByValueCondition or ByEntityCondition",
                found: "another kind",
            },
            &condition.pos,
        )),
    }
}

/// A context's names, for [`evaluate`]'s resolution.
struct Context<'c, C: ?Sized>(&'c C);

impl<C: ConditionContext + ?Sized> Names for Context<'_, C> {
    fn entity(&self, name: &str) -> Option<EntityId> {
        self.0.entity_id(name)
    }

    fn selection(&self, name: &str) -> Option<SelectionId> {
        self.0.selection_id(name)
    }

    fn mark(&mut self, name: &str) -> Option<MarkId> {
        self.0.mark_id(name)
    }

    fn network(&self) -> &opendrive::RoadNetwork {
        self.0.road_network()
    }

    fn routing_options(&self) -> crate::routing::RoutingOptions {
        self.0.routing_options()
    }
}
