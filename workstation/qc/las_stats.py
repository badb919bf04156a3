"""The statistics of ``ws info`` taken straight from LAS/LAZ point records.

The file is decoded chunk by chunk (laspy with lazrs, as :func:`laspy.read` decodes it) and
every figure is computed on the raw records, without building a :class:`Cloud`: no float64
copy of any dimension except the plan coordinates the density needs. Each decoded chunk is
cut into cache-sized slices spread over the cores (numpy releases the GIL); per slice:

- the minimum and maximum of every plain record field (integers as stored);
- a 256-bin histogram of every byte that packs bit fields (return number and count,
  classification and flags), from which the minimum and maximum of each bit field, the
  class histogram and the return histogram follow;
- x and y as the reader computes them, their packed density-cell keys (sorted, unique) and
  the points that may be vertices of the convex hull.

Scaling a record into the reader's attributes (scale and offset, the scan angle unit, a
widening cast) is monotonic, so the extremes of the converted values are the converted
extremes: two records holding the minima and the maxima go through the reader's own
conversion (:class:`workstation.io.las.Filler`), which gives the same numbers, dtypes and
attribute names as reading the whole file.
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from contextlib import nullcontext
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path

import numpy as np

from workstation.core.cpu import available_cores

from .density import DensityAccumulator, hull_candidates, outside_octagon, sorted_unique


@dataclass
class LasStats:
    """What :func:`las_statistics` gathers: the point ``count``; per-column ``lo``/``hi`` of the
    coordinates (CRS units) and ``ranges`` ({attribute: (lo, hi)}) and ``dtypes`` of the
    attributes, as a full read gives them; the histogram of ``classes`` (256 codes); the
    ``returns`` counts by ``"return/number"``; ``crs`` and ``meta`` of the reader."""

    count: int = 0
    lo: np.ndarray | None = None
    hi: np.ndarray | None = None
    ranges: dict = field(default_factory=dict)
    dtypes: dict = field(default_factory=dict)
    classes: np.ndarray = field(default_factory=lambda: np.zeros(256, dtype=np.int64))
    returns: dict = field(default_factory=dict)
    crs: str | None = None
    meta: dict = field(default_factory=dict)


class _Layout:
    """How the fields of a point format's records are summarised: ``plain`` fields by min and
    max (``floats`` among them NaN-ignoring), ``packed`` bytes by a histogram, with their bit
    fields ``bits`` ({byte: [(name, mask, shift)]})."""

    def __init__(self, point_format):
        from laspy.point.dims import COMPOSED_FIELDS

        dtype = point_format.dtype()
        self.dtype = dtype
        self.bits = {
            byte: [(sf.name, sf.mask, (sf.mask & -sf.mask).bit_length() - 1) for sf in subs]
            for byte, subs in COMPOSED_FIELDS[point_format.id].items() if byte in dtype.names
        }
        self.packed = list(self.bits)
        if "classification" in dtype.names and "classification" not in self.bits:
            self.packed.append("classification")  # a whole byte (formats 6-10): a histogram too
        self.plain = [n for n in dtype.names if n not in self.bits]
        self.floats = {n for n in self.plain if dtype[n].base.kind == "f"}

    def bit_field(self, name: str):
        """(byte, mask, shift) of the bit field ``name``, or None for a plain field."""
        for byte, subs in self.bits.items():
            for sub, mask, shift in subs:
                if sub == name:
                    return byte, mask, shift
        return None


def _reduce(a: np.ndarray, is_float: bool, lo: bool):
    """Minimum (``lo``) or maximum of ``a`` along its first axis; NaN ignored for floats
    (NaN only when every value is NaN, without a warning)."""
    if is_float:
        return (np.fmin if lo else np.fmax).reduce(a, axis=0)
    return (np.minimum if lo else np.maximum).reduce(a, axis=0)


def _slice_stats(a: np.ndarray, lay: _Layout, xy_conv, acc: DensityAccumulator | None, cells: bool) -> dict:
    """The figures of one slice ``a`` of raw records: extremes of the plain fields, histograms
    of the packed bytes and, with ``acc``, the hull candidates and sorted unique cell keys of
    its plan coordinates (``xy_conv``: the reader's scales and offsets of X and Y)."""
    out = {
        "lo": [_reduce(a[n], n in lay.floats, True) for n in lay.plain],
        "hi": [_reduce(a[n], n in lay.floats, False) for n in lay.plain],
        "hist": [np.bincount(a[n], minlength=256) for n in lay.packed],
    }
    if acc is not None:
        (sx, sy), (ox, oy) = xy_conv
        x = a["X"] * sx
        x += ox
        y = a["Y"] * sy
        y += oy
        mask = outside_octagon(x, y) if len(x) >= 64 else np.ones(len(x), dtype=bool)
        out["hull"] = np.column_stack([x[mask], y[mask]])
        out["keys"] = sorted_unique(acc.cell_keys(x, y)) if cells else None
    return out


def _fold_range(stats: dict, key: str, chunk_lo, chunk_hi) -> None:
    """Fold one chunk's extremes into ``stats[key]`` (NaN, once met, stays: as np.minimum)."""
    if key not in stats:
        stats[key] = (chunk_lo, chunk_hi)
    else:
        lo, hi = stats[key]
        stats[key] = (np.minimum(lo, chunk_lo), np.maximum(hi, chunk_hi))


def las_statistics(path, chunk_size: int, density=None, slice_size: int | None = None) -> LasStats:
    """Stream the LAS/LAZ file ``path`` in chunks of ``chunk_size`` records and gather
    :class:`LasStats`, feeding ``density``: a :class:`DensityAccumulator`, or a function of
    the CRS that makes one (called once the first points are read), or None (no density).
    Each chunk is cut into slices of ``slice_size`` records (default
    :data:`workstation.io.las.FILL_SLICE`, a few MB of records) spread over the cores.

    Raises InvalidInputError as the reader does (bad header, truncated or corrupt data)."""
    from workstation.io.las import FILL_SLICE, check_point_bytes, meta_and_crs, raw_records, open_las

    path = Path(path)
    st = LasStats()
    with open_las(path) as reader:
        header = reader.header
        check_point_bytes(path, header)
        n = int(header.point_count)
        lay = _Layout(header.point_format)
        raw: dict = {}
        xy_conv = (np.asarray(header.scales[:2], np.float64), np.asarray(header.offsets[:2], np.float64))
        cores = available_cores()
        pool = ThreadPoolExecutor(max_workers=min(cores, 4), thread_name_prefix="las-stats") if cores > 1 else None
        with pool or nullcontext():
            for rec in raw_records(reader, path, n, chunk_size):
                if st.count == 0:
                    st.meta, st.crs = meta_and_crs(header, path)
                    st.meta["las"]["crs"] = st.crs
                    density = density(st.crs) if callable(density) else density
                    warn_crs(path, header, rec, st.crs, st.meta)
                _chunk(rec.array, lay, raw, xy_conv, density, pool, slice_size or FILL_SLICE)
                st.count += len(rec)
    if st.count:
        _convert_extremes(header, lay, raw, st)
    return st


def _chunk(arr: np.ndarray, lay: _Layout, raw: dict, xy_conv, acc, pool, size: int) -> None:
    """Fold one decoded chunk of raw records ``arr`` in: extremes into ``raw`` ({field:
    (lo, hi)}), histograms into ``raw`` (``"#byte"``: counts), density into ``acc``."""
    cells = False
    if acc is not None:
        sc, of = xy_conv
        lo = [arr[c].min() * sc[i] + of[i] for i, c in enumerate("XY")]
        hi = [arr[c].max() * sc[i] + of[i] for i, c in enumerate("XY")]
        cells = acc.start(np.minimum(lo, hi), np.maximum(lo, hi))
    slices = [arr[s : s + size] for s in range(0, len(arr), size)]
    job = partial(_slice_stats, lay=lay, xy_conv=xy_conv, acc=acc, cells=cells)
    parts = list(pool.map(job, slices)) if pool is not None and len(slices) > 1 else [job(a) for a in slices]
    for k, name in enumerate(lay.plain):
        los = np.array([p["lo"][k] for p in parts])
        his = np.array([p["hi"][k] for p in parts])
        if name in lay.floats:  # as np.nanmin over the chunk: warns when the chunk is all NaN
            _fold_range(raw, name, np.nanmin(los, axis=0), np.nanmax(his, axis=0))
        else:
            _fold_range(raw, name, los.min(axis=0), his.max(axis=0))
    for k, name in enumerate(lay.packed):
        h = sum(p["hist"][k] for p in parts)
        raw["#" + name] = raw["#" + name] + h if "#" + name in raw else h
    if acc is not None:
        cands = hull_candidates(np.concatenate([p["hull"] for p in parts]))
        # sorted runs, one a slice: the stable sort (timsort) merges them
        keys = sorted_unique(np.concatenate([p["keys"] for p in parts]), kind="stable") if cells else None
        acc.merge(len(arr), cands, keys)


def warn_crs(path: Path, header, rec, crs, meta) -> None:
    """The reader's once-per-file warning when the CRS does not fit the coordinates
    (:func:`workstation.io.registry.warn_crs`), given the first point as a cloud."""
    from workstation.core.cloud import Cloud
    from workstation.io.las import Filler
    from workstation.io.registry import warn_crs as warn

    f = Filler(header, 1)
    f.fill(rec[:1], 0)
    warn(path, Cloud.from_owned_arrays(f.xyz, f.attrs, crs=crs, meta=meta))


def _bit_extremes(lay: _Layout, raw: dict) -> np.ndarray:
    """Two records of ``lay.dtype``: the minima and the maxima of every field (bit fields
    each at its own extreme, read from its byte's histogram)."""
    rows = np.zeros(2, lay.dtype)
    for name in lay.plain:
        rows[name][0], rows[name][1] = raw[name]
    for byte, subs in lay.bits.items():
        values = np.flatnonzero(raw["#" + byte])
        lo = hi = 0
        for _, mask, shift in subs:
            v = (values & mask) >> shift
            lo |= int(v.min()) << shift
            hi |= int(v.max()) << shift
        rows[byte][0], rows[byte][1] = lo, hi
    return rows


def _histograms(lay: _Layout, raw: dict, st: LasStats) -> None:
    """The class histogram and the return counts from the byte histograms."""
    codes = np.arange(256)
    where = lay.bit_field("classification")
    if where is None:
        st.classes += raw["#classification"]
    else:
        byte, mask, shift = where
        np.add.at(st.classes, (codes & mask) >> shift, raw["#" + byte])
    rn, nr = lay.bit_field("return_number"), lay.bit_field("number_of_returns")
    if rn is None or nr is None or rn[0] != nr[0]:
        return
    hist = raw["#" + rn[0]]
    for v in np.flatnonzero(hist).tolist():
        key = f"{(v & rn[1]) >> rn[2]}/{(v & nr[1]) >> nr[2]}"
        st.returns[key] = st.returns.get(key, 0) + int(hist[v])


def _convert_extremes(header, lay: _Layout, raw: dict, st: LasStats) -> None:
    """Fill ``st`` from the raw extremes and histograms: the extreme records go through the
    reader's conversion, so the coordinates and attributes get its values, names and dtypes."""
    import laspy

    from workstation.io.las import Filler

    rec = laspy.ScaleAwarePointRecord(_bit_extremes(lay, raw), header.point_format, header.scales, header.offsets)
    f = Filler(header, 2)
    f.fill(rec, 0)
    st.lo, st.hi = np.minimum(f.xyz[0], f.xyz[1]), np.maximum(f.xyz[0], f.xyz[1])
    for name, arr in f.attrs.items():
        st.ranges[name] = (np.minimum(arr[0], arr[1]), np.maximum(arr[0], arr[1]))
        st.dtypes[name] = str(arr.dtype) + ("" if arr.ndim == 1 else f"x{arr.shape[1]}")
    _histograms(lay, raw, st)
