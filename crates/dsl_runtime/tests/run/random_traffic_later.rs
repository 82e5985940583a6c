//! What random traffic's actions after its creation ask where the plan cannot know where a
//! member is (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1, §8.9; plan/random_traffic_actions.rs):
//! `lane(n)` beside a later action on a road whose lanes are numbered otherwise along it; and
//! relations to a member of random traffic from a group (plan/random_traffic_relations.rs).
//! Expectations in the scenario files.

use crate::random_traffic::{on_lane_centre, speed_follows_member};
use crate::support::{lower_at, run, run_scenario, DT};

/// Positions of actors driving their plan on a straight road: float round-off only (m).
const S_TOL: f64 = 1e-6;

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

#[test]
fn a_group_related_to_a_member_in_its_first_phase_is_placed_from_the_drawn_member() {
    // random_traffic_member_convoy.osc, worked in the file; seeds 0-3.
    let m = "g.vehicles[0]";
    for seed in 0..4 {
        let r = run("random_traffic_member_convoy", seed, None);
        let (s_m, v_m) = (r.at(0.0, m).s, r.at(0.0, m).speed);
        assert_eq!(r.at(0.0, m).lane, -2, "seed {seed}");
        for (i, back) in [(0, 40.0), (1, 54.0)] {
            let c = format!("convoy.vehicles[{i}]");
            for (t, objs) in &r.frames {
                let o = objs.iter().find(|o| o.name == c).expect("in every frame");
                let s = s_m - back + v_m * t;
                assert!(
                    o.lane == -2 && (o.s - s).abs() < S_TOL && (o.speed - v_m).abs() < S_TOL,
                    "seed {seed} {c} at {t}: {o:?}, want s = {s}, v = {v_m}"
                );
            }
        }
        for i in 0..2 {
            let c = format!("column.vehicles[{i}]");
            assert!((r.at(0.0, &c).speed - v_m).abs() < S_TOL, "seed {seed} {c}");
            speed_follows_member(&r, &c, m, seed);
        }
    }
}

#[test]
fn random_traffic_related_to_a_member_of_other_random_traffic_reads_where_it_is() {
    // random_traffic_member_groups.osc, worked in the file; seeds 0-3.
    for seed in 0..4 {
        let r = run("random_traffic_member_groups", seed, None);
        assert_eq!(r.at(0.0, "g.vehicles[0]").lane, -2, "seed {seed}");
        for i in 0..3 {
            let h = format!("h.vehicles[{i}]");
            assert!(r.at(0.0, &h).h.cos() > 0.0, "seed {seed} {h}: +s");
            on_lane_centre(&r, seed, &h, -2, (0.0, 12.0));
            let k = format!("k.vehicles[{i}]");
            assert_eq!(r.at(1.0, &k).lane, -3, "seed {seed} {k}");
            // Its model (the `idm`: created with lane(1) at: all) is handed lane -2, where the
            // engine reads g.vehicles[0] at 1 s, as its mandatory lane.
            let notes: Vec<_> = r
                .controllers
                .iter()
                .filter(|(t, e, n)| *e == k && (t - 1.0).abs() < 1e-9 && n.contains("mandatory"))
                .collect();
            assert!(
                notes.len() == 1
                    && notes[0].2.ends_with("handed to the controller: mandatory lane -2: changes lane by lane into gaps MOBIL's safety criterion accepts, then keeps it"),
                "seed {seed} {k}: {notes:?}"
            );
            // Between the two lanes' centres at every step, off lane -3's only from the step
            // at 1 s; a change started by 7 s (4.58 s for the cubic at constant speed, longer
            // where the IDM slows behind the nearer leader) ends on lane -2's centre by 12 s.
            let mut started = None;
            for (t, _) in &r.frames {
                let o = r.at(*t, &k);
                assert!(
                    o.y >= -8.75 - 1e-6 && o.y <= -5.25 + 1e-6,
                    "seed {seed} {k} at {t}: {o:?}"
                );
                if started.is_none() && (o.y + 8.75).abs() > 1e-9 {
                    started = Some(t - DT);
                }
            }
            if started.is_some_and(|t| t <= 7.0) {
                on_lane_centre(&r, seed, &k, -2, (12.0, 12.0));
            }
        }
        // No two boxes touch: each change waited for a gap MOBIL's safety criterion accepts.
        let found = crate::random_traffic::touching(&r);
        assert!(found.is_empty(), "seed {seed}: {found:?}");
    }
}

/// Issue 27 follow-up: a mandatory change no longer waits for ever behind a new follower at
/// about its own speed (engine controller/mobil.rs `GAP_OPENING_TIME`).
/// random_traffic_member_groups.osc, seed 1, k.vehicles[2] (4.489 m long, as h's members):
/// handed lane −2 at 1 s at v = 20.792 m/s in lane −3; h.vehicles[2] in lane −2, its reference
/// point 7.82 m back (bumpers 3.33 m apart), at v_n = 20.039 m/s. As a new follower it would
/// need (IDM at the changer's parameters, v0 = 20 m/s) s* = 2 + 20.039·1.6 +
/// 20.039·(20.039 − 20.792)/2.208257 = 27.229 m and g* = s*·√(0.73/(4 + 0.73(1 −
/// (20.039/20)⁴))) = 27.229·0.42751 = 11.64 m, which the 0.753 m/s speed advantage opens in
/// (11.64 − 3.33)/0.753 = 11.0 s > 4.58 s: before, k.vehicles[2] kept lane −3 to the end (the
/// advantage fading as both near 20 m/s). Now it falls back at b = 1.67 m/s² from the step at
/// 1 s (its IDM near v0 asks for −0.12): v(t) = 20.792 − 1.67(t − 1) at every step while it
/// waits. h.vehicles[2] (≈ 20.02 m/s) passes it; the change is safe once h's rear is g ahead
/// of its front with ã_c = a(1 − (v/v0)⁴) − a(s0/g)² ≥ −b_safe (the dynamic part of s*
/// negative behind the faster h): at v = 13.36 m/s, 0.5846 − 0.73(2/g)² ≥ −4, g ≥
/// 2/√(4.5846/0.73) = 0.798 m, reference points 4.489 + 0.798 = 5.287 m apart: 7.82 + 0.753τ
/// − 0.835τ² = −5.287 at τ = 4.44 s, t = 5.44 s, so the change starts in the step from 5.45 s
/// (the frames: gap 0.497 m at 5.40 s, 0.828 m at 5.45 s) and ends on lane −2's centre by
/// 12 s (4.58 s at constant speed).
#[test]
fn a_mandatory_change_behind_a_new_follower_at_its_own_speed_falls_back_and_lets_it_past() {
    let r = run("random_traffic_member_groups", 1, None);
    let k = "k.vehicles[2]";
    let v1 = r.at(1.0, k).speed;
    assert!((v1 - 20.792).abs() < 1e-3, "{v1}");
    assert_eq!(r.at(1.0, "h.vehicles[2]").lane, -2);
    for (t, _) in r
        .frames
        .iter()
        .filter(|(t, _)| *t > 1.0 + 1e-9 && *t < 5.45 + 1e-9)
    {
        let o = r.at(*t, k);
        assert_eq!(o.y, -8.75, "{k} waits in lane -3 at {t}: {o:?}");
        let v = v1 - 1.67 * (t - 1.0);
        assert!(
            (o.speed - v).abs() < 1e-9,
            "{k} at {t}: {} want {v}",
            o.speed
        );
    }
    assert!(r.at(5.5, k).y > -8.75 + 1e-6, "{:?}", r.at(5.5, k));
    on_lane_centre(&r, 1, k, -2, (12.0, 12.0));
    let found = crate::random_traffic::touching(&r);
    assert!(found.is_empty(), "{found:?}");
}

#[test]
fn random_traffic_beside_a_member_not_drawn_yet_or_at_a_members_speed_is_bad_input() {
    for (name, words, at, modifier) in [
        (
            "err_random_traffic_beside_later_group",
            "found it a member of random traffic `h`, dealt after `g` (the groups are dealt in the order of their names)",
            "11:13",
            false,
        ),
        (
            "err_random_traffic_beside_own_member",
            "found it a member of that group (dealt beside itself)",
            "8:13",
            false,
        ),
        (
            "err_random_traffic_speed_of_member",
            "found `speed(…)`",
            "13:13",
            true,
        ),
    ] {
        crate::along::refused(name, words, at);
        let e = crate::support::lower(name, 0, None).expect_err(name);
        let kind = if modifier {
            matches!(e.kind(), dsl_runtime::ErrorKind::Modifier)
        } else {
            matches!(e.kind(), dsl_runtime::ErrorKind::Unsatisfiable)
        };
        assert!(kind, "{name}: {e}");
    }
}

#[test]
fn a_group_phase_first_of_some_members_only_places_those_from_the_drawn_member() {
    // random_traffic_member_mixed_first.osc, worked in the file; seeds 0-3.
    let m = "g.vehicles[0]";
    let mut apart = 0.0_f64;
    for seed in 0..4 {
        let r = run("random_traffic_member_mixed_first", seed, None);
        let (m0, v1) = (r.at(0.0, m).clone(), r.at(1.0, m).speed);
        apart = apart.max((v1 - m0.speed).abs());
        assert_eq!(m0.lane, -2, "seed {seed}");
        // The member keeps v1 from 1 s (keep_speed()).
        assert!((r.at(5.0, m).speed - v1).abs() < 1e-9, "seed {seed}");
        let s0_1 = m0.s - 60.0 + m0.speed;
        for (t, objs) in &r.frames {
            let at = |c: &str| objs.iter().find(|o| o.name == c).expect("in every frame");
            // vehicles[1]: its first phase from 1 s; placed from the member as drawn, 14 m
            // behind vehicles[0] as placed, at v_m(0) to 5 s.
            let o = at("convoy.vehicles[1]");
            if *t <= 5.0 + 1e-9 {
                let s = m0.s - 74.0 + m0.speed * t;
                assert!(
                    o.lane == -2 && (o.s - s).abs() < S_TOL && (o.speed - m0.speed).abs() < S_TOL,
                    "seed {seed} vehicles[1] at {t}: {o:?}, want s = {s}, v = {}",
                    m0.speed
                );
            }
            // vehicles[0]: placed from the member as drawn to 1 s; then the member's speed as
            // the engine reads it at 1 s, v1, to 5 s.
            let o = at("convoy.vehicles[0]");
            let (s, v) = if *t <= 1.0 + 1e-9 {
                (m0.s - 60.0 + m0.speed * t, m0.speed)
            } else if *t <= 5.0 + 1e-9 {
                (s0_1 + v1 * (t - 1.0), v1)
            } else {
                continue;
            };
            assert!(
                o.lane == -2 && (o.s - s).abs() < S_TOL && (o.speed - v).abs() < S_TOL,
                "seed {seed} vehicles[0] at {t}: {o:?}, want s = {s}, v = {v}"
            );
        }
        // The engine's lane check at 1 s held: `run` fails the test on a failed run.
    }
    // The two speeds differ (the member's model moved it to its desired 20 m/s in its first
    // second), so the test tells the members' two forms apart.
    assert!(apart > 0.1, "v1 - v_m(0) at most {apart} m/s");
}

#[test]
fn a_members_own_place_speed_or_acceleration_relative_to_another_member_is_bad_input_at_the_modifier(
) {
    // §8.7.18.1: "the behavioral model assigned to each vehicle defines the actual behavior of
    // the vehicle within the group": a member's lane, place, speed and acceleration among the
    // members are its model's, on every seed. Before, the speed ran and the acceleration was
    // ignored by the engine (the scenarios' comments).
    for (name, what, at) in [
        (
            "err_random_traffic_member_own_place",
            "expected no place of `g.vehicles[0]`, a member of random traffic, relative to `g.vehicles[1]`, found `position(…)`",
            "15:13",
        ),
        (
            "err_random_traffic_member_own_lane",
            "expected no place of `g.vehicles[0]`, a member of random traffic, relative to `g.vehicles[1]`, found `lane(…)`",
            "12:13",
        ),
        (
            "err_random_traffic_member_own_speed",
            "expected no speed of `g.vehicles[0]`, a member of random traffic, relative to `g.vehicles[1]`, found `speed(…)`",
            "23:17",
        ),
        (
            "err_random_traffic_member_own_acceleration",
            "expected no acceleration of `g.vehicles[0]`, a member of random traffic, relative to `g.vehicles[1]`, found `acceleration(…)`",
            "23:17",
        ),
    ] {
        refused_on_every_seed(name, (what, at), |e| {
            matches!(e.kind(), dsl_runtime::ErrorKind::Unsatisfiable)
                && e.to_string().contains("(§8.7.18.1)")
        });
    }
}

/// `name` refused with `what` at `at` (`along::refused`), and on seeds 0-3 with an error
/// `holds` accepts: a member's draw must not change the refusal.
fn refused_on_every_seed(
    name: &str,
    (what, at): (&str, &str),
    holds: impl Fn(&dsl_runtime::Error) -> bool,
) {
    crate::along::refused(name, what, at);
    for seed in 0..4 {
        let e = crate::support::lower(name, seed, None).expect_err(name);
        assert!(holds(&e), "{name} seed {seed}: {e}");
    }
}

/// Runs `name` with seeds 0-3 and checks `g.vehicles[0]`'s speed at each (time, speed) of
/// `want` within 1e-9 m/s (hand-computed numbers of piecewise constant accelerations: float
/// round-off only); returns the runs by seed.
fn member_speeds(name: &str, want: &[(f64, f64)]) -> Vec<crate::support::Run> {
    (0..4)
        .map(|seed| {
            let r = run(name, seed, None);
            for &(t, v) in want {
                let got = r.at(t, "g.vehicles[0]").speed;
                assert!(
                    (got - v).abs() < 1e-9,
                    "{name} seed {seed} at {t} s: {got} m/s, not {v}"
                );
            }
            r
        })
        .collect()
}

/// The controller records of member `m`'s free-road acceleration (time to 0.01 s, note), and
/// their times.
fn free_road_notes(r: &crate::support::Run, m: &str) -> (Vec<(String, String)>, Vec<String>) {
    let notes: Vec<_> = r
        .controllers
        .iter()
        .filter(|(_, who, note)| who == m && note.contains("free-road acceleration"))
        .map(|(t, _, note)| (format!("{t:.2}"), note.clone()))
        .collect();
    let at = notes.iter().map(|(t, _)| t.clone()).collect();
    (notes, at)
}

#[test]
fn a_members_own_acceleration_after_a_run_time_condition_is_its_models_free_road_acceleration() {
    // random_traffic_member_own_acceleration.osc, worked in the file (before, refused as not
    // run yet at 23:17): one member standing with v0 = 0 and no leader in its lane (the IDM's
    // interaction term 0); 2 m/s² handed to its model over 3.05-5.05 s, its own term (−b =
    // −1.67 m/s²) to 6.05 s, ego's acceleration read at every step (1 m/s²) plus 0.5 over
    // 6.05-8.05 s, its own term again to 10 s. Seeds 0-3: the member's place and direction
    // are drawn, its speeds are not.
    let m = "g.vehicles[0]";
    let want = [
        (3.0, 0.0),
        (3.05, 0.0),
        (4.05, 2.0),
        (5.05, 4.0),
        (6.05, 2.33),
        (7.05, 3.83),
        (8.05, 5.33),
        (10.0, 2.0735),
    ];
    let runs = member_speeds("random_traffic_member_own_acceleration", &want);
    for (seed, r) in runs.iter().enumerate() {
        // Ego's ramp, which the second phase reads: v_e = 10 + t.
        let ego = r.at(6.05, "ego").speed;
        assert!((ego - 16.05).abs() < 1e-9, "seed {seed}: ego {ego}");
        // Distance over the first phase: ½·2·2² = 4 m along the member's lane.
        let ds = (r.at(5.05, m).s - r.at(3.05, m).s).abs();
        assert!((ds - 4.0).abs() < 1e-9, "seed {seed}: {ds} m");
        // The hand-offs and releases, at the phase starts and ends.
        let (notes, at) = free_road_notes(r, m);
        assert_eq!(
            at,
            ["3.05", "5.05", "6.05", "8.05"],
            "seed {seed}: {notes:?}"
        );
        assert!(
            notes[0].1.contains("free-road acceleration 2 m/s²")
                && notes[1].1.contains("released")
                && notes[2].1.contains("plus 0.5 m/s²")
                && notes[3].1.contains("released"),
            "seed {seed}: {notes:?}"
        );
    }
}

#[test]
fn a_members_own_acceleration_as_the_rate_of_its_speed_change_is_its_models_rate_toward_the_speed()
{
    // random_traffic_member_own_acceleration_rate.osc, worked in the file (before, refused as
    // not run yet at 24:17): one member standing with v0 = 0 and no leader in its lane (the
    // IDM's interaction term 0). speed(5.45mps, at: end) at 2 m/s² from 3.05 s: 2.70 m/s at the
    // mid-point 4.40 s, 5.40 at 5.75, the last step cut to 1 m/s²: 5.45 at 5.80 (not 5.50),
    // held at 7.05 (phase end) and 8.05; change_speed(2mps) at ego's 1 m/s² plus 0.6 from
    // 8.05 s: 3.77 at 9.10, 2.01 at 10.20, cut to −0.2 m/s²: 2.00 at 10.25, held to 11.05
    // (phase end) and 14 s (the model keeps the speed it was handed). Seeds 0-3: the member's
    // place and direction are drawn, its speeds are not.
    let m = "g.vehicles[0]";
    let want = [
        (3.05, 0.0),
        (4.4, 2.7),
        (5.75, 5.4),
        (5.8, 5.45),
        (7.05, 5.45),
        (8.05, 5.45),
        (9.1, 3.77),
        (10.2, 2.01),
        (10.25, 2.0),
        (11.05, 2.0),
        (14.0, 2.0),
    ];
    let runs = member_speeds("random_traffic_member_own_acceleration_rate", &want);
    for (seed, r) in runs.iter().enumerate() {
        // Distance over the change: ½·2·2.7² + ½·(5.40 + 5.45)·0.05 = 7.56125 m.
        let ds = (r.at(5.8, m).s - r.at(3.05, m).s).abs();
        assert!((ds - 7.56125).abs() < 1e-9, "seed {seed}: {ds} m");
        // Never past the target in either change (the cut step), at every step.
        for (t, objs) in &r.frames {
            let v = objs.iter().find(|o| o.name == m).map_or(0.0, |o| o.speed);
            let over = (*t < 8.0 && v > 5.45 + 1e-9) || (*t > 8.0 && v < 2.0 - 1e-9);
            assert!(!over, "seed {seed} at {t}: {v} m/s");
        }
        // The hand-offs at the phase starts, no release at their ends.
        let (notes, at) = free_road_notes(r, m);
        assert_eq!(at, ["3.05", "8.05"], "seed {seed}: {notes:?}");
        assert!(
            notes[0]
                .1
                .contains("desired speed 5.45 m/s, reached at a free-road acceleration of 2 m/s²")
                && notes[1].1.contains("desired speed 2 m/s")
                && notes[1].1.contains("plus 0.6 m/s²"),
            "seed {seed}: {notes:?}"
        );
    }
}

#[test]
fn a_members_own_acceleration_beside_keep_speed_or_remain_stationary_is_bad_input_as_for_any_actor()
{
    // Before, refused as not run yet. Now the check every actor's phase gets (plan/checks.rs
    // check_keeps), run before the member's refusal: the same kind and message as for an
    // ordinary vehicle, at the acceleration modifier (21:17), naming the action (20:13), on
    // every seed.
    for (name, what) in [
        (
            "err_random_traffic_member_own_acceleration_keep",
            "expected no speed change beside keep_speed() at ",
        ),
        (
            "err_random_traffic_member_own_acceleration_stationary",
            "expected no movement beside remain_stationary() at ",
        ),
    ] {
        let action = format!("{name}.osc:20:13, found `acceleration(…)` at ");
        refused_on_every_seed(name, (what, "21:17"), |e| {
            matches!(e.kind(), dsl_runtime::ErrorKind::Unsatisfiable)
                && e.to_string().contains(&action)
        });
    }
}

#[test]
fn a_members_own_timed_trajectory_is_bad_input_naming_its_model() {
    // A member's own follow_trajectory(…): its times would set the speed its model sets
    // (§8.7.18.1, quoted in the message), and the model takes no trajectory (before, the engine
    // ignored it): an error at the invocation (29:13) before the run, on every seed.
    let what = "expected no follow_trajectory(…) of `g.vehicles[0]`, a member of random traffic: its trajectory's times would set the speed its driver model sets";
    refused_on_every_seed(
        "err_random_traffic_member_own_trajectory",
        (what, "29:13"),
        |e| {
            matches!(e.kind(), dsl_runtime::ErrorKind::Unsatisfiable)
                && e.to_string().contains("(§8.7.18.1: ")
        },
    );
}

#[test]
fn a_members_own_acceleration_toward_a_speed_relative_to_another_actor_is_its_models_rate_toward_it(
) {
    // random_traffic_member_own_acceleration_relative.osc, worked in the file (before, refused
    // as not run yet at 20:17): one member standing with v0 = 0 and no leader in its lane; ego
    // at 10 m/s throughout. speed(2.05mps, faster_than: ego, at: end) at 2 m/s² over
    // 3.05-10.05 s: 7.00 m/s at the mid-point 6.55 s, 12.00 at 9.05, the last step cut to
    // 1 m/s²: 12.05 at 9.10 (not 12.10), held to the phase end (10.05 s) and, released, to
    // 14 s; 48.04875 m travelled over the phase.
    let m = "g.vehicles[0]";
    let want = [
        (3.05, 0.0),
        (6.55, 7.0),
        (9.05, 12.0),
        (9.1, 12.05),
        (10.05, 12.05),
        (14.0, 12.05),
    ];
    let runs = member_speeds("random_traffic_member_own_acceleration_relative", &want);
    for (seed, r) in runs.iter().enumerate() {
        let ego = r.at(6.55, "ego").speed;
        assert!((ego - 10.0).abs() < 1e-9, "seed {seed}: ego {ego}");
        let ds = (r.at(10.05, m).s - r.at(3.05, m).s).abs();
        assert!((ds - 48.04875).abs() < 1e-9, "seed {seed}: {ds} m");
        // Never past the target at any step (the cut step).
        for (t, objs) in &r.frames {
            let v = objs.iter().find(|o| o.name == m).map_or(0.0, |o| o.speed);
            assert!(v <= 12.05 + 1e-9, "seed {seed} at {t}: {v} m/s");
        }
        // The hand-off at the phase start, its release at the end.
        let (notes, at) = free_road_notes(r, m);
        assert_eq!(at, ["3.05", "10.05"], "seed {seed}: {notes:?}");
        assert!(
            notes[0]
                .1
                .contains("desired speed: the reference's at each step plus 2.05 m/s, followed at a free-road acceleration of 2 m/s²")
                && notes[1].1.contains("released"),
            "seed {seed}: {notes:?}"
        );
    }
}

#[test]
fn a_members_own_acceleration_beside_a_path_or_position_action_is_its_models_free_road_acceleration(
) {
    // random_traffic_member_own_acceleration_path.osc, worked in the file (before, refused as
    // not run yet at the modifier): one member standing with v0 = 0 (its model `mobil`), no
    // leader in its lane. replay_path(q0 -> q1) with 2 m/s² over 3.05-5.05 s: at q0 in the
    // frame of 3.10 s, 0.1 m/s; 2.0 m/s and 0.95 m along the path at 4.05 s; 4.0 m/s and 3.9 m
    // at 5.05 s; released, −1.67 m/s²: 2.4135 m/s at 6.0 s, standing from 7.45 s.
    // assign_position(s = 900 m, lane −2) with 2 m/s² from 8.05 s: there at 0.1 m/s at 8.10 s,
    // 0.0165 m/s at 8.15 s, standing at 8.20 s. Seeds 0-3: the member's first place is drawn,
    // the path's and the teleport's are not.
    let m = "g.vehicles[0]";
    let want = [
        (3.05, 0.0),
        (3.1, 0.1),
        (4.05, 2.0),
        (5.05, 4.0),
        (6.0, 2.4135),
        (7.4, 0.0755),
        (7.45, 0.0),
        (8.05, 0.0),
        (8.1, 0.1),
        (8.15, 0.0165),
        (8.2, 0.0),
    ];
    let runs = member_speeds("random_traffic_member_own_acceleration_path", &want);
    let (h, (ux, uy)) = (
        (3.5f64 / 80.0).atan(),
        (80.0 / 80.076_525_898_667_71, 3.5 / 80.076_525_898_667_71),
    );
    for (seed, r) in runs.iter().enumerate() {
        // On the path (the default controller's, not the model's lane): d along it from q0.
        for (t, d) in [(3.1, 0.0), (4.05, 0.95), (5.05, 3.9)] {
            let o = r.at(t, m);
            let (x, y) = (400.0 + d * ux, -5.25 + d * uy);
            assert!(
                (o.x - x).abs() < 1e-6 && (o.y - y).abs() < 1e-6 && (o.h - h).abs() < 1e-9,
                "seed {seed} at {t}: ({}, {}, {}), not ({x}, {y}, {h})",
                o.x,
                o.y,
                o.h
            );
        }
        let o = r.at(8.1, m);
        assert!(
            (o.x - 900.0).abs() < 1e-6 && (o.y + 5.25).abs() < 1e-6,
            "seed {seed}: {o:?}"
        );
        // The lateral domain taken from the model and given back at the path's phase; the
        // free-road acceleration handed and released at each phase's start and end; the path
        // never handed to the model (ignored).
        let notes = |t: f64, what: &str| {
            r.controllers
                .iter()
                .filter(|(at, who, note)| who == m && (at - t).abs() < 1e-9 && note.contains(what))
                .count()
        };
        assert!(
            notes(3.05, "activation changed") == 1 && notes(5.05, "activation changed") == 1,
            "seed {seed}: {:?}",
            r.controllers
        );
        let (all, at) = free_road_notes(r, m);
        assert_eq!(at, ["3.05", "5.05", "8.05", "8.10"], "seed {seed}: {all:?}");
        assert!(
            r.controllers
                .iter()
                .all(|(_, _, note)| !note.contains("ignored")),
            "seed {seed}: {:?}",
            r.controllers
        );
    }
}

#[test]
fn a_members_own_acceleration_beside_its_own_lane_action_is_its_models_free_road_acceleration() {
    // random_traffic_member_own_acceleration_lane.osc, worked in the file (before, refused as
    // not run yet at the modifier): one member standing with v0 = 0 and no leader in its lane
    // before or after its change (the IDM's interaction term 0). follow_lane() with 2 m/s²
    // over 3.05-5.05 s: 2.00 m/s at 4.05, 4.00 at 5.05, 4 m along its lane; its own term
    // (−b = −1.67 m/s²) to 6.05 s: 2.33; change_lane(1, right) with 1 m/s² over 6.05-8.05 s:
    // 3.33 at 7.05, 4.33 at 8.05, in the lane to the right of its own; released, −1.67 m/s²:
    // 4.33 − 1.67·1.95 = 1.0735 at 10 s. Seeds 0-3: the member's place and direction are
    // drawn, its speeds are not.
    let m = "g.vehicles[0]";
    let want = [
        (3.05, 0.0),
        (4.05, 2.0),
        (5.05, 4.0),
        (6.05, 2.33),
        (7.05, 3.33),
        (8.05, 4.33),
        (10.0, 1.0735),
    ];
    let runs = member_speeds("random_traffic_member_own_acceleration_lane", &want);
    for (seed, r) in runs.iter().enumerate() {
        // follow_lane(): ½·2·2² = 4 m along the lane it keeps.
        let (a, b) = (r.at(3.05, m), r.at(5.05, m));
        assert!(((b.s - a.s).abs() - 4.0).abs() < 1e-9, "seed {seed}");
        assert_eq!(a.lane, b.lane, "seed {seed}");
        // change_lane(1, right): lane(2) of its direction is −2 in +s, 1 against s; the lane
        // to its right −3 or 2, reached by 8.05 s and kept.
        let to = match a.lane {
            -2 => -3,
            1 => 2,
            l => panic!("seed {seed}: lane {l}"),
        };
        for t in [8.05, 10.0] {
            assert_eq!(r.at(t, m).lane, to, "seed {seed} at {t}");
        }
        // The hand-offs and releases at the phase starts and ends.
        let (notes, at) = free_road_notes(r, m);
        assert_eq!(
            at,
            ["3.05", "5.05", "6.05", "8.05"],
            "seed {seed}: {notes:?}"
        );
    }
}

#[test]
fn a_members_own_phase_at_a_known_time_is_bad_input_naming_its_model() {
    // §8.7.18.1 (quoted in the message): a member's motion is its model's from its creation,
    // so a phase of its own at 0 s has no place of it to start from, on every seed; the
    // message names that, not a gap action the scenario does not have.
    let name = "err_random_traffic_member_own_phase";
    let what = "expected this phase of `g.vehicles[0]` of random traffic to start on a run-time condition (until, wait), found it at 0.00 s";
    refused_on_every_seed(name, (what, "14:9"), |e| {
        let text = e.to_string();
        matches!(e.kind(), dsl_runtime::ErrorKind::Unsatisfiable)
            && text.contains("(§8.7.18.1: ")
            && !text.contains("gap action")
    });
}

#[test]
fn a_column_beside_an_actor_or_a_member_keeps_its_formation_in_one_lane() {
    // group_lateral_beside.osc, worked in the file; seeds 0-3: both columns' members at
    // y = -2.25 m (lane -1) and -8.25 m (lane -3), 14 m apart, at 0, 2 and 4 s.
    for seed in 0..4 {
        let r = run("group_lateral_beside", seed, None);
        assert_eq!(r.at(0.0, "g.vehicles[0]").lane, -2, "seed {seed}");
        for (group, lane, y) in [("left", -1, -2.25), ("right", -3, -8.25)] {
            for t in [0.0, 2.0, 4.0] {
                let (a, b) = (
                    r.at(t, &format!("{group}.vehicles[0]")),
                    r.at(t, &format!("{group}.vehicles[1]")),
                );
                assert!(
                    a.lane == lane
                        && b.lane == lane
                        && (a.y - y).abs() < S_TOL
                        && (b.y - y).abs() < S_TOL
                        && (a.s - b.s - 14.0).abs() < S_TOL,
                    "seed {seed} {group} at {t}: {a:?} {b:?}"
                );
            }
        }
    }
}

#[test]
fn a_members_own_speed_relative_to_an_actor_outside_its_group_runs() {
    // Not a relation within the group (§8.7.18.1), unlike err_random_traffic_member_own_speed:
    // the wait on `go` (emitted at 3 s) ends in the step ending at 3.05 s, and the member's
    // model takes ego's speed then, 10 m/s from the start, as its desired speed.
    let name = "random_traffic_member_own_speed_of_actor";
    for seed in 0..4 {
        let r = run(name, seed, None);
        let handed: Vec<_> = r
            .controllers
            .iter()
            .filter(|(_, who, note)| who == "g.vehicles[0]" && note.contains("desired speed"))
            .collect();
        assert!(
            handed.len() == 1
                && (handed[0].0 - 3.05).abs() < 1e-9
                && handed[0].2.ends_with("desired speed 10 m/s"),
            "seed {seed}: {handed:?}"
        );
    }
}

#[test]
fn a_members_own_acceleration_of_another_actor_is_read_once_at_start_or_at_every_step() {
    // random_traffic_member_own_acceleration_held.osc, worked in the file; seeds 0-3: ego's
    // 1 m/s² at 3.05 s held over 3.05-7.05 s although ego's turns to −1 at 5 s; −1.67 m/s²
    // (its own term) to 8.05 s; ego's −1 less 0.5 from 8.05 s to a stand at 9.603 s.
    let want = [
        (3.05, 0.0),
        (5.05, 2.0),
        (7.05, 4.0),
        (8.05, 2.33),
        (9.05, 0.83),
        (10.05, 0.0),
        (12.0, 0.0),
    ];
    let runs = member_speeds("random_traffic_member_own_acceleration_held", &want);
    for (seed, r) in runs.iter().enumerate() {
        // Ego's ramps, which the phases read: 15 m/s at 5 s, 12 m/s at 8 s.
        for (t, v) in [(5.0, 15.0), (8.0, 12.0)] {
            let got = r.at(t, "ego").speed;
            assert!((got - v).abs() < 1e-9, "seed {seed}: ego {got} at {t} s");
        }
    }
}

#[test]
fn a_members_own_acceleration_is_braked_by_its_models_interaction_term_behind_a_leader() {
    // random_traffic_member_own_acceleration_leader.osc, worked in the file; seeds 0-3: the
    // first step at 2 − 0.73·(2/g0)², below 4 m/s at 4.05 s (6 m/s without the braking),
    // never nearer than s0·√(0.73/2) = 1.2083 m, standing at the end.
    let name = "random_traffic_member_own_acceleration_leader";
    let (m, x) = ("g.vehicles[0]", "ego");
    // The gap between the member's front and ego's rear along the member's way.
    let gap = |objs: &(f64, Vec<crate::support::Obj>)| {
        let find = |n: &str| objs.1.iter().find(|o| o.name == n).expect("in the frame");
        let (a, b) = (find(m), find(x));
        let (ba, bb) = (&a.object.bounding_box, &b.object.bounding_box);
        (b.s - a.s).abs() + bb.center().x - ba.center().x - (ba.length() + bb.length()) / 2.0
    };
    let standing = 2.0 * (0.73f64 / 2.0).sqrt();
    for seed in 0..4 {
        let r = run(name, seed, None);
        let g0 = gap(&r.frames[21]);
        assert!((r.frames[21].0 - 1.05).abs() < 1e-9);
        let a = 2.0 - 0.73 * (2.0 / g0).powi(2);
        let v = r.at(1.10, m).speed;
        assert!(
            (v - a * DT).abs() < 1e-9,
            "seed {seed}: {v} m/s, not {}",
            a * DT
        );
        assert!(a < 2.0 - 0.005, "seed {seed}: interaction {}", 2.0 - a);
        let v4 = r.at(4.05, m).speed;
        assert!(v4 > 2.0 && v4 < 4.0, "seed {seed}: {v4} m/s at 4.05 s");
        let nearest = r.frames.iter().map(gap).fold(f64::INFINITY, f64::min);
        assert!(
            nearest >= standing && nearest < standing + 0.05,
            "seed {seed}: nearest {nearest} m"
        );
        assert_eq!(r.at(12.0, m).speed, 0.0, "seed {seed}");
    }
}

/// Issue 27 follow-up: a member's driver is activated on the domains its model holds
/// (plan/random_traffic.rs `driver_domains`): the `idm` of members kept in their lanes on the
/// longitudinal one, the `mobil` on both. Before, every member's was activated on both, and the
/// engine recorded "activation changed; lateral is not a domain of this controller: not
/// activated" for each idm member. Now each member's one record at its creation is
/// "activation changed": random_traffic_member_groups.osc (seven idm members, created at 0 s,
/// lower.rs), random_traffic_late_keep_lane.osc (six idm members created at 5 s,
/// plan/random_traffic_late.rs) and random_traffic_late.osc (six mobil members at 5 s);
/// seeds 0-3.
#[test]
fn a_members_driver_is_activated_on_the_domains_its_model_holds() {
    for (name, n, at) in [
        ("random_traffic_member_groups", 7, 0.0),
        ("random_traffic_late_keep_lane", 6, 5.0),
        ("random_traffic_late", 6, 5.0),
    ] {
        for seed in 0..4 {
            let r = run(name, seed, None);
            let created: Vec<_> = r
                .controllers
                .iter()
                .filter(|(t, _, note)| (t - at).abs() < 1e-9 && note.starts_with("activation"))
                .collect();
            assert_eq!(created.len(), n, "{name} seed {seed}: {created:?}");
            for (_, e, note) in created {
                assert_eq!(note, "activation changed", "{name} seed {seed} {e}");
            }
            assert!(
                r.controllers
                    .iter()
                    .all(|(_, _, note)| !note.contains("not a domain")),
                "{name} seed {seed}"
            );
        }
    }
}

/// A member's own `assign_orientation` after a run-time condition is the engine's check that it
/// stands then (§8.7.18.1: its speed is its model's), not the plan's last speed of it
/// (random_traffic_member_orientation*.osc's comments, by hand): a member that stands is turned
/// where it is on every seed (the plan refused it before, reading the drawn start speed); a
/// moving one fails the run at the phase start with the speed the IDM's closed form gives (the
/// plan let it turn before, reading 0 m/s).
#[test]
fn a_members_assign_orientation_after_a_run_time_condition_is_the_engines_standing_check() {
    let m = "g.vehicles[0]";
    for seed in 0..4 {
        let r = run("random_traffic_member_orientation", seed, None);
        let at = r.at(15.05, m);
        assert!(at.speed.abs() < 1e-9, "seed {seed}: {at:?}");
        // Not turned before: the heading it stopped with (its model may have stopped it in a
        // lane change).
        assert_eq!(at.h, r.at(15.0, m).h, "seed {seed}");
        for t in [15.1, 16.0, 20.0] {
            let o = r.at(t, m);
            assert!((o.h - 0.5).abs() < 1e-9, "seed {seed} at {t}: {o:?}");
            assert!((o.x - at.x).abs() < S_TOL && (o.y - at.y).abs() < S_TOL);
        }
    }
    let name = "random_traffic_member_orientation_moving";
    let lowered = crate::support::lower(name, 0, None).unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = crate::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    let want = "expected 'g.vehicles[0]' at 0.000 m/s (within 0.01 m/s) (assign_orientation(…) at ";
    let place = format!("{name}.osc:25:13), found it at ");
    assert!(error.starts_with(want) && error.contains(&place), "{error}");
    let found: f64 = error
        .split("found it at ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("{error}"));
    let v = crate::random_traffic::free_road_speed(0.0, 10.0, 0.73, 7.05);
    assert!((v - 5.08).abs() < 0.005, "hand: {v}");
    assert!((found - v).abs() < 0.01, "{found} vs {v}: {error}");
    assert!(error.ends_with("m/s at t = 8.050 s"), "{error}");
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 8.05).abs() < 1e-9, "{records:?}");
    assert_eq!(records[0].1, "do.1.1/g.vehicles[0]/1:check");
}

/// A member's own path after a run-time condition (random_traffic_member_path_end_offset.osc,
/// random_traffic_member_follow_path_away.osc, by hand): replay_path with end_offset 20 m
/// follows the part 60.076526 m from q0 along the line to q1, at the speed the member's model
/// gives it, and its phase ends in the step the engine has it there or the one after (before:
/// refused, the plan timed the end by its own speed of the member, 0 m/s); follow_path from
/// where the seed drew the member is the engine's check at the phase start, an error record
/// and a failed run (before: the pursuit joined the path part-way or, past its end, not at
/// all).
#[test]
fn a_members_own_path_after_a_run_time_condition_ends_where_the_engine_has_it_at_the_parts_end() {
    let m = "g.vehicles[0]";
    let length = 80.0_f64.hypot(3.5);
    assert!((length - 80.076_526).abs() < 1e-6);
    let (ux, uy) = (80.0 / length, 3.5 / length);
    let part = length - 20.0;
    for seed in 0..4 {
        let r = run("random_traffic_member_path_end_offset", seed, None);
        let (start, end) = r.phase("do.1.path");
        assert!((start - 3.05).abs() < 1e-9, "seed {seed}: {start}");
        let along = |t: f64| {
            let o = r.at(t, m);
            let (dx, dy) = (o.x - 400.0, o.y + 5.25);
            (dx * ux + dy * uy, dx * uy - dy * ux, o.speed)
        };
        // On the line from the first step to the part's end, moving at the model's speed.
        let mut t = start + DT;
        let mut reached = None;
        while t < end + 1e-9 {
            let (d, across, v) = along(t);
            if reached.is_none() {
                assert!(
                    across.abs() < 1e-6,
                    "seed {seed} at {t}: {across} m off the line"
                );
                assert!(v > 1.0, "seed {seed} at {t}: {v} m/s");
                if d >= part - 1e-6 {
                    reached = Some(t);
                }
            }
            t += DT;
        }
        let reached =
            reached.unwrap_or_else(|| panic!("seed {seed}: not at the part's end by {end}"));
        assert!(
            end - reached > -1e-9 && end - reached < DT + 1e-9,
            "seed {seed}: there at {reached}, the phase ends at {end}"
        );
        // One step before, short of it.
        assert!(along(reached - DT).0 < part, "seed {seed}");
    }
    let name = "random_traffic_member_follow_path_away";
    for seed in 0..4 {
        let lowered = crate::support::lower(name, seed, None).unwrap_or_else(|e| panic!("{e}"));
        let (error, records) = crate::support::run_to_error(&lowered.scenario);
        let error = error.expect("the run fails");
        let want = format!(
            "(the start of `g.vehicles[0]`'s path in follow_path(…) at {}",
            crate::support::path(&format!("tests/scenarios/{name}.osc")).display()
        );
        assert!(
            error.starts_with("expected 'g.vehicles[0]'") && error.contains(&want),
            "seed {seed}: {error}"
        );
        assert!(error.ends_with("at t = 3.050 s"), "seed {seed}: {error}");
        assert_eq!(records.len(), 1, "seed {seed}: {records:?}");
        assert_eq!(records[0].1, "do.1.1/g.vehicles[0]/1:check", "seed {seed}");
    }
}
