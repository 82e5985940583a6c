"""OSI ground truth from Python: the bytes decode with the official ASAM OSI bindings (`osi3`
from osi-python 3.8.0) and equal, frame for frame and byte for byte, the trace that
`oscsim run --osi` writes for the same scenario (same entities, same ids)."""

from __future__ import annotations

import struct
from pathlib import Path
from typing import List

import pytest

import oscsim
from conftest import BUNDLED, run_cli

osi_groundtruth_pb2 = pytest.importorskip("osi3.osi_groundtruth_pb2")


def read_osi_trace(path: Path) -> List[bytes]:
    """The messages of a `.osi` trace: each a little-endian uint32 length, then the message
    (ASAM OSI 3.8 §2.2.6.1)."""
    data = path.read_bytes()
    frames, pos = [], 0
    while pos < len(data):
        (n,) = struct.unpack_from("<I", data, pos)
        frames.append(data[pos + 4 : pos + 4 + n])
        pos += 4 + n
    assert pos == len(data)
    return frames


def test_ground_truth_equals_cli_trace(tmp_path: Path, oscsim_bin: Path):
    trace = tmp_path / "cut_in.osi"
    run_cli(oscsim_bin, BUNDLED, "--osi", str(trace))
    cli = read_osi_trace(trace)

    sim = oscsim.Simulation(BUNDLED, osi=True)
    assert sim.osi_ground_truth() == b""
    python: List[bytes] = []
    while True:
        reason = sim.step()
        frames = sim.osi_ground_truths()
        python.extend(frames)
        if reason is not None:
            # The call that ends the run moves nothing and makes no frame.
            assert frames == []
            break
        assert frames[-1] == sim.osi_ground_truth()
    # The current state's GroundTruth is still there after the end.
    assert sim.osi_ground_truth() == python[-1]
    # One frame at t = 0 and one per step (10 s of 0.05 s steps: 200 + 1).
    assert len(python) == sim.steps + 1 == len(cli)
    assert python == cli

    first = osi_groundtruth_pb2.GroundTruth.FromString(python[0])
    last = osi_groundtruth_pb2.GroundTruth.FromString(python[-1])
    # Lanes in the first frame only (oscsim run's default --osi-static first).
    assert len(first.lane) > 0 and len(last.lane) == 0
    names = [e.name for e in sim.entities]
    for gt in (first, last):
        assert len(gt.moving_object) == len(names) == 2
        ids = [o.id.value for o in gt.moving_object]
        assert len(set(ids)) == 2
        assert gt.host_vehicle_id.value == ids[names.index("Ego")]
    # Stable ids through the run.
    assert [o.id.value for o in first.moving_object] == [o.id.value for o in last.moving_object]
    # The last frame's time stamp is the simulation's time.
    assert last.timestamp.seconds + last.timestamp.nanos * 1e-9 == pytest.approx(sim.time, abs=1e-9)
    # The bounding-box centre of Ego (reference point + 1.4 m along the heading) in OSI.
    ego = sim.entity("Ego")
    base = last.moving_object[names.index("Ego")].base
    assert base.dimension.length == 5.0 and base.dimension.width == 2.0
    import math

    assert base.position.x == pytest.approx(ego.pose.x + 1.4 * math.cos(ego.pose.h), abs=1e-9)
    assert base.position.y == pytest.approx(ego.pose.y + 1.4 * math.sin(ego.pose.h), abs=1e-9)


def test_ground_truth_needs_osi_true():
    sim = oscsim.Simulation(BUNDLED)
    sim.step()
    with pytest.raises(oscsim.OscsimError, match="osi=True"):
        sim.osi_ground_truth()
    with pytest.raises(ValueError, match="osi_static"):
        oscsim.Simulation(BUNDLED, osi=True, osi_static="sometimes")
