"""The OpenSCENARIO 2.0 §8.7 methods on entities of a running simulation return the
hand-computed values of the engine's own tests (crates/engine/tests/domain/*.rs), for
entities that a scenario places at the poses those tests use.

The Init actions run in the first step, which also moves every entity over [0, dt]. Entities
at rest stay where they were placed; a moving entity is placed v·dt behind the pose of the
Rust case along its heading, so that it stands there at t = dt, when the method is called.
Off the roads an entity moves straight along its heading; on a straight lane, along it."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import oscsim
from conftest import CORPUS, CURVE_R100, lane, world, write_scenario

DT = 0.05
# Road positions are Newton solutions to 1e-10 m; the Rust tests use 1e-7 to 1e-9 (the
# closed forms below are sums and one rotation of exact decimals). Positions placed v·dt
# behind carry one more rounding of x − v·dt + v·dt.
TOL = 1e-7
JUNCTION = CORPUS / "generated" / "xodr" / "common_junction_creator0.xodr"
# Length of connecting road "100" in common_junction_creator0.xodr (`road/@length`).
L100 = 100.00000012397831


def simulate(tmp_path: Path, road: Path, entities: list) -> oscsim.Simulation:
    sim = oscsim.Simulation(write_scenario(tmp_path, road, entities), dt=DT)
    assert sim.step() is None
    return sim


def test_object_distance(tmp_path: Path):
    # object_distance.rs: caller A at (10, 5) heading π/2 (its x axis is world +y, its y axis
    # world −x); every box spans x ∈ [−0.5, 3.5], y ∈ [−1, 1] of its own frame.
    h = math.pi / 2
    sim = simulate(
        tmp_path,
        CURVE_R100,
        [
            ("A", world(10, 5, h), 0),
            ("Ahead", world(10, 25, h), 0),
            ("Behind", world(10, -15, h), 0),
            ("Left", world(7, 15, h), 0),
            ("Across", world(12, 25, 0), 0),
        ],
    )
    a = sim.entity("A")
    cases = [
        # B 20 m ahead: local (20, 0); B's box x ∈ [19.5, 23.5], A's ends at 3.5 → 16.
        ("Ahead", "longitudinal", "reference_points", 20.0),
        ("Ahead", "longitudinal", "bounding_boxes", 16.0),
        ("Ahead", "lateral", "reference_points", 0.0),
        # B 20 m behind: box x ∈ [−20.5, −16.5], A's starts at −0.5 → −16.
        ("Behind", "longitudinal", "reference_points", -20.0),
        ("Behind", "longitudinal", "bounding_boxes", -16.0),
        # B at (7, 15): offset (−3, 10) → local (10, 3); box y ∈ [2, 4] vs [−1, 1] → 1.
        ("Left", "lateral", "reference_points", 3.0),
        ("Left", "lateral", "bounding_boxes", 1.0),
        # B at (12, 25) heading 0: local (20, −2); its width along A's x: [19, 21] → 15.5;
        # its length along A's y: [−5.5, −1.5] → −0.5.
        ("Across", "longitudinal", "reference_points", 20.0),
        ("Across", "longitudinal", "bounding_boxes", 15.5),
        ("Across", "lateral", "reference_points", -2.0),
        ("Across", "lateral", "bounding_boxes", -0.5),
    ]
    for name, direction, mode, expected in cases:
        got = a.object_distance(sim.entity(name), direction, mode)
        assert got == pytest.approx(expected, abs=1e-9), (name, direction, mode)
    # The standard's default mode is reference_points.
    assert a.object_distance(sim.entity("Ahead")) == pytest.approx(20.0, abs=1e-9)
    with pytest.raises(ValueError, match="distance_direction"):
        a.object_distance(sim.entity("Ahead"), "sideways")


def test_time_to_collision(tmp_path: Path):
    # time_to_collision.rs, first two cases, 1000 m north of the road (off it: straight
    # motion; the TTC is the same anywhere). At t = dt:
    # head-on: A at x = 0 heading 0 at 10 m/s, B at x = 50 heading π at 10 m/s: B's box
    #   x ∈ [46.5, 50.5], gap 46.5 − 3.5 = 43 m, closing 20 m/s → 2.15 s;
    # following: A at 0 at 20 m/s, C ahead at 30 at 10 m/s: C's box x ∈ [29.5, 33.5],
    #   gap 26 m, closing 10 m/s → 2.6 s.
    y = 1000.0
    sim = simulate(
        tmp_path,
        CURVE_R100,
        [
            ("A", world(0 - 10 * DT, y, 0), 10),
            ("B", world(50 + 10 * DT, y, math.pi), 10),
        ],
    )
    a, b = sim.entity("A"), sim.entity("B")
    assert (a.pose.x, b.pose.x) == (pytest.approx(0, abs=1e-12), pytest.approx(50, abs=1e-12))
    assert a.time_to_collision(b) == pytest.approx(2.15, abs=1e-9)
    sim = simulate(
        tmp_path,
        CURVE_R100,
        [("A", world(0 - 20 * DT, y, 0), 20), ("C", world(30 - 10 * DT, y, 0), 10)],
    )
    a, c = sim.entity("A"), sim.entity("C")
    assert a.time_to_collision(c) == pytest.approx(2.6, abs=1e-9)
    # Seen from C, A never reaches it from behind faster than C moves away? No: the closing
    # speed is symmetric, so C's TTC to A is the same 2.6 s.
    assert c.time_to_collision(a) == pytest.approx(2.6, abs=1e-9)


def test_time_headway(tmp_path: Path):
    # time_headway.rs on curve_r100's straight, lane −1 (y = −1.535, driven towards +x):
    # A at x = 100 at 20 m/s, B at 140 at 5 m/s: Δs = 40 m at 20 m/s → 2 s; from B's side
    # (B behind? no: A is 40 m behind B) B's headway to A is −40 / 5 = −8 s; a standing
    # caller has none.
    y = -1.535
    sim = simulate(
        tmp_path,
        CURVE_R100,
        [
            ("A", world(100 - 20 * DT, y), 20),
            ("B", world(140 - 5 * DT, y), 5),
            ("Parked", world(60, y), 0),
        ],
    )
    a, b, parked = sim.entity("A"), sim.entity("B"), sim.entity("Parked")
    assert a.time_headway(b) == pytest.approx(2.0, abs=TOL)
    assert b.time_headway(a) == pytest.approx(-8.0, abs=TOL)
    assert parked.time_headway(a) is None


def test_time_headway_is_a_vehicle_method(tmp_path: Path):
    walker_box = (0.0, 0.0, 0.9, 0.5, 0.5, 1.8)
    sim = simulate(
        tmp_path,
        CURVE_R100,
        [("Car", world(100, -1.535), 0), ("Walker", world(120, -5.0), 0, walker_box, "pedestrian")],
    )
    with pytest.raises(TypeError, match="vehicles"):
        sim.entity("Walker").time_headway(sim.entity("Car"))


def test_space_gap(tmp_path: Path):
    # space_gap.rs, straight road: A at s = 100 and B at s = 120 in lane −1: boxes
    # s ∈ [99.5, 103.5] and [119.5, 123.5]; A is behind: 103.5 − 119.5 = −16, from B +16.
    # C beside A in lane 1 (t = 1.535): t ranges [−2.535, −0.535] and [0.535, 2.535]; A is
    # right of C: −1.07. Oncoming D in lane 1 heading π at s = 130: s ∈ [126.5, 130.5];
    # A behind it: 103.5 − 126.5 = −23.
    sim = simulate(
        tmp_path,
        CURVE_R100,
        [
            ("A", world(100, -1.535), 0),
            ("B", world(120, -1.535), 0),
            ("C", world(100, 1.535), 0),
            ("D", world(130, 1.535, math.pi), 0),
        ],
    )
    a, b, c, d = (sim.entity(n) for n in "ABCD")
    assert a.space_gap(b) == pytest.approx(-16.0, abs=TOL)
    assert b.space_gap(a, "longitudinal") == pytest.approx(16.0, abs=TOL)
    assert a.space_gap(c, "lateral") == pytest.approx(-1.07, abs=TOL)
    assert c.space_gap(a, "lateral") == pytest.approx(1.07, abs=TOL)
    assert a.space_gap(d) == pytest.approx(-23.0, abs=TOL)


def test_route_coordinates(tmp_path: Path):
    # route_coords.rs: on curve_r100's arc, lane −1 at s = 550, 0.25 m left of the lane
    # centre: road s = 550, t = −1.285; lane s = 550, t = 0.25. On the straight in lane 1
    # (driven towards −s) at x = 100, y = 2.035, heading π: road s = 100, t = 2.035; lane s
    # counts from the section end: 600 + 50π − 100 = 500 + 50π, t = −0.5.
    sim = simulate(
        tmp_path,
        CURVE_R100,
        [("Arc", lane("0", -1, 550, 0.25), 0), ("Back", world(100, 2.035, math.pi), 0),
         ("Off", world(250, 50), 0)],
    )
    arc = sim.entity("Arc")
    assert arc.get_s_coord() == pytest.approx(550.0, abs=TOL)
    assert arc.get_t_coord("on_road") == pytest.approx(-1.285, abs=TOL)
    assert arc.get_s_coord("on_lane_section") == pytest.approx(550.0, abs=TOL)
    p = arc.get_route_point("on_lane")
    assert (p.kind, p.road_id, p.lane_section, p.lane_id) == ("lane", "0", 0, -1)
    assert p.s == pytest.approx(550.0, abs=TOL) and p.t == pytest.approx(0.25, abs=TOL)
    back = sim.entity("Back")
    p = back.get_route_point("on_road")
    assert (p.kind, p.road_id) == ("road", "0")
    assert p.s == pytest.approx(100.0, abs=TOL) and p.t == pytest.approx(2.035, abs=TOL)
    p = back.get_route_point("on_lane")
    assert p.lane_id == 1
    assert p.s == pytest.approx(500 + 50 * math.pi, abs=TOL) and p.t == pytest.approx(-0.5, abs=TOL)
    # (250, 50) is off the road: each route type has its error case.
    for route_type in ("on_road", "on_lane_section", "on_lane", "on_crossing"):
        with pytest.raises(oscsim.DomainError):
            sim.entity("Off").get_route_point(route_type)


def test_distance_along_route(tmp_path: Path):
    # distance_along_route.rs on common_junction_creator0: road 1 (100 m) → connecting road
    # 100 (L100) → road 3 (100 m), all towards +s. B at s = 20 on road 3 lane −1 is
    # 100 + L100 + 20 from the start and 80 before the end; A at (30, −1.5) on road 1 is 30
    # from the start, 170 + L100 before the end. On road 1 alone A is 30 / 70.
    sim = simulate(
        tmp_path,
        JUNCTION,
        [("A", world(30, -1.5), 0), ("B", lane("3", -1, 20), 0)],
    )
    a, b = sim.entity("A"), sim.entity("B")
    forward = [("1", 0.0, 100.0, None), ("100", 0.0, L100, None), ("3", 0.0, 100.0, None)]
    assert b.distance_along_route(forward) == pytest.approx(120 + L100, abs=TOL)
    assert b.distance_along_route(forward, "from_end") == pytest.approx(80.0, abs=TOL)
    assert a.distance_along_route(forward, from_="from_start") == pytest.approx(30.0, abs=TOL)
    assert a.distance_along_route(forward, "from_end") == pytest.approx(170 + L100, abs=TOL)
    assert a.distance_along_route([("1", 0.0, 100.0, None)], "from_end") == pytest.approx(70.0, abs=TOL)
    # Not on the route: B is on road 3 only.
    with pytest.raises(oscsim.DomainError):
        b.distance_along_route([("1", 0.0, 100.0, None)])
    with pytest.raises(oscsim.DomainError):
        a.distance_along_route([("no such road", 0.0, 1.0, None)])
    # The route is required.
    with pytest.raises(TypeError):
        a.distance_along_route()
