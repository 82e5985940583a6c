//! AssignControllerAction and ActivateControllerAction (OpenSCENARIO 1.3 §7.7.2.5,
//! XSD `ControllerAction`). oscsim has only the default controller (§7.5.1): activating or
//! deactivating it is accepted (the default controller always runs when no other does).
//! OverrideControllerValueAction is handled by `override_controller` (the `OverrideValues` arm
//! here is not reached from the action host). Assigning any other controller is
//! rejected with a record in the event log naming the controller and the action's position;
//! the entity keeps its default controller, so the scenario runs as the reference runs with
//! controllers disabled.

use scenario::{ControllerAction, SourcePos};

use crate::output::EventRecord;
use crate::runtime::error::RuntimeError;

/// Applies the action.
pub(crate) fn start(
    action: &ControllerAction,
    name: &str,
    pos: &SourcePos,
    time: f64,
    events: &mut Vec<EventRecord>,
) -> Result<(), RuntimeError> {
    match action {
        ControllerAction::Assign { controller, .. } => {
            let is_default = controller.properties.properties.is_empty()
                && controller.name.eq_ignore_ascii_case("default");
            if !is_default {
                events.push(EventRecord::unsupported(
                    time,
                    name,
                    &format!(
                        "controller '{}' (only the default controller runs)",
                        controller.name
                    ),
                    pos,
                ));
            }
            Ok(())
        }
        ControllerAction::Activate { .. } => Ok(()),
        ControllerAction::OverrideValues(_) => {
            events.push(EventRecord::unsupported(
                time,
                name,
                "OverrideControllerValueAction",
                pos,
            ));
            Ok(())
        }
        _ => Err(RuntimeError::unsupported("this ControllerAction", pos)),
    }
}
