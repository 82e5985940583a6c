//! `lateral(…)`: offsets in the lane at the start of the run, at a phase end (a lane offset
//! over the phase) and with a lane change; expectations worked by hand in the scenario files.

use crate::support::run;

/// Lateral positions on the straight road: the sinusoidal shape is exact at its ends and half
/// way; allow float round-off.
const Y_TOL: f64 = 1e-6;

#[test]
fn lateral_offsets_at_start_and_end() {
    let r = run("lateral_lane", 0, None);
    let y = |t: f64| r.at(t, "ego").y;
    assert_eq!(r.at(0.0, "ego").lane, -3);
    assert!((y(0.0) + 9.0).abs() < Y_TOL, "{}", y(0.0));
    assert!((y(2.0) + 9.0).abs() < Y_TOL, "{}", y(2.0));
    assert!((y(4.0) + 8.625).abs() < Y_TOL, "{}", y(4.0));
    assert!((y(6.0) + 8.25).abs() < Y_TOL, "{}", y(6.0));
    assert_eq!(r.at(6.0, "ego").lane, -3);
}

/// measure_by: closest without a reference (lateral_closest.osc's comment, by hand).
#[test]
fn lateral_closest_to_a_lane_border_without_a_reference() {
    let r = run("lateral_closest", 0, None);
    let y = |t: f64| r.at(t, "ego").y;
    for (t, want) in [
        (0.0, -9.25),
        (2.0, -9.25),
        (4.0, -9.0),
        (6.0, -8.75),
        (7.0, -8.625),
        (8.0, -8.5),
    ] {
        assert!((y(t) - want).abs() < Y_TOL, "y({t}) = {} vs {want}", y(t));
    }
    assert_eq!(r.at(8.0, "ego").lane, -3);
    crate::along::refused(
        "err_lateral_closest_side",
        "expected side: left or right in lateral(0.5 m, measure_by: closest) without a reference object (which border of the lane the actor is closest to), found none",
        "11:9",
    );
    crate::along::refused(
        "err_lateral_closest_far",
        "expected a closest distance of at most 0.75 m to a border of the 3.50 m lane for an actor 2.00 m wide (centred), found 1 m",
        "11:9",
    );
}

#[test]
fn lateral_at_end_with_a_lane_change() {
    let r = run("lateral_lane_change", 0, None);
    let ego = r.at(4.0, "ego");
    assert_eq!(ego.lane, -2);
    assert!((ego.y + 5.75).abs() < Y_TOL, "{ego:?}");
}

#[test]
fn lateral_positions_that_cannot_hold_are_errors() {
    crate::along::refused(
        "err_lateral_start",
        "expected this lateral position at the phase start, found `ego` 0.20 m from it",
        "16:13",
    );
    crate::along::refused(
        "err_lateral_outside",
        "puts it 2.25 m from the lane's centre",
        "8:9",
    );
}

#[test]
fn lateral_beside_another_actor_places_at_the_start() {
    let r = run("lateral_beside", 0, None);
    for t in [0.0, 3.0] {
        let npc = r.at(t, "npc");
        assert_eq!(npc.lane, -3, "{npc:?}");
        assert!((npc.y + 8.25).abs() < Y_TOL, "{npc:?}");
    }
    crate::along::refused(
        "err_lateral_beside_lane",
        "expected `npc`'s reference point in its lane -3 (3.50 m wide), found lateral(…) puts it 6.00 m from the lane's centre",
        "16:13",
    );
    crate::along::refused(
        "err_lateral_beside_move",
        "expected a driving lane at t = -11.75 m (where lateral(…) puts `npc` beside `ego` at 3.00 s, s = 90.00 m), found none",
        "19:13",
    );
}

/// lateral(…, left_of: npc, at: end) where the plan has npc at the phase end
/// (lateral_beside_end.osc's comment, by hand): a lane change into the lane that holds the t
/// asked while npc changes lanes, then a lane offset in the actor's own lane.
#[test]
fn lateral_beside_another_actor_at_the_end_is_where_the_plan_has_it() {
    let r = run("lateral_beside_end", 0, None);
    let y = |t: f64, who: &str| r.at(t, who).y;
    for (t, ego, npc) in [
        (1.0, -5.25, -8.75),
        (3.0, -4.0, -7.0),
        (5.0, -2.75, -5.25),
        (6.0, -2.25, -5.25),
        (7.0, -1.75, -5.25),
    ] {
        assert!(
            (y(t, "ego") - ego).abs() < Y_TOL,
            "ego y({t}) = {} vs {ego}",
            y(t, "ego")
        );
        assert!(
            (y(t, "npc") - npc).abs() < Y_TOL,
            "npc y({t}) = {} vs {npc}",
            y(t, "npc")
        );
    }
    assert_eq!(r.at(5.0, "ego").lane, -1);
    assert_eq!(r.at(7.0, "ego").lane, -1);
    crate::along::refused(
        "err_lateral_beside_end_lane",
        "expected `ego`'s reference point in the lane change's target lane -1 (3.50 m wide) at the phase end, found lateral(…) puts it -4.50 m from the lane's centre",
        "20:13",
    );
    crate::along::refused(
        "err_lateral_beside_end_keep_lane",
        "expected `ego` to stay in lane -2 (keep_lane(…) at ",
        "19:13",
    );
}
