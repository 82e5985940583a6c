//! The IDM's leader through a junction, along the route (issue 13: "the gap is … through lane
//! links and junctions along the route or the lane the entity will take"): idm_junction.xosc on
//! two_junction_choice.xodr, Ego (idm, s0 = 2 m) from road 1 through junction 100 with a route
//! to road 2 or road 3, a car standing on each of them (On2 on road 2 at s = 40, On3 on road 3
//! at s = 60). Cars are 5 m long, box centre 1.4 m ahead of the reference point: front bumper
//! s + 3.9, rear bumper s − 1.1.

use std::path::PathBuf;

use engine::output::{Frame, FrameSink};
use engine::{Engine, EngineConfig};

/// Issue 13's stopping tolerance (m).
const GAP_TOLERANCE: f64 = 0.3;

/// Per frame and entity: name, road, s, speed.
#[derive(Default)]
struct Track(Vec<(f64, String, String, f64, f64)>);

impl FrameSink for Track {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        for e in frame.objects() {
            let (road, s) = e
                .road_position
                .map_or((String::new(), f64::NAN), |r| (r.road_id.clone(), r.s));
            self.0
                .push((frame.time, e.name.to_owned(), road, s, e.speed));
        }
        Ok(())
    }
}

fn run(via: &str) -> Track {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/files/controller/idm_junction.xosc");
    let params = [("Via".to_owned(), via.to_owned())];
    let mut engine = Engine::load(&path, &params, EngineConfig::default()).expect("loads");
    let mut track = Track::default();
    engine.run(&mut track, &mut ()).expect("runs");
    track
}

/// With the route via road `via`, Ego ends on that road, stopped with the gap s0 = 2 m
/// (±0.3 m) behind the car standing there at `obstacle_s`: its reference point at
/// obstacle_s − 1.1 − 2 − 3.9 = obstacle_s − 7; the car on the other branch does not stop it.
/// Returns Ego's speed in its last frame on road 1.
fn stops_behind(via: &str, obstacle_s: f64) -> f64 {
    let track = run(via);
    let ego: Vec<_> = track.0.iter().filter(|r| r.1 == "Ego").collect();
    let last = ego.last().expect("frames");
    assert_eq!(last.2, via, "Ego ends on road {via}");
    assert!(last.4.abs() < 0.05, "speed {}", last.4);
    let gap = (obstacle_s - 1.1) - (last.3 + 3.9);
    assert!((gap - 2.0).abs() < GAP_TOLERANCE, "gap {gap} m");
    ego.iter()
        .rev()
        .find(|r| r.2 == "1")
        .expect("Ego starts on road 1")
        .4
}

/// Road 3 (via connecting road 12, not the first successor): Ego stops behind On3 at s = 60.
/// Road 2: behind On2 at s = 40. On road 1 the two runs differ only in the route, so the
/// leader Ego brakes for there is the one on its route: from the end of road 1 On3's rear is
/// 10 + 58.9 = 68.9 m ahead, On2's 10 + 38.9 = 48.9 m, and Ego, braking for the farther car
/// with route 3, is faster there than with route 2 (a search blind to the route would take
/// the first successor, road 2, in both runs and give the same speed).
#[test]
fn idm_finds_its_leader_along_the_route_through_the_junction() {
    let v3 = stops_behind("3", 60.0);
    let v2 = stops_behind("2", 40.0);
    assert!(
        v3 > v2 + 0.5,
        "end of road 1: {v3} m/s (route 3), {v2} m/s (route 2)"
    );
}
