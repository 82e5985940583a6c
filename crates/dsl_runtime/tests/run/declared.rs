//! Actions the program declares (ASAM OpenSCENARIO DSL 2.1 §7.3.9: an action declaration's
//! behavior members include `do`, `on`, fields and `keep`): one with a `do` runs it as an
//! invoked scenario does, one without inherits the meaning of the library action it inherits,
//! and one with neither is an error (`tests/scenarios/declared/*.osc`, worked by hand).

use crate::support::{error, run, stepped};

/// Speeds are closed forms the engine evaluates at step times.
const TOL: f64 = 1e-9;

fn phase(r: &crate::support::Run, path: &str, s: f64, e: f64) {
    let (a, b) = r.phase(path);
    assert!(
        (a - s).abs() < TOL && (b - e).abs() < TOL,
        "{path}: {a}-{b}, expected {s}-{e}"
    );
}

#[test]
fn a_declared_action_runs_its_do_or_the_library_action_it_inherits() {
    let r = run("declared/action_do", 0, None);
    let v = |t: f64| {
        if t <= 1.0 {
            20.0
        } else if t <= 7.0 {
            (20.0 - 2.0 * (t - 1.0)).max(10.0)
        } else {
            (10.0 - 5.0 * (t - 7.0)).max(5.0)
        }
    };
    for (t, want) in [
        (2.0, 18.0),
        (3.5, 15.0),
        (6.0, 10.0),
        (7.0, 10.0),
        (7.5, 7.5),
        (8.0, 5.0),
        (9.0, 5.0),
    ] {
        let got = r.at(t, "ego").speed;
        assert!((got - want).abs() < TOL, "v({t}) = {got}, expected {want}");
        assert!((v(t) - want).abs() < TOL, "hand v({t})");
    }
    // The action's do: its change_speed, then drive(duration: hold) with the keep's 1 s.
    phase(&r, "do.1", 1.0, 7.0);
    phase(&r, "do.1.0", 1.0, 6.0);
    phase(&r, "do.1.1", 6.0, 7.0);
    // brake: change_speed's end, the target reached.
    phase(&r, "do.2", 7.0, 8.0);
    phase(&r, "do.3", 8.0, 9.0);
    // By hand: 20 + 20 + 75 (the 5 s ramp at a mean 15 m/s) + 10 + 7.5 + 5 = 137.5 m at 9 s;
    // the step sum lags each fall by its Δv·dt/2 (10 and 5 m/s: 0.375 m).
    assert!((20.0 + stepped(v, 0.0, 9.0) - (137.5 - 0.375)).abs() < 1e-9);
    assert!((r.at(9.0, "ego").s - (20.0 + stepped(v, 0.0, 9.0))).abs() < 1e-6);
}

#[test]
fn a_declared_action_with_nothing_to_run_is_an_error_at_the_invocation() {
    let e = error("declared/err_action_no_body");
    assert!(e.contains("err_action_no_body.osc:13:9"), "{e}");
    assert!(
        e.starts_with("expected a `do` in `nothing`, an action the program declares without one and without a movement action of the standard library (§8.8) among its ancestors, found neither"),
        "{e}"
    );
    // Driving against s, the same refusal at the same place (issue 27: every §8.8 action and
    // §8.9 modifier runs against s, so this was the only form `against::check_runs` refused).
    let e = error("declared/err_action_no_body_against");
    assert!(e.contains("err_action_no_body_against.osc:20:9"), "{e}");
    assert!(
        e.starts_with("expected a `do` in `nothing`, an action the program declares without one and without a movement action of the standard library (§8.8) among its ancestors, found neither"),
        "{e}"
    );
}

#[test]
fn a_modifier_on_a_declared_action_with_a_do_is_an_error_at_the_modifier() {
    let e = error("declared/err_action_do_modifier");
    assert!(e.contains("err_action_do_modifier.osc:14:13"), "{e}");
    assert!(
        e.starts_with("expected `until` or `keep` in the with: of an invocation of `vehicle.cruise`, found the modifier `speed` (modifiers apply to the standard library's movement actions, not to a behavior that runs a `do` of its own)"),
        "{e}"
    );
}
