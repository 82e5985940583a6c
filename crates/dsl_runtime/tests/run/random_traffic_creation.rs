//! What the phase creating random traffic asks (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1;
//! plan/random_traffic_creation.rs, plan/random_traffic.rs): a speed action as the creating
//! action, and the modifiers that say where the members are dealt. Expectations in the
//! scenario files.

use crate::random_traffic::{free_road_speed, lane_gaps};
use crate::support::{run, Obj, Run};

/// Positions of an actor driving its plan on a straight road: float round-off only (m).
const S_TOL: f64 = 1e-6;
/// The IDM's minimum gap s0 (m) and time headway T (s), the engine's defaults.
const S0: f64 = 2.0;
const T: f64 = 1.6;
/// The default desired speed, 50 km/h (m/s).
const V_DEFAULT: f64 = 50.0 / 3.6;

/// A vehicle's box along s (4 m boxes, reference point 0.5 m from the rear; lanes 1 and 2 are
/// driven in −s, their front at lower s).
fn box_in_s(o: &Obj) -> (i32, f64, f64) {
    if o.lane > 0 {
        (o.lane, o.s - 3.5, o.s + 0.5)
    } else {
        (o.lane, o.s - 0.5, o.s + 3.5)
    }
}

/// The gaps at `t` between `names` in each lane are s0 + v_max·T or more (v_max the fastest).
fn apart(r: &Run, seed: u64, t: f64, names: &[String]) {
    let v_max = names.iter().fold(0.0_f64, |a, m| a.max(r.at(t, m).speed));
    let mut boxes: Vec<(i32, f64, f64, &str)> = names
        .iter()
        .map(|m| {
            let (l, a, b) = box_in_s(r.at(t, m));
            (l, a, b, m.as_str())
        })
        .collect();
    for (gap, a, b, _) in lane_gaps(&mut boxes) {
        assert!(
            gap >= S0 + v_max * T - S_TOL,
            "seed {seed}: {a} to {b}: {gap} m"
        );
    }
}

fn names(g: &str, n: usize, others: &[&str]) -> Vec<String> {
    (0..n)
        .map(|i| format!("{g}.vehicles[{i}]"))
        .chain(others.iter().map(|o| (*o).to_string()))
        .collect()
}

#[test]
fn random_traffic_created_by_change_speed_is_drawn_as_by_drive_then_its_model_takes_the_target() {
    let m = "g.vehicles[0]";
    for seed in 0..4 {
        let r = run("random_traffic_create_speed", seed, None);
        let v_start = r.at(0.0, m).speed;
        assert!(
            (0.9 * V_DEFAULT - S_TOL..=1.1 * V_DEFAULT + S_TOL).contains(&v_start),
            "seed {seed}: v(0) = {v_start}"
        );
        assert!(r.at(0.0, m).lane < 0, "along(r): +s");
        // The change_speed phase ends at once (the model has the target).
        let (start, end) = r.phase("do.0");
        assert!(start.abs() < 1e-9 && end.abs() < 1e-9, "{start} {end}");
        // The IDM's free-road closed form towards 20 m/s (the engine's 0.05 s steps differ
        // by under 1 cm/s, random_traffic_free.osc), while the box is on the road.
        let mut checked = 0;
        for k in 1..=20 {
            let t = f64::from(k);
            let got = r.at(t, m);
            if got.s + 3.5 > 999.0 {
                break;
            }
            checked += 1;
            let want = free_road_speed(v_start, 20.0, 0.73, t);
            assert!(
                (got.speed - want).abs() < 0.01,
                "seed {seed}: v({t}) = {}, closed form {want}",
                got.speed
            );
        }
        assert!(checked >= 5, "seed {seed}: {checked} s on the road");
        if seed == 1 {
            // By hand (the scenario's comment): 12.8682 m/s, 15.555 m/s at 5 s, 17.470 at 10 s.
            assert!((v_start - 12.8682).abs() < 1e-3, "v(0) = {v_start}");
            assert!((r.at(5.0, m).speed - 15.555).abs() < 0.01);
            assert!((r.at(10.0, m).speed - 17.470).abs() < 0.01);
        }
    }
}

#[test]
fn random_traffic_created_by_keep_speed_keeps_its_drawn_speed() {
    let m = "g.vehicles[0]";
    for seed in 0..4 {
        let r = run("random_traffic_create_keep", seed, None);
        let (v0, s0) = (r.at(0.0, m).speed, r.at(0.0, m).s);
        assert!(
            (0.9 * V_DEFAULT - S_TOL..=1.1 * V_DEFAULT + S_TOL).contains(&v0),
            "seed {seed}: v(0) = {v0}"
        );
        for (t, _) in &r.frames {
            let o = r.at(*t, m);
            if o.s + 3.5 > 999.0 {
                break;
            }
            assert!(
                (o.speed - v0).abs() < 1e-9,
                "seed {seed}: v({t}) = {}",
                o.speed
            );
            assert!(
                (o.s - (s0 + v0 * t)).abs() < S_TOL,
                "seed {seed}: s({t}) = {}",
                o.s
            );
        }
    }
}

#[test]
fn random_traffic_with_a_position_is_dealt_from_it_on_in_each_direction() {
    let all = names("g", 6, &["ego"]);
    for seed in 0..4 {
        let r = run("random_traffic_position", seed, None);
        for m in all.iter().filter(|m| m.starts_with("g.")) {
            let o = r.at(0.0, m);
            let (lane, rear, front) = box_in_s(o);
            if lane < 0 {
                assert!(rear >= 600.0 - S_TOL, "seed {seed}: {o:?}");
            } else {
                // u = 1000 − s along its direction: its rear (the larger s) at u ≥ 600 m.
                assert!(1000.0 - front >= 600.0 - S_TOL, "seed {seed}: {o:?}");
            }
        }
        apart(&r, seed, 0.0, &all);
    }
}

#[test]
fn random_traffic_along_a_lane_field_is_dealt_to_that_lane_only() {
    let all = names("g", 5, &["ego"]);
    for seed in 0..4 {
        let r = run("random_traffic_along_lane", seed, None);
        assert_eq!(r.at(0.0, "ego").lane, -2);
        for m in &all {
            assert_eq!(r.at(0.0, m).lane, -2, "seed {seed}: {m}");
        }
        apart(&r, seed, 0.0, &all);
    }
}

#[test]
fn random_traffic_beside_an_actor_driving_against_s_is_dealt_to_the_lane_on_its_right() {
    let all = names("h", 3, &["npc"]);
    for seed in 0..4 {
        let r = run("random_traffic_beside_oncoming", seed, None);
        assert_eq!(r.at(0.0, "npc").lane, 1);
        for (t, objs) in &r.frames {
            for o in objs
                .iter()
                .filter(|o| o.name.starts_with("h.") && o.s > 4.0)
            {
                assert_eq!(o.lane, 2, "seed {seed} at {t}: {o:?}");
            }
        }
        apart(&r, seed, 0.0, &all);
    }
}

#[test]
fn what_sets_a_members_motion_on_the_creating_phase_is_bad_input() {
    let words = "\"the behavioral model assigned to each vehicle defines the actual behavior of the vehicle within the group\", §8.7.18.1";
    for (name, found, at) in [
        ("err_random_traffic_modifier", "found `lateral(…)`", "8:9"),
        (
            "err_random_traffic_create_distance",
            "found `distance(…)`",
            "7:9",
        ),
        (
            "err_random_traffic_create_position_all",
            "found it at: all or end",
            "7:9",
        ),
        (
            "err_random_traffic_create_position_ahead",
            "found it relative to another actor",
            "12:13",
        ),
        (
            "err_random_traffic_create_lane_change",
            "found change_lane(…)",
            "5:8",
        ),
    ] {
        crate::along::refused(name, found, at);
        let e = crate::support::lower(name, 0, None).expect_err(name);
        assert!(e.to_string().contains(words), "{name}: {e}");
        assert!(
            !matches!(e.kind(), dsl_runtime::ErrorKind::Unsupported),
            "{name}: {e}"
        );
    }
}

#[test]
fn random_traffic_along_a_lane_the_map_binds_is_dealt_over_its_lane_section_only() {
    let all = names("g", 3, &[]);
    for seed in 0..4 {
        let lowered = crate::support::lower_at(
            "tests/scenarios/random_traffic_along_map_lane.osc",
            "tests/roads/lane_drop.xodr",
            seed,
            None,
        )
        .expect("plans");
        let r = crate::support::run_scenario(
            "random_traffic_along_map_lane",
            &lowered.scenario,
            seed,
            None,
        );
        for m in &all {
            let (lane, rear, front) = box_in_s(r.at(0.0, m));
            assert_eq!(lane, -2, "seed {seed}: {m}");
            assert!(
                rear >= 300.0 - S_TOL && front <= 500.0 + S_TOL,
                "seed {seed}: {m} {rear}..{front}"
            );
        }
        apart(&r, seed, 0.0, &all);
    }
}

#[test]
fn random_traffic_along_the_roads_driven_against_s_is_dealt_to_their_lanes_only() {
    let all = names("g", 5, &[]);
    for seed in 0..4 {
        let r = run("random_traffic_along_opposite", seed, None);
        for m in &all {
            assert!([1, 2].contains(&r.at(0.0, m).lane), "seed {seed}: {m}");
        }
        apart(&r, seed, 0.0, &all);
    }
}

#[test]
fn random_traffic_created_later_by_change_speed_drives_towards_the_target() {
    let m = "g.vehicles[0]";
    for seed in 0..4 {
        let r = run("random_traffic_create_speed_late", seed, None);
        let at = 5.0 + crate::support::DT;
        let v_start = r.at(at, m).speed;
        assert!(
            (0.9 * V_DEFAULT - S_TOL..=1.1 * V_DEFAULT + S_TOL).contains(&v_start),
            "seed {seed}: v({at}) = {v_start}"
        );
        for k in 1..=10 {
            let t = f64::from(k);
            let got = r.at(at + t, m);
            if got.s + 3.5 > 999.0 {
                break;
            }
            let want = free_road_speed(v_start, 20.0, 0.73, t);
            assert!(
                (got.speed - want).abs() < 0.01,
                "seed {seed}: v({}) = {}, closed form {want}",
                at + t,
                got.speed
            );
        }
    }
}
