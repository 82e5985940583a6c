"""Running scenarios from Python: the bundled scenario runs, and what Python reads equals what
`oscsim run` writes for the same scenario (same numbers, same event log)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import oscsim
from conftest import BUNDLED, REPO, run_cli


def csv_rows_from_python(sim: oscsim.Simulation) -> list:
    """The trajectory CSV rows (`engine::output::CsvWriter`'s layout: time with 3 decimals,
    the rest with 6, road columns empty off the road) formatted from the Python arrays."""
    t = sim.trajectories()
    rows = []
    for i in range(len(t["time"])):
        row = [f"{t['time'][i]:.3f}", str(t["id"][i]), t["name"][i]]
        row += [f"{t[k][i]:.6f}" for k in ("x", "y", "z", "h", "p", "r")]
        if t["road_id"][i]:
            row += [t["road_id"][i], str(t["lane_id"][i])]
            row += [f"{t[k][i]:.6f}" for k in ("offset", "t", "s")]
        else:
            row += ["", "", "", "", ""]
        row.append(f"{t['speed'][i]:.6f}")
        rows.append(",".join(row))
    return rows


def test_bundled_scenario_runs():
    sim = oscsim.Simulation(str(BUNDLED), dt=0.05, seed=1)
    assert sim.stop_reason is None and sim.running
    assert sim.time == 0.0 and sim.entities == []
    reason = sim.run()
    assert reason == sim.stop_reason
    assert reason == "stop_trigger"
    assert not sim.running
    assert [e.name for e in sim.entities] == ["Ego", "OverTaker"]
    # A step after the end does nothing.
    steps = sim.steps
    assert sim.step() == reason and sim.steps == steps


def test_trajectories_equal_cli_csv(tmp_path: Path, oscsim_bin: Path):
    csv = tmp_path / "cut_in.csv"
    run_cli(oscsim_bin, BUNDLED, "--csv", str(csv), "--dt", "0.05", "--seed", "1")
    sim = oscsim.Simulation(oscsim.Scenario.load(BUNDLED), dt=0.05, seed=1)
    sim.run()
    lines = csv.read_text().splitlines()
    assert lines[0] == "time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed"
    python_rows = csv_rows_from_python(sim)
    assert len(python_rows) == len(lines) - 1 > 2
    assert python_rows == lines[1:]


def test_events_equal_cli_event_log(tmp_path: Path, oscsim_bin: Path):
    log = tmp_path / "cut_in.jsonl"
    run_cli(oscsim_bin, BUNDLED, "--events", str(log))
    sim = oscsim.Simulation(BUNDLED)
    sim.run()
    assert sim.event_lines() == log.read_text().splitlines()
    events = sim.events()
    assert events[0]["element"] == "Init Ego TeleportAction"
    assert any(e["element"] == "CutInEvent" and e["to"] == "runningState" for e in events)


def test_stepping_by_hand_matches_run():
    a = oscsim.Simulation(BUNDLED)
    while a.step() is None:
        pass
    b = oscsim.Simulation(BUNDLED)
    b.run()
    assert a.steps == b.steps and a.time == b.time
    for ea, eb in zip(a.entities, b.entities):
        assert ea.pose == eb.pose and ea.speed == eb.speed


def test_entity_state():
    sim = oscsim.Simulation(BUNDLED, dt=0.05)
    sim.step()
    ego = sim.entity("Ego")
    # Init: LanePosition road 0, lane −2, s = 30, speed 25 (step); one step of 0.05 s moves it
    # 25 · 0.05 = 1.25 m along the lane centre (t = −4.5). Road 0 starts with a spiral of
    # curvature κ(s) = −0.004 + s · (0.004 + 1e-5) / 100 (highway.xodr), κ(30) = −0.002797;
    # along s that is, to first order in the step, 1.25 / (1 − κ(30) · t) = 1.265934 m. The
    # engine's lane following differs from the first-order value by O(dt²) terms in κ'
    # (a few 1e-6 m here): tolerance 1e-5 m.
    assert ego.time == pytest.approx(0.05)
    assert sim.in_scene("Ego") and ego.kind == "vehicle" and ego.vehicle_category == "car"
    assert ego.role is None  # the bundled Vehicle has no role attribute
    assert ego.speed == 25.0
    rp = ego.road_position
    assert rp is not None and (rp.road_id, rp.lane_id) == ("0", -2)
    assert rp.s == pytest.approx(31.265934, abs=1e-5) and rp.t == pytest.approx(-4.5, abs=1e-9)
    assert ego.velocity.x == pytest.approx(25.0) and ego.velocity.y == pytest.approx(0.0, abs=1e-9)
    assert ego.odometer == pytest.approx(1.25)
    bb = ego.bounding_box
    assert (bb.center.x, bb.length, bb.width, bb.height) == (1.4, 5.0, 2.0, 1.5)
    with pytest.raises(KeyError):
        sim.entity("Nobody")
    # Before the first step no entity is in the scene.
    fresh = oscsim.Simulation(BUNDLED)
    assert not fresh.in_scene("Ego")
    with pytest.raises(KeyError):
        fresh.entity("Ego")


def test_trajectory_of_one_entity_and_frame():
    sim = oscsim.Simulation(BUNDLED)
    sim.run()
    ego = sim.trajectory("Ego")
    # One row per frame: t = 0, 0.05, …, the final time.
    assert len(ego["time"]) == sim.steps + 1
    assert np.all(np.diff(ego["time"]) > 0)
    assert ego["x"][-1] == sim.entity("Ego").pose.x
    pandas = pytest.importorskip("pandas")
    frame = sim.trajectory_frame()
    assert isinstance(frame, pandas.DataFrame) and len(frame) == sim.trajectory_rows


def test_shared_road_network():
    # One RoadNetwork for several simulations: the same results as each reading its own.
    net = oscsim.RoadNetwork.load(BUNDLED.parent.parent / "roads" / "highway.xodr")
    a = oscsim.Simulation(BUNDLED, road_network=net, duration=2.0)
    b = oscsim.Simulation(BUNDLED, road_network=net, duration=2.0)
    c = oscsim.Simulation(BUNDLED, duration=2.0)
    for s in (a, b, c):
        s.run()
    assert a.entity("Ego").pose == b.entity("Ego").pose == c.entity("Ego").pose


def test_parameters_at_load_and_between_steps():
    scenario = oscsim.Scenario.load(BUNDLED, params={"EgoSpeed": 20})
    assert scenario.parameters["EgoSpeed"] == 20.0
    assert scenario.entity_names == ["Ego", "OverTaker"]
    sim = oscsim.Simulation(scenario)
    sim.step()
    assert sim.entity("Ego").speed == 20.0
    assert sim.parameter("CutInGap") == 10.0
    sim.set_parameter("CutInGap", 12)
    assert sim.parameter("$CutInGap") == 12.0 and isinstance(sim.parameter("CutInGap"), float)
    with pytest.raises(KeyError):
        sim.set_parameter("NoSuchParameter", 1)
    with pytest.raises(ValueError):
        sim.set_parameter("CutInGap", "fast")
    sim.set_user_value("SutState", "braking")  # read by UserDefinedValueConditions, if any


def test_record_off_and_clear():
    sim = oscsim.Simulation(BUNDLED, record=False, duration=1.0)
    assert sim.run() == "duration"
    assert sim.trajectory_rows == 0 and math.isclose(sim.time, 1.0)
    sim = oscsim.Simulation(BUNDLED, duration=1.0)
    sim.run()
    # 21 frames (t = 0 … 1 s) of 2 entities.
    assert sim.trajectory_rows == 42
    sim.clear_trajectories()
    assert sim.trajectory_rows == 0


def test_control_forms_and_errors():
    # Ego at 25 m/s after the first step; 1 s at −5 m/s² under external control: 25 − 5 = 20.
    sim = oscsim.Simulation(BUNDLED)
    sim.step()
    with pytest.raises(oscsim.SimulationError, match="external"):
        sim.control("Ego", acceleration=-5.0)
    sim.attach_external("Ego")
    sim.control("Ego", acceleration=-5.0)
    for _ in range(20):
        sim.step()
    assert sim.entity("Ego").speed == pytest.approx(20.0, abs=1e-9)
    # A pose: where Ego stands at the end of the next step.
    target = oscsim.Pose(100.0, -4.5, 0.0, 0.0)
    sim.control("Ego", pose=target)
    sim.step()
    assert sim.entity("Ego").pose.x == pytest.approx(100.0) and sim.entity("Ego").pose.y == pytest.approx(-4.5)
    with pytest.raises(ValueError, match="one of"):
        sim.control("Ego", acceleration=1.0, throttle=0.5)
    with pytest.raises(ValueError, match="0..1"):
        sim.control("Ego", throttle=1.5)
    with pytest.raises(ValueError, match="finite"):
        sim.control("Ego", acceleration=float("nan"))
    with pytest.raises(oscsim.SimulationError):
        sim.attach_external("Nobody")
    sim.control("Ego", throttle=0.0, brake=1.0)
    v = sim.entity("Ego").speed
    sim.step()
    assert sim.entity("Ego").speed < v


def test_python_controller_class():
    class Brake:
        calls = 0

        def step(self, sim, entity):
            Brake.calls += 1
            assert entity.name == "Ego" and entity.time == sim.time
            return oscsim.Acceleration(-2.0)

    sim = oscsim.Simulation(BUNDLED, duration=1.0)
    sim.set_controller("Ego", Brake())
    assert sim.run() == "duration"
    # Called before each step after the first (which places Ego): 19 times; 19 steps of
    # −2 m/s² · 0.05 s from 25 m/s.
    assert Brake.calls == 19
    assert sim.entity("Ego").speed == pytest.approx(25.0 - 2.0 * 0.05 * 19, abs=1e-9)
    with pytest.raises(TypeError):
        sim.set_controller("Ego", object())


def test_roles_declared_and_drawn():
    # traffic_roles.xosc (engine tests): the Ego is declared with role="ambulance"; the
    # TrafficSourceAction spawns 2 vehicles/s whose roles are drawn from civil 3, police 1,
    # ambulance 0, so after 2 s every spawned vehicle is civil or police, never ambulance.
    path = REPO / "crates" / "engine" / "tests" / "files" / "entities" / "traffic_roles.xosc"
    sim = oscsim.Simulation(path, duration=2.0)
    sim.run()
    assert sim.entity("Ego").role == "ambulance"
    spawned = [e for e in sim.entities if e.name != "Ego"]
    assert spawned, "the source spawned vehicles"
    assert {e.role for e in spawned} <= {"civil", "police"}
