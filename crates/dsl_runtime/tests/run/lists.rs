//! Elements of the library's lists as along's routes (issue 27; ASAM OpenSCENARIO DSL 2.1
//! §8.12 `compound_route.route_elements`, `road.s_positive`, `lane_section.lanes`): a compound
//! route's routes, a road's lane sections in +s, a lane section's lanes flowing in +s. Motions
//! worked by hand in the scenario files' comments.

use crate::support::{error_on, run_on};

/// Positions on a straight road in a lane: float round-off only.
const S_TOL: f64 = 1e-6;

#[test]
fn the_elements_of_the_librarys_lists_are_routes_along_their_part_of_the_road() {
    let r = run_on("lists/list_elements", "lane_drop");
    for (actor, x0, y, lane) in [
        ("ego", 300.0, -5.25, -2),
        ("npc", 50.0, -8.75, -3),
        ("bus", 100.0, -1.75, -1),
        ("car", 200.0, -5.25, -2),
        ("truck", 120.0, -8.75, -3),
        ("van", 80.0, -8.75, -3),
    ] {
        for (t, x) in [(0.0, x0), (2.5, x0 + 25.0), (5.0, x0 + 50.0)] {
            let p = r.at(t, actor);
            assert!(
                (p.x - x).abs() < S_TOL && (p.y - y).abs() < S_TOL && p.lane == lane,
                "{actor} at {t} s: {p:?}"
            );
        }
    }
}

#[test]
fn a_roads_sections_in_minus_s_and_their_lanes_are_driven_against_s() {
    let r = run_on("lists/list_negative", "lane_drop");
    for (actor, x0) in [("bike", 450.0), ("van", 300.0)] {
        for (t, x) in [(0.0, x0), (2.5, x0 - 25.0), (5.0, x0 - 50.0)] {
            let p = r.at(t, actor);
            assert!(
                (p.x - x).abs() < S_TOL
                    && (p.y - 1.75).abs() < S_TOL
                    && p.lane == 1
                    && (p.h.abs() - std::f64::consts::PI).abs() < 1e-9,
                "{actor} at {t} s: {p:?}"
            );
        }
    }
}

#[test]
fn an_element_past_its_list_or_of_no_list_run_is_an_error_at_its_place() {
    for (name, road, at, what) in [
        ("err_list_section", "lane_drop", "9:9", "expected an index below 2 into the lane sections in +s of `rd`"),
        ("err_list_lane", "lane_drop", "9:9", "expected an index below 2 into the lanes of the lane section of road 1 from s = 300.00 m"),
        ("err_list_plan_road", "lane_drop", "9:9", "expected an index below 1 into the route elements of a compound route the runtime chooses"),
        ("err_list_element", "lane_drop", "8:33", "expected an index below 2 into the route elements of the compound route"),
        ("err_list_sidewalk", "sidewalk", "9:9", "expected a driving lane as `rd.s_positive[0].lanes[2]`, found lane -3"),
        ("err_list_section_end", "lane_drop", "10:9", "expected `npc` on route `rd.s_positive[0]` (the lane section of road 1 from s = 0.00 m"),
        ("err_list_negative", "lane_drop", "9:9", "expected an index below 2 into the lane sections in -s of `rd`"),
        ("err_list_compound_lane", "lane_drop", "10:9", "expected an index below 1 into the lanes along `cl` (its lane -3"),
    ] {
        let e = error_on(&format!("lists/{name}"), road);
        assert!(
            e.starts_with(what)
                && e.ends_with(&format!("{name}.osc:{at}"))
                && (name != "err_list_section_end"
                    || e.contains("between s = 0.00 m and 300.00 m at the phase end, found it at s = 330.00 m")),
            "{name}: {e}"
        );
    }
}

#[test]
fn a_roads_sections_in_minus_s_on_a_plan_over_two_roads_are_met_from_its_last_road() {
    // list_negative_roads.osc, by hand: s_negative[0] is road 1's section, s_negative[1] road
    // 0's; u = 300 m - s from road 1's end.
    let r = run_on("lists/list_negative_roads", "manual_add_of_geometries0");
    let (c, s) = (1f64.cos(), 1f64.sin());
    let (x0, y0) = (100.0 + 100.0 * s, 100.0 * (1.0 - c));
    for (actor, t, road, x, y) in [
        (
            "bike",
            0.0,
            Some("1"),
            x0 + 50.0 * c - 1.5 * s,
            y0 + 50.0 * s + 1.5 * c,
        ),
        (
            "bike",
            4.0,
            Some("1"),
            x0 + 10.0 * c - 1.5 * s,
            y0 + 10.0 * s + 1.5 * c,
        ),
        // At road 0's end, which is road 1's start: either road's id.
        ("van", 0.0, None, x0 - 1.5 * s, y0 + 1.5 * c),
    ] {
        let p = r.at(t, actor);
        assert!(
            (p.x - x).abs() < S_TOL
                && (p.y - y).abs() < S_TOL
                && p.lane == 1
                && road.is_none_or(|id| p.road == id)
                && (p.h.rem_euclid(std::f64::consts::TAU) - (1.0 + std::f64::consts::PI)).abs()
                    < 1e-9,
            "{actor} at {t} s: {p:?}"
        );
    }
}

/// list_compound_lane_links.osc on lane_add_inner.xodr, by hand: cl is lane -2 of section 0
/// (lane(1)'s at the start), whose successor link leads into lane -3 of section 1:
/// cl.lanes[1] is that lane from s = 300 m, its centre t = -(w(s − 300) + 5.25), w(d) =
/// 0.00105·d² − 0.000007·d³ the new lane -1's width (-5.25 m at 300 m, -5.796875 m at 325 m,
/// -7.0 m at 350 m). Before, cl.lanes[1] was section 1's lane -2 (the same id), t = -1.75 m
/// at 300 m.
#[test]
fn a_compound_lanes_lanes_follow_the_successor_links_where_the_lane_ids_change() {
    let r = run_on("lists/list_compound_lane_links", "lane_add_inner");
    let w = |d: f64| 0.00105 * d * d - 0.000007 * d * d * d;
    assert!((w(25.0) - 0.546875).abs() < 1e-12 && (w(50.0) - 1.75).abs() < 1e-12);
    let p = r.at(0.0, "bus");
    assert!(
        (p.x - 300.0).abs() < S_TOL && (p.y + 5.25).abs() < S_TOL,
        "{p:?}"
    );
    for k in 0..=100 {
        let t = k as f64 * 0.05;
        let p = r.at(t, "bus");
        let want = -(w(p.s - 300.0) + 5.25);
        assert!(
            (p.y - want).abs() < 1e-3 && p.lane == -3 && (300.0..=350.0 + S_TOL).contains(&p.s),
            "bus at {t} s: {p:?}, want y {want}"
        );
    }
}

#[test]
fn a_compound_lane_alone_and_its_lanes_select_the_same_lane() {
    // list_compound_lane.osc, by hand: cl is lane -2 (lane(1) at the start of lane_add.xodr);
    // cl.lanes[0] and cl.lanes[1] are lane -2 of sections 0 and 1.
    let r = run_on("lists/list_compound_lane", "lane_add");
    for (actor, x0) in [("ego", 50.0), ("van", 120.0), ("bus", 300.0)] {
        for (t, x) in [(0.0, x0), (2.5, x0 + 25.0), (5.0, x0 + 50.0)] {
            let p = r.at(t, actor);
            assert!(
                (p.x - x).abs() < S_TOL && (p.y - -5.25).abs() < S_TOL && p.lane == -2,
                "{actor} at {t} s: {p:?}"
            );
        }
    }
}

/// lane_renumbered.osc on lane_add_inner.xodr, by hand: ego in lane -2 (lane(1), t = -5.25 m)
/// from s = 250 m at 10 m/s, s = 250 + 10·t; across s = 300 m (at 5 s) its successor link leads
/// it into lane -3, still lane(1) (the rightmost), centre t = -(w(s − 300) + 5.25) with the new
/// lane -1's width w(d) = 0.00105·d² − 0.000007·d³: w(25) = 0.546875 (y = -5.796875 m at
/// 7.5 s), w(50) = 1.75 (y = -7.0 m at 10 s), w(60) = 3.78 − 1.512 = 2.268 (y = -7.518 m at
/// 11 s), w(70) = 5.145 − 2.401 = 2.744 (y = -7.994 m at 12 s). do.b's lane(1) at 10 s is
/// lane -3 at s = 350 m, where the plan's track now follows ego (before: refused at 15:13 as
/// "found it in lane -2", the id kept along the road); b runs 10-12 s.
#[test]
fn a_lane_renumbered_by_a_lane_section_is_followed_by_the_plans_track() {
    let r = run_on("lists/lane_renumbered", "lane_add_inner");
    crate::support::phases_are(&r, &[("do.b", 10.0, 12.0)]);
    for (t, x, y, lane) in [
        (0.0, 250.0, -5.25, -2),
        (2.5, 275.0, -5.25, -2),
        (7.5, 325.0, -5.796875, -3),
        (10.0, 350.0, -7.0, -3),
        (11.0, 360.0, -7.518, -3),
        (12.0, 370.0, -7.994, -3),
    ] {
        let p = r.at(t, "ego");
        assert!(
            (p.x - x).abs() < S_TOL && (p.y - y).abs() < 1e-9 + S_TOL && p.lane == lane,
            "ego at {t} s: {p:?}, want ({x}, {y}) in lane {lane}"
        );
    }
}
