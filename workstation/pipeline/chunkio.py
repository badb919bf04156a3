"""Reading a chunk's points: COPC spatial queries, or a plain LAS/LAZ file's per-chunk bins.

A plain LAZ file has no spatial index, so reading a chunk from it means decompressing all of
it; with 250 m chunks over 500 m tiles every tile would be decompressed nine times. The
``index`` stage therefore streams each plain file once and writes its points into one record
file per chunk (a sidecar index, as ``lasindex``/``lastile`` prepare a survey), uncompressed,
so a chunk and its buffer are read with a memory map and a bounds filter. COPC files are read
directly by ``laspy.CopcReader`` queries of the buffered bounds.

Record files hold numpy structured records (``x``, ``y``, ``z`` float64 and every attribute
of the cloud) with their dtype in ``schema.json`` beside them. Memory per read is the chunk
and its buffer, never the survey.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud, concatenate
from workstation.core.errors import InvalidInputError

SCHEMA = "schema.json"


def record_dtype(cloud: Cloud) -> np.dtype:
    """The structured dtype holding ``cloud``'s coordinates and attributes."""
    fields = [("x", "<f8"), ("y", "<f8"), ("z", "<f8")]
    for k, v in cloud.attrs.items():
        fields.append((k, v.dtype.str, v.shape[1:]) if v.ndim > 1 else (k, v.dtype.str))
    return np.dtype(fields)


def to_records(cloud: Cloud, dtype: np.dtype | None = None) -> np.ndarray:
    rec = np.empty(cloud.n, dtype or record_dtype(cloud))
    rec["x"], rec["y"], rec["z"] = cloud.xyz[:, 0], cloud.xyz[:, 1], cloud.xyz[:, 2]
    for k in rec.dtype.names[3:]:
        rec[k] = cloud.attrs[k]
    return rec


def from_records(rec: np.ndarray, crs=None, meta=None) -> Cloud:
    xyz = np.column_stack([rec["x"], rec["y"], rec["z"]])
    attrs = {k: np.ascontiguousarray(rec[k]) for k in rec.dtype.names[3:]}
    return Cloud.from_owned_arrays(xyz, attrs, crs=crs, meta=meta or {})


def _dtype_to_json(dt: np.dtype) -> list:
    return [[name, dt.fields[name][0].base.str, list(dt.fields[name][0].shape)] for name in dt.names]


def _dtype_from_json(items) -> np.dtype:
    return np.dtype([(n, s, tuple(shape)) if shape else (n, s) for n, s, shape in items])


def write_schema(folder: Path, dtype: np.dtype, crs, meta) -> None:
    (folder / SCHEMA).write_text(json.dumps({"dtype": _dtype_to_json(dtype), "crs": crs, "meta": meta}))


def read_schema(folder: Path) -> tuple[np.dtype, str | None, dict]:
    doc = json.loads((folder / SCHEMA).read_text())
    return _dtype_from_json(doc["dtype"]), doc["crs"], doc["meta"]


def _jsonable_meta(meta: dict) -> dict:
    """The cloud's IO meta with bytes made hex, so it survives ``schema.json``."""
    def conv(v):
        if isinstance(v, bytes):
            return {"__bytes__": v.hex()}
        if isinstance(v, dict):
            return {k: conv(x) for k, x in v.items()}
        if isinstance(v, (list, tuple)):
            return [conv(x) for x in v]
        return v
    return conv(dict(meta))


def restore_meta(meta: dict) -> dict:
    def conv(v):
        if isinstance(v, dict):
            return bytes.fromhex(v["__bytes__"]) if set(v) == {"__bytes__"} else {k: conv(x) for k, x in v.items()}
        if isinstance(v, list):
            return [conv(x) for x in v]
        return v
    return conv(meta)


def index_file(path: Path, size: float, dest: Path, crs: str | None, chunk_points: int = 2_000_000,
               start: int = 0, stop: int | None = None) -> dict:
    """Stream ``path`` (its points ``start:stop``) once and write them into ``dest/<ix>_<iy>.bin``
    by owning chunk (chunks of ``size`` CRS units). The folder is built beside ``dest`` and
    renamed into place, so an interrupted index leaves nothing. Returns {"ix_iy": points}."""
    from workstation.io import iter_chunks

    dest.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{dest.name}.", dir=dest.parent))
    counts: dict[str, int] = {}
    dtype = None
    try:
        for piece in iter_chunks(path, chunk_points, start=start, stop=stop):
            if dtype is None:
                dtype = record_dtype(piece)
                write_schema(tmp, dtype, piece.crs or crs, _jsonable_meta(piece.meta))
            rec = to_records(piece, dtype)
            ix = np.floor(rec["x"] / size).astype(np.int64)
            iy = np.floor(rec["y"] / size).astype(np.int64)
            key = (ix - ix.min()) * (int(iy.max() - iy.min()) + 1) + (iy - iy.min())
            order = np.argsort(key, kind="stable")
            bounds = np.flatnonzero(np.diff(key[order])) + 1
            for part in np.split(order, bounds):
                name = f"{ix[part[0]]}_{iy[part[0]]}"
                with open(tmp / f"{name}.bin", "ab") as f:
                    rec[part].tofile(f)
                counts[name] = counts.get(name, 0) + len(part)
        if dtype is None:  # an empty file
            write_schema(tmp, np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8")]), crs, {})
        (tmp / "counts.json").write_text(json.dumps(counts))
        if dest.exists():
            shutil.rmtree(dest)
        os.replace(tmp, dest)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
    return counts


def in_box(x, y, box) -> np.ndarray:
    """Which points lie in ``box`` (xmin, ymin, xmax, ymax), half-open like chunk cores."""
    return (x >= box[0]) & (x < box[2]) & (y >= box[1]) & (y < box[3])


def read_bins(folder: Path, names, box) -> Cloud | None:
    """The points of the record files ``folder/<name>.bin`` inside ``box`` (xmin, ymin, xmax,
    ymax; half-open), as one cloud; None when there are none."""
    dtype, crs, meta = read_schema(folder)
    rec = read_records([folder / f"{name}.bin" for name in names], dtype, box)
    return None if rec is None else from_records(rec, crs, restore_meta(meta))


def read_records(files, dtype: np.dtype, box) -> np.ndarray | None:
    """The records of ``files`` (those that exist) inside ``box``, memory-mapped and filtered
    one file at a time; None when there are none."""
    parts = []
    for f in files:
        if not f.exists() or f.stat().st_size == 0:
            continue
        rec = np.memmap(f, dtype=dtype, mode="r")
        keep = in_box(rec["x"], rec["y"], box)
        if keep.any():
            parts.append(np.asarray(rec[keep]))
        del rec
    return np.concatenate(parts) if parts else None


def read_copc(path: Path, box) -> Cloud | None:
    """The points of a COPC file inside ``box`` (half-open, like chunk cores) by a spatial
    query of its octree (:func:`workstation.io.copc.read`); None when there are none."""
    from workstation.io import copc

    cloud = copc.read(path, bounds=tuple(box))
    keep = in_box(cloud.xyz[:, 0], cloud.xyz[:, 1], box)
    return cloud[keep] if keep.any() else None


def join(parts: list, crs) -> Cloud | None:
    """Concatenate clouds from several files; the first one's IO meta is kept for writing."""
    parts = [p for p in parts if p is not None and p.n]
    if not parts:
        return None
    out = parts[0] if len(parts) == 1 else concatenate(parts, check_crs=False)
    return out.with_crs(out.crs or crs)
