//! What random traffic's actions after its creation ask where the plan cannot know where a
//! member is (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1, §8.9; plan/random_traffic_actions.rs):
//! `lane(n)` beside a later action on a road whose lanes are numbered otherwise along it.
//! Expectations in the scenario files.

use crate::random_traffic::on_lane_centre;
use crate::support::{lower_at, run_scenario};

#[test]
fn random_traffic_kept_to_a_lane_numbered_otherwise_along_the_road_changes_to_it_where_it_is() {
    // random_traffic_lane_renumbered.osc on lane_add.xodr, worked in the file; seeds 0-3.
    // Members by where they are at the phase start (1 s): +s before s = 300 m, +s from there
    // on, -s.
    let mut cases = [0; 3];
    let mut moved = 0;
    for seed in 0..4 {
        let lowered = lower_at(
            "tests/scenarios/random_traffic_lane_renumbered.osc",
            "tests/roads/lane_add.xodr",
            seed,
            None,
        )
        .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        let r = run_scenario(
            "random_traffic_lane_renumbered",
            &lowered.scenario,
            seed,
            None,
        );
        for i in 0..6 {
            let m = format!("g.vehicles[{i}]");
            let start = r.at(1.0, &m);
            // Lane 1 from the right of its direction where it is at 1 s (the file): -2 before
            // s = 300 m, -3 from there on, in -s lane 1.
            let (want, case) = if start.h.cos() < 0.0 {
                (1, 2)
            } else if start.s < 300.0 {
                (-2, 0)
            } else {
                (-3, 1)
            };
            cases[case] += 1;
            moved += usize::from(start.lane != want);
            // On that lane's centre from 12 s (7 m at 1 m/s peak: π·7/2 = 11.0 s after 1 s)
            // to the phase end at 13 s.
            on_lane_centre(&r, seed, &m, want, (12.0, 13.0));
        }
        let (s, e) = r.phase("do.right");
        assert!(
            (s - 1.0).abs() < 1e-9 && (e - 13.0).abs() < 1e-9,
            "[{s}, {e}]"
        );
    }
    // Each of the three numberings met by some member of the four seeds.
    assert!(cases.iter().all(|c| *c > 0), "{cases:?}");
    // Not all of them there already at 1 s: the lanes were changed (12 of 24 in these seeds).
    assert!(moved >= 6, "{moved} of 24 members changed lanes");
}

#[test]
fn a_lane_number_missing_where_a_member_may_be_is_an_error_at_the_modifier() {
    // err_random_traffic_lane_missing.osc on lane_add.xodr: no lane 3 from the right in +s
    // before s = 300 m (two driving lanes there).
    let e = lower_at(
        "tests/scenarios/err_random_traffic_lane_missing.osc",
        "tests/roads/lane_add.xodr",
        0,
        None,
    )
    .expect_err("lane 3 is missing before s = 300 m");
    let text = e.to_string();
    assert!(
        matches!(e.kind(), dsl_runtime::ErrorKind::Unsatisfiable)
            && text.contains(
                "expected a driving lane numbered 3 from the right all along the plan's roads"
            )
            && text.contains("found none 0.0 m along its direction of travel")
            && text.ends_with("err_random_traffic_lane_missing.osc:12:13"),
        "{text}"
    );
}
