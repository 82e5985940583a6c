//! Vehicle groups driving against s (ASAM OpenSCENARIO DSL 2.1 §8.7.18, OpenDRIVE 1.8 §11.2):
//! the formation placed front to back along the direction of travel on the plan's roads
//! driven the other way, each member lowered and driven in its lane's driving direction.
//! Every expectation is worked by hand in the scenario's comment.

use std::f64::consts::PI;

use crate::opposite::wrap;
use crate::support::{error_on, phases_are, run_on, Run};

/// Positions on straight roads: the engine integrates speed exactly; float round-off only.
const S_TOL: f64 = 1e-6;
/// Positions on road 2 of junction_trippel_twoway0 from its geometry's digits (m).
const XY_TOL: f64 = 1e-4;
/// Headings (rad).
const H_TOL: f64 = 1e-9;
/// Headings of the pursuit and its mirror (rad): the two integrate the same steering from
/// geometry turned by pi, whose round-off differs and is carried on (at most 1.3e-7 rad seen,
/// at the end; a wrong direction would be off by radians, a wrong place by metres).
const MIRROR_H_TOL: f64 = 1e-6;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;
/// Across a spiral the engine steps the curvature per step (1 cm, as in run::opposite).
const SPIRAL_TOL: f64 = 0.01;

fn member(i: usize) -> String {
    format!("g.vehicles[{i}]")
}

#[test]
fn a_column_against_s_is_placed_front_to_back_along_its_direction_of_travel() {
    let r = run_on("opposite_group_column", "junction_trippel_twoway0");
    // At 0 s: road 2 s = 50, 65, 80 m in lane 1, heading 0.3 + pi.
    let start = [
        (50.0, 177.0408, 19.3388),
        (65.0, 191.3708, 23.7716),
        (80.0, 205.7009, 28.2044),
    ];
    for (i, (s, x, y)) in start.into_iter().enumerate() {
        let m = r.at(0.0, &member(i));
        assert_eq!((m.road.as_str(), m.lane), ("2", 1), "{m:?}");
        assert!((m.s - s).abs() < S_TOL, "{m:?}");
        assert!(
            (m.x - x).abs() < XY_TOL && (m.y - y).abs() < XY_TOL,
            "{m:?}"
        );
        assert!(wrap(m.h - (0.3 + PI)).abs() < H_TOL, "{m:?}");
        assert!((m.speed - 10.0).abs() < S_TOL, "{m:?}");
    }
    let mid = r.at(1.5, &member(1));
    assert!(
        (mid.x - 177.0408).abs() < XY_TOL && (mid.y - 19.3388).abs() < XY_TOL,
        "{mid:?}"
    );
    let at3 = r.at(3.0, &member(0));
    assert!(
        (at3.x - 148.3807).abs() < XY_TOL && (at3.y - 10.4732).abs() < XY_TOL,
        "{at3:?}"
    );
    // change_speed: every member's SpeedAction, 10 -> 5 m/s over [3, 5] s.
    let at4 = r.at(4.0, &member(0));
    assert!((at4.speed - 7.5).abs() < S_TOL, "{at4:?}");
    assert!((at4.s - 11.3125).abs() < S_TOL, "{at4:?}");
    let (s, e) = r.phase("do.1.1");
    assert!(
        (s - 3.0).abs() < T_TOL && (e - 5.0).abs() < T_TOL,
        "[{s}, {e}]"
    );
    for (i, s) in [(0, 5.125), (2, 35.125)] {
        let m = r.at(5.0, &member(i));
        assert!(
            (m.s - s).abs() < S_TOL && (m.speed - 5.0).abs() < S_TOL,
            "{m:?}"
        );
    }
    // Through the junction backwards onto road 0, the spacing kept.
    for (i, s) in [(0, 64.675), (1, 79.675), (2, 94.675)] {
        let m = r.at(19.0, &member(i));
        assert_eq!((m.road.as_str(), m.lane), ("0", 1), "{m:?}");
        assert!((m.s - s).abs() < SPIRAL_TOL, "{m:?}");
        assert!((m.y - 1.5).abs() < SPIRAL_TOL, "{m:?}");
        assert!(wrap(m.h - PI).abs() < SPIRAL_TOL, "{m:?}");
    }
    let ego = r.at(19.0, "ego");
    assert!(
        (ego.x - 86.0).abs() < S_TOL && (ego.y + 1.5).abs() < S_TOL,
        "{ego:?}"
    );
}

#[test]
fn a_group_over_two_lanes_against_s_fills_them_towards_the_drivers_left() {
    let r = run_on("opposite_group_lanes", "straight");
    // (lane, x at 0 s, y).
    let expected = [(2, 900.0, 5.25), (1, 900.0, 1.75), (2, 915.0, 5.25)];
    for (i, (lane, x, y)) in expected.into_iter().enumerate() {
        let m = r.at(0.0, &member(i));
        assert_eq!(m.lane, lane, "{m:?}");
        assert!((m.x - x).abs() < S_TOL && (m.y - y).abs() < S_TOL, "{m:?}");
        assert!(wrap(m.h - PI).abs() < H_TOL, "{m:?}");
        assert!((r.at(1.0, &member(i)).x - (x - 12.0)).abs() < S_TOL);
        let end = r.at(2.0, &member(i));
        assert!(
            (end.x - (x - 24.0)).abs() < S_TOL && end.lane == lane,
            "{end:?}"
        );
    }
    assert!((r.at(2.0, "ego").x - 30.0).abs() < S_TOL);
}

#[test]
fn a_groups_space_gap_against_s_is_a_chain_along_its_direction_of_travel() {
    let r = run_on("opposite_group_space_gap", "straight");
    // u = 1000 - s along the direction of travel; boxes front 3.5 m, rear 0.5 m along it.
    let u = |t: f64, who: &str| 1000.0 - r.at(t, who).s;
    let gap = |t: f64, back: &str, front: &str| (u(t, front) - 0.5) - (u(t, back) + 3.5);
    for (who, s) in [("lead", 900.0), (&member(0), 970.0), (&member(1), 984.0)] {
        let m = r.at(0.0, who);
        assert_eq!(m.lane, 2, "{m:?}");
        assert!(
            (m.s - s).abs() < S_TOL && (m.y - 5.25).abs() < S_TOL,
            "{m:?}"
        );
        assert!(wrap(m.h - PI).abs() < H_TOL, "{m:?}");
    }
    crate::groups::group_space_gap_chain(&r, &gap);
    assert!((r.at(30.0, "lead").x - 450.0).abs() < S_TOL);
}

/// g.assign_position against s: each member put at its offset from member 0 in the direction of
/// travel, along it and to the drivers' left (opposite_group_assign_position.osc's comment).
#[test]
fn a_groups_assign_position_against_s_keeps_the_offsets_in_the_direction_of_travel() {
    let r = run_on("opposite_group_assign_position", "straight");
    // (x at 1 s, x at 1.05 s, x at 2 s, lane, y).
    let expected = [
        (888.0, 500.0, 488.6, 2, 5.25),
        (888.0, 500.0, 488.6, 1, 1.75),
        (903.0, 515.0, 503.6, 2, 5.25),
    ];
    for (i, (before, at, after, lane, y)) in expected.into_iter().enumerate() {
        assert!((r.at(1.0, &member(i)).x - before).abs() < S_TOL);
        for (t, x) in [(1.05, at), (2.0, after)] {
            driving_against_s_at(&r, (t, i), lane, (x, y));
        }
    }
    phases_are(&r, &[("do.1", 1.0, 1.0), ("do.2", 1.0, 2.0)]);
}

/// g.assign_orientation against s: each standing member turned where it is to the absolute yaw
/// 0.5 rad (opposite_group_assign_orientation.osc).
#[test]
fn a_groups_assign_orientation_against_s_turns_each_member_where_it_stands() {
    let r = run_on("opposite_group_assign_orientation", "straight");
    // Member 0 by hand: lane 2 at u = 100 m, (900, 5.25), heading pi.
    let m0 = r.at(1.0, &member(0));
    assert!(
        (m0.x - 900.0).abs() < S_TOL && (m0.y - 5.25).abs() < S_TOL,
        "{m0:?}"
    );
    for i in 0..2 {
        let before = r.at(1.0, &member(i));
        assert_eq!(before.lane, 2, "{before:?}");
        assert!((before.y - 5.25).abs() < S_TOL && wrap(before.h - PI).abs() < H_TOL);
        for t in [1.05, 2.0] {
            let m = r.at(t, &member(i));
            assert!((m.h - 0.5).abs() < H_TOL, "{m:?}");
            assert!(
                (m.x - before.x).abs() < S_TOL && (m.y - before.y).abs() < S_TOL,
                "{m:?}"
            );
        }
    }
    // Member 1 behind member 0 along the direction of travel: further along +x.
    assert!(r.at(1.0, &member(1)).x > 900.0 + 5.0);
    phases_are(&r, &[("do.1", 1.0, 1.0), ("do.2", 1.0, 2.0)]);
}

/// Member `i` at time `t` in `lane` at (x, y) on straight.xodr, heading pi.
fn driving_against_s_at(r: &Run, (t, i): (f64, usize), lane: i32, (x, y): (f64, f64)) {
    let m = r.at(t, &member(i));
    assert_eq!(m.lane, lane, "{m:?}");
    assert!((m.x - x).abs() < S_TOL && (m.y - y).abs() < S_TOL, "{m:?}");
    assert!(wrap(m.h - PI).abs() < H_TOL, "{m:?}");
}

/// g.assign_position against s after a run-time condition: the offsets the plan last knows,
/// checked by the engine in the direction of travel (opposite_group_assign_position_runtime.osc).
#[test]
fn a_groups_assign_position_against_s_after_a_run_time_condition_keeps_the_offsets() {
    let r = run_on("opposite_group_assign_position_runtime", "straight");
    for (i, (at_until, jumped, after)) in [(833.0, 700.0, 680.0), (848.0, 715.0, 695.0)]
        .into_iter()
        .enumerate()
    {
        assert!((r.at(3.35, &member(i)).x - at_until).abs() < S_TOL);
        for (t, x) in [(3.4, jumped), (4.4, after)] {
            driving_against_s_at(&r, (t, i), 1, (x, 1.75));
        }
    }
}

/// g.change_position against s: parallel lines to the target and to the target moved by each
/// member's offset in the direction of travel (opposite_group_change_position.osc's comment).
#[test]
fn a_groups_change_position_against_s_moves_each_member_along_its_own_line() {
    let r = run_on("opposite_group_change_position", "straight");
    // (x at 0 s, mid-point x at 1.25 s, x at 2.5 s, x at 3 s).
    for (i, (x0, mid, x1, x3)) in [(900.0, 894.0, 888.0, 885.5), (915.0, 909.0, 903.0, 900.5)]
        .into_iter()
        .enumerate()
    {
        let m = r.at(0.0, &member(i));
        assert!(
            (m.x - x0).abs() < S_TOL && (m.y - 5.25).abs() < S_TOL && m.lane == 2,
            "{m:?}"
        );
        let m = r.at(1.25, &member(i));
        assert!(
            (m.x - mid).abs() < S_TOL && (m.y - 3.5).abs() < S_TOL,
            "{m:?}"
        );
        for (t, x) in [(2.5, x1), (3.0, x3)] {
            driving_against_s_at(&r, (t, i), 1, (x, 1.75));
        }
    }
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 2.5).abs() < T_TOL, "[{s}, {e}]");
}

/// g.replay_path against s: a column follows the path in file, each member from its own
/// lead-in along its lane in its direction of travel (opposite_group_replay_path.osc).
#[test]
fn a_column_against_s_replays_a_path_from_each_members_lead_in() {
    let r = &run_on("opposite_group_replay_path", "straight");
    driving_against_s_at(r, (1.0, 1), 2, (905.0, 5.25));
    for (t, i) in [(0.5, 0), (2.0, 1)] {
        on_the_leg_at(r, (t, i), 895.2);
    }
    for (t, i) in [(6.25, 0), (7.75, 1)] {
        driving_against_s_at(r, (t, i), 1, (838.0, 1.75));
    }
    phases_are(r, &[("do.0", 0.0, 7.75)]);
}

/// g.follow_path against s: the engine's pursuit of each member's path is the +s one turned half
/// a turn about (500, 0), at every step (opposite_group_follow_path.osc,
/// group_follow_path_mirror.osc): (x, y, h) there is (1000 - x, -y, h + pi) here.
#[test]
fn a_column_against_s_follows_a_path_as_the_mirrored_column_in_plus_s() {
    let r = run_on("opposite_group_follow_path", "straight");
    let m = run_on("group_follow_path_mirror", "straight");
    assert_eq!(r.frames.len(), m.frames.len());
    for (t, objs) in &m.frames {
        for o in objs {
            let a = r.at(*t, &o.name);
            assert!(
                (a.x - (1000.0 - o.x)).abs() < S_TOL
                    && (a.y + o.y).abs() < S_TOL
                    && wrap(a.h - (o.h + PI)).abs() < MIRROR_H_TOL
                    && a.lane == -o.lane,
                "{t}: {a:?} {o:?}"
            );
        }
    }
    phases_are(&r, &[("do.0", 0.0, m.phase("do.0").1)]);
}

/// g.follow_trajectory and g.replay_trajectory against s: each member's stamps shifted by its
/// headway behind member 0 along the direction of travel (opposite_group_follow_trajectory.osc,
/// opposite_group_replay_trajectory.osc: the same trajectory replayed).
#[test]
fn a_column_against_s_follows_a_trajectory_with_its_stamps_shifted_by_each_headway() {
    for name in [
        "opposite_group_follow_trajectory",
        "opposite_group_replay_trajectory",
    ] {
        column_on_the_trajectory(&run_on(name, "straight"));
    }
}

/// Member `i` at time `t` at x on the paths' leg from lane 2 to lane 1 (dx -12 m, dy -3.5 m),
/// 0.4 of the way along it (y = 3.85 m), heading atan2(-3.5, -12) = atan(3.5/12) - pi.
fn on_the_leg_at(r: &Run, (t, i): (f64, usize), x: f64) {
    let m = r.at(t, &member(i));
    assert!(
        (m.x - x).abs() < S_TOL && (m.y - 3.85).abs() < S_TOL,
        "{m:?}"
    );
    assert!(
        wrap(m.h - ((3.5f64 / 12.0).atan() - PI)).abs() < H_TOL,
        "{m:?}"
    );
}

fn column_on_the_trajectory(r: &Run) {
    driving_against_s_at(r, (2.0, 2), 2, (910.0, 5.25));
    for (t, i) in [(2.5, 0), (4.0, 1), (5.5, 2)] {
        on_the_leg_at(r, (t, i), 875.2);
    }
    for (t, i) in [(6.25, 0), (7.75, 1), (9.25, 2)] {
        driving_against_s_at(r, (t, i), 1, (838.0, 1.75));
    }
    phases_are(r, &[("do.0", 0.0, 9.25)]);
}

/// g.follow_trajectory against s for a group over two lanes: member 1's trajectory is member
/// 0's moved to the drivers' left (opposite_group_block_trajectory.osc).
#[test]
fn a_group_over_two_lanes_against_s_follows_the_trajectory_moved_by_each_offset() {
    let r = run_on("opposite_group_block_trajectory", "straight");
    for (i, (lane, y)) in [(2, 5.25), (1, 1.75)].into_iter().enumerate() {
        for (t, x) in [(3.0, 870.0), (4.0, 860.0)] {
            driving_against_s_at(&r, (t, i), lane, (x, y));
        }
    }
    phases_are(&r, &[("do.0", 0.0, 4.0)]);
}

/// A group whose members drive both ways: an error at its invocation (err_opposite_group_mixed).
#[test]
fn a_group_whose_members_drive_both_ways_is_an_error_at_its_invocation() {
    let name = "err_opposite_group_mixed";
    let e = error_on(name, "straight");
    let text = "expected the members of group `g` to drive one direction (its formation is placed along one direction of travel), found `g.vehicles[1]` in +s and `g.vehicles[0]` against s";
    assert!(
        e.contains(text) && e.ends_with(&format!("{name}.osc:15:9")),
        "{e}"
    );
}

/// g.replay_path against s after a run-time condition: member 0 checked at the path's start
/// and member 1 at its offset along the direction of travel, its lead-in from there
/// (opposite_group_replay_path_runtime.osc, by hand there).
#[test]
fn a_column_against_s_replays_a_path_after_a_run_time_condition_from_its_checked_offset() {
    let r = &run_on("opposite_group_replay_path_runtime", "straight");
    let (s, e) = r.phase("do.signal.1.follow");
    assert!(
        (s - 2.55).abs() < T_TOL && (e - 7.3).abs() < T_TOL,
        "[{s}, {e}]"
    );
    for (t, i, x) in [
        (2.55, 0, 874.5),
        (2.55, 1, 889.5),
        (4.05, 1, 874.5),
        (5.55, 1, 859.5),
    ] {
        driving_against_s_at(r, (t, i), 2, (x, 5.25));
    }
    on_the_leg_at(r, (6.55, 1), 849.7);
    // The path's end, in lane 1, still heading along the leg (its last segment).
    for (t, i) in [(5.8, 0), (7.3, 1)] {
        let m = r.at(t, &member(i));
        assert!(
            m.lane == 1 && (m.x - 842.5).abs() < S_TOL && (m.y - 1.75).abs() < S_TOL,
            "{m:?}"
        );
        assert!(
            wrap(m.h - ((3.5f64 / 12.0).atan() - PI)).abs() < H_TOL,
            "{m:?}"
        );
    }
}

/// g.follow_trajectory against s after a run-time condition for a group over two lanes:
/// member 1's points relative to itself in the road frame, member 0's path moved 3.5 m to the
/// drivers' left (opposite_group_block_trajectory_runtime.osc, by hand there).
#[test]
fn a_group_over_two_lanes_against_s_follows_a_trajectory_after_a_run_time_condition() {
    let r = run_on("opposite_group_block_trajectory_runtime", "straight");
    let (s, e) = r.phase("do.signal.1.follow");
    assert!(
        (s - 2.55).abs() < T_TOL && (e - 6.55).abs() < T_TOL,
        "[{s}, {e}]"
    );
    for (i, (lane, y)) in [(2, 5.25), (1, 1.75)].into_iter().enumerate() {
        for (t, x) in [(2.55, 874.5), (5.55, 844.5), (6.55, 834.5)] {
            driving_against_s_at(&r, (t, i), lane, (x, y));
        }
    }
}

/// Against s after a run-time condition the engine checks member 0 at the path's start in the
/// view's u: 5.5 m past it, the run fails (opposite_group_path_runtime_off.osc).
#[test]
fn a_column_against_s_off_the_paths_start_after_a_run_time_condition_fails_the_run() {
    // u = 1000 - 880 m asked, 100 + 25.5 m found (the comment).
    let want = "expected 'g.vehicles[0]' at u = 120.000 m along the direction of travel (against s) (within 0.5 m) (the start of group `g`'s path in replay_path(…) at ";
    let tail = "opposite_group_path_runtime_off.osc:38:41), found it at u = 125.500 m along the direction of travel (against s) at t = 2.550 s";
    crate::support::fails_once(
        "tests/scenarios/opposite_group_path_runtime_off.osc",
        "tests/roads/straight.xodr",
        (want, tail),
        (2.55, "do.signal.1.1/g.vehicles[0]/1:check"),
    );
}
