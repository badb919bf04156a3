"""Survey presets: everything needed to fly (or drive, or set up) a scanner over a scene.

:class:`SurveyConfig` bundles a platform, a scan pattern, a sensor, an error model and the
nominal mounting; :func:`default_survey` gives sensible presets per kind (``als``, ``uls``,
``mls``, ``tls``) for a scene, :func:`survey_from_toml` reads overrides from a config file
(tables ``[survey]``, ``[flight]``, ``[vehicle]``, ``[scanner]``, ``[sensor]``, ``[errors]``,
``[[stations]]``), and :func:`run_survey` builds the trajectory and runs the simulator.
"""

from __future__ import annotations

import dataclasses
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError

from workstation.io.textfile import read_text

from .georef import GeorefChain
from .platforms import FlightSpec, Oscillation, Station, Trajectory, VehicleSpec, flight_lines, station_trajectory, vehicle_path
from .scanners import ScanPattern
from .scene import Scene
from .simulate import DEFAULT_GPS_TIME, SENSOR_PRESETS, ErrorModel, Sensor, SimulationResult, ground_height_fn, simulate

KINDS = ("als", "uls", "mls", "tls")


@dataclass(frozen=True)
class SurveyConfig:
    """A complete survey description.

    Attributes
    ----------
    kind : str
        ``als``, ``uls``, ``mls`` or ``tls``.
    scanner : ScanPattern
    sensor : Sensor
    errors : ErrorModel
    flight : FlightSpec
        ALS/ULS block (its ``swath`` is recomputed from altitude and FOV).
    area : (xmin, xmax, ymin, ymax) or None
        Block to cover in local scene metres; None = the whole scene (ULS: its central
        150 m square).
    vehicle : VehicleSpec
    waypoints : ((x, y), ...) or None
        MLS path in local metres; None = along the scene's road.
    stations : tuple of Station or None
        TLS set-ups; None = three stations beside the road.
    lever_arm : (3,) float
        Nominal lever arm, body frame (m).
    boresight_deg : (3,) float
        Nominal boresight roll, pitch, yaw (degrees).
    start_gps_time : float
        Adjusted standard GPS time at the start (s).
    """

    kind: str = "als"
    scanner: ScanPattern = field(default_factory=ScanPattern)
    sensor: Sensor = field(default_factory=Sensor)
    errors: ErrorModel = field(default_factory=ErrorModel)
    flight: FlightSpec = field(default_factory=FlightSpec)
    area: tuple | None = None
    vehicle: VehicleSpec = field(default_factory=VehicleSpec)
    waypoints: tuple | None = None
    stations: tuple | None = None
    lever_arm: tuple = (0.0, 0.0, 0.0)
    boresight_deg: tuple = (0.0, 0.0, 0.0)
    start_gps_time: float = DEFAULT_GPS_TIME


def default_survey(kind: str) -> SurveyConfig:
    """Preset survey of a kind (see the module docs for what each flies)."""
    if kind == "als":
        return SurveyConfig("als", ScanPattern("zigzag", prf=300_000, scan_frequency=50, fov_deg=40),
                            SENSOR_PRESETS["als"], ErrorModel(),
                            FlightSpec(altitude=500, speed=60, overlap=0.5, run_in=30, min_lines=2),
                            lever_arm=(0.1, 0.0, 0.25))
    if kind == "uls":
        return SurveyConfig("uls", ScanPattern("polygon", prf=100_000, scan_frequency=100, fov_deg=90),
                            SENSOR_PRESETS["uls"], ErrorModel(gnss_noise_m=(0.015, 0.015, 0.03), imu_noise_deg=(0.01, 0.01, 0.02)),
                            FlightSpec(altitude=60, speed=8, overlap=0.5, run_in=10, bank_deg=30, min_lines=2,
                                       oscillation=Oscillation(1.5, 1.0, 1.0, 0.3, (2.0, 5.0, 13.0))),
                            lever_arm=(0.05, 0.0, 0.1))
    if kind == "mls":
        return SurveyConfig("mls", ScanPattern("rotating", prf=200_000, scan_frequency=100, fov_deg=360),
                            SENSOR_PRESETS["mls"], ErrorModel(gnss_noise_m=(0.02, 0.02, 0.03), boresight_error_deg=(0.01, -0.01, 0.01)),
                            vehicle=VehicleSpec(speed=10.0), lever_arm=(-0.5, 0.0, -0.6))
    if kind == "tls":
        return SurveyConfig("tls", ScanPattern("spherical", prf=1_000_000, h_step_deg=0.25, v_step_deg=0.25,
                                               v_min_deg=-45, v_max_deg=90),
                            SENSOR_PRESETS["tls"],
                            ErrorModel.none(range_noise_m=0.003, gnss_noise_m=(0.005, 0.005, 0.005), gnss_correlation_s=1e6,
                                            imu_noise_deg=(0.0, 0.0, 0.0)))
    raise InvalidInputError(f"unknown survey kind '{kind}'", f"use one of {', '.join(KINDS)}", field="kind")


def _update(obj, data: dict, where: str):
    names = {f.name for f in dataclasses.fields(obj)}
    bad = set(data) - names
    if bad:
        raise InvalidInputError(f"unknown key(s) {sorted(bad)} in [{where}]", "keys: " + ", ".join(sorted(names)), field=where)
    conv = {k: tuple(v) if isinstance(v, list) else v for k, v in data.items()}
    if "oscillation" in conv and isinstance(conv["oscillation"], dict):
        conv["oscillation"] = replace(getattr(obj, "oscillation"), **conv["oscillation"])
    return replace(obj, **conv)


def survey_from_toml(path, kind: str | None = None) -> tuple[SurveyConfig, dict]:
    """A survey from a TOML config; returns it and the ``[survey]`` table (scene, seed, ...)."""
    p = Path(path)
    if not p.exists():
        raise InvalidInputError("config file not found", path=p)
    try:
        data = tomllib.loads(read_text(p))
    except tomllib.TOMLDecodeError as e:
        raise InvalidInputError(f"not valid TOML: {e}", path=p) from None
    top = dict(data.get("survey", {}))
    kind = kind or top.get("kind", "als")
    cfg = default_survey(kind)
    return apply_overrides(cfg, data), top


def apply_overrides(cfg: SurveyConfig, data: dict) -> SurveyConfig:
    """Apply nested override tables (``flight``, ``scanner``, ``sensor``, ``errors``, ...)."""
    kw = {}
    for sect in ("flight", "vehicle", "scanner", "sensor", "errors"):
        if data.get(sect):
            kw[sect] = _update(getattr(cfg, sect), data[sect], sect)
    if data.get("stations"):
        try:
            kw["stations"] = tuple(Station(**s) for s in data["stations"])
        except TypeError as e:
            raise InvalidInputError(f"bad [[stations]] entry: {e}", "keys: x, y, height, heading_deg", field="stations") from None
    top = data.get("survey", {})
    for k in ("area", "waypoints", "lever_arm", "boresight_deg", "start_gps_time"):
        if k in top:
            v = top[k]
            kw[k] = tuple(tuple(x) if isinstance(x, list) else x for x in v) if isinstance(v, list) else v
    return replace(cfg, **kw)


def _scene_area(scene: Scene) -> tuple[float, float, float, float]:
    lo, hi = scene.bounds_local()
    return float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1])


def _road_points(scene: Scene, margin: float = 10.0, step: float = 5.0) -> np.ndarray:
    """Points along the scene's road (local m), inside the extent; a diagonal if no road."""
    xmin, xmax, ymin, ymax = _scene_area(scene)
    road = scene.meta.get("road")
    if road:
        p, d = np.array(road["p"]), np.array(road["d"])
    else:
        p, d = np.array([(xmin + xmax) / 2, (ymin + ymax) / 2]), np.array([1.0, 1.0]) / np.sqrt(2)
    s = np.arange(-2000.0, 2000.0, step)
    pts = p + s[:, None] * d
    inside = (pts[:, 0] > xmin + margin) & (pts[:, 0] < xmax - margin) & (pts[:, 1] > ymin + margin) & (pts[:, 1] < ymax - margin)
    pts = pts[inside]
    if len(pts) < 2:
        raise InvalidInputError("the scene is too small for a vehicle path", field="waypoints")
    return pts


def default_stations(scene: Scene, n: int = 3) -> tuple[Station, ...]:
    """``n`` TLS stations on the verge of the road, spread along it, away from the stream."""
    pts = _road_points(scene, margin=25.0, step=1.0)
    road = scene.meta.get("road")
    normal = np.array([-road["d"][1], road["d"][0]]) if road else np.zeros(2)
    stream = scene.meta.get("stream")
    if stream:
        sp, sd = np.array(stream["p"]), np.array(stream["d"])
        dist = np.abs((pts[:, 0] - sp[0]) * -sd[1] + (pts[:, 1] - sp[1]) * sd[0])
        pts = pts[dist > stream["half_width"] + 15.0] if np.any(dist > stream["half_width"] + 15.0) else pts
    idx = np.linspace(0, len(pts) - 1, n + 2)[1:-1].round().astype(int)
    return tuple(Station(float(x), float(y), 1.6, 0.0) for x, y in pts[idx] + 4.0 * normal)


def survey_trajectory(scene: Scene, cfg: SurveyConfig, seed: int = 0) -> Trajectory:
    """The true platform trajectory of ``cfg`` over ``scene`` (deterministic for a seed)."""
    rng = np.random.default_rng(np.random.SeedSequence([int(seed), 0x7A7]))
    ground = ground_height_fn(scene)
    if cfg.kind in ("als", "uls"):
        area = cfg.area
        if area is None:
            area = _scene_area(scene)
            if cfg.kind == "uls":
                cx, cy = (area[0] + area[1]) / 2, (area[2] + area[3]) / 2
                h = min(75.0, (area[1] - area[0]) / 2, (area[3] - area[2]) / 2)
                area = (cx - h, cx + h, cy - h, cy + h)
        if cfg.scanner.kind not in ("zigzag", "polygon", "palmer"):
            raise InvalidInputError(f"{cfg.kind} needs a zigzag, polygon or palmer scanner", field="scanner")
        swath = 2 * cfg.flight.altitude * np.tan(np.radians(cfg.scanner.fov_deg) / 2)
        cx, cy = (area[0] + area[1]) / 2, (area[2] + area[3]) / 2
        gh = float(np.median(ground(np.array([[cx, cy], [area[0], area[2]], [area[1], area[3]], [area[0], area[3]], [area[1], area[2]]]))))
        return flight_lines(area, gh, replace(cfg.flight, swath=float(swath)), rng)
    elif cfg.kind == "mls":
        wp = np.array(cfg.waypoints, float) if cfg.waypoints else _road_points(scene)
        return vehicle_path(wp, ground, cfg.vehicle, rng)
    elif cfg.kind == "tls":
        if cfg.scanner.kind != "spherical":
            raise InvalidInputError("tls needs the spherical scanner", field="scanner")
        stations = cfg.stations or default_stations(scene)
        return station_trajectory(list(stations), ground, [cfg.scanner.tls_duration()] * len(stations))
    raise InvalidInputError(f"unknown survey kind '{cfg.kind}'", f"use one of {', '.join(KINDS)}", field="kind")


def count_pulses(traj: Trajectory, scanner: ScanPattern) -> int:
    """Pulses fired over all scanning segments of a trajectory."""
    return int(sum(scanner.pulses_in(s.t1 - s.t0) for s in traj.segments))


def run_survey(scene: Scene, cfg: SurveyConfig, seed: int = 0, progress=None, with_nir: bool = False,
               trajectory: Trajectory | None = None) -> SimulationResult:
    """Simulate the survey ``cfg`` over ``scene`` (trajectory from :func:`survey_trajectory`
    unless given)."""
    traj = trajectory if trajectory is not None else survey_trajectory(scene, cfg, seed)
    mount = GeorefChain(cfg.lever_arm, tuple(np.radians(cfg.boresight_deg)))
    roll_in = cfg.kind != "tls"
    return simulate(scene, traj, cfg.scanner, cfg.sensor, cfg.errors, mount=mount, seed=seed,
                    start_gps_time=cfg.start_gps_time, progress=progress, roll_in_scan_angle=roll_in, with_nir=with_nir)

