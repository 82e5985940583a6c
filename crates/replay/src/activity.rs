//! When each action ran for each of its actors (OpenSCENARIO 1.3 §8.2 action states): from
//! the event log's `action` transitions (`start` opens an interval; `end`, `stop` and `skip`
//! close it) and the manifest's action → actors table. An action still running when the log
//! ends stays open.

use std::collections::BTreeMap;

use crate::events::EventEntry;
use crate::manifest::ActionActors;

/// One running interval of an action.
#[derive(Debug, Clone, PartialEq)]
pub struct ActiveAction {
    /// The action's name.
    pub name: String,
    /// Its kind (`LateralAction`, …).
    pub kind: String,
    /// Start time (s).
    pub start: f64,
    /// End time (s); `None` while running at the log's end.
    pub end: Option<f64>,
}

/// The running intervals of each actor's actions, by actor name, in start order.
pub fn active_actions(
    events: &[EventEntry],
    actions: &[ActionActors],
) -> BTreeMap<String, Vec<ActiveAction>> {
    let mut out: BTreeMap<String, Vec<ActiveAction>> = BTreeMap::new();
    // Index in `out[actor]` of each action's open interval, by (action, actor).
    let mut open: BTreeMap<(String, String), usize> = BTreeMap::new();
    for e in events.iter().filter(|e| e.kind == "action") {
        let Some(action) = actions.iter().find(|a| a.name == e.element) else {
            continue;
        };
        for actor in &action.actors {
            let key = (e.element.clone(), actor.clone());
            let list = out.entry(actor.clone()).or_default();
            match e.transition.as_deref() {
                Some("start") => {
                    open.insert(key, list.len());
                    list.push(ActiveAction {
                        name: e.element.clone(),
                        kind: action.kind.clone(),
                        start: e.time,
                        end: None,
                    });
                }
                Some("end" | "stop" | "skip") => {
                    if let Some(k) = open.remove(&key) {
                        list[k].end = Some(e.time);
                    }
                }
                _ => {}
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn event(time: f64, element: &str, transition: &str) -> EventEntry {
        EventEntry {
            time,
            element: element.into(),
            kind: "action".into(),
            transition: Some(transition.into()),
            entity: None,
            detail: String::new(),
        }
    }

    #[test]
    fn intervals_open_at_start_and_close_at_end() {
        let actions = [ActionActors {
            name: "CutInAction".into(),
            kind: "LateralAction".into(),
            actors: vec!["OverTaker".into()],
        }];
        // The cut-in's log: CutInAction starts at 5.65 s and ends at 7.6 s.
        let events = [
            event(5.65, "CutInAction", "start"),
            event(7.6, "CutInAction", "end"),
        ];
        let active = active_actions(&events, &actions);
        assert_eq!(
            active["OverTaker"],
            vec![ActiveAction {
                name: "CutInAction".into(),
                kind: "LateralAction".into(),
                start: 5.65,
                end: Some(7.6)
            }]
        );
    }
}
