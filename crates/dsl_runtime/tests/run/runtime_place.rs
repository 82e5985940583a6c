//! `change_position` in phases that start on a run-time condition (ASAM OpenSCENARIO DSL 2.1
//! §8.8.2.11): the path starts where the engine finds the actor, and ends as at a known start.
//! Every moment is worked by hand in the scenario file.

use super::runtime::phases;
use super::support::run;

/// Positions on the straight road: exact up to float round-off.
const S_TOL: f64 = 1e-6;
/// Headings: the polyline's vertex headings, exact up to float round-off.
const H_TOL: f64 = 1e-9;

/// runtime_place_heading.osc's comment, by hand: the line from (167, −8.75) m to
/// (191, −1.75) m at 20 m/s faces atan(7/24) until it ends at 4.6 s; then ego faces along
/// lane -1 (h = 0) and drives on along its centre.
#[test]
fn after_a_straight_change_position_after_an_until_the_actor_faces_along_its_lane() {
    let r = run("runtime_place_heading", 0, None);
    phases(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.cut", 3.35, 4.6),
            ("do.on", 4.6, 5.6),
        ],
    );
    let along = 7.0_f64.atan2(24.0);
    for (t, x, y, h) in [
        (3.35, 167.0, -8.75, 0.0),
        (4.1, 181.4, -4.55, along),
        (4.6, 191.0, -1.75, 0.0),
        (5.1, 201.0, -1.75, 0.0),
        (5.6, 211.0, -1.75, 0.0),
    ] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.x - x).abs() < S_TOL && (ego.y - y).abs() < S_TOL && (ego.h - h).abs() < H_TOL,
            "{t}: {ego:?}, want ({x}, {y}) facing {h}"
        );
    }
    assert_eq!(r.at(5.6, "ego").lane, -1);
}
