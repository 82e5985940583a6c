//! FollowTrajectoryAction with a ClothoidSpline whose first segment has no PositionStart
//! (OpenSCENARIO 1.3 XSD `ClothoidSplineSegment`: positionStart is optional) starts the spline at
//! the actor's pose instead of being refused.

use crate::runtime_support;

use engine::{Engine, EngineConfig};
use runtime_support::{corpus, Recorder};

/// esmini's parking_demo.xosc: Target4 parks along such a spline (its maneuver starts at about
/// 10 s) and stands still from about 15 s. esmini 3.6.0's reference
/// (corpus/reference/esmini/parking_demo.csv) has it at rest at x = 119.864, y = 0.223,
/// h = 1.209 from 19.9 s on; the spline is evaluated by a different implementation here
/// (trajectory::ClothoidSpline over opendrive's exact spiral), so 0.5 m and 0.05 rad.
#[test]
fn clothoid_spline_without_position_start_starts_at_the_actor() {
    let path = corpus("esmini/xosc/parking_demo.xosc");
    let config = EngineConfig {
        max_time: 25.0,
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(&path, &[], config).expect("parking_demo loads");
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    engine
        .run(&mut frames, &mut events)
        .expect("parking_demo runs");
    let end = frames.at("Target4", 25.0);
    let d = (end.x - 119.864).hypot(end.y - 0.223);
    assert!(
        d < 0.5,
        "Target4 ends {d} m from esmini's rest pose: {end:?}"
    );
    assert!((end.h - 1.209).abs() < 0.05, "heading {}", end.h);
}
