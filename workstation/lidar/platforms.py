"""Platforms and their trajectories: aircraft / drone flight lines, a vehicle path, tripod stations.

A :class:`Trajectory` is the navigation solution sampled at the IMU rate: time, position of the
IMU origin (local scene frame: x east, y north, z up, metres), attitude (roll, pitch, yaw in
radians; yaw clockwise from north, the aerospace convention used by :mod:`georef`) and the
scanning segments (time intervals in which the scanner fires, each with its point source id:
a flight line, a drive or a station).

Flight lines over a rectangle are laid out with a lateral overlap; between lines the aircraft
turns with a constant bank angle :math:`\\varphi`, radius :math:`R = v^2 / (g \\tan\\varphi)`
(the coordinated-turn relation). Lines closer than :math:`2R` use a "bulb" (procedure) turn of
three arcs whose length is :math:`R(\\pi + 4\\beta)`, :math:`\\cos\\beta = (d + 2R)/(4R)`; wider
ones a semicircle pair joined by a straight leg. Attitude oscillates with a few sinusoids
(turbulence and autopilot corrections), and the aircraft banks in the turns.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from workstation.core.errors import InvalidInputError

G = 9.80665  # m/s^2


@dataclass(frozen=True)
class Segment:
    """A scanning interval of a trajectory: [t0, t1) seconds, point source id, kind."""

    t0: float
    t1: float
    source_id: int
    kind: str = "line"


@dataclass(frozen=True)
class Trajectory:
    """Navigation solution sampled at the IMU rate.

    Attributes
    ----------
    time : (k,) float64
        Seconds from the start of the survey (strictly increasing).
    position : (k, 3) float64
        IMU origin in the local scene frame (m).
    rpy : (k, 3) float64
        Roll, pitch, yaw (radians), yaw unwrapped (continuous).
    segments : tuple of Segment
    """

    time: np.ndarray
    position: np.ndarray
    rpy: np.ndarray
    segments: tuple = ()

    def __post_init__(self):
        t = np.asarray(self.time, float)
        if t.ndim != 1 or t.size < 2 or np.any(np.diff(t) <= 0):
            raise InvalidInputError("trajectory time must have >= 2 strictly increasing samples", field="time")
        for name in ("position", "rpy"):
            a = np.asarray(getattr(self, name), float)
            if a.shape != (t.size, 3):
                raise InvalidInputError(f"{name} must be ({t.size}, 3), got {a.shape}", field=name)

    def interpolate(self, t) -> tuple[np.ndarray, np.ndarray]:
        """Position (n, 3) and roll/pitch/yaw (n, 3) at times ``t`` (n,), linear interpolation."""
        t = np.asarray(t, float)
        cols = self._columns
        pos = np.empty((t.size, 3))
        rpy = np.empty((t.size, 3))
        for i in range(3):
            pos[:, i] = np.interp(t, self.time, cols[i])
            rpy[:, i] = np.interp(t, self.time, cols[3 + i])
        return pos, rpy

    @property
    def _columns(self) -> list[np.ndarray]:
        cols = self.__dict__.get("_cols")
        if cols is None:
            cols = [np.ascontiguousarray(a[:, i]) for a in (self.position, self.rpy) for i in range(3)]
            object.__setattr__(self, "_cols", cols)
        return cols

    def velocity(self) -> np.ndarray:
        """(k, 3) velocity (m/s) by central differences."""
        return np.gradient(self.position, self.time, axis=0)

    def with_offsets(self, dpos: np.ndarray, drpy: np.ndarray) -> "Trajectory":
        return Trajectory(self.time, self.position + dpos, self.rpy + drpy, self.segments)


@dataclass(frozen=True)
class Oscillation:
    """Attitude and height oscillation of a platform (amplitudes in degrees / metres).

    Each axis is a sum of three sinusoids with periods ``periods_s`` and random phases, scaled
    so the peak is about the amplitude given.
    """

    roll_deg: float = 1.0
    pitch_deg: float = 0.5
    yaw_deg: float = 0.7
    height_m: float = 0.5
    periods_s: tuple = (4.0, 11.0, 27.0)

    def sample(self, t: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(k, 3) roll/pitch/yaw offsets (rad) and (k,) height offsets (m) at times ``t``."""
        out = np.zeros((t.size, 4))
        amps = np.array([np.radians(self.roll_deg), np.radians(self.pitch_deg), np.radians(self.yaw_deg), self.height_m])
        for j in range(4):
            for p in self.periods_s:
                out[:, j] += np.sin(2 * np.pi * t / p + rng.uniform(0, 2 * np.pi)) * amps[j] / len(self.periods_s)
        return out[:, :3], out[:, 3]

    @classmethod
    def none(cls) -> "Oscillation":
        return cls(0.0, 0.0, 0.0, 0.0)


@dataclass(frozen=True)
class FlightSpec:
    """A block of parallel flight lines (ALS or ULS).

    Attributes
    ----------
    altitude : float
        Flying height above ``ground_height`` (m).
    speed : float
        Ground speed (m/s).
    swath : float
        Swath width on flat ground (m) used to space the lines (from the scanner FOV).
    overlap : float
        Lateral overlap of neighbouring swaths (0-1).
    heading_deg : float
        Direction of the first line, clockwise from north (degrees).
    run_in : float
        Extra line length before and after the area (m), scanned.
    bank_deg : float
        Bank angle in the turns (degrees).
    imu_rate : float
        Trajectory sample rate (Hz).
    n_lines : int or None
        Fly this many lines (centred on the area) instead of covering it.
    min_lines : int
        Fly at least this many lines (e.g. 2 to have an overlap to check strips).
    oscillation : Oscillation
    """

    altitude: float = 800.0
    speed: float = 60.0
    swath: float = 580.0
    overlap: float = 0.3
    heading_deg: float = 90.0
    run_in: float = 50.0
    bank_deg: float = 20.0
    imu_rate: float = 200.0
    n_lines: int | None = None
    min_lines: int = 1
    oscillation: Oscillation = field(default_factory=Oscillation)


def _arc_or_straight(p0, psi0, kind: str, length: float, radius: float, step: float):
    """Sample one path primitive. Heading psi clockwise from north; dir = (sin psi, cos psi)."""
    n = max(int(np.ceil(length / step)), 1)
    s = np.linspace(0.0, length, n + 1)
    if kind == "S":
        d = np.array([np.sin(psi0), np.cos(psi0)])
        xy = p0 + s[:, None] * d
        psi = np.full_like(s, psi0)
        bank = np.zeros_like(s)
    else:
        sgn = 1.0 if kind == "R" else -1.0  # right turn: heading increases
        psi = psi0 + sgn * s / radius
        rn0 = np.array([np.cos(psi0), -np.sin(psi0)])  # right normal
        c = p0 + sgn * radius * rn0
        xy = c - sgn * radius * np.column_stack([np.cos(psi), -np.sin(psi)])
        bank = np.full_like(s, sgn)
    return xy, psi, bank


def _turn(kind: str, d: float, R: float):
    """Primitives (kind, length) of a 180-degree turn to an offset ``d`` on the ``kind`` side."""
    other = "L" if kind == "R" else "R"
    if d >= 2 * R:
        return [(kind, np.pi / 2 * R), ("S", d - 2 * R), (kind, np.pi / 2 * R)]
    beta = np.arccos((d + 2 * R) / (4 * R))
    return [(other, beta * R), (kind, (np.pi + 2 * beta) * R), (other, beta * R)]


def turn_length(d: float, R: float) -> float:
    """Path length (m) of a 180-degree turn between lines ``d`` metres apart with radius ``R``."""
    return float(sum(L for _, L in _turn("R", d, R)))


def flight_lines(area: tuple, ground_height: float, spec: FlightSpec, rng: np.random.Generator) -> Trajectory:
    """Trajectory of a block of parallel lines over ``area`` = (xmin, xmax, ymin, ymax) (local m).

    Lines run along ``spec.heading_deg`` (and back), spaced ``swath * (1 - overlap)`` apart
    and centred on the area; every line is a scanning :class:`Segment` with ``source_id`` 1,
    2, ...; the turns between them, and 2 s of straight flight before the first and after the
    last line, are part of the trajectory but not scanned.
    """
    if spec.speed <= 0 or spec.altitude <= 0 or spec.swath <= 0 or not 0 <= spec.overlap < 1:
        raise InvalidInputError("speed, altitude and swath must be positive and overlap in [0, 1)", field="flight")
    xmin, xmax, ymin, ymax = area
    psi = np.radians(spec.heading_deg)
    u = np.array([np.sin(psi), np.cos(psi)])  # along
    w = np.array([np.cos(psi), -np.sin(psi)])  # right of along
    corners = np.array([[xmin, ymin], [xmax, ymin], [xmax, ymax], [xmin, ymax]])
    cu, cw = corners @ u, corners @ w
    width = cw.max() - cw.min()
    spacing = spec.swath * (1 - spec.overlap)
    n = spec.n_lines or max(int(np.ceil(max(width - spec.swath, 0.0) / spacing)) + 1, spec.min_lines, 1)
    w_pos = (cw.min() + cw.max()) / 2 + (np.arange(n) - (n - 1) / 2) * spacing
    length = cu.max() - cu.min() + 2 * spec.run_in
    u0 = cu.min() - spec.run_in
    R = spec.speed ** 2 / (G * np.tan(np.radians(spec.bank_deg)))
    step = spec.speed / spec.imu_rate
    xy_parts, psi_parts, bank_parts, seg_bounds = [], [], [], []
    lead = 2.0 * spec.speed  # 2 s of unscanned straight flight before the first and after the last line
    pos = (u0 - lead) * u + w_pos[0] * w
    heading = psi
    xy, ps, bk = _arc_or_straight(pos, heading, "S", lead, R, step)
    xy_parts.append(xy[:-1]), psi_parts.append(ps[:-1]), bank_parts.append(bk[:-1])
    pos, s_total = xy[-1], lead
    for i in range(n):
        xy, ps, bk = _arc_or_straight(pos, heading, "S", length, R, step)
        seg_bounds.append((s_total, s_total + length, i + 1))
        xy_parts.append(xy[:-1]), psi_parts.append(ps[:-1]), bank_parts.append(bk[:-1])
        s_total += length
        pos, heading = xy[-1], ps[-1]
        if i == n - 1:
            xy, ps, bk = _arc_or_straight(pos, heading, "S", lead, R, step)
            xy_parts.append(xy), psi_parts.append(ps), bank_parts.append(bk)
            break
        kind = "R" if i % 2 == 0 else "L"
        for k, L in _turn(kind, spacing, R):
            if L <= 0:
                continue
            xy, ps, bk = _arc_or_straight(pos, heading, k, L, R, step)
            xy_parts.append(xy[:-1]), psi_parts.append(ps[:-1]), bank_parts.append(bk[:-1])
            s_total += L
            pos, heading = xy[-1], ps[-1]
    xy = np.vstack(xy_parts)
    heading = np.concatenate(psi_parts)
    bank = np.concatenate(bank_parts)
    # arc length -> time; resample on a uniform time grid at the IMU rate
    seglen = np.r_[0.0, np.cumsum(np.hypot(*np.diff(xy, axis=0).T))]
    t_s = seglen / spec.speed
    t = np.arange(0.0, t_s[-1], 1.0 / spec.imu_rate)
    x = np.interp(t, t_s, xy[:, 0])
    y = np.interp(t, t_s, xy[:, 1])
    hd = np.interp(t, t_s, heading)
    bk = np.interp(t, t_s, bank)
    # ease the bank in and out over ~2 s (roll rate of a real aircraft)
    k = max(int(2.0 * spec.imu_rate), 1)
    bk = np.convolve(np.pad(bk, (k // 2, k - 1 - k // 2), mode="edge"), np.ones(k) / k, mode="valid")
    osc, dz = spec.oscillation.sample(t, rng)
    rpy = np.column_stack([np.radians(spec.bank_deg) * bk + osc[:, 0], osc[:, 1], hd + osc[:, 2]])
    z = ground_height + spec.altitude + dz
    segs = tuple(Segment(s0 / spec.speed, s1 / spec.speed, sid, "line") for s0, s1, sid in seg_bounds)
    return Trajectory(t, np.column_stack([x, y, z]), rpy, segs)


@dataclass(frozen=True)
class VehicleSpec:
    """A mobile mapping vehicle driving a polyline.

    Attributes
    ----------
    speed : float
        m/s.
    imu_height : float
        Height of the IMU origin above the road (m).
    imu_rate : float
        Hz.
    oscillation : Oscillation
        Body roll/pitch/yaw wobble (degrees) and suspension bounce (m).
    """

    speed: float = 10.0
    imu_height: float = 1.8
    imu_rate: float = 200.0
    oscillation: Oscillation = field(default_factory=lambda: Oscillation(0.3, 0.3, 0.2, 0.02, (1.5, 3.7, 9.0)))


def vehicle_path(waypoints: np.ndarray, ground_fn, spec: VehicleSpec, rng: np.random.Generator,
                 source_id: int = 1) -> Trajectory:
    """Trajectory along a 2-D polyline ``waypoints`` (k, 2) at constant speed.

    ``ground_fn(xy (n, 2)) -> (n,)`` gives the road height; the pitch follows the road slope
    and the heading the path direction. The whole drive is one scanning segment.
    """
    wp = np.asarray(waypoints, float)
    if wp.ndim != 2 or wp.shape[1] != 2 or len(wp) < 2:
        raise InvalidInputError("waypoints must be (k >= 2, 2)", field="waypoints")
    seglen = np.r_[0.0, np.cumsum(np.hypot(*np.diff(wp, axis=0).T))]
    t = np.arange(0.0, seglen[-1] / spec.speed, 1.0 / spec.imu_rate)
    s = t * spec.speed
    xy = np.column_stack([np.interp(s, seglen, wp[:, 0]), np.interp(s, seglen, wp[:, 1])])
    zg = np.asarray(ground_fn(xy), float)
    d = np.gradient(xy, axis=0)
    heading = np.unwrap(np.arctan2(d[:, 0], d[:, 1]))
    ds = np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-9)
    pitch = np.arctan2(np.gradient(zg), ds)
    k = max(int(0.5 * spec.imu_rate), 1)
    pitch = np.convolve(np.pad(pitch, (k // 2, k - 1 - k // 2), mode="edge"), np.ones(k) / k, mode="valid")
    osc, dz = spec.oscillation.sample(t, rng)
    rpy = np.column_stack([osc[:, 0], pitch + osc[:, 1], heading + osc[:, 2]])
    pos = np.column_stack([xy, zg + spec.imu_height + dz])
    return Trajectory(t, pos, rpy, (Segment(float(t[0]), float(t[-1]), source_id, "drive"),))


@dataclass(frozen=True)
class Station:
    """A terrestrial scanner set up on a tripod.

    Attributes
    ----------
    x, y : float
        Local position (m).
    height : float
        Instrument height above the ground (m).
    heading_deg : float
        Direction of the scanner's zero azimuth, clockwise from north.
    """

    x: float
    y: float
    height: float = 1.6
    heading_deg: float = 0.0


def station_trajectory(stations: list[Station], ground_fn, durations: list[float], pause: float = 60.0) -> Trajectory:
    """A trajectory holding each station's pose (level) for its scan ``durations`` (s).

    The scanner is levelled (roll = pitch = 0); station ``i`` becomes point source ``i + 1``.
    """
    if not stations:
        raise InvalidInputError("no stations", "give at least one TLS station", field="stations")
    xy = np.array([[s.x, s.y] for s in stations], float)
    z = np.asarray(ground_fn(xy), float) + np.array([s.height for s in stations])
    t, pos, rpy, segs = [], [], [], []
    t0 = 0.0
    for i, (s, d) in enumerate(zip(stations, durations)):
        t.extend([t0, t0 + d])
        p = [s.x, s.y, z[i]]
        pos.extend([p, p])
        r = [0.0, 0.0, np.radians(s.heading_deg)]
        rpy.extend([r, r])
        segs.append(Segment(t0, t0 + d, i + 1, "station"))
        t0 += d + pause
    return Trajectory(np.array(t), np.array(pos), np.array(rpy), tuple(segs))
