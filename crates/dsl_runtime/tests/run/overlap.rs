//! `parallel(overlap: …)` (ASAM OpenSCENARIO DSL 2.1 §7.3.9 composition operators;
//! dsl_runtime::plan::overlap): when each member starts and ends under every kind, and the
//! kinds the plan cannot meet as errors at the argument. Expectations worked by hand in the
//! scenario files.

use crate::along::refused;
use crate::support::{phases_are, run};

/// Positions: float round-off on the straight road.
const S_TOL: f64 = 1e-6;

#[test]
fn every_overlap_kind_starts_and_ends_the_members_as_it_says() {
    let r = run("overlap_kinds", 0, None);
    phases_are(
        &r,
        &[
            ("do.p_start", 0.0, 3.0),
            ("do.p_start.a", 0.0, 3.0),
            ("do.p_start.b", 0.0, 1.0),
            // end: b (1 s) starts 4 − 1 = 3 s after the parallel, ending with a.
            ("do.p_end", 3.0, 7.0),
            ("do.p_end.a", 3.0, 7.0),
            ("do.p_end.b", 6.0, 7.0),
            // equal: b, with no end of its own, ends with a.
            ("do.p_equal", 7.0, 9.0),
            ("do.p_equal.a", 7.0, 9.0),
            ("do.p_equal.b", 7.0, 9.0),
            ("do.p_initial", 9.0, 11.0),
            ("do.p_initial.b", 9.0, 10.0),
            ("do.p_final", 11.0, 13.0),
            ("do.p_final.a", 11.0, 13.0),
            ("do.p_final.b", 11.0, 12.0),
            ("do.p_inside", 13.0, 15.0),
            ("do.p_inside.b", 13.0, 14.0),
            ("do.p_full", 15.0, 17.0),
            ("do.p_full.a", 15.0, 16.0),
            ("do.p_full.b", 15.0, 17.0),
            ("do.p_any", 17.0, 18.0),
            ("do.p_any.b", 17.0, 18.0),
            // end within the parallel's own 3 s: a (1 s) starts 2 s after it.
            ("do.p_end_own", 18.0, 21.0),
            ("do.p_end_own.a", 20.0, 21.0),
            ("do.p_end_own.b", 18.0, 21.0),
        ],
    );
    for (t, ego, npc) in [
        (3.0, 130.0, 190.0),
        (6.0, 175.0, 250.0),
        (7.0, 190.0, 275.0),
        (21.0, 400.0, 625.0),
    ] {
        assert!((r.at(t, "ego").s - ego).abs() < S_TOL, "ego at {t} s");
        assert!((r.at(t, "npc").s - npc).abs() < S_TOL, "npc at {t} s");
    }
}

#[test]
fn overlaps_the_plan_cannot_meet_are_errors_at_the_argument() {
    refused(
        "err_overlap_equal",
        "expected the members of this parallel to end together (overlap: equal), found `do.0.a` lasts 2.000 s (to 2.000 s) and `do.0.b` 3.000 s (to 3.000 s)",
        "7:27",
    );
    refused(
        "err_overlap_equal_own",
        "expected every member of this parallel to end with it (overlap: equal), found `do.0.a` lasts 2.000 s where the parallel lasts 3.000 s",
        "7:41",
    );
    refused(
        "err_overlap_final",
        "expected `do.0.b` to end no later than the first member `do.0.a` (overlap: final), found `do.0.b` lasts 2.000 s (to 2.000 s) and `do.0.a` 1.000 s (to 1.000 s)",
        "7:27",
    );
    refused(
        "err_overlap_full",
        "expected the first member `do.0.a` to end no later than `do.0.b` (overlap: full), found `do.0.b` lasts 1.000 s (to 1.000 s) and `do.0.a` 2.000 s (to 2.000 s)",
        "7:27",
    );
    refused(
        "err_overlap_end_long",
        "expected the members of this parallel to end together (overlap: end) within its 2.000 s, found `do.0.a` lasts 3.000 s",
        "7:41",
    );
    refused(
        "err_overlap_runtime",
        "expected ends the plan knows under overlap: equal, found `do.0.b` ends at run time beside `do.0.a`",
        "7:27",
    );
    refused(
        "err_overlap_kind",
        "expected one of equal, start, end, initial, final, inside, full, any in overlap:, found `sideways`",
        "6:27",
    );
    refused(
        "err_overlap_serial",
        "expected a `duration:` (`overlap:` is parallel's) argument, found `overlap:`",
        "4:24",
    );
}
