//! The order in which the running actions of one step act (actions/mod.rs,
//! controller/default.rs): storyboard (document) order. The standard leaves it open; esmini
//! 3.6.0 uses document order, which its lane_change_simple reference shows.

use crate::runtime_support;

use engine::EngineConfig;
use runtime_support::{corpus, esmini_reference, run_with};

/// lane_change_simple.xosc, first lap: Ego accelerates under the End Of Road speed action
/// (started 35.65 s) while the Lane change action (started 40.75 s, sinusoidal, 4 s) moves it
/// to lane 1. The Lane change maneuver is written before the speed maneuver, so in each step
/// the lateral motion runs at the speed of the step's start: esmini's s advances 1.928 m over
/// 40.8 .. 40.9 s where the step-end speeds would give 1.949 m (start order would have put the
/// speed action first: 0.30 m too far by 43 s). Every reference row up to 60 s agrees within
/// 2 mm (the reference prints millimetres).
#[test]
fn running_actions_act_in_document_order() {
    let config = EngineConfig {
        duration: Some(60.0),
        ..EngineConfig::default()
    };
    let (_, frames, _) = run_with(&corpus("esmini/xosc/lane_change_simple.xosc"), &[], config);
    let mut rows = 0;
    for row in esmini_reference("lane_change_simple") {
        let (t, x, y) = (row.time, row.x, row.y);
        if !(35.0..=60.0).contains(&t) {
            continue;
        }
        let r = frames.at("Ego", t);
        assert!(
            (r.x - x).abs() < 2e-3 && (r.y - y).abs() < 2e-3,
            "{t}: ({}, {}) vs esmini ({x}, {y})",
            r.x,
            r.y
        );
        rows += 1;
    }
    assert_eq!(rows, 251, "rows 35.0 ..= 60.0 s at 0.1 s");
}
