//! The 33-vertex Polyline of esmini's lane-change_trajectory_wp.xosc (OpenSCENARIO 1.3 §6.9,
//! XSD `Polyline`, `Vertex` with WorldPositions; FollowTrajectoryAction in Init without a time
//! reference, 0–8 s) against the path esmini 3.6.0's car took
//! (shared/corpus/reference/esmini/lane-change_trajectory_wp.csv, 0.1 s rows, 3 decimals):
//! every sampled position lies on the polyline, and the distance along it grows with the
//! car's speed.

use crate::runtime_support;
use crate::trajectory_support;

use engine::trajectory::build;
use runtime_support::esmini_reference;
use scenario::RoutingAction;
use trajectory_support::{corpus_scenario, init_routing_actions, straight};

#[test]
fn esmini_drives_on_the_polyline() {
    let sc = corpus_scenario("esmini/xosc/lane-change_trajectory_wp.xosc");
    let (trajectory, pos) = init_routing_actions(&sc)
        .find_map(|(r, pos)| match r {
            RoutingAction::FollowTrajectory { trajectory, .. } => {
                Some((trajectory.clone(), pos.clone()))
            }
            _ => None,
        })
        .expect("a FollowTrajectoryAction in Init");
    let t = build(&trajectory, &straight(), &pos).unwrap();
    // First vertex (50.00, −1.53), last (160.94, 1.53).
    let (a, b) = (t.eval(0.0), t.eval(t.length()));
    assert!((a.x - 50.0).abs() < 1e-12 && (b.x - 160.94).abs() < 1e-12);
    let mut worst: f64 = 0.0;
    let mut rows = 0;
    let mut last_s = -1.0;
    for row in esmini_reference("lane-change_trajectory_wp") {
        let time = row.time;
        if time > 7.95 {
            break;
        }
        let c = t.closest(row.x, row.y);
        worst = worst.max(c.distance);
        assert!(c.point.s >= last_s, "backwards at {time} s");
        last_s = c.point.s;
        rows += 1;
    }
    assert_eq!(rows, 80);
    // The rows are rounded to 0.5 mm; the car stays within 1 mm of the straight segments
    // between the vertices (found: 0.47 mm at most).
    assert!(
        worst < 1e-3,
        "largest distance from the polyline: {worst} m"
    );
}
