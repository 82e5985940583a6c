"""OpenSCENARIO DSL scenarios from Python, and `call` of external methods bound with
`Simulation.bind` (issue 28 step 4): the bound function runs after the step whose event log
records the call, with the call's arguments."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, List, Tuple

import pytest

import oscsim
from conftest import REPO

DSL = REPO / "crates" / "dsl_runtime" / "tests"
# call_external.osc: `call log_speed("ego", 20mps)` logged at 2.0 s (after a 2 s drive at
# 10 m/s from s = 50 m: ego at s = 70 m), the handler's `call note(1, true)` at 2.05 s (the
# first step whose start sees the 20 m/s step above 15 m/s). Worked in the file's comment. A
# call logged at t runs in the step from t to t + dt; the bound function runs after it, at
# sim.time = t + dt, seeing that step's frame: after the call at 2.0 s ego has driven 0.05 s at
# the new 20 m/s, s = 70 + 20 · 0.05 = 71 m.
CALLS = DSL / "scenarios" / "call_external.osc"
STRAIGHT = DSL / "roads" / "straight.xodr"
STEP_TOL = 1e-9


def test_bound_functions_run_at_the_step_of_their_call():
    sim = oscsim.Simulation(str(CALLS), dt=0.05, seed=0, road=str(STRAIGHT))
    assert [m for m, _ in sim.external_calls] == ["log_speed", "note"]
    seen: List[Tuple[str, float, Any]] = []

    def log_speed(name: str, v: float) -> None:
        seen.append(("log_speed", sim.time, (name, v, sim.entity("ego").road_position.s)))

    sim.bind("log_speed", log_speed)
    sim.bind("note", lambda n, flag: seen.append(("note", sim.time, (n, flag))))
    assert sim.run() == "stories_complete"
    assert [s[0] for s in seen] == ["log_speed", "note"]
    name, t, (who, v, s) = seen[0]
    assert abs(t - 2.05) < STEP_TOL and who == "ego" and abs(v - 20.0) < STEP_TOL
    assert abs(s - 71.0) < 1e-6, s
    assert abs(seen[1][1] - 2.10) < STEP_TOL and seen[1][2] == (1.0, True)
    # The event log has each call at the time of the step that ran it.
    calls = [e for e in sim.events() if e["kind"] == "customCommand" and e["type"] == "call"]
    assert [(e["time"], e["content"]) for e in calls] == [
        (2.0, 'log_speed("ego", 20.0)'),
        (2.05, "note(1.0, true)"),
    ]


# call_named.osc: `call log("ego", flag: true, v: 20mps)` of `log(name, v, n = 3,
# flag = false)` at 1.0 s and the handler's `call note(flag: true, n: 2)` at 1.05 s: the host's
# functions take the arguments in the methods' declaration order, defaults filled in.
NAMED = DSL / "scenarios" / "call_named.osc"


def test_named_arguments_reach_the_function_in_declaration_order():
    sim = oscsim.Simulation(str(NAMED), dt=0.05, seed=0, road=str(STRAIGHT))
    seen: List[Tuple[str, Any]] = []
    sim.bind("log", lambda *a: seen.append(("log", a)))
    sim.bind("note", lambda *a: seen.append(("note", a)))
    assert sim.run() == "stories_complete"
    assert seen == [("log", ("ego", 20.0, 3.0, True)), ("note", (2.0, True))], seen


def test_an_unbound_external_method_is_an_error_naming_the_call():
    sim = oscsim.Simulation(str(CALLS), dt=0.05, seed=0, road=str(STRAIGHT))
    sim.bind("log_speed", lambda *a: None)
    with pytest.raises(oscsim.ScenarioError) as info:
        sim.step()
    e = info.value
    # `call note(1, true)` is at line 13, column 9 of the file.
    assert (Path(e.file), e.line, e.column) == (CALLS, 13, 9), str(e)
    assert "external method `note`" in str(e)
    assert sim.steps == 0


def test_an_exception_in_a_bound_function_propagates():
    sim = oscsim.Simulation(str(CALLS), dt=0.05, seed=0, road=str(STRAIGHT))

    def fails(*args: Any) -> None:
        raise RuntimeError("host failed")

    sim.bind("log_speed", fails)
    sim.bind("note", lambda *a: None)
    with pytest.raises(RuntimeError, match="host failed"):
        sim.run()
    # Raised after the step that ran the call logged at 2.0 s.
    assert abs(sim.time - 2.05) < STEP_TOL


def test_a_dsl_scenario_that_does_not_plan_raises_with_its_place():
    bad = DSL / "scenarios" / "err_on_call.osc"
    with pytest.raises(oscsim.ScenarioError) as info:
        oscsim.Simulation(str(bad), road=str(STRAIGHT))
    assert (Path(info.value.file), info.value.line, info.value.column) == (bad, 8, 14)


# external_value.osc (worked in its comment): `until ticks() > 40` reads the host's function
# before each step; `call log_speed("ego", 20mps)` runs after the step that ends the drive.
VALUE = DSL / "scenarios" / "external_value.osc"


def test_bindings_at_load_read_a_method_in_until_and_run_its_call():
    ticks = [0]
    seen: List[Tuple[float, Any]] = []

    def count() -> int:
        ticks[0] += 1
        return ticks[0]

    sim = oscsim.Simulation(
        str(VALUE),
        dt=0.05,
        seed=0,
        road=str(STRAIGHT),
        bindings={
            "ticks": count,
            "log_speed": lambda name, v: seen.append((sim.time, (name, v, sim.entity("ego").road_position.s))),
        },
    )
    assert sim.run() == "stories_complete"
    # ticks() is 41 before the step at 2.0 s: the drive ends there at s = 70 m, the call is
    # logged at 2.0 s and its function runs after that step (sim.time 2.05 s, ego still at
    # 10 m/s in it: 70.5 m); ego then drives at 20 m/s from 2.05 s: 89.5 m at 3.0 s.
    assert len(seen) == 1
    t, (who, v, s) = seen[0]
    assert abs(t - 2.05) < STEP_TOL and who == "ego" and abs(v - 20.0) < STEP_TOL
    assert abs(s - 70.5) < 1e-6, s
    calls = [e for e in sim.events() if e["kind"] == "customCommand" and e["type"] == "call"]
    assert [(e["time"], e["content"]) for e in calls] == [(2.0, 'log_speed("ego", 20.0)')]
    traj = sim.trajectory("ego")
    at3 = [s for t, s in zip(traj["time"], traj["s"]) if abs(t - 3.0) < STEP_TOL]
    assert at3 and abs(at3[0] - 89.5) < 1e-6, at3


def test_an_unbound_method_is_refused_at_load_with_its_place():
    with pytest.raises(oscsim.ScenarioError) as info:
        oscsim.Simulation(
            str(VALUE), dt=0.05, seed=0, road=str(STRAIGHT), bindings={"log_speed": lambda *a: None}
        )
    e = info.value
    # `until ticks() > 40`: the comparison at line 19, column 19.
    assert (Path(e.file), e.line, e.column) == (VALUE, 19, 19), str(e)
    assert "external method `ticks`" in str(e)
