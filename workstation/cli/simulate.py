"""`ws simulate {als,uls,mls,tls} -o OUT.laz`: simulated, fully labelled LiDAR of a synthetic scene."""

from __future__ import annotations

import click

from workstation.lidar.platforms import FlightSpec
from workstation.lidar.scanners import AIRBORNE_KINDS, ScanPattern
from workstation.lidar.simulate import ErrorModel, Sensor
from workstation.lidar.survey import KINDS as SURVEY_KINDS

from .options import RegistryChoice, bound, param_group
from .options import allow_outside_option, emit_json, float_triple, overwrite_option
from .options import FiniteFloatRange, finite_float, nonneg_float, nonneg_int, positive_float, positive_int


def _line_bias(ctx, param, value):
    """``LINE:dE,dN,dU`` (repeatable) -> ((line, dE, dN, dU), ...) in metres."""
    import math

    out = []
    for v in value or ():
        try:
            line, rest = v.split(":")
            sid = int(line)
            d = tuple(float(a) for a in rest.split(","))
        except ValueError:
            raise click.BadParameter(f"'{v}' is not LINE:dE,dN,dU (e.g. 2:0,0,0.1)") from None
        if len(d) != 3 or not all(math.isfinite(a) for a in d) or not 1 <= sid <= 65535:
            raise click.BadParameter(f"'{v}': give a line id 1-65535 and three finite offsets in metres")
        if sid in {o[0] for o in out}:
            raise click.BadParameter(f"line {sid} is given twice")
        out.append((sid, *d))
    return tuple(out)


def _xy(ctx, param, value):
    out = []
    for v in value or ():
        try:
            x, y = (float(a) for a in v.split(","))
        except ValueError:
            raise click.BadParameter(f"'{v}' is not X,Y in metres") from None
        out.append((x, y))
    return tuple(out)


def _given(cls, field: str, *decls, **attrs) -> dict:
    """An option over ``field`` of ``cls``: left to the survey config (or its defaults) unless given."""
    return bound(cls, field, *decls, default=None, **attrs)


@click.command()
@click.argument("kind", type=RegistryChoice(SURVEY_KINDS))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False), help="Output cloud (.laz, .las, ...).")
@click.option("--scene", "scene_path", default=None,
              help="Scene recipe TOML or the name of a shipped one (mixed, urban, rural, forest, mountain, demo_small). Default: mixed.")
@click.option("--seed", type=nonneg_int, default=None, help="Seed of the scene and of every random error (default 0).")
@click.option("--config", "config_path", type=click.Path(exists=True, dir_okay=False), default=None,
              help="Survey TOML: [survey] scene/seed/area/lever_arm..., [flight], [vehicle], [scanner], [sensor], [errors], [[stations]].")
@param_group(
    "flight",
    _given(FlightSpec, "altitude", "--altitude", type=positive_float, help="Flying height above ground in metres (ALS/ULS)."),
    _given(FlightSpec, "speed", "--speed", type=positive_float, help="Platform ground speed in m/s (ALS/ULS/MLS)."),
    _given(FlightSpec, "overlap", "--overlap", type=FiniteFloatRange(0.0, 1.0, max_open=True),
           help="Lateral strip overlap as a fraction 0-1 (ALS/ULS)."),
    _given(FlightSpec, "n_lines", "--lines", type=positive_int,
           help="Number of flight lines to fly (default: cover the scene, at least 2)."),
    _given(FlightSpec, "heading_deg", "--heading", type=FiniteFloatRange(-360.0, 360.0),
           help="Flight line direction in degrees clockwise from north."),
)
@param_group(
    "scanner",
    _given(ScanPattern, "kind", "--pattern", type=RegistryChoice(AIRBORNE_KINDS), help="Airborne scan mechanism."),
    _given(ScanPattern, "prf", "--prf", type=positive_float, help="Pulse repetition frequency in Hz."),
    _given(ScanPattern, "scan_frequency", "--scan-frequency", type=positive_float,
           help="Scan frequency in Hz (mirror cycles, lines or revolutions)."),
    _given(ScanPattern, "fov_deg", "--fov", type=FiniteFloatRange(0.0, 360.0, min_open=True),
           help="Full field of view in degrees."),
    _given(ScanPattern, "h_step_deg", "--h-step", type=FiniteFloatRange(0.0, 360.0, min_open=True),
           help="TLS horizontal angular step in degrees."),
    _given(ScanPattern, "v_step_deg", "--v-step", type=FiniteFloatRange(0.0, 180.0, min_open=True),
           help="TLS vertical angular step in degrees."),
)
@click.option("--station", "stations", multiple=True, callback=_xy, help="TLS station X,Y in local scene metres (repeatable).")
@param_group(
    "sensor",
    _given(Sensor, "subrays", "--subrays", type=positive_int,
           help="Rays per pulse sampling the beam footprint (1 = first return only)."),
    _given(Sensor, "divergence_mrad", "--divergence", type=nonneg_float, help="Full beam divergence in mrad."),
    _given(Sensor, "wavelength_nm", "--wavelength", type=positive_float,
           help="Laser wavelength in nm (reflectances are given at 1064 and 1550)."),
    _given(Sensor, "max_returns", "--max-returns", type=click.IntRange(1, 15), help="Returns recorded per pulse (1-15)."),
)
@click.option("--no-errors", is_flag=True, help="Perfect measurements: switch every error off (then apply the error options).")
@param_group(
    "errors",
    _given(ErrorModel, "range_noise_m", "--range-noise", type=nonneg_float, help="1-sigma range noise in metres."),
    _given(ErrorModel, "gnss_noise_m", "--gnss-noise", callback=float_triple, help="1-sigma GNSS noise E,N,U in metres."),
    _given(ErrorModel, "gnss_bias_m", "--gnss-bias", callback=float_triple, help="GNSS bias E,N,U in metres."),
    _given(ErrorModel, "imu_noise_deg", "--imu-noise", callback=float_triple,
           help="1-sigma attitude noise roll,pitch,yaw in degrees."),
    _given(ErrorModel, "lever_arm_error_m", "--lever-arm-error", callback=float_triple,
           help="Lever-arm error x,y,z (body frame) in metres."),
    _given(ErrorModel, "boresight_error_deg", "--boresight-error", callback=float_triple,
           help="Boresight error roll,pitch,yaw in degrees."),
    _given(ErrorModel, "scan_angle_scale", "--scan-angle-scale",
           type=FiniteFloatRange(-1.0, 1.0, min_open=True, max_open=True),
           help="Relative mirror-angle scale error (negative: smile)."),
    _given(ErrorModel, "scan_angle_offset_deg", "--scan-angle-offset",
           type=FiniteFloatRange(-90.0, 90.0, min_open=True, max_open=True), help="Mirror angle offset in degrees."),
    _given(ErrorModel, "time_bias_s", "--time-bias", type=finite_float,
           help="Scanner-to-navigation clock offset in seconds."),
    _given(ErrorModel, "line_bias_m", "--line-bias", "line_bias", multiple=True, callback=_line_bias,
           metavar="LINE:dE,dN,dU",
           help="Navigation bias of one flight line (its point source id) east,north,up in metres, "
                "e.g. 2:0,0,0.1 raises line 2 by 10 cm (repeatable)."),
    _given(ErrorModel, "range_offset_m", "--range-offset", type=finite_float,
           help="Constant ranging bias in metres: every recorded range is this much too long (0 = off)."),
    _given(ErrorModel, "range_walk_m", "--range-walk", type=nonneg_float,
           help="Range walk of the weakest returns in metres (0 = off)."),
)
@click.option("--point-format", type=click.Choice(["6", "7", "8"]), default="7", show_default=True,
              help="LAS 1.4 point format: 6 (no colour), 7 (RGB), 8 (RGB + NIR).")
@click.option("--trajectory", "trajectory_path", type=click.Path(dir_okay=False), default=None,
              help="Trajectory CSV to write (default: OUT with suffix .trajectory.csv).")
@click.option("--save-scene", "scene_out", type=click.Path(dir_okay=False), default=None,
              help="Also write the labelled scene mesh (.npz: triangles, class, material, object id, colour).")
@allow_outside_option
@overwrite_option
@click.option("--json", "as_json", is_flag=True, help="Print a summary as JSON on stdout.")
def simulate(kind, output, scene_path, seed, config_path, flight, scanner, stations, sensor, no_errors, errors,
             point_format, trajectory_path, scene_out, overwrite, as_json):
    """Simulate an ALS, ULS, MLS or TLS survey of a synthetic scene.

    Without --scene the default mixed scene (~300 m x 300 m: terrain features, houses, the
    heritage church, trees, a road with cars, a stream with a bridge, a pond, a power line) is
    flown with two overlapping ALS lines, or scanned from three TLS stations. The cloud carries
    the scene's class, object id (user_data and extra dimension object_id), part (roof, wall,
    trunk, crown, vehicle, ...), return numbers, intensity from the laser range equation, GPS time, scan angle and flags; the trajectory is
    written beside it as CSV.
    """
    import time
    from pathlib import Path

    from workstation.core.log import get_logger
    from workstation.core.progress import progress_bar
    from workstation.io import check_outputs, format_of
    from workstation.lidar.scene import build_scene, scene_summary
    from workstation.lidar.survey import count_pulses, run_survey, survey_trajectory

    log = get_logger(__name__)
    t0 = time.perf_counter()
    format_of(output)
    traj_out = Path(trajectory_path) if trajectory_path else Path(output).with_suffix(".trajectory.csv")
    outputs = [output, traj_out, *([scene_out] if scene_out else [])]
    inputs = [p for p in (config_path, scene_path) if p and Path(p).is_file()]
    check_outputs(outputs, overwrite, inputs=inputs)
    cfg, scene_arg, seed = _survey_config(kind, config_path, scene_path, seed)
    cfg = _with_options(cfg, kind, no_errors, stations, flight=flight, scanner=scanner, sensor=sensor, errors=errors)

    scene = build_scene(scene_arg, seed)
    log.info("scene: %s", scene_summary(scene))
    traj = survey_trajectory(scene, cfg, seed)
    total = count_pulses(traj, cfg.scanner)
    with progress_bar(f"simulate {kind}", total, unit="pulses") as advance:
        result = run_survey(scene, cfg, seed, progress=advance, with_nir=point_format == "8", trajectory=traj)
    cloud = _write_outputs(result, scene, outputs, overwrite, inputs, point_format)
    dt = time.perf_counter() - t0
    log.info("wrote %s (%d points) and %s in %.1f s", output, cloud.n, traj_out, dt)
    from workstation.cli.summary import count, emit_summary

    emit_summary("simulate", f"{kind} {count(cloud.n, 'points')}", [output, traj_out, scene_out], dt,
                 details=[count(result.stats["pulses"], "pulses"), count(len(traj.segments), "lines or stations")])
    if as_json:
        emit_json(_json_summary(cloud, result, scene, traj, kind, seed, output, traj_out, scene_out, dt))


def _survey_config(kind: str, config_path, scene_path, seed):
    """The survey of ``kind`` from the --config TOML or the defaults, the scene to build (the
    --scene option, else the config's, a TOML path there resolved beside the config, else
    "mixed") and the seed (--seed, else the config's, else 0)."""
    from pathlib import Path

    from workstation.core.errors import InvalidInputError
    from workstation.lidar.survey import default_survey, survey_from_toml

    top: dict = {}
    if config_path:
        cfg, top = survey_from_toml(config_path, kind)
        if top.get("kind", kind) != kind:
            raise InvalidInputError(f"config is for '{top['kind']}' but '{kind}' was asked", path=config_path)
    else:
        cfg = default_survey(kind)
    scene_arg = scene_path or top.get("scene", "mixed")
    if not scene_path and "scene" in top and str(scene_arg).endswith(".toml"):  # a path written in the config
        from workstation.io.paths import resolve_inside

        scene_arg = str(resolve_inside(scene_arg, Path(config_path).parent, source=config_path, field="survey.scene"))
    seed = seed if seed is not None else int(top.get("seed", 0))
    return cfg, scene_arg, seed


def _replace_given(obj, values: dict):
    """``obj`` with each field of ``values`` that was given (not None) replaced, one field at a
    time (each step is validated by the dataclass)."""
    from dataclasses import replace

    for name, val in values.items():
        if val is not None:
            obj = replace(obj, **{name: val})
    return obj


def _with_options(cfg, kind: str, no_errors: bool, stations, *, flight: dict, scanner: dict, sensor: dict,
                  errors: dict):
    """The survey ``cfg`` with the command-line options applied over the config: flight,
    scanner, sensor and error fields (dicts keyed by field name); --no-errors first switches
    every error off; --speed is also the MLS vehicle's speed; --station replaces the TLS
    stations."""
    from dataclasses import replace

    from workstation.lidar.platforms import Station

    speed = flight["speed"]
    errors = {**errors, "line_bias_m": errors["line_bias_m"] or None}  # no --line-bias: the config's
    vehicle = replace(cfg.vehicle, speed=speed) if (speed is not None and kind == "mls") else cfg.vehicle
    st = tuple(Station(x, y) for x, y in stations) if stations else cfg.stations
    return replace(cfg, flight=_replace_given(cfg.flight, flight), scanner=_replace_given(cfg.scanner, scanner),
                   sensor=_replace_given(cfg.sensor, sensor),
                   errors=_replace_given(ErrorModel.none() if no_errors else cfg.errors, errors),
                   vehicle=vehicle, stations=st)


def _write_outputs(result, scene, outputs: list, overwrite: bool, inputs: list, point_format: str):
    """Write the cloud (without colour for point format 6), the trajectory CSV and optionally
    the scene mesh: all files or none. Returns the cloud as written."""
    from workstation.io import atomic_paths, format_of, write_cloud
    from workstation.lidar.scene import save_scene
    from workstation.lidar.simulate import write_trajectory_csv

    cloud = result.cloud
    if point_format == "6":
        cloud = cloud.without_attrs("rgb")
    opts = {"point_format": int(point_format)} if format_of(outputs[0])[0] in ("las", "laz") else {}
    with atomic_paths(outputs, overwrite, inputs=inputs) as tmps:  # all files or none
        write_cloud(cloud, tmps[0], overwrite=True, **opts)
        write_trajectory_csv(result, tmps[1], overwrite=True)
        if len(outputs) > 2:
            save_scene(scene, tmps[2], overwrite=True)
    return cloud


def _json_summary(cloud, result, scene, traj, kind: str, seed: int, output, traj_out, scene_out, dt: float) -> dict:
    """The --json document: outputs, survey, counts, classes (code: points), CRS, seconds."""
    import numpy as np

    cls, cnt = np.unique(cloud.attrs["classification"], return_counts=True)
    return {
        "output": output, "trajectory": str(traj_out), "scene_mesh": scene_out, "kind": kind, "scene": scene.meta.get("recipe"), "seed": seed,
        "pulses": result.stats["pulses"], "point_count": cloud.n,
        "multiple_return_share": result.stats["multiple_return_share"],
        "flight_lines_or_stations": len(traj.segments),
        "classes": {int(c): int(n) for c, n in zip(cls, cnt)}, "crs": cloud.crs, "seconds": dt,
    }
