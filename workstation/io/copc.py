"""COPC (Cloud Optimized Point Cloud, copc.io 1.0): detection, octree summary and queries.

A COPC file is a LAZ 1.4 file (PDRF 6-8) whose first VLR (``copc``/1, 160 bytes) gives the
octree cube (centre, half size), the point spacing at the root and where the hierarchy
(``copc``/1000, an EVLR) starts. The hierarchy is a set of pages of 32-byte entries
(VoxelKey level/x/y/z int32, offset uint64, byte size int32, point count int32); a count of
-1 points to a child page. Every node is one LAZ chunk, so a reader decompresses only the
nodes that a bounding box or a level of detail needs.

Writing is :mod:`workstation.publish.copc`; every other writer refuses a ``.copc.laz`` name
(:func:`refuse_copc_output`).

Queries go through ``laspy.CopcReader.query`` (its bounds are inclusive on the integer
coordinates; 2-D bounds take z from the header), so ``read(path, bounds=...)`` returns exactly
the points laspy returns. Detection and the hierarchy summary read a few KB of raw bytes.
"""

from __future__ import annotations

import contextlib
import contextvars
from dataclasses import dataclass
from pathlib import Path
import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError

#: (user_id, record_id) of the COPC info VLR and of the hierarchy EVLR.
COPC_INFO = ("copc", 1)
COPC_HIERARCHY = ("copc", 1000)
#: The only COPC version (the info VLR carries no version number).
COPC_VERSION = "1.0"

#: The info VLR's fields (72 bytes; 88 reserved bytes follow) and a hierarchy entry (32 bytes).
INFO_DTYPE = np.dtype([("center", "<f8", 3), ("halfsize", "<f8"), ("spacing", "<f8"), ("root_offset", "<u8"),
                       ("root_size", "<u8"), ("gps_min", "<f8"), ("gps_max", "<f8")])
ENTRY_DTYPE = np.dtype([("level", "<i4"), ("x", "<i4"), ("y", "<i4"), ("z", "<i4"), ("offset", "<u8"),
                        ("byte_size", "<i4"), ("point_count", "<i4")])
_VLR_HEADER = 54  # bytes: reserved u16, user_id char[16], record_id u16, length u16, description char[32]


def is_copc_vlr(user_id: str, record_id: int) -> bool:
    """True for the records of user ``copc``: the info VLR and the hierarchy EVLR describe one
    file's octree and byte offsets, copc-lib's extents (record 10000) one file's points, so
    none may be copied into another file."""
    return user_id == "copc"


@dataclass(frozen=True)
class CopcInfo:
    """The COPC info VLR: octree cube ``center`` (x, y, z) and ``halfsize``, ``spacing`` between
    points at the root (halved at each level), root hierarchy page (``root_offset``,
    ``root_size`` in bytes) and the GPS time range. Lengths in CRS units."""

    center: tuple
    halfsize: float
    spacing: float
    root_offset: int
    root_size: int
    gps_min: float
    gps_max: float


def read_info(path) -> CopcInfo | None:
    """The COPC info of ``path`` from its raw header bytes, or None when it is not COPC.

    COPC requires the info VLR to be the first VLR of a LAS 1.4 file, so reading the public
    header and that one record is enough (no laspy, no point decoding).
    """
    with open(path, "rb") as f:
        head = f.read(375)
        if len(head) < 227 or head[:4] != b"LASF" or head[24:26] != b"\x01\x04":
            return None
        header_size = int.from_bytes(head[94:96], "little")
        n_vlrs = int.from_bytes(head[100:104], "little")
        if n_vlrs == 0:
            return None
        f.seek(header_size)
        vlr = f.read(_VLR_HEADER + INFO_DTYPE.itemsize)
    if len(vlr) < _VLR_HEADER + INFO_DTYPE.itemsize:
        return None
    user_id = vlr[2:18].split(b"\0", 1)[0].decode("ascii", "replace")
    if (user_id, int.from_bytes(vlr[18:20], "little")) != COPC_INFO:
        return None
    r = np.frombuffer(vlr, INFO_DTYPE, count=1, offset=_VLR_HEADER)[0]
    return CopcInfo(tuple(float(c) for c in r["center"]), float(r["halfsize"]), float(r["spacing"]),
                    int(r["root_offset"]), int(r["root_size"]), float(r["gps_min"]), float(r["gps_max"]))


def is_copc(path) -> bool:
    """Whether ``path`` is a COPC file (its first VLR is the COPC info VLR)."""
    try:
        return read_info(path) is not None
    except OSError:
        return False


def hierarchy(path, info: CopcInfo) -> np.ndarray:
    """Every node entry of the octree (structured array of ``ENTRY_DTYPE``: level, x, y, z,
    offset, byte_size, point_count), following the child pages from the root page."""
    size = Path(path).stat().st_size
    pages, found = [(info.root_offset, info.root_size)], []
    with open(path, "rb") as f:
        while pages:
            offset, nbytes = pages.pop()
            if offset + nbytes > size or nbytes % ENTRY_DTYPE.itemsize:
                raise InvalidInputError(f"COPC hierarchy page at byte {offset:,} ({nbytes:,} bytes) is outside the file "
                                        "or not a whole number of entries", "the file is truncated or not valid COPC",
                                        path=path, field="copc")
            f.seek(offset)
            page = np.frombuffer(f.read(nbytes), ENTRY_DTYPE)
            child = page["point_count"] == -1
            pages.extend(zip(page["offset"][child].tolist(), page["byte_size"][child].tolist()))
            found.append(page[~child])
    return np.concatenate(found) if found else np.empty(0, ENTRY_DTYPE)


def summary(path) -> dict | None:
    """The COPC facts ``ws info`` shows, or None for a file that is not COPC.

    Returns
    -------
    dict
        ``version``, ``center``, ``halfsize``, ``spacing`` (root, CRS units), ``gps_time``
        ([min, max]), ``levels``, ``nodes`` (nodes holding points), ``points`` (sum of the node
        counts), ``points_per_level``, ``nodes_per_level`` and ``spacing_per_level`` (lists
        indexed by level; the spacing halves at each level).
    """
    info = read_info(path)
    if info is None:
        return None
    e = hierarchy(path, info)
    e = e[e["point_count"] > 0]
    levels = int(e["level"].max()) + 1 if len(e) else 0
    per_level = np.bincount(e["level"], weights=e["point_count"], minlength=levels).astype(np.int64)
    return {
        "version": COPC_VERSION,
        "center": list(info.center),
        "halfsize": info.halfsize,
        "spacing": info.spacing,
        "gps_time": [info.gps_min, info.gps_max],
        "levels": levels,
        "nodes": int(len(e)),
        "points": int(per_level.sum()),
        "points_per_level": per_level.tolist(),
        "nodes_per_level": np.bincount(e["level"], minlength=levels).tolist(),
        "spacing_per_level": (info.spacing / 2.0 ** np.arange(levels)).tolist(),
    }


def level_range(resolution: float | None, level: int | None, spacing: float) -> range | None:
    """The octree levels a query reads: ``level`` L means levels 0..L (the cloud at that level of
    detail); ``resolution`` R the levels down to the first whose spacing is at most R (laspy's
    rule: ``max(1, ceil(log2(spacing / R)) + 1)`` levels)."""
    if resolution is not None and level is not None:
        raise InvalidInputError("--resolution and --level cannot be given together",
                                "give one: --level picks octree levels, --resolution derives them", field="--level")
    if level is not None:
        return range(0, int(level) + 1)
    if resolution is not None:
        return range(0, max(1, int(np.ceil(np.log2(spacing / resolution))) + 1))
    return None


def query_records(path, bounds=None, resolution=None, level=None):
    """(laspy header, point records) of a COPC query; ``bounds`` is (xmin, ymin, xmax, ymax[, zmin,
    zmax]) or None (whole file)."""
    import laspy
    from laspy.copc import Bounds

    try:
        with laspy.CopcReader.open(str(path)) as reader:
            levels = level_range(resolution, level, reader.copc_info.spacing)
            box = None
            if bounds is not None:
                b = np.asarray(bounds, dtype=np.float64)
                half = len(b) // 2
                box = Bounds(mins=b[[0, 1, 4][:half]], maxs=b[[2, 3, 5][:half]])
            return reader.header, reader.query(bounds=box, level=levels)
    except (laspy.errors.LaspyException, ValueError, OSError, EOFError) as e:
        raise InvalidInputError(f"COPC query failed: {e}", "the file is truncated or not valid COPC", path=path) from None


def read(path, bounds=None, resolution=None, level=None) -> Cloud:
    """The points of a COPC file inside ``bounds`` at the level of detail asked, as a Cloud
    (the same points ``laspy.CopcReader.query`` returns; see :func:`level_range`)."""
    import laspy

    from workstation.io.las import Filler, meta_and_crs, vlr_records

    path = Path(path)
    header, rec = query_records(path, bounds, resolution, level)
    with open(path, "rb") as f:  # CopcReader skips the EVLRs, where the CRS may be
        full = laspy.LasHeader.read_from(f, read_evlrs=True)
    meta, crs = meta_and_crs(full, path)
    meta["las"]["evlrs"] = vlr_records(full.evlrs or [])
    meta["las"]["crs"] = crs
    meta["format"] = "laz"
    f = Filler(header, len(rec))
    if len(rec):
        f.fill(rec, 0)
    return Cloud.from_owned_arrays(f.xyz, f.attrs, crs=crs, meta=meta)



#: True while the COPC writer (:mod:`workstation.publish.copc`) writes an output.
_COPC_WRITER = contextvars.ContextVar("copc_writer", default=False)


def is_copc_name(path) -> bool:
    """Whether ``path`` is named as a COPC file (``.copc.laz``, any case)."""
    name = Path(path).name.lower()
    return name.endswith(".copc.laz") or name.endswith(".copc.las")


@contextlib.contextmanager
def copc_output():
    """Accept ``.copc.laz`` outputs inside the block: the COPC writer is the one writing them
    (:func:`workstation.publish.copc.save_copc`, ``ws convert``)."""
    token = _COPC_WRITER.set(True)
    try:
        yield
    finally:
        _COPC_WRITER.reset(token)


def refuse_copc_output(path) -> None:
    """Refuse a ``.copc.laz`` output outside the COPC writer: the other writers make plain
    LAS/LAZ, which that name would misrepresent (a COPC reader would find no octree)."""
    if is_copc_name(path) and not _COPC_WRITER.get():
        name = Path(path).name
        raise InvalidInputError("cannot write COPC here: this writes plain LAS/LAZ, which a .copc.laz name would "
                                "misrepresent", f"write {name[: -len('.copc.laz')]}.laz, then make COPC with "
                                f"`ws convert {name[: -len('.copc.laz')]}.laz {name}`", path=path, field="output")
