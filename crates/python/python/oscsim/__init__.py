"""oscsim: an ASAM OpenSCENARIO scenario engine, driven from Python.

Load a scenario, step it, read the entities' states, the event log and the trajectories::

    import oscsim

    sim = oscsim.Simulation("examples/scenarios/cut_in_highway.xosc", dt=0.05, seed=1)
    # or an OpenSCENARIO DSL scenario, through the same front door:
    # oscsim.Scenario.load("examples/scenarios/cut_in_highway.osc", road="examples/roads/highway.xodr", seed=7)
    reason = sim.run()                       # or: while sim.step() is None: ...
    ego = sim.entity("Ego")
    print(sim.time, reason, ego.pose.x, ego.speed)
    traj = sim.trajectories()                # NumPy arrays by column, the CSV's rows

The engine is Rust (the native module ``oscsim._oscsim``); this module adds the Python-side
conveniences: parsed events, per-entity trajectories and data frames.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Union

try:  # Python >= 3.8
    from typing import Protocol
except ImportError:  # pragma: no cover
    Protocol = object  # type: ignore

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
    "Acceleration",
    "BoundingBox",
    "Controller",
    "DomainError",
    "Entity",
    "InternalError",
    "OscsimError",
    "Pedals",
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


@dataclass(frozen=True)
class Acceleration:
    """A command for an externally controlled entity: ``acceleration`` along its direction of
    travel (m/s²) and, optionally, the front wheel angle ``steering`` (rad, positive left;
    None keeps the lane as the default controller does)."""

    acceleration: float
    steering: Optional[float] = None


@dataclass(frozen=True)
class Pedals:
    """A command for an externally controlled vehicle: ``throttle`` and ``brake`` pedals (0..1)
    and the ``steering_wheel`` angle (rad, positive left), through the engine's vehicle
    model."""

    throttle: float = 0.0
    brake: float = 0.0
    steering_wheel: float = 0.0


Command = Union[Acceleration, Pedals, Pose]


class Controller(Protocol):
    """What :meth:`Simulation.set_controller` takes: any object with this method."""

    def step(self, sim: "Simulation", entity: Entity) -> Optional[Command]:
        """The command for the next step, given the entity's state now; None keeps the last
        command (before the first, the entity drives as under the default controller)."""
        ...


class Simulation(_oscsim.Simulation):
    """One run of a scenario, stepped from Python.

    ``Simulation(scenario, dt=0.05, seed=1, duration=None, max_time=3600.0, record=True,
    params=None, osi=False, osi_host=None, osi_static="first", road_network=None, road=None,
    entry=None, csv=None)``: ``scenario`` is a :class:`Scenario` or the path of a scenario
    file, loaded as :meth:`Scenario.load` does (a .xosc with ``params``, global parameter
    overrides by name; a .osc planned on ``road``, an OpenDRIVE path, by default the file its
    ``map.set_map_file`` names, its constraints solved with ``seed``, ``entry`` the scenario to
    run when several could be); ``road_network`` a :class:`RoadNetwork` shared by the
    simulations given it; ``csv`` a path the trajectory CSV is written to, the file
    ``oscsim run --csv`` writes.

    Python controllers (:meth:`set_controller`) are called before each step with the state
    of their entity at the current time.

    ``bindings`` (a dict of external method name to function) binds a DSL scenario's external
    methods at load: a scenario that calls or reads a method not in it raises
    :class:`ScenarioError` at the ``call``'s (or the condition's) file, line and column. Each
    ``call m(a, b)`` runs ``m(a, b)`` after the step that runs it (:meth:`bind`); a method read
    in a condition (``until m(…) > 3``) is called before each step and the condition compares
    its result (a number, a boolean or a string) in that step. Arguments arrive as the JSON
    values of the event log (numbers in SI units as floats, strings, booleans); an exception
    the function raises propagates from :meth:`step`/:meth:`run`. Without ``bindings``,
    :meth:`bind` binds them after the load (checked before the first step).
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self._controllers: Dict[str, Any] = {}
        self._attached: set = set()
        bindings = kwargs.get("bindings")
        # Bound at load: the native constructor checked every external method is bound.
        self._bound_at_load = bindings is not None
        self._bound: Dict[str, Callable[..., Any]] = dict(bindings or {})
        self._events_read = 0

    def bind(self, name: str, function: Callable[..., Any]) -> None:
        """Binds ``function`` to the DSL scenario's external method ``name`` (``def name(…) is
        external …``). Each ``call name(a, b)`` the scenario reaches is a ``customCommand``
        record of type ``call`` in the event log at the time t of the step that runs it (from t
        to t + dt), and ``function(a, b)`` runs after that step, before the next one:
        ``sim.time`` is t + dt and the entities are as that step left them. Arguments arrive as the JSON values of the log (numbers in SI
        units as floats, strings, booleans). Every external method the scenario calls must be
        bound before the first step (:attr:`external_calls`), else that step raises
        :class:`ScenarioError` naming the ``call``'s file, line and column. An exception the
        function raises propagates from :meth:`step`/:meth:`run`."""
        if not callable(function):
            raise TypeError(f"expected a callable for external method {name!r}, found {function!r}")
        self._bound[name] = function

    def _check_bindings(self) -> None:
        for method, place in self.external_calls:
            if method not in self._bound:
                error = ScenarioError(
                    f"expected a function bound to external method `{method}` (Simulation.bind) "
                    f"before the run, found none at {place}"
                )
                file, line, column = place.rsplit(":", 2)
                error.file, error.line, error.column = file, int(line), int(column)
                raise error

    def _set_reads(self) -> None:
        # The values of the methods read in conditions, for the next step's triggers.
        for method, value in self._external_reads:
            _, _, rest = value.partition("(")
            args = json.loads("[" + rest[:-1] + "]")
            self.set_user_value(value, self._bound[method](*args))

    def _run_calls(self) -> None:
        lines = self._event_lines_since(self._events_read)
        self._events_read += len(lines)
        for line in lines:
            record = json.loads(line)
            if record.get("kind") != "customCommand" or record.get("type") != "call":
                continue
            content = record["content"]
            name, _, rest = content.partition("(")
            args = json.loads("[" + rest[:-1] + "]")
            self._bound[name](*args)

    def set_controller(self, name: str, controller: Any) -> None:
        """Drives entity ``name`` by ``controller``, an object whose ``step(sim, entity)``
        returns an :class:`Acceleration`, :class:`Pedals`, :class:`Pose` or None before each
        step (see :class:`Controller`). The entity is handed to an ``external`` controller
        (:meth:`attach_external`) when it first appears in the scene (also when the scenario
        gave it one: then both its domains are held). ``controller=None`` removes it (the entity keeps its last
        input)."""
        if controller is None:
            self._controllers.pop(name, None)
            return
        if not callable(getattr(controller, "step", None)):
            raise TypeError(f"expected an object with a step(sim, entity) method, found {controller!r}")
        self._controllers[name] = controller

    def command(self, name: str, command: Command) -> None:
        """Gives entity ``name``'s external controller ``command`` (:meth:`control` with the
        command's fields)."""
        if isinstance(command, Acceleration):
            self.control(name, acceleration=command.acceleration, steering=command.steering)
        elif isinstance(command, Pedals):
            self.control(
                name, throttle=command.throttle, brake=command.brake, steering_wheel=command.steering_wheel
            )
        elif isinstance(command, Pose):
            self.control(name, pose=command)
        else:
            raise TypeError(f"expected an Acceleration, Pedals or Pose command, found {command!r}")

    def _drive(self) -> None:
        for name, controller in self._controllers.items():
            if not self.in_scene(name):
                continue
            entity = self.entity(name)
            if name not in self._attached:
                self.attach_external(name)
                self._attached.add(name)
            command = controller.step(self, entity)
            if command is not None:
                self.command(name, command)

    def step(self) -> Optional[str]:
        """Runs one step of ``dt`` after asking the Python controllers for their commands,
        then the functions bound to the external methods the step called; returns None while
        the run goes on, then why it ended (see the native ``step``)."""
        if self.steps == 0 and not self._bound_at_load:
            self._check_bindings()
        if self._controllers and self.running:
            self._drive()
        if self._external_reads and self.running:
            self._set_reads()
        reason = super().step()
        if self.external_calls:
            self._run_calls()
        return reason

    def run(self) -> str:
        """Steps until the run ends; returns why."""
        if not self._controllers and not self.external_calls:
            return super().run()
        while True:
            reason = self.step()
            if reason is not None:
                return reason

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
