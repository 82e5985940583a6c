"""Errors cross the boundary as Python exceptions with the place in the file; a panic inside
oscsim becomes `InternalError`, and the interpreter lives on."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import oscsim
from conftest import BUNDLED, HIGHWAY, world, write_scenario


def test_malformed_scenario_raises_with_file_line_column(tmp_path: Path):
    good = write_scenario(tmp_path, HIGHWAY, [("Ego", world(0, 0), 10.0)])
    text = good.read_text()
    # A dynamics shape the XSD does not have, on a line of its own.
    bad_text = text.replace('dynamicsShape="step"', '\n        dynamicsShape="stepp"')
    bad = tmp_path / "bad.xosc"
    bad.write_text(bad_text)
    lines = bad_text.splitlines()
    line = next(i for i, l in enumerate(lines, 1) if 'dynamicsShape="stepp"' in l)
    # 1-based column of the value's first character, where the reader points.
    column = lines[line - 1].index("stepp") + 1
    with pytest.raises(oscsim.ScenarioError) as info:
        oscsim.Scenario.load(bad)
    e = info.value
    assert (e.file, e.line, e.column) == (str(bad), line, column)
    assert f"{bad}:{line}:{column}" in str(e)
    assert "stepp" in str(e)
    # The same through Simulation(path).
    with pytest.raises(oscsim.ScenarioError) as info:
        oscsim.Simulation(str(bad))
    assert (info.value.line, info.value.column) == (line, column)


def test_broken_xml_raises_with_position(tmp_path: Path):
    bad = tmp_path / "broken.xosc"
    bad.write_text('<?xml version="1.0"?>\n<OpenSCENARIO>\n  <FileHeader revMajor="1"\n</OpenSCENARIO>\n')
    with pytest.raises(oscsim.ScenarioError) as info:
        oscsim.Scenario.load(bad)
    assert info.value.file == str(bad) and info.value.line is not None


def test_missing_file_and_bad_parameter():
    with pytest.raises(oscsim.ScenarioError):
        oscsim.Scenario.load("/nonexistent/x.xosc")
    with pytest.raises(oscsim.ScenarioError) as info:
        oscsim.Scenario.load(BUNDLED, params={"EgoSpeed": "fast"})
    assert info.value.file == str(BUNDLED)
    with pytest.raises(oscsim.ScenarioError):
        oscsim.Scenario.load(BUNDLED, params={"NoSuchParameter": 1})
    with pytest.raises(TypeError):
        oscsim.Scenario.load(BUNDLED, params={"EgoSpeed": [1, 2]})


def test_bad_configuration_raises():
    with pytest.raises(oscsim.ScenarioError, match="dt"):
        oscsim.Simulation(BUNDLED, dt=0.0)
    with pytest.raises(oscsim.ScenarioError):
        oscsim.Simulation(BUNDLED, dt=float("nan"))


def test_road_network_errors(tmp_path: Path):
    bad = tmp_path / "bad.xodr"
    bad.write_text("<OpenDRIVE>\n  <header revMajor='1' revMinor='8'/>\n  <road id='1' length='x'/>\n</OpenDRIVE>\n")
    with pytest.raises(oscsim.ScenarioError) as info:
        oscsim.RoadNetwork.load(bad)
    assert info.value.file == str(bad) and info.value.line == 3
    net = oscsim.RoadNetwork.load(HIGHWAY)
    assert net.road_ids and net.road_length(net.road_ids[0]) > 0


def test_panic_raises_internal_error_and_interpreter_lives():
    with pytest.raises(oscsim.InternalError, match="boom"):
        oscsim._oscsim._debug_panic("boom")
    # An InternalError is an ordinary Exception (PyO3's PanicException is not).
    assert issubclass(oscsim.InternalError, Exception)
    sim = oscsim.Simulation(BUNDLED)
    sim.step()
    with pytest.raises(oscsim.InternalError):
        sim._debug_panic()
    # The simulation that panicked mid-call refuses further use …
    with pytest.raises(oscsim.InternalError, match="unusable"):
        sim.step()
    # … and everything else goes on.
    other = oscsim.Simulation(BUNDLED)
    assert other.run() == "stop_trigger"


def test_panic_in_a_fresh_interpreter_does_not_abort():
    code = (
        "import oscsim\n"
        "try:\n"
        "    oscsim._oscsim._debug_panic('x')\n"
        "except oscsim.InternalError:\n"
        "    print('caught')\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "caught"
