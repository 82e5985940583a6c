//! When a run with `duration` ends: at the first step whose time reaches it, whatever the step
//! length (runtime/step.rs: a tolerance of a millionth of a step for the round-off of
//! steps · dt).

use crate::runtime_support;

use engine::{EngineConfig, StopReason};
use runtime_support::{file, run_with};

/// duration / dt steps: 1 s at 0.05 s is 20 steps; 0.3 s at 0.1 s is 3 (3 · 0.1 =
/// 0.30000000000000004, past 0.3 by round-off only); 5e-10 s at 1e-10 s is 5 (a fixed 1e-9 s
/// tolerance stopped this run after its first step).
#[test]
fn duration_ends_the_run_at_its_step_for_any_step_length() {
    for (dt, duration, steps) in [(0.05, 1.0, 20), (0.1, 0.3, 3), (1e-10, 5e-10, 5)] {
        let config = EngineConfig {
            dt,
            duration: Some(duration),
            ..EngineConfig::default()
        };
        let (engine, _, _) = run_with(&file("speed_linear.xosc"), &[], config);
        assert_eq!(engine.steps(), steps, "dt {dt}, duration {duration}");
        assert_eq!(engine.stop_reason(), Some(StopReason::Duration));
    }
}

/// The one list of stop-reason names (issue 33: batch and Python each had their own): the
/// names of docs/batch.md's `stop_reason` column, in declaration order, each read back.
#[test]
fn stop_reason_names_are_the_documented_ones_and_read_back() {
    use engine::StopReason;
    let names: Vec<&str> = StopReason::ALL.iter().map(|r| r.name()).collect();
    assert_eq!(
        names,
        ["stop_trigger", "stories_complete", "duration", "time_cap"]
    );
    for r in StopReason::ALL {
        assert_eq!(StopReason::from_name(r.name()), Some(r));
    }
    assert_eq!(StopReason::from_name("Duration"), None);
}
