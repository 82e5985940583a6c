//! `track: projected` (§8.9.1.1.3): a modifier relative to another actor read against that
//! actor's movement projected from its state at the phase start, not its actual movement.
//! Expectations worked by hand in the scenario files.

use crate::along::refused;
use crate::ramp_lead;
use crate::support::run;

const S_TOL: f64 = 1e-6;
const V_TOL: f64 = 1e-9;
/// Lateral positions: the sinusoid is exact at its ends and half way, up to round-off.
const Y_TOL: f64 = 1e-6;

/// track_projected.osc: lead brakes 10 -> 5 m/s over 1-5 s; ego keeps 20 m behind lead
/// projected at 10 m/s (150 m at 5 s), other 20 m behind lead's actual place (140 m).
#[test]
fn a_position_behind_a_projected_reference_ignores_its_braking() {
    let r = run("track_projected", 0, None);
    let (ego, other, lead) = (
        |t| r.at(t, "ego"),
        |t| r.at(t, "other"),
        |t| r.at(t, "lead"),
    );
    // Half way: vm 25 m/s (projected) and 20 m/s (actual); 17.5 and 15 m/s at 2 s.
    for (t, v_ego, v_other) in [(2.0, 17.5, 15.0), (3.0, 25.0, 20.0), (5.0, 10.0, 10.0)] {
        assert!(
            (ego(t).speed - v_ego).abs() < V_TOL,
            "ego v({t}) = {}",
            ego(t).speed
        );
        assert!(
            (other(t).speed - v_other).abs() < V_TOL,
            "other v({t}) = {}",
            other(t).speed
        );
    }
    // s(3): 95 m and 90 m plus the engine's lead of the first half's ramp.
    assert!(
        (ego(3.0).s - (95.0 + ramp_lead(7.5, 2.0))).abs() < S_TOL,
        "{}",
        ego(3.0).s
    );
    assert!(
        (other(3.0).s - (90.0 + ramp_lead(5.0, 2.0))).abs() < S_TOL,
        "{}",
        other(3.0).s
    );
    // At 5 s the second half has undone the lead: 130 m (projected), 120 m (actual); lead at
    // 140 m less its own ramp's lag.
    assert!((ego(5.0).s - 130.0).abs() < S_TOL, "{}", ego(5.0).s);
    assert!((other(5.0).s - 120.0).abs() < S_TOL, "{}", other(5.0).s);
    let lead5 = 140.0 + ramp_lead(-1.25, 4.0);
    assert!((lead(5.0).s - lead5).abs() < S_TOL, "{}", lead(5.0).s);
    assert!((lead(5.0).speed - 5.0).abs() < V_TOL);
    assert!((ego(6.0).s - 140.0).abs() < S_TOL, "{}", ego(6.0).s);
    // tail: to lead's speed at the phase start, 8 -> 10 m/s.
    for (t, v) in [(3.0, 9.0), (5.0, 10.0)] {
        assert!((r.at(t, "tail").speed - v).abs() < V_TOL, "tail v({t})");
    }
    // holder: lead's 10 m/s at the phase start, held while lead brakes.
    for (t, v) in [(0.5, 8.0), (1.05, 10.0), (3.0, 10.0), (5.0, 10.0)] {
        assert!((r.at(t, "holder").speed - v).abs() < V_TOL, "holder v({t})");
    }
}

#[test]
fn track_projected_without_a_reference_is_an_error() {
    refused(
        "err_track_projected",
        "expected track: projected on `speed(…)` relative to another actor (ahead_of, behind, same_as, faster_than, slower_than, side_of, left_of, right_of), found no reference (the track is the referenced actor's movement)",
        "5:29",
    );
}

/// track_projected_shadowed.osc: the actors named `projected` and `actual` do not hide the
/// members of `track` where a track is expected (the checker's rule: an expected enum's member
/// wins over a field of another type), so the run is track_projected.osc's: 130 m (projected)
/// and 120 m (actual) at 5 s, 25 and 20 m/s half way (by hand in track_projected.osc).
#[test]
fn an_actor_named_like_a_track_member_does_not_hide_it() {
    let r = run("track_projected_shadowed", 0, None);
    for (who, v3, s5) in [("projected", 25.0, 130.0), ("actual", 20.0, 120.0)] {
        let v = r.at(3.0, who).speed;
        assert!((v - v3).abs() < V_TOL, "{who} v(3) = {v}");
        let s = r.at(5.0, who).s;
        assert!((s - s5).abs() < S_TOL, "{who} s(5) = {s}");
    }
}

/// track_projected_lanes.osc: npc changes lanes -3 -> -2 over 1-5 s; lanes and lateral
/// positions relative to it at the phase end, actual and projected (the comment, by hand).
#[test]
fn lanes_and_lateral_positions_beside_a_projected_reference() {
    let r = run("track_projected_lanes", 0, None);
    let at = |t: f64, who: &str| r.at(t, who);
    for (who, y3, y5, lane5) in [
        ("npc", -7.0, -5.25, -2),
        ("keeper", -1.75, -1.75, -1),
        ("mover", -3.5, -5.25, -2),
        ("beside", -3.75, -5.75, -2),
    ] {
        assert!(
            (at(3.0, who).y - y3).abs() < Y_TOL,
            "{who} y(3) = {}",
            at(3.0, who).y
        );
        assert!(
            (at(5.0, who).y - y5).abs() < Y_TOL,
            "{who} y(5) = {}",
            at(5.0, who).y
        );
        assert_eq!(at(5.0, who).lane, lane5, "{who}");
        assert_eq!(at(6.0, who).lane, lane5, "{who}");
    }
}

/// track_projected_gap.osc: without a duration, the phase ends when the plan has the gap to
/// lead's projection reached (3.00 s by hand), while lead brakes.
#[test]
fn a_gap_to_a_projected_reference_ends_its_phase_at_the_planned_time() {
    let r = run("track_projected_gap", 0, None);
    let (s, e) = r.phase("do.ego.close");
    assert!(
        (s - 1.0).abs() < 1e-9 && (e - 3.0).abs() < 1e-9,
        "close [{s}, {e}]"
    );
    assert!(
        (r.at(3.0, "ego").s - 110.0).abs() < S_TOL,
        "{}",
        r.at(3.0, "ego").s
    );
    let lead = 129.0 + ramp_lead(-0.5, 2.0);
    assert!(
        (r.at(3.0, "lead").s - lead).abs() < S_TOL,
        "{}",
        r.at(3.0, "lead").s
    );
}
