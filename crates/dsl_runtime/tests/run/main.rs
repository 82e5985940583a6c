//! DSL scenarios planned, lowered and run on the engine; every expectation is worked by hand in
//! the scenario file's comment (straight road: s is the distance travelled). Times are on the
//! 0.05 s step grid.

mod actors;
mod along;
mod bad_input;
mod car_following;
mod crossings;
mod declared;
mod distance;
mod gap_actions;
mod groups;
mod handlers;
mod held_relations;
mod keep_args;
mod lane_side;
mod lateral;
mod lateral_actions;
mod links;
mod lists;
mod map;
mod map_modifiers;
mod opposite;
mod opposite_actions;
mod opposite_gaps;
mod opposite_groups;
mod opposite_relations;
mod orientation;
mod orientation_runtime;
mod overlap;
mod paths;
mod position_actions;
mod random_traffic;
mod random_traffic_creation;
mod random_traffic_later;
mod random_traffic_runtime;
mod relative_modifiers;
mod reuse;
mod routes;
mod runtime;
mod runtime_place;
mod runtime_rates;
mod runtime_relative_speed;
mod runtime_start_checks;
mod shapes;
mod speed_actions;
mod support;
mod track;

use support::{error, run, DT};

/// Positions: the engine integrates speed exactly on a straight road; allow float round-off.
const S_TOL: f64 = 1e-6;
/// Event times are step times.
const T_TOL: f64 = 1e-9;

#[test]
fn constant_speed_position_after_t() {
    let r = run("constant_speed", 0, None);
    let ego = r.at(0.0, "ego");
    assert_eq!(ego.lane, -3);
    assert!((ego.s - 50.0).abs() < S_TOL);
    assert!(
        (ego.y + 8.75).abs() < S_TOL,
        "lane -3 centre at t = -8.75 m"
    );
    assert!((r.at(2.5, "ego").s - 100.0).abs() < S_TOL);
    assert!((r.at(5.0, "ego").s - 150.0).abs() < S_TOL);
    let (start, end) = r.phase("do");
    assert!((start - 0.0).abs() < T_TOL && (end - 5.0).abs() < T_TOL);
    assert!(
        (r.last_time() - 5.0).abs() < T_TOL,
        "the run ends with the phase"
    );
}

#[test]
fn serial_phases_follow_each_other() {
    let r = run("serial_speeds", 0, None);
    let (s0, e0) = r.phase("do.slow");
    let (s1, e1) = r.phase("do.fast");
    let (s, e) = r.phase("do");
    assert_eq!((s0, e0, s1, e1, s, e), (0.0, 2.0, 2.0, 5.0, 0.0, 5.0));
    assert_eq!(r.at(0.0, "ego").lane, -2);
    assert!((r.at(2.0, "ego").s - 120.0).abs() < S_TOL);
    assert!((r.at(5.0, "ego").s - 180.0).abs() < S_TOL);
    assert!((r.at(3.0, "ego").speed - 20.0).abs() < S_TOL);
}

#[test]
fn parallel_ends_with_its_longest_member_or_its_duration() {
    let r = run("parallel_timing", 0, None);
    assert_eq!(r.phase("do.both.0"), (0.0, 2.0));
    assert_eq!(r.phase("do.both.1"), (0.0, 3.0));
    assert_eq!(r.phase("do.both"), (0.0, 3.0));
    let (s, e) = r.phase("do.shared");
    assert!((s - 3.0).abs() < T_TOL && (e - 7.0).abs() < T_TOL);
    let (s, e) = r.phase("do.shared.0");
    assert!((s - 3.0).abs() < T_TOL && (e - 7.0).abs() < T_TOL);
    assert_eq!(r.at(0.0, "npc").lane, -1);
    assert!((r.at(7.0, "ego").s - 170.0).abs() < S_TOL);
    assert!((r.at(7.0, "npc").s - 225.0).abs() < S_TOL);
}

#[test]
fn wait_elapsed_holds_the_serial_for_its_time() {
    let r = run("wait_elapsed", 0, None);
    assert_eq!(r.phase("do.0"), (0.0, 1.0));
    let (s, e) = r.phase("do.1");
    assert!((s - 1.0).abs() < T_TOL && (e - 4.0).abs() < T_TOL);
    let (s, e) = r.phase("do.2");
    assert!((s - 4.0).abs() < T_TOL && (e - 5.0).abs() < T_TOL);
    assert!((r.at(4.0, "ego").s - 60.0).abs() < S_TOL);
    assert!((r.at(5.0, "ego").s - 60.0).abs() < S_TOL);
}

#[test]
fn duration_range_is_drawn_from_the_seed() {
    let mut seen = Vec::new();
    for seed in [1, 2, 3] {
        let a = support::lower("duration_range", seed, None).expect("plans");
        let b = support::lower("duration_range", seed, None).expect("plans");
        let end = a
            .phases
            .iter()
            .find(|p| p.path == "do")
            .and_then(|p| p.end)
            .expect("known end");
        assert_eq!(
            Some(end),
            b.phases.iter().find(|p| p.path == "do").and_then(|p| p.end),
            "same seed, same draw"
        );
        assert!((2.0..=6.0).contains(&end), "{end} within [2 s, 6 s]");
        seen.push(end);
    }
    assert!(
        seen[0] != seen[1] && seen[1] != seen[2],
        "different seeds draw differently: {seen:?}"
    );
    // The run ends at the first step at or after the drawn end, where s = 10 + 10·t.
    let r = run("duration_range", 1, None);
    let t = r.last_time();
    assert!(
        t >= seen[0] - T_TOL && t < seen[0] + DT,
        "{t} is the step of {}",
        seen[0]
    );
    assert!((r.at(t, "ego").s - (10.0 + 10.0 * t)).abs() < S_TOL);
}

#[test]
fn one_of_runs_the_member_the_seed_draws() {
    let mut branches = std::collections::BTreeSet::new();
    for seed in 0..12 {
        let r = run("one_of", seed, None);
        let slow = r.when("do.slow", "Start").is_some();
        let fast = r.when("do.fast", "Start").is_some();
        assert!(slow != fast, "exactly one member runs");
        let want = if slow { 30.0 } else { 70.0 };
        assert!((r.at(2.0, "ego").s - want).abs() < S_TOL);
        branches.insert(slow);
        // Same seed, same branch.
        let again = run("one_of", seed, None);
        assert_eq!(again.when("do.slow", "Start").is_some(), slow);
    }
    assert_eq!(branches.len(), 2, "both members are drawn over 12 seeds");
}

#[test]
fn position_at_end_is_met_by_the_planned_speed_profile() {
    let r = run("position_end", 0, None);
    assert!((r.at(0.0, "npc").s - 90.0).abs() < S_TOL);
    assert_eq!(r.at(0.0, "npc").lane, -1);
    // The speed profile's corner: 30 m/s at 3 s, 165 m.
    assert!((r.at(3.0, "npc").speed - 30.0).abs() < 1e-6);
    let (_, end) = r.phase("do");
    assert!((end - 6.0).abs() < T_TOL);
    let (ego, npc) = (r.at(6.0, "ego"), r.at(6.0, "npc"));
    assert!((ego.s - 220.0).abs() < S_TOL);
    // Met within the plan's 0.5 m at the phase end (the engine's linear speed change is
    // integrated per step: 165 m and 240 m up to its discretisation).
    let gap = npc.s - ego.s;
    assert!(
        (gap - 20.0).abs() < dsl_runtime::POSITION_TOLERANCE,
        "gap {gap}"
    );
    assert!((r.at(3.0, "npc").s - 165.0).abs() < dsl_runtime::POSITION_TOLERANCE);
}

#[test]
fn lane_at_end_is_met_by_a_lane_change_over_the_phase() {
    let r = run("lane_end", 0, None);
    assert_eq!(r.at(0.0, "npc").lane, -1);
    let npc = r.at(3.0, "npc");
    assert_eq!(npc.lane, r.at(3.0, "ego").lane);
    assert_eq!(npc.lane, -2);
    assert!(
        (npc.y + 5.25).abs() < 1e-6,
        "on the lane centre: y = {}",
        npc.y
    );
    // Half way through the sinusoidal change it is half way between the lane centres.
    assert!(
        (r.at(1.5, "npc").y + 3.5).abs() < 0.05,
        "y(1.5) = {}",
        r.at(1.5, "npc").y
    );
}

#[test]
fn until_ends_a_phase_at_the_step_its_method_condition_first_holds() {
    let r = run("until_headway", 0, None);
    let (s, e) = r.phase("do.close.1");
    assert!(
        (s - 0.0).abs() < T_TOL && (e - 3.9).abs() < T_TOL,
        "ego phase [{s}, {e}]"
    );
    // The parallel ends with its member that has an end, and lead's drive with it.
    assert!((r.phase("do.close").1 - 3.9).abs() < T_TOL);
    assert!((r.phase("do.close.0").1 - 3.9).abs() < T_TOL);
    // The next phase starts in the same step and lasts its 2 s.
    let (s, e) = r.phase("do.follow");
    assert!(
        (s - 3.9).abs() < T_TOL && (e - 5.9).abs() < T_TOL,
        "follow [{s}, {e}]"
    );
    assert!((r.at(3.9, "ego").s - 178.0).abs() < S_TOL);
    assert!((r.at(5.9, "ego").s - 202.0).abs() < S_TOL);
}

#[test]
fn errors_name_the_place_before_the_run() {
    let e = error("err_unsatisfiable_end");
    assert!(e.contains("err_unsatisfiable_end.osc:14:13"), "{e}");
    assert!(e.contains("70 m/s") && e.contains("270.00 m/s"), "{e}");
    let e = error("err_unknown_actor");
    assert!(
        e.contains("unknown name `npc` at ") && e.contains("err_unknown_actor.osc:6:9"),
        "{e}"
    );
    let e = error("err_modifier_wrong_action");
    assert!(
        e.contains("modifier `speed` applies to `movable_object.action_for_movable_object`, not to `vehicle.honk`")
            && e.contains("err_modifier_wrong_action.osc:8:9"),
        "{e}"
    );
    let e = error("err_start_speed");
    assert!(
        e.contains("expected a start speed of `npc` within 0 to 70 m/s, found -3.00 m/s")
            && e.contains("err_start_speed.osc:10:13"),
        "{e}"
    );
    let e = error("err_no_end");
    assert!(
        e.contains("expected a way for phase `do.0` to end") && e.contains("err_no_end.osc:5:9"),
        "{e}"
    );
}

/// One error for the crate: `dsl`'s check errors and `opendrive`'s stay typed inside it
/// (`ErrorKind::Check`, `ErrorKind::RoadNetwork`) beside the planner's kinds, and `pos()` is
/// the place the text names (the places of `errors_name_the_place_before_the_run`).
#[test]
fn one_error_keeps_the_check_and_road_network_errors_typed() {
    let place = |e: &dsl_runtime::Error| {
        let p = e.pos().unwrap_or_else(|| panic!("{e}: no place"));
        let file = p
            .file
            .file_name()
            .and_then(|f| f.to_str())
            .unwrap_or_default()
            .to_owned();
        (file, p.line, p.col)
    };
    let e = support::lower("err_unknown_actor", 0, None).expect_err("unknown actor");
    assert!(
        matches!(e.kind(), dsl_runtime::ErrorKind::Check(_)),
        "{e:?}"
    );
    assert_eq!(place(&e), ("err_unknown_actor.osc".to_owned(), 6, 9), "{e}");
    let e = support::lower("err_unsatisfiable_end", 0, None).expect_err("unsatisfiable");
    assert!(
        matches!(e.kind(), dsl_runtime::ErrorKind::Unsatisfiable),
        "{e:?}"
    );
    assert_eq!(
        place(&e),
        ("err_unsatisfiable_end.osc".to_owned(), 14, 13),
        "{e}"
    );
    let e = support::lower_at(
        "tests/scenarios/constant_speed.osc",
        "tests/roads/no_such_road.xodr",
        0,
        None,
    )
    .expect_err("no road file");
    assert!(
        matches!(e.kind(), dsl_runtime::ErrorKind::RoadNetwork(_)),
        "{e:?}"
    );
    assert_eq!(place(&e), ("no_such_road.xodr".to_owned(), 1, 1), "{e}");
}

#[test]
fn driving_alongside_group_runs_beside_the_dut() {
    // The seed's §8.7.18.1.1 Code 4 as written, on the bundled highway (right lanes -1, -2, -3),
    // bounded by --duration as it has no end of its own.
    for seed in 0..6 {
        let lowered = support::lower_at(
            "../dsl/tests/files/seed/driving_alongside_group.osc",
            "../../examples/roads/highway.xodr",
            seed,
            Some(2.0),
        )
        .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        let objects = &lowered.scenario.entities.scenario_objects;
        let members: Vec<&scenario::ScenarioObject> = objects
            .iter()
            .filter(|o| o.name.starts_with("g.vehicles["))
            .collect();
        assert!(
            (2..=4).contains(&members.len()),
            "seed {seed}: {} members",
            members.len()
        );
        for m in &members {
            let scenario::EntityObject::Vehicle(v) = &m.entity_object else {
                panic!("{} is no vehicle", m.name)
            };
            assert!(
                matches!(
                    v.vehicle_category,
                    scenario::VehicleCategory::Bus | scenario::VehicleCategory::Truck
                ),
                "seed {seed}: {} is a {:?}",
                m.name,
                v.vehicle_category
            );
        }
        let r = support::run_scenario(
            "driving_alongside_group",
            &lowered.scenario,
            seed,
            Some(2.0),
        );
        let dut = r.at(0.0, "dut.vehicle");
        let mut previous_s = f64::INFINITY;
        for (i, _) in members.iter().enumerate() {
            let m = r.at(0.0, &format!("g.vehicles[{i}]"));
            // Beside the dut: the lane to its left (ids grow towards the centre on the right
            // side), all members in that one lane (single-lane group), in list order from the
            // front, member 0 alongside the dut.
            assert_eq!(
                m.lane,
                dut.lane + 1,
                "seed {seed}: member {i} in lane {} beside {}",
                m.lane,
                dut.lane
            );
            assert!(
                m.s < previous_s,
                "seed {seed}: member {i} behind member {}",
                i.saturating_sub(1)
            );
            if i == 0 {
                assert!((m.s - dut.s).abs() < 1e-6, "member 0 alongside the dut");
            }
            previous_s = m.s;
        }
        assert!((r.last_time() - 2.0).abs() < T_TOL);
    }
}

#[test]
fn dsl_cut_in_matches_the_xml_cut_in_within_a_tenth_of_a_metre() {
    // examples/scenarios/cut_in_highway.osc against cut_in_highway.xosc: same start states,
    // the lane change on the same freespace condition, the brake 0.5 s after it.
    const MATCH: f64 = 0.1;
    let lowered = support::lower_at(
        "../../examples/scenarios/cut_in_highway.osc",
        "../../examples/roads/highway.xodr",
        0,
        Some(10.0),
    )
    .expect("plans");
    let dsl = support::run_scenario("cut_in_highway.osc", &lowered.scenario, 0, Some(10.0));
    let xml_model = scenario::Scenario::load(&support::path(
        "../../examples/scenarios/cut_in_highway.xosc",
    ))
    .expect("loads");
    let xml = support::run_scenario("cut_in_highway.xosc", &xml_model, 0, None);
    assert_eq!(dsl.frames.len(), xml.frames.len());
    let mut worst: f64 = 0.0;
    for ((t, a), (u, b)) in dsl.frames.iter().zip(&xml.frames) {
        assert!((t - u).abs() < T_TOL);
        for (dsl_name, xml_name) in [("ego", "Ego"), ("overtaker", "OverTaker")] {
            let p = a.iter().find(|o| o.name == dsl_name).expect("dsl entity");
            let q = b.iter().find(|o| o.name == xml_name).expect("xml entity");
            worst = worst.max(((p.x - q.x).powi(2) + (p.y - q.y).powi(2)).sqrt());
        }
    }
    assert!(worst < MATCH, "largest distance {worst} m");
    // The phases' lines in the event log: the cut-in starts where the XML's CutInEvent does.
    assert_eq!(
        dsl.when("do.cut_in", "Start"),
        xml.when("CutInEvent", "Start")
    );
    assert_eq!(
        dsl.when("do.brake", "Start"),
        xml.when("BrakeEvent", "Start")
    );
}

/// The engine moves each step with the speed at the step's end, so during a linear speed change
/// at `a` m/s² it is ahead of the exact integral by a·dt/2 per second of the change.
fn ramp_lead(a: f64, seconds: f64) -> f64 {
    0.5 * a * DT * seconds
}

#[test]
fn change_speed_is_a_linear_change_over_the_phase() {
    let r = run("change_speed", 0, None);
    assert!((r.at(2.0, "ego").speed - 20.0).abs() < S_TOL);
    assert!((r.at(2.0, "ego").s - (50.0 + ramp_lead(5.0, 2.0))).abs() < S_TOL);
    assert!((r.at(4.0, "ego").s - (100.0 + ramp_lead(5.0, 4.0))).abs() < S_TOL);
    assert!((r.at(5.0, "ego").s - (130.0 + ramp_lead(5.0, 4.0))).abs() < S_TOL);
    assert_eq!(r.phase("do.0"), (0.0, 4.0));
    assert_eq!(r.phase("do.1"), (4.0, 5.0));
}

#[test]
fn speed_at_end_brakes_to_a_stop_over_the_phase() {
    let r = run("speed_end", 0, None);
    assert!((r.at(2.5, "ego").speed - 10.0).abs() < S_TOL);
    assert!((r.at(2.5, "ego").s - (77.5 - ramp_lead(4.0, 2.5))).abs() < S_TOL);
    assert!(r.at(5.0, "ego").speed.abs() < S_TOL);
    assert!((r.at(5.0, "ego").s - (90.0 - ramp_lead(4.0, 5.0))).abs() < S_TOL);
}

#[test]
fn speed_faster_than_another_actor() {
    let r = run("faster_than", 0, None);
    assert!((r.at(0.0, "npc").speed - 20.0).abs() < S_TOL);
    assert_eq!((r.at(0.0, "ego").lane, r.at(0.0, "npc").lane), (-2, -3));
    assert!((r.at(4.0, "ego").s - 160.0).abs() < S_TOL);
    assert!((r.at(4.0, "npc").s - 170.0).abs() < S_TOL);
}

#[test]
fn change_lane_moves_one_lane_left_over_the_phase() {
    let r = run("change_lane", 0, None);
    assert!((r.at(0.0, "ego").y + 8.75).abs() < S_TOL);
    assert!((r.at(2.0, "ego").y + 7.0).abs() < 1e-6, "half way at 2 s");
    let end = r.at(4.0, "ego");
    assert_eq!(end.lane, -2);
    assert!((end.y + 5.25).abs() < 1e-6);
    // 10 m/s along a path that also moves 3.5 m sideways: a little less than 40 m of s.
    assert!(end.s < 70.0 && end.s > 69.5, "s = {}", end.s);
}

#[test]
fn position_by_time_behind_a_reference() {
    let r = run("position_time", 0, None);
    assert!((r.at(0.0, "npc").s - 160.0).abs() < S_TOL);
    assert_eq!(r.at(0.0, "npc").lane, r.at(0.0, "ego").lane);
    assert!((r.at(3.0, "ego").s - 260.0).abs() < S_TOL);
    assert!((r.at(3.0, "npc").s - 220.0).abs() < S_TOL);
}

#[test]
fn lanes_counted_from_the_right_or_from_the_left() {
    let r = run("lane_from_left", 0, None);
    assert_eq!(r.at(0.0, "a").lane, -1);
    assert_eq!(r.at(0.0, "b").lane, -2);
    assert_eq!(r.at(0.0, "c").lane, -1);
    // No speed given: 50 km/h.
    assert!((r.at(0.0, "a").speed - 50.0 / 3.6).abs() < S_TOL);
}

#[test]
fn until_time_to_collision_ends_at_its_first_step() {
    let r = run("until_ttc", 0, None);
    let (_, end) = r.phase("do.0");
    assert!((end - 2.95).abs() < T_TOL, "ends at {end}");
    assert!((r.phase("do").1 - 2.95).abs() < T_TOL);
    assert!(
        (r.phase("do.1").1 - 2.95).abs() < T_TOL,
        "lead ends with the parallel"
    );
}

#[test]
fn wait_on_a_space_gap_then_the_next_phase() {
    let r = run("wait_condition", 0, None);
    let (s, e) = r.phase("do.approach.1");
    assert!(
        (s - 1.0).abs() < T_TOL && (e - 1.55).abs() < T_TOL,
        "wait [{s}, {e}]"
    );
    let (s, e) = r.phase("do.approach.2");
    assert!(
        (s - 1.55).abs() < T_TOL && (e - 2.55).abs() < T_TOL,
        "drive [{s}, {e}]"
    );
    assert!((r.phase("do.approach").1 - 2.55).abs() < T_TOL);
    assert!(
        (r.phase("do").1 - 6.0).abs() < T_TOL,
        "lead's 6 s end the parallel"
    );
    assert!((r.at(1.55, "ego").s - 131.0).abs() < S_TOL);
    assert!((r.at(2.55, "ego").s - 141.0).abs() < S_TOL);
}

#[test]
fn serial_inside_a_parallel() {
    let r = run("nested", 0, None);
    assert_eq!(r.phase("do.ego_part.0"), (0.0, 2.0));
    assert_eq!(r.phase("do.ego_part.1"), (2.0, 4.0));
    assert_eq!(r.phase("do.ego_part"), (0.0, 4.0));
    assert_eq!(r.phase("do.1"), (0.0, 5.0));
    assert_eq!(r.phase("do"), (0.0, 5.0));
    assert!((r.at(4.0, "ego").s - 70.0).abs() < S_TOL);
    assert!((r.at(5.0, "ego").s - 90.0).abs() < S_TOL);
    assert!((r.at(5.0, "npc").s - 105.0).abs() < S_TOL);
}

#[test]
fn serial_duration_gives_the_rest_to_its_last_member() {
    let r = run("serial_duration", 0, None);
    assert_eq!(r.phase("do.0"), (0.0, 2.0));
    assert_eq!(r.phase("do.1"), (2.0, 6.0));
    assert!((r.at(6.0, "ego").s - 110.0).abs() < S_TOL);
}

#[test]
fn until_rise_of_speed_during_a_speed_change() {
    let r = run("until_rise_speed", 0, None);
    let (_, e) = r.phase("do.speed_up");
    assert!((e - 1.1).abs() < T_TOL, "ends at {e}");
    let (s, e) = r.phase("do.settle");
    assert!(
        (s - 1.1).abs() < T_TOL && (e - 2.1).abs() < T_TOL,
        "settle [{s}, {e}]"
    );
    assert!((r.at(1.05, "ego").speed - 14.9875).abs() < 1e-9);
    assert!((r.at(1.1, "ego").speed - 15.225).abs() < 1e-9);
    assert!((r.at(2.1, "ego").speed - 12.0).abs() < S_TOL);
}

#[test]
fn every_checked_fixture_plans_or_fails_with_a_position_never_a_panic() {
    // The language front end's fixtures (semantic cases, seed examples): whatever they do,
    // planning them on the test road gives a plan or an error at FILE:LINE:COL.
    let root = support::path("../dsl/tests/files");
    let mut files = Vec::new();
    for dir in ["semantics", "seed", "syntax"] {
        if let Ok(entries) = std::fs::read_dir(root.join(dir)) {
            files.extend(
                entries
                    .flatten()
                    .map(|e| e.path())
                    .filter(|p| p.extension().is_some_and(|x| x == "osc")),
            );
        }
    }
    files.sort();
    assert!(files.len() > 100, "{} fixtures", files.len());
    let road = support::path("tests/roads/straight.xodr");
    let (mut planned, mut refused) = (0, 0);
    // Bounded runs (open ends allowed), so that open-ended fixtures such as the seed's plan too.
    let options = dsl_runtime::Options {
        seed: 3,
        dt: DT,
        open_end: true,
        scenario: None,
    };
    for f in &files {
        match dsl_runtime::load(f, Some(&road), &options) {
            Ok(_) => planned += 1,
            Err(e) => {
                // The planner's own kinds: a place in the file itself, 1-based.
                if matches!(
                    e.kind(),
                    dsl_runtime::ErrorKind::Check(_) | dsl_runtime::ErrorKind::RoadNetwork(_)
                ) {
                    continue;
                }
                refused += 1;
                let pos = e
                    .pos()
                    .unwrap_or_else(|| panic!("{}: {e} has no place", f.display()));
                assert!(
                    pos.file.as_ref() == f.as_path() && pos.line >= 1 && pos.col >= 1,
                    "{}: {e}",
                    f.display()
                );
            }
        }
    }
    assert!(
        planned > 0 && refused > 0,
        "planned {planned}, refused {refused}"
    );
}

#[test]
fn position_at_end_holds_in_road_s_on_a_curved_road() {
    let lowered = support::lower_at(
        "tests/scenarios/position_end_curved.osc",
        "../../examples/roads/highway.xodr",
        0,
        None,
    )
    .expect("plans");
    let r = support::run_scenario("position_end_curved", &lowered.scenario, 0, None);
    assert!((r.phase("do").1 - 6.0).abs() < T_TOL);
    let (ego, npc) = (r.at(6.0, "ego"), r.at(6.0, "npc"));
    let gap = npc.s - ego.s;
    assert!(
        (gap - 15.0).abs() < dsl_runtime::POSITION_TOLERANCE,
        "gap {gap} m in s"
    );
}

#[test]
fn until_elapsed_caps_the_duration() {
    let r = run("until_elapsed", 0, None);
    let (s, e) = r.phase("do");
    assert!(s.abs() < T_TOL && (e - 1.5).abs() < T_TOL, "[{s}, {e}]");
    assert!((r.at(1.5, "ego").s - 48.0).abs() < S_TOL);
}

#[test]
fn the_scenario_names_its_road_network() {
    let options = dsl_runtime::Options {
        seed: 0,
        dt: DT,
        open_end: false,
        scenario: None,
    };
    let lowered = dsl_runtime::load(
        &support::path("tests/scenarios/map_file.osc"),
        None,
        &options,
    )
    .expect("plans on the map it names");
    let road = lowered
        .scenario
        .road_network
        .logic_file
        .clone()
        .expect("a road");
    assert!(road.ends_with("roads/straight.xodr"), "{}", road.display());
    let r = support::run_scenario("map_file", &lowered.scenario, 0, None);
    assert!((r.at(2.0, "ego").s - 41.0).abs() < S_TOL);
    // Without a map and without --road: an error before the run.
    let e = dsl_runtime::load(
        &support::path("tests/scenarios/constant_speed.osc"),
        None,
        &options,
    )
    .expect_err("no road");
    assert!(e.to_string().contains("expected a road network"), "{e}");
}

#[test]
fn a_serial_duration_stops_its_running_member_and_skips_the_rest() {
    let r = run("serial_cap", 0, None);
    assert_eq!(r.phase("do.0"), (0.0, 2.0));
    assert_eq!(r.phase("do"), (0.0, 2.0));
    assert_eq!(r.when("do.1", "Start"), None);
    assert!((r.at(2.0, "ego").s - 30.0).abs() < S_TOL);
    assert!((r.last_time() - 2.0).abs() < T_TOL);
}

#[test]
fn emit_and_wait_on_events() {
    let r = run("events", 0, None);
    // The emit is an instant at 2 s.
    assert_eq!(r.when("do.ego_part.1", "Start"), Some(2.0));
    assert_eq!(r.when("do.ego_part.1", "End"), Some(2.0));
    let (_, e) = r.phase("do.npc_part.0");
    assert!((e - 2.05).abs() < T_TOL, "until @passed ends at {e}");
    let (s, e) = r.phase("do.npc_part.1");
    assert!((s - 2.05).abs() < T_TOL && (e - 3.05).abs() < T_TOL);
    assert!((r.at(2.05, "npc").s - 30.25).abs() < S_TOL);
    assert!((r.at(3.05, "npc").s - 30.25).abs() < S_TOL);
    // wait @fast (a condition true from the start) ends in the step after it starts, and the
    // serial with it.
    let (s, e) = r.phase("do.ego_part.3");
    assert!(
        (s - 3.0).abs() < T_TOL && (e - 3.05).abs() < T_TOL,
        "wait [{s}, {e}]"
    );
    assert!((r.phase("do.ego_part").1 - 3.05).abs() < T_TOL);
}

#[test]
fn acceleration_sets_the_rate_of_the_speed_change() {
    let r = run("acceleration", 0, None);
    assert!((r.at(3.0, "ego").speed - 16.0).abs() < S_TOL);
    assert!((r.at(3.0, "ego").s - (59.0 + ramp_lead(2.0, 3.0))).abs() < S_TOL);
    assert!((r.at(5.0, "ego").speed - 10.0).abs() < S_TOL);
    assert!((r.at(5.0, "ego").s - 85.0).abs() < S_TOL);
    assert!((r.at(7.0, "ego").s - 105.0).abs() < S_TOL);
    let e = error("err_acceleration_too_slow");
    assert!(
        e.contains("found it needs 20.00 s") && e.contains("err_acceleration_too_slow.osc:7:9"),
        "{e}"
    );
}
