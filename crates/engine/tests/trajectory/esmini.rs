//! The ClothoidSpline trajectories of esmini's lane-change_clothoid_spline_based_trajectory.xosc
//! (OpenSCENARIO 1.3 §6.9, XSD `ClothoidSpline`, `ClothoidSplineSegment`, `Timing`), loaded
//! with the scenario crate and checked against hand computations and against esmini 3.6.0's
//! run of the same scenario (shared/corpus/reference/esmini/…csv: 0.1 s rows, 3 decimals).
//! The car drives at 30 km/h = 8.333 m/s; each trajectory starts at the car's pose when its
//! event starts (times from the reference's events.txt).

use crate::trajectory_support;

use engine::trajectory::{build_for_actor, Trajectory, TrajectoryClock};
use opendrive::Pose;
use trajectory_support::{corpus_scenario, follow_trajectory_of, scenario_roads, Placed};

/// The CSV's start poses and end points are rounded to 0.5 mm each; agreement within 2 mm
/// (found: 0.4 mm at most).
const REF_TOL: f64 = 0.002;

/// The trajectory of event `event`, built with the car at `car`.
fn trajectory_of(event: &str, car: Pose) -> (Trajectory, Option<scenario::Timing>) {
    let sc = corpus_scenario("esmini/xosc/lane-change_clothoid_spline_based_trajectory.xosc");
    let (trajectory, time_reference, pos) = follow_trajectory_of(&sc, event);
    let world = Placed::new(scenario_roads(&sc), "Car", car);
    let t = build_for_actor(trajectory, &world, Some(&car), pos).unwrap();
    (t, time_reference)
}

fn at(x: f64, y: f64, h: f64) -> Pose {
    Pose {
        x,
        y,
        h,
        ..Pose::default()
    }
}

#[test]
fn lane_change_of_two_arcs_and_a_line() {
    // Arc κ = 1/100 for 15 m (turns 0.15 rad), line 5 m, arc κ = −1/100 for 15 m. Lateral
    // shift: 2·100·(1 − cos 0.15) + 5·sin 0.15 = 2.245784… + 0.747191… = 2.992975 m; forward:
    // 2·100·sin 0.15 + 5·cos 0.15 = 34.831518 m; end heading 0. From the car on lane −1
    // (y = −1.535) the end is at y = 1.457975: esmini's y after the action (6.3 s) is 1.458.
    let x0 = 67.083;
    let (t, time_reference) = trajectory_of("LaneChangeEvent", at(x0, -1.535, 0.0));
    assert!(time_reference.is_none());
    assert!((t.length() - 35.0).abs() < 1e-12);
    let lateral = 200.0 * (1.0 - 0.15f64.cos()) + 5.0 * 0.15f64.sin();
    let forward = 200.0 * 0.15f64.sin() + 5.0 * 0.15f64.cos();
    let end = t.eval(t.length());
    assert!((end.y - (-1.535 + lateral)).abs() < 1e-9, "{end:?}");
    assert!((end.x - (x0 + forward)).abs() < 1e-9, "{end:?}");
    assert!(end.heading.abs() < 1e-12);
    assert!((end.y - 1.458).abs() < REF_TOL);
}

#[test]
fn single_clothoid_pair_starts_at_the_car() {
    // No PositionStart: the spline starts where the car is at 8.3 s (esmini: (118.998,
    // 1.458), heading 0). Heading change: (0 − 0.08)/2·5 + (−0.08 + 0.12)/2·10.5 = −0.2 + 0.21
    // = 0.01 rad, esmini's heading after the action. esmini ends the action at 10.1 s at
    // (134.048, −1.663).
    let (t, _) = trajectory_of("SingleClothoidEvent", at(118.998, 1.458, 0.0));
    let end = t.eval(t.length());
    assert!((end.heading - 0.01).abs() < 1e-12, "{end:?}");
    assert!(
        (end.x - 134.048).abs() < REF_TOL && (end.y + 1.663).abs() < REF_TOL,
        "{end:?}"
    );
}

#[test]
fn discontinuous_heading_adds_h_offset_to_the_start_orientation() {
    // Segment 2 starts at the car's (9.94, −1.0) with relative heading 0.2, plus hOffset 0.4;
    // segment 3 turns by −0.14/2·8.9 = −0.623 rad, so the end heading is
    // 0.01 + 0.2 + 0.4 − 0.623 = −0.013 rad (esmini: 6.270 = 2π − 0.0132). The car is at
    // (151.048, −1.660) heading 0.01 at 12.2 s; esmini's end point is (170.683, 2.016).
    let (t, _) = trajectory_of("DiscontinuousHeadingEvent", at(151.048, -1.660, 0.01));
    assert!((t.length() - 20.9).abs() < 1e-12);
    let end = t.eval(t.length());
    assert!((end.heading + 0.013).abs() < 1e-12, "{end:?}");
    assert!(
        (end.x - 170.683).abs() < REF_TOL && (end.y - 2.016).abs() < REF_TOL,
        "{end:?}"
    );
}

#[test]
fn timestamps_set_the_speed_per_segment() {
    // Segments of 10, 14, 10 and 6.5 m starting at 0, 2, 4 and 7 s, timeEnd 8 s; Timing
    // relative, scale 1, offset 0, action started at 18.75 s. Speeds: 10/2 = 5, 14/2 = 7,
    // 10/3 = 3.333, 6.5/1 = 6.5 m/s, which esmini reports at 19.5, 21.5, 24.0 and 26.5 s.
    let (t, time_reference) = trajectory_of("TrajectoryWithTimestamps", at(204.0, 2.011, 0.0));
    let timing = time_reference.expect("Timing");
    let clock = TrajectoryClock::new(&timing, 18.75, &trajectory_support::here()).unwrap();
    for (time, esmini) in [(19.5, 5.0), (21.5, 7.0), (24.0, 3.333), (26.5, 6.5)] {
        let v = t.speed_at_simulation_time(&clock, time).unwrap();
        assert!(
            (v - esmini).abs() < 1e-3,
            "{time} s: {v} m/s, esmini {esmini}"
        );
    }
    // The end (40.5 m) is reached at 18.75 + 8 = 26.75 s.
    assert!((t.simulation_time_at(&clock, t.length()).unwrap() - 26.75).abs() < 1e-12);
}
