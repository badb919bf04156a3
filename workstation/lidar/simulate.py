r"""The LiDAR simulator: pulses from a platform and scanner, cast into a labelled scene.

For every pulse (vectorised in batches; no Python loop over pulses):

1. **Timing and angles**: pulse ``k`` of a scanning segment fires at ``t0 + k / PRF``; the scan
   pattern gives the encoder angles (:mod:`workstation.lidar.scanners`).
2. **True beam**: the true mirror angle carries the scan-angle errors, the true trajectory
   (interpolated at the pulse time) and the true mounting (lever arm and boresight with their
   misalignment) place the beam in the scene (:mod:`workstation.lidar.georef`).
3. **Footprint**: the beam has a divergence :math:`\gamma` (full angle, 1/e^2); ``subrays`` rays
   sample its footprint on a sunflower (Vogel) pattern turned by a random angle per pulse, each
   carrying the Gaussian beam energy of its area. Each sub-ray is cast to its first hit with
   Open3D's Embree ``RaycastingScene``.
4. **Received power** of each sub-ray from the laser range equation for an extended
   Lambertian target (Jelalian 1992, eq. 2.35; Wagner et al. 2006, eq. 5):

   .. math:: P_r = w_j\, P_t\, \frac{D_r^2}{4 R^2}\, \eta_{sys}\, \eta_{atm}^2\,
             \left(\rho \cos\alpha + s\, e^{-(\alpha'/\sigma_s)^2}\right)

   with the peak power :math:`P_t`, receiver aperture :math:`D_r`, range :math:`R`,
   incidence angle :math:`\alpha`, diffuse reflectance :math:`\rho` of the material at the
   laser wavelength, an optional specular lobe (water: :math:`s` and width :math:`\sigma_s`, the
   angle perturbed by random wave slopes so returns are sparse), system efficiency and the
   one-way atmospheric transmission :math:`\eta_{atm} = e^{-\sigma R}`, :math:`\sigma` from the
   visibility by Kruse's law (Kim, McArthur & Korevaar 2001).
5. **Returns**: the sub-ray hits of a pulse sorted by range are split where consecutive ranges
   differ by more than ``min_separation`` (the pulse width / dead zone); each group becomes one
   return at the power-weighted mean range, labelled by its strongest sub-ray. A return is
   recorded when its power reaches the detection threshold (so the maximum range follows from
   the received power: :meth:`Sensor.max_range`) and its range is within the range gate; at
   most ``max_returns`` per pulse. Intensity is the received power on a 16-bit scale,
   saturating at ``saturation_power``.
6. **Measurement and processing**: the recorded range gets Gaussian noise; the point is then
   georeferenced the way a user would: with the *encoder* angle, the *nominal* mounting and the
   *navigation solution* (true trajectory plus GNSS noise, bias and per-line bias and IMU
   attitude noise, read at the pulse time plus the time bias). Every error of :class:`ErrorModel` is therefore
   visible the way it appears in real data (strip offsets, the smile of a scan-angle scale
   error, boresight tilts).

References
----------
A. V. Jelalian (1992). Laser Radar Systems. Artech House.
W. Wagner, A. Ullrich, V. Ducic, T. Melzer, N. Studnicka (2006). Gaussian decomposition and
calibration of a novel small-footprint full-waveform digitising airborne laser scanner.
ISPRS J. Photogramm. Remote Sens. 60(2):100-112.
I. I. Kim, B. McArthur, E. Korevaar (2001). Comparison of laser beam propagation at 785 nm
and 1550 nm in fog and haze for optical wireless communications. Proc. SPIE 4214:26-37.
E. P. Baltsavias (1999). Airborne laser scanning: basic relations and formulas. ISPRS J.
Photogramm. Remote Sens. 54(2-3):199-214.
"""

from __future__ import annotations

import os
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from workstation.core.classes import ASPRSClass as C
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger

from .georef import GeorefChain, rotate_rpy, rpy_trig
from .materials import material_arrays
from .platforms import Trajectory
from .scanners import ScanPattern
from .scene import Scene

log = get_logger(__name__)

#: Default start of the survey in adjusted standard GPS time (GPS seconds - 1e9), seconds.
DEFAULT_GPS_TIME = 4.0e8
GOLDEN_ANGLE = np.pi * (3.0 - np.sqrt(5.0))


@dataclass(frozen=True)
class Sensor:
    """Laser, receiver and digitiser of a scanner.

    Attributes
    ----------
    wavelength_nm : float
        Laser wavelength (nm); selects the material reflectance.
    peak_power_w : float
        Transmitted peak power (W).
    aperture_m : float
        Receiver aperture diameter (m).
    system_efficiency : float
        Optical and electronic efficiency (0-1).
    divergence_mrad : float
        Full beam divergence at 1/e^2 (mrad).
    subrays : int
        Rays sampling the footprint (1 = a single infinitely thin ray, first return only).
    max_returns : int
        Returns recorded per pulse (1-15).
    min_separation_m : float
        Minimum range difference between two returns of one pulse (m).
    detection_threshold_w : float
        Smallest received power recorded as a return (W).
    saturation_power_w : float
        Received power mapped to intensity 65535 (W).
    visibility_km : float
        Meteorological visibility for the atmospheric extinction (km).
    min_range_m, max_range_m : float
        Range gate (m).
    """

    wavelength_nm: float = 1064.0
    peak_power_w: float = 4000.0
    aperture_m: float = 0.08
    system_efficiency: float = 0.8
    divergence_mrad: float = 0.25
    subrays: int = 5
    max_returns: int = 5
    min_separation_m: float = 1.5
    detection_threshold_w: float = 2e-7
    saturation_power_w: float = 2e-5
    visibility_km: float = 23.0
    min_range_m: float = 1.0
    max_range_m: float = 6000.0

    def __post_init__(self):
        if self.subrays < 1 or not 1 <= self.max_returns <= 15:
            raise InvalidInputError("subrays must be >= 1 and max_returns in 1..15", field="subrays")
        for name in ("peak_power_w", "aperture_m", "system_efficiency", "detection_threshold_w", "saturation_power_w",
                     "visibility_km"):
            if not getattr(self, name) > 0:
                raise InvalidInputError(f"{name} must be positive", field=name)

    @property
    def extinction_per_m(self) -> float:
        """Atmospheric extinction coefficient (1/m) by Kruse's law from the visibility."""
        v = self.visibility_km
        q = 1.6 if v > 50 else (1.3 if v > 6 else 0.585 * v ** (1 / 3))
        return 3.912 / v * (self.wavelength_nm / 550.0) ** (-q) / 1000.0

    def received_power(self, rng_m, reflectance, cos_incidence=1.0):
        """Received power (W) from an extended Lambertian target filling the footprint."""
        rng_m = np.asarray(rng_m, float)
        k = self.peak_power_w * self.aperture_m ** 2 * self.system_efficiency / 4.0
        return k * np.exp(-2 * self.extinction_per_m * rng_m) * np.asarray(reflectance) * cos_incidence / rng_m ** 2

    def max_range(self, reflectance: float = 0.2) -> float:
        """Largest range (m) at which a target of this reflectance at normal incidence is detected."""
        from scipy.optimize import brentq

        f = lambda r: self.received_power(r, reflectance) - self.detection_threshold_w  # noqa: E731
        hi = 1e6
        if f(hi) > 0:
            return min(hi, self.max_range_m)
        return float(min(brentq(f, 1e-3, hi), self.max_range_m))


SENSOR_PRESETS: dict[str, Sensor] = {
    "als": Sensor(),
    "uls": Sensor(wavelength_nm=1550.0, peak_power_w=60.0, aperture_m=0.05, divergence_mrad=0.5, subrays=3,
                  min_separation_m=1.0, max_range_m=500.0),
    "mls": Sensor(wavelength_nm=1550.0, peak_power_w=50.0, aperture_m=0.04, divergence_mrad=0.3, subrays=1,
                  min_separation_m=0.8, min_range_m=1.0, max_range_m=300.0),
    "tls": Sensor(wavelength_nm=1550.0, peak_power_w=50.0, aperture_m=0.04, divergence_mrad=0.3, subrays=1,
                  min_separation_m=0.8, min_range_m=0.6, max_range_m=300.0),
}


@dataclass(frozen=True)
class ErrorModel:
    """Measurement and calibration errors; each is switched off by setting it to zero.

    Attributes
    ----------
    range_noise_m : float
        1-sigma Gaussian range noise (m). Default 0.02.
    gnss_noise_m : (3,) float
        1-sigma GNSS/INS position noise east, north, up (m), correlated over
        ``gnss_correlation_s``. Default (0.02, 0.02, 0.04).
    gnss_correlation_s : float
        Correlation time of the position noise (s): white samples this far apart,
        interpolated linearly. Default 10.
    gnss_bias_m : (3,) float
        Constant position bias east, north, up (m). Default 0.
    imu_noise_deg : (3,) float
        1-sigma attitude noise roll, pitch, yaw (degrees), white at the IMU rate.
        Default (0.003, 0.003, 0.008) (a post-processed tactical-grade IMU).
    lever_arm_error_m : (3,) float
        True minus nominal lever arm in the body frame (m). Default (0.01, -0.01, 0.02).
    boresight_error_deg : (3,) float
        True minus nominal boresight roll, pitch, yaw (degrees). Default (0.005, -0.004, 0.01).
    scan_angle_scale : float
        Relative error of the mirror angle: true = encoder x (1 + scale). A negative value
        bends a flat surface into a "smile" (edges up), a positive one into a frown.
        Default 2e-4.
    scan_angle_offset_deg : float
        Constant mirror angle offset (degrees); tilts every scan line. Default 0.
    time_bias_s : float
        Latency between the scanner clock and the navigation solution (s): points are
        georeferenced with the pose at ``t + time_bias``. Default 0.
    range_walk_m : float
        Amplitude-dependent range bias of leading-edge timing (range walk): a return at the
        detection threshold is ranged ``range_walk_m`` too long, a saturated one not at all,
        log-linear in received power in between. Default 0.02.
    range_offset_m : float
        Constant ranging bias (m): every recorded range is this much longer than the true
        one (an uncalibrated range zero, e.g. a cable or electronic delay). It enters the
        georeferencing chain along each beam, so it moves points along their lines of sight
        (mostly vertically near nadir, across track towards the swath edges). Default 0.
    line_bias_m : tuple of (line_id, dE, dN, dU)
        Navigation position bias per flight line (m, east / north / up), as a different GNSS
        ambiguity fix per line gives: while the scanning segment of point source id ``line_id``
        is flown, the navigation solution is offset by (dE, dN, dU), so that line's points move
        rigidly by it (a strip shifted against its neighbours, what the swath-overlap DZ check
        of the USGS Lidar Base Specification detects). Ids must be flown segments of the
        trajectory; each at most once. Default () (none).
    """

    range_noise_m: float = 0.02
    gnss_noise_m: tuple = (0.02, 0.02, 0.04)
    gnss_correlation_s: float = 10.0
    gnss_bias_m: tuple = (0.0, 0.0, 0.0)
    imu_noise_deg: tuple = (0.003, 0.003, 0.008)
    lever_arm_error_m: tuple = (0.01, -0.01, 0.02)
    boresight_error_deg: tuple = (0.005, -0.004, 0.01)
    scan_angle_scale: float = 2e-4
    scan_angle_offset_deg: float = 0.0
    time_bias_s: float = 0.0
    range_walk_m: float = 0.02
    range_offset_m: float = 0.0
    line_bias_m: tuple = ()

    def __post_init__(self):
        if not np.isfinite(self.range_offset_m):
            raise InvalidInputError(f"range_offset_m must be finite metres, got {self.range_offset_m}", field="range_offset_m")
        object.__setattr__(self, "line_bias_m", _line_biases(self.line_bias_m))

    @classmethod
    def none(cls, **overrides) -> "ErrorModel":
        """Every error off (perfect measurements), then ``overrides``."""
        z = dict(range_noise_m=0.0, gnss_noise_m=(0.0, 0.0, 0.0), gnss_bias_m=(0.0, 0.0, 0.0),
                 imu_noise_deg=(0.0, 0.0, 0.0), lever_arm_error_m=(0.0, 0.0, 0.0),
                 boresight_error_deg=(0.0, 0.0, 0.0), scan_angle_scale=0.0, scan_angle_offset_deg=0.0, time_bias_s=0.0, range_walk_m=0.0)
        z.update(overrides)
        return cls(**z)


def _line_biases(value) -> tuple:
    """``line_bias_m`` as a tuple of ``(int id, dE, dN, dU)``, checked (ids 1..65535, unique,
    finite metres); a TOML list of lists is accepted."""
    out, seen = [], set()
    for item in value or ():
        try:
            sid, de, dn, du = item
            sid_f, d = float(sid), tuple(float(v) for v in (de, dn, du))
        except (TypeError, ValueError):
            raise InvalidInputError(f"line bias {item!r} is not (line_id, dE, dN, dU)",
                                    "e.g. (2, 0.0, 0.0, 0.1) for line 2 raised 10 cm", field="line_bias_m") from None
        if not (sid_f.is_integer() and 1 <= sid_f <= 65535) or not np.all(np.isfinite(d)):
            raise InvalidInputError(f"line bias {item!r}: the id must be an integer 1-65535 and the offsets "
                                    "finite metres", field="line_bias_m")
        if int(sid_f) in seen:
            raise InvalidInputError(f"line {int(sid_f)} is biased twice", "give each line once", field="line_bias_m")
        seen.add(int(sid_f))
        out.append((int(sid_f), *d))
    return tuple(out)


@dataclass
class SimulationResult:
    """A simulated survey: the point cloud, the navigation solution used and run statistics."""

    cloud: Cloud
    trajectory: Trajectory
    true_trajectory: Trajectory
    origin: np.ndarray
    start_gps_time: float
    stats: dict = field(default_factory=dict)


def subray_pattern(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Unit-disc offsets (n, 2) on a sunflower pattern and Gaussian energy weights (n,) summing to 1.

    Offset radius 1 is the 1/e^2 beam radius; each point stands for an equal area of the disc
    and carries the Gaussian irradiance :math:`e^{-2 r^2}` of its position.
    """
    if n == 1:
        return np.zeros((1, 2)), np.ones(1)
    j = np.arange(n)
    r = np.sqrt((j + 0.5) / n)
    a = j * GOLDEN_ANGLE
    w = np.exp(-2 * r ** 2)
    return np.column_stack([r * np.cos(a), r * np.sin(a)]), w / w.sum()


class _Caster:
    """Scene arrays prepared once for vectorised lookups during a simulation."""

    def __init__(self, scene: Scene, sensor: Sensor):
        from workstation.interop.open3d_raycast import RaycastScene

        self.rc = RaycastScene(scene.vertices, scene.faces)
        tri = scene.vertices[scene.faces]
        n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        ln = np.linalg.norm(n, axis=1, keepdims=True)
        self.normals = (n / np.where(ln > 0, ln, 1.0)).astype(np.float32)
        mats = material_arrays(sensor.wavelength_nm, scene.materials)
        self.refl = mats["reflectance"][scene.material].astype(np.float32)
        self.spec = mats["specular"][scene.material].astype(np.float32)
        self.spec_w = mats["specular_width"][scene.material].astype(np.float32)
        self.has_spec = bool(np.any(self.spec > 0))
        self.porosity = mats["porosity"][scene.material].astype(np.float32)
        self.has_porous = bool(np.any(self.porosity > 0))
        self.cls = scene.classification
        self.obj = scene.object_id
        self.part = scene.part
        self.rgb = scene.face_rgb
        self.rgb16 = scene.face_rgb.astype(np.uint16) * 257


def _power(c: _Caster, sensor: Sensor, t: np.ndarray, prim: np.ndarray, dirs: np.ndarray, w, rng) -> np.ndarray:
    """Received power (W) for hits ``t`` (k,), triangles ``prim`` (k,), ray directions (k, 3)."""
    cosi = np.abs(np.einsum("ij,ij->i", c.normals[prim], dirs.astype(np.float32, copy=False)))
    rho = c.refl[prim] * cosi
    if c.has_spec:
        s = c.spec[prim]
        m = s > 0
        if np.any(m):
            ang = np.arccos(np.clip(cosi[m], 0, 1)) + rng.normal(0, WAVE_SLOPE_RAD, int(m.sum()))
            rho[m] += s[m] * np.exp(-((ang / c.spec_w[prim[m]]) ** 2))
    return sensor.received_power(t, rho) * w


#: 1-sigma random tilt of specular (water) surfaces: calm-water wave slopes (Cox & Munk 1954,
#: J. Opt. Soc. Am. 44(11):838-850: sigma^2 = 0.003 + 0.00512 U for wind speed U m/s).
WAVE_SLOPE_RAD = np.radians(3.0)

#: Size (m) of the cells of the procedural gap pattern inside porous (foliage) triangles.
GAP_CELL_M = 0.05


def _gap_value(points: np.ndarray, prim: np.ndarray) -> np.ndarray:
    """Uniform [0, 1) value per hit from a hash of its ``GAP_CELL_M`` cell and triangle.

    A spatial pattern, not a per-ray coin toss: rays hitting the same leaf-sized cell share
    the outcome, so a beam with a footprint smaller than a leaf passes or stops as a whole and
    only a wider footprint (larger divergence or range) splits into several returns.
    """
    q = np.floor(points / GAP_CELL_M).astype(np.int64)
    h = (q[:, 0] * 73856093) ^ (q[:, 1] * 19349663) ^ (q[:, 2] * 83492791) ^ (prim.astype(np.int64) * 2654435761)
    h = (h ^ (h >> 13)) * 0x5BD1E995
    h ^= h >> 15
    return (h & 0xFFFFFF).astype(np.float32) / np.float32(1 << 24)


def _cast(c: _Caster, rays: np.ndarray, rng, max_passes: int = 4) -> tuple[np.ndarray, np.ndarray]:
    """First hits of ``rays`` (n, 6) f32, letting rays pass porous (foliage) triangles.

    A triangle of porosity p stands for foliage with gaps smaller than the triangle: a ray
    goes on through it where the procedural gap pattern (:func:`_gap_value`) at the hit is
    below p, from just beyond the hit, up to ``max_passes`` times. Returns the range from the
    ray origin (n,) f64 (inf = miss) and the triangle (n,) (-1).
    """
    t, prim = c.rc.cast_rays(rays)
    t = t.astype(np.float64)
    if not c.has_porous:
        return t, prim
    eps = 0.01
    hit = np.flatnonzero(np.isfinite(t))
    active = hit[c.porosity[prim[hit]] > 0]
    for _ in range(max_passes):
        if active.size == 0:
            break
        pts = rays[active, :3].astype(np.float64) + rays[active, 3:] * t[active, None]
        go = active[_gap_value(pts, prim[active]) < c.porosity[prim[active]]]
        if go.size == 0:
            break
        r2 = rays[go].copy()
        r2[:, :3] += r2[:, 3:] * (t[go] + eps)[:, None].astype(np.float32)
        t2, p2 = c.rc.cast_rays(r2)
        ok = np.isfinite(t2)
        t[go] = np.where(ok, t[go] + eps + t2, np.inf)
        prim[go] = p2
        active = go[ok][c.porosity[p2[ok]] > 0]
    return t, prim


def _returns(c: _Caster, sensor: Sensor, origins, dirs, rng):
    """Cast the pulses' footprints and group sub-ray hits into returns.

    Returns a dict of per-return arrays: ``pulse`` (index into the batch), ``range`` (m),
    ``prim`` (triangle), ``power`` (W), ``return_number``, ``number_of_returns``.
    """
    P = len(origins)
    N = sensor.subrays
    if N == 1:
        return _single_ray_returns(c, sensor, origins, dirs, rng)
    rays, weights = _footprint_rays(sensor, origins, dirs, rng)
    t, prim = _cast(c, rays.reshape(-1, 6), rng)
    t = t.reshape(P, N)
    t = np.where((t >= sensor.min_range_m) & (t <= sensor.max_range_m), t, np.inf)
    # each pulse's hits by range; a new group starts where the next hit is beyond the pulse width
    order = np.argsort(t, axis=1)
    ts = np.take_along_axis(t, order, 1)
    ps = np.take_along_axis(prim.reshape(P, N), order, 1)
    valid = np.isfinite(ts)
    with np.errstate(invalid="ignore"):
        gap = np.diff(ts, axis=1) > sensor.min_separation_m
    gid = np.concatenate([np.zeros((P, 1), np.int64), np.cumsum(gap, axis=1)], axis=1)
    flat = np.flatnonzero(valid.ravel())
    if flat.size == 0:
        e = np.zeros(0, np.int64)
        return {"pulse": e, "range": np.zeros(0), "prim": e, "power": np.zeros(0),
                "return_number": e.astype(np.uint8), "number_of_returns": e.astype(np.uint8)}
    pulse = flat // N
    sub = order.ravel()[flat]
    tf = ts.ravel()[flat]
    pf = ps.ravel()[flat]
    dsub = rays.reshape(-1, 6)[pulse * N + sub, 3:]
    pw = _power(c, sensor, tf, pf, dsub, weights[sub], rng)
    return _merge_groups(sensor, P, pulse, pulse * N + gid.ravel()[flat], tf, pf, pw)


def _single_ray_returns(c: _Caster, sensor: Sensor, origins, dirs, rng) -> dict:
    """Returns of pulses cast as one ray each (``subrays == 1``): the first hit within the
    range gate whose received power reaches the detection threshold, one return per pulse."""
    P = len(origins)
    rays = np.empty((P, 6), np.float32)
    rays[:, :3] = origins
    rays[:, 3:] = dirs
    t, prim = _cast(c, rays, rng)
    ok = np.isfinite(t) & (t >= sensor.min_range_m) & (t <= sensor.max_range_m)
    idx = np.flatnonzero(ok)
    t = t[idx]
    prim = prim[idx]
    pw = _power(c, sensor, t, prim, dirs[idx], 1.0, rng)
    det = pw >= sensor.detection_threshold_w
    idx, t, prim, pw = idx[det], t[det], prim[det], pw[det]
    one = np.ones(len(idx), np.uint8)
    return {"pulse": idx, "range": t, "prim": prim, "power": pw, "return_number": one, "number_of_returns": one}


def _footprint_rays(sensor: Sensor, origins, dirs, rng) -> tuple[np.ndarray, np.ndarray]:
    """The sub-rays (P, N, 6) f4 sampling each beam's footprint (step 3 of the module
    docstring): the sunflower pattern scaled to the half divergence, turned by a random angle
    per pulse, in an orthonormal basis across the beam; and the sub-rays' energy weights (N,)."""
    P, N = len(origins), sensor.subrays
    offs, weights = subray_pattern(N)
    half = np.float32(sensor.divergence_mrad * 1e-3 / 2)
    d = np.asarray(dirs, np.float32)
    dx, dy, dz = d[:, 0], d[:, 1], d[:, 2]
    # an orthonormal basis (u, v) across each beam: u = d x z (or d x x near vertical), v = d x u
    steep = np.abs(dz) >= 0.9
    ux = np.where(steep, np.float32(0), dy)
    uy = np.where(steep, dz, -dx)
    uz = np.where(steep, -dy, np.float32(0))
    inv = np.float32(1) / np.sqrt(ux * ux + uy * uy + uz * uz)
    ux, uy, uz = ux * inv, uy * inv, uz * inv
    vx, vy, vz = dy * uz - dz * uy, dz * ux - dx * uz, dx * uy - dy * ux
    rot = rng.random(P, dtype=np.float32) * np.float32(2 * np.pi)
    cr, sr = np.cos(rot)[:, None], np.sin(rot)[:, None]
    o0, o1 = offs[None, :, 0].astype(np.float32), offs[None, :, 1].astype(np.float32)
    ox = half * (cr * o0 - sr * o1)  # (P, N) angular offsets (rad)
    oy = half * (sr * o0 + cr * o1)
    rays = np.empty((P, N, 6), np.float32)
    rays[:, :, :3] = origins[:, None, :]
    for i, (dc, uc, vc) in enumerate(((dx, ux, vx), (dy, uy, vy), (dz, uz, vz))):
        rays[:, :, 3 + i] = dc[:, None] + ox * uc[:, None] + oy * vc[:, None]
    return rays, weights


def _merge_groups(sensor: Sensor, P: int, pulse: np.ndarray, key: np.ndarray, tf: np.ndarray, pf: np.ndarray,
                  pw: np.ndarray) -> dict:
    """Merge the range-sorted sub-ray hits of each group (same ``key``) into one return (step 5
    of the module docstring): power-weighted mean range, summed power, the strongest sub-ray's
    triangle; keep those reaching the detection threshold, at most ``max_returns`` per pulse."""
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    lens = np.diff(np.r_[starts, key.size])
    psum = np.add.reduceat(pw, starts)
    rmean = np.add.reduceat(pw * tf, starts) / np.where(psum > 0, psum, 1.0)
    rmean = np.where(psum > 0, rmean, tf[starts])
    pmax = np.maximum.reduceat(pw, starts)
    cand = np.where(pw == np.repeat(pmax, lens), np.arange(key.size), key.size)
    strongest = np.minimum.reduceat(cand, starts)
    det = psum >= sensor.detection_threshold_w
    rp = pulse[starts][det]
    rr, rprim, rpow = rmean[det], pf[strongest[det]], psum[det]
    first = np.flatnonzero(np.r_[True, rp[1:] != rp[:-1]]) if rp.size else np.zeros(0, np.int64)
    run = np.repeat(first, np.diff(np.r_[first, rp.size]))
    rank = np.arange(rp.size) - run
    keep = rank < sensor.max_returns
    rp, rr, rprim, rpow, rank = rp[keep], rr[keep], rprim[keep], rpow[keep], rank[keep]
    count = np.bincount(rp, minlength=P)[rp]
    return {"pulse": rp, "range": rr, "prim": rprim, "power": rpow,
            "return_number": (rank + 1).astype(np.uint8), "number_of_returns": count.astype(np.uint8)}


def _walk_fraction(power: np.ndarray, sensor: Sensor) -> np.ndarray:
    """Range-walk share (1 at the detection threshold, 0 at saturation, log-linear between)."""
    lo, hi = np.log(sensor.detection_threshold_w), np.log(sensor.saturation_power_w)
    return np.clip((hi - np.log(np.maximum(power, 1e-30))) / (hi - lo), 0.0, 1.0)


def _truth(ret: dict, origins: np.ndarray, dirs: np.ndarray, origin: np.ndarray) -> dict:
    p = origins + ret["range"][:, None] * dirs + origin
    return {"true_x": p[:, 0], "true_y": p[:, 1], "true_z": p[:, 2]}


def _nav_errors(traj: Trajectory, errors: ErrorModel, rng: np.random.Generator) -> Trajectory:
    """The navigation solution: true trajectory plus GNSS noise/bias, per-line biases and IMU attitude noise."""
    t = traj.time
    k = t.size
    dpos = np.broadcast_to(np.asarray(errors.gnss_bias_m, float), (k, 3)).copy()
    sig = np.asarray(errors.gnss_noise_m, float)
    if np.any(sig > 0):
        tau = max(errors.gnss_correlation_s, 1e-3)
        knots = np.arange(t[0], t[-1] + 2 * tau, tau)
        white = rng.normal(0, 1, (knots.size, 3)) * sig
        for i in range(3):
            dpos[:, i] += np.interp(t, knots, white[:, i])
    _add_line_biases(dpos, traj, errors.line_bias_m)
    drpy = np.zeros((k, 3))
    sa = np.radians(np.asarray(errors.imu_noise_deg, float))
    if np.any(sa > 0):
        drpy = rng.normal(0, 1, (k, 3)) * sa
    return traj.with_offsets(dpos, drpy)


def _add_line_biases(dpos: np.ndarray, traj: Trajectory, biases: tuple) -> None:
    """Add each line's (dE, dN, dU) to the navigation samples of its scanning segments, from the
    last sample at or before the segment start to the first at or after its end, so every pulse
    of the line is georeferenced with the full bias (turns between lines are not scanned)."""
    t = traj.time
    ids = sorted({s.source_id for s in traj.segments})
    for sid, *d in biases:
        segs = [s for s in traj.segments if s.source_id == sid]
        if not segs:
            raise InvalidInputError(f"line bias for line {sid}, but the trajectory flies lines {ids}",
                                    "use the point source id of a flown line", field="line_bias_m")
        for s in segs:
            i0 = max(int(np.searchsorted(t, s.t0, "right")) - 1, 0)
            i1 = min(int(np.searchsorted(t, s.t1, "left")), t.size - 1)
            dpos[i0 : i1 + 1] += d


def _to_map(rpy: np.ndarray, v_b: np.ndarray, trig=None) -> np.ndarray:
    """Body-frame vectors (n, 3) to map-frame (ENU) vectors for per-pulse attitudes (n, 3)."""
    v_n = rotate_rpy(rpy, v_b, trig=trig)
    out = np.empty_like(v_n)
    out[:, 0] = v_n[:, 1]
    out[:, 1] = v_n[:, 0]
    out[:, 2] = -v_n[:, 2]
    return out


class _BatchSimulator:
    """The fixed inputs of one simulation; calling it with a job ``(segment index, segment, k0,
    k1)`` simulates pulses ``k0..k1-1`` of that segment (steps 1-6 of the module docstring).

    Each batch draws from its own random stream seeded by (seed, segment, k0), so the output
    does not depend on the order or concurrency in which batches run.
    """

    def __init__(self, scene: Scene, trajectory: Trajectory, nav: Trajectory, scanner: ScanPattern, sensor: Sensor,
                 errors: ErrorModel, mount: GeorefChain, caster: _Caster, seed: int, start_gps_time: float,
                 roll_in_scan_angle: bool, with_nir: bool, with_truth: bool):
        self.scene, self.trajectory, self.nav, self.scanner = scene, trajectory, nav, scanner
        self.sensor, self.errors, self.mount, self.caster = sensor, errors, mount, caster
        self.seed, self.start_gps_time = int(seed), start_gps_time
        self.roll_in_scan_angle, self.with_nir, self.with_truth = roll_in_scan_angle, with_nir, with_truth
        # the true mounting: nominal lever arm and boresight plus their errors
        self.true_chain = GeorefChain(
            tuple(np.asarray(mount.lever_arm) + np.asarray(errors.lever_arm_error_m, float)),
            tuple(np.asarray(mount.boresight) + np.radians(np.asarray(errors.boresight_error_deg, float))),
        )
        self.R_bs_true = self.true_chain.R_bs
        self.lever_true = np.asarray(self.true_chain.lever_arm)
        self.scale = 1.0 + errors.scan_angle_scale
        self.offset = np.radians(errors.scan_angle_offset_deg)
        self.exact_angles = self.scale == 1.0 and self.offset == 0.0

    def __call__(self, job) -> tuple[int, dict | None]:
        """Simulate one batch: (pulses fired, per-return arrays or None when nothing returned)."""
        si, seg, k0, k1 = job
        rng = np.random.default_rng([self.seed, 0x51D, si, k0])  # per batch: order-independent
        k = np.arange(k0, k1, dtype=np.int64)
        t = seg.t0 + k / self.scanner.prf
        ang = self.scanner.angles(k)
        d_true, origins, dirs = self._true_beams(t, ang)
        ret = _returns(self.caster, self.sensor, origins, dirs, rng)
        j = ret["pulse"]
        if j.size == 0:
            return len(k), None
        r_meas = self._measured_range(ret, rng)
        d_enc = d_true[j] if self.exact_angles else self.scanner.directions(ang.primary[j], ang.secondary[j])
        tp = t[j]
        pos_p, rpy_p = self.nav.interpolate(tp + self.errors.time_bias_s)
        xyz = self.mount.forward(r_meas, d_enc, pos_p, rpy_p, trig=rpy_trig(rpy_p, precise=False))
        sa = self.scanner.scan_angle_deg(ang.primary[j])
        if self.roll_in_scan_angle:
            sa = sa + np.degrees(rpy_p[:, 0])
        part = {"xyz": xyz, "gps_time": self.start_gps_time + tp}
        part.update(self._point_attrs(ret, ang, j, sa, r_meas, seg.source_id))
        if self.with_truth:
            part.update(_truth(ret, origins[j], dirs[j], self.scene.origin))
        return len(k), part

    def _true_beams(self, t: np.ndarray, ang):
        """The true beams of pulses at times ``t`` (s): mirror directions with the scan-angle
        errors (k, 3) f4, and the beam origins and directions in the scene frame through the
        true trajectory and true mounting (step 2 of the module docstring)."""
        # the true beam in float32 (the rays are float32): trig ~15x faster than float64 in numpy
        primary = ang.primary * self.scale + self.offset if not self.exact_angles else ang.primary
        d_true = self.scanner.directions(primary, ang.secondary, np.float32)
        pos, rpy = self.trajectory.interpolate(t)
        trig = rpy_trig(rpy, precise=False)
        if self.lever_true.any():
            origins = pos + _to_map(rpy, np.broadcast_to(self.lever_true.astype(np.float32), (len(t), 3)), trig)
        else:
            origins = pos
        tilted = self.true_chain.boresight != (0.0, 0.0, 0.0)
        dirs = _to_map(rpy, d_true @ self.R_bs_true.T.astype(np.float32) if tilted else d_true, trig)
        return d_true, origins, dirs

    def _measured_range(self, ret: dict, rng: np.random.Generator) -> np.ndarray:
        """The recorded range (m): true range plus Gaussian noise, range walk and offset."""
        errors = self.errors
        r_meas = ret["range"] + (rng.normal(0, errors.range_noise_m, ret["range"].size)
                                 if errors.range_noise_m > 0 else 0.0)
        if errors.range_walk_m:
            r_meas = r_meas + errors.range_walk_m * _walk_fraction(ret["power"], self.sensor)
        if errors.range_offset_m:
            r_meas = r_meas + errors.range_offset_m
        return r_meas

    def _point_attrs(self, ret: dict, ang, j: np.ndarray, sa: np.ndarray, r_meas: np.ndarray, source_id: int) -> dict:
        """The per-return attributes after ``xyz`` and ``gps_time``: labels of the hit triangle,
        return numbers, intensity on a 16-bit scale saturating at ``saturation_power_w``, scan
        angle (deg) and flags, line id, colour, measured range (m) and optionally NIR."""
        c, prim = self.caster, ret["prim"]
        attrs = {
            "classification": c.cls[prim],
            "return_number": ret["return_number"],
            "number_of_returns": ret["number_of_returns"],
            "intensity": np.minimum(np.rint(ret["power"] * (65535.0 / self.sensor.saturation_power_w)),
                                    65535).astype(np.uint16),
            "scan_angle": np.clip(sa, -180.0, 180.0).astype(np.float32),
            "scan_direction_flag": ang.direction[j],
            "edge_of_flight_line": ang.edge[j],
            "point_source_id": np.full(j.size, source_id, np.uint16),
            "object_id": c.obj[prim],
            "part": c.part[prim],
            "rgb": c.rgb16[prim],
            "range": r_meas.astype(np.float32),
        }
        if self.with_nir:
            attrs["nir"] = np.rint(c.refl[prim] * 65535).astype(np.uint16)
        return attrs


def _batch_jobs(trajectory: Trajectory, scanner: ScanPattern, per_batch: int) -> list[tuple]:
    """Split every scanning segment's pulses into batches of at most ``per_batch`` pulses:
    ``(segment index, segment, first pulse, end pulse)``."""
    return [(si, seg, k0, min(k0 + per_batch, n_seg))
            for si, seg in enumerate(trajectory.segments)
            for n_seg in [scanner.pulses_in(seg.t1 - seg.t0)]
            for k0 in range(0, n_seg, per_batch)]


def _run_batches(run_batch: Callable, jobs: list, threads: int | None,
                 progress: Callable[[int], None] | None) -> tuple[list[dict], int]:
    """Run the batches on up to 4 threads, in job order; return the non-empty parts and the
    number of pulses fired. numpy and Embree release the GIL on large arrays, so batches
    overlap on several cores. Raises StageError when no pulse returned anything."""
    from concurrent.futures import ThreadPoolExecutor

    parts: list[dict] = []
    n_pulses = 0
    workers = max(1, min(threads if threads else (os.cpu_count() or 1), 4))
    with ThreadPoolExecutor(max_workers=workers) as pool:
        for n_k, part in (pool.map(run_batch, jobs) if workers > 1 else map(run_batch, jobs)):
            n_pulses += n_k
            if progress:
                progress(n_k)
            if part is not None:
                parts.append(part)
    if not parts:
        raise StageError("simulate", f"no returns from {n_pulses} pulses",
                         "check that the trajectory flies over the scene and the range gate / power allow returns")
    return parts, n_pulses


def _join_batches(parts: list[dict], origin: np.ndarray) -> tuple[np.ndarray, dict]:
    """Concatenate the batches' returns: map coordinates (n, 3) and attributes, one attribute
    at a time, freeing the batch arrays as they are joined (peak ~ output + 1 attribute)."""
    xyz = np.concatenate([p.pop("xyz") for p in parts])
    xyz += origin
    attrs = {k: np.concatenate([p.pop(k) for p in parts]) for k in list(parts[0])}
    attrs["user_data"] = (attrs["object_id"] % 256).astype(np.uint8)
    return xyz, attrs


def _run_stats(n_pulses: int, n_returns: int, attrs: dict, seconds: float, sensor: Sensor, scanner: ScanPattern,
               errors: ErrorModel) -> dict:
    """The run statistics of :class:`SimulationResult`: counts, wall time (s), pulse rate (1/s),
    share of returns from multiple-return pulses, and the sensor, scanner and error settings."""
    return {"pulses": n_pulses, "returns": n_returns, "seconds": seconds,
            "pulses_per_second": n_pulses / seconds if seconds > 0 else float("nan"),
            "multiple_return_share": float(np.mean(attrs["number_of_returns"] > 1)),
            "sensor": asdict(sensor), "scanner": asdict(scanner), "errors": asdict(errors)}


def _simulated_cloud(xyz: np.ndarray, attrs: dict, scene: Scene, scanner: ScanPattern, seed: int,
                     seconds: float) -> Cloud:
    """The output cloud in the scene's CRS with the simulation's meta and history entry;
    StageError if it is empty."""
    cloud = Cloud(xyz, attrs, crs=scene.crs, meta={"simulation": {"seed": int(seed), "scene": scene.meta.get("recipe")}})
    cloud = cloud.with_history("simulate", {"scanner": scanner.kind, "prf": scanner.prf, "seed": int(seed)}, seconds)
    if cloud.n == 0:
        raise StageError("simulate", "empty cloud")
    return cloud


def simulate(
    scene: Scene,
    trajectory: Trajectory,
    scanner: ScanPattern,
    sensor: Sensor | None = None,
    errors: ErrorModel | None = None,
    *,
    mount: GeorefChain = GeorefChain(),
    seed: int = 0,
    start_gps_time: float = DEFAULT_GPS_TIME,
    batch_rays: int = 1 << 20,
    progress: Callable[[int], None] | None = None,
    roll_in_scan_angle: bool = True,
    with_nir: bool = False,
    with_truth: bool = False,
    threads: int | None = None,
) -> SimulationResult:
    """Simulate a survey of ``scene`` along ``trajectory`` with ``scanner`` and ``sensor``.

    Parameters
    ----------
    scene : Scene
    trajectory : Trajectory
        True platform trajectory (local frame); its segments are scanned.
    scanner : ScanPattern
    sensor : Sensor, optional
        Default :data:`SENSOR_PRESETS` ``["als"]``.
    errors : ErrorModel, optional
        Default :class:`ErrorModel` (realistic small errors); ``ErrorModel.none()`` for none.
    mount : GeorefChain
        Nominal lever arm and boresight (known to the processing).
    seed : int
        Seeds every random draw (noise, sub-ray rotation); same inputs and seed -> same output.
    start_gps_time : float
        Adjusted standard GPS time of trajectory time 0 (s).
    batch_rays : int
        Rays cast per batch (memory ~ 100 bytes per ray).
    progress : callable, optional
        Called with the number of pulses done after each batch.
    roll_in_scan_angle : bool
        Add the platform roll to the LAS scan angle (LAS 1.4: "including the roll of the
        aircraft"); False for TLS, whose scan angle is the elevation.
    with_nir : bool
        Also give ``nir`` (u16): the hit material's reflectance at the laser wavelength on a
        16-bit scale (LAS point format 8).
    with_truth : bool
        Also give ``true_x``, ``true_y``, ``true_z`` (f8, map coordinates): where the return
        really is (power-weighted mean of its sub-ray hits), so every error is known per point.
    threads : int, optional
        Batches processed at once (default: the number of cores, at most 4). The output does
        not depend on it: every batch draws from its own random stream.

    Returns
    -------
    SimulationResult
        ``cloud`` in map coordinates (scene CRS) with ``classification``, ``return_number``,
        ``number_of_returns``, ``intensity``, ``gps_time``, ``scan_angle``,
        ``scan_direction_flag``, ``edge_of_flight_line``, ``point_source_id``, ``user_data``
        (object id mod 256), ``object_id`` (u32), ``part`` (u8, roof / wall / trunk / crown /
        vehicle ... see :data:`workstation.lidar.scene.PARTS`), ``rgb`` and ``range`` (f4, m).
    """
    sensor = sensor or SENSOR_PRESETS["als"]
    errors = errors or ErrorModel()
    t_start = time.perf_counter()
    nav_rng = np.random.default_rng([int(seed), 0x4E4156])
    caster = _Caster(scene, sensor)
    nav = _nav_errors(trajectory, errors, nav_rng)
    run_batch = _BatchSimulator(scene, trajectory, nav, scanner, sensor, errors, mount, caster, seed, start_gps_time,
                                roll_in_scan_angle, with_nir, with_truth)
    jobs = _batch_jobs(trajectory, scanner, max(batch_rays // sensor.subrays, 1))
    parts, n_pulses = _run_batches(run_batch, jobs, threads, progress)
    xyz, attrs = _join_batches(parts, scene.origin)
    seconds = time.perf_counter() - t_start
    stats = _run_stats(n_pulses, xyz.shape[0], attrs, seconds, sensor, scanner, errors)
    cloud = _simulated_cloud(xyz, attrs, scene, scanner, seed, seconds)
    log.info("simulated %d pulses -> %d returns in %.1f s", n_pulses, xyz.shape[0], seconds)
    return SimulationResult(cloud, nav, trajectory, scene.origin, start_gps_time, stats)


def trajectory_table(result: SimulationResult) -> dict[str, np.ndarray]:
    """The navigation solution as columns in map coordinates (SBET-like), degrees for angles."""
    tr = result.trajectory
    v = tr.velocity()
    return {
        "gps_time": result.start_gps_time + tr.time,
        "easting": tr.position[:, 0] + result.origin[0],
        "northing": tr.position[:, 1] + result.origin[1],
        "height": tr.position[:, 2] + result.origin[2],
        "roll_deg": np.degrees(tr.rpy[:, 0]),
        "pitch_deg": np.degrees(tr.rpy[:, 1]),
        "heading_deg": np.mod(np.degrees(tr.rpy[:, 2]), 360.0),
        "vel_east": v[:, 0],
        "vel_north": v[:, 1],
        "vel_up": v[:, 2],
    }


def write_trajectory_csv(result: SimulationResult, path, overwrite: bool = False) -> Path:
    """Write the navigation solution as CSV (one row per IMU epoch, header line, metres/degrees)."""
    from workstation.io import atomic_path

    cols = trajectory_table(result)
    arr = np.column_stack(list(cols.values()))
    fmt = ["%.6f", "%.4f", "%.4f", "%.4f", "%.6f", "%.6f", "%.6f", "%.4f", "%.4f", "%.4f"]
    with atomic_path(path, overwrite=overwrite) as tmp:
        np.savetxt(tmp, arr, delimiter=",", header=",".join(cols), comments="", fmt=fmt)
    return Path(path)


def ground_height_fn(scene: Scene, classes=(C.GROUND, C.ROAD_SURFACE, C.BRIDGE_DECK, C.WATER)):
    """A function ``xy (n, 2) -> z (n,)`` giving the height of the ground-like surfaces below."""
    from workstation.interop.open3d_raycast import RaycastScene

    mask = np.isin(scene.classification, np.asarray(classes, np.uint8))
    if not mask.any():
        raise InvalidInputError("scene has no ground faces to stand on", field="classification")
    rc = RaycastScene(scene.vertices, scene.faces[mask])
    top = float(scene.vertices[:, 2].max()) + 100.0
    fallback = float(np.median(scene.vertices[:, 2]))

    def fn(xy):
        xy = np.atleast_2d(np.asarray(xy, float))
        o = np.column_stack([xy, np.full(len(xy), top)])
        d = np.tile([0.0, 0.0, -1.0], (len(xy), 1))
        t, _ = rc.cast(o, d)
        return np.where(np.isfinite(t), top - t, fallback)

    return fn
