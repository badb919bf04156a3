"""Scan mechanisms: beam angles as a function of the pulse index.

Each pattern maps pulse indices ``k`` (counted from the start of a scanning segment, pulse
``k`` fired at ``k / prf`` seconds) to encoder angles, LAS scan-direction / edge flags and a
scan-line index; :meth:`ScanPattern.directions` turns angles into unit beam vectors in the
scanner frame (x forward, y right, z down; see :mod:`workstation.lidar.georef`).

* ``zigzag`` - oscillating mirror: the across-track angle is a triangle wave of frequency
  ``scan_frequency`` (one full mirror cycle = two scan lines), so points form a zigzag on the
  ground (Baltsavias 1999, Table 2; e.g. Leica ALS, Optech ALTM).
* ``polygon`` - rotating polygon mirror: a sawtooth, every line swept in the same direction,
  ``scan_frequency`` lines per second, giving parallel lines (Riegl LMS/VQ series).
* ``palmer`` - nutating (Palmer) mirror: the beam traces an ellipse of half-angles
  ``fov/2`` across and ``palmer_along_deg`` along track at ``scan_frequency`` revolutions per
  second, so the ground pattern is a series of overlapping ellipses (e.g. ScaLARS, Livox-like
  drone sensors), and each spot is seen looking forward and backward.
* ``rotating`` - a 360 degree profiler in the plane across the direction of travel (MLS);
  ``fov`` is 360 and ``scan_frequency`` is rotations (lines) per second.
* ``spherical`` - a terrestrial scanner: the head turns in azimuth by ``h_step_deg`` per
  vertical profile, each profile sampled every ``v_step_deg`` between ``v_min_deg`` and
  ``v_max_deg`` of elevation; ``n_pulses`` is fixed by the steps.

References
----------
E. P. Baltsavias (1999). Airborne laser scanning: basic relations and formulas. ISPRS J.
Photogramm. Remote Sens. 54(2-3):199-214.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError

from .georef import beam_direction

KINDS = ("zigzag", "polygon", "palmer", "rotating", "spherical")
#: The mechanisms of an airborne (ALS/ULS) scanner; rotating is a mobile profiler, spherical a TLS.
AIRBORNE_KINDS = ("zigzag", "polygon", "palmer")


@dataclass(frozen=True)
class ScanAngles:
    """Encoder angles and flags for a batch of pulses.

    Attributes
    ----------
    primary : (n,) float64
        Across-track angle (rad, positive right) for line scanners; elevation (rad) for TLS.
    secondary : (n,) float64
        Along-track angle (rad, positive forward) for line scanners; azimuth (rad) for TLS.
    direction : (n,) uint8
        LAS scan direction flag: 1 while the primary angle increases.
    edge : (n,) uint8
        LAS edge of flight line: 1 on the last pulse of a scan line.
    line : (n,) int64
        Scan-line (or TLS profile) index within the segment.
    """

    primary: np.ndarray
    secondary: np.ndarray
    direction: np.ndarray
    edge: np.ndarray
    line: np.ndarray


@dataclass(frozen=True)
class ScanPattern:
    """A scan mechanism and its timing.

    Attributes
    ----------
    kind : str
        One of ``zigzag``, ``polygon``, ``palmer``, ``rotating``, ``spherical``.
    prf : float
        Pulse repetition frequency (Hz).
    scan_frequency : float
        Hz: mirror cycles (zigzag: 2 lines each), lines (polygon, rotating) or revolutions
        (palmer). Unused for ``spherical``.
    fov_deg : float
        Full across-track field of view (degrees).
    palmer_along_deg : float
        Along-track half-angle of the Palmer ellipse (degrees).
    h_step_deg, v_step_deg, v_min_deg, v_max_deg : float
        TLS angular steps and elevation limits (degrees).
    h_fov_deg : float
        TLS azimuth range (degrees, 360 for a full panorama).
    """

    kind: str = "zigzag"
    prf: float = 300_000.0
    scan_frequency: float = 50.0
    fov_deg: float = 40.0
    palmer_along_deg: float = 7.0
    h_step_deg: float = 0.2
    v_step_deg: float = 0.2
    v_min_deg: float = -45.0
    v_max_deg: float = 90.0
    h_fov_deg: float = 360.0

    def __post_init__(self):
        if self.kind not in KINDS:
            raise InvalidInputError(f"unknown scan pattern '{self.kind}'", f"use one of {', '.join(KINDS)}", field="kind")
        if self.prf <= 0:
            raise InvalidInputError(f"prf {self.prf} must be positive (Hz)", field="prf")
        if self.kind != "spherical" and (self.scan_frequency <= 0 or not 0 < self.fov_deg <= 360):
            raise InvalidInputError("scan_frequency must be > 0 Hz and fov in (0, 360] degrees", field="scan_frequency")
        if self.kind == "spherical" and (self.h_step_deg <= 0 or self.v_step_deg <= 0 or self.v_max_deg <= self.v_min_deg):
            raise InvalidInputError("TLS steps must be > 0 and v_max > v_min (degrees)", field="v_step_deg")

    @property
    def lines_per_second(self) -> float:
        """Scan lines per second (zigzag: 2 per mirror cycle; palmer: 2 sweeps per revolution)."""
        return {"zigzag": 2.0, "polygon": 1.0, "palmer": 2.0, "rotating": 1.0}.get(self.kind, 0.0) * self.scan_frequency

    @property
    def tls_shape(self) -> tuple[int, int]:
        """(profiles in azimuth, pulses per profile) of a spherical scan."""
        nh = int(round(self.h_fov_deg / self.h_step_deg))
        nv = int(np.floor((self.v_max_deg - self.v_min_deg) / self.v_step_deg)) + 1
        return nh, nv

    def pulses_in(self, duration: float) -> int:
        """Number of pulses fired in a segment of ``duration`` seconds (TLS: the full scan)."""
        if self.kind == "spherical":
            nh, nv = self.tls_shape
            return nh * nv
        return int(np.floor(duration * self.prf))

    def tls_duration(self) -> float:
        return self.pulses_in(0.0) / self.prf

    def angles(self, k: np.ndarray) -> ScanAngles:
        """Encoder angles of pulses ``k`` (n,) int64, counted from the segment start."""
        k = np.asarray(k, np.int64)
        if self.kind == "spherical":
            nh, nv = self.tls_shape
            ih, iv = np.divmod(k, nv)
            up = (ih % 2) == 0  # the mirror sweeps up, then down on the next profile
            ivv = np.where(up, iv, nv - 1 - iv)
            elev = np.radians(self.v_min_deg + ivv * self.v_step_deg)
            az = np.radians(ih * self.h_step_deg)
            edge = ((iv == nv - 1)).astype(np.uint8)
            return ScanAngles(elev, az, up.astype(np.uint8), edge, ih)
        A = np.radians(self.fov_deg) / 2
        t = k / self.prf
        step = self.lines_per_second / self.prf  # scan lines per pulse
        line = np.floor(k * step + 1e-9).astype(np.int64)
        edge = (np.floor((k + 1) * step + 1e-9).astype(np.int64) != line).astype(np.uint8)
        if self.kind == "zigzag":
            u = np.mod(t * self.scan_frequency, 1.0)
            up = u < 0.5
            a = np.where(up, A * (4 * u - 1), A * (3 - 4 * u))
            return ScanAngles(a, np.zeros_like(a), up.astype(np.uint8), edge, line)
        if self.kind in ("polygon", "rotating"):
            u = np.mod(t * self.scan_frequency, 1.0)
            a = A * (2 * u - 1)
            return ScanAngles(a, np.zeros_like(a), np.ones(k.shape, np.uint8), edge, line)
        # palmer
        w = 2 * np.pi * self.scan_frequency * t
        a = A * np.sin(w)
        b = np.radians(self.palmer_along_deg) * np.cos(w)
        return ScanAngles(a, b, (np.cos(w) >= 0).astype(np.uint8), edge, line)

    def directions(self, primary: np.ndarray, secondary: np.ndarray, dtype=np.float64) -> np.ndarray:
        """Unit beam vectors (n, 3) in the scanner frame for encoder (or true) angles."""
        if self.kind == "spherical":
            p = np.asarray(primary, dtype)
            q = np.asarray(secondary, dtype)
            ce = np.cos(p)
            out = np.empty(p.shape + (3,), dtype)
            out[:, 0] = ce * np.cos(q)
            out[:, 1] = ce * np.sin(q)
            out[:, 2] = -np.sin(p)
            return out
        return beam_direction(primary, secondary, dtype)

    def scan_angle_deg(self, primary: np.ndarray) -> np.ndarray:
        """The LAS scan angle (degrees) before adding the platform roll."""
        return np.degrees(primary)
