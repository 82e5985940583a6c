//! The timed NURBS of esmini's trajectory-test.xosc (OpenSCENARIO 1.3 §6.9, XSD `Nurbs`: order
//! 3, five control points given relative to the entity "Target", with weights and times,
//! knots 0 0 0 ⅓ ⅔ 1 1 1; Timing relative, scale 1) against esmini 3.6.0's run
//! (shared/corpus/reference/esmini/trajectory-test.csv).
//!
//! The path agrees: every position esmini's Target took while following it lies within 1 mm
//! of the curve oscsim builds. The timing is read differently, on purpose: oscsim takes
//! `ControlPoint/@time` as a further coordinate of the rational curve (the XSD calls it the
//! control point's time dimension), while esmini pins each control point's time to the
//! parameter where its basis function peaks and interpolates linearly in the parameter
//! between them; positions at one moment therefore differ along the path (up to about 6 m
//! here), but both start at 0 s and end at the last control point's 12.2 s.

use crate::runtime_support;
use crate::trajectory_support;

use engine::trajectory::{build, TrajectoryClock};
use opendrive::Pose;
use runtime_support::esmini_reference;
use trajectory_support::{corpus_scenario, follow_trajectory_of, scenario_roads, Placed};

#[test]
fn timed_nurbs_follows_esmini() {
    let sc = corpus_scenario("esmini/xosc/trajectory-test.xosc");
    let (trajectory, time_reference, pos) = follow_trajectory_of(&sc, "FollowTrajectoryNurbsEvent");
    let roads = scenario_roads(&sc);
    // Target at 12.0 s, when the event starts (reference row).
    let start = Pose {
        x: 201.282,
        y: 80.491,
        z: -2.297,
        h: 1.285,
        ..Pose::default()
    };
    let world = Placed::new(roads, "Target", start);
    let t = build(trajectory, &world, pos).unwrap();
    let clock = TrajectoryClock::new(&time_reference.expect("Timing"), 12.0, pos).unwrap();
    let mut worst: f64 = 0.0;
    let mut rows = 0;
    for row in esmini_reference("trajectory-test") {
        if row.name != "Target" || !(12.05..24.1).contains(&row.time) {
            continue;
        }
        worst = worst.max(t.closest(row.x, row.y).distance);
        rows += 1;
    }
    assert_eq!(rows, 120);
    // Rows are rounded to 0.5 mm; the start pose too (and its heading to 0.5 mrad).
    assert!(worst < 1e-3, "largest distance from the curve: {worst} m");
    // Clamped knots: the curve and its time start at control point 1 (0 s) and end at
    // control point 5 (12.2 s), i.e. at 12 s and 24.2 s of simulation time.
    assert!((t.simulation_time_at(&clock, 0.0).unwrap() - 12.0).abs() < 1e-12);
    assert!((t.simulation_time_at(&clock, t.length()).unwrap() - 24.2).abs() < 1e-9);
}
