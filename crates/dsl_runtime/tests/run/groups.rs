//! Vehicle groups (ASAM OpenSCENARIO DSL 2.1 §8.7.18): a common-route group over several lanes
//! fills the lanes from its own leftwards, a row at a time (random traffic: `random_traffic`).
//! Expectations in the scenario files.

use crate::support::{run, Run};

const S_TOL: f64 = 1e-6;

#[test]
fn common_route_group_fills_the_lanes_row_by_row() {
    let r = run("common_route_group", 0, None);
    let expected = [(-3, 100.0), (-2, 100.0), (-1, 100.0), (-3, 85.0)];
    for (i, (lane, s0)) in expected.into_iter().enumerate() {
        let name = format!("g.vehicles[{i}]");
        let m = r.at(0.0, &name);
        assert_eq!(m.lane, lane, "{m:?}");
        assert!((m.s - s0).abs() < S_TOL, "{m:?}");
        assert!((r.at(2.0, &name).s - (s0 + 20.0)).abs() < S_TOL);
    }
}

#[test]
fn single_lane_group_places_its_first_member_and_the_rest_behind() {
    let r = run("single_lane_group", 0, None);
    for (i, s0) in [100.0, 85.0, 70.0].into_iter().enumerate() {
        let m = r.at(0.0, &format!("g.vehicles[{i}]"));
        assert_eq!(m.lane, -2, "{m:?}");
        assert!((m.s - s0).abs() < S_TOL, "{m:?}");
    }
}

/// Positions after a teleport or along straight lines at constant speed (m).
const TOL: f64 = 1e-6;
/// The gap controller's stepped law, worked in the scenario's comment, against the engine (m,
/// m/s): only rounding separates them.
const LAW_TOL: f64 = 1e-3;
/// The engine's distance controller ends a change within this of its distance (m).
const REACHED: f64 = 0.1;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;
/// s after a sideways move against √(v² − ẏ²) over its whole time (m): the engine's steps.
const SIDEWAYS_TOL: f64 = 1e-4;

fn close(got: f64, want: f64, tol: f64, what: &str) {
    assert!((got - want).abs() < tol, "{what}: {got} vs {want}");
}

/// The gap actions on a group are a chain along the formation (group_space_gap.osc's comment,
/// worked step by step).
#[test]
fn a_groups_space_gap_is_a_chain_along_its_formation() {
    let r = run("actions/group_space_gap", 0, None);
    // Boxes: front 3.5 m, rear 0.5 m from the reference points.
    let gap = |t: f64, back: &str, front: &str| (r.at(t, front).s - 0.5) - (r.at(t, back).s + 3.5);
    close(
        r.at(0.0, "g.vehicles[1]").s,
        16.0,
        TOL,
        "member 1 placed 10 m behind member 0",
    );
    group_space_gap_chain(&r, &gap);
    close(r.at(30.0, "lead").s, 550.0, TOL, "lead at 30 s");
}

/// group_space_gap.osc's chain, worked in its comment, with `gap(t, back, front)` the gap
/// between the bumpers of `back` and `front` along their direction of travel at `t` (the
/// scenario driven in +s, or against s: run::opposite_groups).
pub(crate) fn group_space_gap_chain(r: &Run, gap: &dyn Fn(f64, &str, &str) -> f64) {
    let (m0, m1) = ("g.vehicles[0]", "g.vehicles[1]");
    close(gap(0.0, m0, "lead"), 66.0, TOL, "gap 0 at 0 s");
    close(gap(0.0, m1, m0), 10.0, TOL, "gap 1 at 0 s");
    // Mid-points at 2 s.
    close(gap(2.0, m0, "lead"), 61.9, LAW_TOL, "member 0's gap at 2 s");
    close(
        r.at(2.0, m0).speed,
        19.0,
        LAW_TOL,
        "member 0's speed at 2 s",
    );
    close(gap(2.0, m1, m0), 16.5662, LAW_TOL, "member 1's gap at 2 s");
    close(
        r.at(2.0, m1).speed,
        14.9627,
        LAW_TOL,
        "member 1's speed at 2 s",
    );
    // Member 1's change reaches 20 m at the step from 2.85 s and ends; it keeps 16.7627 m/s.
    close(
        gap(2.85, m1, m0),
        20.0,
        REACHED,
        "member 1 reached at 2.85 s",
    );
    assert!(
        (gap(2.8, m1, m0) - 20.0).abs() > REACHED,
        "not a step earlier"
    );
    close(
        r.at(5.0, m1).speed,
        16.7627,
        LAW_TOL,
        "member 1 keeps its speed",
    );
    // The phase ends with member 0's change, at 9.05 s.
    let (s, e) = r.phase("do.1.close");
    assert!(
        s.abs() < T_TOL && (e - 9.05).abs() < T_TOL,
        "close [{s}, {e}]"
    );
    close(
        gap(8.95, m0, "lead"),
        20.0904,
        LAW_TOL,
        "member 0 reached at 8.95 s",
    );
    close(gap(9.0, m1, m0), 46.8150, LAW_TOL, "member 1 behind at 9 s");
    // The keep holds the chain: each to its own neighbour.
    let (s2, e2) = r.phase("do.1.hold");
    assert!(
        (s2 - e).abs() < T_TOL && (e2 - 30.0).abs() < T_TOL,
        "hold [{s2}, {e2}]"
    );
    close(gap(20.0, m0, "lead"), 19.9999, LAW_TOL, "member 0 at 20 s");
    close(gap(20.0, m1, m0), 20.0102, LAW_TOL, "member 1 at 20 s");
    for (back, front) in [(m0, "lead"), (m1, m0)] {
        close(
            gap(30.0, back, front),
            20.0,
            LAW_TOL,
            &format!("{back} at 30 s"),
        );
        close(
            r.at(30.0, back).speed,
            15.0,
            LAW_TOL,
            &format!("{back} speed at 30 s"),
        );
    }
}

/// Each actor's LongitudinalDistanceAction in a lowered scenario: (reference, time gap,
/// displacement).
type DistanceRefs = std::collections::BTreeMap<
    String,
    (
        String,
        Option<f64>,
        Option<scenario::LongitudinalDisplacement>,
    ),
>;

fn distance_refs(name: &str) -> DistanceRefs {
    let lowered = crate::support::lower(name, 0, None).expect("plans");
    let mut refs = DistanceRefs::new();
    for story in &lowered.scenario.storyboard.stories {
        for act in &story.acts {
            for mg in &act.maneuver_groups {
                let actions = mg
                    .maneuvers
                    .iter()
                    .flat_map(|m| &m.events)
                    .flat_map(|e| &e.actions);
                for action in actions {
                    if let scenario::ActionKind::Private(scenario::PrivateAction::Longitudinal(
                        scenario::LongitudinalAction::LongitudinalDistance {
                            entity_ref,
                            time_gap,
                            displacement,
                            ..
                        },
                    )) = &action.kind
                    {
                        for actor in &mg.actors.entity_refs {
                            refs.insert(
                                actor.clone(),
                                (entity_ref.clone(), *time_gap, *displacement),
                            );
                        }
                    }
                }
            }
        }
    }
    refs
}

/// The reference each member's LongitudinalDistanceAction names (group_headway_chains.osc).
#[test]
fn a_groups_headway_chain_runs_row_by_row_towards_the_reference() {
    let refs = distance_refs("actions/group_headway_chains");
    let want = [
        ("g.vehicles[0]", "g.vehicles[3]"),
        ("g.vehicles[1]", "follower"),
        ("g.vehicles[2]", "follower"),
        ("g.vehicles[3]", "follower"),
    ];
    assert_eq!(refs.len(), want.len(), "{refs:?}");
    for (member, reference) in want {
        let (r, gap, displacement) = &refs[member];
        assert_eq!(r, reference, "{refs:?}");
        assert_eq!(*gap, Some(2.0));
        assert_eq!(
            *displacement,
            Some(scenario::LongitudinalDisplacement::LeadingReferencedEntity)
        );
    }
}

/// Without a direction the side the plan has the reference on decides the chain
/// (group_gap_no_direction.osc).
#[test]
fn a_groups_gap_without_a_direction_chains_from_the_side_of_the_reference() {
    let refs = distance_refs("actions/group_gap_no_direction");
    assert_eq!(refs.len(), 2, "{refs:?}");
    for (member, reference) in [
        ("g.vehicles[0]", "lead"),
        ("g.vehicles[1]", "g.vehicles[0]"),
    ] {
        let (r, gap, displacement) = &refs[member];
        assert_eq!(r, reference, "{refs:?}");
        assert_eq!(*gap, None, "a space gap");
        assert_eq!(*displacement, Some(scenario::LongitudinalDisplacement::Any));
    }
}

/// assign_position on a group moves its formation (group_assign_position.osc's comment).
#[test]
fn a_groups_assign_position_moves_its_formation_as_a_whole() {
    let r = run("actions/group_assign_position", 0, None);
    for (name, before, at, after) in [
        ("g.vehicles[0]", 110.0, 200.0, 209.5),
        ("g.vehicles[1]", 95.0, 185.0, 194.5),
    ] {
        close(r.at(1.0, name).x, before, TOL, &format!("{name} x(1)"));
        close(r.at(1.05, name).x, at, TOL, &format!("{name} x(1.05)"));
        let end = r.at(2.0, name);
        close(end.x, after, TOL, &format!("{name} x(2)"));
        close(end.y, -1.75, TOL, &format!("{name} y(2)"));
        assert_eq!(end.lane, -1, "{name}");
    }
    assert_eq!(r.phase("do.1"), (1.0, 1.0));
    assert_eq!(r.phase("do.2"), (1.0, 2.0));
}

/// change_position on a group: parallel lines (group_change_position.osc's comment).
#[test]
fn a_groups_change_position_moves_each_member_along_its_own_line() {
    let r = run("actions/group_change_position", 0, None);
    for (name, x0, mid, x1) in [
        ("g.vehicles[0]", 30.0, 42.0, 54.0),
        ("g.vehicles[1]", 15.0, 27.0, 39.0),
    ] {
        close(r.at(0.0, name).x, x0, TOL, &format!("{name} x(0)"));
        let m = r.at(1.25, name);
        close(m.x, mid, TOL, &format!("{name} x(1.25)"));
        close(m.y, -5.25, TOL, &format!("{name} y(1.25)"));
        let end = r.at(2.5, name);
        close(end.x, x1, TOL, &format!("{name} x(2.5)"));
        close(end.y, -1.75, TOL, &format!("{name} y(2.5)"));
        assert_eq!(end.lane, -1, "{name}");
    }
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 2.5).abs() < T_TOL, "[{s}, {e}]");
}

/// The group forms that stay errors, each saying why.
#[test]
fn group_forms_that_cannot_keep_the_formation_are_errors() {
    let cases = [
        (
            "err_group_assign_position_off",
            "13:38",
            "expected `g.vehicles[1]` in a driving lane of road 1 when assign_position(…) moves group `g` as a whole (its offset from `g.vehicles[0]`: 0.00 m along the road, 3.50 m across it), found s = 200.00 m, t = 1.75 m outside them",
        ),
        (
            "err_group_path_start",
            "13:32",
            "expected `g.vehicles[0]` at the start of the path when group `g` follows it (every member enters it where member 0 does), found it 10.00 m from (50.00, -8.75)",
        ),
        (
            "err_group_lateral_gap",
            "12:9",
            "expected a single-lane group for a lateral gap in change_space_gap(…), found `g`",
        ),
        (
            "err_group_gap_member",
            "5:8",
            "expected a reference outside group `g` in change_space_gap(…) on it, found its member `g.vehicles[0]`",
        ),
        (
            "err_group_gap_side",
            "12:9",
            "expected `direction: ahead` or `behind` in change_space_gap(…) on group `g`",
        ),
    ];
    for (name, place, text) in cases {
        let e = crate::support::error(&format!("actions/{name}"));
        assert!(e.contains(&format!("{name}.osc:{place}")), "{e}");
        assert!(e.contains(text), "{text:?} not in {e}");
    }
}

/// The other group forms, one after the other (group_forms.osc's comment, by hand).
#[test]
fn the_other_group_forms_run_member_by_member() {
    use crate::support::stepped;
    let r = run("actions/group_forms", 0, None);
    let v = |t: f64| {
        if t <= 1.0 {
            0.0
        } else if t <= 2.0 {
            10.0
        } else if t <= 4.0 {
            10.0 + 2.0 * (t - 2.0)
        } else if t <= 4.8 {
            let u = t - 4.0;
            14.0 + 2.0 * u - 1.25 * u * u
        } else if t <= 7.8 {
            14.8
        } else {
            (14.8 - 5.0 * (t - 7.8)).max(0.0)
        }
    };
    // The step sums against the exact integrals and the step lead.
    close(stepped(v, 0.0, 2.0), 10.0, TOL, "hand sum to 2 s");
    close(stepped(v, 0.0, 4.0), 34.0 + 0.1, TOL, "hand sum to 4 s");
    for (name, s0) in [("g.vehicles[0]", 100.0), ("g.vehicles[1]", 85.0)] {
        close(r.at(0.0, name).s, s0, TOL, &format!("{name} s(0)"));
        close(r.at(1.0, name).s, s0, TOL, &format!("{name} stands to 1 s"));
        for (t, want) in [
            (3.0, 12.0),
            (4.0, 14.0),
            (4.4, 14.6),
            (4.8, 14.8),
            (5.8, 14.8),
            (9.3, 7.3),
            (10.8, 0.0),
        ] {
            close(r.at(t, name).speed, want, TOL, &format!("{name} v({t})"));
        }
        for t in [2.0, 4.0, 4.8, 5.8] {
            close(
                r.at(t, name).s,
                s0 + stepped(v, 0.0, t),
                TOL,
                &format!("{name} s({t})"),
            );
        }
        // The engine moves a vehicle along its heading: while it moves sideways at 0.25 m/s
        // (5.8 to 7.8 s) s grows at √(14.8² − 0.25²) m/s, 2·(14.8 − 14.797888) = 0.0042 m
        // less than the speed gives; the engine's steps of the offset change leave < 0.1 mm.
        let sideways = 2.0 * (14.8 - (14.8f64 * 14.8 - 0.25 * 0.25).sqrt());
        for t in [7.8, 10.8] {
            close(
                r.at(t, name).s,
                s0 + stepped(v, 0.0, t) - sideways,
                SIDEWAYS_TOL,
                &format!("{name} s({t})"),
            );
        }
        close(r.at(5.8, name).y, -5.25, TOL, &format!("{name} y(5.8)"));
        close(r.at(6.8, name).y, -5.0, TOL, &format!("{name} y(6.8)"));
        close(r.at(7.8, name).y, -4.75, TOL, &format!("{name} y(7.8)"));
        close(r.at(10.8, name).h, 0.0, TOL, &format!("{name} h(10.8)"));
        let end = r.at(11.8, name);
        close(end.h, 0.5, TOL, &format!("{name} h(11.8)"));
        close(end.speed, 0.0, TOL, &format!("{name} v(11.8)"));
        close(
            end.s,
            r.at(10.8, name).s,
            TOL,
            &format!("{name} stands from 10.8 s"),
        );
    }
    for (path, a, b) in [
        ("do.a", 0.0, 1.0),
        ("do.b", 1.0, 1.0),
        ("do.c", 1.0, 2.0),
        ("do.d", 2.0, 2.0),
        ("do.e", 2.0, 4.0),
        ("do.f", 4.0, 4.8),
        ("do.gk", 4.8, 5.8),
        ("do.h", 5.8, 7.8),
        ("do.i", 7.8, 10.8),
        ("do.j", 10.8, 10.8),
        ("do.k", 10.8, 11.8),
    ] {
        let (s, e) = r.phase(path);
        assert!(
            (s - a).abs() < T_TOL && (e - b).abs() < T_TOL,
            "{path} [{s}, {e}]"
        );
    }
}

/// A lateral gap on a single-lane group: each member to the reference (group_lateral_gap.osc's
/// comment; the stepped law of lateral_gap.osc).
#[test]
fn a_single_lane_groups_lateral_gap_is_each_members_to_the_reference() {
    let r = run("actions/group_lateral_gap", 0, None);
    for (name, s0) in [("g.vehicles[0]", 100.0), ("g.vehicles[1]", 85.0)] {
        close(r.at(0.0, name).y, -8.75, TOL, &format!("{name} y(0)"));
        close(r.at(2.0, name).y, -8.1095, LAW_TOL, &format!("{name} y(2)"));
        let at_end = r.at(6.3, name).y;
        assert!((at_end + 7.75).abs() <= 0.01, "{name} y(6.3) = {at_end}");
        assert!(
            (r.at(6.25, name).y + 7.75).abs() > 0.01,
            "{name}: not a step earlier"
        );
        // Along its heading: ∫(v − √(v² − ẏ²))dt ≈ ∫ẏ²dt/(2v) = (ω/4 m²/s)/(2·20 m/s) with
        // ẏ = ω²t·e^(−ωt) (1 m, ω = 1.0954 /s): 0.0068 m less s than 20 m/s gives.
        let sideways = (0.4f64 * 3.0).sqrt() / 4.0 / 40.0;
        close(
            r.at(6.4, name).s,
            s0 + 128.0 - sideways,
            LAW_TOL,
            &format!("{name} s(6.4)"),
        );
        assert_eq!(r.at(6.4, name).lane, -3, "{name} stays in its lane");
    }
    let (s, e) = r.phase("do.close");
    assert!(
        s.abs() < T_TOL && (e - 6.4).abs() < T_TOL,
        "close [{s}, {e}]"
    );
}

/// change_position on the road network on a group: each member's lane change over the same T
/// (group_change_position_on_road.osc's comment, with change_position_on_road.osc's values).
#[test]
fn a_groups_change_position_on_the_road_network_keeps_the_formation() {
    /// change_position_on_road.osc's worked integrals (midpoint rule, 100,000 points) against
    /// the engine's steps of 0.05 s (m), as in position_actions.
    const ROAD_TOL: f64 = 1e-4;
    let r = run("actions/group_change_position_on_road", 0, None);
    for (name, shift) in [("g.vehicles[0]", 0.0), ("g.vehicles[1]", -15.0)] {
        for (t, x, y) in [(2.0, 39.90654, -7.01291), (4.0, 59.81131, -5.25019)] {
            let m = r.at(t, name);
            close(m.x, x + shift, ROAD_TOL, &format!("{name} x({t})"));
            close(m.y, y, ROAD_TOL, &format!("{name} y({t})"));
        }
        assert_eq!(r.at(4.05, name).lane, -2, "{name}");
    }
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 4.05).abs() < T_TOL, "[{s}, {e}]");
}

/// The pursuit's lag behind a smooth path (m), as in position_actions' follow_path test: the
/// S-curve's radius is 76.8 m or more.
const PURSUIT_TOL: f64 = 0.02;

/// A column follows a path in file, each member from its own lead-in along its lane
/// (group_follow_path.osc's comment, by hand).
#[test]
fn a_column_follows_a_path_in_file() {
    let r = run("actions/group_follow_path", 0, None);
    // Member 2 at 2 s: on its lead-in along lane -3, 20 m from where it started.
    let at2 = r.at(2.0, "g.vehicles[2]");
    close(at2.x, 40.0, PURSUIT_TOL, "member 2 x(2)");
    close(at2.y, -8.75, PURSUIT_TOL, "member 2 y(2)");
    close(at2.h, 0.0, PURSUIT_TOL, "member 2 h(2)");
    assert_eq!(at2.lane, -3);
    // At 7 s: 20 m along the S-curve, where member 0 was at 4 s.
    for (name, t) in [
        ("g.vehicles[2]", 7.0),
        ("g.vehicles[1]", 5.5),
        ("g.vehicles[0]", 4.0),
    ] {
        let m = r.at(t, name);
        close(m.x, 89.909, PURSUIT_TOL, &format!("{name} x({t})"));
        close(m.y, -7.012, PURSUIT_TOL, &format!("{name} y({t})"));
        close(m.h, 0.13077, PURSUIT_TOL, &format!("{name} h({t})"));
        close(m.speed, 10.0, 1e-9, &format!("{name} v({t})"));
    }
    // Member 2 reaches the end at 13.018 s, in the step to 13.05 s, which ends the phase.
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 13.05).abs() < T_TOL, "[{s}, {e}]");
}

/// A column follows a trajectory in file, each member's stamps shifted by its headway
/// (group_follow_trajectory.osc's comment, by hand).
#[test]
fn a_column_follows_a_trajectory_with_its_stamps_shifted_by_each_headway() {
    let r = run("actions/group_follow_trajectory", 0, None);
    places(
        &r,
        &[
            ("g.vehicles[2]", 2.0, 40.0, -8.75),
            ("g.vehicles[2]", 6.25, 82.0, -5.25),
            ("g.vehicles[1]", 6.25, 96.5, -1.75),
            ("g.vehicles[0]", 3.25, 82.0, -5.25),
            ("g.vehicles[2]", 10.5, 124.0, -1.75),
        ],
    );
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 10.5).abs() < T_TOL, "[{s}, {e}]");
}

/// A group over several lanes follows a trajectory moved across the road by each member's
/// offset (group_follow_trajectory_rows.osc's comment, by hand).
#[test]
fn a_group_over_several_lanes_follows_the_trajectory_moved_by_each_offset() {
    let r = run("actions/group_follow_trajectory_rows", 0, None);
    places(
        &r,
        &[
            ("g.vehicles[0]", 3.25, 82.0, -7.0),
            ("g.vehicles[1]", 3.25, 82.0, -3.5),
            ("g.vehicles[0]", 7.5, 124.0, -5.25),
            ("g.vehicles[1]", 7.5, 124.0, -1.75),
        ],
    );
    assert_eq!(r.at(7.5, "g.vehicles[0]").lane, -2);
    assert_eq!(r.at(7.5, "g.vehicles[1]").lane, -1);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 7.5).abs() < T_TOL, "[{s}, {e}]");
}

/// Round a bend, a group over several lanes follows the trajectory moved to each member's
/// place in the road frame, with member 0's stamps (group_follow_trajectory_bend_rows.osc on
/// bend.xodr, by hand there).
#[test]
fn a_group_over_several_lanes_follows_the_trajectory_moved_round_a_bend() {
    let r = crate::support::run_on("actions/group_follow_trajectory_bend_rows", "bend");
    for (name, t, x, y, s, lane) in [
        ("g.vehicles[0]", 0.0, 90.0, -8.75, 90.0, -3),
        ("g.vehicles[1]", 0.0, 90.0, -5.25, 90.0, -2),
        ("g.vehicles[0]", 3.0, 120.0, -5.1875, 118.7894, -3),
        ("g.vehicles[1]", 3.0, 119.3462, -1.7491, 118.7894, -2),
        ("g.vehicles[0]", 4.0, 130.0, -4.0, 128.0838, -3),
        ("g.vehicles[1]", 4.0, 129.0299, -0.6371, 128.0838, -2),
    ] {
        let m = r.at(t, name);
        close(m.x, x, CHORD_TOL, &format!("{name} x({t})"));
        close(m.y, y, CHORD_TOL, &format!("{name} y({t})"));
        close(m.s, s, CHORD_TOL, &format!("{name} s({t})"));
        assert_eq!(m.lane, lane, "{name} at {t} s");
    }
    let (s, e) = r.phase("do");
    assert!(s.abs() < T_TOL && (e - 4.0).abs() < T_TOL, "[{s}, {e}]");
}

/// After a run-time condition a group over several lanes still moves as a block: member 1's
/// points are placed from where it is when the action starts
/// (group_follow_trajectory_bend_runtime.osc on bend.xodr, by hand there).
#[test]
fn a_group_over_several_lanes_follows_a_trajectory_after_a_run_time_condition() {
    let r = crate::support::run_on("actions/group_follow_trajectory_bend_runtime", "bend");
    let (s, _) = r.phase("do.signal.1.follow");
    assert!((s - 2.55).abs() < T_TOL, "follow starts at {s}");
    for (name, t, x, y, s, lane) in [
        ("g.vehicles[0]", 2.55, 90.0, -8.75, 90.0, -3),
        ("g.vehicles[1]", 2.55, 90.0, -5.25, 90.0, -2),
        ("g.vehicles[0]", 5.55, 120.0, -5.1875, 118.7894, -3),
        ("g.vehicles[1]", 5.55, 119.3462, -1.7491, 118.7894, -2),
        ("g.vehicles[1]", 6.55, 129.0299, -0.6371, 128.0838, -2),
    ] {
        let m = r.at(t, name);
        close(m.x, x, CHORD_TOL, &format!("{name} x({t})"));
        close(m.y, y, CHORD_TOL, &format!("{name} y({t})"));
        close(m.s, s, CHORD_TOL, &format!("{name} s({t})"));
        assert_eq!(m.lane, lane, "{name} at {t} s");
    }
    let (_, e) = r.phase("do.signal.1.follow");
    assert!((e - 6.55).abs() < T_TOL, "follow ends at {e}");
}

/// After a run-time condition the engine checks that member 0 stands at the path's start;
/// elsewhere the run fails (group_follow_trajectory_bend_runtime_off.osc on bend.xodr).
#[test]
fn a_blocks_member_0_off_the_paths_start_after_a_run_time_condition_fails_the_run() {
    let want = "expected 'g.vehicles[0]' at s = 90.000 m (within 0.5 m) (the start of group `g`'s path in follow_trajectory(…) at ";
    let tail = "group_follow_trajectory_bend_runtime_off.osc:37:55), found it at s = 85.500 m at t = 2.550 s";
    crate::support::fails_once(
        "tests/scenarios/actions/group_follow_trajectory_bend_runtime_off.osc",
        "tests/roads/bend.xodr",
        (want, tail),
        (2.55, "do.signal.1.follow/g.vehicles[0]/1:check"),
    );
}

/// assign_position on a group after a run-time condition: the offsets the plan last knows,
/// checked by the engine (group_assign_position_runtime.osc, by hand there).
#[test]
fn a_groups_assign_position_after_a_run_time_condition_keeps_the_checked_formation() {
    let r = run("actions/group_assign_position_runtime", 0, None);
    for (name, x) in [("g.vehicles[0]", 320.0), ("g.vehicles[1]", 305.0)] {
        close(
            r.at(3.35, name).x,
            x - 153.0,
            TOL,
            &format!("{name} x(3.35)"),
        );
        close(r.at(3.4, name).x, x - 20.0, TOL, &format!("{name} x(3.4)"));
        let m = r.at(4.4, name);
        close(m.x, x, TOL, &format!("{name} x(4.4)"));
        close(m.y, -1.75, TOL, &format!("{name} y(4.4)"));
        assert_eq!(m.lane, -1, "{name}");
    }
}

/// change_position on a group after a run-time condition: parallel lines from where the
/// engine finds each member (group_change_position_runtime.osc, by hand there).
#[test]
fn a_groups_change_position_after_a_run_time_condition_moves_each_member_along_its_line() {
    let r = run("actions/group_change_position_runtime", 0, None);
    for (name, x) in [("g.vehicles[0]", 191.0), ("g.vehicles[1]", 176.0)] {
        close(
            r.at(3.35, name).x,
            x - 24.0,
            TOL,
            &format!("{name} x(3.35)"),
        );
        let m = r.at(4.1, name);
        close(m.x, x - 9.6, TOL, &format!("{name} x(4.1)"));
        close(m.y, -4.55, TOL, &format!("{name} y(4.1)"));
        let m = r.at(4.6, name);
        close(m.x, x, TOL, &format!("{name} x(4.6)"));
        close(m.y, -1.75, TOL, &format!("{name} y(4.6)"));
        assert_eq!(m.lane, -1, "{name}");
    }
}

/// change_position(p, smooth) on a group after a run-time condition: each member's smooth
/// curve from its own pose to its place in the formation (group_change_position_smooth_
/// runtime.osc, by hand there).
#[test]
fn a_groups_smooth_change_position_after_a_run_time_condition_curves_each_member() {
    let r = run("actions/group_change_position_smooth_runtime", 0, None);
    let (s, e) = r.phase("do.curve");
    assert!(
        (s - 3.35).abs() < T_TOL && (e - 5.4).abs() < T_TOL,
        "[{s}, {e}]"
    );
    // The engine's arc length against the sums: 1 cm.
    const ALONG: f64 = 0.01;
    for (name, x) in [("g.vehicles[0]", 207.0), ("g.vehicles[1]", 192.0)] {
        let m = r.at(4.35, name);
        close(m.x, x - 20.352, ALONG, &format!("{name} x(4.35)"));
        close(m.y, -5.343, ALONG, &format!("{name} y(4.35)"));
        let m = r.at(5.4, name);
        close(m.y, -1.75, TOL, &format!("{name} y(5.4)"));
        assert_eq!(m.lane, -1, "{name}");
    }
}

/// replay_path on a column after a run-time condition: the checked offset, the lead-in from
/// there (group_replay_path_runtime.osc, by hand there).
#[test]
fn a_column_replays_a_path_after_a_run_time_condition_from_its_checked_offset() {
    let r = run("actions/group_replay_path_runtime", 0, None);
    let (s, e) = r.phase("do.signal.1.follow");
    assert!(
        (s - 2.55).abs() < T_TOL && (e - 8.55).abs() < T_TOL,
        "[{s}, {e}]"
    );
    places(
        &r,
        &[
            ("g.vehicles[0]", 2.55, 90.0, -8.75),
            ("g.vehicles[1]", 2.55, 75.0, -8.75),
            ("g.vehicles[0]", 7.05, 134.0, -1.75),
            ("g.vehicles[1]", 4.05, 90.0, -8.75),
            ("g.vehicles[1]", 6.05, 110.0, -8.75),
            ("g.vehicles[1]", 7.3, 122.0, -5.25),
            ("g.vehicles[1]", 8.55, 134.0, -1.75),
        ],
    );
}

/// A formation changed before a run-time start fails the engine's check of the offsets
/// (group_assign_position_runtime_off.osc).
#[test]
fn a_groups_assign_position_after_its_formation_changed_at_run_time_fails_the_run() {
    let lowered = crate::support::lower("actions/group_assign_position_runtime_off", 0, None)
        .unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = crate::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    // Member 1 23.5 m further back than the -15 m the plan last knows (at 1 s): 38.5 m.
    let want = "15.000 m from 'g.vehicles[1]' along the road (within 0.5 m) (`g.vehicles[1]`'s offset from `g.vehicles[0]` in group `g`, -15.00 m along the road and 0.00 m across it as at 1.00 s, kept by assign_position(…) at ";
    let tail = "group_assign_position_runtime_off.osc:30:9), found 38.500 m at t = 3.350 s";
    assert!(error.contains(want) && error.ends_with(tail), "{error}");
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 3.35).abs() < T_TOL, "{records:?}");
    assert_eq!(records[0].1, "do.2/g.vehicles[1]/formation:check");
}

/// A group follows the part of a trajectory between its offsets, each member entering and
/// leaving its own path where the part does (group_trajectory_offsets.osc, by hand there).
#[test]
fn a_column_follows_the_part_of_a_trajectory_between_its_offsets() {
    let r = run("actions/group_trajectory_offsets", 0, None);
    places(
        &r,
        &[
            ("g.vehicles[0]", 0.0, 30.0, -8.75),
            ("g.vehicles[1]", 0.0, 15.0, -8.75),
            ("g.vehicles[0]", 3.0, 60.0, -8.75),
            ("g.vehicles[0]", 4.0, 69.6, -5.95),
            ("g.vehicles[0]", 4.25, 72.0, -5.25),
            ("g.vehicles[0]", 5.0, 79.5, -5.25),
            ("g.vehicles[1]", 1.5, 30.0, -8.75),
            ("g.vehicles[1]", 4.5, 60.0, -8.75),
            ("g.vehicles[1]", 5.5, 69.6, -5.95),
            ("g.vehicles[1]", 5.75, 72.0, -5.25),
        ],
    );
    assert_eq!(r.at(5.75, "g.vehicles[1]").lane, -2);
    let (s, e) = r.phase("do");
    assert!(s.abs() < T_TOL && (e - 5.75).abs() < T_TOL, "[{s}, {e}]");
}

/// Each member named at each time is at (x, y) within [`TOL`].
fn places(r: &crate::support::Run, cases: &[(&str, f64, f64, f64)]) {
    for &(name, t, x, y) in cases {
        let m = r.at(t, name);
        close(m.x, x, TOL, &format!("{name} x({t})"));
        close(m.y, y, TOL, &format!("{name} y({t})"));
    }
}

/// The chords of a lead-in round a bend leave the lane's arc by at most 1.4 mm (m).
const CHORD_TOL: f64 = 2e-3;

/// A column's lead-in follows its lane round a bend, and its stamps are shifted by its
/// distance along the lane (group_follow_trajectory_bend.osc on bend.xodr, by hand).
#[test]
fn a_columns_lead_in_follows_its_lane_round_a_bend() {
    let name = "actions/group_follow_trajectory_bend";
    let r = crate::support::run_on(name, "bend");
    for (i, s) in [130.0, 115.0, 100.0].into_iter().enumerate() {
        // Member 0 on the trajectory's first point, written to 0.1 mm.
        close(r.at(0.0, &format!("g.vehicles[{i}]")).s, s, 1e-4, "s(0)");
    }
    let m = r.at(1.5, "g.vehicles[2]");
    close(m.x, 114.9525, CHORD_TOL, "member 2 x(1.5)");
    close(m.y, -7.7172, CHORD_TOL, "member 2 y(1.5)");
    assert_eq!(m.lane, -3);
    let m = r.at(4.3, "g.vehicles[2]");
    close(m.x, 142.5126, CHORD_TOL, "member 2 x(4.3)");
    close(m.y, 0.4936, CHORD_TOL, "member 2 y(4.3)");
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 5.3).abs() < T_TOL, "[{s}, {e}]");
}

/// A column replays a path exactly, each member from its own lead-in (group_replay_path.osc,
/// by hand).
#[test]
fn a_column_replays_a_path_from_each_members_lead_in() {
    let r = run("actions/group_replay_path", 0, None);
    let leg = (7.0f64 / 24.0).atan();
    for (name, t, x, y, h) in [
        ("g.vehicles[1]", 1.0, 45.0, -8.75, 0.0),
        ("g.vehicles[1]", 2.75, 62.0, -5.25, leg),
        ("g.vehicles[0]", 1.25, 62.0, -5.25, leg),
        ("g.vehicles[1]", 9.0, 124.0, -1.75, 0.0),
    ] {
        let m = r.at(t, name);
        close(m.x, x, TOL, &format!("{name} x({t})"));
        close(m.y, y, TOL, &format!("{name} y({t})"));
        close(m.h, h, TOL, &format!("{name} h({t})"));
    }
    assert_eq!(r.at(9.0, "g.vehicles[1]").lane, -1);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < T_TOL && (e - 9.0).abs() < T_TOL, "[{s}, {e}]");
}

#[test]
fn a_group_over_several_lanes_beside_another_actor_keeps_its_block() {
    // group_block_beside.osc, worked in the file: member 0 3 m left of ego (1 m between the
    // sides, two half widths), member 1 a lane further left at member 0's offset in its lane,
    // member 2 the second row 14 m behind member 0; each keeps its t less ego's while ego moves.
    let r = run("group_block_beside", 0, None);
    for (i, lane, s, y) in [
        (0, -2, 100.0, -5.75),
        (1, -1, 100.0, -2.25),
        (2, -2, 86.0, -5.75),
    ] {
        let m = r.at(0.0, &format!("g.vehicles[{i}]"));
        assert!(
            m.lane == lane && (m.s - s).abs() < S_TOL && (m.y - y).abs() < S_TOL,
            "member {i}: {m:?}"
        );
    }
    // ego ends with its left side 0.5 m from lane -3's left border (y = -7 m): y = -7.5 - 1.
    assert!(
        (r.at(4.0, "ego").y - -8.5).abs() < 1e-3,
        "ego moved 0.25 m left"
    );
    for (t, objs) in &r.frames {
        let y = |n: &str| objs.iter().find(|o| o.name == n).map(|o| o.y).unwrap();
        let ego = y("ego");
        for (i, d) in [(0, 3.0), (1, 6.5), (2, 3.0)] {
            let got = y(&format!("g.vehicles[{i}]")) - ego;
            assert!(
                (got - d).abs() < S_TOL,
                "member {i} at {t}: {got} m left of ego"
            );
        }
    }
}

/// The block beside ego in a phase that starts at run time (group_block_beside_runtime.osc,
/// worked in the file): each member checked and followed at its own slot, the block as the
/// plan last knows it, while ego moves 0.5 m right.
#[test]
fn a_group_over_several_lanes_beside_another_actor_after_a_run_time_condition_keeps_its_slots() {
    let r = run("group_block_beside_runtime", 0, None);
    let (start, end) = r.phase("do.1.2");
    close(start, 3.05, T_TOL, "the run-time phase's start");
    close(end, 8.0, T_TOL, "the run-time phase's end");
    // Ego sinusoidal over [4, 7] s from -8.75 to -9.25 m.
    close(r.at(5.5, "ego").y, -9.0, 1e-9, "ego at the mid-point");
    close(r.at(7.0, "ego").y, -9.25, 1e-9, "ego at its move's end");
    // Each member's slot, its lane and y at the mid-point (5.5 s) and the end (8 s).
    for (i, slot, lane, y_mid, y_end) in [
        (0, 3.0, -2, -6.0, -6.25),
        (1, 6.5, -1, -2.5, -2.75),
        (2, 3.0, -2, -6.0, -6.25),
    ] {
        let name = format!("g.vehicles[{i}]");
        for (t, y) in [(5.5, y_mid), (8.0, y_end)] {
            let m = r.at(t, &name);
            assert_eq!(m.lane, lane, "{name} at {t}: {m:?}");
            close(m.y, y, S_TOL, &format!("{name} y at {t}"));
        }
        for (t, objs) in r.frames.iter().filter(|(t, _)| *t >= start - T_TOL) {
            let y = |n: &str| objs.iter().find(|o| o.name == n).map(|o| o.y).unwrap();
            close(
                y(&name) - y("ego"),
                slot,
                S_TOL,
                &format!("{name}'s slot at {t}"),
            );
        }
    }
    // Along the road before ego moves sideways (its move slows every member's s by about
    // ẏ²/2v, 1.3 mm by 5.5 s): member 2 at s = 86 + 20·4 = 166 m, 14 m behind member 0.
    close(
        r.at(4.0, "g.vehicles[2]").s,
        166.0,
        S_TOL,
        "member 2's s at 4 s",
    );
    close(
        r.at(4.0, "g.vehicles[0]").s,
        180.0,
        S_TOL,
        "member 0's s at 4 s",
    );
    // No two members on one spot at any step.
    for (t, objs) in &r.frames {
        let at = |i: usize| {
            let n = format!("g.vehicles[{i}]");
            let o = objs.iter().find(|o| o.name == n).unwrap();
            (o.x, o.y)
        };
        for (a, b) in [(0, 1), (0, 2), (1, 2)] {
            let ((xa, ya), (xb, yb)) = (at(a), at(b));
            assert!(
                (xa - xb).abs() > 4.0 || (ya - yb).abs() > 2.0,
                "members {a} and {b} overlap at {t}"
            );
        }
    }
    // Each member's own check, held from the phase's start until its end stopped it.
    for i in 0..3 {
        r.held(&format!("do.1.2/g.vehicles[{i}]/2:check"), (3.05, 8.0));
    }
}

/// A member of the block moved sideways of its own inside the block's run-time phase
/// (group_block_beside_runtime_breaks.osc, by hand there): its held check fails, naming it.
#[test]
fn a_block_member_leaving_its_slot_after_a_run_time_condition_fails_the_run() {
    // The check at the start of the step from 5.20 s finds member 1 0.010361 m off its slot
    // (by hand in the file), 6.510 m left of ego where it must be 6.500 m within 1 cm; the
    // record at that step's end. Members 0 and 2 keep theirs: one record only.
    let want = "expected 'g.vehicles[1]' 6.500 m to the left of 'ego' across the road (within 0.01 m) (lateral(…) at ";
    let tail = "group_block_beside_runtime_breaks.osc:44:17), found 6.510 m at t = 5.200 s";
    crate::support::fails_once(
        "tests/scenarios/group_block_beside_runtime_breaks.osc",
        "tests/roads/straight.xodr",
        (want, tail),
        (5.25, "do.1.2/g.vehicles[1]/2:check"),
    );
}

/// A block moved beside ego at a phase's end, at a start the plan knows and at one after a
/// run-time condition (group_block_beside_end.osc, group_block_beside_end_runtime.osc, by
/// hand there): each member ends at its own slot, 0.5 m right in its own lane.
#[test]
fn a_group_over_several_lanes_ends_a_phase_beside_another_actor_at_its_slots() {
    // Members' y half way and at the end, in lanes -2, -1, -2 throughout.
    const MID: [f64; 3] = [-5.5, -2.0, -5.5];
    const END: [f64; 3] = [-5.75, -2.25, -5.75];
    let slots = |r: &Run, when: &[(f64, [f64; 3])]| {
        for &(t, ys) in when {
            for (i, (lane, y)) in [-2, -1, -2].into_iter().zip(ys).enumerate() {
                let name = format!("g.vehicles[{i}]");
                let m = r.at(t, &name);
                assert_eq!(m.lane, lane, "{name} at {t}: {m:?}");
                close(m.y, y, S_TOL, &format!("{name} y at {t}"));
            }
        }
    };
    let r = run("group_block_beside_end", 0, None);
    slots(&r, &[(2.5, MID), (4.0, END), (6.0, END)]);
    let r = run("group_block_beside_end_runtime", 0, None);
    slots(&r, &[(4.55, MID), (6.05, END), (8.0, END)]);
}
