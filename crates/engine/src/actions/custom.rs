//! CustomCommandAction (OpenSCENARIO 1.3 §7.7.3 "UserDefinedAction", XSD `CustomCommandAction`):
//! a command for the simulator. oscsim runs headless and has no command interpreter; it records
//! the command (type and content) in the event log, where a downstream tool can act on it.

use scenario::UserDefinedAction;

use crate::output::EventRecord;

/// Records the command.
pub(crate) fn record(
    action: &UserDefinedAction,
    name: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) {
    events.push(EventRecord::CustomCommand {
        time,
        element: name.to_owned(),
        command_type: action.command_type.clone(),
        content: action.content.clone(),
    });
}
