"""Type stubs of the native module oscsim._oscsim (crates/python/src)."""

from __future__ import annotations

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

__version__: str

_Value = Union[bool, int, float, str]
_Path = Union[str, "os.PathLike[str]"]

class OscsimError(Exception):
    """Base class of the exceptions oscsim raises."""

class ScenarioError(OscsimError):
    """A scenario, catalog or road network did not load, or the engine could not be built."""

    file: Optional[str]
    line: Optional[int]
    column: Optional[int]

class SimulationError(OscsimError):
    """A step failed; the simulation refuses further steps."""

    file: Optional[str]
    line: Optional[int]
    column: Optional[int]

class InternalError(OscsimError):
    """oscsim panicked (a bug); the call failed, the interpreter lives."""

class DomainError(OscsimError):
    """A §8.7 method has no answer for these objects (off the roads, not on the route, …)."""

class Pose:
    """Position and orientation of a reference point in world coordinates (m, rad)."""

    x: float
    y: float
    z: float
    h: float
    p: float
    r: float
    def __init__(
        self, x: float, y: float, z: float = 0.0, h: float = 0.0, p: float = 0.0, r: float = 0.0
    ) -> None: ...
    def as_tuple(self) -> Tuple[float, float, float, float, float, float]: ...

class Vector3:
    """A velocity (m/s), acceleration (m/s²) or point (m)."""

    x: float
    y: float
    z: float
    def __init__(self, x: float, y: float, z: float = 0.0) -> None: ...
    def as_tuple(self) -> Tuple[float, float, float]: ...

class RoadPosition:
    """Road, lane and reference-line coordinates of a point (OpenDRIVE)."""

    road_id: str
    lane_id: int
    s: float
    t: float
    offset: float
    junction_id: Optional[str]

class BoundingBox:
    """Centre relative to the reference point (entity axes) and dimensions (m), §8.7.9."""

    center: Vector3
    length: float
    width: float
    height: float

class RoutePoint:
    """§8.7.2.1.4 route_point: a route element and s, t in its system."""

    kind: str
    road_id: str
    lane_section: Optional[int]
    lane_id: Optional[int]
    junction_id: Optional[str]
    s: float
    t: float

class Scenario:
    """A scenario loaded from an OpenSCENARIO 1.x file."""

    @staticmethod
    def load(path: _Path, params: Optional[Mapping[str, _Value]] = None) -> Scenario: ...
    @property
    def path(self) -> str: ...
    @property
    def road_network_path(self) -> Optional[str]: ...
    @property
    def parameters(self) -> Dict[str, _Value]: ...
    @property
    def entity_names(self) -> List[str]: ...

class RoadNetwork:
    """An OpenDRIVE road network, loaded once."""

    @staticmethod
    def load(path: _Path) -> RoadNetwork: ...
    @property
    def path(self) -> str: ...
    @property
    def road_ids(self) -> List[str]: ...
    def road_length(self, road_id: str) -> Optional[float]: ...

class Entity:
    """The state of one entity at one simulation time, with the §8.7 methods."""

    @property
    def name(self) -> str: ...
    @property
    def id(self) -> int: ...
    @property
    def kind(self) -> str: ...
    @property
    def vehicle_category(self) -> Optional[str]: ...
    @property
    def role(self) -> Optional[str]: ...
    @property
    def time(self) -> float: ...
    @property
    def pose(self) -> Pose: ...
    @property
    def speed(self) -> float: ...
    @property
    def velocity(self) -> Vector3: ...
    @property
    def acceleration(self) -> Vector3: ...
    @property
    def yaw_rate(self) -> float: ...
    @property
    def odometer(self) -> float: ...
    @property
    def road_position(self) -> Optional[RoadPosition]: ...
    @property
    def bounding_box(self) -> BoundingBox: ...
    def object_distance(
        self, reference: Entity, direction: str = "longitudinal", mode: str = "reference_points"
    ) -> float: ...
    def get_s_coord(self, route_type: str = "on_road") -> float: ...
    def get_t_coord(self, route_type: str = "on_road") -> float: ...
    def get_route_point(self, route_type: str = "on_road") -> RoutePoint: ...
    def distance_along_route(
        self,
        route: Sequence[Tuple[str, float, float, Optional[int]]],
        from_: str = "from_start",
    ) -> float: ...
    def time_to_collision(self, reference: Entity) -> Optional[float]: ...
    def time_headway(self, reference: Entity) -> Optional[float]: ...
    def space_gap(self, reference: Entity, direction: str = "longitudinal") -> float: ...

class Simulation:
    """One run of a scenario, stepped from Python."""

    def __init__(
        self,
        scenario: Union[Scenario, _Path],
        dt: float = 0.05,
        seed: int = 1,
        duration: Optional[float] = None,
        max_time: float = 3600.0,
        record: bool = True,
        params: Optional[Mapping[str, _Value]] = None,
        osi: bool = False,
        osi_host: Optional[str] = None,
        osi_static: str = "first",
        road_network: Optional[RoadNetwork] = None,
        road: Optional[_Path] = None,
        entry: Optional[str] = None,
        csv: Optional[_Path] = None,
        bindings: Optional[Mapping[str, Callable[..., Any]]] = None,
    ) -> None: ...
    def step(self) -> Optional[str]: ...
    def run(self) -> str: ...
    @property
    def time(self) -> float: ...
    @property
    def steps(self) -> int: ...
    @property
    def dt(self) -> float: ...
    @property
    def seed(self) -> int: ...
    @property
    def scenario_path(self) -> str: ...
    @property
    def external_calls(self) -> List[Tuple[str, str]]: ...
    @property
    def _external_reads(self) -> List[Tuple[str, str]]: ...
    @property
    def stop_reason(self) -> Optional[str]: ...
    @property
    def running(self) -> bool: ...
    @property
    def entities(self) -> List[Entity]: ...
    def entity(self, name: str) -> Entity: ...
    def in_scene(self, name: str) -> bool: ...
    def event_lines(self) -> List[str]: ...
    def _event_lines_since(self, start: int) -> List[str]: ...
    def trajectories(self) -> Dict[str, np.ndarray]: ...
    def osi_ground_truth(self) -> bytes: ...
    def osi_ground_truths(self) -> List[bytes]: ...
    @property
    def trajectory_rows(self) -> int: ...
    def clear_trajectories(self) -> None: ...
    def set_user_value(self, name: str, value: _Value) -> None: ...
    def set_parameter(self, name: str, value: _Value) -> None: ...
    def parameter(self, name: str) -> _Value: ...
    def attach_external(self, name: str) -> None: ...
    def control(
        self,
        name: str,
        *,
        acceleration: Optional[float] = None,
        steering: Optional[float] = None,
        throttle: Optional[float] = None,
        brake: Optional[float] = None,
        steering_wheel: Optional[float] = None,
        pose: Optional[Pose] = None,
    ) -> None: ...
    def monitors(self) -> List[Tuple[str, bool]]: ...
    def signal_states(self) -> List[Tuple[str, str]]: ...
    def _debug_panic(self) -> None: ...

def _debug_panic(message: str) -> None: ...

class BatchPlan:
    """The variants of a ParameterValueDistribution file, checked against its ScenarioFile."""

    def __init__(self, path: _Path) -> None: ...
    @property
    def distribution(self) -> str: ...
    @property
    def scenario(self) -> str: ...
    @property
    def variant_count(self) -> int: ...
    @property
    def parameters(self) -> List[str]: ...
    @property
    def warnings(self) -> List[str]: ...
    def variant(self, i: int) -> Dict[str, str]: ...
    def run(
        self,
        variants: Optional[Sequence[int]] = None,
        *,
        seed: int = 1,
        dt: float = 0.05,
        duration: Optional[float] = None,
        max_time: float = 3600.0,
        host: str = "Ego",
        jobs: int = 1,
        save: Sequence[str] = (),
        out_dir: Optional[_Path] = None,
        recording_time: Optional[int] = None,
        variant_timeout: Optional[float] = None,
        journal: Optional["BatchJournal"] = None,
    ) -> str: ...

class BatchJournal:
    """out_dir/batch.journal of a batch: the variants recorded so far, rows recorded as they come
    back (a driver's shares, or BatchPlan.run with journal=), the results files at the end."""

    def __init__(
        self,
        plan: BatchPlan,
        out_dir: _Path,
        *,
        seed: int = 1,
        dt: float = 0.05,
        duration: Optional[float] = None,
        max_time: float = 3600.0,
        host: str = "Ego",
        save: Sequence[str] = (),
        recording_time: Optional[int] = None,
        variant_timeout: Optional[float] = None,
    ) -> None: ...
    @property
    def done(self) -> List[int]: ...
    def record(self, csv: str) -> int: ...
    def finish(self) -> str: ...

def merge_results(parts: Sequence[str], out_dir: Optional[_Path] = None) -> str: ...
def summary(csv: str) -> str: ...
