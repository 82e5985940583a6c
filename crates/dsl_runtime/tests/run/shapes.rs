//! Movement modifiers with a `shape:` (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.4, §8.9.1.2): the
//! library's common shapes run with the dynamics of the §8.8 action their semantic
//! clarification names (`tests/scenarios/shapes/*.osc`, each worked out by hand in its
//! comments), on `tests/roads/straight.xodr`; shapes the engine cannot run are errors at the
//! argument.

use std::f64::consts::PI;

use crate::support::{error, run, stepped};

/// Speeds and offsets are closed forms the engine evaluates at the step times.
const TOL: f64 = 1e-9;
/// Distances are sums of a few hundred steps (their closed forms checked separately).
const S_TOL: f64 = 1e-6;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;

fn close(got: f64, want: f64, tol: f64, what: &str) {
    assert!((got - want).abs() < tol, "{what}: {got} vs {want}");
}

fn phase(r: &crate::support::Run, path: &str, s: f64, e: f64) {
    let (a, b) = r.phase(path);
    assert!(
        (a - s).abs() < T_TOL && (b - e).abs() < T_TOL,
        "{path}: {a}-{b}, expected {s}-{e}"
    );
}

#[test]
fn a_common_speed_shape_is_change_speeds_dynamics() {
    let r = run("shapes/speed_shape", 0, None);
    let v = |t: f64| {
        if t <= 1.0 {
            10.0
        } else if t <= 3.0 {
            10.0 + 5.0 * (t - 1.0)
        } else if t <= 7.0 {
            20.0 - 5.0 * (1.0 - (PI * (t - 3.0) / 4.0).cos())
        } else {
            10.0
        }
    };
    // The shape with no end of its own ends its phase when its target is reached.
    phase(&r, "do.0", 0.0, 1.0);
    phase(&r, "do.1", 1.0, 3.0);
    phase(&r, "do.2", 3.0, 7.0);
    phase(&r, "do.3", 7.0, 8.0);
    close(r.at(2.0, "ego").speed, 15.0, TOL, "v(2)");
    close(r.at(3.0, "ego").speed, 20.0, TOL, "v(3)");
    close(r.at(4.0, "ego").speed, 18.535_533_905_932_74, TOL, "v(4)");
    close(r.at(5.0, "ego").speed, 15.0, TOL, "v(5)");
    close(r.at(7.0, "ego").speed, 10.0, TOL, "v(7)");
    close(r.at(8.0, "ego").speed, 10.0, TOL, "v(8)");
    for t in [2.0, 3.0, 5.0, 8.0] {
        close(
            r.at(t, "ego").s,
            20.0 + stepped(v, 0.0, t),
            S_TOL,
            &format!("s({t})"),
        );
    }
    // By hand: 10 m by 1 s, + 30 m by 3 s (the linear change), + 60 m by 7 s (the sinusoid's
    // mean speed 15 m/s), + 10 m by 8 s = 110 m; the step sum leads the way up by
    // 10 m/s·dt/2 and lags the way down by as much (the sinusoid symmetric about its middle).
    close(stepped(v, 0.0, 8.0), 110.0, 1e-9, "hand s(8)");
}

#[test]
fn a_common_acceleration_shape_is_change_accelerations_dynamics() {
    let r = run("shapes/acceleration_shape", 0, None);
    close(r.at(1.0, "ego").speed, 10.0, TOL, "v(1)");
    close(r.at(2.0, "ego").speed, 10.5, 1e-6, "v(2)");
    close(r.at(3.0, "ego").speed, 12.0, 1e-6, "v(3)");
    close(r.at(4.0, "ego").speed, 14.0, 1e-6, "v(4)");
    phase(&r, "do.1", 1.0, 4.0);
}

#[test]
fn a_common_lateral_shape_is_the_lane_change_and_offset_dynamics() {
    let r = run("shapes/lateral_shape", 0, None);
    close(r.at(0.0, "ego").y, -8.75, TOL, "y(0)");
    close(r.at(2.0, "ego").y, -7.0, TOL, "y(2)");
    let end = r.at(4.0, "ego");
    close(end.y, -5.25, TOL, "y(4)");
    assert_eq!(end.lane, -2);
    phase(&r, "do.0", 0.0, 4.0);
    phase(&r, "do.1", 4.0, 8.0);
    close(r.at(5.0, "ego").y, -5.0, 1e-6, "y(5)");
    close(r.at(6.0, "ego").y, -4.75, 1e-6, "y(6)");
    close(r.at(8.0, "ego").y, -4.75, 1e-6, "y(8)");
    assert_eq!(r.at(8.0, "ego").lane, -2);
}

#[test]
fn a_common_lateral_shape_on_a_lane_at_the_end_is_that_lane_change() {
    let r = run("shapes/lane_shape", 0, None);
    for (t, y) in [(0.0, -8.75), (2.0, -7.0), (4.0, -5.25), (5.0, -5.25)] {
        close(r.at(t, "ego").y, y, TOL, &format!("y({t})"));
    }
    assert_eq!(r.at(4.0, "ego").lane, -2);
    phase(&r, "do.0", 0.0, 4.0);
    phase(&r, "do.1", 4.0, 5.0);
}

#[test]
fn a_speed_shape_after_a_run_time_condition_starts_from_the_engines_speed() {
    let r = run("shapes/runtime_speed_shape", 0, None);
    phase(&r, "do.approach", 0.0, 3.35);
    phase(&r, "do.slow", 3.35, 5.85);
    phase(&r, "do.after", 5.85, 6.85);
    for (t, v) in [
        (3.35, 20.0),
        (3.85, 18.0),
        (4.85, 14.0),
        (5.85, 10.0),
        (6.85, 10.0),
    ] {
        close(r.at(t, "ego").speed, v, 1e-6, &format!("v({t})"));
    }
}

/// A common_position_shape is the speed profile that covers the distance
/// (position_shape.osc's comment, by hand).
#[test]
fn a_common_position_shape_is_the_speed_profile_that_covers_the_distance() {
    let r = run("shapes/position_shape", 0, None);
    let v = |t: f64| {
        if t <= 1.0 {
            10.0
        } else if t <= 3.0 {
            10.0 + 10.0 * (1.0 - (PI * (t - 1.0) / 2.0).cos()) / 2.0
        } else if t <= 5.0 {
            20.0 - 10.0 * (1.0 - (PI * (t - 3.0) / 2.0).cos()) / 2.0
        } else {
            15.0
        }
    };
    phase(&r, "do.0", 0.0, 1.0);
    phase(&r, "do.1", 1.0, 5.0);
    phase(&r, "do.2", 5.0, 7.0);
    phase(&r, "do.3", 7.0, 8.0);
    for (t, want) in [
        (2.0, 15.0),
        (3.0, 20.0),
        (4.0, 15.0),
        (5.0, 10.0),
        (6.0, 15.0),
    ] {
        close(r.at(t, "ego").speed, want, TOL, &format!("v({t})"));
    }
    for t in [3.0, 5.0, 6.0, 7.0, 8.0] {
        close(
            r.at(t, "ego").s,
            20.0 + stepped(v, 0.0, t),
            S_TOL,
            &format!("s({t})"),
        );
    }
    // By hand: 60 m at 3 s, 90 m at 5 s (the position asked for), 105 m at 6 s, 120 m at 7 s,
    // 135 m at 8 s; the step sum leads the way up by as much as it lags the way down.
    for (t, hand) in [(5.0, 90.0), (6.0, 105.0), (7.0, 120.0), (8.0, 135.0)] {
        close(
            20.0 + stepped(v, 0.0, t),
            hand,
            1e-9,
            &format!("hand s({t})"),
        );
    }
}

fn expect(name: &str, place: &str, words: &[&str]) {
    let e = error(&format!("shapes/{name}"));
    assert!(e.contains(&format!("{name}.osc:{place}")), "{e}");
    for w in words {
        assert!(e.contains(w), "{w:?} not in {e}");
    }
}

#[test]
fn shapes_the_engine_does_not_run_are_errors_at_the_argument() {
    expect(
        "err_shape_own",
        "9:22",
        &["expected a common_speed_shape as the shape of `speed(…)`, found `my_speed_shape`, a shape of the program's own: its compute() is no dynamics the engine runs"],
    );
    expect(
        "err_shape_kind",
        "7:22",
        &["expected a common_speed_shape as the shape of `speed(…)`, found `common_lateral_shape`"],
    );
}

#[test]
fn shapes_that_contradict_their_phase_or_modifiers_are_errors() {
    // 20 m/s at a constant 2 m/s² from 10 m/s: 10 s, in a 4 s phase.
    expect(
        "err_shape_long",
        "10:9",
        &["expected the change of `speed(…)`'s shape within the phase's 4.00 s, found it takes 10.00 s"],
    );
    expect(
        "err_shape_beside",
        "10:9",
        &["expected no `acceleration(…)` beside `speed(…)` at", "err_shape_beside.osc:9:9, whose common_speed_shape fixes that state variable over the phase"],
    );
    expect(
        "err_shape_position",
        "10:9",
        &["expected rate_profile constant, smooth or none in `position(…)`'s common_position_shape, found asap"],
    );
    expect(
        "err_shape_position_peak",
        "14:13",
        &["expected the shape's rate_peak to cover 30.00 m in the phase's 3.00 s, found it takes 2.00 s"],
    );
    expect(
        "err_shape_target",
        "9:38",
        &["expected the shape's target to agree with `speed(…)`'s own value, found 20 against 15 (SI units"],
    );
}
