//! Times along trajectories and the TimeReference/Timing rules (OpenSCENARIO 1.3 §6.9,
//! XSD `Vertex/@time`, `Clothoid/@startTime`/`@stopTime`, `ClothoidSplineSegment/@timeStart`,
//! `ControlPoint/@time`, `Timing`: t_sim = t_traj · scale + offset, absolute or relative to
//! the action's start), and the closest point used for initialDistanceOffset and follow mode.

use crate::trajectory_support;

use std::f64::consts::{FRAC_PI_2, PI};

use engine::trajectory::{build, controls_longitudinal, Trajectory, TrajectoryClock};
use scenario::{ClothoidSpline, ClothoidSplineSegment, Shape};
use trajectory_support::{arc, here, nurbs, polyline, straight, timing, trajectory, world};

fn built(shape: Shape) -> Trajectory {
    // Every shape in this file is valid; a failure is the bug under test.
    build(&trajectory(shape, false), &straight(), &here()).expect("valid trajectory")
}

/// (0,0) at 0 s → (30,40) at 5 s (50 m, 10 m/s) → (30,100) at 8 s (60 m, 20 m/s).
fn timed_polyline() -> Trajectory {
    built(polyline(&[
        (0.0, 0.0, Some(0.0)),
        (30.0, 40.0, Some(5.0)),
        (30.0, 100.0, Some(8.0)),
    ]))
}

#[test]
fn polyline_with_times_is_reached_on_time() {
    let t = timed_polyline();
    assert!(t.has_times());
    assert_eq!(t.time_range(), Some((0.0, 8.0)));
    // Linear between vertices: 2.5 s → 25 m → (15, 20); 6.5 s → 50 + 1.5·20 = 80 m → (30, 70).
    let s = t.s_at_time(2.5).unwrap();
    assert!((s - 25.0).abs() < 1e-12);
    let p = t.eval(t.s_at_time(6.5).unwrap());
    assert!((p.x - 30.0).abs() < 1e-12 && (p.y - 70.0).abs() < 1e-12);
    // The middle vertex is reached at 5 s.
    assert!((t.time_at(50.0).unwrap() - 5.0).abs() < 1e-12);
}

#[test]
fn relative_timing_with_scale_and_offset_reaches_each_vertex_on_time() {
    // Relative, scale 2, offset 1, action started at 10 s: vertex k with time t_k is reached
    // at 10 + 1 + 2·t_k, i.e. 11 s, 21 s and 27 s. Stepping the clock at 0.05 s from the
    // action's start, the entity stands on vertex (30, 40) at 21 s and on the last at 27 s.
    let t = timed_polyline();
    let clock = TrajectoryClock::new(&timing(false, 2.0, 1.0), 10.0, &here()).unwrap();
    let mut at_21 = None;
    for step in 0..=400 {
        let now = 10.0 + 0.05 * step as f64;
        let p = t.eval(t.s_at_simulation_time(&clock, now).unwrap());
        if (now - 21.0).abs() < 1e-9 {
            at_21 = Some(p);
        }
    }
    let p = at_21.unwrap();
    assert!(
        (p.x - 30.0).abs() < 1e-9 && (p.y - 40.0).abs() < 1e-9,
        "{p:?}"
    );
    assert!((t.s_at_simulation_time(&clock, 27.0).unwrap() - 110.0).abs() < 1e-9);
    // Before the first vertex's time (11 s) the entity waits at the start.
    assert!(t.s_at_simulation_time(&clock, 10.5).unwrap().abs() < 1e-12);
    // Speed: 10 m/s of trajectory time on the first segment, halved by scale 2.
    assert!((t.speed_at_simulation_time(&clock, 15.0).unwrap() - 5.0).abs() < 1e-12);
    assert!((t.simulation_time_at(&clock, 50.0).unwrap() - 21.0).abs() < 1e-12);
}

#[test]
fn absolute_timing_ignores_the_action_start() {
    // Absolute, scale 1, offset 3: vertex (30, 40) at 5 + 3 = 8 s whenever the action began.
    let t = timed_polyline();
    let clock = TrajectoryClock::new(&timing(true, 1.0, 3.0), 6.0, &here()).unwrap();
    assert!((t.s_at_simulation_time(&clock, 8.0).unwrap() - 50.0).abs() < 1e-12);
    assert!((clock.simulation_time(8.0) - 11.0).abs() < 1e-12);
}

#[test]
fn without_time_reference_only_the_lateral_domain_is_controlled() {
    // §6.9 / semantics-pitfalls #7: TimeReference/None → lateral only.
    assert!(!controls_longitudinal(None));
    assert!(controls_longitudinal(Some(&timing(true, 1.0, 0.0))));
    // An untimed shape has no s(t).
    let t = built(polyline(&[(0.0, 0.0, None), (10.0, 0.0, None)]));
    assert!(!t.has_times() && t.s_at_time(1.0).is_none());
}

#[test]
fn clothoid_spline_times_per_segment() {
    // Segment 1: 20 m from 0 s to 2 s; segment 2: quarter circle 50π m from 2 s to timeEnd
    // 4 s. At 3 s the point is half-way round the quarter circle of radius 100 about
    // (20, 100): (20 + 100·sin(π/4), 100 − 100·cos(π/4)).
    let seg = |k: f64, length: f64, time: f64| ClothoidSplineSegment {
        curvature_start: k,
        curvature_end: k,
        length,
        h_offset: None,
        time_start: Some(time),
        position_start: None,
    };
    let mut first = seg(0.0, 20.0, 0.0);
    first.position_start = Some(world(0.0, 0.0));
    let t = built(Shape::ClothoidSpline(ClothoidSpline {
        time_end: Some(4.0),
        segments: vec![first, seg(0.01, 50.0 * PI, 2.0)],
    }));
    let s = t.s_at_time(3.0).unwrap();
    assert!((s - (20.0 + 25.0 * PI)).abs() < 1e-9);
    let p = t.eval(s);
    let r = 100.0 * std::f64::consts::FRAC_PI_4.sin();
    assert!(
        (p.x - (20.0 + r)).abs() < 1e-9 && (p.y - (100.0 - r)).abs() < 1e-9,
        "{p:?}"
    );
}

#[test]
fn nurbs_control_point_times_of_degree_one_match_the_polyline() {
    // Degree 1 on knots (0,0,1,2,2): t is linear in u on each span, and so is s; so the times
    // are those of the polyline with vertex times 0, 5, 8: s = 80 at 6.5 s.
    let t = built(nurbs(
        2,
        &[
            (0.0, 0.0, None, Some(0.0)),
            (30.0, 40.0, None, Some(5.0)),
            (30.0, 100.0, None, Some(8.0)),
        ],
        &[0.0, 0.0, 1.0, 2.0, 2.0],
    ));
    assert!((t.s_at_time(6.5).unwrap() - 80.0).abs() < 1e-8);
    assert!((t.time_at(25.0).unwrap() - 2.5).abs() < 1e-8);
}

#[test]
fn closest_point_on_a_polyline_with_lateral_offset() {
    // (0,0) → (100,0) → (100,100). (50, 3) is 3 m left of s = 50; (103, 40) is 3 m right of
    // the second segment (heading +y) at s = 140.
    let t = built(polyline(&[
        (0.0, 0.0, None),
        (100.0, 0.0, None),
        (100.0, 100.0, None),
    ]));
    let c = t.closest(50.0, 3.0);
    assert!((c.point.s - 50.0).abs() < 1e-8 && (c.distance - 3.0).abs() < 1e-8);
    assert!((c.t - 3.0).abs() < 1e-8);
    let c = t.closest(103.0, 40.0);
    assert!(
        (c.point.s - 140.0).abs() < 1e-8 && (c.t + 3.0).abs() < 1e-8,
        "{c:?}"
    );
}

#[test]
fn closest_point_on_an_arc() {
    // Quarter circle of radius 100 about (0, 100) from the origin heading 0 (κ = 0.01). The
    // point 105 m from the centre in the direction of arc angle 0.5 rad lies 5 m outside
    // (to the right) of s = 50: (105·sin 0.5, 100 − 105·cos 0.5).
    let t = built(arc(0.01, 50.0 * PI, world(0.0, 0.0)));
    let c = t.closest(105.0 * 0.5f64.sin(), 100.0 - 105.0 * 0.5f64.cos());
    assert!((c.point.s - 50.0).abs() < 1e-6, "{c:?}");
    assert!((c.distance - 5.0).abs() < 1e-9 && (c.t + 5.0).abs() < 1e-9);
    assert!((c.point.heading - 0.5).abs() < 1e-8);
    // A point beyond the end is closest to the end (s = 50π, heading π/2).
    let c = t.closest(100.0, 150.0);
    assert!((c.point.s - 50.0 * PI).abs() < 1e-6 && (c.point.heading - FRAC_PI_2).abs() < 1e-8);
}

#[test]
fn skipping_deducts_the_time_to_the_initial_distance_offset() {
    // FollowTrajectoryAction/@initialDistanceOffset: "the time that would be taken to reach
    // this point is deducted from all calculated waypoint time values". Offset 80 m on the
    // timed polyline is reached at 6.5 s; relative timing, scale 2, offset 1, action started
    // at 10 s: the vertex at 8 s (110 m) is reached at 10 + 1 + 2·(8 − 6.5) = 14 s, and the
    // start of the motion (trajectory time 6.5 s, s = 80 m) at 11 s.
    let t = timed_polyline();
    let skipped = t.time_at(80.0).unwrap() - t.time_at(0.0).unwrap();
    assert!((skipped - 6.5).abs() < 1e-12);
    let clock = TrajectoryClock::new(&timing(false, 2.0, 1.0), 10.0, &here())
        .unwrap()
        .skipping(skipped);
    assert!((t.s_at_simulation_time(&clock, 11.0).unwrap() - 80.0).abs() < 1e-9);
    assert!((t.simulation_time_at(&clock, 110.0).unwrap() - 14.0).abs() < 1e-12);
    // Half-way in simulation time, 12.5 s: trajectory time 6.5 + 1.5/2 = 7.25 s → 95 m.
    assert!((t.s_at_simulation_time(&clock, 12.5).unwrap() - 95.0).abs() < 1e-9);
}

#[test]
fn arrival_speed_is_the_last_interval_over_the_scale() {
    // The last piece of the timed polyline is 60 m from 5 s to 8 s: 20 m/s of trajectory
    // time, 10 m/s of simulation time at scale 2.
    let t = timed_polyline();
    let clock = TrajectoryClock::new(&timing(false, 2.0, 0.0), 0.0, &here()).unwrap();
    assert!((t.arrival_speed(&clock).unwrap() - 10.0).abs() < 1e-12);
    let untimed = built(polyline(&[(0.0, 0.0, None), (10.0, 0.0, None)]));
    assert!(untimed.arrival_speed(&clock).is_none());
}

#[test]
fn clothoid_spline_segments_without_time_run_at_the_speed_between_timed_points() {
    // The 1.3 XSD makes ClothoidSplineSegment/@timeStart optional and asks only for
    // ClothoidSpline/@timeEnd once one is given. Straight segments of 10, 10, 20 and 10 m;
    // timeStart on the second (2 s) and fourth (8 s), timeEnd 10 s. Timed points: (10 m, 2 s),
    // (40 m, 8 s), (50 m, 10 s). The third segment starts at 20 m, a third of the way from
    // 10 m to 40 m: 2 + 6/3 = 4 s. The first segment continues the 5 m/s of the first timed
    // stretch backwards: it starts at 2 − 10/5 = 0 s.
    let seg = |length: f64, time: Option<f64>| ClothoidSplineSegment {
        curvature_start: 0.0,
        curvature_end: 0.0,
        length,
        h_offset: None,
        time_start: time,
        position_start: None,
    };
    let mut first = seg(10.0, None);
    first.position_start = Some(world(0.0, 0.0));
    let t = built(Shape::ClothoidSpline(ClothoidSpline {
        time_end: Some(10.0),
        segments: vec![
            first,
            seg(10.0, Some(2.0)),
            seg(20.0, None),
            seg(10.0, Some(8.0)),
        ],
    }));
    assert_eq!(t.time_range(), Some((0.0, 10.0)));
    assert!((t.time_at(20.0).unwrap() - 4.0).abs() < 1e-12);
    assert!((t.s_at_time(1.0).unwrap() - 5.0).abs() < 1e-12);
    assert!((t.s_at_time(9.0).unwrap() - 45.0).abs() < 1e-12);
}
