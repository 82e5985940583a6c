//! Class 1 — `::`-qualified storyboard references (OpenSCENARIO 1.1 User Guide §1.4.5
//! "Naming conventions for OpenSCENARIO references", kept in 1.3's "Naming" and
//! "References"; `scenario::names`): a reference is a name, optionally preceded by the names of
//! enclosing elements separated by `::`; it designates the elements of its type whose name path
//! ends with it (a leading `::` asks for the whole path). It must designate exactly one;
//! an ambiguous or unknown reference is refused at load with file:line:col.
//!
//! Fixture `qualified_names.xosc`: Maneuvers Slow and Fast of ManeuverGroup MG each hold an
//! Event "Go"; Watch::Mark starts on the end transition of the Event `$Ref` names. Ego drives
//! at 10 m/s; Slow::Go (from t = 1 s) reaches 5 m/s after its 1 s linear ramp, at t = 2 s;
//! Fast::Go (from t = 3 s) reaches 20 m/s after 2 s, at t = 5 s. An end reached at the end of
//! the step [t − 0.05, t] is logged with the step's start, t − 0.05; Mark (after both in
//! document order) sees it in the next step, at t.

use engine::storyboard::Transition;

use crate::support::{load, run, transitions};

/// Within one step of 0.05 s summed in floating point.
const TIME_TOL: f64 = 1e-6;

fn mark_start(reference: &str) -> (Vec<f64>, Vec<f64>) {
    let (_, _, events) = run("qualified_names.xosc", &[("Ref", reference)]);
    (
        transitions(&events, "Go", Transition::End),
        transitions(&events, "Mark", Transition::Start),
    )
}

#[test]
fn a_prefixed_name_picks_its_maneuvers_event() {
    // Both Events end: Slow::Go logged at 1.95 s, Fast::Go at 4.95 s.
    let (go_ends, mark) = mark_start("Fast::Go");
    assert_eq!(go_ends.len(), 2);
    assert!((go_ends[0] - 1.95).abs() < TIME_TOL, "{go_ends:?}");
    assert!((go_ends[1] - 4.95).abs() < TIME_TOL, "{go_ends:?}");
    // Fast::Go's end at t = 5 s starts Mark then; Slow::Go's end (t = 2 s) does not.
    assert_eq!(mark.len(), 1, "{mark:?}");
    assert!((mark[0] - 5.0).abs() < TIME_TOL, "{mark:?}");

    let (_, mark) = mark_start("Slow::Go");
    assert_eq!(mark.len(), 1, "{mark:?}");
    assert!((mark[0] - 2.0).abs() < TIME_TOL, "{mark:?}");
}

#[test]
fn a_leading_separator_names_the_whole_path() {
    let (_, mark) = mark_start("::S::A::MG::Fast::Go");
    assert_eq!(mark.len(), 1);
    assert!((mark[0] - 5.0).abs() < TIME_TOL, "{mark:?}");
    // Absolute but not the whole path: MG::Fast::Go is a suffix, not a path from the Story.
    let err = load("qualified_names.xosc", &[("Ref", "::MG::Fast::Go")]).err();
    assert!(
        err.as_deref()
            .is_some_and(|e| e.contains("named '::MG::Fast::Go', found none")),
        "{err:?}"
    );
}

#[test]
fn an_ambiguous_or_unknown_reference_is_refused_at_load_with_its_place() {
    // The Condition OnEnd is written at line 97, column 17 of the fixture.
    let err = load("qualified_names.xosc", &[("Ref", "Go")]).expect_err("ambiguous");
    assert!(
        err.contains(
            "expected 'Go' to name one storyboard element of type event, found 2 \
             (S::A::MG::Slow::Go, S::A::MG::Fast::Go); prefix it with enclosing names \
             (Maneuver::Event) at "
        ) && err.ends_with("qualified_names.xosc:97:17"),
        "{err}"
    );
    // MG is not the Events' parent, so MG::Go is no suffix of either path.
    let err = load("qualified_names.xosc", &[("Ref", "MG::Go")]).expect_err("unknown");
    assert!(
        err.contains("expected a storyboard element of type event named 'MG::Go', found none at ")
            && err.ends_with("qualified_names.xosc:97:17"),
        "{err}"
    );
}

#[test]
fn a_reference_is_looked_for_from_where_it_is_written_outwards() {
    // qualified_names_scope.xosc: ManeuverGroups G1 and G2 hold the same Maneuver M; each
    // M::E2 starts on the end of "E1". Car1's E1 (t = 1 s, 10 → 5 m/s in 1 s) ends at 2 s,
    // Car2's E1 (t = 3 s, 10 → 20 m/s in 1 s) at 4 s; each E2 follows its own group's E1.
    let (_, _, events) = run("qualified_names_scope.xosc", &[]);
    let e2 = transitions(&events, "E2", Transition::Start);
    assert_eq!(e2.len(), 2, "{e2:?}");
    assert!((e2[0] - 2.0).abs() < TIME_TOL, "{e2:?}");
    assert!((e2[1] - 4.0).abs() < TIME_TOL, "{e2:?}");
}
