//! The §8.8.3 gap actions (`change_space_gap`, `keep_space_gap`, `change_time_headway`,
//! `keep_time_headway`) through the engine's LongitudinalDistanceAction on
//! `tests/roads/straight.xodr`: each change ends when its gap is reached (the engine's 0.1 m),
//! each keep holds it to its phase's end, against the scenario's hand-worked comment.

use crate::support::{run, DT};

/// The engine's distance controller ends a change within this of its distance (m).
const REACHED: f64 = 0.1;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;

#[test]
fn change_space_gap_ends_at_the_gap_and_keep_space_gap_holds_it() {
    let r = run("actions/space_gap", 0, None);
    // Boxes: front 3.5 m, rear 0.5 m ahead of / behind the reference points.
    let gap = |t: f64| (r.at(t, "lead").s - 0.5) - (r.at(t, "ego").s + 3.5);
    assert!((gap(0.0) - 66.0).abs() < 1e-9, "gap(0) = {}", gap(0.0));
    let (s, e) = r.phase("do.1.close");
    assert!(s.abs() < T_TOL && e > 0.0 && e < 30.0, "close [{s}, {e}]");
    // The engine checks the gap at a step's start (the frame e − 2·dt), logs the action's end
    // with the next step, and the phase's stop trigger sees that one step later.
    let at_end = gap(e - 2.0 * DT);
    assert!(
        (at_end - 20.0).abs() <= REACHED + 1e-9,
        "gap {at_end} at {e}"
    );
    // Closing only: the gap never falls below the target by more than the tolerance.
    for (t, _) in r.frames.iter().filter(|(t, _)| *t <= e) {
        assert!(gap(*t) > 20.0 - REACHED, "gap {} at {t}", gap(*t));
    }
    let (s2, e2) = r.phase("do.1.hold");
    assert!(
        (s2 - e).abs() < T_TOL && (e2 - 30.0).abs() < T_TOL,
        "hold [{s2}, {e2}]"
    );
    let (lead, ego) = (r.at(30.0, "lead"), r.at(30.0, "ego"));
    assert!((lead.s - 550.0).abs() < 1e-9, "lead s(30) = {}", lead.s);
    assert!(
        (gap(30.0) - 20.0).abs() < REACHED,
        "gap(30) = {}",
        gap(30.0)
    );
    assert!((ego.speed - 15.0).abs() < 0.05, "ego v(30) = {}", ego.speed);
}

#[test]
fn change_time_headway_ends_at_the_headway_and_keep_time_headway_holds_it() {
    let r = run("actions/time_headway", 0, None);
    let between = |t: f64| r.at(t, "lead").s - r.at(t, "ego").s;
    assert!((between(0.0) - 130.0).abs() < 1e-9);
    let (s, e) = r.phase("do.1.open");
    assert!(s.abs() < T_TOL && e > 0.0 && e < 40.0, "open [{s}, {e}]");
    let at_end = between(e - 2.0 * DT);
    assert!((at_end - 30.0).abs() <= REACHED + 1e-9, "{at_end} m at {e}");
    let (s2, e2) = r.phase("do.1.follow");
    assert!(
        (s2 - e).abs() < T_TOL && (e2 - 40.0).abs() < T_TOL,
        "follow [{s2}, {e2}]"
    );
    assert!((r.at(40.0, "lead").s - 950.0).abs() < 1e-9);
    assert!(
        (between(40.0) - 30.0).abs() < REACHED,
        "{} m at 40 s",
        between(40.0)
    );
    assert!((r.at(40.0, "ego").speed - 20.0).abs() < 0.05);
}
