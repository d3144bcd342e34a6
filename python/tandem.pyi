"""tandem: interactive motion planning with contact. Type stubs of the compiled module."""
from typing import Any, Sequence, overload

import numpy as np
import numpy.typing as npt

class InputError(ValueError):
    """Bad input: the message names the file or parameter and the fault (exit code 2 on the
    command line)."""

class Problem:
    """A motion-planning problem, loaded as `tandem plan` loads it."""
    def __init__(self, spec: str, part: str = "", allow_dirs: Sequence[str] = ...) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def planar(self) -> bool: ...
    @property
    def bounds(self) -> npt.NDArray[np.float64]:
        """(2, 3): the minimum and maximum corners."""
    @property
    def start(self) -> npt.NDArray[np.float64]:
        """(7,) x y z qx qy qz qw, or (3,) x y theta in a planar space."""
    @property
    def goal(self) -> npt.NDArray[np.float64]: ...
    @property
    def obstacles(self) -> list[str]: ...

def planners() -> list[dict[str, Any]]:
    """Every planner: name, description, citation, uses_operator, parameters."""

def parameters(planner: str) -> list[dict[str, Any]]:
    """The parameters a planner reads: name, default, range, help."""

def plan(problem: Problem | str, planner: str | None = None, seed: int | None = None,
         time_limit: float | None = None, simplify: bool = True,
         **params: float | int | bool | str) -> dict[str, Any]:
    """Plans as `tandem plan` does (same seed and threads, same path). The record's fields
    (status, solved, time_s, iterations, nodes, collision_checks, ...), `path` ((n, 7) or (n, 3),
    empty unless solved), `path_length` and `mode`."""

def check_path(problem: Problem | str, path: npt.ArrayLike) -> dict[str, Any]:
    """valid, index, motion, out_of_bounds, message: every state and motion checked exactly."""

class Collision:
    """Collision and distance queries (FCL) for a problem; one thread at a time."""
    def __init__(self, problem: Problem) -> None: ...
    @overload
    def is_free(self, q: Sequence[float]) -> bool: ...
    @overload
    def is_free(self, q: npt.ArrayLike) -> bool | npt.NDArray[np.bool_]: ...
    def nearest(self, q: npt.ArrayLike) -> dict[str, Any]:
        """in_collision, distance, obstacle, point_on_object, point_on_obstacle."""
    def distances(self, qs: npt.ArrayLike) -> tuple[npt.NDArray[np.float64], list[str]]: ...
