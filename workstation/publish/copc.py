"""COPC 1.0 writer (Cloud Optimized Point Cloud, https://copc.io): an octree of LAZ chunks.

A COPC file is a LAZ 1.4 file of point format 6, 7 or 8 whose first VLR (``copc``/1, 160
bytes) gives the octree cube and root spacing, whose points are stored one LAZ chunk per
octree node (variable-size chunks, lazrs), and whose EVLR ``copc``/1000 lists every node
(VoxelKey level/x/y/z, file offset, byte size, point count; 32-byte entries, one page here).
A reader decompresses only the nodes a box or a level of detail needs.

The octree is built as PDAL's ``writers.copc`` / untwine build theirs (a level-of-detail
octree by grid sampling, as in Potree, Schütz 2016, "Potree: Rendering Large Point Clouds in
Web Browsers"): the root is a cube around the data; a node keeps every point left to it when
there are at most ``max_points`` of them, else one point per cell of a ``cells``³ grid over the
node (the median point of the cell in Morton order) and passes the others to its eight
children. So level L has a point spacing of ``2 * halfsize / cells / 2**L`` and the union of
levels 0..L is an even thinning of the cloud.

Everything is vectorised over points: each point gets a 63-bit Morton code (21 bits per
axis, Morton 1966) of its position in the cube; one sort puts every node and every grid cell
of every level in a contiguous run, and each level is a pass of shifts and run boundaries over
the points still unassigned. Only per-point codes, levels and indices (a 64-bit code,
32-bit indices, plus one compression batch) are held in memory: the point records are
first written, as they come, to a temporary uncompressed LAS file beside the output (through
:class:`workstation.io.las.ChunkWriter`, which makes the header, extra bytes, CRS and
scales/offsets as for any LAS output), then read back node by node through a memory map
(its pages are file cache, counted in RSS but reclaimable) and compressed in parallel
batches. A stream of chunks and the whole cloud at once therefore give the same file.

The cube has a side of ``2**k`` coordinate units (of the coarsest axis scale) and its corner
half a unit below the smallest integer coordinate, so with axis scales that divide each
other no stored point lies on a node boundary and a reader's float node bounds agree with the
integer assignment made here.
"""

from __future__ import annotations

import dataclasses
import os
import struct
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.io.copc import COPC_HIERARCHY, COPC_INFO, ENTRY_DTYPE

log = get_logger(__name__)

DEPTH = 21  # bits per axis of the Morton code (3 * 21 = 63 bits)
COPC_FORMATS = (6, 7, 8)
_EVLR_HEADER = struct.Struct("<H16sHQ32s")  # reserved, user_id, record_id, length after header, description
SLICE_POINTS = 1 << 20  # points per slice when computing codes from the memory map


@dataclass(frozen=True)
class CopcParams:
    """Octree parameters of the COPC writer.

    Attributes
    ----------
    max_points : int
        A node keeps all the points left to it when there are at most this many (then it
        has no children); a node with more keeps one point per grid cell. Points.
    cells : int
        Grid cells per node side for the sampling (a power of two): the root spacing is
        ``2 * halfsize / cells`` (CRS units), halved at each level. 128 as in untwine.
    batch_points : int
        Points gathered and compressed per lazrs call (its nodes are compressed in
        parallel); bounds the memory of the gathered records to ``batch_points`` × record
        size bytes.
    """

    max_points: int = 100_000
    cells: int = 128
    batch_points: int = 2_000_000

    def __post_init__(self):
        if self.max_points < 1:
            raise InvalidInputError(f"max_points {self.max_points} must be at least 1", field="max_points")
        if self.cells < 2 or self.cells & (self.cells - 1) or self.cells > 2**10:
            raise InvalidInputError(f"cells {self.cells} must be a power of two from 2 to 1024", field="cells")
        if self.batch_points < 1:
            raise InvalidInputError(f"batch_points {self.batch_points} must be at least 1", field="batch_points")


@dataclass(frozen=True)
class CopcResult:
    """What was written: ``points``, ``nodes`` (octree nodes holding points), ``levels``,
    ``points_per_level`` (tuple by level), ``point_format`` (6, 7 or 8), the cube ``center``
    (x, y, z) and ``halfsize`` and the root ``spacing`` (CRS units), ``bytes`` (file size)."""

    path: Path
    points: int
    nodes: int
    levels: int
    points_per_level: tuple
    point_format: int
    center: tuple
    halfsize: float
    spacing: float
    bytes: int

    def to_dict(self) -> dict:
        return {"path": str(self.path), "points": self.points, "nodes": self.nodes, "levels": self.levels,
                "points_per_level": list(self.points_per_level), "point_format": self.point_format,
                "center": list(self.center), "halfsize": self.halfsize, "spacing": self.spacing, "bytes": self.bytes}


def copc_point_format(attrs, point_format: int | None = None) -> int:
    """The COPC point format for attribute names ``attrs``: 8 with ``nir``, 7 with ``rgb``,
    else 6; ``point_format`` when given (it must be 6, 7 or 8, the formats COPC allows).

    Examples
    --------
    >>> copc_point_format({"intensity"}), copc_point_format({"rgb"}), copc_point_format({"rgb", "nir"})
    (6, 7, 8)
    """
    if point_format is not None:
        if point_format not in COPC_FORMATS:
            raise InvalidInputError(f"COPC cannot store point format {point_format}", "COPC 1.0 allows point formats "
                                    "6, 7 (RGB) and 8 (RGB + NIR)", field="point_format")
        return int(point_format)
    attrs = set(attrs)
    return 8 if "nir" in attrs else (7 if "rgb" in attrs else 6)


def write_copc(cloud: Cloud, path, params: CopcParams = CopcParams(), *, point_format: int | None = None,
               scales=None, offsets=None) -> CopcResult:
    """Write ``cloud`` as a COPC file at ``path`` (this exact path; see :func:`save_copc` for an
    atomic write with overwrite checks).

    Every attribute is kept (standard LAS dimensions in the point format, the others as extra
    bytes), with the CRS (WKT VLR) and the scales/offsets the cloud was read with (or
    ``scales``/``offsets``; see :func:`workstation.io.las.write`).
    """
    return write_copc_chunks(iter([cloud]), path, params, point_format=point_format, scales=scales, offsets=offsets)


def write_copc_chunks(chunks: Iterable[Cloud], path, params: CopcParams = CopcParams(), *, bounds=None,
                      point_format: int | None = None, scales=None, offsets=None, on_octree=None) -> CopcResult:
    """Write a stream of clouds (same attributes and CRS, e.g. from
    :func:`workstation.io.registry.iter_chunks`) as one COPC file, holding one chunk at a time.

    ``bounds`` (lo, hi) of all the data, when known (a LAS header), let the automatic offsets
    fit every chunk; else those of the first chunk are used. ``on_octree``, when given, is
    called with the :class:`StagedOctree` once the octree is built and before the file is
    written, so another product of the same octree (a 3D Tiles tileset) is made from this one
    read and sort of the points.
    """
    t0 = time.perf_counter()
    chunks = iter(chunks)
    first = next(chunks, None)
    if first is None:
        raise InvalidInputError("no point chunks to write", "give a cloud (it may have 0 points)", path=path)
    path = Path(path)
    fmt = copc_point_format(first.attrs, point_format)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".records.las", dir=path.parent)
    os.close(fd)
    try:
        header = stage_records(first, chunks, Path(tmp), fmt, bounds, scales, offsets)
        result = _write_octree(Path(tmp), header, path, params, first.crs, on_octree)
    finally:
        Path(tmp).unlink(missing_ok=True)
    log.info("COPC %s: %d points in %d nodes over %d levels (%.1f s)", path.name, result.points, result.nodes,
             result.levels, time.perf_counter() - t0)
    return result


def save_copc(cloud_or_chunks, path, params: CopcParams = CopcParams(), *, overwrite: bool = False, inputs=(),
              bounds=None, point_format: int | None = None, scales=None, offsets=None) -> CopcResult:
    """Write a cloud (or an iterable of chunk clouds) as COPC atomically: refuses an existing
    ``path`` unless ``overwrite``, writes to a temporary file beside it and renames it."""
    from workstation.io.atomic import atomic_path
    from workstation.io.copc import copc_output

    chunks = iter([cloud_or_chunks]) if isinstance(cloud_or_chunks, Cloud) else cloud_or_chunks
    with copc_output(), atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        result = write_copc_chunks(chunks, tmp, params, bounds=bounds, point_format=point_format, scales=scales,
                                   offsets=offsets)
    return dataclasses.replace(result, path=Path(path))


# ---------------------------------------------------------------------------------------
# staging: the records, uncompressed, in a temporary LAS file


def stage_records(first: Cloud, rest: Iterator[Cloud], tmp: Path, fmt: int, bounds, scales, offsets):
    """Write every chunk to the plain LAS file ``tmp`` (header, extra bytes, CRS, scales and
    offsets made by :class:`~workstation.io.las.ChunkWriter`); return its header, EVLRs read."""
    import laspy

    from workstation.io.las import ChunkWriter

    if bounds is None and first.n:
        bounds = first.bounds
    with ChunkWriter(tmp, first, point_format=fmt, version="1.4", scales=scales, offsets=offsets, compress=False,
                     bounds=bounds) as writer:
        writer.write(first)
        for chunk in rest:
            if chunk.crs != first.crs:
                raise InvalidInputError(f"chunks have different CRSs ({first.crs} and {chunk.crs})",
                                        "reproject them to one CRS first", field="crs")
            writer.write(chunk)
    with open(tmp, "rb") as f:
        return laspy.LasHeader.read_from(f, read_evlrs=True)


def staged_records(tmp: Path, header) -> np.ndarray:
    """The point records of the staged LAS file as a read-only memory map."""
    dtype = header.point_format.dtype()
    if dtype.itemsize != header.point_format.size:
        raise StageError("copc", f"record size {dtype.itemsize} differs from the header's {header.point_format.size}")
    if header.point_count == 0:
        return np.zeros(0, dtype)
    return np.memmap(tmp, dtype=dtype, mode="r", offset=header.offset_to_point_data, shape=(header.point_count,))


# ---------------------------------------------------------------------------------------
# the octree


@dataclass(frozen=True)
class _Cube:
    """The octree cube: ``corner`` (x, y, z) and ``side`` in CRS units."""

    corner: np.ndarray
    side: float


def _cube(header) -> _Cube:
    """A cube of side ``2**k`` units of the coarsest axis scale holding every integer
    coordinate, its corner half a unit below the smallest one (see the module docstring)."""
    scales, offsets = np.asarray(header.scales, float), np.asarray(header.offsets, float)
    if header.point_count:
        ilo = np.round((np.asarray(header.mins) - offsets) / scales)
        ihi = np.round((np.asarray(header.maxs) - offsets) / scales)
    else:
        ilo = ihi = np.zeros(3)
    unit = float(scales.max())
    extent = float(((ihi - ilo + 1.0) * scales).max())
    k = max(0, int(np.ceil(np.log2(extent / unit))))
    while unit * 2.0**k < extent:
        k += 1
    return _Cube(offsets + scales * (ilo - 0.5), unit * 2.0**k)


def _part1by2(v: np.ndarray) -> np.ndarray:
    """Spread the low 21 bits of ``v`` (uint64) to every third bit (Morton interleave)."""
    v = v & np.uint64(0x1FFFFF)
    for shift, mask in ((32, 0x1F00000000FFFF), (16, 0x1F0000FF0000FF), (8, 0x100F00F00F00F00F),
                        (4, 0x10C30C30C30C30C3), (2, 0x1249249249249249)):
        v = (v | (v << np.uint64(shift))) & np.uint64(mask)
    return v


def compact1by2(v: np.ndarray) -> np.ndarray:
    """Inverse of :func:`_part1by2`: every third bit of ``v`` gathered into the low bits."""
    v = v & np.uint64(0x1249249249249249)
    for shift, mask in ((2, 0x10C30C30C30C30C3), (4, 0x100F00F00F00F00F), (8, 0x1F0000FF0000FF),
                        (16, 0x1F00000000FFFF), (32, 0x1FFFFF)):
        v = (v | (v >> np.uint64(shift))) & np.uint64(mask)
    return v


def _morton_codes(records: np.ndarray, header, cube: _Cube) -> tuple[np.ndarray, float, float]:
    """(Morton code of every point in the cube, min and max GPS time), slice by slice so the
    temporaries stay small. The coordinates are those a reader computes (X * scale + offset)."""
    n = len(records)
    codes = np.empty(n, np.uint64)
    scales, offsets = np.asarray(header.scales, float), np.asarray(header.offsets, float)
    top = float(2**DEPTH - 1)
    gmin, gmax = np.inf, -np.inf
    for s in range(0, n, SLICE_POINTS):
        part = records[s : s + SLICE_POINTS]
        code = np.zeros(len(part), np.uint64)
        for i, c in enumerate("XYZ"):
            t = ((part[c] * scales[i] + offsets[i]) - cube.corner[i]) * (2.0**DEPTH / cube.side)
            code |= _part1by2(np.clip(np.floor(t), 0.0, top).astype(np.uint64)) << np.uint64(i)
        codes[s : s + len(part)] = code
        g = part["gps_time"]
        gmin, gmax = min(gmin, float(g.min())), max(gmax, float(g.max()))
    return codes, (gmin if n else 0.0), (gmax if n else 0.0)


def _run_starts(keys: np.ndarray) -> np.ndarray:
    """Start index of every run of equal values in the sorted ``keys``."""
    if not len(keys):
        return np.zeros(0, np.int64)
    return np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])


def assign_levels(codes: np.ndarray, params: CopcParams) -> np.ndarray:
    """The octree level of every point, given Morton codes sorted ascending.

    At level d a node is a run of codes sharing their top ``3d`` bits and a grid cell a run
    sharing their top ``3(d + log2 cells)`` bits. A node with at most ``max_points`` points
    left keeps them all; a larger one keeps the median point (in code order) of each of its
    cells. At the deepest level the Morton code resolves (21 - log2 cells) every point left
    is kept.

    Examples
    --------
    >>> codes = np.sort(np.random.default_rng(0).integers(0, 2**63, 1000, dtype=np.uint64))
    >>> lev = assign_levels(codes, CopcParams(max_points=100, cells=4))
    >>> int(lev.min()), bool((lev >= 0).all()), int((lev == 0).sum()) <= 4**3
    (0, True, True)
    """
    n = len(codes)
    level = np.full(n, -1, np.int8)
    grid_bits = int(params.cells).bit_length() - 1
    last = DEPTH - grid_bits
    rem = None  # all points at level 0 (no index array needed)
    for d in range(last + 1):
        if rem is not None and not len(rem):
            break
        c = codes if rem is None else codes[rem]
        starts = _run_starts(c >> np.uint64(3 * (DEPTH - d)))
        counts = np.diff(np.r_[starts, len(c)])
        take = np.repeat((counts <= params.max_points) | (d == last), counts)  # whole nodes
        cstarts = _run_starts(c >> np.uint64(3 * (DEPTH - d - grid_bits)))
        take[cstarts + np.diff(np.r_[cstarts, len(c)]) // 2] = True
        if rem is None:
            level[take] = d
            rem = np.flatnonzero(~take)
        else:
            level[rem[take]] = d
            rem = rem[~take]
    return level


def _compact_index(index: np.ndarray) -> np.ndarray:
    """``index`` as uint32 when it fits (half the memory of the int64 numpy sorts return)."""
    return index.astype(np.uint32) if len(index) < 2**32 else index


def _node_runs(codes: np.ndarray, level: np.ndarray):
    """(order, starts, node levels, node Morton prefixes): ``order`` sorts the points by
    (level, code), so each node's points are the run ``order[starts[i]:starts[i + 1]]``.
    Level by level (at most 21), so the temporaries are those of one level."""
    order = _compact_index(np.argsort(level, kind="stable"))  # codes are sorted: (level, code) order
    bounds = np.searchsorted(level[order], np.arange(level.max() + 2 if len(level) else 1))
    starts, levels, prefixes = [], [], []
    for d in range(len(bounds) - 1):
        a, b = int(bounds[d]), int(bounds[d + 1])
        if a == b:
            continue
        prefix = codes[order[a:b]] >> np.uint64(3 * (DEPTH - d))
        run = _run_starts(prefix)
        starts.append(run + a)
        levels.append(np.full(len(run), d, np.int32))
        prefixes.append(prefix[run])
    if not starts:
        return order, np.zeros(0, np.int64), np.zeros(0, np.int32), np.zeros(0, np.uint64)
    return order, np.concatenate(starts), np.concatenate(levels), np.concatenate(prefixes)


# ---------------------------------------------------------------------------------------
# the file


@dataclass(frozen=True)
class Octree:
    """The octree of staged records: ``src`` (record index of every point, node by node, each
    node's run in (level, Morton code) order), ``starts`` (first index of each node in
    ``src``), node ``level`` and Morton ``prefix`` (the node's code bits, ``3 * level`` of
    them), the ``cube`` and the GPS time range (``gmin``, ``gmax``) of the points."""

    src: np.ndarray
    starts: np.ndarray
    level: np.ndarray
    prefix: np.ndarray
    cube: _Cube
    gmin: float
    gmax: float


@dataclass(frozen=True)
class StagedOctree:
    """What :func:`write_copc_chunks` passes to its ``on_octree`` callback: the staged point
    ``records`` (a read-only memory map, valid only during the call), their LAS ``header``
    (scales, offsets, bounds, point count), the :class:`Octree`, the ``crs`` and the
    :class:`CopcParams` it was built with."""

    records: np.ndarray
    header: object
    tree: Octree
    crs: object
    params: CopcParams


def build_octree(records: np.ndarray, header, params: CopcParams) -> Octree:
    """The COPC octree of the staged ``records``: one Morton sort, then the levels
    (:func:`assign_levels`) and the node runs."""
    cube = _cube(header)
    codes, gmin, gmax = _morton_codes(records, header, cube)
    perm = _compact_index(np.argsort(codes, kind="stable"))
    codes = codes[perm]
    order, starts, node_level, prefix = _node_runs(codes, assign_levels(codes, params))
    del codes
    src = perm[order]
    del perm, order
    return Octree(src, starts, node_level, prefix, cube, gmin, gmax)


def _write_octree(tmp: Path, header, path: Path, params: CopcParams, crs, on_octree=None) -> CopcResult:
    """Sort the staged records into the octree, hand it to ``on_octree`` (when given) and
    write the COPC file at ``path``."""
    import lazrs

    records = staged_records(tmp, header)
    tree = build_octree(records, header, params)
    if on_octree is not None:
        on_octree(StagedOctree(records, header, tree, crs, params))
    cube, src, starts, node_level, prefix = tree.cube, tree.src, tree.starts, tree.level, tree.prefix
    fmt = header.point_format.id
    laz_vlr = lazrs.LazVlr.new_for_compression(fmt, header.point_format.num_extra_bytes, True)
    out, info_vlr, evlrs = _copc_header(header, laz_vlr, crs)
    with open(path, "w+b") as f:
        out.write_to(f)
        table = _compress_nodes(f, laz_vlr, records, src, starts, params.batch_points, out.offset_to_point_data)
        f.seek(0, os.SEEK_END)
        evlr_start = f.tell()
        entries = _entries(node_level, prefix, table, out.offset_to_point_data)
        counts = entries["point_count"].astype(np.int64)
        if int(counts.sum()) != header.point_count:
            raise StageError("copc", f"the octree holds {int(counts.sum()):,} points, the input {header.point_count:,}")
        if not len(entries):  # an empty cloud: a root node without points
            entries = np.zeros(1, ENTRY_DTYPE)
        _write_evlr(f, *COPC_HIERARCHY, "EPT hierarchy", entries.tobytes())
        for v in evlrs:
            _write_evlr(f, v.user_id, int(v.record_id), v.description, bytes(v.record_data_bytes()))
        size = f.tell()
        out.start_of_first_evlr = evlr_start
        info_vlr.record_data = _info_bytes(cube, params, evlr_start + _EVLR_HEADER.size, entries.nbytes, tree.gmin,
                                           tree.gmax)
        f.seek(0)
        out.write_to(f, ensure_same_size=True)
    per_level = np.bincount(node_level, weights=counts, minlength=1 if len(counts) else 0).astype(np.int64)
    half = cube.side / 2.0
    return CopcResult(path, int(counts.sum()), int(len(counts)), int(len(per_level) if len(counts) else 0),
                      tuple(per_level.tolist()), int(fmt), tuple((cube.corner + half).tolist()), half,
                      cube.side / params.cells, size)


def _copc_header(header, laz_vlr, crs):
    """(header to write, its COPC info VLR, the EVLRs to keep): the staged header made LAZ,
    with the info VLR first, the laszip VLR, and the CRS as a WKT VLR (LAS 1.4, formats 6-8)."""
    import laspy

    header.are_points_compressed = True
    keep = [v for v in header.vlrs if v.user_id not in ("copc", "laszip encoded")]
    info = laspy.VLR(COPC_INFO[0], COPC_INFO[1], "COPC info", bytes(160))
    header.vlrs = [info, laspy.VLR("laszip encoded", 22204, "lazrs", bytes(laz_vlr.record_data())), *keep]
    evlrs = [v for v in (header.evlrs or []) if v.user_id != "copc"]
    header.global_encoding.wkt = True  # LAS 1.4: required for point formats 6-10, CRS or not
    if crs:
        import pyproj

        header.add_crs(pyproj.CRS.from_user_input(crs))  # replaces GeoTIFF keys by WKT, sets the WKT bit
        evlrs = [v for v in evlrs if v.user_id != "LASF_Projection"]
    if header.vlrs[0] is not info:
        raise StageError("copc", "the COPC info VLR is not the first VLR")
    header.number_of_evlrs = 1 + len(evlrs)
    header.start_of_first_evlr = 0
    return header, info, evlrs


def _compress_nodes(f, laz_vlr, records, src, starts, batch_points: int, data_start: int) -> list:
    """Compress each node's records as one LAZ chunk (points in input order, which compresses
    best), ``batch_points`` at a time in parallel; return the chunk table [(points, bytes)]."""
    import lazrs

    from workstation.core.progress import progress_bar

    comp = lazrs.ParLasZipCompressor(f, laz_vlr)
    comp.reserve_offset_to_chunk_table()
    ends = np.r_[starts[1:], len(src)].astype(np.int64)
    batch, size = [], 0
    with progress_bar("COPC", total=len(src), unit="points") as advance:
        for s, e in zip(starts.tolist(), ends.tolist()):
            batch.append(np.asarray(records[np.sort(src[s:e])]).view(np.uint8))
            size += e - s
            if size >= batch_points:
                comp.compress_chunks(batch)
                advance(size)
                batch, size = [], 0
        if batch:
            comp.compress_chunks(batch)
            advance(size)
    comp.done()
    f.seek(data_start)
    return lazrs.read_chunk_table(f, laz_vlr)


def _entries(node_level, prefix, table, data_start: int) -> np.ndarray:
    """The hierarchy entries of the nodes: key from the Morton prefix, chunk offset and size
    from the LAZ chunk table (chunks follow the 8-byte chunk table offset, in node order)."""
    e = np.zeros(len(node_level), ENTRY_DTYPE)
    if not len(e):
        return e
    counts = np.array([c for c, _ in table], np.int64)
    nbytes = np.array([b for _, b in table], np.int64)
    if len(counts) != len(e):
        raise StageError("copc", f"{len(counts)} LAZ chunks written for {len(e)} octree nodes")
    e["level"] = node_level
    for i, axis in enumerate("xyz"):
        e[axis] = compact1by2(prefix >> np.uint64(i)).astype(np.int32)
    e["offset"] = data_start + 8 + np.r_[0, np.cumsum(nbytes)[:-1]]
    e["byte_size"] = nbytes
    e["point_count"] = counts
    return e


def _write_evlr(f, user_id: str, record_id: int, description: str, data: bytes) -> None:
    f.write(_EVLR_HEADER.pack(0, user_id.encode()[:16], record_id, len(data), description.encode()[:32]))
    f.write(data)


def _info_bytes(cube: _Cube, params: CopcParams, root_offset: int, root_size: int, gmin: float, gmax: float) -> bytes:
    """The 160-byte COPC info record: centre, half size, root spacing, root hierarchy page,
    GPS time range, 88 reserved bytes."""
    half = cube.side / 2.0
    centre = cube.corner + half
    return struct.pack("<5d2Q2d", *centre.tolist(), half, cube.side / params.cells, root_offset, root_size,
                       gmin, gmax) + bytes(88)
