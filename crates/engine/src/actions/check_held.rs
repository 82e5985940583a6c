//! oscsim's state check held over its phase (`scenario::StateCheck::throughout`, no XML form):
//! the OpenSCENARIO DSL runtime's constraints `at: all` of a phase whose place or end its plan
//! does not know (ASAM OpenSCENARIO DSL 2.1 §8.9 `at: all`: "the constraint holds throughout
//! the phase"), such as a `yaw` measured in the world (`check_heading`). The check runs when
//! the action starts, as any state check (`check::start`), and again in every step of stage 2
//! after it, on the actor as the stage finds it (the pose the last step's moves gave it), until
//! the action is stopped: its phase's Act ending stops it. A failure ends the action and is the
//! step's failure: an error record in the event log and a failed run.

use scenario::{SourcePos, StateCheck};

use super::check;
use crate::error::Error;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::EntityId;

/// A state check held from its start until its action is stopped.
#[derive(Debug, Clone)]
pub(crate) struct HeldCheck {
    /// What it requires.
    check: Box<StateCheck>,
    /// Where it is written.
    pos: SourcePos,
    /// Why it failed, once it has.
    pub failure: Option<Error>,
}

impl HeldCheck {
    /// `check` (written at `pos`), which held at its start.
    pub(super) fn new(check: &StateCheck, pos: &SourcePos) -> Self {
        Self {
            check: Box::new(check.clone()),
            pos: pos.clone(),
            failure: None,
        }
    }
}

/// Checks `held` on `actor` at `now`: running while it holds, ended with its failure noted
/// once it does not.
pub(super) fn step(world: &World, actor: EntityId, held: &mut HeldCheck, now: f64) -> ActionStatus {
    match check::require(world, actor, &held.check, (now, &held.pos)) {
        Ok(()) => ActionStatus::Running,
        Err(e) => {
            held.failure = Some(e);
            ActionStatus::Ended
        }
    }
}
