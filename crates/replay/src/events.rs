//! Reads the event log that `oscsim run --events` writes (JSON lines; `engine::output`'s
//! `JsonlWriter`): storyboard transitions (OpenSCENARIO 1.3 §8.2 `{"time", "element",
//! "kind", "from", "transition", "to"}`), entity changes, custom commands, skipped features and
//! errors, each kept with a one-line description for the replay's timeline.

use std::path::Path;

use serde_json::Value;

use crate::error::{Error, Result};

/// One record of the event log.
#[derive(Debug, Clone, PartialEq)]
pub struct EventEntry {
    /// Simulation time (s).
    pub time: f64,
    /// The element's name (storyboard element, action, traffic action).
    pub element: String,
    /// `storyboard`, `story`, `act`, `maneuverGroup`, `maneuver`, `event`, `action`, or for
    /// records that are no transition `entity`, `customCommand`, `unsupported`, `error`.
    pub kind: String,
    /// The transition (`start`, `end`, `stop`, `skip`) of a transition record.
    pub transition: Option<String>,
    /// The entity of an `entity` record.
    pub entity: Option<String>,
    /// What happened, in words: "standbyState → runningState (start)", "spawned", the message.
    pub detail: String,
}

/// The string field `key` of `v`, or "".
fn text<'a>(v: &'a Value, key: &str) -> &'a str {
    v.get(key).and_then(Value::as_str).unwrap_or("")
}

impl EventEntry {
    /// Reads one JSON object.
    fn from_json(v: &Value) -> Option<EventEntry> {
        let time = v.get("time")?.as_f64()?;
        let kind = v.get("kind")?.as_str()?.to_owned();
        let (transition, entity, detail) = match kind.as_str() {
            "entity" => (
                None,
                Some(text(v, "entity").to_owned()),
                text(v, "change").to_owned(),
            ),
            "customCommand" => (
                None,
                None,
                format!("{}: {}", text(v, "type"), text(v, "content")),
            ),
            "unsupported" | "error" => (None, None, text(v, "message").to_owned()),
            _ => {
                let transition = text(v, "transition").to_owned();
                let detail = format!("{} → {} ({transition})", text(v, "from"), text(v, "to"));
                (Some(transition), None, detail)
            }
        };
        Some(EventEntry {
            time,
            element: text(v, "element").to_owned(),
            kind,
            transition,
            entity,
            detail,
        })
    }
}

/// Reads event log `text`; `path` names the file in errors.
pub fn parse(text: &str, path: &Path) -> Result<Vec<EventEntry>> {
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let v: Value = serde_json::from_str(line).map_err(|e| {
            Error::invalid(
                path,
                i + 1,
                e.column(),
                "a JSON object per line",
                e.to_string(),
            )
        })?;
        let entry = EventEntry::from_json(&v).ok_or_else(|| {
            Error::invalid(
                path,
                i + 1,
                1,
                "an event record with \"time\" and \"kind\"",
                format!("'{line}'"),
            )
        })?;
        out.push(entry);
    }
    Ok(out)
}

/// Reads the event log at `path`.
pub fn read(path: &Path) -> Result<Vec<EventEntry>> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io("cannot read", path, e))?;
    parse(&text, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transitions_and_entity_records_are_described() {
        let log = r#"{"time":5.650,"element":"CutInEvent","kind":"event","from":"standbyState","transition":"start","to":"runningState"}
{"time":1.000,"element":"Swarm","kind":"entity","entity":"swarm_3","change":"spawned"}
"#;
        let e = parse(log, Path::new("e.jsonl")).expect("valid log");
        assert_eq!(e[0].time, 5.65);
        assert_eq!(e[0].detail, "standbyState → runningState (start)");
        assert_eq!(e[0].transition.as_deref(), Some("start"));
        assert_eq!(e[1].entity.as_deref(), Some("swarm_3"));
        assert_eq!(e[1].detail, "spawned");
    }

    #[test]
    fn a_broken_line_is_an_error_at_its_line() {
        let err = parse(
            "{\"time\":1,\"kind\":\"act\"}\n{oops\n",
            Path::new("e.jsonl"),
        )
        .expect_err("line 2 is no JSON");
        assert!(err.to_string().contains("at e.jsonl:2:"), "{err}");
    }
}
