//! Properties over random input (OpenSCENARIO 1.3 §6.9): building any NURBS or polyline
//! either fails with an error or gives a trajectory whose points are finite everywhere, whose
//! s(t) never runs backwards, and whose closest point is no farther than any sampled point.

use crate::trajectory_support;

use engine::trajectory::build;
use proptest::prelude::*;
use trajectory_support::{here, nurbs, polyline, straight, trajectory, Roads};

fn world() -> &'static Roads {
    static ROADS: std::sync::OnceLock<Roads> = std::sync::OnceLock::new();
    ROADS.get_or_init(straight)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn any_nurbs_builds_or_errs_and_stays_finite(
        order in 0u32..6,
        points in prop::collection::vec((-100.0..100.0f64, -100.0..100.0f64, 0.1..3.0f64), 0..8),
        knots in prop::collection::vec(-2.0..12.0f64, 0..16),
        sorted in any::<bool>(),
    ) {
        let mut knots = knots;
        if sorted {
            knots.sort_by(f64::total_cmp);
        }
        let pts: Vec<_> = points
            .iter()
            .enumerate()
            .map(|(i, &(x, y, w))| (x, y, Some(w), Some(i as f64)))
            .collect();
        let shape = nurbs(order, &pts, &knots);
        if let Ok(t) = build(&trajectory(shape, false), world(), &here()) {
            let n = 50;
            let mut last_s = 0.0;
            for i in 0..=n {
                let s = t.length() * i as f64 / n as f64;
                let p = t.eval(s);
                prop_assert!(p.x.is_finite() && p.y.is_finite() && p.heading.is_finite());
                let time = t.time_at(s).unwrap();
                prop_assert!(time.is_finite());
                let s_back = t.s_at_time(time).unwrap();
                prop_assert!(s_back >= last_s - 1e-9);
                last_s = s_back;
            }
        }
    }

    #[test]
    fn closest_point_is_no_farther_than_any_vertex(
        points in prop::collection::vec((-50.0..50.0f64, -50.0..50.0f64), 2..8),
        qx in -60.0..60.0f64,
        qy in -60.0..60.0f64,
    ) {
        let pts: Vec<_> = points.iter().map(|&(x, y)| (x, y, None)).collect();
        if let Ok(t) = build(&trajectory(polyline(&pts), false), world(), &here()) {
            let c = t.closest(qx, qy);
            for &(x, y) in &points {
                prop_assert!(c.distance <= (x - qx).hypot(y - qy) + 1e-9);
            }
            // The reported point is where the reported distance says.
            prop_assert!(((c.point.x - qx).hypot(c.point.y - qy) - c.distance).abs() < 1e-9);
        }
    }
}
