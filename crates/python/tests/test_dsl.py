"""OpenSCENARIO DSL scenarios from Python: loaded through the same front door as `oscsim run`
(`Scenario.load(path, road=…, seed=…)`), they run the same trajectories, byte for byte."""

from __future__ import annotations

from pathlib import Path

import pytest

import oscsim
from conftest import BUNDLED, HIGHWAY, REPO, run_cli
from test_run import csv_rows_from_python

OSC = REPO / "examples" / "scenarios" / "cut_in_highway.osc"


@pytest.mark.parametrize("seed", [1, 7])
def test_dsl_cut_in_from_python_writes_the_cli_csv(tmp_path: Path, oscsim_bin: Path, seed: int):
    cli_csv = tmp_path / "cli.csv"
    run_cli(oscsim_bin, OSC, "--road", str(HIGHWAY), "--csv", str(cli_csv), "--seed", str(seed))
    scenario = oscsim.Scenario.load(OSC, road=HIGHWAY, seed=seed)
    assert scenario.language == "dsl"
    assert scenario.entity_names == ["ego", "overtaker"]
    # The do tree's phases by path, the root last (docs/dsl.md).
    assert {"do.get_ahead", "do.cut_in", "do.brake"} <= set(scenario.phases)
    assert scenario.phases[-1] == "do"
    py_csv = tmp_path / "python.csv"
    sim = oscsim.Simulation(scenario, seed=seed, csv=py_csv)
    sim.run()
    cli_bytes = cli_csv.read_bytes()
    assert py_csv.read_bytes() == cli_bytes
    # The arrays Python reads are the same rows (over 6.75 s of phases, 2 vehicles, dt 0.05).
    lines = cli_bytes.decode().splitlines()
    assert csv_rows_from_python(sim) == lines[1:]
    assert len(lines) - 1 > 2 * 135


def test_a_path_loads_through_the_front_door_too(tmp_path: Path):
    by_path = oscsim.Simulation(str(OSC), road=str(HIGHWAY), seed=3)
    by_scenario = oscsim.Simulation(oscsim.Scenario.load(OSC, road=HIGHWAY, seed=3), seed=3)
    assert by_path.run() == by_scenario.run()
    assert csv_rows_from_python(by_path) == csv_rows_from_python(by_scenario)
    assert oscsim.Scenario.load(BUNDLED).language == "xml"
    assert oscsim.Scenario.load(BUNDLED).phases == []


def test_bad_input_raises_with_the_place():
    with pytest.raises(oscsim.ScenarioError) as e:
        oscsim.Scenario.load(OSC)  # names no road network itself
    assert e.value.file == str(OSC) and (e.value.line, e.value.column) == (1, 1)
    assert "expected a road network" in str(e.value)
    with pytest.raises(oscsim.ScenarioError) as e:
        oscsim.Scenario.load(BUNDLED, road=HIGHWAY)  # XML names its own
    assert (e.value.line, e.value.column) == (1, 1)
    with pytest.raises(oscsim.ScenarioError) as e:
        oscsim.Scenario.load(OSC, {"x": 1}, road=HIGHWAY)  # the DSL varies by seed
    assert "found 'x'" in str(e.value)
    with pytest.raises(ValueError):
        oscsim.Simulation(oscsim.Scenario.load(OSC, road=HIGHWAY), road=HIGHWAY)
