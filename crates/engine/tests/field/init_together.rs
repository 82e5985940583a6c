//! Issue 34 class 1 — the Init's actions take effect together (OpenSCENARIO 1.3 §7.2.1: the
//! Init "sets the initial states of the scenario elements, such as the position and speed of
//! instances of Entity"; it has no order of its own). A position or speed relative to another
//! entity resolves against that entity's initial one wherever its Private stands in the file
//! (`scenario::init_order`); only a true cycle is an error, at load, naming both entities.
//!
//! Fixture `init_together.xosc`, after ASAM's SlowPrecedingVehicle example, on
//! `straight_500m.xodr` (road 1 along +x, lane -1 3.07 m wide, its centre at y = −1.535):
//! Ego's Private comes first, with a RelativeTargetSpeed of A1 + 5 m/s and a
//! RelativeLanePosition 50 m behind A1; A1's Private follows with 20 m/s and LanePosition
//! lane -1, s = 100.

use crate::support::{file, load, run};

/// A straight road: closed forms up to round-off.
const POS_TOL: f64 = 1e-6;
const SPEED_TOL: f64 = 1e-9;

#[test]
fn positions_and_speeds_relative_to_an_entity_placed_later_in_the_file_resolve() {
    let (_, rows, _) = run("init_together.xosc", &[]);
    // t = 0: A1 at s = 100 on lane -1's centre, Ego at s = 100 − 50 = 50 in the same lane,
    // Ego at A1's initial speed + 5 = 25 m/s.
    let a1 = rows.at("A1", 0.0);
    let ego = rows.at("Ego", 0.0);
    assert!((a1.x - 100.0).abs() < POS_TOL && (a1.y + 1.535).abs() < POS_TOL);
    assert!((ego.x - 50.0).abs() < POS_TOL && (ego.y + 1.535).abs() < POS_TOL);
    assert!((a1.speed - 20.0).abs() < SPEED_TOL && (ego.speed - 25.0).abs() < SPEED_TOL);
    // t = 2 s at constant speeds: Ego x = 50 + 25 · 2 = 100, A1 x = 100 + 20 · 2 = 140.
    assert!((rows.at("Ego", 2.0).x - 100.0).abs() < POS_TOL);
    assert!((rows.at("A1", 2.0).x - 140.0).abs() < POS_TOL);
}

#[test]
fn init_actions_that_refer_to_each_other_in_a_cycle_are_a_load_error_naming_both() {
    // Ego 50 m behind A1, A1 50 m ahead of Ego: no order places either first.
    let Err(err) = load("init_cycle.xosc", &[]) else {
        panic!("init_cycle.xosc loads, expected a load error");
    };
    let at = format!("{}:36:", file("init_cycle.xosc").display());
    assert_eq!(
        err.split(" at ").next().unwrap_or_default(),
        "expected Init actions whose positions and speeds can be resolved in some order, \
         found a cycle Ego's TeleportAction → A1's TeleportAction → Ego",
        "{err}"
    );
    assert!(err.contains(&at), "{err}");
}
