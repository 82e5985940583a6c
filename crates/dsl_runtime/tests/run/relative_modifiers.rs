//! Modifiers relative to another actor that the plan once refused (issue 27): `acceleration(…,
//! track: projected)`, shaped modifiers relative to another actor, `lateral(…)` beside another
//! actor that moves sideways, and `lateral(…, at: end)` beside another actor after a run-time
//! start. Every expectation is worked by hand in the scenario's comment (`tests/scenarios/relative`).

use crate::support::run;

/// Speeds of linear changes on the 0.05 s grid: float round-off.
const V_TOL: f64 = 1e-9;
/// Positions where the engine integrates a linear speed change step by step: its steps lag
/// the ramp by a·dt/2 per second (0.05 m/s·s at 2 m/s², over 4 s 0.2 m), within the plan's
/// 0.5 m check; asserted at the plan's figure to this.
const S_LAG_TOL: f64 = 0.25;

fn close(got: f64, want: f64, tol: f64, what: &str) {
    assert!((got - want).abs() < tol, "{what}: {got} vs {want}");
}

/// ego's and `other`'s speeds at each (t, ego's, other's).
fn speeds(r: &crate::support::Run, other: &str, want: &[(f64, f64, f64)]) {
    for &(t, ego, x) in want {
        close(r.at(t, "ego").speed, ego, V_TOL, &format!("ego v({t})"));
        close(r.at(t, other).speed, x, V_TOL, &format!("{other} v({t})"));
    }
}

/// acceleration_projected.osc's comment, by hand: npc's -3 m/s² at the phase start + 1, fixed
/// while npc's own braking ends at 5 s.
#[test]
fn a_projected_acceleration_relative_to_another_is_its_acceleration_at_the_start_fixed() {
    let r = run("relative/acceleration_projected", 0, None);
    let want = [
        (3.0, 10.0, 16.0),
        (4.0, 8.0, 13.0),
        (5.0, 6.0, 10.0),
        (6.0, 4.0, 10.0),
        (7.0, 2.0, 10.0),
        (8.0, 2.0, 10.0),
    ];
    speeds(&r, "npc", &want);
    close(r.at(7.0, "ego").s, 104.0, S_LAG_TOL, "ego s(7)");
    close(r.at(8.0, "ego").s, 106.0, S_LAG_TOL, "ego s(8)");
}

/// runtime_acceleration_projected.osc's comment, by hand: after the until at 3.35 s, lead's
/// acceleration over each phase's first step, ± the value, held.
#[test]
fn a_projected_acceleration_relative_to_another_after_an_until_is_its_acceleration_at_the_start() {
    let r = run("relative/runtime_acceleration_projected", 0, None);
    let (s, e) = r.phase("do.follow");
    close(s, 3.35, 1e-9, "do.follow starts");
    close(e, 7.35, 1e-9, "do.follow ends");
    let want = [
        (3.35, 20.0, 8.0),
        (4.35, 19.0, 6.0),
        (5.35, 18.0, 4.0),
        (6.35, 17.0, 4.0),
        (7.35, 16.0, 4.0),
        (8.35, 17.0, 5.0),
        (9.35, 18.0, 5.0),
    ];
    speeds(&r, "lead", &want);
}

/// runtime_acceleration_shape.osc's comment, by hand: after the until at 3.35 s, the shape's
/// 1 m/s³ change from 0 to lead's −2 m/s² + 1, then lead's + 1 followed (ego) or −1 held
/// (tail).
#[test]
fn a_shaped_acceleration_relative_to_another_after_an_until_reaches_xs_at_the_shapes_rate() {
    let r = run("relative/runtime_acceleration_shape", 0, None);
    crate::runtime::phases(&r, &[("do.follow", 3.35, 7.35)]);
    for (t, ego, tail, lead) in [
        (3.35, 20.0, 20.0, 8.0),
        (3.85, 19.875, 19.875, 7.0),
        (4.35, 19.5, 19.5, 6.0),
        (5.35, 18.5, 18.5, 4.0),
        (6.35, 19.5, 17.5, 4.0),
        (7.35, 20.5, 16.5, 4.0),
    ] {
        close(r.at(t, "ego").speed, ego, V_TOL, &format!("ego v({t})"));
        close(r.at(t, "tail").speed, tail, V_TOL, &format!("tail v({t})"));
        close(r.at(t, "lead").speed, lead, V_TOL, &format!("lead v({t})"));
    }
}

/// Lateral positions: float round-off on the straight road.
const Y_TOL: f64 = 1e-6;

/// shape_relative.osc's comment, by hand: the shapes' targets from npc's speed, acceleration
/// and lateral place.
#[test]
fn a_shaped_modifier_relative_to_another_aims_at_its_value_plus_the_modifiers() {
    let r = run("relative/shape_relative", 0, None);
    let ego = |t: f64| r.at(t, "ego");
    for (t, v) in [
        (1.0, 10.0),
        (2.5, 13.0),
        (4.0, 16.0),
        (5.0, 16.0),
        (6.0, 16.125),
        (7.0, 16.5),
        (9.0, 17.5),
    ] {
        close(ego(t).speed, v, SHAPE_V_TOL, &format!("ego v({t})"));
    }
    for (t, y) in [(9.0, -5.25), (10.0, -5.75), (11.0, -6.25), (12.0, -6.25)] {
        close(ego(t).y, y, Y_TOL, &format!("ego y({t})"));
    }
    close(r.at(12.0, "npc").y, -8.75, Y_TOL, "npc y(12)");
}

/// The speeds of a constant-jerk acceleration change, integrated by the engine per step: its
/// speed lags v = v₀ + j·τ²/2 by j·τ·dt/2 at most (0.25·2·0.05/2 = 0.0125 m/s), then keeps it.
const SHAPE_V_TOL: f64 = 0.015;

/// runtime_speed_shape_relative.osc's comment, by hand: lead's 8 m/s + 2 read by the engine.
#[test]
fn a_shaped_speed_relative_to_another_after_an_until_aims_at_its_speed_as_the_engine_reads_it() {
    let r = run("relative/runtime_speed_shape_relative", 0, None);
    let (s, e) = r.phase("do.slow");
    close(s, 3.35, 1e-9, "do.slow starts");
    close(e, 5.85, 1e-9, "do.slow ends where the change does");
    for (t, v) in [(3.85, 18.0), (4.85, 14.0), (5.85, 10.0), (6.85, 10.0)] {
        close(r.at(t, "ego").speed, v, V_TOL, &format!("ego v({t})"));
    }
}

#[test]
fn a_shaped_speed_relative_to_one_that_changes_over_the_change_is_an_error() {
    crate::along::refused(
        "relative/err_shape_relative_changes",
        "expected `npc`'s planned speed (m/s) where `speed(…)`'s shaped change ends its phase (3.00 s) to be the 14.00 its target was read from at 0.00 s, found 17.00 (give the phase a duration, or track: projected)",
        "20:38",
    );
}

/// lane_shape_relative.osc's comment, by hand: one lane to npc's at 0.875 m/s.
#[test]
fn a_shaped_lane_relative_to_another_changes_to_its_lane_with_the_shapes_dynamics() {
    let r = run("relative/lane_shape_relative", 0, None);
    for (t, y) in [(1.0, -5.25), (3.0, -7.0), (5.0, -8.75), (6.0, -8.75)] {
        close(r.at(t, "ego").y, y, Y_TOL, &format!("ego y({t})"));
    }
    assert_eq!(r.at(6.0, "ego").lane, -3);
}

/// lateral_follow.osc's comment, by hand: ego follows npc's offset change and lane change 2.5 m
/// to its left at every step; keeper holds npc's t at the phase start + 4.5 m.
#[test]
fn a_lateral_position_beside_another_that_moves_sideways_follows_it_throughout() {
    let r = run("relative/lateral_follow", 0, None);
    let y = |t: f64, who: &str| r.at(t, who).y;
    let npc = |t: f64| {
        if t <= 1.0 {
            -8.75
        } else if t <= 5.0 {
            -8.75 + 0.25 * (1.0 - (std::f64::consts::PI * (t - 1.0) / 4.0).cos())
        } else if t <= 9.0 {
            -8.25 + 1.5 * (1.0 - (std::f64::consts::PI * (t - 5.0) / 4.0).cos())
        } else {
            -5.25
        }
    };
    for (t, want) in [(3.0, -8.5), (5.0, -8.25), (7.0, -6.75), (9.0, -5.25)] {
        close(npc(t), want, 1e-12, &format!("the comment's npc y({t})"));
    }
    // At every step: ego 2.5 m left of npc (actual), keeper at -4.25 m (projected).
    for (t, objs) in &r.frames {
        if *t > 9.0 + 1e-9 {
            break;
        }
        let at = |who: &str| {
            objs.iter()
                .find(|o| o.name == who)
                .unwrap_or_else(|| panic!("{who}"))
        };
        close(at("npc").y, npc(*t), Y_TOL, &format!("npc y({t})"));
        close(at("ego").y, npc(*t) + 2.5, Y_TOL, &format!("ego y({t})"));
        close(at("keeper").y, -4.25, Y_TOL, &format!("keeper y({t})"));
    }
    for (t, want, lane) in [
        (3.0, -6.0, -2),
        (5.0, -5.75, -2),
        (7.0, -4.25, -2),
        (9.0, -2.75, -1),
        (10.0, -2.75, -1),
    ] {
        close(y(t, "ego"), want, Y_TOL, &format!("ego y({t})"));
        assert_eq!(r.at(t, "ego").lane, lane, "ego's lane at {t}");
    }
    // ego moves sideways as npc does at the same speed: its heading is npc's, from its lateral
    // speed over the step (x's t over the step, the engine's second pass).
    for t in [3.0, 7.0] {
        let (e, n) = (r.at(t, "ego").h, r.at(t, "npc").h);
        close(e, n, HEADING_TOL, &format!("ego heading({t})"));
    }
}

/// ego's heading from npc's lateral speed over one step (the chord of npc's sinusoid) against
/// npc's (its tangent at the step's end): they differ by O(dt²) of the slope, 3e-5 rad at 7 s.
const HEADING_TOL: f64 = 1e-4;

/// runtime_lateral_beside_lane_of.osc's comment, by hand: ego beside npc into lane -1, one
/// lane left of lead's lane at the phase end, checked then.
#[test]
fn a_lane_relative_to_another_beside_a_lateral_position_after_an_until_is_checked_at_the_end() {
    let r = run("relative/runtime_lateral_beside_lane_of", 0, None);
    crate::runtime::phases(&r, &[("do.shift", 3.35, 5.35)]);
    let f = |tau: f64| (1.0 - (std::f64::consts::PI * tau / 2.0).cos()) / 2.0;
    for k in 0..=40 {
        let t = 3.35 + 0.05 * f64::from(k);
        let g = f(t - 3.35);
        close(
            r.at(t, "ego").y,
            -5.25 + 2.0 * g + g * g,
            Y_TOL,
            &format!("ego y({t})"),
        );
    }
    for (t, y, lane) in [(4.35, -4.0, -2), (5.35, -2.25, -1), (6.35, -2.25, -1)] {
        close(r.at(t, "ego").y, y, Y_TOL, &format!("ego y({t})"));
        assert_eq!(r.at(t, "ego").lane, lane, "ego's lane at {t}");
    }
    crate::runtime::ran_at(&r, &[("do.shift.0/ego/2:lane.end", 5.35)]);
    crate::runtime::fails(
        "relative/runtime_lateral_beside_lane_of_fails",
        (
            "expected 'ego' in lane -2",
            "runtime_lateral_beside_lane_of_fails.osc:38:17), found it in lane -1 of road 1 at t = 5.350 s",
        ),
        "do.shift.0/ego/2:lane.end",
        5.35,
    );
}

/// runtime_lateral_end_several_roads.osc's comment, by hand: ego on road 0 moves to lead's t
/// on road 1 + 0.5 m over 2 s (one measure across the continuous joint).
#[test]
fn a_lateral_position_beside_another_on_another_of_the_plans_roads_after_an_until_is_reached() {
    let r = crate::support::run_on(
        "relative/runtime_lateral_end_several_roads",
        "junction_trippel_twoway0",
    );
    crate::runtime::phases(&r, &[("do.shift", 5.85, 7.85)]);
    let lead = r.at(5.85, "lead");
    assert_eq!((lead.road.as_str(), lead.lane), ("1", -1), "{lead:?}");
    let f = |tau: f64| (1.0 - (std::f64::consts::PI * tau / 2.0).cos()) / 2.0;
    for k in 0..=40 {
        let t = 5.85 + 0.05 * f64::from(k);
        close(
            r.at(t, "ego").y,
            -1.5 + 0.5 * f(t - 5.85),
            Y_TOL,
            &format!("ego y({t})"),
        );
    }
    // x: 8 m/s along the path, less its cost along the road: t(u) = -1.5 + 0.25·(1 − cos(π·u/16))
    // over u in [0, 16] m, slope k·sin(π·u/16), k = 0.25·π/16; ∫ (1 − cos θ) du ≈ ∫ slope²/2 du
    // = k²·u/4 − k²·sin(2π·u/16)·16/(8π): 0.00482 m half way, 0.00964 m at the end.
    let k: f64 = 0.25 * std::f64::consts::PI / 16.0;
    let cost = |u: f64| {
        k * k * u / 4.0
            - k * k * (2.0 * std::f64::consts::PI * u / 16.0).sin() * 16.0
                / (8.0 * std::f64::consts::PI)
    };
    for (t, x, y) in [
        (6.85, 75.0 - cost(8.0), -1.25),
        (7.85, 83.0 - cost(16.0), -1.0),
        (8.85, 91.0 - cost(16.0), -1.0),
    ] {
        let ego = r.at(t, "ego");
        assert_eq!((ego.road.as_str(), ego.lane), ("0", -1), "{ego:?}");
        close(ego.x, x, X_COST_TOL, &format!("ego x({t})"));
        close(ego.y, y, Y_TOL, &format!("ego y({t})"));
    }
}

/// x along a sideways move against the closed form of its cost (slope²/2 for 1 − cos θ, and
/// the engine's steps): 1e-4 m.
const X_COST_TOL: f64 = 1e-4;

/// position_shape_relative.osc's comment, by hand: 20 m behind lead's place at the phase end
/// (actual 158 m, projected 150 m), the smooth profile over the phase's 4 s.
#[test]
fn a_shaped_position_relative_to_another_covers_the_distance_to_its_place_at_the_end() {
    let r = run("relative/position_shape_relative", 0, None);
    for (who, v2, v3, s3, s5) in [
        ("ego", 14.5, 19.0, 109.0, 138.0),
        ("tail", 12.5, 15.0, 105.0, 130.0),
    ] {
        close(r.at(2.0, who).speed, v2, SINE_V_TOL, &format!("{who} v(2)"));
        close(r.at(3.0, who).speed, v3, SINE_V_TOL, &format!("{who} v(3)"));
        // The engine's steps are ahead of the first half's integral by (v_m − v0)·dt/2 at its
        // end, and the second half gives it back.
        let lead_of_steps = (v3 - 10.0) * crate::support::DT / 2.0;
        close(
            r.at(3.0, who).s,
            s3 + lead_of_steps,
            STEP_S_TOL,
            &format!("{who} s(3)"),
        );
        close(r.at(5.0, who).s, s5, STEP_S_TOL, &format!("{who} s(5)"));
    }
    close(
        r.at(5.0, "lead").s,
        158.0 + 4.0 * crate::support::DT / 2.0,
        STEP_S_TOL,
        "lead s(5)",
    );
}

/// position_shape_relative_rate.osc's comment, by hand: without a phase duration the shape's
/// rate_peak sets the end T = 4 s where the profile covering the distance to lead's place
/// then (actual: 158 m − 20; projected: 150 m − 20) takes exactly T.
#[test]
fn a_shaped_position_relative_to_another_without_a_duration_ends_where_its_rate_meets_xs_place() {
    let r = run("relative/position_shape_relative_rate", 0, None);
    crate::runtime::phases(
        &r,
        &[
            ("do.1.1", 1.0, 5.0),
            ("do.1.2", 5.0, 6.0),
            ("do.2.1", 1.0, 5.0),
        ],
    );
    // ego: two sinusoidal halves 10 → 20 → 10 m/s; the engine's steps lead the first half's
    // integral by (v_m − v0)·dt/2 at its end and give it back over the second.
    close(r.at(2.0, "ego").speed, 15.0, SINE_V_TOL, "ego v(2)");
    close(r.at(3.0, "ego").speed, 20.0, SINE_V_TOL, "ego v(3)");
    close(r.at(5.0, "ego").speed, 10.0, SINE_V_TOL, "ego v(5)");
    let lead_of_steps = 10.0 * crate::support::DT / 2.0;
    close(
        r.at(3.0, "ego").s,
        108.0 + lead_of_steps,
        STEP_S_TOL,
        "ego s(3)",
    );
    close(r.at(5.0, "ego").s, 138.0, STEP_S_TOL, "ego s(5)");
    close(r.at(6.0, "ego").s, 148.0, STEP_S_TOL, "ego s(6)");
    // lead's linear change, stepped: a·dt/2 per second ahead of the closed form.
    let lead5 = r.at(5.0, "lead").s;
    close(
        lead5,
        158.0 + 4.0 * crate::support::DT / 2.0,
        STEP_S_TOL,
        "lead s(5)",
    );
    // tail: a step to 20 m/s, held to 5 s.
    close(r.at(3.0, "tail").speed, 20.0, SINE_V_TOL, "tail v(3)");
    close(r.at(3.0, "tail").s, 90.0, STEP_S_TOL, "tail s(3)");
    close(r.at(5.0, "tail").s, 130.0, STEP_S_TOL, "tail s(5)");
}

/// err_position_shape_unreachable.osc's comment: lead at 30 m/s outruns a profile of 20 m/s.
#[test]
fn a_shaped_position_relative_to_one_that_outruns_its_rate_is_an_error_naming_both() {
    let e = crate::support::error("relative/err_position_shape_unreachable");
    for w in [
        "err_position_shape_unreachable.osc:22:39",
        "expected `ego` to reach its place 20 m behind `lead` at the rate of `position(…)`'s shape (a mean 20.00 m/s), found `lead` moving away as fast",
    ] {
        assert!(e.contains(w), "{w:?} not in {e}");
    }
}

/// runtime_lateral_shape_actual.osc's comment, by hand: after the until at 3.35 s, linear at
/// 0.5 m/s from ego's t to npc's moving t + 3 m over 1 s, then npc's t + 3 m held.
#[test]
fn a_shaped_lateral_position_beside_an_actual_reference_after_an_until_follows_it_at_the_shapes_rate(
) {
    let r = run("relative/runtime_lateral_shape_actual", 0, None);
    crate::runtime::phases(&r, &[("do.shift", 3.35, 5.35)]);
    let pi = std::f64::consts::PI;
    let npc = |tau: f64| -8.75 + (1.0 - (pi * tau / 2.0).cos()) / 2.0;
    for k in 0..=40 {
        let t = 3.35 + 0.05 * f64::from(k);
        let tau = t - 3.35;
        let f = tau.min(1.0);
        let want = (1.0 - f) * -5.25 + f * (npc(tau) + 3.0);
        close(r.at(t, "npc").y, npc(tau), Y_TOL, &format!("npc y({t})"));
        close(r.at(t, "ego").y, want, Y_TOL, &format!("ego y({t})"));
    }
    for (t, y) in [
        (3.85, -5.426777),
        (4.35, -5.25),
        (4.85, -4.896447),
        (5.35, -4.75),
    ] {
        close(r.at(t, "ego").y, y, 1e-6, &format!("ego y({t}) by hand"));
    }
}

/// The engine's sinusoidal speed halves, stepped: speeds exact on the grid up to round-off.
const SINE_V_TOL: f64 = 1e-6;
/// Positions integrated per step, their lead over the profile's integral written out: float
/// round-off.
const STEP_S_TOL: f64 = 1e-6;

/// runtime_lateral_shape_projected.osc's comment, by hand: 0.5 m at 0.5 m/s from 3.35 s to
/// npc's t at the start + 3 m, held while npc moves.
#[test]
fn a_shaped_lateral_position_beside_a_projected_reference_after_an_until_reaches_it_at_the_shapes_rate(
) {
    let r = run("relative/runtime_lateral_shape_projected", 0, None);
    crate::runtime::phases(&r, &[("do.shift", 3.35, 5.35)]);
    for k in 0..=40 {
        let t = 3.35 + 0.05 * f64::from(k);
        let want = -5.25 - 0.5 * (t - 3.35).min(1.0);
        close(r.at(t, "ego").y, want, Y_TOL, &format!("ego y({t})"));
        assert_eq!(r.at(t, "ego").lane, -2, "ego's lane at {t}");
    }
    close(r.at(5.35, "npc").y, -7.75, Y_TOL, "npc y(5.35)");
}
