"""Cut clouds into square tiles (PDAL ``filters.splitter``, LAStools ``lastile``), streamed.

Tiles are aligned to multiples of their size and named by their lower-left corner in CRS
units (``482250_5452000.laz``, the naming of :class:`workstation.pipeline.chunks.Chunk`), so
two runs over the same survey cut it the same way. A point belongs to the tile that holds it
(``floor(x / size)``, ``floor(y / size)``) and, with a buffer, also to every neighbouring
tile whose square grown by the buffer holds it. Inputs are read chunk by chunk and every tile
is written chunk by chunk through its own LAS writer, so memory is one chunk plus the open
writers; with more candidate tiles than :data:`MAX_OPEN` the inputs are read again for each
group of tiles.
"""

from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud, concatenate
from workstation.core.errors import InvalidInputError, OutputExistsError, StageError
from workstation.pipeline.chunks import Chunk

from .stream import CHUNK, cloud_sink, input_chunks

MAX_OPEN = 200  # tile writers open at once (file handles, LAZ encoder buffers)
MAX_TILES = 100_000  # more files than this from one command is a mistaken --size, not a tiling


@dataclass(frozen=True)
class TileParams:
    """Parameters of :func:`tile_files`.

    Attributes
    ----------
    size : float
        Tile side in CRS units, > 0.
    buffer : float
        Points within this distance (CRS units) outside a tile are written to it too; 0 <= buffer < size.
    ext : str
        Extension of the tile files (".laz" or ".las").
    """

    size: float
    buffer: float = 0.0
    ext: str = ".laz"

    def __post_init__(self):
        if not (math.isfinite(self.size) and self.size > 0):
            raise InvalidInputError(f"tile size must be positive, got {self.size}", field="size")
        if not (math.isfinite(self.buffer) and 0 <= self.buffer < self.size):
            raise InvalidInputError(f"buffer {self.buffer} must be at least 0 and less than the size {self.size}",
                                    field="buffer")
        if self.ext not in (".las", ".laz"):
            raise InvalidInputError(f"tiles are written as .las or .laz, not {self.ext}", field="ext")


def tile_name(ix: int, iy: int, size: float) -> str:
    """Lower-left corner name of tile (ix, iy): ``"482250_5452000"`` (decimals for a fractional size).

    Examples
    --------
    >>> tile_name(3, -2, 250.0), tile_name(3, 1, 0.5)
    ('750_-500', '1.5_0.5')
    """
    if float(size).is_integer():
        return Chunk(ix, iy, size, 0.0).name
    digits = min(12, max(1, math.ceil(-math.log10(size)) + 1))  # enough to tell neighbours apart

    def fmt(v: float) -> str:
        return f"{v:.{digits}f}".rstrip("0").rstrip(".")

    return f"{fmt(ix * size)}_{fmt(iy * size)}"


def tile_memberships(xy: np.ndarray, size: float, buffer: float = 0.0):
    """Yield (point indices, ix, iy) arrays: each point's own tile, then with a buffer the
    neighbouring tiles whose buffered square holds it (up to 3 more per point)."""
    ix = np.floor(xy[:, 0] / size).astype(np.int64)
    iy = np.floor(xy[:, 1] / size).astype(np.int64)
    yield np.arange(len(xy)), ix, iy
    if buffer <= 0:
        return
    fx, fy = xy[:, 0] - ix * size, xy[:, 1] - iy * size  # position inside the own tile
    near_x = {-1: fx < buffer, 0: np.ones(len(xy), bool), 1: size - fx <= buffer}
    near_y = {-1: fy < buffer, 0: np.ones(len(xy), bool), 1: size - fy <= buffer}
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            if dx == dy == 0:
                continue
            idx = np.flatnonzero(near_x[dx] & near_y[dy])
            yield idx, ix[idx] + dx, iy[idx] + dy


def occupied_tiles(inputs, params: TileParams, chunk_size: int, read_opts: dict | None = None
                   ) -> tuple[list, tuple[float, float]]:
    """The tiles that receive at least one point (buffer included) and the z range of all the
    points, from one streamed pass: the cost follows the points, not the bounding box
    (``read_opts``: the point selection of :func:`~workstation.ops.stream.input_chunks`)."""
    keys: set = set()
    zlo, zhi = np.inf, -np.inf
    for src in inputs:
        for chunk in input_chunks(src, chunk_size, **(read_opts or {})):
            zlo, zhi = min(zlo, float(chunk.xyz[:, 2].min())), max(zhi, float(chunk.xyz[:, 2].max()))
            for _, ix, iy in tile_memberships(chunk.xyz[:, :2], params.size, params.buffer):
                keys.update(map(tuple, np.unique(np.column_stack([ix, iy]), axis=0).tolist()))
            if len(keys) > MAX_TILES:
                raise InvalidInputError(f"--size {params.size:g} would write more than {MAX_TILES:,} tiles",
                                        "give a larger --size (in the CRS units, like the coordinates)",
                                        path=src, field="--size")
    return sorted(keys), (zlo, zhi)


class _Tiles:
    """The open tile writers of one pass, each published when the pass ends without error."""

    def __init__(self, folder: Path, params: TileParams, overwrite: bool, inputs, zrange):
        self.folder, self.params, self.overwrite, self.inputs, self.zrange = folder, params, overwrite, inputs, zrange
        self.stack = contextlib.ExitStack()
        self.sinks: dict = {}

    def write(self, key, cloud: Cloud) -> None:
        sink = self.sinks.get(key)
        if sink is None:
            s, b = self.params.size, self.params.buffer
            lo = np.array([key[0] * s - b, key[1] * s - b, self.zrange[0]])
            hi = np.array([(key[0] + 1) * s + b, (key[1] + 1) * s + b, self.zrange[1]])
            path = self.folder / (tile_name(key[0], key[1], s) + self.params.ext)
            sink = self.stack.enter_context(cloud_sink(path, cloud, overwrite=self.overwrite, inputs=self.inputs,
                                                       bounds=(lo, hi), offsets="auto"))
            self.sinks[key] = sink
        sink.write(cloud)


def _schema(inputs, chunk_size: int, read_opts: dict | None = None) -> Cloud | None:
    """An empty cloud with the union of the inputs' attributes (None for a single input)."""
    if len(inputs) < 2:
        return None
    firsts = [next(input_chunks(p, chunk_size, **(read_opts or {})), None) for p in inputs]
    return concatenate([f[:1] for f in firsts if f is not None], check_crs=False)[:0]


def tile_files(inputs, folder, params: TileParams, *, overwrite: bool = False, chunk_size: int = CHUNK,
               read_opts: dict | None = None) -> dict:
    """Tile the inputs into ``folder`` (which must exist); returns {tile name: points written}.
    ``read_opts`` ({bounds, resolution, level}) selects the points read from every input.

    Raises
    ------
    OutputExistsError
        When a tile file the inputs can reach exists and ``overwrite`` is False (checked first).
    StageError
        When no point was written.
    """
    folder = Path(folder)
    inputs = [Path(p) for p in inputs]
    cands, zrange = occupied_tiles(inputs, params, chunk_size, read_opts)
    if not overwrite:
        for ix, iy in cands:
            path = folder / (tile_name(ix, iy, params.size) + params.ext)
            if path.exists():
                raise OutputExistsError(path)
    schema = _schema(inputs, chunk_size, read_opts)
    counts: dict[str, int] = {}
    for g in range(0, len(cands), MAX_OPEN):
        group = set(cands[g:g + MAX_OPEN])
        tiles = _Tiles(folder, params, overwrite, inputs, zrange)
        with tiles.stack:
            for src in inputs:
                for chunk in input_chunks(src, chunk_size, **(read_opts or {})):
                    _tile_chunk(chunk if schema is None else concatenate([schema, chunk], check_crs=False),
                                params, group, tiles)
        counts.update({tile_name(k[0], k[1], params.size): s.count for k, s in tiles.sinks.items()})
    if not counts:
        raise StageError("tile", "no point was written", "check the inputs")
    return dict(sorted(counts.items()))


def _tile_chunk(chunk: Cloud, params: TileParams, group: set, tiles: _Tiles) -> None:
    """Send each point of ``chunk`` to its tiles of ``group``."""
    for idx, ix, iy in tile_memberships(chunk.xyz[:, :2], params.size, params.buffer):
        if idx.size == 0:
            continue
        keys = ix * (1 << 32) + (iy & 0xFFFFFFFF)
        order = np.argsort(keys, kind="stable")
        uniq, starts = np.unique(keys[order], return_index=True)
        ends = np.r_[starts[1:], len(order)]
        for a, e in zip(starts, ends):
            key = (int(ix[order[a]]), int(iy[order[a]]))
            if key in group:
                tiles.write(key, chunk[idx[order[a:e]]])
