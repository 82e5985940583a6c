//! FollowTrajectoryAction at runtime (OpenSCENARIO 1.3 §6.9 "Trajectories", XSD
//! `FollowTrajectoryAction`, `Timing`): the timed motion, initialDistanceOffset, the speed an
//! entity keeps after a timed trajectory, six-dimensional polylines and partially timed
//! ClothoidSplines, on this crate's fixtures (`tests/files/trajectory/`) and corpus scenarios.

use crate::runtime_support;

use std::path::{Path, PathBuf};

use engine::output::EventRecord;
use engine::storyboard::Transition;
use engine::{Engine, EngineConfig};
use runtime_support::{corpus, esmini_reference, Recorder};

/// Positions and speeds here are sums of a few exact steps: 1e-6 m, m/s, rad.
const TOL: f64 = 1e-6;

/// Runs `path` to its end (or `max_time`).
fn run(path: &Path, max_time: f64) -> (Recorder, Vec<EventRecord>) {
    let config = EngineConfig {
        max_time,
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(path, &[], config)
        .unwrap_or_else(|e| panic!("{} does not load: {e}", path.display()));
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    engine
        .run(&mut frames, &mut events)
        .unwrap_or_else(|e| panic!("{} does not run: {e}", path.display()));
    (frames, events)
}

fn fixture(name: &str) -> PathBuf {
    crate::corpus::fixture("trajectory").join(name)
}

/// The time of the end transition of storyboard element `element`.
fn ended_at(events: &[EventRecord], element: &str) -> Option<f64> {
    events.iter().find_map(|e| match e {
        EventRecord::Transition(t) if t.name == element && t.transition == Transition::End => {
            Some(t.time)
        }
        _ => None,
    })
}

#[test]
fn initial_distance_offset_deducts_the_time_to_reach_it() {
    // Vertices (100, −1.535) at 0 s and (200, −1.535) at 10 s: 10 m/s. initialDistanceOffset
    // 40 m takes 4 s, deducted from the vertex times (FollowTrajectoryAction/
    // @initialDistanceOffset): with relative timing from 0 s the car is at x = 140 + 10·t,
    // reaches the end x = 200 at 6 s (the action ends in the step that gets there, 5.95 s),
    // and drives on at the 10 m/s it arrived with: x = 210 at 7 s.
    let (frames, events) = run(&fixture("timed_offset.xosc"), 10.0);
    for (t, x) in [
        (0.0, 140.0),
        (1.0, 150.0),
        (3.5, 175.0),
        (6.0, 200.0),
        (7.0, 210.0),
    ] {
        let r = frames.at("Ego", t);
        assert!((r.x - x).abs() < TOL, "x at {t} s: {} (expected {x})", r.x);
        assert!((r.speed - 10.0).abs() < TOL, "speed at {t} s: {}", r.speed);
    }
    let end = ended_at(&events, "Init Ego RoutingAction").expect("the action ends");
    assert!((end - 5.95).abs() < 1e-9, "ended at {end}");
}

#[test]
fn six_dimensional_polyline_turns_between_its_vertex_headings() {
    // Vertices 10 m apart on a straight line state headings 0, 0.4, 0 rad (§6.9: the path
    // then also gives the entity's orientation). At 10 m/s from x = 100: 0.2 rad at s = 5 m
    // (0.5 s) and 15 m (1.5 s), 0.4 rad at the middle vertex (1 s), 0 at the last (2 s); the
    // position stays on the line.
    let (frames, _) = run(&fixture("oriented_polyline.xosc"), 3.0);
    for (t, x, h) in [
        (0.5, 105.0, 0.2),
        (1.0, 110.0, 0.4),
        (1.5, 115.0, 0.2),
        (2.0, 120.0, 0.0),
    ] {
        let r = frames.at("Ego", t);
        assert!((r.x - x).abs() < TOL && (r.y + 1.535).abs() < TOL, "{r:?}");
        assert!(
            (r.h - h).abs() < TOL,
            "heading at {t} s: {} (expected {h})",
            r.h
        );
    }
}

#[test]
fn clothoid_spline_with_one_timed_segment_runs_at_constant_speed() {
    // The scenariogeneration example clothoid_spline_shape_trajectory0.xosc: segment 1 (10 m)
    // has no timeStart, segment 2 (10 m) starts at 5 s, timeEnd 10 s. The 1.3 XSD makes each
    // timeStart optional, so the file is valid; between timed points the speed is constant
    // (10 m / 5 s = 2 m/s) and the untimed first segment continues it backwards: it starts at
    // 5 − 10/2 = 0 s. The event starts at 0.05 s (SimulationTime > 0), so Ego moves at
    // 2 m/s from then to 10.05 s; the run stops when its story completes, at 10 s.
    let (frames, events) = run(
        &corpus("generated/xosc/clothoid_spline_shape_trajectory0.xosc"),
        20.0,
    );
    assert!(
        !events
            .iter()
            .any(|e| matches!(e, EventRecord::Error { .. })),
        "an error was logged: {events:?}"
    );
    for t in [1.0, 5.0, 5.05, 9.0, 10.0] {
        let r = frames.at("Ego", t);
        assert!((r.speed - 2.0).abs() < TOL, "speed at {t} s: {}", r.speed);
    }
    // 9 s at 2 m/s between 1 s and 10 s: 18 m of the spline's 20.
    let ego: Vec<_> = frames
        .0
        .iter()
        .filter(|r| r.name == "Ego" && r.time >= 1.0 - 1e-9)
        .collect();
    let path: f64 = ego
        .windows(2)
        .map(|w| (w[1].x - w[0].x).hypot(w[1].y - w[0].y))
        .sum();
    // The path is the curve's chords every 0.05 s (0.1 m): shorter than the arc by
    // ≈ κ²·ℓ³/24 per chord, under 1e-5 m in all for κ ≤ 0.08.
    assert!((path - 18.0).abs() < 1e-4, "travelled {path} m");
}

#[test]
fn speed_after_a_timed_trajectory_is_the_arrival_speed() {
    // esmini's lane-change_clothoid_spline_based_trajectory.xosc, event
    // TrajectoryWithTimestamps: the last segment is 6.5 m from 7 s to timeEnd 8 s, so the car
    // arrives at 6.5 m/s and drives on at it along the straight road (esmini 3.6.0's
    // reference has 6.500 m/s from the end on, too). The event starts at 18.70 s here, so the
    // trajectory ends at 26.70 s.
    let (frames, _) = run(
        &corpus("esmini/xosc/lane-change_clothoid_spline_based_trajectory.xosc"),
        30.0,
    );
    let a = frames.at("Car", 27.0);
    let b = frames.at("Car", 29.0);
    assert!((a.speed - 6.5).abs() < TOL && (b.speed - 6.5).abs() < TOL);
    assert!((b.x - a.x - 13.0).abs() < 1e-3, "{a:?} {b:?}");
}

#[test]
fn speed_at_a_vertex_is_that_of_the_step_arriving_there() {
    // esmini's trajectory-test.xosc: Target's timed Polyline has vertices at 2 s and 4 s of
    // trajectory time, started at 2 s. The frame at 6.00 s is the vertex; the step into it
    // ran on the interval 2 s → 4 s, and esmini 3.6.0's reference row at 6.000 s has that
    // interval's 24.524 m/s (the next interval's 27.341 m/s from 6.05 s on); the CSV has
    // 3 decimals.
    let (frames, _) = run(&corpus("esmini/xosc/trajectory-test.xosc"), 8.0);
    assert!((frames.at("Target", 6.0).speed - 24.524).abs() < 1e-3);
    assert!((frames.at("Target", 6.1).speed - 27.341).abs() < 1e-3);
}

#[test]
fn follow_mode_tracks_the_speed_continuous_reading_of_the_times() {
    // TrajectoryFollowingMode follow ("observing the dynamic constraints of the entity"): the
    // timed Polyline runs at 10 m/s to x = 150 at 5 s, then to x = 250 at 10 s. Read as
    // given, the speed would jump from 10 to 20 m/s at 5 s; `follow` tracks the reading whose
    // speed changes linearly between the vertices and reaches each on time
    // (trajectory::TimeTable::continuous_speeds): from 10 m/s, the first interval ends at
    // 2·50/5 − 10 = 10 m/s, the second at 2·100/5 − 10 = 30 m/s, so from 5 s on
    // v = 10 + 4τ and x = 150 + 10τ + 2τ² (τ = t − 5), within the car's 10 m/s² limits. A
    // frame shows the mean speed of the step that ends there, 10 + 4(τ − 0.025).
    let (frames, events) = run(&fixture("follow_speed_jump.xosc"), 12.0);
    let ego: Vec<_> = frames.0.iter().filter(|r| r.name == "Ego").collect();
    let before = frames.at("Ego", 4.0);
    assert!((before.x - 140.0).abs() < TOL && (before.speed - 10.0).abs() < TOL);
    for w in ego.windows(2).filter(|w| w[1].time <= 10.0 + 1e-9) {
        let dv = w[1].speed - w[0].speed;
        assert!(
            dv.abs() <= 10.0 * 0.05 + 1e-9,
            "{dv} m/s in a step at {}",
            w[1].time
        );
    }
    for (t, x) in [(7.5, 187.5), (9.0, 222.0)] {
        let tau = t - 5.0;
        let r = frames.at("Ego", t);
        assert!(
            (r.x - x).abs() < TOL && (r.speed - (10.0 + 4.0 * (tau - 0.025))).abs() < TOL,
            "{r:?}"
        );
    }
    // The action ends in the step that reaches x = 250 at 10 s, and the car leaves with the
    // reading's final speed, 30 m/s (within one step's 0.5 m/s of the step's mean 29.9).
    let last = frames.at("Ego", 10.0);
    assert!((last.x - 250.0).abs() < TOL && (last.speed - 30.0).abs() < TOL);
    let end = ended_at(&events, "Init Ego RoutingAction").expect("the action ends");
    assert!((end - 9.95).abs() < 1e-9, "ended at {end}");
}

/// bicycle_fall_over.xosc: an Init FollowTrajectoryAction (follow, timed Polyline) on a
/// cyclist that no TeleportAction placed starts it at the first vertex (100, −1.535), and the
/// continuous reading brakes it from 10 m/s to rest over 2.5 .. 3.5 s (s = 125 + 10τ − 5τ²),
/// where it waits on the last vertex until the last time, 4 s. Every row of esmini 3.6.0's
/// reference agrees to its 1 mm print precision.
#[test]
fn unplaced_cyclist_starts_on_its_trajectory_and_stops_on_the_last_vertex() {
    let (frames, _) = run(&corpus("esmini/xosc/bicycle_fall_over.xosc"), 6.0);
    let mut rows = 0;
    for row in esmini_reference("bicycle_fall_over") {
        let (t, x, speed) = (row.time, row.x, row.speed);
        if t > 6.0 + 1e-9 {
            break;
        }
        let r = frames.at("Cyclist", t);
        assert!(
            (r.x - x).abs() < 1e-3 && (r.speed - speed).abs() < 1e-3,
            "{t}: {r:?} vs x {x}, speed {speed}"
        );
        rows += 1;
    }
    assert!(rows > 50, "{rows} rows compared");
    let at = |t: f64| frames.at("Cyclist", t).x;
    assert!((at(3.0) - (125.0 + 5.0 - 1.25)).abs() < TOL);
    assert!((at(3.5) - 130.0).abs() < TOL && (at(5.0) - 130.0).abs() < TOL);
}

#[test]
fn trajectory_from_a_catalog_with_a_parameter_assignment() {
    // TrajectoryRef/CatalogReference to "straight" (catalogs/Trajectories.xosc): from
    // x = 100 at 0 s to x = 100 + Length at 5 s, Length assigned 80: 16 m/s, x = 116 at 1 s,
    // 180 at 5 s, and on at 16 m/s after the end.
    let (frames, _) = run(&fixture("catalog_ref.xosc"), 8.0);
    for (t, x) in [(1.0, 116.0), (5.0, 180.0), (6.0, 196.0)] {
        let r = frames.at("Ego", t);
        assert!(
            (r.x - x).abs() < TOL && (r.speed - 16.0).abs() < TOL,
            "{r:?}"
        );
    }
}

/// The car of the follow fixtures: FrontAxle maxSteering 0.5 rad at 2.98 m, RearAxle at 0:
/// κ_max = tan 0.5 / 2.98 (kinematic bicycle), minimum turning radius 5.455 m.
fn fixture_max_curvature() -> f64 {
    0.5f64.tan() / 2.98
}

#[test]
fn follow_mode_steers_a_circle_it_can_drive_exactly() {
    // A Clothoid of constant curvature 0.1 < κ_max = 0.1833 (radius 10 about (100, 8.465))
    // from the car's pose. Pure pursuit aims at the circle point a look-ahead further on; the
    // arc tangent to the heading through it is the circle itself (2·sin α/ℓ = 1/R), so the
    // car stays at 10 m from the centre. 5π m at 10 m/s: over in the step to 1.6 s (1.55 s).
    let (frames, events) = run(&fixture("follow_circle.xosc"), 3.0);
    assert!(fixture_max_curvature() > 0.1);
    for r in frames
        .0
        .iter()
        .filter(|r| r.name == "Ego" && r.time <= 1.55)
    {
        let radius = (r.x - 100.0).hypot(r.y - 8.465);
        assert!((radius - 10.0).abs() < 1e-6, "{r:?} at {radius} m");
        // Heading along the circle: the angle swept, d/R = 10·t/10.
        assert!((r.h - r.time).abs() < 1e-6, "{r:?}");
    }
    let end = ended_at(&events, "Init Ego RoutingAction").expect("the action ends");
    assert!((end - 1.55).abs() < 1e-9, "ended at {end}");
}

#[test]
fn follow_mode_takes_a_corner_within_the_steering_limit() {
    // A right-angle left corner at (130, −1.535) from x = 100, at 10 m/s (0.5 m a step). The
    // look-ahead is the minimum turning radius L = 1/κ_max = 5.455 m: the car is exactly on
    // the first leg until the look-ahead point passes the corner, s > 30 − L = 24.55 m
    // (2.455 s); every step's arc turns at most κ_max·0.5 m; it comes back onto the second
    // leg (within 0.1 m from 4.8 s) and the action ends when the nearest trajectory point is
    // the end.
    let (frames, events) = run(&fixture("follow_corner.xosc"), 8.0);
    let ego: Vec<_> = frames.0.iter().filter(|r| r.name == "Ego").collect();
    let end = ended_at(&events, "Init Ego RoutingAction").expect("the action ends");
    for r in ego.iter().filter(|r| r.time <= 2.45 + 1e-9) {
        assert!((r.y + 1.535).abs() < 1e-9 && r.h.abs() < 1e-9, "{r:?}");
        assert!((r.x - 100.0 - 10.0 * r.time).abs() < 1e-6, "{r:?}");
    }
    let limit = fixture_max_curvature() * 0.5 + 1e-9;
    for w in ego.windows(2).filter(|w| w[1].time <= end + 1e-9) {
        let turn = opendrive::normalize_angle(w[1].h - w[0].h);
        assert!(turn.abs() <= limit, "{turn} rad in a step at {}", w[1].time);
    }
    assert!(
        ego.iter().any(|r| r.x > 130.5),
        "the corner is cut and overshot"
    );
    for r in ego.iter().filter(|r| r.time >= 4.8 && r.time <= end) {
        assert!((r.x - 130.0).abs() < 0.1, "{r:?}");
    }
    assert!(end > 4.8 && end < 6.0, "ended at {end}");
}

#[test]
fn untimed_trajectory_leaves_the_speed_to_other_actions() {
    // TimeReference None: the trajectory gives no speed (§6.9) and the action holds the
    // lateral domain only (semantics-pitfalls #7). A SpeedAction from 1 s (10 → 20 m/s,
    // linear over 2 s: 15 m/s at 2 s) runs to its end beside it, and the car stays on the
    // Polyline (100, −1.535) → (130, −1.535) → (230, 8.465) at the speed it sets.
    let (frames, events) = run(&fixture("lateral_only.xosc"), 8.0);
    let faster = events.iter().find_map(|e| match e {
        EventRecord::Transition(t) if t.name == "FasterAction" => {
            (t.transition != Transition::Start).then_some(t.transition)
        }
        _ => None,
    });
    assert_eq!(faster, Some(Transition::End), "{events:?}");
    assert!((frames.at("Ego", 2.0).speed - 15.0).abs() < TOL);
    assert!((frames.at("Ego", 4.0).speed - 20.0).abs() < TOL);
    let end = ended_at(&events, "Init Ego RoutingAction").expect("the trajectory ends");
    for r in frames.0.iter().filter(|r| r.name == "Ego" && r.time <= end) {
        // Distance to the polyline: to the first leg for x ≤ 130, else to the second, whose
        // unit normal is (−0.1, 1)/√1.01.
        let off = if r.x <= 130.0 {
            (r.y + 1.535).abs()
        } else {
            (-(r.x - 130.0) * 0.1 + (r.y + 1.535)).abs() / 1.01f64.sqrt()
        };
        assert!(off < 1e-9, "{r:?} is {off} m off the polyline");
    }
    // 130.5 m: 10 m by 1 s, about 30 m during the speed change, the rest at 20 m/s.
    assert!(end > 7.0 && end < 8.0, "ended at {end}");
}

#[test]
fn initial_distance_offset_beyond_the_end_is_refused() {
    // Range of FollowTrajectoryAction/@initialDistanceOffset: [0, arc length]; 150 m on the
    // 100 m Polyline is refused with the PrivateAction's place (line 44, column 11), and the
    // car drives on under the default controller from x = 100 at its 10 m/s.
    let path = fixture("offset_beyond_end.xosc");
    let (frames, events) = run(&path, 2.0);
    let message = events
        .iter()
        .find_map(|e| match e {
            EventRecord::Error { message, .. } => Some(message.clone()),
            _ => None,
        })
        .expect("an error is logged");
    let expected = format!(
        "expected initialDistanceOffset in [0, 100] m (the trajectory's length), found 150 m at {}:44:11",
        path.display()
    );
    assert_eq!(message, expected);
    let r = frames.at("Ego", 1.0);
    assert!(
        (r.x - 110.0).abs() < TOL && (r.speed - 10.0).abs() < TOL,
        "{r:?}"
    );
}
