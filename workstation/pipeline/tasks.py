"""The work of one task: index a file, process a chunk's points, grid a chunk, join tiles.

These functions run on Dask workers: module level, plain arguments, and each writes its
outputs atomically (a temporary file renamed into place), so a task killed half-way leaves
nothing and simply runs again. They return small dicts (counts, seconds, output paths) that
the runner records in ``run.json``.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import StageError
from workstation.core.log import get_logger

from . import chunkio
from .chunks import Chunk

log = get_logger(__name__)

# the fields of a chunk's points the raster stages need, kept uncompressed beside the LAZ
RASTER_FIELDS = np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("classification", "u1"), ("return_number", "u1")])


@dataclass(frozen=True)
class RunContext:
    """What every task needs to find its inputs and place its outputs.

    Attributes
    ----------
    out : Path
        The output folder (``ground/``, ``dem/``, ``run.json`` ...).
    cache : Path
        Work files: ``index/<file>/`` bins of plain LAS/LAZ inputs, ``points/`` the raster
        fields of processed chunks.
    crs : str or None
    tiles : tuple of TileInfo
    index_dirs : dict
        Input path (str) -> its bins folder (plain LAS/LAZ files only).
    index_parts : dict
        Input path (str) -> how many index tasks share the file (a part per
        :data:`INDEX_PART_POINTS` points, each in ``<bins folder>/p<k>``).
    dem_grid : GridSpec or None
        The one grid of every DEM tile and mosaic.
    density_grid : GridSpec or None
    project_folder : Path
    photos, scans : tuple of Path
        The project's photos and scans (:mod:`.photos`, :mod:`.scans`).
    """

    out: Path
    cache: Path
    crs: str | None
    tiles: tuple
    index_dirs: dict
    index_parts: dict
    dem_grid: object = None
    density_grid: object = None
    project_folder: Path = Path(".")
    photos: tuple = ()
    scans: tuple = ()


def elapsed(t0: float) -> float:
    return round(time.perf_counter() - t0, 3)


def peak_rss_mb() -> float:
    """The peak resident memory of this worker process so far, MB (Linux ru_maxrss is in kB)."""
    import resource

    return round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, 1)


# ----------------------------------------------------------------------------- index
INDEX_PART_POINTS = 4_000_000  # a larger file is binned by several tasks at once


def index_parts(point_count: int) -> int:
    return max(1, math.ceil(point_count / INDEX_PART_POINTS))


def index_task(ctx: RunContext, tile_path: str, size: float, part: int = 0) -> dict:
    """Bin part ``part`` of one plain LAS/LAZ file into per-chunk record files (see
    :mod:`.chunkio`)."""
    t0 = time.perf_counter()
    dest = Path(ctx.index_dirs[tile_path]) / f"p{part}"
    n = next(t.point_count for t in ctx.tiles if str(t.path) == tile_path)
    step = math.ceil(n / ctx.index_parts[tile_path])
    counts = chunkio.index_file(Path(tile_path), size, dest, ctx.crs, start=part * step, stop=min(n, (part + 1) * step))
    return {"points": int(sum(counts.values())), "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": [str(dest)]}


def read_input_chunk(ctx: RunContext, chunk: Chunk):
    """The input points in ``chunk``'s buffered bounds, from every tile that reaches them."""
    box = chunk.buffered
    names = [f"{c.ix}_{c.iy}" for c in chunk.neighbours()]  # the bins of chunkio.index_file
    parts = []
    for t in ctx.tiles:
        if not t.intersects(box):
            continue
        if t.copc:
            parts.append(chunkio.read_copc(t.path, box))
        else:
            folder = Path(ctx.index_dirs[str(t.path)])
            parts += [chunkio.read_bins(folder / f"p{k}", names, box) for k in range(ctx.index_parts[str(t.path)])]
    return chunkio.join(parts, ctx.crs)


# ----------------------------------------------------------------------------- points
_MODELS: dict = {}


def _classifier(ctx: RunContext, stage):
    """The point classifier, loaded once per worker process."""
    from workstation.ml.classifier import PointClassifier

    model = None if stage.model is None else str((ctx.project_folder / stage.model).resolve())
    if model not in _MODELS:
        _MODELS[model] = PointClassifier.load(model, device="cpu")
    clf = _MODELS[model]
    clf.water, clf.roof_test, clf.raised_patches = stage.water, stage.roof_test, stage.raised_patches
    return clf


def run_point_stages(cloud, plan, ctx: RunContext, warnings: list):
    """Noise, ground, classify and height above ground (those the plan asks for) on a cloud."""
    if plan.noise is not None:
        from workstation.ground.noise import classify_noise

        cloud = classify_noise(cloud, plan.noise)
    if plan.ground is not None:
        cloud = _ground(cloud, plan.ground, warnings)
    if plan.classify is not None:
        cloud = _classifier(ctx, plan.classify).classify(cloud)
    if plan.hag is not None:
        from workstation.ground.hag import height_above_ground

        try:
            cloud = height_above_ground(cloud, plan.hag)
        except StageError as e:
            warnings.append(f"hag: {e.message}; hag left at 0")
            cloud = cloud.with_attrs(hag=np.zeros(cloud.n, np.float32))
    return cloud


def _ground(cloud, stage, warnings: list):
    """The ground filter; a chunk where it finds no ground (a lake, one roof) keeps its points
    non-ground and says so, as ``ws ground`` does tile by tile."""
    from workstation.core.classes import ASPRSClass

    try:
        if stage.method == "ml":
            from workstation.ml.ground import ml_ground

            return ml_ground(cloud, stage.params)
        from workstation.ground.methods import methods

        return methods()[stage.method].func(cloud, stage.params)
    except StageError as e:
        warnings.append(f"ground: {e.message}; points left non-ground")
        cls = np.asarray(cloud.get("classification", np.zeros(cloud.n, np.uint8))).copy()
        cls[np.isin(cls, (0, 1, 2))] = ASPRSClass.UNCLASSIFIED
        return cloud.with_attrs(classification=cls)


def points_task(ctx: RunContext, plan, chunk: Chunk, folder: str, *upstream) -> dict:
    """Run the point stages on ``chunk`` with its buffer; write its own points to
    ``OUT/<folder>/<chunk>.laz`` and their raster fields to the cache."""
    from workstation.io import write_cloud

    t0 = time.perf_counter()
    cloud = read_input_chunk(ctx, chunk)
    core = None if cloud is None else chunk.core_mask(cloud.xyz[:, :2])
    if cloud is None or not core.any():
        return {"points": 0, "buffered": 0 if cloud is None else cloud.n, "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": []}
    warnings: list[str] = []
    out = run_point_stages(cloud, plan, ctx, warnings)[core]
    laz = ctx.out / folder / f"{chunk.name}.laz"
    laz.parent.mkdir(parents=True, exist_ok=True)
    write_cloud(out, laz, overwrite=True)
    side = write_raster_fields(out, ctx.cache / "points" / f"{chunk.ix}_{chunk.iy}.bin")
    return {"points": int(out.n), "buffered": int(cloud.n), "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "warnings": warnings,
            "outputs": [str(laz), str(side)]}


def write_raster_fields(cloud, path: Path) -> Path:
    """The coordinates, class and return number of ``cloud``, as records (atomic)."""
    from workstation.io import atomic_path

    rec = np.zeros(cloud.n, RASTER_FIELDS)
    rec["x"], rec["y"], rec["z"] = cloud.xyz[:, 0], cloud.xyz[:, 1], cloud.xyz[:, 2]
    for k in ("classification", "return_number"):
        if k in cloud.attrs:
            rec[k] = cloud.attrs[k]
        elif k == "return_number":
            rec[k] = 1
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path, overwrite=True) as tmp:
        rec.tofile(tmp)
    return path


# ----------------------------------------------------------------------------- rasters
def grid_window(grid, box, pad: float = 0.0) -> tuple[int, int, int, int]:
    """Rows r0:r1 and columns c0:c1 of ``grid`` whose cell centres lie in ``box`` (xmin, ymin,
    xmax, ymax; half-open), widened by ``pad`` CRS units and clipped to the grid."""
    res = grid.res
    c0 = math.ceil((box[0] - pad - grid.x0) / res - 0.5)
    c1 = math.ceil((box[2] + pad - grid.x0) / res - 0.5)
    r0 = math.floor((grid.y1 - (box[3] + pad)) / res - 0.5) + 1
    r1 = math.floor((grid.y1 - (box[1] - pad)) / res - 0.5) + 1
    return max(r0, 0), min(r1, grid.rows), max(c0, 0), min(c1, grid.cols)


def sub_grid(grid, r0: int, r1: int, c0: int, c1: int):
    from workstation.raster.grid import GridSpec

    return GridSpec(grid.x0 + c0 * grid.res, grid.y1 - r0 * grid.res, grid.res, r1 - r0, c1 - c0)


def raster_source(ctx: RunContext, plan, chunk: Chunk):
    """The points a chunk's rasters are made of: the processed chunks' raster fields when the
    plan has point stages, else the inputs; None when there are none."""
    if not plan.point_stages:
        return read_input_chunk(ctx, chunk)
    files = [ctx.cache / "points" / f"{c.ix}_{c.iy}.bin" for c in chunk.neighbours()]
    rec = chunkio.read_records(files, RASTER_FIELDS, chunk.buffered)
    return None if rec is None else chunkio.from_records(rec, ctx.crs)


def raster_task(ctx: RunContext, plan, chunk: Chunk, *upstream) -> dict:
    """DEM tiles (each kind) and the density tile of ``chunk``: gridded on the project grid
    with the chunk's buffer, cropped to the cells whose centres lie in the chunk."""
    t0 = time.perf_counter()
    cloud = raster_source(ctx, plan, chunk)
    outputs, n = [], 0 if cloud is None else cloud.n
    if cloud is not None and plan.dem is not None:
        outputs += _dem_tiles(ctx, plan.dem, chunk, cloud)
    if cloud is not None and plan.density is not None:
        outputs += _density_tile(ctx, chunk, cloud)
    return {"points": int(n), "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": outputs}


def _dem_tiles(ctx: RunContext, stage, chunk: Chunk, cloud) -> list[str]:
    from workstation.core.products import Raster
    from workstation.io.geotiff import write_raster
    from workstation.raster.dem import build_dem

    g = ctx.dem_grid
    r0, r1, c0, c1 = grid_window(g, chunk.bounds)
    if r1 <= r0 or c1 <= c0:
        return []
    ra, rb, ca, cb = grid_window(g, chunk.bounds, pad=chunk.buffer)
    made = []
    for kind in stage.kinds:
        try:
            r = build_dem(cloud, dataclasses.replace(stage.params, kind=kind), grid=sub_grid(g, ra, rb, ca, cb),
                          tile_cells=0)
        except StageError:
            continue  # no ground / no valid cell here: the mosaic leaves it nodata
        tile = r.array[r0 - ra : r1 - ra, c0 - ca : c1 - ca]
        if not np.isfinite(tile).any():
            continue
        path = ctx.out / "dem" / "tiles" / kind / f"{chunk.name}.tif"
        path.parent.mkdir(parents=True, exist_ok=True)
        write_raster(Raster(tile, sub_grid(g, r0, r1, c0, c1).transform, ctx.crs, -9999.0, {"kind": kind}), path,
                     overwrite=True, overviews=False)
        made.append(str(path))
    return made


def _density_tile(ctx: RunContext, chunk: Chunk, cloud) -> list[str]:
    from workstation.core.classes import NOISE
    from workstation.core.products import Raster
    from workstation.io.geotiff import write_raster

    g = ctx.density_grid
    r0, r1, c0, c1 = grid_window(g, chunk.bounds)
    if r1 <= r0 or c1 <= c0:
        return []
    xy = cloud.xyz[:, :2]
    keep = chunk.core_mask(xy)
    cls = cloud.get("classification")
    if cls is not None:
        keep &= ~np.isin(cls, [int(k) for k in NOISE])
    sub = sub_grid(g, r0, r1, c0, c1)
    row, col, inside = sub.cell_index(xy[keep, 0], xy[keep, 1])
    counts = np.bincount(row[inside] * sub.cols + col[inside], minlength=sub.rows * sub.cols)
    from workstation.ground.common import crs_unit_factors

    area_m2 = (g.res * crs_unit_factors(ctx.crs)[0]) ** 2
    dens = (counts / area_m2).reshape(sub.shape).astype(np.float32)
    path = ctx.out / "density" / "tiles" / f"{chunk.name}.tif"
    path.parent.mkdir(parents=True, exist_ok=True)
    write_raster(Raster(dens, sub.transform, ctx.crs, -9999.0, {"kind": "density"}), path, overwrite=True,
                 overviews=False)
    return [str(path)]


# ----------------------------------------------------------------------------- mosaics
def mosaic_task(ctx: RunContext, grid, tiles: list, out: str, meta: dict) -> dict:
    """One COG over the project grid from the tiles (paths on that grid)."""
    import rasterio

    from workstation.io.geotiff import write_mosaic

    t0 = time.perf_counter()
    if not tiles:
        raise StageError("mosaic", f"no tile of {meta.get('kind')} was made", "check the earlier stages' errors")
    placed = []
    for p in sorted(tiles):
        with rasterio.open(p) as src:
            t = src.transform
        placed.append((p, int(round((grid.y1 - t.f) / grid.res)), int(round((t.c - grid.x0) / grid.res))))
    Path(out).parent.mkdir(parents=True, exist_ok=True)
    write_mosaic(placed, grid.transform, grid.shape, out, crs=ctx.crs, meta=meta, overwrite=True)
    return {"tiles": len(placed), "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": [out]}


def hillshade_task(ctx: RunContext, params, dtm: str, out: str, *upstream) -> dict:
    from workstation.io.geotiff import read_raster, write_raster
    from workstation.raster.terrain import hillshade

    t0 = time.perf_counter()
    write_raster(hillshade(read_raster(dtm), params), out, overwrite=True)
    return {"seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": [out]}


def contours_task(ctx: RunContext, params, dtm: str, out: str, *upstream) -> dict:
    from workstation.io.geotiff import read_raster
    from workstation.raster.contours import contour_lines, write_geojson

    t0 = time.perf_counter()
    cs = contour_lines(read_raster(dtm), params)
    write_geojson(cs, out, overwrite=True)
    return {"lines": len(cs.lines), "interval": cs.interval, "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": [out]}


# ----------------------------------------------------------------------------- quality control
def qc_task(ctx: RunContext, stage, dtm: str | None, out: str, *upstream) -> dict:
    """The QC report of the run (``ws qc`` of its point files and DTM) into ``out``, merged from
    the partial states of the QC tasks (:mod:`.qc_tasks`)."""
    from workstation.qc.partial import merge_report

    from .qc_tasks import qc_params, state_root

    t0, c0 = time.perf_counter(), time.process_time()
    params = qc_params(ctx, stage, dtm if dtm and Path(dtm).exists() else None)
    doc = merge_report(state_root(ctx), params, Path(out), overwrite=True)
    outs = [str(p) for p in sorted(Path(out).iterdir()) if p.is_file()]
    return {"points": 0, "checked_points": doc["points"], "spec": doc["verdict"]["spec"],
            "pass": doc["verdict"]["pass"],
            "seconds": elapsed(t0), "cpu_s": round(time.process_time() - c0, 3), "peak_rss_mb": peak_rss_mb(),
            "outputs": outs}
