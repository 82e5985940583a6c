//! Bad trajectories give clear errors, never panics (OpenSCENARIO 1.3 §6.9 "Trajectories";
//! XSD `Polyline`: a line needs two vertices; `Nurbs`: order, a knot vector of (control
//! points plus order) non-decreasing values; `Timing/@scale`). Each message is checked
//! in full: what was expected, what was found, and where.

use crate::trajectory_support;

use engine::position::PositionErrorKind;
use engine::trajectory::{build, TrajectoryClock, TrajectoryErrorKind};
use scenario::{ClothoidSpline, ClothoidSplineSegment, Shape};
use trajectory_support::{here, nurbs, polyline, straight, timing, trajectory, world};

/// The error of the shape (the build's error is the position resolver's, which holds it).
fn error(shape: Shape) -> engine::trajectory::TrajectoryError {
    match build(&trajectory(shape, false), &straight(), &here()) {
        Ok(t) => panic!("expected an error, built {t:?}"),
        Err(e) => match e.kind() {
            PositionErrorKind::Trajectory(shape) => shape.clone(),
            _ => panic!("expected an error of the shape, found {e}"),
        },
    }
}

/// Four control points on a line for order-2 NURBS tests.
const LINE4: [(f64, f64, Option<f64>, Option<f64>); 4] = [
    (0.0, 0.0, None, None),
    (10.0, 0.0, None, None),
    (20.0, 0.0, None, None),
    (30.0, 0.0, None, None),
];

#[test]
fn polyline_with_one_vertex() {
    let e = error(polyline(&[(0.0, 0.0, None)]));
    assert_eq!(
        e.to_string(),
        "expected at least 2 vertices in Polyline of trajectory \"T\", found 1 at test.xosc:3:5"
    );
    assert!(matches!(
        e.kind(),
        TrajectoryErrorKind::TooFewVertices { found: 1, .. }
    ));
    let e = error(polyline(&[]));
    assert!(matches!(
        e.kind(),
        TrajectoryErrorKind::TooFewVertices { found: 0, .. }
    ));
}

#[test]
fn polyline_whose_vertices_coincide() {
    let e = error(polyline(&[(5.0, 5.0, None), (5.0, 5.0, None)]));
    assert_eq!(
        e.to_string(),
        "expected a trajectory of positive length, found length 0 m at test.xosc:3:5"
    );
}

#[test]
fn knots_out_of_order() {
    // Knot 4 (1.0) is below knot 3 (2.0).
    let e = error(nurbs(2, &LINE4, &[0.0, 0.0, 2.0, 1.0, 3.0, 3.0]));
    assert_eq!(
        e.to_string(),
        "expected Knot 4 >= 2 (knots in non-decreasing order), found 1 at test.xosc:3:5"
    );
}

#[test]
fn wrong_number_of_knots() {
    let e = error(nurbs(2, &LINE4, &[0.0, 0.0, 1.0, 2.0, 2.0]));
    assert_eq!(
        e.to_string(),
        "expected 6 Knots (control points + order), found 5 at test.xosc:3:5"
    );
}

#[test]
fn order_beyond_the_control_points() {
    let e = error(nurbs(5, &LINE4, &[0.0; 9]));
    assert_eq!(
        e.to_string(),
        "expected Nurbs order in 2..=4 (2 to the number of control points), found 5 at test.xosc:3:5"
    );
    let e = error(nurbs(1, &LINE4, &[0.0, 1.0, 2.0, 3.0, 4.0]));
    assert!(matches!(
        e.kind(),
        TrajectoryErrorKind::Order {
            order: 1,
            points: 4
        }
    ));
}

#[test]
fn knots_spanning_no_range() {
    // Order 2, 4 points: the curve runs over knots 2..5 (1-based), all 1 here.
    let e = error(nurbs(2, &LINE4, &[0.0, 1.0, 1.0, 1.0, 1.0, 2.0]));
    assert_eq!(
        e.to_string(),
        "expected Knots spanning a parameter range (knot 2 < knot 5), found both 1 at test.xosc:3:5"
    );
}

#[test]
fn zero_weight_names_its_control_point() {
    let mut pts = LINE4;
    pts[2].2 = Some(0.0);
    let e = error(nurbs(2, &pts, &[0.0, 0.0, 1.0, 2.0, 3.0, 3.0]));
    // Control point 3 is written on line 22 of the test file.
    assert_eq!(
        e.to_string(),
        "expected ControlPoint 3 weight > 0, found 0 at test.xosc:22:5"
    );
}

#[test]
fn nan_knot_is_an_error() {
    let e = error(nurbs(2, &LINE4, &[0.0, 0.0, f64::NAN, 2.0, 3.0, 3.0]));
    assert_eq!(
        e.to_string(),
        "expected a finite Knot value, found NaN at test.xosc:3:5"
    );
}

#[test]
fn times_on_some_vertices_only() {
    let e = error(polyline(&[
        (0.0, 0.0, Some(0.0)),
        (10.0, 0.0, None),
        (20.0, 0.0, Some(2.0)),
    ]));
    // Vertex 2 is written on line 11.
    assert_eq!(
        e.to_string(),
        "expected a time on every Vertex once one has a time, found none on Vertex 2 at test.xosc:11:5"
    );
}

#[test]
fn times_going_back() {
    let e = error(polyline(&[(0.0, 0.0, Some(3.0)), (10.0, 0.0, Some(1.0))]));
    assert_eq!(
        e.to_string(),
        "expected the time of Vertex 2 >= 3 s, found 1 s at test.xosc:11:5"
    );
}

#[test]
fn clothoid_spline_without_start_position() {
    let e = error(Shape::ClothoidSpline(ClothoidSpline {
        time_end: None,
        segments: vec![ClothoidSplineSegment {
            curvature_start: 0.0,
            curvature_end: 0.0,
            length: 10.0,
            h_offset: None,
            time_start: None,
            position_start: None,
        }],
    }));
    assert_eq!(
        e.to_string(),
        "expected a PositionStart on the first ClothoidSplineSegment, found none at test.xosc:3:5"
    );
    let e = error(Shape::ClothoidSpline(ClothoidSpline {
        time_end: None,
        segments: vec![],
    }));
    assert!(matches!(e.kind(), TrajectoryErrorKind::NoSegments));
}

#[test]
fn clothoid_of_no_length() {
    let e = error(Shape::Clothoid(scenario::Clothoid {
        curvature: 0.0,
        curvature_prime: 0.0,
        length: 0.0,
        start_time: None,
        stop_time: None,
        position: world(0.0, 0.0),
    }));
    assert_eq!(
        e.to_string(),
        "expected Clothoid length > 0, found 0 at test.xosc:3:5"
    );
}

#[test]
fn timing_with_zero_scale() {
    let e = TrajectoryClock::new(&timing(true, 0.0, 0.0), 0.0, &here()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "expected Timing scale > 0, found 0 at test.xosc:3:5"
    );
}

/// A straight ClothoidSpline segment of `length` m starting at `time` (the first at the
/// origin).
fn timed_segment(length: f64, time: Option<f64>, first: bool) -> ClothoidSplineSegment {
    ClothoidSplineSegment {
        curvature_start: 0.0,
        curvature_end: 0.0,
        length,
        h_offset: None,
        time_start: time,
        position_start: first.then(|| world(0.0, 0.0)),
    }
}

#[test]
fn clothoid_spline_with_a_time_needs_time_end() {
    // 1.3 XSD ClothoidSpline/@timeEnd: required once a segment has timeStart (one timed
    // segment of two is enough to ask for it).
    let e = error(Shape::ClothoidSpline(ClothoidSpline {
        time_end: None,
        segments: vec![
            timed_segment(10.0, None, true),
            timed_segment(10.0, Some(2.0), false),
        ],
    }));
    assert_eq!(
        e.to_string(),
        "expected ClothoidSpline timeEnd when its segments have timeStart, found none at test.xosc:3:5"
    );
}

#[test]
fn clothoid_spline_times_going_back() {
    // Segment 3 starts at 1 s, before segment 1's 4 s (segment 2 has no time); and a timeEnd
    // before the last timeStart.
    let e = error(Shape::ClothoidSpline(ClothoidSpline {
        time_end: Some(9.0),
        segments: vec![
            timed_segment(10.0, Some(4.0), true),
            timed_segment(10.0, None, false),
            timed_segment(10.0, Some(1.0), false),
        ],
    }));
    assert!(
        matches!(
            e.kind(),
            TrajectoryErrorKind::TimesOutOfOrder { index: 3, .. }
        ),
        "{e}"
    );
    assert_eq!(
        e.to_string(),
        "expected the time of ClothoidSplineSegment 3 >= 4 s, found 1 s at test.xosc:3:5"
    );
    let e = error(Shape::ClothoidSpline(ClothoidSpline {
        time_end: Some(3.0),
        segments: vec![
            timed_segment(10.0, Some(0.0), true),
            timed_segment(10.0, Some(5.0), false),
        ],
    }));
    assert_eq!(
        e.to_string(),
        "expected ClothoidSpline timeEnd >= 5 s (the last timeStart), found 3 s at test.xosc:3:5"
    );
}
