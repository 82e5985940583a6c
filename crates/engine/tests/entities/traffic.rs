//! Spawned traffic (OpenSCENARIO 1.3 §7.2.2.3 "Spawned objects"): TrafficSourceAction,
//! TrafficSinkAction and TrafficSwarmAction, ByType selections over spawned vehicles, and
//! seeded, reproducible streams.

use crate::runtime_support;

use std::path::{Path, PathBuf};

use engine::output::EventRecord;
use engine::{Engine, EngineConfig};
use runtime_support::{corpus, Recorder, Row};

fn file(name: &str) -> PathBuf {
    crate::corpus::fixture("entities").join(name)
}

fn run(path: &Path, config: EngineConfig) -> (Recorder, Vec<EventRecord>) {
    let mut engine = Engine::load(path, &[], config)
        .unwrap_or_else(|e| panic!("{} does not load: {e}", path.display()));
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    engine.run(&mut frames, &mut events).expect("runs");
    (frames, events)
}

fn rows<'r>(frames: &'r Recorder, name: &'r str) -> impl Iterator<Item = &'r Row> + 'r {
    frames.0.iter().filter(move |r| r.name == name)
}

/// The source owes 1 vehicle/s: after 20 steps of 0.05 s the first one appears, in the frame
/// of t = 1.00 s (not in 0.95 s), named `src.entity_1` (§7.2.2.3's naming scheme), on lane −1
/// within 1 m of x = 100, at 20 m/s. The event "seen" waits for any member of the ByType
/// vehicle selection to be faster than 5 m/s (the parked Ego never is): it starts at the
/// next step's triggers, t = 1.00 s.
#[test]
fn by_type_counts_a_spawned_vehicle_the_step_after_it_appears() {
    let (frames, events) = run(&file("traffic_source_sink.xosc"), EngineConfig::default());
    assert!(rows(&frames, "src.entity_1").all(|r| r.time > 0.975));
    let first = frames.at("src.entity_1", 1.0);
    assert!(
        (first.x - 100.0).abs() <= 1.0 && (first.y + 1.535).abs() < 1e-9,
        "{first:?}"
    );
    assert!((first.speed - 20.0).abs() < 1e-12);
    assert_eq!(first.road.as_ref().map(|r| r.1), Some(-1));
    let seen = events.iter().find_map(|e| match e {
        EventRecord::Transition(t) if t.name == "seen" => Some(t.time),
        _ => None,
    });
    assert!(seen.is_some_and(|t| (t - 1.0).abs() < 1e-9), "{seen:?}");
}

/// The sink removes every vehicle whose reference point comes within 5 m of (300, −1.535).
/// Driving 1 m per step along y = −1.535, a vehicle's last frame has x in [294, 295] (the
/// next step would take it past 295), and it is in no later frame. One vehicle is due each
/// second, 20 m apart (more than the 10 m spawn gap), so vehicles 1–20 appear by t = 20 s;
/// those spawned by t = 10 s (x ≈ 100 + 20 (20 − n) ≥ 295) have all been removed.
#[test]
fn sink_removes_vehicles_that_reach_it() {
    let (frames, events) = run(&file("traffic_source_sink.xosc"), EngineConfig::default());
    let end = frames.0.last().map_or(0.0, |r| r.time);
    let logged = |entity: &str, what: &str| {
        events.iter().find_map(|e| match e {
            EventRecord::Entity {
                time,
                element,
                entity: n,
                change,
            } if n == entity && change == what => Some((*time, element.clone())),
            _ => None,
        })
    };
    let mut removed = 0;
    for n in 1..=20 {
        let name = format!("src.entity_{n}");
        let (t, by) = logged(&name, "spawned").expect("spawn logged");
        assert!(
            (t - n as f64).abs() < 1e-9 && by == "src",
            "{name}: {t} {by}"
        );
        let last = rows(&frames, &name)
            .last()
            .unwrap_or_else(|| panic!("{name} never appeared"));
        assert!(
            rows(&frames, &name).all(|r| r.x < 295.0),
            "{name} passed the sink"
        );
        if last.time < end - 1e-9 {
            assert!((294.0..295.0).contains(&last.x), "{name} left at {last:?}");
            // The log names the sink and the first frame without the vehicle.
            let (t, by) = logged(&name, "removed").expect("removal logged");
            assert!(
                (t - last.time - 0.05).abs() < 1e-9 && by == "sink",
                "{t} {by}"
            );
            removed += 1;
        }
    }
    assert!(removed >= 10, "{removed} removed");
    assert!(rows(&frames, "src.entity_21").next().is_none());
    // Ego, parked beyond the sink, is untouched.
    assert!((frames.at("Ego", end).x - 450.0).abs() < 1e-9);
}

/// The swarm action runs around esmini's swarm.xosc: 75 vehicles at most, between the
/// 200 m circle and the ellipse (semi-axes 300 m along Ego's heading, 500 m across) around
/// Ego. Every frame: at most 75 swarm vehicles, each inside the ellipse and on a drivable
/// lane of e6mini.xodr within 0.5 m of its centre; each appears at 200 m or more from Ego.
/// The count is not compared with esmini's (its random stream differs) but is in the same
/// range: some vehicles after 5 s, at most 75 ever.
#[test]
fn swarm_keeps_its_vehicles_within_bounds_and_on_lanes() {
    let config = EngineConfig {
        duration: Some(30.0),
        ..EngineConfig::default()
    };
    let (frames, _) = run(&corpus("esmini/xosc/swarm.xosc"), config);
    let net = opendrive::RoadNetwork::from_file(&corpus("esmini/xodr/e6mini.xodr"))
        .expect("e6mini loads");
    let mut seen = std::collections::HashSet::new();
    let mut times: Vec<f64> = frames.0.iter().map(|r| r.time).collect();
    times.dedup();
    let mut most = 0;
    for t in &times {
        let ego = frames.at("Ego", *t);
        let (c, s) = (ego.h.cos(), ego.h.sin());
        let swarm: Vec<&Row> = frames
            .0
            .iter()
            .filter(|r| {
                (r.time - t).abs() < 1e-9 && r.name.starts_with("Init TrafficAction.entity_")
            })
            .collect();
        most = most.max(swarm.len());
        for r in swarm {
            let (dx, dy) = (r.x - ego.x, r.y - ego.y);
            let (u, v) = (dx * c + dy * s, -dx * s + dy * c);
            assert!(
                (u / 300.0).powi(2) + (v / 500.0).powi(2) <= 1.0 + 1e-9,
                "{r:?}"
            );
            if seen.insert(r.name.clone()) {
                assert!(
                    dx.hypot(dy) >= 200.0 - 1e-9,
                    "{r:?} appeared inside the inner radius"
                );
            }
            let (road, lane, s_, _, offset) = r.road.clone().expect("on a road");
            let lane_type = net
                .road(&road)
                .and_then(|rd| {
                    rd.lane_section_at(s_)
                        .lane(lane)
                        .map(|l| l.lane_type.clone())
                })
                .expect("lane exists");
            assert!(lane_type.is_drivable() && offset.abs() < 0.5, "{r:?}");
        }
    }
    assert!(
        (5..=75).contains(&most),
        "at most {most} swarm vehicles at once"
    );
    assert!(frames
        .0
        .iter()
        .any(|r| r.time <= 5.0 && r.name.ends_with(".entity_1")));
}

/// Swarm vehicles' (time, name, x, y) of a 10 s run with `seed`.
fn swarm_traffic(seed: u64) -> Vec<(String, f64, f64, f64)> {
    let config = EngineConfig {
        duration: Some(10.0),
        seed,
        ..EngineConfig::default()
    };
    let (frames, _) = run(&corpus("esmini/xosc/swarm.xosc"), config);
    frames
        .0
        .into_iter()
        .filter(|r| r.name.contains(".entity_"))
        .map(|r| (r.name, r.time, r.x, r.y))
        .collect()
}

/// The same seed gives the same spawned traffic, bit for bit; another seed another traffic.
#[test]
fn same_seed_same_traffic_other_seed_other_traffic() {
    let a = swarm_traffic(1);
    assert!(a.len() > 50, "{} swarm rows", a.len());
    assert_eq!(a, swarm_traffic(1));
    assert_ne!(a, swarm_traffic(2));
}

/// TrafficStopAction names `src` and starts at the first step with t > 3 s (3.05 s): the
/// source has spawned its vehicles of 1, 2 and 3 s and no more; those drive on (entity_3 at
/// about 100 + 20 · (8.05 − 3) = 201 m in the last frame).
#[test]
fn traffic_stop_action_ends_the_named_source() {
    let (frames, _) = run(&file("traffic_stop.xosc"), EngineConfig::default());
    let end = frames.0.last().map_or(0.0, |r| r.time);
    for n in 1..=3 {
        assert!(rows(&frames, &format!("src.entity_{n}")).next().is_some());
    }
    assert!(rows(&frames, "src.entity_4").next().is_none());
    let last = frames.at("src.entity_3", end);
    assert!(
        (last.x - 201.0).abs() <= 1.0 && (last.speed - 20.0).abs() < 1e-12,
        "{last:?}"
    );
}

/// A one-off TrafficAreaAction (1.3) on the road range s = 100 … 300 of lane −1: five vehicles
/// from its distribution (a van, 5.5 m long), one per step, so in the frames of 0.05 … 0.25 s,
/// each appearing inside the range, and never a sixth.
#[test]
fn traffic_area_action_fills_its_road_range_once() {
    let path = file("traffic_area.xosc");
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    let mut frames = Recorder::default();
    engine.run(&mut frames, &mut Vec::new()).expect("runs");
    for n in 1..=5 {
        let name = format!("area.entity_{n}");
        let first = rows(&frames, &name).next().expect("spawned");
        assert!((first.time - 0.05 * n as f64).abs() < 1e-9, "{first:?}");
        assert!((100.0..=300.0).contains(&first.x), "{first:?}");
        assert_eq!(first.road.as_ref().map(|r| r.1), Some(-1));
        let spawned = engine.entity(&name).expect("in the scene");
        assert!((spawned.bounding_box.length() - 5.5).abs() < 1e-12);
    }
    assert!(rows(&frames, "area.entity_6").next().is_none());
}

/// DirectionOfTravelDistribution (1.2): on the straight road, lane −1 runs Ego's way (+x) and
/// lane 1 the opposite way. With same = 1, opposite = 0 every swarm vehicle is on lane −1
/// heading 0; with same = 0, opposite = 1 every one is on lane 1 heading π. Speeds are drawn
/// from InitialSpeedRange [8, 12] m/s.
#[test]
fn swarm_direction_of_travel_picks_the_lanes() {
    let path = file("swarm_direction.xosc");
    for (same, lane, heading) in [("1", -1, 0.0), ("0", 1, std::f64::consts::PI)] {
        let params = [
            ("Same".to_owned(), same.to_owned()),
            (
                "Opposite".to_owned(),
                if same == "1" { "0" } else { "1" }.to_owned(),
            ),
        ];
        let mut engine = Engine::load(&path, &params, EngineConfig::default()).expect("loads");
        let mut frames = Recorder::default();
        engine.run(&mut frames, &mut Vec::new()).expect("runs");
        let swarm: Vec<&Row> = frames
            .0
            .iter()
            .filter(|r| r.name.starts_with("swarm.entity_"))
            .collect();
        assert!(swarm.len() > 100, "{} rows", swarm.len());
        for r in swarm {
            assert_eq!(r.road.as_ref().map(|p| p.1), Some(lane), "{r:?}");
            let dh = (r.h - heading).rem_euclid(std::f64::consts::TAU);
            assert!(dh.min(std::f64::consts::TAU - dh) < 1e-9, "{r:?}");
            assert!((8.0..=12.0).contains(&r.speed), "{r:?}");
        }
    }
}

/// A continuous TrafficAreaAction keeps 2 vehicles in s = 100 … 150 of lane −1. Driving at
/// 50/3.6 m/s they leave within 50 / 13.9 = 3.6 s and are removed in the step they cross
/// s = 150, so no frame shows one beyond it and never more than 2 at once; replacements keep
/// coming, so over 12 s more than 2 vehicles have been spawned.
#[test]
fn continuous_traffic_area_replaces_vehicles_that_leave() {
    let (frames, _) = run(
        &file("traffic_area_continuous.xosc"),
        EngineConfig::default(),
    );
    let area: Vec<&Row> = frames
        .0
        .iter()
        .filter(|r| r.name.starts_with("area.entity_"))
        .collect();
    let mut times: Vec<f64> = area.iter().map(|r| r.time).collect();
    times.dedup();
    for t in times {
        let now = area.iter().filter(|r| (r.time - t).abs() < 1e-9).count();
        assert!(now <= 2, "{now} area vehicles at {t}");
    }
    assert!(
        area.iter().all(|r| (100.0..=150.0).contains(&r.x)),
        "a vehicle beyond the range"
    );
    let spawned: std::collections::HashSet<&str> = area.iter().map(|r| r.name.as_str()).collect();
    assert!(spawned.len() >= 6, "{} spawned", spawned.len());
}

/// A condition on spawned objects (§7.2.2.3): their names are not declared, so a condition
/// reaches them through a ByType selection, whose members are taken at each evaluation, by id
/// (engine condition/refs.rs); the Walker it measures to is resolved when the engine is built.
/// Before the first vehicle appears the selection is empty: `any` is false and nothing is an
/// error. `src.entity_1` appears in the frame of 1.00 s at x0 (within 1 m of 100) on lane −1
/// (y = −1.535) and moves 20 m/s · 0.05 s = 1 m per step; the Walker stands at (150, 1.535).
/// Reference points 20 m apart: √(dx² + 3.07²) = 20 at dx = √(400 − 9.4249) = 19.76297 m,
/// so the distance is below 20 m from the first frame with x > 150 − 19.76297 = 130.23703 m:
/// k = ⌊130.23703 − x0⌋ + 1 steps after 1.00 s, which the triggers of that frame's step see
/// (the event starts at t1 = 1 + 0.05·k, between 2.50 and 2.60 s for x0 in [99, 101]).
#[test]
fn a_condition_on_spawned_vehicles_reads_them_by_id() {
    let (frames, events) = run(&file("condition_spawned.xosc"), EngineConfig::default());
    let first = frames.at("src.entity_1", 1.0);
    assert!(
        (first.x - 100.0).abs() <= 1.0 && (first.y + 1.535).abs() < 1e-9,
        "{first:?}"
    );
    let dx_max = (400.0_f64 - 3.07 * 3.07).sqrt();
    assert!((dx_max - 19.76297).abs() < 1e-5, "{dx_max}");
    let k = (150.0 - dx_max - first.x).floor() + 1.0;
    let t1 = 1.0 + 0.05 * k;
    assert!((2.5 - 1e-9..=2.6 + 1e-9).contains(&t1), "{t1}");
    // The frame there is the first within 20 m, by the hand distance.
    let d = |r: &Row| ((150.0 - r.x).powi(2) + (1.535 - r.y).powi(2)).sqrt();
    assert!(d(frames.at("src.entity_1", t1)) < 20.0);
    assert!(d(frames.at("src.entity_1", t1 - 0.05)) >= 20.0);
    let near = events.iter().find_map(|e| match e {
        EventRecord::Transition(t) if t.name == "near" => Some(t.time),
        _ => None,
    });
    assert!(near.is_some_and(|t| (t - t1).abs() < 1e-9), "{near:?} {t1}");
    let errors: Vec<_> = events
        .iter()
        .filter(|e| matches!(e, EventRecord::Error { .. }))
        .collect();
    assert!(errors.is_empty(), "{errors:?}");
}
