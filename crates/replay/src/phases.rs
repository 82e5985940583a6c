//! When each phase of an OpenSCENARIO DSL scenario's `do` tree ran (ASAM OpenSCENARIO DSL 2.1
//! §7.3.9): a phase is lowered to an Act named by its path (docs/dsl.md), so its interval is
//! that Act's in the event log — from its `start` transition to its `end` or `stop` (the run's
//! end when it never ended). Phases that never started are left out.

use crate::events::EventEntry;
use crate::run::Run;

/// A phase that ran.
#[derive(Debug, Clone, PartialEq)]
pub struct PhaseSpan {
    /// Its path (`do`, `do.cut_in`, `do.cut_in.1`).
    pub path: String,
    /// Its depth in the tree (`do` 0, `do.cut_in` 1).
    pub depth: usize,
    /// Start (s).
    pub start: f64,
    /// End (s).
    pub end: f64,
}

/// The phases of `run` (its manifest's, in its order) with their intervals.
pub fn spans(run: &Run) -> Vec<PhaseSpan> {
    let last = run.trajectories.times.last().copied().unwrap_or(0.0);
    spans_of(&run.manifest.phases, &run.events, last)
}

/// The intervals of the phases `paths` in the event log `events` of a run that ended at
/// `last` (s).
pub fn spans_of(paths: &[String], events: &[EventEntry], last: f64) -> Vec<PhaseSpan> {
    paths
        .iter()
        .filter_map(|path| {
            let act = |transitions: &[&str]| {
                events
                    .iter()
                    .find(|e| {
                        e.kind == "act"
                            && e.element == *path
                            && e.transition
                                .as_deref()
                                .is_some_and(|t| transitions.contains(&t))
                    })
                    .map(|e| e.time)
            };
            let start = act(&["start"])?;
            Some(PhaseSpan {
                path: path.clone(),
                depth: path.matches('.').count(),
                start,
                end: act(&["end", "stop"]).unwrap_or(last),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::events::parse;
    use std::path::Path;

    #[test]
    fn a_phase_runs_from_its_act_start_to_its_stop() {
        // The DSL cut-in's log: `do.cut_in` starts at 3.4 s and is stopped at 5.4 s (2 s).
        let log = r#"{"time":3.400,"element":"do.cut_in","kind":"act","from":"standbyState","transition":"start","to":"runningState"}
{"time":5.400,"element":"do.cut_in","kind":"act","from":"runningState","transition":"stop","to":"completeState"}
{"time":0.000,"element":"do","kind":"act","from":"initState","transition":"start","to":"runningState"}
"#;
        let events = parse(log, Path::new("e.jsonl")).expect("valid log");
        let paths = ["do.cut_in", "do", "do.never"].map(String::from);
        let s = spans_of(&paths, &events, 9.5);
        assert_eq!(s.len(), 2, "do.never never started");
        assert_eq!((s[0].depth, s[0].start, s[0].end), (1, 3.4, 5.4));
        // `do` never ended in the log: it runs to the last frame.
        assert_eq!((s[1].path.as_str(), s[1].depth, s[1].end), ("do", 0, 9.5));
    }
}
