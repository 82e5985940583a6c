//! `change_lane()` without a side (§8.9: randomized): drawn from the seed among the sides that
//! have a lane; a lane change to no lane is an error. Expectations in the scenario files.

use crate::support::run;

const Y_TOL: f64 = 1e-6;

#[test]
fn change_lane_side_is_drawn_from_the_seed() {
    let mut ends = Vec::new();
    for seed in 0..8 {
        let a = run("change_lane_random", seed, None);
        let b = run("change_lane_random", seed, None);
        let (ea, eb) = (a.at(4.0, "ego"), b.at(4.0, "ego"));
        assert_eq!(ea, eb, "seed {seed}: the same run twice");
        let y = ea.y;
        assert!(
            (ea.lane == -1 && (y + 1.75).abs() < Y_TOL)
                || (ea.lane == -3 && (y + 8.75).abs() < Y_TOL),
            "{ea:?}"
        );
        ends.push(ea.lane);
    }
    assert!(
        ends.contains(&-1) && ends.contains(&-3),
        "both sides over 8 seeds: {ends:?}"
    );
    for seed in 0..4 {
        let e = run("change_lane_one_side", seed, None);
        let ego = e.at(4.0, "ego");
        assert!(ego.lane == -2 && (ego.y + 5.25).abs() < Y_TOL, "{ego:?}");
    }
    crate::along::refused(
        "err_change_lane_no_lane",
        "expected a driving lane 1 to the left of `ego`'s lane -1 at s = ",
        "8:9",
    );
}

#[test]
fn lane_number_at_the_end_is_an_absolute_target() {
    let r = run("lane_number_end", 0, None);
    let ego = r.at(4.0, "ego");
    assert!(ego.lane == -1 && (ego.y + 1.75).abs() < Y_TOL, "{ego:?}");
    assert!((r.at(2.0, "ego").y + 5.25).abs() < Y_TOL);
    let npc = r.at(4.0, "npc");
    assert!(npc.lane == -2 && (npc.y + 5.25).abs() < Y_TOL, "{npc:?}");
    crate::along::refused(
        "err_lane_number_end",
        "expected a driving lane numbered 4 from the right on road 1 at s = ",
        "7:9",
    );
    crate::along::refused(
        "err_lane_left_of_end",
        "expected a driving lane 1 to the left of `ego`'s lane -1 at the phase end",
        "13:13",
    );
}

#[test]
fn lane_at_a_later_phase_start_is_checked() {
    let r = run("lane_start_kept", 0, None);
    for t in [3.0, 5.0, 7.0] {
        let ego = r.at(t, "ego");
        assert!(
            ego.lane == -2 && (ego.y + 5.25).abs() < Y_TOL,
            "{ego:?} at {t}"
        );
    }
    crate::along::refused(
        "err_lane_start",
        "expected `ego` in lane -2 at the phase start, found it in lane -3",
        "10:13",
    );
}
