//! The event log as JSON lines, one object per record:
//! a transition is `{"time", "element", "kind", "from", "transition", "to"}` with the element's
//! name and kind (`act`, `event`, …), the states' standard names (`standbyState`) and the
//! transition as `start`, `end`, `stop` or `skip` (the form `compare_run.py` reads); a custom
//! command is `{"time", "element", "kind": "customCommand", "type", "content"}`; skipped
//! features and errors are `{"time", "element", "kind": "unsupported"|"error", "message"}`;
//! an entity entering or leaving is `{"time", "element", "kind": "entity", "entity", "change"}`;
//! a signal controller's phase or a signal's state is `{"time", "element", "kind":
//! "trafficSignalController"|"trafficSignal", "from", "to"}` (`from` null for the first); a
//! monitor's value is `{"time", "element", "kind": "monitor", "value"}`.
//! Times have 3 decimals, so logs of identical runs are byte-identical.

use std::io::Write;

use super::event::{EventRecord, EventSink};
use super::SinkError;
use crate::storyboard::Transition;

/// Writes event records as JSON lines to `W`.
#[derive(Debug)]
pub struct JsonlWriter<W: Write> {
    out: W,
}

impl<W: Write> JsonlWriter<W> {
    /// A writer on `out`.
    pub fn new(out: W) -> Self {
        JsonlWriter { out }
    }

    /// The underlying writer.
    pub fn into_inner(self) -> W {
        self.out
    }
}

/// A JSON string literal.
fn string(s: &str) -> String {
    // Serializing a &str cannot fail: serde_json errors only for maps with non-string keys
    // and for writers that fail, and this writes to a String.
    serde_json::to_string(s).unwrap_or_default()
}

/// The short transition name of the event log.
pub fn transition_name(t: Transition) -> &'static str {
    match t {
        Transition::Start => "start",
        Transition::End => "end",
        Transition::Stop => "stop",
        Transition::Skip => "skip",
    }
}

impl<W: Write> EventSink for JsonlWriter<W> {
    fn event(&mut self, record: &EventRecord) -> Result<(), SinkError> {
        self.write(record).map_err(SinkError::from)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(self.out.flush()?)
    }
}

impl<W: Write> JsonlWriter<W> {
    /// Writes `record` as one line.
    fn write(&mut self, record: &EventRecord) -> std::io::Result<()> {
        match record {
            EventRecord::Transition(t) => writeln!(
                self.out,
                "{{\"time\":{:.3},\"element\":{},\"kind\":\"{}\",\"from\":\"{}\",\"transition\":\"{}\",\"to\":\"{}\"}}",
                t.time,
                string(&t.name),
                t.kind,
                t.from,
                transition_name(t.transition),
                t.to
            ),
            EventRecord::CustomCommand {
                time,
                element,
                command_type,
                content,
            } => writeln!(
                self.out,
                "{{\"time\":{time:.3},\"element\":{},\"kind\":\"customCommand\",\"type\":{},\"content\":{}}}",
                string(element),
                string(command_type),
                string(content)
            ),
            EventRecord::Unsupported {
                time,
                element,
                message,
            } => writeln!(
                self.out,
                "{{\"time\":{time:.3},\"element\":{},\"kind\":\"unsupported\",\"message\":{}}}",
                string(element),
                string(message)
            ),
            EventRecord::Entity {
                time,
                element,
                entity,
                change,
            } => writeln!(
                self.out,
                "{{\"time\":{time:.3},\"element\":{},\"kind\":\"entity\",\"entity\":{},\"change\":{}}}",
                string(element),
                string(entity),
                string(change)
            ),
            EventRecord::Signal {
                time,
                element,
                kind,
                from,
                to,
            } => writeln!(
                self.out,
                "{{\"time\":{time:.3},\"element\":{},\"kind\":\"{}\",\"from\":{},\"to\":{}}}",
                string(element),
                kind.name(),
                from.as_deref().map_or_else(|| "null".to_owned(), string),
                string(to)
            ),
            EventRecord::Monitor {
                time,
                element,
                value,
            } => writeln!(
                self.out,
                "{{\"time\":{time:.3},\"element\":{},\"kind\":\"monitor\",\"value\":{value}}}",
                string(element),
            ),
            EventRecord::Controller {
                time,
                element,
                entity,
                controller,
                model,
                active,
                note,
            } => writeln!(
                self.out,
                "{{\"time\":{time:.3},\"element\":{},\"kind\":\"controller\",\"entity\":{},\"controller\":{},\"model\":{},\"longitudinal\":{},\"lateral\":{},\"lighting\":{},\"animation\":{},\"note\":{}}}",
                string(element),
                string(entity),
                string(controller),
                string(model),
                active.longitudinal,
                active.lateral,
                active.lighting,
                active.animation,
                string(note)
            ),
            EventRecord::Error {
                time,
                element,
                message,
            } => writeln!(
                self.out,
                "{{\"time\":{time:.3},\"element\":{},\"kind\":\"error\",\"message\":{}}}",
                string(element),
                string(message)
            ),
        }
    }
}
