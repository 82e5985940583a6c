//! `keep(…)` in the `with:` of an action invocation (ASAM OpenSCENARIO DSL 2.1 §7.3.9
//! behavior-with-member): the invocation is an instance the solver resolves with the scenario's
//! seed, so its arguments satisfy the keep (`tests/scenarios/keep/*.osc`).

use crate::support::{error, lower, run, stepped};

/// Speeds are closed forms the engine evaluates at step times.
const TOL: f64 = 1e-9;

#[test]
fn a_keep_narrows_an_actions_drawn_argument_for_every_seed() {
    let mut drawn = Vec::new();
    for seed in 0..6 {
        let r = run("keep/keep_drawn", seed, None);
        let (s, e) = r.phase("do.1");
        // The keep's duration: 4 s from 1 s.
        assert!(
            (s - 1.0).abs() < TOL && (e - 5.0).abs() < TOL,
            "seed {seed}: {s}-{e}"
        );
        let v = r.at(5.0, "ego").speed;
        assert!(
            (15.0 - TOL..=20.0 + TOL).contains(&v),
            "seed {seed}: {v} m/s"
        );
        // Linear from 10 m/s: half way at 3 s.
        let mid = r.at(3.0, "ego").speed;
        assert!(
            (mid - (10.0 + v) / 2.0).abs() < 1e-6,
            "seed {seed}: {mid} vs {v}"
        );
        drawn.push(v);
    }
    // The seed draws: not one value for all (the keep narrows, it does not fix).
    assert!(
        drawn.iter().any(|v| (v - drawn[0]).abs() > 1e-3),
        "{drawn:?}"
    );
    // Same seed, same value.
    let again = run("keep/keep_drawn", 3, None).at(5.0, "ego").speed;
    assert!((again - drawn[3]).abs() < TOL);
    assert!(lower("keep/keep_drawn", 0, None).is_ok());
}

#[test]
fn a_keep_that_leaves_one_value_gives_the_motion_by_hand() {
    let r = run("keep/keep_fixed", 0, None);
    let v = |t: f64| {
        if t <= 1.0 {
            10.0
        } else {
            (10.0 + 2.0 * (t - 1.0)).min(18.0)
        }
    };
    assert!((r.at(3.0, "ego").speed - 14.0).abs() < TOL);
    assert!((r.at(5.0, "ego").speed - 18.0).abs() < TOL);
    assert!((r.at(6.0, "ego").speed - 18.0).abs() < TOL);
    let (s, e) = r.phase("do.1");
    assert!((s - 1.0).abs() < TOL && (e - 5.0).abs() < TOL, "{s}-{e}");
    // 86 m by hand at 5 s; the step sum leads by 8 m/s·dt/2 = 0.2 m.
    assert!((stepped(v, 0.0, 5.0) - (66.0 + 0.2)).abs() < 1e-9);
    assert!((r.at(5.0, "ego").s - (20.0 + stepped(v, 0.0, 5.0))).abs() < 1e-6);
}

#[test]
fn a_keep_that_contradicts_the_arguments_is_an_error_at_its_place() {
    // The argument's hard constraint it.target == 30 m/s (4:33) against the keep (6:9).
    let e = error("keep/err_keep_contradicts");
    assert!(
        e.starts_with(
            "the constraints have no solution: this constraint conflicts with 1 other(s) at "
        ) && e.contains("err_keep_contradicts.osc:4:33")
            && e.contains("conflicting constraint at ")
            && e.contains("err_keep_contradicts.osc:6:9"),
        "{e}"
    );
}

/// keep(…) in the with: of an action invoked in an `on` handler: the invocation itself is bad
/// input (§7.3.10: an `on` directive's members are `emit` and `call`), the parser's error at
/// the invocation.
#[test]
fn a_keep_on_an_action_in_an_on_handler_is_an_error_at_the_invocation() {
    let e = error("err_keep_on_handler");
    assert!(e.contains("err_keep_on_handler.osc:7:9"), "{e}");
    assert!(
        e.starts_with("expected a `call` or `emit` directive, found an invocation"),
        "{e}"
    );
}
