"""Cost of stepping from Python: per-step time of a Python loop of `Simulation.step()` minus
that of `Simulation.run()`, which runs the same steps in one call (the loop in Rust, the same
engine, the same recording). The difference is what each step pays for crossing the boundary:
the Python call, argument and result conversion, the panic guard and the simulation's lock.

Usage: python scripts/python_overhead.py [SCENARIO] [REPEATS]
  SCENARIO  default examples/scenarios/cut_in_highway.xosc (2 entities, 200 steps of 0.05 s)
  REPEATS   default 200 runs of each kind; the minimum per-step time over the runs (the run
            least disturbed by other processes) and the median are reported.

Needs the package installed (pip install ./crates/python). Prints one line per figure.
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

import oscsim

ROOT = Path(__file__).resolve().parents[1]


def per_step(scenario: oscsim.Scenario, loop_in_python: bool, record: bool) -> float:
    sim = oscsim.Simulation(scenario, record=record)
    start = time.perf_counter()
    if loop_in_python:
        step = sim.step
        while step() is None:
            pass
    else:
        sim.run()
    elapsed = time.perf_counter() - start
    return elapsed / sim.steps


def main() -> None:
    path = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "examples/scenarios/cut_in_highway.xosc"
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    scenario = oscsim.Scenario.load(path)
    print(f"scenario {path} ({len(scenario.entity_names)} entities), {repeats} runs of each kind")
    for record in (False, True):
        # Interleaved so that a busy machine hurts both kinds alike.
        rust, python = [], []
        for _ in range(repeats):
            rust.append(per_step(scenario, False, record))
            python.append(per_step(scenario, True, record))
        for label, pick in (("min", min), ("median", statistics.median)):
            r, p = pick(rust), pick(python)
            print(
                f"record={record} {label}: run() {r * 1e6:.2f} us/step, step() loop "
                f"{p * 1e6:.2f} us/step, overhead {(p - r) * 1e6:.2f} us/step"
            )


if __name__ == "__main__":
    main()
