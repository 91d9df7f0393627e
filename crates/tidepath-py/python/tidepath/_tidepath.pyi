"""Type stubs of the native module ``tidepath._tidepath`` (re-exported by ``tidepath``)."""

from os import PathLike
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

ArrayLike = npt.ArrayLike
Float64Array = npt.NDArray[np.float64]

def scenarios() -> List[Dict[str, Any]]:
    """The built-in scenarios: dicts with ``id``, ``description``, ``citation``."""

def planners() -> List[Dict[str, Any]]:
    """The planners: dicts with ``id``, ``description``, ``citation``, ``capabilities`` and
    ``parameters`` (``name``, ``range``, ``default``, ``default_text``, ``optional``,
    ``help``, ``source``)."""

def optimize(
    fun: Union[str, Callable[[Float64Array], float]],
    bounds: Optional[Union[Tuple[float, float], Sequence[Tuple[float, float]], ArrayLike]] = None,
    algo: str = "de",
    iterations: Optional[int] = None,
    evaluations: Optional[int] = None,
    population: Optional[int] = None,
    seed: int = 0,
    dim: Optional[int] = None,
    params: Optional[Mapping[str, Any]] = None,
    time_limit: Optional[float] = None,
) -> Dict[str, Any]:
    """Runs optimizer ``algo`` on a benchmark function (by id, at full speed) or on a Python
    callable (slower: each evaluation calls back into Python under the GIL). Returns ``x``,
    ``cost``, ``evaluations``, ``iterations``, ``history``, ``stop_reason``, ``elapsed_s``."""

def compare_json(
    scenario: Scenario,
    planners: List[str],
    runs: int,
    seed: int,
    budget: str,
    reference: Optional[str],
    jobs: Optional[int] = None,
) -> str: ...
def compare_share_json(
    toml: str,
    source: str,
    planners: List[str],
    runs: int,
    seed: int,
    budget: str,
    reference: Optional[str],
    k: int,
    n: int,
) -> str: ...
def merge_json(shards: List[str]) -> str: ...
def after_fork_in_child() -> None: ...

class Mission:
    """One mission of a plan."""

    @property
    def name(self) -> str: ...
    @property
    def waypoints(self) -> Float64Array:
        """The planner's path, start and goal included, ``(n, 3)`` metres."""
    @property
    def smoothed(self) -> Optional[Float64Array]: ...
    @property
    def path(self) -> Float64Array:
        """The final path: the smoothed one when a smoother ran, else the waypoints."""
    @property
    def times(self) -> Float64Array:
        """Arrival time (s) at each point of the final path."""
    @property
    def lonlat(self) -> Optional[Float64Array]:
        """The final path's (longitude, latitude), ``(n, 2)``, in a geographic scenario."""
    @property
    def cost(self) -> Optional[float]: ...
    @property
    def terms(self) -> Dict[str, float]: ...
    @property
    def feasible(self) -> bool: ...
    @property
    def status(self) -> str: ...
    @property
    def reason(self) -> str: ...
    @property
    def violations(self) -> List[str]: ...
    @property
    def metrics(self) -> Optional[Dict[str, Any]]: ...

class Plan:
    """The result of ``Scenario.plan``: the report ``tidepath plan --out plan.json`` writes."""

    @property
    def status(self) -> str: ...
    @property
    def reason(self) -> str: ...
    @property
    def cost(self) -> Optional[float]: ...
    @property
    def feasible(self) -> bool: ...
    @property
    def planner(self) -> str: ...
    @property
    def seed(self) -> int: ...
    @property
    def terms(self) -> Dict[str, float]: ...
    @property
    def history(self) -> Float64Array: ...
    @property
    def missions(self) -> List[Mission]: ...
    @property
    def evaluations(self) -> int: ...
    @property
    def iterations(self) -> int: ...
    @property
    def expansions(self) -> int: ...
    @property
    def samples(self) -> int: ...
    @property
    def stop_reason(self) -> str: ...
    @property
    def elapsed_s(self) -> float: ...
    def to_json(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def save(self, path: Union[str, "PathLike[str]"]) -> None:
        """Writes .json, .csv, or (geographic scenarios) .geojson, .kml, .gpx by extension."""

class Scenario:
    """A checked scenario. Immutable: ``with_mission`` returns a new one."""

    @staticmethod
    def builtin(name: str) -> Scenario: ...
    @staticmethod
    def load(path: Union[str, "PathLike[str]"]) -> Scenario: ...
    @staticmethod
    def from_toml(text: str, source: str = "<string>") -> Scenario: ...
    @staticmethod
    def from_dict(d: Mapping[str, Any], source: str = "<dict>") -> Scenario: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_toml(self) -> str: ...
    def with_mission(
        self,
        start: Optional[ArrayLike] = None,
        goal: Optional[ArrayLike] = None,
    ) -> Scenario: ...
    @property
    def name(self) -> str: ...
    @property
    def description(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def dims(self) -> int: ...
    @property
    def geographic(self) -> bool: ...
    @property
    def bounds(self) -> Tuple[List[float], List[float]]: ...
    @property
    def start(self) -> List[float]: ...
    @property
    def goal(self) -> List[float]: ...
    @property
    def mission_names(self) -> List[str]: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def planner(self) -> str: ...
    def plan(
        self,
        planner: Optional[str] = None,
        seed: int = 0,
        iterations: Optional[int] = None,
        evaluations: Optional[int] = None,
        time_limit: Optional[float] = None,
        params: Optional[Mapping[str, Any]] = None,
        smoother: Optional[str] = None,
        smoother_params: Optional[Mapping[str, Any]] = None,
        init: Optional[Union[ArrayLike, Sequence[ArrayLike]]] = None,
        population: Optional[int] = None,
        progress: bool = False,
    ) -> Plan: ...
    def view(
        self,
        plans: Sequence[Plan] = (),
        path: Optional[Union[str, "PathLike[str]"]] = None,
        title: Optional[str] = None,
    ) -> str:
        """The interactive 3-D view (one offline HTML page, as ``tidepath view``); written to ``path`` (.html) when given."""
        def evaluate(self, waypoints: Union[ArrayLike, Sequence[ArrayLike]]) -> Dict[str, Any]: ...
    def seabed(self, x: ArrayLike, y: ArrayLike) -> Float64Array: ...
    def current(self, x: ArrayLike, y: ArrayLike, z: ArrayLike, t: Optional[ArrayLike] = None) -> Float64Array: ...
    def clearance(self, points: ArrayLike, t: float = 0.0) -> Float64Array: ...
