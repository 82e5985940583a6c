//! `on` handlers (ASAM OpenSCENARIO DSL 2.1 §7.3.10): `emit` in a handler makes the event occur
//! whenever the handler's event does; `call` is an error. Expectations in the scenario files.

use crate::support::run;

/// Event times are step times.
const T_TOL: f64 = 1e-9;

#[test]
fn on_handler_emits_an_event_others_wait_on() {
    let r = run("on_emit", 0, None);
    let (_, e) = r.phase("do.npc_part.0");
    assert!((e - 1.10).abs() < T_TOL, "until @quick ended at {e}");
    let (s, e) = r.phase("do.npc_part.1");
    assert!(
        (s - 1.10).abs() < T_TOL && (e - 2.10).abs() < T_TOL,
        "[{s}, {e}]"
    );
    assert!((r.at(1.10, "npc").s - 25.5).abs() < 1e-6);
    assert!((r.at(2.10, "npc").s - 25.5).abs() < 1e-6);
}

#[test]
fn call_or_every_in_a_handler_is_an_error() {
    crate::along::refused(
        "err_on_call",
        "expected `emit` in an `on` handler, found `call`",
        "8:9",
    );
    crate::along::refused(
        "err_on_every",
        "found every(…) (periodic events are not run yet)",
        "6:8",
    );
}
