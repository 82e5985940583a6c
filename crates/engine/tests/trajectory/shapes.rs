//! Trajectory shapes by arc length (OpenSCENARIO 1.3 §6.9, XSD `Polyline`, `Clothoid`,
//! `ClothoidSpline`, `Nurbs`), against hand computations and closed forms written out at
//! each test.

use crate::trajectory_support;

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_6, PI};

use engine::trajectory::{build, ShapeKind, Trajectory, TrajectoryPoint};
use scenario::{Clothoid, ClothoidSpline, ClothoidSplineSegment, Shape};
use trajectory_support::{arc, here, lane, nurbs, polyline, straight, trajectory, world, world_at};

/// Tolerance of closed-form positions and headings (m, rad).
const TOL: f64 = 1e-9;

fn built(shape: Shape, closed: bool) -> Trajectory {
    // Every shape in this file is valid; a failure is the bug under test.
    build(&trajectory(shape, closed), &straight(), &here()).expect("valid trajectory")
}

fn assert_point(p: TrajectoryPoint, x: f64, y: f64, heading: f64, tol: f64) {
    assert!(
        (p.x - x).abs() < tol && (p.y - y).abs() < tol,
        "expected ({x}, {y}), found {p:?}"
    );
    assert!(
        opendrive::angle_difference(p.heading, heading).abs() < tol,
        "expected heading {heading}, found {p:?}"
    );
}

#[test]
fn polyline_points_by_arc_length() {
    // (0,0) → (30,40): 50 m at heading atan2(40, 30); → (30,100): 60 m at heading π/2.
    let t = built(
        polyline(&[(0.0, 0.0, None), (30.0, 40.0, None), (30.0, 100.0, None)]),
        false,
    );
    assert_eq!(t.kind(), ShapeKind::Polyline);
    assert!((t.length() - 110.0).abs() < TOL);
    let h1 = 40f64.atan2(30.0);
    assert_point(t.eval(25.0), 15.0, 20.0, h1, TOL);
    assert_point(t.eval(80.0), 30.0, 70.0, FRAC_PI_2, TOL);
    assert!(t.eval(80.0).curvature.abs() < TOL);
    // Clamped beyond either end.
    assert_point(t.eval(-5.0), 0.0, 0.0, h1, TOL);
    assert_point(t.eval(500.0), 30.0, 100.0, FRAC_PI_2, TOL);
}

#[test]
fn closed_polyline_returns_to_its_first_vertex() {
    // Square of side 10: the closing side (0,10) → (0,0) makes the length 40; at s = 35 the
    // point is (0, 5) heading −π/2.
    let t = built(
        polyline(&[
            (0.0, 0.0, None),
            (10.0, 0.0, None),
            (10.0, 10.0, None),
            (0.0, 10.0, None),
        ]),
        true,
    );
    assert!((t.length() - 40.0).abs() < TOL);
    assert_point(t.eval(35.0), 0.0, 5.0, -FRAC_PI_2, TOL);
}

#[test]
fn polyline_vertices_from_lane_positions() {
    // esmini straight_500m: lane −1's centre is 1.535 m right of the reference line (+x), so
    // LanePosition(1, −1, s) is (s, −1.535). From s = 10 to the world point (10, 38.465): a
    // 40 m segment heading π/2.
    let shape = Shape::Polyline(vec![
        scenario::Vertex {
            time: None,
            position: lane("1", -1, 10.0),
        },
        scenario::Vertex {
            time: None,
            position: world(10.0, 38.465),
        },
    ]);
    let t = built(shape, false);
    assert!((t.length() - 40.0).abs() < 1e-6);
    assert_point(t.eval(20.0), 10.0, 18.465, FRAC_PI_2, 1e-6);
}

/// Fresnel integrals C(1), S(1) (Abramowitz & Stegun, table 7.7).
const C1: f64 = 0.779_893_400_376_822_8;
const S1: f64 = 0.438_259_147_390_354_8;

#[test]
fn clothoid_end_point_and_heading_from_fresnel_integrals() {
    // κ(s) = κ'·s with κ' = π/L², L = 100: θ(s) = κ's²/2, so θ(L) = π/2 and the end point in
    // the start frame is L·(C(1), S(1)) = (77.98934…, 43.82591…). Start (10, 20), heading π/6:
    // end = (10, 20) + R(π/6)·(77.989…, 43.826…).
    let shape = Shape::Clothoid(Clothoid {
        curvature: 0.0,
        curvature_prime: PI / 1e4,
        length: 100.0,
        start_time: None,
        stop_time: None,
        position: world_at(10.0, 20.0, 1.5, FRAC_PI_6, 3),
    });
    let t = built(shape, false);
    let (u, v) = (100.0 * C1, 100.0 * S1);
    let (sn, cs) = FRAC_PI_6.sin_cos();
    let end = t.eval(100.0);
    assert_point(
        end,
        10.0 + u * cs - v * sn,
        20.0 + u * sn + v * cs,
        FRAC_PI_6 + FRAC_PI_2,
        1e-9,
    );
    // κ(L) = π/100; z stays at the start's 1.5.
    assert!((end.curvature - PI / 100.0).abs() < 1e-12);
    assert!((end.z - 1.5).abs() < 1e-12);
    assert!((t.length() - 100.0).abs() < 1e-12);
}

#[test]
fn clothoid_without_curvature_change_is_an_arc() {
    // κ = 0.01 constant over 50π m: a quarter circle of radius 100 turning left from the
    // origin heading 0, ending at (100, 100) heading π/2; half-way at
    // (100·sin(π/4), 100·(1 − cos(π/4))).
    let t = built(arc(0.01, 50.0 * PI, world(0.0, 0.0)), false);
    assert_point(t.eval(50.0 * PI), 100.0, 100.0, FRAC_PI_2, 1e-9);
    let r = 100.0 * FRAC_PI_4.sin();
    assert_point(t.eval(25.0 * PI), r, 100.0 - r, FRAC_PI_4, 1e-9);
}

fn segment(k0: f64, k1: f64, length: f64, h_offset: Option<f64>) -> ClothoidSplineSegment {
    ClothoidSplineSegment {
        curvature_start: k0,
        curvature_end: k1,
        length,
        h_offset,
        time_start: None,
        position_start: None,
    }
}

#[test]
fn clothoid_spline_segments_continue_from_each_other() {
    // Segment 1: straight 20 m from the origin → (20, 0). Segment 2: κ = 0.01 for 50π m, a
    // quarter circle of radius 100 → (120, 100) heading π/2. Segment 3: straight 10 m turned
    // by hOffset −π/2 → heading 0, from (120, 100) to (130, 100).
    let mut first = segment(0.0, 0.0, 20.0, None);
    first.position_start = Some(world(0.0, 0.0));
    let shape = Shape::ClothoidSpline(ClothoidSpline {
        time_end: None,
        segments: vec![
            first,
            segment(0.01, 0.01, 50.0 * PI, None),
            segment(0.0, 0.0, 10.0, Some(-FRAC_PI_2)),
        ],
    });
    let t = built(shape, false);
    assert_eq!(t.kind(), ShapeKind::ClothoidSpline);
    assert!((t.length() - (30.0 + 50.0 * PI)).abs() < 1e-12);
    // At a joint the later segment answers: (120, 100) with segment 3's heading 0; just
    // before it, segment 2's heading π/2.
    assert_point(t.eval(20.0 + 50.0 * PI), 120.0, 100.0, 0.0, 1e-9);
    assert_point(
        t.eval(20.0 + 50.0 * PI - 1e-7),
        120.0,
        100.0,
        FRAC_PI_2,
        1e-6,
    );
    assert_point(t.eval(t.length()), 130.0, 100.0, 0.0, 1e-9);
    // Inside segment 2 the curvature is 0.01.
    assert!((t.eval(50.0).curvature - 0.01).abs() < 1e-12);
}

#[test]
fn nurbs_of_degree_one_is_the_polyline_through_its_control_points() {
    // Order 2 (degree 1) with a clamped knot vector interpolates its control points linearly.
    // Uneven knots (0, 0, 3, 10, 10) change the speed in u, not the curve, so by arc length
    // it is the polyline (0,0) → (30,40) → (30,100).
    let pts = [(0.0, 0.0), (30.0, 40.0), (30.0, 100.0)];
    let nurbs_shape = nurbs(
        2,
        &pts.map(|(x, y)| (x, y, None, None)),
        &[0.0, 0.0, 3.0, 10.0, 10.0],
    );
    let n = built(nurbs_shape, false);
    let p = built(polyline(&pts.map(|(x, y)| (x, y, None))), false);
    assert_eq!(n.kind(), ShapeKind::Nurbs);
    assert!((n.length() - 110.0).abs() < 1e-9, "{}", n.length());
    for i in 0..=22 {
        let s = 5.0 * i as f64;
        let (a, b) = (n.eval(s), p.eval(s));
        assert!(
            (a.x - b.x).abs() < 1e-8 && (a.y - b.y).abs() < 1e-8,
            "s = {s}: nurbs {a:?}, polyline {b:?}"
        );
    }
    // Hand values: s = 25 is (15, 20); s = 80 is (30, 70) heading π/2.
    assert_point(n.eval(25.0), 15.0, 20.0, 40f64.atan2(30.0), 1e-8);
    assert_point(n.eval(80.0), 30.0, 70.0, FRAC_PI_2, 1e-8);
}

#[test]
fn rational_quadratic_nurbs_is_an_exact_circle() {
    // The quarter circle of radius 100 about the origin from (100, 0) to (0, 100): control
    // points (100,0), (100,100), (0,100) with weights 1, √2/2, 1 and knots (0,0,0,1,1,1)
    // (the standard rational quadratic arc, The NURBS Book, ch. 7). Length 50π; at s the point is 100·(cos(s/100), sin(s/100)),
    // heading s/100 + π/2, curvature 0.01.
    let w = FRAC_PI_4.cos();
    let shape = nurbs(
        3,
        &[
            (100.0, 0.0, Some(1.0), None),
            (100.0, 100.0, Some(w), None),
            (0.0, 100.0, Some(1.0), None),
        ],
        &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    );
    let t = built(shape, false);
    assert!((t.length() - 50.0 * PI).abs() < 1e-8, "{}", t.length());
    for s in [0.0, 10.0, 25.0 * PI, 120.0, 50.0 * PI] {
        let a = s / 100.0;
        let p = t.eval(s);
        assert_point(p, 100.0 * a.cos(), 100.0 * a.sin(), a + FRAC_PI_2, 1e-8);
        assert!((p.curvature - 0.01).abs() < 1e-8, "{p:?}");
    }
}

#[test]
fn nurbs_with_a_cusp_stays_finite() {
    // Quadratic B-spline on (0,0), (10,0), (10,0), (20,0), knots (0,0,0,1,2,2,2): every point
    // lies on the x-axis between 0 and 20 and x(u) is non-decreasing, so the curve is the
    // segment [0, 20] run once, with speed 0 where the doubled control point pulls it to a
    // stop. Length 20; the point at s is (s, 0).
    let t = built(
        nurbs(
            3,
            &[
                (0.0, 0.0, None, None),
                (10.0, 0.0, None, None),
                (10.0, 0.0, None, None),
                (20.0, 0.0, None, None),
            ],
            &[0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
        ),
        false,
    );
    assert!((t.length() - 20.0).abs() < 1e-6, "{}", t.length());
    for s in [0.0, 5.0, 10.0, 15.0, 20.0] {
        let p = t.eval(s);
        assert!((p.x - s).abs() < 1e-6 && p.y.abs() < 1e-12, "{p:?}");
    }
    // NaN and out-of-range arc lengths are clamped, never a panic.
    assert!(t.eval(f64::NAN).x.abs() < 1e-12);
    assert!((t.eval(1e300).x - 20.0).abs() < 1e-6);
}

#[test]
fn lateral_offset_from_an_arc_is_a_concentric_arc() {
    // Quarter circle of radius 100 about (0, 100) turning left from the origin. 10 m to the
    // left at s = 50π (the end, heading π/2) is (90, 100); the offset curve has radius 90, so
    // curvature 1/90.
    let t = built(arc(0.01, 50.0 * PI, world(0.0, 0.0)), false);
    let p = t.point_at(50.0 * PI, 10.0);
    assert_point(p, 90.0, 100.0, FRAC_PI_2, 1e-9);
    assert!((p.curvature - 1.0 / 90.0).abs() < 1e-12);
}

#[test]
fn high_degree_nurbs_keeps_linear_precision() {
    // Degree 8 (order 9) Bézier on nine equally spaced collinear points (0,0) … (80,0):
    // B-splines reproduce linear functions, so x(u) = 80·u and the curve is the segment,
    // length 80, the point at s being (s, 0).
    let pts: Vec<_> = (0..9).map(|i| (10.0 * i as f64, 0.0, None, None)).collect();
    let mut knots = vec![0.0; 9];
    knots.extend([1.0; 9]);
    let t = built(nurbs(9, &pts, &knots), false);
    assert!((t.length() - 80.0).abs() < 1e-9, "{}", t.length());
    assert_point(t.eval(33.0), 33.0, 0.0, 0.0, 1e-9);
}

#[test]
fn line_from_the_actor_faces_along_it_and_turns_to_its_end_heading_where_it_ends() {
    // oscsim's LineFromActor: the actor at (10, 5) facing 1.0 rad when the action starts, the
    // end (50, 35) facing π/6: the chord (40, 30) is 50 m at atan2(30, 40) = 0.6435 rad; the
    // vehicle faces it from its first point (not its own 1.0 rad) to the end, and π/6 at the
    // end point (a vertex that adds no length).
    let actor = opendrive::Pose {
        x: 10.0,
        y: 5.0,
        h: 1.0,
        ..opendrive::Pose::default()
    };
    let shape = Shape::LineFromActor(scenario::LineFromActor {
        end: world_at(50.0, 35.0, 0.0, FRAC_PI_6, 1),
    });
    let t = engine::trajectory::build_for_actor(
        &trajectory(shape, false),
        &straight(),
        Some(&actor),
        &here(),
    )
    .expect("valid trajectory");
    let along = 30f64.atan2(40.0);
    assert!((t.length() - 50.0).abs() < TOL);
    assert_point(t.eval(25.0), 30.0, 20.0, along, TOL);
    for (s, h) in [
        (0.0, along),
        (25.0, along),
        (50.0 - 1e-6, along),
        (50.0, FRAC_PI_6),
    ] {
        let got = t.orientation_at(s).expect("six-dimensional");
        assert!(
            opendrive::angle_difference(got, h).abs() < TOL,
            "{s}: {got}, want {h}"
        );
    }
    // Without an actor (a TrajectoryPosition's shape): an error, not a line from nowhere.
    let shape = Shape::LineFromActor(scenario::LineFromActor {
        end: world_at(50.0, 35.0, 0.0, FRAC_PI_6, 1),
    });
    assert!(build(&trajectory(shape, false), &straight(), &here()).is_err());
}
