"""Ground filtering tile by tile, for clouds too large to filter at once.

A filter holds several arrays per point and per grid cell on top of the cloud it is given
(72–350 bytes per point, ``auto`` the most), so a 100 M-point
file through ``auto`` would need some 35 GB at once. As lidR processes a LAScatalog in chunks
with a buffer, and PDAL pipelines run ``filters.splitter`` before a filter, the cloud is cut
into equal rectangles of about ``tile_points`` points; each tile is filtered together with the
points of its neighbours within ``buffer`` metres (the filters' windows reach that far, so a
tile's edge sees the terrain beyond it), and only the tile's own points keep the classes
found. Peak memory then follows the tile, not the file; with ``workers`` > 1 the tiles are
filtered on a local Dask cluster of as many worker processes (the same classes as one after
the other), since most of a filter's work runs on one core. ``ws run`` cuts whole surveys
the same way, file by file (:mod:`workstation.pipeline`).

The buffer (60 m) is twice the widest window of the default filters (``auto``'s 30 m SMRF
window; PTD's 20 m seed cells): a roof at a tile's edge is opened away with the same window
as anywhere else. A tile in which a filter finds no ground (open water, a roof filling the
whole tile) gives its points class 1 and is reported; a cloud with no ground at all is an
error, as without tiles.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.progress import progress_bar, track

from .common import OVERWRITABLE, crs_unit_factors

log = get_logger(__name__)
STAGE = "ground.tiles"


@dataclass(frozen=True)
class TileParams:
    """How a large cloud is cut for ground filtering.

    Attributes
    ----------
    tile_points : int
        About this many points per tile (without the buffer); a cloud with no more points is
        filtered whole (10,000,000: about 3.5 GB for ``auto``).
    buffer : float
        Metres of neighbouring points filtered with each tile (60).
    workers : int
        Tiles filtered at once, each by a worker of a local Dask cluster (1: one after the
        other, in this process). Memory grows with it: each worker holds one buffered tile and
        its filter. The workers are spawned processes, so a script that asks for more than one
        needs Python's ``if __name__ == "__main__":`` guard around its work (``ws ground`` has it).
    """

    tile_points: int = 10_000_000
    buffer: float = 60.0
    workers: int = 1

    def __post_init__(self):
        if self.workers < 1:
            raise InvalidInputError(f"workers {self.workers} is below 1", "use 1 or more processes", field="workers")
        if self.tile_points < 1000:
            raise InvalidInputError(f"tile_points {self.tile_points} is too small", "use at least 1000 points per tile",
                                    field="tile_points")
        if not self.buffer >= 0:
            raise InvalidInputError(f"buffer {self.buffer} m is negative", "use 0 or more metres", field="buffer")


class TileLayout:
    """Square tiles over planar points ``xy`` (m, 2) in metres.

    The tiles are rectangles of equal size, as many along each axis as a square of about
    ``tile_points`` points (at the mean density of the occupied area: 10 m cells that hold a
    point, so a gap or an L-shaped survey does not make the tiles fuller than asked) needs to
    cover the extent: no tile holds more than about ``tile_points`` points at that density,
    and none is left nearly empty beside a full one. Iterating gives (core indices, buffered
    indices) per non-empty tile, both sorted, the core a subset of the buffered set; every
    point is in exactly one core. Memory: 12 bytes per point (float32 planar coordinates and
    int32 tile order) plus one tile's indices at a time.
    """

    def __init__(self, xy: np.ndarray, tile_points: int, buffer: float):
        lo = xy.min(axis=0)
        self.xy = (xy - lo).astype(np.float32)
        self.buffer = float(buffer)
        cells = np.floor(self.xy / 10.0).astype(np.int64)
        dims = cells.max(axis=0) + 1
        if int(dims[0]) * int(dims[1]) <= 50_000_000:  # a bitmap of the 10 m cells: O(n)
            occupied = np.zeros(int(dims[0]) * int(dims[1]), bool)
            occupied[cells[:, 0] * dims[1] + cells[:, 1]] = True
            n_cells = int(np.count_nonzero(occupied))
        else:
            n_cells = len(np.unique(cells[:, 0] * dims[1] + cells[:, 1]))
        del cells
        area = max(n_cells * 100.0, 1.0)
        side = max(float(np.sqrt(tile_points * area / len(xy))), 1.0)
        ext = self.xy.max(axis=0).astype(np.float64)
        self.nx, self.ny = max(1, int(np.ceil(ext[0] / side))), max(1, int(np.ceil(ext[1] / side)))
        self.sx, self.sy = max(ext[0] / self.nx, 1e-6), max(ext[1] / self.ny, 1e-6)
        ix = np.minimum((self.xy[:, 0] / self.sx).astype(np.int64), self.nx - 1)
        iy = np.minimum((self.xy[:, 1] / self.sy).astype(np.int64), self.ny - 1)
        tile = ix * self.ny + iy
        self.order = np.argsort(tile, kind="stable").astype(np.int32 if len(xy) < 2**31 else np.int64)
        self.starts = np.searchsorted(tile[self.order], np.arange(self.nx * self.ny + 1))

    def __len__(self) -> int:
        return int(np.count_nonzero(np.diff(self.starts)))

    def __iter__(self):
        sx, sy, buf, xy = self.sx, self.sy, self.buffer, self.xy
        for a in range(self.nx):
            # the buffered selection per column of tiles first, then per row
            col = np.flatnonzero((xy[:, 0] >= a * sx - buf) & (xy[:, 0] <= (a + 1) * sx + buf))
            ycol = xy[col, 1]
            for b in range(self.ny):
                t = a * self.ny + b
                if self.starts[t] == self.starts[t + 1]:
                    continue
                core = np.sort(self.order[self.starts[t]:self.starts[t + 1]]).astype(np.int64)
                # the union (a core point on a tile's edge is in its buffered set whatever the
                # rounding) as a mask: O(n), where np.union1d's hashing took seconds per tile
                mask = np.zeros(len(xy), bool)
                mask[col[(ycol >= b * sy - buf) & (ycol <= (b + 1) * sy + buf)]] = True
                mask[core] = True
                yield core, np.flatnonzero(mask)


def tile_layout(xy: np.ndarray, tile_points: int, buffer: float) -> TileLayout:
    """The tiles of :class:`TileLayout` (iterate for (core, buffered) index pairs)."""
    return TileLayout(xy, tile_points, buffer)


def _filter_tile(method: str, params, xyz: np.ndarray, attrs: dict, crs, inner: np.ndarray):
    """Classes of a buffered tile's own points (``inner``), and the filter's history record;
    ``None`` classes when the filter finds no ground or no usable point there. Module level,
    on plain arrays: a worker process receives it pickled."""
    from .methods import methods

    try:
        out = methods()[method].func(Cloud(xyz, attrs, crs=crs), params)
    except StageError as e:
        return None, e.message
    return np.asarray(out.attrs["classification"])[inner], out.history[-1]


def _filter_on_dask(layout, task, collect, advance, workers: int) -> None:
    """Filter the tiles on a local Dask cluster of ``workers`` single-threaded processes (the
    scheduler ``ws run`` uses), at most one tile per worker in flight: a tile's copy is made
    only when a worker is free for it."""
    from workstation.core.dasktasks import local_client, run_bounded
    from workstation.core.signals import caught_signals

    with local_client(workers) as client, caught_signals() as latch:
        def done(core, result):
            collect(core, result)
            advance(1)

        calls = ((core, lambda core=core, sel=sel: (_filter_tile, *task(core, sel))) for core, sel in layout)
        run_bounded(client, calls, workers, done, latch)


def ground_tiled(cloud: Cloud, method: str, params, tiles: TileParams = TileParams()) -> Cloud:
    """Run the ground filter ``method`` (a name of :mod:`workstation.ground.methods`) with
    ``params`` tile by tile (see the module doc); the whole cloud at once when it has no more
    than ``tiles.tile_points`` points.

    Returns
    -------
    Cloud
        As the filter returns it: ``classification`` 2 on ground, 1 elsewhere, other classes
        kept unless the parameters say ``reclassify``; one history record for the whole run.
    """
    from .methods import methods

    if cloud.n <= tiles.tile_points:
        return methods()[method].func(cloud, params)
    t0 = time.perf_counter()
    hf, _ = crs_unit_factors(cloud.crs)
    layout = tile_layout(cloud.xyz[:, :2] * hf, tiles.tile_points, tiles.buffer)
    old = cloud.attrs.get("classification")
    reclassify = bool(getattr(params, "reclassify", False))
    cls = np.full(cloud.n, np.uint8(ASPRSClass.UNCLASSIFIED))
    if old is not None and not reclassify:
        cls = np.where(np.isin(old, OVERWRITABLE), cls, np.asarray(old, dtype=np.uint8))
    record, empty = None, []

    def task(core, sel):  # the arguments of one tile's filter run
        return (method, params, cloud.xyz[sel], {k: np.asarray(v)[sel] for k, v in cloud.attrs.items()}, cloud.crs,
                np.searchsorted(sel, core))  # core ⊂ sel, both sorted

    def collect(core, result):
        nonlocal record
        got, rec = result
        if got is None:
            empty.append(len(core))
            log.warning("%s: a tile of %d points has no ground (%s); its points stay non-ground", STAGE, len(core), rec)
            return
        cls[core] = got
        record = record or rec

    desc = f"ground ({method}) tile by tile" + (f", {tiles.workers} processes" if tiles.workers > 1 else "")
    if tiles.workers == 1:
        for core, sel in track(layout, desc, total=len(layout), unit="tiles"):
            collect(core, _filter_tile(*task(core, sel)))
    else:
        with progress_bar(desc, len(layout), unit="tiles") as advance:
            _filter_on_dask(layout, task, collect, advance, tiles.workers)
    if record is None or not (cls == ASPRSClass.GROUND).any():
        raise StageError(STAGE, f"no ground point found in any of {len(layout)} tiles",
                         "check the units and the parameters, or the noise classes")
    info = {**record.params, "tiles": len(layout), "tile_points": tiles.tile_points, "buffer_m": tiles.buffer,
            "workers": tiles.workers, "tiles_without_ground": len(empty)}
    log.info("%s: %s on %d points in %d tiles (%d without ground) in %.1f s", STAGE, method, cloud.n, len(layout),
             len(empty), time.perf_counter() - t0)
    return cloud.with_attrs(classification=cls).with_history(record.stage, info, time.perf_counter() - t0)
