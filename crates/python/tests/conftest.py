"""Shared fixtures of the oscsim Python tests: repository paths, the oscsim binary, and a
writer of small scenarios that place entities at given poses."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path
from typing import List, Optional, Sequence

import pytest

REPO = Path(__file__).resolve().parents[3]
CORPUS = Path(os.environ.get("CORPUS", REPO.parent / "shared" / "corpus"))
BUNDLED = REPO / "examples" / "scenarios" / "cut_in_highway.xosc"
HIGHWAY = REPO / "examples" / "roads" / "highway.xodr"
CURVE_R100 = CORPUS / "esmini" / "xodr" / "curve_r100.xodr"


@pytest.fixture(scope="session")
def oscsim_bin() -> Path:
    """The release `oscsim` binary (.ci/run builds it before the tests; OSCSIM overrides)."""
    path = Path(os.environ.get("OSCSIM", REPO / "target" / "release" / "oscsim"))
    if not path.is_file():
        pytest.fail(f"no oscsim binary at {path}: cargo build --release -p oscsim-cli")
    return path


def run_cli(oscsim_bin: Path, scenario: Path, *args: str) -> None:
    """`oscsim run SCENARIO ARGS…` with the outputs' clock pinned, as the golden check does."""
    env = dict(os.environ, SOURCE_DATE_EPOCH="0")
    subprocess.run(
        [str(oscsim_bin), "run", str(scenario), "--quiet", *args],
        check=True,
        env=env,
        stdout=subprocess.DEVNULL,
    )


# The test car of the engine's domain tests (crates/engine/tests/support/domain.rs): length 4,
# width 2, height 1.5, centre (1.5, 0, 0.75), so it spans x ∈ [−0.5, 3.5], y ∈ [−1, 1].
CAR_BOX = (1.5, 0.0, 0.75, 4.0, 2.0, 1.5)


def _object(name: str, box: Sequence[float], kind: str) -> str:
    cx, cy, cz, length, width, height = box
    bb = (
        f'<BoundingBox><Center x="{cx}" y="{cy}" z="{cz}"/>'
        f'<Dimensions width="{width}" length="{length}" height="{height}"/></BoundingBox>'
    )
    if kind == "pedestrian":
        return (
            f'<ScenarioObject name="{name}"><Pedestrian name="{name}" mass="80" '
            f'pedestrianCategory="pedestrian">{bb}<Properties/></Pedestrian></ScenarioObject>'
        )
    # Rear axle at the reference point, as the domain tests' vehicles have.
    return (
        f'<ScenarioObject name="{name}"><Vehicle name="{name}" vehicleCategory="car">{bb}'
        '<Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/>'
        '<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.8" positionZ="0.4"/>'
        '<RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles>'
        "<Properties/></Vehicle></ScenarioObject>"
    )


def _init(name: str, position: str, speed: float) -> str:
    return (
        f'<Private entityRef="{name}"><PrivateAction><TeleportAction><Position>{position}</Position>'
        "</TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction>"
        '<SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/>'
        f'<SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget>'
        "</SpeedAction></LongitudinalAction></PrivateAction></Private>"
    )


def world(x: float, y: float, h: float = 0.0) -> str:
    """A WorldPosition."""
    return f'<WorldPosition x="{x!r}" y="{y!r}" z="0" h="{h!r}"/>'


def lane(road: str, lane_id: int, s: float, offset: float = 0.0) -> str:
    """A LanePosition."""
    return f'<LanePosition roadId="{road}" laneId="{lane_id}" s="{s!r}" offset="{offset!r}"/>'


def write_scenario(
    folder: Path,
    road: Path,
    entities: List[tuple],
    stop_time: float = 1.0,
    name: str = "placed.xosc",
    extra_parameters: str = "",
) -> Path:
    """A scenario on `road` with `entities`, each (name, position xml, speed[, box[, kind]]),
    that ends at `stop_time`."""
    objects, inits = [], []
    for entity in entities:
        ename, position, speed = entity[:3]
        box: Sequence[float] = entity[3] if len(entity) > 3 and entity[3] else CAR_BOX
        kind: Optional[str] = entity[4] if len(entity) > 4 else "vehicle"
        objects.append(_object(ename, box, kind or "vehicle"))
        inits.append(_init(ename, position, speed))
    text = f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="3" date="2026-01-01T00:00:00" description="test" author="oscsim tests"/>
  <ParameterDeclarations>{extra_parameters}</ParameterDeclarations>
  <CatalogLocations/>
  <RoadNetwork><LogicFile filepath="{road}"/></RoadNetwork>
  <Entities>{"".join(objects)}</Entities>
  <Storyboard>
    <Init><Actions>{"".join(inits)}</Actions></Init>
    <StopTrigger><ConditionGroup><Condition name="End" delay="0" conditionEdge="none">
      <ByValueCondition><SimulationTimeCondition value="{stop_time}" rule="greaterOrEqual"/></ByValueCondition>
    </Condition></ConditionGroup></StopTrigger>
  </Storyboard>
</OpenSCENARIO>
"""
    path = folder / name
    path.write_text(text)
    return path
