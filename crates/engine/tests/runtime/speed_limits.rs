//! A LongitudinalDistanceAction within the vehicle's Performance, whatever its own
//! DynamicConstraints allow: esmini's distance_test.xosc against esmini 3.6.0's reference run.
//!
//! distance_test: Dummy (catalog car_red: Performance maxAcceleration 5, maxDeceleration 10
//! m/s²) keeps 10 m behind Ego with a LongitudinalDistanceAction whose DynamicConstraints allow
//! maxAcceleration 15 and maxDeceleration 15 m/s². Both start at 15 m/s with a 35 m free gap.
//! The reference accelerates Dummy at 5 m/s² (0.5 m/s per 0.1 s row, 15 → 25 m/s from 0 to
//! 2 s), not at 15. The standard does not say how a LongitudinalDistanceAction's
//! DynamicConstraints relate to the vehicle's Performance (only for SpeedProfileAction does it
//! give the action's constraints precedence); oscsim, like esmini (which truncates
//! DynamicConstraints at the Performance), lets the Performance, what the vehicle can do, bound
//! the motion whatever the action allows (semantics-pitfalls #9). oscsim once took 15 m/s²
//! (16.5 vs 15.5 m/s at 0.1 s).

use crate::runtime_support;

use engine::EngineConfig;
use runtime_support::{corpus, esmini_reference, run_with};

/// Dummy's speed follows the reference at every 0.1 s row (to the CSV's rounding), and over the
/// first 2 s it gains exactly 5 m/s² · t.
#[test]
fn distance_test_dummy_accelerates_at_its_performance_limit() {
    let path = corpus("esmini/xosc/distance_test.xosc");
    let (_, frames, _) = run_with(&path, &[], EngineConfig::default());
    for k in 1..=20 {
        let t = f64::from(k) * 0.1;
        let v = frames.at("Dummy", t).speed;
        assert!(
            (v - (15.0 + 5.0 * t)).abs() < 1e-9,
            "Dummy at {t} s: {v} m/s, 5 m/s² from 15 m/s gives {}",
            15.0 + 5.0 * t
        );
    }
    let mut compared = 0;
    for esmini in esmini_reference("distance_test") {
        if esmini.name != "Dummy" {
            continue;
        }
        let (time, speed) = (esmini.time, esmini.speed);
        let ours = frames.at("Dummy", time).speed;
        assert!(
            (ours - speed).abs() <= 5e-3,
            "Dummy at {time} s: {ours} m/s, esmini {speed} m/s"
        );
        compared += 1;
    }
    assert!(compared > 100, "only {compared} reference rows compared");
}
