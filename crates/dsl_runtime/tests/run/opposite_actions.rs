//! The §8.8 actions and §8.9 modifiers of an actor driving against s (oncoming traffic) beyond
//! `drive()` and the lane and speed changes (`run::opposite`): planned on the view of the plan's
//! roads driven the other way, lowered back to the road's s and t, run by the engine. Every
//! expectation is worked by hand in the scenario's comment.

use std::f64::consts::PI;

use crate::opposite::{ends_without_error, wrap};
use crate::support::{error_on, run_on, stepped};

/// Positions on straight roads: the engine integrates speed exactly; float round-off only.
const S_TOL: f64 = 1e-6;
/// Headings (rad).
const H_TOL: f64 = 1e-9;
/// Event times are step times.
const T_TOL: f64 = 1e-9;
/// A hand sum of exact integrals and the engine's step leads, against the stepped sum.
const LEAD_TOL: f64 = 1e-3;
/// Along the road during a lateral move: the move's cost v·T·(1 − cos θ) is worked for a
/// constant crossing speed; the engine's steps round it (1 mm).
const COST_TOL: f64 = 1e-3;
/// change_position_on_road.osc's hand-worked integrals (midpoint rule, 100,000 points) against
/// the engine's steps of 0.05 s (m), as `run::position_actions` takes them.
const ON_ROAD_TOL: f64 = 1e-4;
/// change_position_smooth.osc's figures (the curve's length to 1e-4 m), as
/// `run::position_actions` takes them.
const CURVE_TOL: f64 = 1e-3;
/// acceleration_relative_changing.osc's distances with the steps' lag of the ramp (exact on
/// the 0.05 s grid: float round-off).
const FOLLOW_TOL: f64 = 1e-6;
/// World points written to 6 decimals in the scenario (the engine follows them exactly).
const PATH_TOL: f64 = 1e-5;
/// Along the road during a sinusoidal offset at a changing speed: its cost (3 mm here, worked
/// at the mean speed) is not a closed form at every step.
const OFFSET_COST_TOL: f64 = 5e-3;

fn phase_is(r: &crate::support::Run, path: &str, start: f64, end: f64) {
    let (s, e) = r.phase(path);
    assert!(
        (s - start).abs() < T_TOL && (e - end).abs() < T_TOL,
        "{path}: [{s}, {e}], expected [{start}, {end}]"
    );
}

#[test]
fn speed_and_acceleration_actions_against_s_run_along_the_direction_of_travel() {
    let r = run_on("opposite_acceleration_actions", "straight");
    // v(t) of the scenario's comment.
    let v = |t: f64| {
        if t <= 1.0 {
            10.0
        } else if t <= 2.0 {
            20.0
        } else if t <= 3.0 {
            20.0 - 4.0 * (t - 2.0)
        } else if t <= 4.0 {
            let tau = t - 3.0;
            16.0 - 4.0 * tau + 1.25 * tau * tau
        } else {
            13.25 - 1.5 * (t - 4.0)
        }
    };
    for (t, want) in [
        (1.5, 20.0),
        (3.0, 16.0),
        (3.5, 14.3125),
        (4.0, 13.25),
        (6.0, 10.25),
    ] {
        let npc = r.at(t, "npc");
        assert!((npc.speed - want).abs() < S_TOL, "v({t}): {npc:?}");
    }
    // x = 980 − u, u the distance the engine's steps cover.
    for t in [0.0, 1.0, 2.0, 3.0, 3.5, 4.0, 6.0] {
        let npc = r.at(t, "npc");
        let x = 980.0 - stepped(v, 0.0, t);
        assert!(
            (npc.x - x).abs() < S_TOL && (npc.y - 1.75).abs() < S_TOL,
            "at {t}: {npc:?}, x {x}"
        );
        assert!(npc.lane == 1 && wrap(npc.h - PI).abs() < H_TOL, "{npc:?}");
    }
    // The hand figures: x 970, 950, 932 less the lead 0.1 m, and 894.0833 at 6 s less
    // 0.2437 m of leads less the jerk's 0.0005 m.
    for (t, x) in [
        (1.0, 970.0),
        (2.0, 950.0),
        (3.0, 932.1),
        (6.0, 894.0833 + 0.24375 - 0.0005),
    ] {
        assert!((r.at(t, "npc").x - x).abs() < LEAD_TOL, "x({t})");
    }
    phase_is(&r, "do.1", 1.0, 1.0);
    phase_is(&r, "do.3", 2.0, 2.0);
    phase_is(&r, "do.5", 3.0, 4.0);
    phase_is(&r, "do.6", 4.0, 6.0);
}

#[test]
fn yaw_relative_to_the_road_and_shapes_against_s_run_on_the_view() {
    let r = run_on("opposite_orientation_shapes", "straight");
    // npc faces -s (yaw 180° from the s-axis) throughout.
    for t in [0.0, 2.0, 3.0, 4.0, 8.0, 10.0, 12.0] {
        let npc = r.at(t, "npc");
        assert!(npc.lane == 1 && wrap(npc.h - PI).abs() < 1e-3, "{npc:?}");
    }
    let at0 = r.at(0.0, "npc");
    assert!(
        (at0.x - 950.0).abs() < S_TOL && (at0.y - 1.75).abs() < S_TOL,
        "{at0:?}"
    );
    assert!((r.at(2.0, "npc").x - 930.0).abs() < S_TOL);
    // The speed shape: 10 -> 20 m/s in 2 s, the phase's end.
    phase_is(&r, "do.0.1", 2.0, 4.0);
    assert!((r.at(3.0, "npc").speed - 15.0).abs() < S_TOL);
    let at4 = r.at(4.0, "npc");
    assert!(
        (at4.x - 899.75).abs() < S_TOL && (at4.speed - 20.0).abs() < S_TOL,
        "{at4:?}"
    );
    // The lateral shape: 0.5 m to the driver's left (towards the centre line) at 0.25 m/s.
    assert!(
        (r.at(5.0, "npc").y - 1.5).abs() < S_TOL,
        "{:?}",
        r.at(5.0, "npc")
    );
    let at8 = r.at(8.0, "npc");
    assert!((at8.y - 1.25).abs() < S_TOL, "{at8:?}");
    let cost = 40.0 - 2.0 * (20.0f64.powi(2) - 0.25f64.powi(2)).sqrt();
    assert!(
        (at8.x - (819.75 + cost)).abs() < COST_TOL,
        "{at8:?} cost {cost}"
    );
    // The position shape: u = 240 m (s = 760 m) at 12 s, 10 m/s at the middle.
    phase_is(&r, "do.0.3", 8.0, 12.0);
    let at10 = r.at(10.0, "npc");
    assert!((at10.speed - 10.0).abs() < S_TOL, "{at10:?}");
    // The speed-up's 0.25 m lead, less the first half's 0.25 m, plus the offset's cost.
    assert!((at10.x - (790.0 + cost)).abs() < COST_TOL, "{at10:?}");
    let at12 = r.at(12.0, "npc");
    assert!(
        (at12.x - (759.75 + cost)).abs() < COST_TOL && (at12.speed - 20.0).abs() < S_TOL,
        "{at12:?}"
    );
    // bus stands at 150° from the s-axis for the run.
    for t in [0.0, 6.0, 12.0] {
        let bus = r.at(t, "bus");
        assert!(
            (bus.x - 900.0).abs() < S_TOL
                && (bus.y - 5.25).abs() < S_TOL
                && bus.speed.abs() < S_TOL,
            "{bus:?}"
        );
        assert!(wrap(bus.h - 150f64.to_radians()).abs() < H_TOL, "{bus:?}");
    }
}

#[test]
fn lateral_and_acceleration_beside_an_oncoming_actor_are_the_drivers() {
    let r = run_on("opposite_beside", "straight");
    // The truck: 10 m/s, then 1 m/s² from 2 s.
    let truck0 = r.at(0.0, "truck");
    assert!(
        (truck0.x - 900.0).abs() < S_TOL && (truck0.y - 1.75).abs() < S_TOL && truck0.lane == 1,
        "{truck0:?}"
    );
    for (t, x, v) in [(2.0, 880.0, 10.0), (4.0, 857.95, 12.0), (6.0, 831.9, 14.0)] {
        let truck = r.at(t, "truck");
        assert!(
            (truck.x - x).abs() < S_TOL && (truck.speed - v).abs() < S_TOL,
            "truck at {t}: {truck:?}"
        );
    }
    // npc 3 m to the truck driver's right (+y), in lane 2.
    let npc0 = r.at(0.0, "npc");
    assert!(
        (npc0.x - 880.0).abs() < S_TOL && (npc0.y - 4.75).abs() < S_TOL && npc0.lane == 2,
        "{npc0:?}"
    );
    assert!(wrap(npc0.h - PI).abs() < H_TOL, "{npc0:?}");
    assert!((r.at(2.0, "npc").x - 860.0).abs() < S_TOL);
    // 1.5 m/s², the truck's 1 m/s² and 0.5; 3.5 m to its right at 6 s, half way at 4 s.
    let mid = r.at(4.0, "npc");
    assert!((mid.speed - 13.0).abs() < S_TOL, "{mid:?}");
    assert!((mid.y - 5.0).abs() < S_TOL, "{mid:?}");
    assert!((mid.x - 836.925).abs() < OFFSET_COST_TOL, "{mid:?}");
    let end = r.at(6.0, "npc");
    assert!(
        (end.speed - 16.0).abs() < S_TOL && (end.y - 5.25).abs() < S_TOL && end.lane == 2,
        "{end:?}"
    );
    assert!((end.x - 807.85).abs() < OFFSET_COST_TOL, "{end:?}");
    phase_is(&r, "do.1", 2.0, 6.0);
}

#[test]
fn a_lateral_position_beside_an_oncoming_actor_after_a_run_time_start_is_the_drivers() {
    let r = run_on("opposite_beside_runtime", "straight");
    let (_, e) = r.phase("do.2.0");
    assert!((e - 1.10).abs() < T_TOL, "until @quick ended at {e}");
    let start = r.at(1.10, "npc");
    assert!(
        (start.x - 869.0).abs() < S_TOL && (start.y - 4.75).abs() < S_TOL,
        "{start:?}"
    );
    let cost = 0.25 * PI * PI / (16.0 * 4.0 * 10.0);
    let mid = r.at(3.10, "npc");
    assert!((mid.y - 5.0).abs() < S_TOL, "{mid:?}");
    assert!((mid.x - (849.0 + cost / 2.0)).abs() < COST_TOL, "{mid:?}");
    let end = r.at(5.10, "npc");
    assert!((end.y - 5.25).abs() < S_TOL && end.lane == 2, "{end:?}");
    assert!((end.x - (829.0 + cost)).abs() < COST_TOL, "{end:?}");
    assert!((r.at(5.10, "truck").x - 849.0).abs() < S_TOL);
    // The engine's lane change found its target: no error record, the run ends.
    ends_without_error("opposite_beside_runtime", "straight");
}

#[test]
fn position_actions_against_s_put_the_actor_on_its_view() {
    let r = run_on("opposite_position_actions", "straight");
    assert!((r.at(2.0, "npc").x - 930.0).abs() < S_TOL);
    phase_is(&r, "do.0.1", 2.0, 2.0);
    // assign_position: lane 2, 0.5 m left of its centre in the road's t.
    let put = r.at(2.05, "npc");
    assert!(
        (put.x - 880.0).abs() < S_TOL && (put.y - 5.75).abs() < S_TOL && put.lane == 2,
        "{put:?}"
    );
    let at3 = r.at(3.0, "npc");
    assert!(
        (at3.x - 870.5).abs() < S_TOL && wrap(at3.h - PI).abs() < H_TOL,
        "{at3:?}"
    );
    // change_position along the chord (-7.5, -4) at 10 m/s.
    let chord = (-4.0f64).atan2(-7.5);
    let mid = r.at(3.45, "npc");
    assert!(
        (mid.x - (870.5 - 4.5 * 7.5 / 8.5)).abs() < S_TOL
            && (mid.y - (5.75 - 4.5 * 4.0 / 8.5)).abs() < S_TOL,
        "{mid:?}"
    );
    assert!(wrap(mid.h - chord).abs() < H_TOL, "{mid:?}");
    phase_is(&r, "do.0.3", 3.0, 3.85);
    let there = r.at(3.85, "npc");
    assert!(
        (there.x - 863.0).abs() < S_TOL && (there.y - 1.75).abs() < S_TOL && there.lane == 1,
        "{there:?}"
    );
    let on = r.at(4.85, "npc");
    assert!(
        (on.x - 853.0).abs() < S_TOL && (on.y - 1.75).abs() < S_TOL,
        "{on:?}"
    );
    // change_position on the road network: change_position_on_road.osc's T, x and y mirrored.
    for (t, along, across) in [(6.85, 19.90654, 1.73709), (8.85, 39.81131, 3.49981)] {
        let npc = r.at(t, "npc");
        assert!(
            (npc.x - (853.0 - along)).abs() < ON_ROAD_TOL
                && (npc.y - (1.75 + across)).abs() < ON_ROAD_TOL,
            "at {t}: {npc:?}"
        );
    }
    phase_is(&r, "do.0.5", 4.85, 8.9);
    let end = r.at(8.9, "npc");
    assert!(
        (end.x - 812.68869).abs() < ON_ROAD_TOL && (end.y - 5.25).abs() < S_TOL && end.lane == 2,
        "{end:?}"
    );
    // bus turned to the world's 1.5 rad where it stands.
    assert!(wrap(r.at(0.0, "bus").h - PI).abs() < H_TOL);
    for t in [1.05, 2.0] {
        let bus = r.at(t, "bus");
        assert!(
            (bus.x - 700.0).abs() < S_TOL
                && (bus.y - 5.25).abs() < S_TOL
                && (bus.h - 1.5).abs() < H_TOL,
            "{bus:?}"
        );
    }
}

#[test]
fn paths_against_s_run_in_world_coordinates_and_end_on_the_view() {
    let r = run_on("opposite_paths", "junction_trippel_twoway0");
    let at1 = r.at(1.0, "npc");
    assert_eq!((at1.road.as_str(), at1.lane), ("2", 1), "{at1:?}");
    assert!((at1.x - 196.147505).abs() < PATH_TOL && (at1.y - 25.249188).abs() < PATH_TOL);
    // The trajectory: half way along a-b at 2 s, b at 3 s, c at 5 s.
    for (t, x, y) in [
        (2.0, 186.446380, 22.771654),
        (3.0, 176.745255, 20.294120),
        (5.0, 157.934046, 13.428379),
    ] {
        let npc = r.at(t, "npc");
        assert!(
            (npc.x - x).abs() < PATH_TOL && (npc.y - y).abs() < PATH_TOL && npc.lane == 1,
            "at {t}: {npc:?}"
        );
    }
    phase_is(&r, "do.1.1", 1.0, 5.0);
    let v = 20.024984 / 2.0;
    assert!((r.at(5.0, "npc").speed - v).abs() < PATH_TOL);
    // The path across the junction: 30.037477 m along c-d at 8 s; d at 11.888728 s.
    let at8 = r.at(8.0, "npc");
    assert!(
        (at8.x - 128.349174).abs() < PATH_TOL && (at8.y - 8.233641).abs() < PATH_TOL,
        "{at8:?}"
    );
    let (s, e) = r.phase("do.1.2");
    assert!(
        (s - 5.0).abs() < T_TOL && (e - 11.9).abs() < T_TOL,
        "[{s}, {e}]"
    );
    let end = r.at(11.9, "npc");
    assert_eq!((end.road.as_str(), end.lane), ("0", 1), "{end:?}");
    // At d, less what of the step to 11.9 s is left after it (0.0113 s at v).
    let past = v * (11.9 - 11.888728);
    assert!(
        ((end.x - 90.0).hypot(end.y - 1.5) - past).abs() < PATH_TOL,
        "{end:?}"
    );
    // On along lane 1 of road 0 towards -x.
    let last = r.at(12.9, "npc");
    assert!(
        (last.x - (end.x - v)).abs() < PATH_TOL && last.lane == 1,
        "{last:?}"
    );
}

#[test]
fn relative_trajectories_against_s_take_the_roads_or_the_lanes_frame() {
    let r = run_on("opposite_relative_paths", "straight");
    assert!((r.at(1.0, "truck").x - 600.0).abs() < S_TOL);
    // road_relative: x along +s, y to the road's left.
    for (t, x, y) in [(2.0, 590.0, 2.5), (3.0, 580.0, 3.25), (5.0, 560.0, 3.25)] {
        let truck = r.at(t, "truck");
        assert!(
            (truck.x - x).abs() < S_TOL && (truck.y - y).abs() < S_TOL && truck.lane == 1,
            "at {t}: {truck:?}"
        );
    }
    assert!(wrap(r.at(2.0, "truck").h - (1.5f64).atan2(-20.0)).abs() < H_TOL);
    phase_is(&r, "do.0.1", 1.0, 5.0);
    // lane_relative: x along the lane's direction, y to the driver's left from its centre.
    for (t, x, y) in [(6.0, 550.0, 2.5), (7.0, 540.0, 1.75)] {
        let truck = r.at(t, "truck");
        assert!(
            (truck.x - x).abs() < S_TOL && (truck.y - y).abs() < S_TOL && truck.lane == 1,
            "at {t}: {truck:?}"
        );
    }
    phase_is(&r, "do.0.2", 5.0, 7.0);
    assert!((r.at(7.0, "truck").speed - 20.0f64.hypot(1.5) / 2.0).abs() < S_TOL);
    // object_relative: bus's own frame, heading pi, so y = 1 m is to its left (-y).
    for (t, x, y) in [(2.0, 590.0, 4.75), (3.0, 580.0, 4.25)] {
        let bus = r.at(t, "bus");
        assert!(
            (bus.x - x).abs() < S_TOL && (bus.y - y).abs() < S_TOL && bus.lane == 2,
            "at {t}: {bus:?}"
        );
    }
    phase_is(&r, "do.1.1", 1.0, 3.0);
}

#[test]
fn change_position_on_the_road_network_against_s_after_a_run_time_start_arrives_ahead() {
    let r = run_on("opposite_place_runtime", "straight");
    phase_is(&r, "do.1.1", 1.10, 3.20);
    assert!((r.at(1.10, "npc").x - 878.0).abs() < S_TOL);
    // y as the sinusoid of the distance along, 878 − x on the straight road (1 mm, as in +s).
    for k in 0..40 {
        let t = 1.10 + 0.05 * f64::from(k);
        let npc = r.at(t, "npc");
        let d = 878.0 - npc.x;
        let want = 1.75 + 2.0 * (1.0 - (PI * d / 40.0).cos());
        assert!((npc.y - want).abs() < 1e-3, "{t}: {npc:?}, want y {want}");
    }
    let there = r.at(3.15, "npc");
    assert!(
        (there.y - 5.75).abs() < S_TOL && there.lane == 2,
        "{there:?}"
    );
    // Arrived at 3.11228 s: 0.03772 s on at 20 m/s by 3.15 s (1 cm: the arc's series).
    assert!((there.x - 837.2456).abs() < 0.01, "{there:?}");
    let last = r.at(4.20, "npc");
    assert!(
        (last.x - (there.x - 21.0)).abs() < S_TOL && (last.y - 5.75).abs() < S_TOL,
        "{last:?}"
    );
    ends_without_error("opposite_place_runtime", "straight");
}

#[test]
fn change_position_smooth_against_s_curves_from_the_direction_of_travel() {
    let r = run_on("opposite_change_position_smooth", "straight");
    // change_position_smooth.osc's figures mirrored: 0.0917 m short of (960, 3.5) at 2 s,
    // along the heading pi - 0.13077 there.
    let (h, back) = (PI - 0.13077f64, 0.0917);
    let at2 = r.at(2.0, "npc");
    assert!(
        (at2.x - (960.0 - back * h.cos())).abs() < CURVE_TOL
            && (at2.y - (3.5 - back * h.sin())).abs() < CURVE_TOL,
        "{at2:?}"
    );
    assert!(wrap(at2.h - h).abs() < CURVE_TOL, "{at2:?}");
    phase_is(&r, "do.0", 0.0, 4.05);
    let end = r.at(4.05, "npc");
    assert!(
        (end.y - 5.25).abs() < CURVE_TOL && wrap(end.h - PI).abs() < CURVE_TOL && end.lane == 2,
        "{end:?}"
    );
}

#[test]
fn follow_path_and_replay_trajectory_against_s() {
    let r = run_on("opposite_follow_path", "straight");
    let mid = r.at(1.5, "npc");
    assert!(
        (mid.x - 945.0).abs() < PATH_TOL && (mid.y - 1.75).abs() < PATH_TOL,
        "{mid:?}"
    );
    assert!(wrap(mid.h - PI).abs() < PATH_TOL, "{mid:?}");
    let at3 = r.at(3.0, "npc");
    assert!((at3.x - 930.0).abs() < PATH_TOL, "{at3:?}");
    phase_is(&r, "do.0", 0.0, 3.0);
    // replay_trajectory from 3 s: half way along the first chord 1 s in, the end 4 s in.
    let half = r.at(4.0, "npc");
    assert!(
        (half.x - 920.0).abs() < PATH_TOL && (half.y - 2.5).abs() < PATH_TOL,
        "{half:?}"
    );
    phase_is(&r, "do.1", 3.0, 7.0);
    let end = r.at(7.0, "npc");
    assert!(
        (end.x - 890.0).abs() < PATH_TOL && (end.y - 3.25).abs() < PATH_TOL && end.lane == 1,
        "{end:?}"
    );
    assert!((end.speed - 10.0).abs() < PATH_TOL, "{end:?}");
}

#[test]
fn a_route_point_is_along_its_route_in_its_direction() {
    let r = run_on("opposite_route_point", "straight");
    assert!((r.at(1.0, "npc").x - 890.0).abs() < S_TOL);
    let npc = r.at(1.05, "npc");
    assert!(
        (npc.x - 850.0).abs() < S_TOL && (npc.y - 5.25).abs() < S_TOL && npc.lane == 2,
        "{npc:?}"
    );
    let npc = r.at(2.0, "npc");
    assert!(
        (npc.x - 840.5).abs() < S_TOL && wrap(npc.h - PI).abs() < H_TOL,
        "{npc:?}"
    );
    assert!((r.at(1.0, "ego").x - 40.0).abs() < S_TOL);
    let ego = r.at(1.05, "ego");
    assert!(
        (ego.x - 100.0).abs() < S_TOL && (ego.y + 1.75).abs() < S_TOL && ego.lane == -1,
        "{ego:?}"
    );
    let ego = r.at(2.0, "ego");
    assert!(
        (ego.x - 109.5).abs() < S_TOL && wrap(ego.h).abs() < H_TOL,
        "{ego:?}"
    );
}

#[test]
fn an_acceleration_followed_from_an_oncoming_actor_is_its_acceleration() {
    let r = run_on("opposite_acceleration_follow", "straight");
    for (t, truck_v, npc_v) in [
        (4.0, 13.0, 7.0),
        (5.0, 10.0, 4.0),
        (6.0, 10.0, 4.0),
        (7.0, 10.0, 4.0),
    ] {
        let (truck, npc) = (r.at(t, "truck"), r.at(t, "npc"));
        assert!(
            (truck.speed - truck_v).abs() < S_TOL,
            "truck at {t}: {truck:?}"
        );
        assert!((npc.speed - npc_v).abs() < S_TOL, "npc at {t}: {npc:?}");
        assert!(npc.lane == 2 && wrap(npc.h - PI).abs() < H_TOL, "{npc:?}");
    }
    // u 101.85 m at 7 s (the plan's 102 m less the steps' lag), 4 m/s on.
    assert!(
        (r.at(7.0, "npc").x - 898.15).abs() < FOLLOW_TOL,
        "{:?}",
        r.at(7.0, "npc")
    );
    assert!(
        (r.at(8.0, "npc").x - 894.15).abs() < FOLLOW_TOL,
        "{:?}",
        r.at(8.0, "npc")
    );
}

/// `tests/scenarios/NAME.osc` on `tests/roads/ROAD.xodr` is an error holding each of `texts`
/// at `place` (line:col).
fn error_at(name: &str, road: &str, texts: &[&str], place: &str) {
    let e = error_on(name, road);
    assert!(
        texts.iter().all(|t| e.contains(t)) && e.ends_with(&format!("{name}.osc:{place}")),
        "{name}: {e}"
    );
}

/// What has no meaning for an actor driving against s: an error at its place before the run.
#[test]
fn what_has_no_meaning_against_s_is_an_error_at_its_place() {
    // yaw(0) would face an actor driving against s against its travel (§8.9.9: from the
    // road's s-axis it faces pi).
    error_at(
        "err_opposite_yaw",
        "straight",
        &[
            "expected angle 3.1416 rad relative to the road (§8.9.9: relative to the road's s-axis; the actor drives its lane against s, facing -s",
            "found 0.0000 rad",
        ],
        "12:17",
    );
    // A place in a lane driven the other way: the actor would drive on in that lane's direction.
    error_at(
        "err_opposite_assign_lane",
        "straight",
        &["expected a place in a driving lane of road 1, found s = 900.00 m, lane -1 (the actor drives against s, in lanes [2, 1]) outside them"],
        "11:40",
    );
    error_at(
        "err_opposite_path_end",
        "straight",
        &["expected a place in a driving lane of road 1, found s = 900.00 m, t = -1.75 m (the actor drives against s, in lanes [2, 1]) outside them"],
        "21:41",
    );
}

#[test]
fn relative_odr_points_against_s_are_in_the_roads_own_axes() {
    // opposite_relative_odr.osc, by hand: s from truck's 600 m along the road's s-axis, t from
    // the named lane's centre to the road's left.
    let r = run_on("opposite_relative_odr", "straight");
    assert!((r.at(1.0, "truck").x - 600.0).abs() < S_TOL);
    for (t, x, y, lane) in [
        (2.0, 590.0, 1.75, 1),
        (3.0, 580.0, 1.75, 1),
        (4.0, 570.0, 3.75, 2),
        (5.0, 560.0, 5.75, 2),
    ] {
        let truck = r.at(t, "truck");
        assert!(
            (truck.x - x).abs() < S_TOL && (truck.y - y).abs() < S_TOL && truck.lane == lane,
            "at {t}: {truck:?}"
        );
    }
    assert!(wrap(r.at(4.0, "truck").h - (4.0f64).atan2(-20.0)).abs() < H_TOL);
    assert!((r.at(5.0, "truck").speed - 20.0f64.hypot(4.0) / 2.0).abs() < S_TOL);
    phase_is(&r, "do.1", 1.0, 5.0);
}

#[test]
fn a_relative_odr_path_against_s_is_in_the_roads_own_axes() {
    // opposite_relative_path_odr.osc, by hand: the points from truck's 600 m along the road's
    // s-axis, t from the named lane's centre to the road's left, one line on lane 1's centre:
    // x = 600 - 10·(t - 1), y = 1.75, heading pi; the end (40.25 m) in the step to 5.05 s.
    let r = run_on("opposite_relative_path_odr", "straight");
    assert!((r.at(1.0, "truck").x - 600.0).abs() < S_TOL);
    for (t, x) in [(2.0, 590.0), (3.0, 580.0), (4.0, 570.0), (5.0, 560.0)] {
        let truck = r.at(t, "truck");
        assert!(
            (truck.x - x).abs() < S_TOL
                && (truck.y - 1.75).abs() < S_TOL
                && truck.lane == 1
                && wrap(truck.h - std::f64::consts::PI).abs() < H_TOL,
            "at {t}: {truck:?}"
        );
    }
    phase_is(&r, "do.1", 1.0, 5.05);
}
