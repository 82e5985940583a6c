//! The default controller (OpenSCENARIO 1.3 §7.5.1): follows its lane through a junction and
//! into the next lane section by the lanes' links.

use crate::runtime_support;

use approx::assert_abs_diff_eq;
use engine::EngineConfig;
use opendrive::{normalize_angle, RoadNetwork};
use runtime_support::{file, run, run_with};

/// junction_follow.xosc: road 0 lane −1 from s = 90 at 10 m/s for 6 s (60 m of travel).
/// Road 0 ends at s = 100 in junction 1, whose first connection from road 0 lane −1 is
/// connecting road 1 (a 30 m spiral, lane −1 → −1) ending at the start of road 2. So the
/// entity passes road 1 and ends on road 2, lane −1, travelling towards +s, at
/// s = 60 − 10 − (its travel on road 1), about 20 m (the travel along lane −1 of the spiral
/// differs from the reference line's 30 m by the factor 1 − κ·t). Its pose there is the road
/// model's lane pose.
#[test]
fn default_controller_follows_lane_through_junction() {
    let (_, frames, _) = run("junction_follow.xosc");
    let net = RoadNetwork::from_file(&file("junction_trippel_twoway0.xodr")).expect("road loads");
    let on_connecting = frames
        .0
        .iter()
        .any(|r| r.road.as_ref().is_some_and(|p| p.0 == "1" && p.1 == -1));
    assert!(on_connecting, "the entity drives through connecting road 1");
    let row = frames.at("Ego", 6.0);
    let (road, lane, s, _, offset) = row.road.clone().unwrap_or_default();
    assert_eq!((road.as_str(), lane), ("2", -1));
    assert!(s > 15.0 && s < 25.0, "s on road 2 = {s}");
    let pose = net.lane_pose("2", -1, s, offset).expect("lane exists");
    assert_abs_diff_eq!(row.x, pose.x, epsilon = 1e-9);
    assert_abs_diff_eq!(row.y, pose.y, epsilon = 1e-9);
    assert_abs_diff_eq!(normalize_angle(row.h - pose.h), 0.0, epsilon = 1e-9);
    // The speed is kept: 10 m/s throughout.
    assert!(frames.0.iter().all(|r| (r.speed - 10.0).abs() < 1e-12));
}

/// velocity_init.xosc: Init places Ego off the road (50 m left of straight_500m.xodr, so it
/// moves along its heading) at heading h = 0.3 rad and sets 10 m/s with a step SpeedAction. The frame at t = 0 carries the velocity along the heading (world axes):
/// vx = 10·cos 0.3 = 9.553364891, vy = 10·sin 0.3 = 2.955202067, vz = 0; and the frame after
/// the first step the same (straight travel, no speed change).
#[test]
fn first_frame_velocity_follows_speed_and_heading() {
    let (_, frames, _) = run("velocity_init.xosc");
    let first = frames.at("Ego", 0.0);
    assert_abs_diff_eq!(first.speed, 10.0, epsilon = 1e-12);
    assert_abs_diff_eq!(first.h, 0.3, epsilon = 1e-12);
    assert_abs_diff_eq!(first.velocity.0, 9.553364891, epsilon = 1e-9);
    assert_abs_diff_eq!(first.velocity.1, 2.955202067, epsilon = 1e-9);
    assert_abs_diff_eq!(first.velocity.2, 0.0, epsilon = 1e-12);
    let next = frames.at("Ego", 0.05);
    assert_abs_diff_eq!(next.velocity.0, first.velocity.0, epsilon = 1e-9);
    assert_abs_diff_eq!(next.velocity.1, first.velocity.1, epsilon = 1e-9);
}

/// turned_follow.xosc: Ego on lane −1 of straight_500m.xodr (reference line along +x from the
/// origin, so s = x) at (20, −1.5), turned h = 1.2 rad from the road, at 10 m/s. The default
/// controller keeps the lane (§7.5.1) whatever the heading: after 1 s it is at x = 20 + 10·1 = 30,
/// still at y = t = −1.5 (the lane offset kept) and h = 1.2; the velocity is that of the travel,
/// (10, 0) in world axes, not along the heading (10·cos 1.2, 10·sin 1.2) = (3.62, 9.32).
#[test]
fn turned_entity_follows_its_lane() {
    let (_, frames, _) = run("turned_follow.xosc");
    for (t, x) in [(0.0, 20.0), (0.5, 25.0), (1.0, 30.0)] {
        let row = frames.at("Ego", t);
        assert_abs_diff_eq!(row.x, x, epsilon = 1e-9);
        assert_abs_diff_eq!(row.y, -1.5, epsilon = 1e-9);
        assert_abs_diff_eq!(row.h, 1.2, epsilon = 1e-9);
        assert_abs_diff_eq!(row.velocity.0, 10.0, epsilon = 1e-9);
        assert_abs_diff_eq!(row.velocity.1, 0.0, epsilon = 1e-9);
    }
}

/// routing/section_link.xosc: Ego on lane −2 of section_link.xodr (reference line along +x from
/// the origin, so s = x, y = t) at s = 10, 10 m/s, no route. Lane −1 is 3.5 m wide to s = 20,
/// then narrows to nothing at s = 50, where lane −2 continues as lane −1 of the next lane
/// section by its link (OpenDRIVE 1.8 §11.4). At s = 30 (2 s) lane −1 is
/// 3.5 − 3.5·10/30 = 2.3333 m wide, so lane −2's centre is at t = −(2.3333 + 1.75) = −4.0833,
/// and the heading follows the centre's slope, atan(3.5/30) = 0.116143 rad. From s = 50 on Ego
/// is in lane −1, centre t = −1.75, heading 0: at 7 s, (80, −1.75).
#[test]
fn lane_link_carries_the_entity_into_the_next_lane_section() {
    let path = runtime_support::file("../routing/section_link.xosc");
    let (_, frames, _) = run_with(&path, &[], EngineConfig::default());
    let at = |t: f64| frames.at("Ego", t);
    assert_abs_diff_eq!(at(2.0).x, 30.0, epsilon = 1e-9);
    assert_abs_diff_eq!(at(2.0).y, -(3.5 - 3.5 * 10.0 / 30.0 + 1.75), epsilon = 1e-9);
    assert_abs_diff_eq!(at(2.0).h, (3.5f64 / 30.0).atan(), epsilon = 1e-6);
    for t in [4.0, 7.0, 8.0] {
        let row = at(t);
        assert_abs_diff_eq!(row.x, 10.0 + 10.0 * t, epsilon = 1e-9);
        assert_abs_diff_eq!(row.y, -1.75, epsilon = 1e-9);
        assert_abs_diff_eq!(row.h, 0.0, epsilon = 1e-9);
        assert_eq!(row.road.as_ref().map(|p| p.1), Some(-1), "lane at {t} s");
    }
}
