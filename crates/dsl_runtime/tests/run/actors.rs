//! Every actor of §8.7 acts (issue 27): persons and animals walk and stand, a stationary object
//! stands where its `location(pose)` puts it and is measured as an obstacle, vehicles take their
//! 1.x category from `vehicle_category`. Motion against each scenario's hand-worked comment.

use scenario::{EntityObject, MiscObjectCategory, PedestrianCategory, PositionKind, PrivateAction};

use crate::support::{lower_at, run_scenario, stepped};

/// Positions on a straight road: sums of step speeds; allow float round-off.
const S_TOL: f64 = 1e-9;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;

const SIDEWALK: &str = "tests/roads/sidewalk.xodr";

#[test]
fn persons_walk_along_the_sidewalk_and_one_stands() {
    let lowered = lower_at("tests/scenarios/actors/walkers.osc", SIDEWALK, 0, None).expect("plans");
    let objects = &lowered.scenario.entities.scenario_objects;
    let category = |name: &str| match &objects
        .iter()
        .find(|o| o.name == name)
        .expect(name)
        .entity_object
    {
        EntityObject::Pedestrian(p) => p.pedestrian_category,
        other => panic!("{name} is a {other:?}"),
    };
    assert_eq!(category("alice"), PedestrianCategory::Pedestrian);
    assert_eq!(category("bob"), PedestrianCategory::Pedestrian);
    assert_eq!(category("deer"), PedestrianCategory::Animal);
    let r = run_scenario("walkers", &lowered.scenario, 0, None);
    // alice placed on the sidewalk (lane -3, centre t = -8 m), 1.5 m/s from s = 20 m; she walks
    // along its centre. (The engine's frames give every entity the nearest driving lane, -2,
    // with its offset: its convention for entities off the driving lanes.)
    assert_eq!(init_lane(&lowered, "alice"), "-3");
    for t in [0.0, 4.0, 8.0] {
        let y = r.at(t, "alice").y;
        assert!((y + 8.0).abs() < S_TOL, "alice y({t}) = {y}");
    }
    assert!((r.at(4.0, "alice").s - 26.0).abs() < S_TOL);
    // Then linear to 2.5 m/s over 4 s: v(6) = 2 m/s.
    let v = |t: f64| {
        if t <= 4.0 {
            1.5
        } else {
            1.5 + 0.25 * (t - 4.0)
        }
    };
    assert!((r.at(6.0, "alice").speed - 2.0).abs() < S_TOL);
    let s8 = r.at(8.0, "alice").s;
    assert!(
        (s8 - (20.0 + stepped(v, 0.0, 8.0))).abs() < S_TOL,
        "s(8) = {s8}"
    );
    // The hand value 34 m plus the engine's step lead dt/2 · 1 m/s.
    assert!((20.0 + stepped(v, 0.0, 8.0) - 34.025).abs() < S_TOL);
    // bob stands at s = 60 m on the sidewalk.
    assert_eq!(init_lane(&lowered, "bob"), "-3");
    for t in [0.0, 4.0, 8.0] {
        let b = r.at(t, "bob");
        assert!((b.y + 8.0).abs() < S_TOL, "bob y({t}) = {}", b.y);
        assert!(
            (b.s - 60.0).abs() < S_TOL && b.speed.abs() < S_TOL,
            "bob at {t}: {b:?}"
        );
    }
    // The deer on the rightmost driving lane, -2, at 3 m/s.
    let d = r.at(8.0, "deer");
    assert_eq!(d.lane, -2);
    assert!((d.s - 124.0).abs() < S_TOL, "deer s(8) = {}", d.s);
    let (s, e) = r.phase("do");
    assert!(s.abs() < T_TOL && (e - 8.0).abs() < T_TOL, "[{s}, {e}]");
}

/// The lane of `name`'s Init TeleportAction.
fn init_lane(lowered: &dsl_runtime::Lowered, name: &str) -> String {
    let private = lowered
        .scenario
        .storyboard
        .init
        .privates
        .iter()
        .find(|p| p.entity_ref == name)
        .expect(name);
    match &private.actions[0].kind {
        scenario::ActionKind::Private(PrivateAction::Teleport(p)) => match &p.kind {
            PositionKind::Lane { lane_id, .. } => lane_id.clone(),
            other => panic!("{name} placed at {other:?}"),
        },
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn a_car_stops_behind_a_stationary_object_it_measures() {
    let lowered = crate::support::lower("actors/stop_behind_object", 0, None).expect("plans");
    let barrier = lowered
        .scenario
        .entities
        .scenario_objects
        .iter()
        .find(|o| o.name == "barrier")
        .expect("the barrier is an entity");
    match &barrier.entity_object {
        EntityObject::MiscObject(m) => {
            assert_eq!(m.misc_object_category, MiscObjectCategory::Barrier)
        }
        other => panic!("barrier is a {other:?}"),
    }
    let r = run_scenario("stop_behind_object", &lowered.scenario, 0, None);
    let b = r.at(0.0, "barrier");
    assert!(
        (b.x - 150.0).abs() < S_TOL && (b.y + 8.75).abs() < S_TOL,
        "{b:?}"
    );
    let (s, e) = r.phase("do.approach");
    assert!(
        s.abs() < T_TOL && (e - 3.85).abs() < T_TOL,
        "approach [{s}, {e}]"
    );
    assert!((r.at(3.85, "car").s - 97.0).abs() < S_TOL);
    let (s, e) = r.phase("do.brake");
    assert!(
        (s - 3.85).abs() < T_TOL && (e - 7.85).abs() < T_TOL,
        "brake [{s}, {e}]"
    );
    assert!((r.at(5.85, "car").speed - 10.0).abs() < S_TOL);
    let v = |t: f64| (20.0 - 5.0 * (t - 3.85)).max(0.0);
    let stop = 97.0 + stepped(v, 3.85, 7.85);
    assert!((stop - 136.5).abs() < S_TOL, "hand sum {stop}");
    for t in [7.85, 8.85, 9.85] {
        let c = r.at(t, "car");
        assert!(
            (c.s - 136.5).abs() < S_TOL && c.speed.abs() < S_TOL,
            "car at {t}: {c:?}"
        );
        let gap = 149.5 - (c.s + 3.5);
        assert!((gap - 9.5).abs() < S_TOL, "gap {gap}");
        let b = r.at(t, "barrier");
        assert!((b.x - 150.0).abs() < S_TOL && b.speed.abs() < S_TOL);
    }
    assert!((r.phase("do").1 - 9.85).abs() < T_TOL);
}

#[test]
fn a_stationary_object_is_located_once_and_before_it_is_used() {
    let e = crate::support::error("actors/err_location_twice");
    assert!(
        e.contains("expected one location(…) of `b` (it cannot change, §8.7.3.1.1), found a second; the first is at ")
            && e.contains("err_location_twice.osc:8:5")
            && e.ends_with("err_location_twice.osc:9:5"),
        "{e}"
    );
    let e = crate::support::error("actors/err_unlocated");
    assert!(
        e.contains("expected a location of stationary object `b`")
            && e.contains("err_unlocated.osc:9:"),
        "{e}"
    );
}

/// Runs `actors/NAME`, whose ego's phase `do.1` ends on a sampled variable: it must end at
/// `end` s with ego at s = `s` m then.
fn sampled_phase_ends(name: &str, end: f64, s: f64) -> crate::support::Run {
    let r = crate::support::run(&format!("actors/{name}"), 0, None);
    let (s0, e) = r.phase("do.1");
    assert!(
        s0.abs() < T_TOL && (e - end).abs() < T_TOL,
        "{name}: [{s0}, {e}]"
    );
    assert!((r.at(end, "ego").s - s).abs() < S_TOL, "{name}");
    r
}

#[test]
fn a_sampled_variable_ends_a_phase_at_a_sample() {
    sampled_phase_ends("sampled_ttc", 2.0, 50.0);
}

/// §7.3.10.5 `sample(m, e)` with e `every(p, offset: o)`: samples at o + k·p (issue 27; was an
/// error "not run yet"). By hand in sampled_ttc_offset.osc: TTC(t) = 4.6 − t, sampled at 0.5 s
/// (4.1 s) and 2.5 s (2.1 s < 3 s): the phase ends at 2.5 s, ego at 60 m.
#[test]
fn a_variable_sampled_with_an_offset_ends_a_phase_at_an_offset_sample() {
    sampled_phase_ends("sampled_ttc_offset", 2.5, 60.0);
}

/// §7.3.10.5 `sample(m, @e)` of an emitted event: m read at each occurrence (issue 27; was an
/// error "not run yet"). By hand in sampled_ttc_event.osc: `look` at 1.0 s and 2.5 s, seen in
/// the steps ending 1.05 s (TTC 3.6 s) and 2.55 s (2.1 s < 3 s): the phase ends at 2.55 s, ego
/// at 61 m; the emissions are in the event log at 1.0 and 2.5 s.
#[test]
fn a_variable_sampled_at_an_emitted_event_ends_a_phase_at_its_occurrence() {
    let r = sampled_phase_ends("sampled_ttc_event", 2.55, 61.0);
    let emitted: Vec<f64> = r
        .commands
        .iter()
        .filter(|(_, _, ty, content)| ty == "emit" && content == "look")
        .map(|(t, ..)| *t)
        .collect();
    assert_eq!(emitted.len(), 2, "{emitted:?}");
    for (got, want) in emitted.iter().zip([1.0, 2.5]) {
        assert!((got - want).abs() < T_TOL, "{emitted:?}");
    }
}

#[test]
fn vehicles_take_their_category_from_vehicle_category() {
    use scenario::VehicleCategory as C;
    let lowered = crate::support::lower("actors/seed_vehicles", 0, None).expect("plans");
    let objects = &lowered.scenario.entities.scenario_objects;
    for (name, want) in [
        ("my_wide_car", C::Car),
        ("my_motorcycle", C::Motorbike),
        ("my_bicycle", C::Bicycle),
    ] {
        match &objects
            .iter()
            .find(|o| o.name == name)
            .expect(name)
            .entity_object
        {
            EntityObject::Vehicle(v) => assert_eq!(v.vehicle_category, want, "{name}"),
            other => panic!("{name} is a {other:?}"),
        }
    }
    let r = run_scenario("seed_vehicles", &lowered.scenario, 0, None);
    for name in ["my_wide_car", "my_motorcycle", "my_bicycle"] {
        let d = r.at(2.0, name).s - r.at(0.0, name).s;
        assert!((d - 20.0).abs() < S_TOL, "{name} covered {d} m");
    }
}

#[test]
fn the_seeds_examples_of_8_7_run_or_validate() {
    let seed = |f: &str| crate::support::path(&format!("../dsl/tests/files/seed/{f}.osc"));
    // Code 1 and Code 2 declare (no do): they check, and there is nothing to run.
    for f in ["vehicles", "location"] {
        dsl::check(&seed(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        let e = crate::support::lower_at(
            &format!("../dsl/tests/files/seed/{f}.osc"),
            "tests/roads/straight.xodr",
            0,
            None,
        )
        .expect_err("nothing to run");
        assert!(
            e.to_string()
                .contains("expected a scenario with a `do` to run"),
            "{e}"
        );
    }
    // Code 3 on the bundled highway, bounded as it has no end of its own: ego behind other_car
    // with no distance given, 2 s at other_car's 50 km/h (27.78 m between reference points),
    // both at 50 km/h (ego has no speed of its own), so the sampled time to collision never
    // falls below 10 s and ego's phase runs to the bound.
    let lowered = crate::support::lower_at(
        "../dsl/tests/files/seed/prevent_collision.osc",
        "../../examples/roads/highway.xodr",
        0,
        Some(5.0),
    )
    .expect("plans");
    let r = run_scenario("prevent_collision", &lowered.scenario, 0, Some(5.0));
    let (ego, other) = (r.at(0.0, "ego"), r.at(0.0, "other_car"));
    assert_eq!(ego.lane, other.lane);
    let v = 50.0 / 3.6;
    assert!(
        (other.s - ego.s - 2.0 * v).abs() < 1e-6,
        "{} m apart",
        other.s - ego.s
    );
    assert!((ego.speed - v).abs() < S_TOL && (other.speed - v).abs() < S_TOL);
    assert_eq!(r.when("do.1", "Stop"), None);
    assert!((r.last_time() - 5.0).abs() < T_TOL);
}
