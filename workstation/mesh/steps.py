"""Shared pieces of the meshing stages: step records, point spacing, the MeshLab session.

Every filter of a chain is recorded as a :class:`StepRecord` (name, parameters with their
units resolved to numbers, seconds, summary figures) so a mesh carries how it was made in
``Mesh.meta["steps"]``, the same way a :class:`~workstation.core.cloud.Cloud` carries its
``history``.
"""

from __future__ import annotations

import dataclasses
import os
import time
from dataclasses import dataclass, field
from typing import Any, Mapping

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

log = get_logger(__name__)


@dataclass(frozen=True)
class StepRecord:
    """One filter of a chain: its name, resolved parameters, wall seconds and summary."""

    name: str
    params: Mapping[str, Any] = field(default_factory=dict)
    seconds: float = 0.0
    summary: Mapping[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict:
        return {"name": self.name, "params": dict(self.params), "seconds": round(self.seconds, 4),
                "summary": dict(self.summary)}


class Timer:
    """``with Timer() as t: ...`` then ``t.seconds`` (wall) and ``t.cpu`` (process CPU)."""

    def __enter__(self):
        self._t0 = time.perf_counter()
        self._c0 = time.process_time()
        return self

    def __exit__(self, *exc):
        self.seconds = time.perf_counter() - self._t0
        self.cpu = time.process_time() - self._c0
        return False


def params_dict(p) -> dict:
    """A frozen parameter dataclass as a plain dict (for step records and JSON)."""
    return {k: (list(v) if isinstance(v, tuple) else v) for k, v in dataclasses.asdict(p).items()}


def point_spacing(xyz: np.ndarray, sample: int = 20000, seed: int = 0, tree=None) -> float:
    """Median distance from a point to its nearest neighbour, in coordinate units.

    The one scale every meshing size derives from when it is not given (ball radius,
    hole size, small-piece diameter, triangle edge limit). Computed on a random sample of at
    most ``sample`` query points against the whole cloud (scipy cKDTree, O(n log n)).

    Parameters
    ----------
    xyz : (n, 3) float
    sample : int
        Number of query points.
    tree : scipy.spatial.cKDTree, optional
        A tree of ``xyz`` less its mean (:func:`~workstation.mesh.reconstruct.centred_tree`)
        a caller already has: it finds the neighbours, whose distances are then measured in
        ``xyz`` itself, as the tree built here (of ``xyz``) measures them.

    Returns
    -------
    float
        Median nearest-neighbour distance (> 0).
    """
    from scipy.spatial import cKDTree

    xyz = np.asarray(xyz, dtype=np.float64)
    if xyz.shape[0] < 2:
        raise InvalidInputError(f"{xyz.shape[0]} points: need at least 2 to measure point spacing")
    rng = np.random.default_rng(seed)
    q = xyz if xyz.shape[0] <= sample else xyz[rng.choice(xyz.shape[0], sample, replace=False)]
    if tree is None:
        nn = cKDTree(xyz).query(q, k=2)[0][:, 1]
    else:  # the second nearest: the nearest is the query itself (or a duplicate of it)
        nn = np.linalg.norm(xyz[tree.query(q - xyz.mean(axis=0), k=2)[1][:, 1]] - q, axis=1)
    nn = nn[nn > 0]
    if nn.size == 0:
        raise InvalidInputError("all points coincide: the point spacing is zero", "remove duplicate points")
    return float(np.median(nn))


def _libgomp_loaded() -> bool:
    try:
        with open("/proc/self/maps") as fh:
            return "libgomp" in fh.read()
    except OSError:  # pragma: no cover - not Linux
        return False


def import_pymeshlab():
    """Import pymeshlab with OpenMP threads that sleep while they wait.

    MeshLab's screened Poisson runs OpenMP loops; with GNU OpenMP's default (spinning) wait
    policy its threads burn CPU while waiting, and on a machine with more busy processes than
    cores the filter runs 5-10x slower (measured here: depth 9 on the 110 k-point bunny took
    328 s wall / 112 s CPU with 2 threads by default, 49 s / 20 s with
    ``OMP_WAIT_POLICY=PASSIVE``; this is the likely cause of PyMeshLab issue #408).
    The policy is read once, when libgomp is loaded, so it is set here only if no OpenMP
    runtime is loaded yet and the user has not chosen one.
    """
    passive_openmp()
    from workstation.interop.pymeshlab import import_pymeshlab

    return import_pymeshlab()


def passive_openmp() -> None:
    """Ask for sleeping OpenMP waits (``OMP_WAIT_POLICY=PASSIVE``) if no OpenMP runtime is
    loaded yet and the user has not chosen a policy (see :func:`import_pymeshlab`)."""
    if "OMP_WAIT_POLICY" not in os.environ and not _libgomp_loaded():
        os.environ["OMP_WAIT_POLICY"] = "PASSIVE"


def openmp_threads(requested: int) -> int:
    """Threads for an OpenMP filter: ``requested`` if > 0; else every core when OpenMP waits
    passively, and 1 otherwise (another library loaded a spinning OpenMP runtime first, and
    spinning threads on a busy machine are slower than one thread: 28 s wall for one thread
    against 328 s for two, Poisson depth 9 on the bunny, measured here under load)."""
    if requested and requested > 0:
        return int(requested)
    if os.environ.get("OMP_WAIT_POLICY", "").upper() == "PASSIVE":
        return max(1, os.cpu_count() or 1)
    log.info("OpenMP may spin (OMP_WAIT_POLICY is not PASSIVE): running single-threaded")
    return 1
