"""oscsim: an ASAM OpenSCENARIO scenario engine, driven from Python.

Load a scenario, step it, read the entities' states, the event log and the trajectories::

    import oscsim

    sim = oscsim.Simulation("examples/scenarios/cut_in_highway.xosc", dt=0.05, seed=1)
    reason = sim.run()                       # or: while sim.step() is None: ...
    ego = sim.entity("Ego")
    print(sim.time, reason, ego.pose.x, ego.speed)
    traj = sim.trajectories()                # NumPy arrays by column, the CSV's rows

The engine is Rust (the native module ``oscsim._oscsim``); this module adds the Python-side
conveniences: parsed events, per-entity trajectories and data frames.
"""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional

from . import _oscsim
from ._oscsim import (
    BoundingBox,
    DomainError,
    Entity,
    InternalError,
    OscsimError,
    Pose,
    RoadNetwork,
    RoadPosition,
    RoutePoint,
    Scenario,
    ScenarioError,
    SimulationError,
    Vector3,
    __version__,
)

__all__ = [
    "BoundingBox",
    "DomainError",
    "Entity",
    "InternalError",
    "OscsimError",
    "Pose",
    "RoadNetwork",
    "RoadPosition",
    "RoutePoint",
    "Scenario",
    "ScenarioError",
    "Simulation",
    "SimulationError",
    "Vector3",
    "__version__",
]


class Simulation(_oscsim.Simulation):
    """One run of a scenario, stepped from Python.

    ``Simulation(scenario, dt=0.05, seed=1, duration=None, max_time=3600.0, record=True,
    params=None)``: ``scenario`` is a :class:`Scenario` or the path of a .xosc file (loaded
    with ``params``, global parameter overrides by name).
    """

    def events(self) -> List[Dict[str, Any]]:
        """The event log so far, one dict per record (the objects of ``oscsim run --events``:
        ``{"time", "element", "kind", "from", "transition", "to"}`` for storyboard
        transitions)."""
        return [json.loads(line) for line in self.event_lines()]

    def trajectory(self, name: str) -> Dict[str, Any]:
        """The recorded trajectory of entity ``name``: the columns of :meth:`trajectories`,
        restricted to its rows."""
        columns = self.trajectories()
        rows = columns["name"] == name
        return {key: values[rows] for key, values in columns.items()}

    def trajectory_frame(self) -> Any:
        """The recorded trajectories as a pandas DataFrame, or a polars DataFrame when pandas
        is not installed. Raises ``ImportError`` when neither is."""
        columns = self.trajectories()
        try:
            import pandas

            return pandas.DataFrame(columns)
        except ImportError:
            pass
        try:
            import polars

            return polars.DataFrame({k: list(v) if v.dtype == object else v for k, v in columns.items()})
        except ImportError:
            raise ImportError("trajectory_frame needs pandas or polars; trajectories() gives NumPy arrays") from None


def _entity_names(sim: Simulation) -> List[str]:
    return [e.name for e in sim.entities]


def run(path: str, dt: float = 0.05, seed: int = 1, params: Optional[Dict[str, Any]] = None) -> Simulation:
    """Loads ``path``, runs it to its end and returns the finished simulation."""
    sim = Simulation(path, dt=dt, seed=seed, params=params)
    sim.run()
    return sim
