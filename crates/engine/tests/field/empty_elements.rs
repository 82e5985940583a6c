//! Issue 34 class 2 — empty elements in ASAM's own examples. The XSD requires a choice in
//! `ObjectController` (CatalogReference or Controller); ASAM's 1.2 SimpleOvertake writes
//! `<ObjectController/>`. Where an empty element names nothing, nothing is lost: it is read
//! with a warning (file:line:col) and the run goes on as if it were absent, as the project
//! already does for an empty `<Action/>` (issue 16, `empty_action.xosc`).
//!
//! Fixture `empty_object_controller.xosc`: Ego with `<ObjectController/>` on
//! `straight_500m.xodr`, lane -1 from s = 10 at 10 m/s for 2 s.

use crate::support::{file, run};

/// A straight road: closed forms up to round-off.
const POS_TOL: f64 = 1e-6;

#[test]
fn an_empty_object_controller_is_read_with_a_warning_as_no_controller() {
    let path = file("empty_object_controller.xosc");
    let scenario = scenario::Scenario::load(&path).expect("loads");
    let warnings: Vec<String> = scenario.warnings.iter().map(|w| w.to_string()).collect();
    assert_eq!(
        warnings,
        [format!(
            "ObjectController has none of CatalogReference, Controller; it is read as no \
             controller (the default controller drives) at {}:20:7",
            path.display()
        )]
    );
    let ego = &scenario.entities.scenario_objects[0];
    assert!(ego.object_controllers.is_empty());
    // The default controller keeps the Init speed: x = 10 + 10 · 2 = 30 m at t = 2 s.
    let (_, rows, _) = run("empty_object_controller.xosc", &[]);
    assert!((rows.at("Ego", 2.0).x - 30.0).abs() < POS_TOL);
}
