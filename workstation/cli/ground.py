"""`ws ground IN -o OUT --method ...`: classify ground (class 2) and the rest (class 1)."""

from __future__ import annotations

import click

from workstation.ground.methods import METHOD_NAMES, PRESET_NAMES, ground_filter, methods
from workstation.ground.tiles import TileParams

from .options import RegistryChoice, bound, field_option, param_group
from .options import emit_json, json_option, output_option, overwrite_option, read_options
from .options import FiniteFloatRange, nonneg_float, positive_int
from .options import nonneg_length, positive_length
from .pipeline_out import pipeline_out_option


def _for(field: str) -> str:
    """The help tag of a filter parameter: the methods whose parameter dataclass has ``field``
    (``ml`` is the point classifier's :class:`~workstation.ml.ground.MLGroundParams`)."""
    import dataclasses

    from workstation.ml.ground import MLGroundParams

    names = [n for n, m in methods().items() if field in {f.name for f in dataclasses.fields(m.params)}]
    if field in {f.name for f in dataclasses.fields(MLGroundParams)}:
        names.append("ml")
    return "[all but ml]" if names == list(METHOD_NAMES) else f"[{', '.join(names)}]"


def _filter_option(field: str, *decls, **attrs) -> dict:
    """A filter parameter left to the method's preset unless given (its class is --method's)."""
    return bound(None, field, *decls, default=None, **attrs)


@click.command()
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@output_option
@field_option(ground_filter, "method", "--method", type=RegistryChoice(METHOD_NAMES, extra=["ml"]),
              show_default=True, help="Ground filter.")
@field_option(ground_filter, "preset", "--preset", type=RegistryChoice(PRESET_NAMES),
              show_default=True, help="Parameter set for a kind of terrain.")
@click.option("--reclassify", is_flag=True, help="Overwrite every class (also noise and classes other than 0/1/2).")
@click.option("--all-returns", is_flag=True, help="Let first/intermediate returns be ground too (default: last and only).")
@click.option("--noise/--no-noise", default=False, show_default=True,
              help="Classify noise first (isolated low points -> 7, outliers -> 7/18).")
@click.option("--noise-step/--no-noise-step", default=None,
              help=f"{_for('noise')} the low-noise step before the filter: points over 1 m under the lowest points "
                   "around them -> class 7, never ground (default on; as PDAL's filters.elm before filters.smrf).")
@click.option("--bridges/--no-bridges", default=None,
              help=f"{_for('bridges')} take bridge decks out of the ground as class 17 (surfaces spanning a gap at least "
                   "2 m below them, the road continuing beyond both ends); default on.")
@click.option("--water", is_flag=True,
              help="Then make the ground on still water class 9 (level single-echo surfaces of 150 m2 or more "
                   "whose banks rise from them), as ws classify does.")
@click.option("--hag", is_flag=True, help="Add the height above ground (hag, CRS vertical unit) from a ground TIN.")
@param_group(
    "given",
    _filter_option("cell", "--cell", type=positive_length, help=f"{_for('cell')} grid cell, metres."),
    _filter_option("slope", "--slope", type=nonneg_float, help=f"{_for('slope')} terrain slope, rise over run."),
    _filter_option("window", "--window", type=positive_length, help=f"{_for('window')} largest window radius, metres."),
    _filter_option("threshold", "--threshold", type=nonneg_length,
                   help=f"{_for('threshold')} elevation threshold, metres."),
    _filter_option("scalar", "--scalar", type=nonneg_float,
                   help=f"{_for('scalar')} elevation scaling factor (metres per unit slope)."),
    _filter_option("trend_slope", "--trend-slope", type=nonneg_float,
                   help=f"{_for('trend_slope')} slope-adaptive object test: per-cell slope max(--slope, factor x "
                        "mean terrain slope); 0 = off (PDAL)."),
    _filter_option("understorey", "--understorey/--no-understorey",
                   help=f"{_for('understorey')} under canopy (multi-echo pulses), keep only the ground's lower "
                        "envelope (default on)."),
    _filter_option("raised_patches", "--raised-patches/--no-raised-patches",
                   help=f"{_for('raised_patches')} take out patches of ground that drop by 1 m or more on all sides "
                        "(roofs, decks; default on)."),
    _filter_option("member_vote", "--member-vote/--no-member-vote",
                   help=f"{_for('member_vote')} the classifier's ground gate votes with auto's five members (ground "
                        "where 4 of the 6 accept a point), then auto's refine chain; costs the members' run time "
                        "and, untiled, refuses clouds of more than --tile-points points (default off)."),
    _filter_option("risers", "--risers/--no-risers",
                   help=f"{_for('risers')} put back rejected points on terrain steps the ground TIN spans (default on)."),
    _filter_option("max_window", "--max-window", type=positive_length, help=f"{_for('max_window')} largest window size, metres."),
    _filter_option("cloth_resolution", "--cloth-resolution", type=positive_length,
                   help=f"{_for('cloth_resolution')} particle spacing, metres."),
    _filter_option("rigidness", "--rigidness", type=click.IntRange(1, 3), help=f"{_for('rigidness')} 1 steep, 2 mixed, 3 flat."),
    _filter_option("class_threshold", "--class-threshold", type=positive_length,
                   help=f"{_for('class_threshold')} largest distance to the cloth, metres."),
    _filter_option("iterations", "--iterations", type=positive_int, help=f"{_for('iterations')} largest number of time steps."),
    _filter_option("slope_smooth", "--slope-smooth/--no-slope-smooth", help=f"{_for('slope_smooth')} slope post-processing."),
    _filter_option("max_angle", "--max-angle", type=FiniteFloatRange(0.0, 90.0, min_open=True),
                   help=f"{_for('max_angle')} iteration angle, degrees."),
    _filter_option("max_distance", "--max-distance", type=positive_length,
                   help=f"{_for('max_distance')} pmf: largest elevation threshold; ptd: iteration distance; metres."),
    _filter_option("seed_cell", "--seed-cell", type=positive_length, help=f"{_for('seed_cell')} seed cell, metres."),
    given_only=True,
)
@param_group(
    "tiles",
    bound(TileParams, "tile_points", "--tile-points", type=click.IntRange(min=0), show_default=True,
          help="Filter a larger cloud tile by tile, about this many points a tile (bounded memory); 0 = never."),
    bound(TileParams, "buffer", "--tile-buffer", type=nonneg_float, show_default=True,
          help="Metres of neighbouring points filtered with each tile."),
    bound(TileParams, "workers", "--tile-workers", type=click.IntRange(min=1), show_default=True,
          help="Tiles filtered at once, one process each (memory grows with it)."),
)
@click.option("--columns", default=None, help="Column spec of a text input, e.g. x,y,z,label.")
@pipeline_out_option
@overwrite_option
@read_options
@json_option
def ground(src, output, method, preset, reclassify, all_returns, noise, noise_step, bridges, water, hag, given, tiles,
           columns, pipeline_out, overwrite, read_opts, as_json):
    """Classify the ground of IN with one of the filters; write OUT (any cloud format).

    Lengths are in metres whatever the CRS unit (a feet CRS is converted). Points already in
    classes other than 0, 1 and 2 keep them unless --reclassify. A cloud of more than
    --tile-points points is filtered tile by tile, each tile with --tile-buffer metres of its
    neighbours; the point classifier (--method ml) tiles on its own, but with --member-vote it
    refuses a cloud of more than --tile-points points.
    """
    import time

    from workstation.io import check_output, format_of, read_cloud, write_cloud

    t0 = time.perf_counter()
    format_of(src)
    format_of(output)
    check_output(output, overwrite, inputs=[src])
    if pipeline_out:
        _check_pipeline_out(method, output, pipeline_out, overwrite, src)
    given = _given_params(given, reclassify, all_returns, noise_step, bridges)
    params = _method_params(method, preset, given, reclassify)
    cloud = read_cloud(src, **read_opts, **({"columns": columns} if columns else {}))
    out, params = _filter(cloud, method, params, given, noise, tiles)
    n_tiles = int(out.history[-1].params.get("tiles", 1)) if out.history else 1
    out, n_water = _after_filter(out, water, hag)
    write_cloud(out, output, overwrite=overwrite, inputs=[src])
    if pipeline_out:
        _save_ground_pipeline(pipeline_out, src, output, method, params, out.crs, overwrite)
    _report(src, output, method, preset, params, out, time.perf_counter() - t0, n_tiles, n_water, water, as_json)


def _given_params(given: dict, reclassify: bool, all_returns: bool, noise_step, bridges) -> dict:
    """The filter parameters the user gave (the options left at None are the method's or
    preset's to decide), with the flags translated to parameter names."""
    given = dict(given)
    if reclassify:
        given["reclassify"] = True
    if all_returns:
        given["last_returns_only"] = False
    if noise_step is not None:
        given["noise"] = noise_step
    if bridges is not None:
        given["bridges"] = bridges
    return given


def _method_params(method: str, preset: str, given: dict, reclassify: bool):
    """The parameter dataclass of the method: the point classifier's for ``ml`` (its
    ``raised_patches`` and ``member_vote`` when given; the other filter options are not its),
    else the preset's with the given options applied (an invalid combination is a usage error)."""
    from workstation.core.errors import InvalidInputError
    from workstation.ground.methods import make_params

    if method == "ml":  # the shipped point classifier (workstation.ml.ground)
        from workstation.ml.ground import MLGroundParams

        ml = {k: given[k] for k in ("raised_patches", "member_vote") if given.get(k) is not None}
        return MLGroundParams(reclassify=reclassify, **ml)
    try:
        return make_params(method, preset, **given)
    except InvalidInputError as e:
        raise click.UsageError(e.message) from None


def _filter(cloud, method: str, params, given: dict, noise: bool, tiles: dict):
    """Classify noise first if asked, size the default cells by the points, then run the filter:
    the point classifier (its member vote refused above ``tiles["tile_points"]`` points), or
    another filter tile by tile above ``tiles["tile_points"]`` points (``tiles``: the fields of
    :class:`~workstation.ground.tiles.TileParams`) or on the whole cloud.
    Returns ``(classified cloud, the parameters used)``."""
    from workstation.ground.methods import methods

    if noise:
        from workstation.ground.noise import classify_noise

        cloud = classify_noise(cloud)
    if method != "ml":
        from workstation.ground.methods import fit_to_points

        params = fit_to_points(params, cloud, set(given))  # default cells sized by the points
    if method == "ml":
        from workstation.ml.ground import ml_ground

        _check_member_vote_size(cloud.n, params, tiles["tile_points"])
        return ml_ground(cloud, params), params
    if tiles["tile_points"] and cloud.n > tiles["tile_points"]:
        from workstation.ground.tiles import ground_tiled

        return ground_tiled(cloud, method, params, TileParams(**tiles)), params
    return methods()[method].func(cloud, params), params


def _check_member_vote_size(n: int, params, tile_points: int) -> None:
    """Refuse ``--member-vote`` on a cloud of more than ``tile_points`` points (0: no limit):
    auto's members then run on the whole cloud at once, not tile by tile."""
    if params.member_vote and tile_points and n > tile_points:
        raise click.UsageError(
            f"--member-vote runs auto's five members on the whole cloud, not tile by tile, and the cloud has {n} "
            f"points (over --tile-points {tile_points}); cut it first (ws tile), drop --member-vote, or raise "
            "--tile-points if the memory allows (0 = no limit)")


def _after_filter(out, water: bool, hag: bool):
    """The optional steps after the filter: still water on the ground (class 9) and the height
    above ground. Returns ``(cloud, water point count)``."""
    n_water = 0
    if water:
        from workstation.ground.water import classify_water

        out = classify_water(out)
        n_water = int(out.history[-1].params["water_points"])
    if hag:
        from workstation.ground.hag import height_above_ground

        out = height_above_ground(out)
    return out, n_water


def _report(src, output, method, preset, params, out, dt: float, n_tiles: int, n_water: int, water: bool,
            as_json: bool) -> None:
    """Log the ground share, print the one-line summary and, with ``--json``, the run record
    (counts, fractions, seconds)."""
    import numpy as np

    from workstation.cli.summary import count, emit_summary, percent
    from workstation.core.classes import ASPRSClass
    from workstation.core.log import get_logger

    cls = np.asarray(out.attrs["classification"])
    n_ground = int(np.count_nonzero(cls == ASPRSClass.GROUND))
    get_logger(__name__).info("%s: %d of %d points ground (%.1f %%) in %.2f s", method, n_ground, out.n,
                              100.0 * n_ground / out.n, dt)
    emit_summary("ground", count(out.n, "points"), output, dt,
                 [f"ground {percent(n_ground, out.n)}", method, f"{n_tiles} tiles" if n_tiles > 1 else "",
                  f"water {count(n_water, 'points')}" if water else ""])
    if as_json:
        import dataclasses

        emit_json({"input": src, "output": output, "method": method, "preset": preset,
                   "params": dataclasses.asdict(params), "point_count": out.n, "ground_count": n_ground,
                   "ground_fraction": n_ground / out.n, "seconds": dt, "tiles": n_tiles,
                   "water_count": n_water, "low_noise_count": int(np.count_nonzero(cls == ASPRSClass.LOW_POINT))})


def _check_pipeline_out(method, output, pipeline_out, overwrite, src) -> None:
    """Refuse ``--pipeline-out`` for a method PDAL has no filter for, before any work."""
    from workstation.io import check_outputs
    from workstation.ops.pdal import ground_equivalent

    why = ground_equivalent(method)
    if why:
        raise click.UsageError(f"--pipeline-out: {why}")
    check_outputs([output, pipeline_out], overwrite, inputs=[src])


def _save_ground_pipeline(path, src, output, method, params, crs, overwrite) -> None:
    """The PDAL pipeline of this run (the filter's parameters in the CRS's units)."""
    from workstation.io import format_of
    from workstation.io.crs import crs_units
    from workstation.ops import pdal

    from .pipeline_out import save_pipeline

    layout = pdal.las_layout(output) if format_of(output)[0] in ("las", "laz") else None
    save_pipeline(path, pdal.ground_stages(src, output, method, params, crs_units(crs), layout), overwrite, [src])
