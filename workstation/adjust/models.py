r"""The correction models of the strip adjustment.

Both give corrected coordinates :math:`X(\theta)` of every point and the derivatives
:math:`\partial X/\partial\theta` that the Gauss-Newton iterations of
:mod:`workstation.adjust.adjust` need.

* **Strip-wise** (no trajectory; the quasi-rigorous model of most delivered tiles): every
  strip :math:`s` but the datum strip is moved rigidly by a shift :math:`\mathbf t_s`,
  :math:`X' = X + \mathbf t_s` (Kilian et al. 1996; Filin 2003 shows that boresight errors
  over a small area act mostly as such offsets).
* **Rigorous** (with the trajectory; Skaloud & Lichti 2006; Glira et al. 2015): each point
  is re-georeferenced from its GPS time through the interpolated pose, the lever arm
  :math:`\mathbf a`, the boresight :math:`R^b_s(\mathbf b)` and the reconstructed range
  :math:`r` and beam :math:`\mathbf d_s`:

  .. math:: X = \mathbf p + R^m_n R^n_b\left(R^b_s(\mathbf b_0 + \delta\mathbf b)\,
            (r - \delta r)\,\mathbf d_s + \mathbf a_0 + \delta\mathbf a\right) + \mathbf t_s

  with the boresight corrections :math:`\delta\mathbf b` (roll, pitch, yaw of the scanner in
  the body frame, the convention of :class:`~workstation.lidar.georef.GeorefChain`), the range
  offset :math:`\delta r` (recorded minus true range), the lever-arm corrections
  :math:`\delta\mathbf a`, optionally a scan-angle scale :math:`k` (the true across-track
  mirror angle is the encoder's times :math:`1 + k`, so :math:`\mathbf d_s` is rebuilt from the
  encoder angles recovered from it) and optional strip shifts. The estimates are therefore the errors in
  the simulator's convention: the true minus the nominal boresight, and the ranging bias.

Lever arm and boresight are constant over a flight, so their errors are systematic, not
random (Lohani, course notes CE676A): they show as strips that do not
match in the overlaps, which is what makes them estimable from the data.

References
----------
B. Lohani. Laser Scanning & Photogrammetry, course notes CE676A (calibration of the
lever arm and boresight).
J. Kilian, N. Haala, M. Englich (1996). Capture and evaluation of airborne laser scanner data.
Int. Arch. Photogramm. Remote Sens. 31(B3):383-388.
S. Filin (2003). Recovery of systematic biases in laser altimetry data using natural surfaces.
Photogramm. Eng. Remote Sens. 69(11):1235-1242.
J. Skaloud, D. Lichti (2006). Rigorous approach to bore-sight self-calibration in airborne
laser scanning. ISPRS J. Photogramm. Remote Sens. 61(1):47-59.
P. Glira, N. Pfeifer, C. Briese, C. Ressl (2015). Rigorous strip adjustment of airborne
laserscanning data based on the ICP algorithm. ISPRS Annals II-3/W5:73-80.
"""

from __future__ import annotations

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.lidar.georef import GeorefChain, beam_direction, rotate_rpy, rpy_matrix, rpy_trig

from .trajectory import Navigation

#: What can be estimated, as ``--estimate`` names them.
ESTIMABLE = ("boresight", "leverarm", "range", "scan-angle", "strip-shift")
BORESIGHT = ("boresight_roll", "boresight_pitch", "boresight_yaw")
LEVERARM = ("lever_arm_x", "lever_arm_y", "lever_arm_z")


def _to_map(rpy_trig_: tuple, rpy: np.ndarray, v_b: np.ndarray) -> np.ndarray:
    """Body-frame vectors (n, 3) to map (ENU) vectors."""
    v = rotate_rpy(rpy, v_b, trig=rpy_trig_)
    return np.column_stack([v[:, 1], v[:, 0], -v[:, 2]])  # R^m_n: east, north, up


class StripShifts:
    """Shift columns of every strip but the datum: ``names``, ``scale`` and derivatives."""

    def __init__(self, strips: np.ndarray, fixed: int):
        self.strips = np.asarray(strips, np.int64)
        self.fixed = int(fixed)
        self.free = self.strips[self.strips != self.fixed]
        self.names = [f"strip_{s}_{ax}" for s in self.free for ax in "xyz"]
        self.scale = np.ones(len(self.names))

    def offsets(self, theta: np.ndarray, sid: np.ndarray) -> np.ndarray:
        """(n, 3) shift of points of strips ``sid`` under parameters ``theta`` (this block)."""
        t = np.zeros((int(max(self.strips.max(), sid.max() if sid.size else 0)) + 1, 3))
        t[self.free] = np.asarray(theta).reshape(-1, 3)
        return t[sid]

    def design(self, normal: np.ndarray, strip_a: np.ndarray, strip_b: np.ndarray) -> np.ndarray:
        """(p, 3 * free) columns of :math:`n^\\top(\\partial c_b - \\partial c_a)` for the shifts."""
        A = np.zeros((normal.shape[0], len(self.names)))
        for k, s in enumerate(self.free):
            A[:, 3 * k:3 * k + 3] += normal * ((strip_b == s) * 1.0 - (strip_a == s))[:, None]
        return A


class Rigorous:
    """The rigorous model for a set of points (module docs).

    Parameters
    ----------
    xyz : (n, 3) float
        Points as delivered (map metres).
    gps_time : (n,) float
    nav : Navigation
    mount : GeorefChain
        Nominal lever arm and boresight used to georeference the points.
    estimate : tuple of str
        Which of ``boresight``, ``leverarm``, ``range``, ``scan-angle`` to estimate.
    """

    def __init__(self, xyz, gps_time, nav: Navigation, mount: GeorefChain, estimate: tuple):
        t = np.asarray(gps_time, float)
        outside = ~nav.covers(t)
        if outside.any():
            raise InvalidInputError(f"{int(outside.sum())} points lie outside the trajectory's time span",
                                    "give the trajectory of these flight lines (same GPS time base)", field="trajectory")
        self.mount = mount
        self.pos, self.rpy = nav.interpolate(t)
        self.trig = rpy_trig(self.rpy)
        self.range, self.beam = mount.inverse(xyz, self.pos, self.rpy)
        self.names = ([*BORESIGHT] if "boresight" in estimate else []) + (["range_offset"] if "range" in estimate else []) \
            + ([*LEVERARM] if "leverarm" in estimate else []) + (["scan_angle_scale"] if "scan-angle" in estimate else [])
        if "scan_angle_scale" in self.names:  # encoder angles of beam_direction(across, along)
            self.across = np.arcsin(np.clip(self.beam[:, 1], -1.0, 1.0))
            self.along = np.arctan2(self.beam[:, 0], self.beam[:, 2])
        r_mean = float(np.mean(self.range)) if self.range.size else 1.0
        a_mean = float(np.mean(np.abs(self.across))) if "scan_angle_scale" in self.names and self.range.size else 0.0
        self.scale = np.array([r_mean if n in BORESIGHT else r_mean * a_mean if n == "scan_angle_scale" else 1.0
                               for n in self.names])

    def _split(self, theta: np.ndarray) -> tuple[np.ndarray, float, np.ndarray, float]:
        d = dict(zip(self.names, theta))
        b = np.array([d.get(n, 0.0) for n in BORESIGHT])
        a = np.array([d.get(n, 0.0) for n in LEVERARM])
        return (np.asarray(self.mount.boresight) + b, d.get("range_offset", 0.0), np.asarray(self.mount.lever_arm) + a,
                d.get("scan_angle_scale", 0.0))

    def _beam(self, k: float, rows) -> np.ndarray:
        """Scanner-frame beams with the true across-track angle ``encoder * (1 + k)``."""
        if "scan_angle_scale" not in self.names:
            return self.beam[rows]
        return beam_direction(self.across[rows] * (1.0 + k), self.along[rows])

    def coords(self, theta: np.ndarray, rows: slice | np.ndarray = slice(None)) -> np.ndarray:
        """Corrected map coordinates (k, 3) of the points ``rows``."""
        b, dr, a, k = self._split(theta)
        v_b = ((self.range[rows] - dr)[:, None] * self._beam(k, rows)) @ rpy_matrix(*b).T + a
        trig = tuple((c[rows], s[rows]) for c, s in self.trig)
        return self.pos[rows] + _to_map(trig, self.rpy[rows], v_b)

    def derivatives(self, theta: np.ndarray, rows: slice | np.ndarray = slice(None)):
        """Yield (k, 3) :math:`\\partial X/\\partial\\theta_j` of the points ``rows``, one per unknown."""
        b, dr, _, k = self._split(theta)
        trig = tuple((c[rows], s[rows]) for c, s in self.trig)
        beam = self._beam(k, rows)
        rpy, rd = self.rpy[rows], (self.range[rows] - dr)[:, None] * beam
        h = 1e-6
        for name in self.names:
            if name in BORESIGHT:
                e = np.zeros(3)
                e[BORESIGHT.index(name)] = h
                dR = (rpy_matrix(*(b + e)) - rpy_matrix(*(b - e))) / (2 * h)
                yield _to_map(trig, rpy, rd @ dR.T)
            elif name == "range_offset":
                yield -_to_map(trig, rpy, beam @ rpy_matrix(*b).T)
            elif name == "scan_angle_scale":  # d beam / dk = across * d beam / d across
                a1, b1 = self.across[rows] * (1.0 + k), self.along[rows]
                db = np.column_stack([-np.sin(b1) * np.sin(a1), np.cos(a1), -np.cos(b1) * np.sin(a1)]) * self.across[rows][:, None]
                yield _to_map(trig, rpy, ((self.range[rows] - dr)[:, None] * db) @ rpy_matrix(*b).T)
            else:
                e = np.zeros((rd.shape[0], 3))
                e[:, LEVERARM.index(name)] = 1.0
                yield _to_map(trig, rpy, e)
