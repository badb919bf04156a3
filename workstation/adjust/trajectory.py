r"""The navigation solution (SBET-like trajectory CSV) and the measurements it explains.

A trajectory CSV has a header line and one row per IMU epoch: ``gps_time`` (s, the time base
of the points' GPS time), ``easting``, ``northing``, ``height`` (the IMU origin in the map
frame, metres) and ``roll_deg``, ``pitch_deg``, ``heading_deg`` (degrees, the aerospace
z-y-x sequence of :mod:`workstation.lidar.georef`); other columns are ignored. This is what
``ws simulate`` writes; exports of post-processed SBET files can be brought to it.

Laser points rarely carry their range and mirror angle, so they are reconstructed from the
point, the pose interpolated at its GPS time and the nominal mounting by running the
georeferencing chain backwards (:meth:`GeorefChain.inverse`), as Glira et al. (2015, sec. 3.1)
do. Running it forwards again with corrected mounting parameters gives the corrected points.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError

#: Accepted names of each needed column (lower case), first match wins.
COLUMNS = {
    "time": ("gps_time", "time", "t"),
    "x": ("easting", "x", "east"),
    "y": ("northing", "y", "north"),
    "z": ("height", "z", "up", "elevation"),
    "roll": ("roll_deg", "roll"),
    "pitch": ("pitch_deg", "pitch"),
    "heading": ("heading_deg", "heading", "yaw_deg", "yaw"),
}


@dataclass(frozen=True)
class Navigation:
    """A trajectory: ``time`` (k,) s increasing, ``position`` (k, 3) map metres, ``rpy`` (k, 3)
    radians with the heading unwrapped (continuous), so linear interpolation is valid."""

    time: np.ndarray
    position: np.ndarray
    rpy: np.ndarray

    def interpolate(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Position (n, 3) and roll/pitch/yaw (n, 3) at times ``t`` (n,), linearly."""
        pos = np.column_stack([np.interp(t, self.time, self.position[:, i]) for i in range(3)])
        rpy = np.column_stack([np.interp(t, self.time, self.rpy[:, i]) for i in range(3)])
        return pos, rpy

    def covers(self, t: np.ndarray) -> np.ndarray:
        """Mask of times within the trajectory's span."""
        return (t >= self.time[0]) & (t <= self.time[-1])


def read_trajectory_csv(path) -> Navigation:
    """Read a trajectory CSV (module docs)."""
    p = Path(path)
    try:
        with open(p, encoding="utf-8") as f:
            header = [h.strip().lower() for h in f.readline().split(",")]
        data = np.loadtxt(p, delimiter=",", skiprows=1, ndmin=2)
    except (OSError, ValueError) as e:
        raise InvalidInputError(f"cannot read the trajectory: {e}", "a CSV with a header line", path=p) from None
    cols = {}
    for key, names in COLUMNS.items():
        hit = [header.index(n) for n in names if n in header]
        if not hit:
            raise InvalidInputError(f"trajectory has no {key} column", f"name it one of {', '.join(names)}", path=p)
        cols[key] = data[:, hit[0]]
    t = cols["time"]
    if t.size < 2 or np.any(np.diff(t) <= 0) or not np.all(np.isfinite(data)):
        raise InvalidInputError("trajectory times must increase strictly and every value be finite", path=p)
    rpy = np.radians(np.column_stack([cols["roll"], cols["pitch"], cols["heading"]]))
    rpy[:, 2] = np.unwrap(rpy[:, 2])
    return Navigation(t, np.column_stack([cols["x"], cols["y"], cols["z"]]), rpy)
