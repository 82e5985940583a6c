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
