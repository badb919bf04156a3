"""`ws strip-adjust IN... -o OUT_DIR`: boresight calibration and strip adjustment of ALS flight lines."""

from __future__ import annotations

import click

from workstation.adjust import AdjustParams, PatchParams

from .options import emit_json, float_triple, json_option, overwrite_option, positive_float
from .options import bound, field_default, param_group, read_options


def _triple(cls, field: str) -> str:
    """The default triple of ``field`` of ``cls`` as the text --help shows (``0,0,0``)."""
    return ",".join(f"{v:g}" for v in field_default(cls, field))


def _estimate(ctx, param, value):
    from workstation.adjust.models import ESTIMABLE

    if value is None:
        return None
    names = tuple(v.strip() for v in value.split(",") if v.strip())
    bad = [n for n in names if n not in ESTIMABLE]
    if bad or not names:
        raise click.BadParameter(f"{', '.join(bad) or 'nothing'}: choose from {', '.join(ESTIMABLE)}")
    return names


@click.command("strip-adjust")
@click.argument("inputs", nargs=-1, required=True, type=click.Path(exists=True, dir_okay=False))
@click.option("-o", "--output", "out_dir", required=True, type=click.Path(file_okay=False),
              help="Output folder: the adjusted clouds (input names, .laz for a .copc.laz), strip_adjust.json, "
                   "DZ images before/after.")
@click.option("--trajectory", "trajectory_path", type=click.Path(exists=True, dir_okay=False), default=None,
              help="Trajectory CSV (gps_time, easting, northing, height, roll_deg, pitch_deg, heading_deg), "
                   "as ws simulate writes: enables the rigorous model.")
@click.option("--estimate", callback=_estimate, default=None,
              help="Unknowns, comma-separated: boresight, leverarm, range, scan-angle (need --trajectory), strip-shift. "
                   "Default: boresight,range with --trajectory, else strip-shift.")
@param_group(
    "given",
    bound(AdjustParams, "fixed_strip", "--fixed-strip", type=click.IntRange(0, 65535),
          help="Point source id of the datum strip (default: the one in the most overlaps)."),
    bound(AdjustParams, "lever_arm", "--lever-arm", callback=float_triple, default=_triple(AdjustParams, "lever_arm"),
          show_default=True,
          help="Nominal lever arm the points were georeferenced with: x,y,z body frame (fwd, right, down) in metres."),
    bound(AdjustParams, "boresight_deg", "--boresight", callback=float_triple,
          default=_triple(AdjustParams, "boresight_deg"), show_default=True,
          help="Nominal boresight roll,pitch,yaw the points were georeferenced with, in degrees."),
)
@param_group(
    "patches",
    bound(PatchParams, "cell_m", "--cell", type=positive_float,
          help="Patch cell side in metres (default: ~40 single returns of one strip per cell)."),
    bound(PatchParams, "noise_m", "--noise", type=positive_float,
          help="1-sigma point noise along the surface normal in metres (default: estimated from the data)."),
)
@read_options
@overwrite_option
@json_option
def strip_adjust(inputs, out_dir, trajectory_path, estimate, given, patches, read_opts, overwrite, as_json):
    """Estimate and remove the systematic misalignment between overlapping flight lines.

    Planar patches seen by two strips (point_source_id) give plane-to-plane distances; without a
    trajectory each strip gets a shift (one strip is the datum), with --trajectory every point is
    re-georeferenced and the boresight angles and range offset are estimated by Gauss-Newton,
    with standard deviations and correlations. Combinations the overlaps cannot determine (the
    heading from flat ground only) are reported, not estimated. The adjusted clouds keep every
    attribute; the swath separation RMSDz of `ws qc` is reported before and after.
    """
    import time
    from pathlib import Path

    from workstation.adjust import apply_corrections, estimate_corrections, read_trajectory_csv
    from workstation.adjust.report import pair_table, result_dict, swath_pass
    from workstation.core.errors import InvalidInputError
    from workstation.core.progress import progress_bar
    from workstation.io import read_cloud

    t0 = time.perf_counter()
    out = Path(out_dir)
    _check_output(out, inputs, overwrite)
    estimate = estimate or (("boresight", "range") if trajectory_path else ("strip-shift",))
    if not trajectory_path and set(estimate) - {"strip-shift"}:
        raise InvalidInputError(f"estimating {', '.join(sorted(set(estimate) - {'strip-shift'}))} needs the trajectory",
                                "give --trajectory CSV, or --estimate strip-shift")
    params = AdjustParams(estimate, **given, patches=PatchParams(**patches))
    nav = read_trajectory_csv(trajectory_path) if trajectory_path else None
    with progress_bar("strip-adjust", 2 * len(inputs) + 3, unit="steps") as advance:
        clouds = []
        for p in inputs:
            clouds.append(read_cloud(p, **read_opts))
            advance(1)
        xyz, attrs = _joined(clouds, inputs)
        res = estimate_corrections(xyz, attrs, params, nav)
        advance(1)
        new_xyz = apply_corrections(xyz, attrs, res, params, nav)
        advance(1)
        before = swath_pass(xyz, attrs)
        after = swath_pass(new_xyz, attrs, before.grid.cell)
        advance(1)
        report = {**result_dict(res), "rmsdz_before_m": before.result()["rmsdz_all"],
                  "rmsdz_after_m": after.result()["rmsdz_all"], "pairs": pair_table(before.result(), after.result())}
        _write(out, inputs, clouds, new_xyz, (before, after), report, res.model, overwrite, t0, advance)
    from workstation.cli.summary import emit_summary

    rb, ra = report["rmsdz_before_m"], report["rmsdz_after_m"]
    emit_summary("strip-adjust", f"{res.model} model, {len(res.strips)} strips", [out], report["seconds"],
                 details=[f"RMSDz {rb:.3f} -> {ra:.3f} m" if rb is not None and ra is not None else "no swath DZ"])
    if as_json:
        emit_json(report)


def _check_output(out, inputs, overwrite) -> None:
    """Refuse an existing folder without --overwrite, a folder holding an input, clashing names."""
    from pathlib import Path

    from workstation.core.errors import InvalidInputError, OutputExistsError

    names = [_out_name(p) for p in inputs]
    if len(set(names)) != len(names):
        raise InvalidInputError("two inputs have the same file name", "the outputs are named after the inputs")
    if out.exists() and not overwrite:
        raise OutputExistsError(out)
    if any(out.resolve() == Path(p).resolve().parent for p in inputs):
        raise InvalidInputError("the output folder holds an input", "write the adjusted clouds elsewhere", path=out)


def _out_name(path) -> str:
    """The name of an adjusted cloud: the input's, but ``.laz`` for a ``.copc.laz`` input (the
    adjusted points are written as plain LAZ, which a COPC name would misrepresent)."""
    from pathlib import Path

    name = Path(path).name
    return name[: -len(".copc.laz")] + ".laz" if name.lower().endswith(".copc.laz") else name


def _write(out, inputs, clouds, new_xyz, passes, report, model, overwrite, t0, advance) -> None:
    """The adjusted clouds (input names, every attribute), the DZ images and strip_adjust.json,
    all in a folder built beside ``out`` and swapped in (all or nothing)."""
    import json
    import time

    from workstation.io import atomic_dir, write_cloud

    names = [_out_name(p) for p in inputs]
    with atomic_dir(out, overwrite=overwrite) as tmp:
        start = 0
        for name, c in zip(names, clouds):
            write_cloud(c.with_xyz(new_xyz[start:start + c.n]).with_history("strip-adjust", {"model": model}),
                        tmp / name, overwrite=True)
            start += c.n
            advance(1)
        passes[0].write(tmp / "dz_before", clouds[0].crs)
        passes[1].write(tmp / "dz_after", clouds[0].crs)
        report.update(outputs=[str(out / n) for n in names], seconds=time.perf_counter() - t0)
        (tmp / "strip_adjust.json").write_text(json.dumps(report, indent=2))


def _joined(clouds, inputs):
    """Coordinates and the attributes the adjustment reads, of every input in order (metres,
    one CRS, flight line ids required)."""
    import numpy as np

    from workstation.core.errors import InvalidInputError
    from workstation.io.crs import crs_units

    for p, c in zip(inputs, clouds):
        u = crs_units(c.crs)
        if u.known and not u.is_metric:
            raise InvalidInputError("strip-adjust works in metres", "reproject with ws convert --crs", path=p)
        if "point_source_id" not in c.attrs:
            raise InvalidInputError("no point_source_id", "strips are told apart by their flight line id", path=p)
    if len({c.crs for c in clouds}) > 1:
        raise InvalidInputError("the inputs have different CRSs", "reproject them to one CRS with ws convert --crs")
    xyz = np.concatenate([c.xyz for c in clouds])
    keys = [k for k in ("point_source_id", "gps_time", "number_of_returns", "classification", "withheld")
            if all(k in c.attrs for c in clouds)]
    return xyz, {k: np.concatenate([c.attrs[k] for c in clouds]) for k in keys}
