"""tandem: interactive motion planning with contact. Type stubs of the compiled module."""
from typing import Any, Callable, Sequence, overload

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

OperatorView = dict[str, Any]
"""What a Python operator is shown at each update: time (operator time, in planner iterations),
iteration, nodes, tree_sizes, distance_to_roadmap (of its previous q_device, or None) and previous:
None before its first update, else its previous state (time, q_device, nearest: {in_collision,
distance, obstacle, point_on_object, point_on_obstacle}, contact_frame: None when touching, else
{P_o, P_n, P_c, normal, R, delta, distance})."""

class Session:
    """A planner stepped from Python, in virtual time, with its operator; journaled on request
    (then `tandem replay JOURNAL` rebuilds the same trees). A context manager: leaving it ends
    the session."""
    def __init__(self, problem: Problem | str, planner: str | None = None,
                 seed: int | None = None, time_limit: float | None = None,
                 operator: str | Callable[[OperatorView], npt.ArrayLike] | None = None,
                 journal: str = "", digest_every: int = 10000,
                 **params: float | int | bool | str) -> None:
        """operator: for the interactive planners, None (the planner's default simulated
        operator), 'experienced', 'inexperienced', 'trace:FILE', or a callable view -> q_device
        ((7,) or (3,)) called every operator_period iterations. Keyword arguments set the
        planner's parameters by name (tandem.parameters(planner))."""
    def step(self, n: int = 1) -> str:
        """Up to n iterations (fewer if the planner ends); the status."""
    def run(self) -> str:
        """Until solved, the time limit or the iteration limit; the status."""
    def close(self) -> None: ...
    def __enter__(self) -> Session: ...
    def __exit__(self, *args: object) -> None: ...
    @property
    def status(self) -> str: ...
    @property
    def steps(self) -> int: ...
    @property
    def tree_digest(self) -> str: ...
    @property
    def stats(self) -> dict[str, Any]:
        """iterations, nodes, edges, collision_checks, operator_iterations, contact_entries,
        nodes_by_source."""
    @property
    def mode(self) -> str: ...
    @property
    def seed(self) -> int: ...
    def trees(self) -> list[dict[str, Any]]:
        """Per tree (the first rooted at the start): nodes (n, 7), parents (n,) with -1 at the
        root, sources ('root', 'random', 'operator', 'contact')."""
    @property
    def solution(self) -> npt.NDArray[np.float64]: ...
    @property
    def operator_state(self) -> dict[str, Any] | None: ...
    @property
    def journal(self) -> str | None: ...

def live(problem: Problem | str, planner: str | None = None, seed: int | None = None,
         time_limit: float | None = None,
         operator: str | Callable[[OperatorView], npt.ArrayLike] | None = None,
         journal: str = "", rate_hz: float = 200.0,
         **params: float | int | bool | str) -> dict[str, Any]:
    """A live session in human time, as `tandem interactive` runs one: the planner on this
    thread, the operator on its own, called rate_hz times a second (its view's time in seconds,
    with iteration, nodes, elapsed_s, iterations_per_s and previous). Journaled to `journal`
    (required); `tandem replay` rebuilds the trees. An exception of the operator ends the session
    and is raised here. Returns status, steps, iterations, nodes, tree_digest, solution,
    journal."""

def bench(experiment: str, out: str = "", jobs: int = 0, seeds: int | None = None,
          allow_dirs: Sequence[str] = (), shard: str = "") -> dict[str, Any]:
    """Runs an experiment file as `tandem bench` does; name, records, planned, ran, resumed,
    out, runs (the runs file), report (None for a shard)."""

def read_runs(file: str) -> list[dict[str, Any]]:
    """The records of a runs file, as dicts."""
