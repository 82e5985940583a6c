//! An actor driving against s beside what it measures: the engine's car following
//! (`avoid_collisions(true)`) finding its leader along its direction of travel, a stationary
//! object's place turned into the distance along that direction, a route through points driven
//! against s. Every expectation is worked by hand in the scenario's comment.

use std::f64::consts::PI;

use crate::opposite::wrap;
use crate::support::{error_on, run_on, DT};

/// Positions on straight roads: the engine integrates speed exactly; float round-off only.
const S_TOL: f64 = 1e-6;
/// Places measured from the cone's coordinates, which the scenario gives to 1e-6 m
/// (`opposite_object_behind.osc`).
const COORD_TOL: f64 = 2e-6;
/// Along the road during a sinusoidal offset change: its cost Δ²π²/(16·T·v) is the
/// small-slope approximation of the path's extra length (as in run::opposite).
const COST_TOL: f64 = 1e-3;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;
/// Headings (rad).
const H_TOL: f64 = 1e-9;
/// How close the follower is to the IDM equilibrium after 50 s (m, m/s), as in
/// run::car_following: the residue of the approach from above decays (2.3 cm, 4 mm/s there).
const SETTLED_GAP: f64 = 0.05;
const SETTLED_SPEED: f64 = 0.01;

#[test]
fn avoid_collisions_against_s_follows_the_leader_along_the_direction_of_travel() {
    let r = run_on("opposite_avoid_collisions", "straight");
    // Boxes: front 3.5 m, rear 0.5 m along the direction of travel (-x).
    let gap = |t: f64| (r.at(t, "ego").x - 3.5) - (r.at(t, "lead").x + 0.5);
    assert!((gap(0.0) - 96.0).abs() < 1e-9, "gap(0) = {}", gap(0.0));
    // The first step: IDM's -1.908 m/s² at t = 0 over dt.
    let a0 = 0.73 * (-(155.2117 / 96.0_f64).powi(2));
    let v1 = r.at(DT, "ego").speed;
    assert!((v1 - (25.0 + a0 * DT)).abs() < 1e-3, "ego v({DT}) = {v1}");
    for (t, _) in &r.frames {
        assert!(gap(*t) > 27.869 - SETTLED_GAP, "gap {} at {t}", gap(*t));
    }
    let (lead, ego) = (r.at(50.0, "lead"), r.at(50.0, "ego"));
    assert!((lead.x - 50.0).abs() < 1e-9, "{lead:?}");
    assert!(
        (gap(50.0) - 27.869).abs() < SETTLED_GAP,
        "gap(50) = {}",
        gap(50.0)
    );
    assert!((ego.x - 81.869).abs() < SETTLED_GAP, "{ego:?}");
    assert!((ego.speed - 15.0).abs() < SETTLED_SPEED, "{ego:?}");
    assert!(ego.lane == 1 && wrap(ego.h - PI).abs() < H_TOL, "{ego:?}");
}

#[test]
fn an_oncoming_car_is_placed_and_stopped_behind_a_stationary_object_in_its_frame() {
    let r = run_on("opposite_object_behind", "junction_trippel_twoway0");
    // The cone's coordinates are given to 1e-6 m: its s on road 2 is 20 m within that.
    let cone = r.at(0.0, "cone");
    assert_eq!((cone.road.as_str(), cone.lane), ("2", 1), "{cone:?}");
    assert!((cone.s - 20.0).abs() < COORD_TOL, "{cone:?}");
    // 60 m behind the cone along the car's direction of travel: road 2 s = 80 m.
    let car = r.at(0.0, "car");
    assert_eq!((car.road.as_str(), car.lane), ("2", 1), "{car:?}");
    assert!((car.s - 80.0).abs() < COORD_TOL, "{car:?}");
    assert!(
        (car.x - 205.700870).abs() < COORD_TOL && (car.y - 28.204390).abs() < COORD_TOL,
        "{car:?}"
    );
    assert!(wrap(car.h - (0.3 + PI)).abs() < H_TOL, "{car:?}");
    assert!((car.speed - 10.0).abs() < S_TOL, "{car:?}");
    let mid = r.at(4.0, "car");
    assert!((mid.speed - 5.0).abs() < S_TOL, "{mid:?}");
    assert!((mid.s - 50.125).abs() < COORD_TOL, "{mid:?}");
    for t in [8.0, 10.0] {
        let c = r.at(t, "car");
        assert!(c.speed.abs() < S_TOL, "{c:?}");
        assert!((c.s - 40.25).abs() < COORD_TOL, "{c:?}");
        // 16.5 m between the car's front and the cone (car front 3.5 m, cone 0.25 m).
        let gap = (c.s - 3.5) - (r.at(t, "cone").s + 0.25);
        assert!((gap - 16.5).abs() < COORD_TOL, "gap {gap} at {t}");
    }
    let (s, e) = r.phase("do.1.0");
    assert!(s.abs() < T_TOL && (e - 8.0).abs() < T_TOL, "[{s}, {e}]");
    assert!((r.last_time() - 10.0).abs() < 1e-9);
    assert!((r.at(10.0, "ego").x - 60.0).abs() < S_TOL);
}

#[test]
fn a_route_through_points_in_a_lane_driven_against_s_is_the_plans_roads_backwards() {
    let r = run_on("opposite_route_points", "junction_trippel_twoway0");
    // (time, road, road s, x): lane 1's centre at y = 1.5 m, heading pi throughout.
    for (t, road, s, x) in [
        (0.0, "6", 80.0, 200.0),
        (9.0, "5", 10.0, 110.0),
        (15.0, "0", 50.0, 50.0),
    ] {
        let car = r.at(t, "car");
        assert_eq!((car.road.as_str(), car.lane), (road, 1), "{car:?}");
        assert!(
            (car.s - s).abs() < S_TOL && (car.x - x).abs() < S_TOL,
            "{car:?}"
        );
        assert!((car.y - 1.5).abs() < S_TOL, "{car:?}");
        assert!(wrap(car.h - PI).abs() < H_TOL, "{car:?}");
        assert!((car.speed - 10.0).abs() < S_TOL, "{car:?}");
    }
    let ego = r.at(15.0, "ego");
    assert!(
        (ego.x - 85.0).abs() < S_TOL && (ego.y + 1.5).abs() < S_TOL,
        "{ego:?}"
    );
    let (s, e) = r.phase("do");
    assert!(s.abs() < T_TOL && (e - 15.0).abs() < T_TOL, "[{s}, {e}]");
}

#[test]
fn routes_against_s_no_path_joins_or_left_are_errors_at_the_along() {
    for (name, text, place) in [
        (
            "err_opposite_route_order",
            "expected a path in lane 1 from road 0 at s = 20 m to road 6 at s = 80 m in the driving direction, found none",
            "8:13",
        ),
        (
            "err_opposite_route_end",
            "expected `car` on the route in lane 1 from road 6 at s = 80 m to road 0 at s = 20 m between u = 20.00 m and 200.00 m at the phase end, found it at u = 220.00 m (u along its direction of travel on the plan's roads driven against s)",
            "9:13",
        ),
    ] {
        let e = error_on(name, "junction_trippel_twoway0");
        assert!(
            e.contains(text) && e.ends_with(&format!("{name}.osc:{place}")),
            "{name}: {e}"
        );
    }
}
#[test]
fn a_lane_counted_from_an_object_in_a_lane_of_the_other_direction_is_an_error_at_the_argument() {
    let e = error_on("err_opposite_object_change_lane", "straight");
    assert!(
        e.contains("expected `reference:` of change_lane(…) to name an object in a lane `npc` drives in its direction (against s, a lane of the left side), found `cone` in lane -1, driven in +s")
            && e.ends_with("err_opposite_object_change_lane.osc:19:53"),
        "{e}"
    );
}
#[test]
fn a_lateral_position_beside_a_stationary_object_is_to_the_drivers_side() {
    let r = run_on("opposite_beside_object", "straight");
    let cone = r.at(0.0, "cone");
    assert!(
        (cone.x - 880.0).abs() < S_TOL && (cone.y - 5.75).abs() < S_TOL && cone.lane == 2,
        "{cone:?}"
    );
    // 1 m to the driver's left of the cone (towards the centre line): y = 4.75 m throughout.
    for (t, x) in [(0.0, 900.0), (2.0, 880.0), (4.0, 860.0)] {
        let car = r.at(t, "car");
        assert!(
            (car.x - x).abs() < S_TOL && (car.y - 4.75).abs() < S_TOL && car.lane == 2,
            "{car:?}"
        );
        assert!(wrap(car.h - PI).abs() < H_TOL, "{car:?}");
    }
    // A later phase: 2 m left of the cone at 8 s, half way at 6 s.
    let mid = r.at(6.0, "car");
    assert!((mid.y - 4.25).abs() < S_TOL, "{mid:?}");
    let end = r.at(8.0, "car");
    assert!((end.y - 3.75).abs() < S_TOL && end.lane == 2, "{end:?}");
    let cost = PI * PI / 640.0;
    assert!((end.x - (820.0 + cost)).abs() < COST_TOL, "{end:?}");
}
