"""LAS / LAZ 1.0-1.4, point formats 0-10, through laspy (+ lazrs for LAZ).

Reading streams the file in chunks into preallocated arrays, so peak memory is the output
arrays plus one chunk. Every standard dimension becomes a canonical attribute (see
:mod:`workstation.core.dims`), extra-byte dimensions keep their own names (scaled values when
the extra-byte definition has scales), and everything needed to write the same file again
(version, point format, scales, offsets, VLRs, EVLRs, extra-byte definitions, header fields)
goes into ``Cloud.meta["las"]`` so that read -> write -> read is exact.

Known upstream limitation: lazrs 0.8 corrupts wave-packet fields of LAZ point formats 9 and
10 when the scanner channel changes from one point to the next (plain LAS is exact).

Writing chooses the point format and version from the attributes present unless told, or
keeps the ones the cloud was read with when its attributes still fit.

Reading refuses a bad header before laspy trusts it: an unknown point format, a zero or
non-finite scale, a non-finite offset, or a point count that disagrees with the data (the
bytes present for LAS; the LAZ chunk table, exact for point formats 6-10, whose chunks
store their counts, and for variable-size chunks; for formats 0-5 with fixed-size chunks a
count within the last chunk cannot be checked without decoding it).
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path
from typing import Iterator

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.cpu import available_cores
from workstation.core.dims import DIMS, LAS_FLAGS
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

log = get_logger(__name__)

CHUNK_LAS = 262_144  # uncompressed: small enough that per-field copies stay in cache
CHUNK_LAZ = 1_048_576  # compressed: large enough for lazrs to decompress chunks in parallel
FILL_SLICE = 131_072  # points per field-copy job: a few MB of records, copied out of cache
SCAN_ANGLE_UNIT = 0.006  # degrees per unit of the LAS 1.4 (formats 6-10) scan angle
_DEFAULT_SCALE = 0.001  # metres (or feet) for projected CRSs
_GEOGRAPHIC_SCALE = 1e-7  # degrees

# LAS dimension name -> canonical attribute name (per-point scalar dims only; rgb handled apart)
_LAS_TO_ATTR = {d.las[0]: d.name for d in DIMS.values() if len(d.las) == 1}
_LAS_TO_ATTR["scan_angle_rank"] = "scan_angle"
_SKIP = {"X", "Y", "Z", "red", "green", "blue"}

# Standard dims each point format carries, as canonical names.
_RGB_FORMATS = {2, 3, 5, 7, 8, 10}
_GPS_FORMATS = {1, 3, 4, 5, 6, 7, 8, 9, 10}
_NIR_FORMATS = {8, 10}
_WAVE_FORMATS = {4, 5, 9, 10}
_WAVE_ATTRS = ("wavepacket_index", "wavepacket_offset", "wavepacket_size", "return_point_wave_location", "x_t", "y_t", "z_t")


def _laspy():
    import laspy

    return laspy


def _format_attrs(fmt: int) -> set[str]:
    """Canonical attribute names a point format stores natively."""
    names = {
        "intensity", "return_number", "number_of_returns", "scan_direction_flag", "edge_of_flight_line",
        "classification", "synthetic", "key_point", "withheld", "scan_angle", "user_data", "point_source_id",
    }
    if fmt >= 6:
        names |= {"overlap", "scanner_channel"}
    if fmt in _GPS_FORMATS:
        names.add("gps_time")
    if fmt in _RGB_FORMATS:
        names.add("rgb")
    if fmt in _NIR_FORMATS:
        names.add("nir")
    if fmt in _WAVE_FORMATS:
        names |= set(_WAVE_ATTRS)
    return names


def choose_point_format(attrs, legacy: bool = False) -> int:
    """Smallest point format that stores the attributes natively.

    LAS 1.4 formats (6-10) unless ``legacy`` (then 0-5 for LAS 1.2/1.3 readers).

    Examples
    --------
    >>> choose_point_format({"intensity"}), choose_point_format({"rgb"}), choose_point_format({"rgb", "nir"})
    (6, 7, 8)
    >>> choose_point_format({"gps_time", "rgb"}, legacy=True)
    3
    """
    attrs = set(attrs)
    wave = bool(attrs & set(_WAVE_ATTRS))
    if legacy and not attrs & {"nir", "overlap", "scanner_channel"}:
        rgb, gps = "rgb" in attrs, "gps_time" in attrs
        if wave:
            return 5 if rgb else 4
        return {(False, False): 0, (False, True): 1, (True, False): 2, (True, True): 3}[(rgb, gps)]
    if wave:
        return 10 if attrs & {"rgb", "nir"} else 9
    if "nir" in attrs:
        return 8
    return 7 if "rgb" in attrs else 6


def _version_for(fmt: int, wanted) -> str:
    """The LAS version to write: ``wanted`` ("1.1"-"1.4"), raised to what ``fmt`` needs."""
    minimum = "1.4" if fmt >= 6 else ("1.3" if fmt in (4, 5) else ("1.2" if fmt in (2, 3) else "1.1"))
    if wanted is not None:
        text = f"{wanted:.1f}" if isinstance(wanted, float) else str(wanted).strip()
        if text not in _WRITE_VERSIONS:
            raise InvalidInputError(
                f"LAS version {text} cannot be written",
                f"use one of {', '.join(_WRITE_VERSIONS)} (1.1 has the layout of 1.0 for point formats 0 and 1)",
                field="version",
            )
        wanted = text
    if wanted is None:
        return "1.4" if fmt >= 6 else max(minimum, "1.2")
    if wanted < minimum:
        return minimum
    return wanted


# ---------------------------------------------------------------------------------------
# reading


def wrap_open_error(path, exc) -> InvalidInputError:
    text = str(exc) or type(exc).__name__
    if "signature" in text.lower() or "LASF" in text:
        return InvalidInputError(
            "not a LAS/LAZ file (the first 4 bytes are not 'LASF')", "check that the file is LAS or LAZ and not renamed", path=path
        )
    if type(exc).__name__ == "FileVersionNotSupported":
        return InvalidInputError(f"LAS version {text} is not supported", f"readable versions: {', '.join(_READ_VERSIONS)}",
                                 path=path, field="version")
    return InvalidInputError(f"cannot read the LAS header: {text}", "the file may be truncated or corrupt", path=path)


_HEADER_MIN = 227  # bytes of the LAS 1.0-1.2 public header, the fields every version has
_READ_VERSIONS = ("1.0", "1.1", "1.2", "1.3", "1.4")
_WRITE_VERSIONS = ("1.1", "1.2", "1.3", "1.4")


def check_raw_header(path: Path) -> None:
    """Check the header fields laspy trusts blindly, from the raw bytes, before laspy opens the file.

    The point data record format (byte 104, its two high bits are LAZ compression flags)
    must be 0-10; the x/y/z scale factors (bytes 131-154) finite and non-zero and the
    offsets (bytes 155-178) finite, else every coordinate would collapse or become NaN.
    """
    try:
        with open(path, "rb") as f:
            head = f.read(_HEADER_MIN)
    except OSError as exc:
        raise InvalidInputError(f"cannot open: {exc.strerror or exc}", "check the path and its permissions", path=path) from None
    if head[:4] != b"LASF":
        raise wrap_open_error(path, ValueError("signature"))
    if len(head) < _HEADER_MIN:
        raise InvalidInputError(f"file of {len(head)} bytes is too small to hold a LAS header ({_HEADER_MIN}+ bytes)",
                                "the file is truncated; get a complete copy", path=path, field="header")
    if head[104] & 0x3F > 10:
        raise InvalidInputError(f"point data record format {head[104] & 0x7F} is unknown (valid formats: 0-10)",
                                "the header is corrupt or the file is not LAS/LAZ", path=path, field="point_format")
    values = np.frombuffer(head, dtype="<f8", count=6, offset=131)
    with np.errstate(over="ignore", invalid="ignore"):
        reach = 2.0**31 * np.abs(values[:3]) + np.abs(values[3:])  # largest |coordinate| the fields allow
    for kind, vals in (("scale", values[:3]), ("offset", values[3:])):
        bad = ~np.isfinite(vals)
        if kind == "scale":
            bad |= (vals == 0) | (~np.isfinite(reach) & np.isfinite(values[3:]))
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            what = "all collapse to the offset" if vals[i] == 0 else "not be finite"
            if np.isfinite(vals[i]) and vals[i] != 0:
                what = "overflow to infinity"
            raise InvalidInputError(
                f"the {'xyz'[i]} {kind} is {float(vals[i])}; every {'xyz'[i]} coordinate would {what}",
                "the header is corrupt; repair the scale/offset fields with a LAS tool", path=path, field=f"{'xyz'[i]}_{kind}",
            )


def check_point_bytes(path: Path, header) -> None:
    """Compare the header's point count with the points present (bytes for LAS, the chunk table for LAZ)."""
    if header.are_points_compressed:
        _check_laz_count(path, header)
        return
    size = path.stat().st_size
    rl = header.point_format.size
    end = size
    if header.version.minor >= 4 and getattr(header, "number_of_evlrs", 0) and header.start_of_first_evlr:
        end = min(size, header.start_of_first_evlr)
    available = max(0, end - header.offset_to_point_data) // rl
    _count_error(path, header.point_count, available, available)


def _count_error(path: Path, n: int, lo: int, hi: int) -> None:
    """Raise when the header count ``n`` is outside the ``lo..hi`` points the file holds."""
    if lo <= n <= hi:
        return
    available = lo if n < lo else hi
    if available < n:
        raise InvalidInputError(
            f"header says {n:,} points but the file holds only {available:,} (truncated)",
            "get a complete copy of the file",
            path=path,
            field="point_count",
        )
    if available > n:
        raise InvalidInputError(
            f"header says {n:,} points but the file holds {available:,}",
            "the header is inconsistent; repair it (e.g. rewrite the file with a LAS tool) so no points are lost",
            path=path,
            field="point_count",
        )


def laz_chunk_counts(path: Path, header):
    """(chunk point counts, whether the last count is exact) from the LAZ chunk table, or None.

    Variable-size chunk tables store every count. Fixed-size tables store the chunk size
    only, but a layered chunk (point formats 6-10) starts with its first point stored raw
    followed by the number of points in the chunk (u32), so its count is read there.
    None when the file has no chunk table (a streaming writer); decoding then checks the count.
    """
    import lazrs

    vlr = next((v for v in header.vlrs if v.user_id == "laszip encoded"), None)
    if vlr is None:
        return None
    try:
        laz_vlr = lazrs.LazVlr(vlr.record_data_bytes())
        with open(path, "rb") as f:
            f.seek(header.offset_to_point_data)
            table = lazrs.read_chunk_table(f, laz_vlr)
    except Exception:  # noqa: BLE001 - no (readable) chunk table
        return None
    counts = [int(c) for c, _ in table]
    if laz_vlr.uses_variable_size_chunks() or not counts:
        return counts, True
    if header.point_format.id < 6:
        return counts, False
    start = header.offset_to_point_data + 8 + sum(int(b) for _, b in table[:-1])
    with open(path, "rb") as f:
        f.seek(start + header.point_format.size)
        raw = f.read(4)
    if len(raw) < 4:
        return counts, False
    counts[-1] = int.from_bytes(raw, "little")
    return counts, True


def _check_laz_count(path: Path, header) -> None:
    """Compare the header's point count with the LAZ chunk table (exact for formats 6-10 and
    variable-size chunks; within the last chunk's size for fixed-size chunks of formats 0-5)."""
    found = laz_chunk_counts(path, header)
    if found is None:
        return
    counts, exact = found
    total = sum(counts)
    lo = total if exact else total - counts[-1] + 1
    _count_error(path, int(header.point_count), lo, total)


def vlr_records(vlrs) -> list[dict]:
    """The (E)VLRs to keep for writing back, as plain records. The COPC info VLR and hierarchy
    EVLR are left out without a word: they index this file's bytes and would be false in any
    file written from the points (a COPC file written as LAZ is plain LAZ)."""
    from .copc import is_copc_vlr

    out = []
    for v in vlrs:
        if is_copc_vlr(v.user_id, v.record_id):
            continue
        try:
            data = v.record_data_bytes() if hasattr(v, "record_data_bytes") else bytes(v.record_data)
        except Exception:  # a VLR laspy cannot serialise back: keep nothing rather than garbage
            log.warning("VLR %s/%s could not be kept", v.user_id, v.record_id)
            continue
        out.append({"user_id": v.user_id, "record_id": int(v.record_id), "description": v.description, "data": data})
    return out


def crs_string(header, path, identify: bool = True) -> str | None:
    """The file's CRS as "EPSG:code" when it is one, else WKT; None without one.

    ``identify``: a WKT without an EPSG identifier is searched for in PROJ's database (about
    0.5 s, cached per WKT); with False only a stated identifier counts (header summaries)."""
    try:
        crs = header.parse_crs()
    except Exception as exc:  # malformed CRS records: keep the points, say so
        log.warning("%s: CRS records could not be parsed (%s); CRS left unset", path, exc)
        return None
    if crs is None:
        return None
    from workstation.io.crs import apply_unit_geokeys

    fixed = apply_unit_geokeys(crs, header.vlrs)  # ProjLinearUnits/VerticalUnits GeoKeys (laspy ignores them)
    if fixed is not crs:  # units overridden: no EPSG code says that (skip PROJ's slow search)
        return fixed.to_wkt()
    wkt = crs.to_wkt()
    from workstation.io.crs import stated_epsg

    epsg = stated_epsg(crs) or (_exact_epsg(wkt) if identify else None)
    return f"EPSG:{epsg}" if epsg else wkt


@lru_cache(maxsize=64)
def _exact_epsg(wkt: str) -> int | None:
    """The EPSG code PROJ finds equal to ``wkt`` (confidence 100), once per WKT."""
    import pyproj

    return pyproj.CRS.from_wkt(wkt).to_epsg(min_confidence=100)


def _extra_defs(header) -> list[dict]:
    defs = []
    for d in header.point_format.extra_dimensions:
        dt = d.dtype
        base = dt.base if dt.shape else dt
        defs.append(
            {
                "name": d.name,
                "type": (f"{dt.shape[0]}{base.str[1:]}" if dt.shape else base.str[1:]),
                "description": d.description or "",
                "scales": None if d.scales is None else np.asarray(d.scales, dtype=float).tolist(),
                "offsets": None if d.offsets is None else np.asarray(d.offsets, dtype=float).tolist(),
                "no_data": None if getattr(d, "no_data", None) is None else np.asarray(d.no_data).tolist(),
            }
        )
    return defs


def _header_meta(header, path) -> dict:
    return {
        "version": str(header.version),
        "point_format": int(header.point_format.id),
        "scales": [float(s) for s in header.scales],
        "offsets": [float(o) for o in header.offsets],
        "vlrs": vlr_records([v for v in header.vlrs if not _is_managed_vlr(v)]),
        "extra_dims": _extra_defs(header),
        "system_identifier": header.system_identifier,
        "generating_software": header.generating_software,
        "file_source_id": int(header.file_source_id),
        "creation_date": None if header.creation_date is None else header.creation_date.isoformat(),
        "global_encoding_gps_standard": bool(header.global_encoding.gps_time_type.value),
        "compressed": bool(header.are_points_compressed),
        "header_point_count": int(header.point_count),
    }


def _is_managed_vlr(v) -> bool:
    """VLRs laspy writes itself (extra bytes, LASzip)."""
    return (v.user_id == "LASF_Spec" and v.record_id == 4) or v.user_id == "laszip encoded"


def _is_crs_vlr(rec: dict) -> bool:
    return rec["user_id"] == "LASF_Projection" and rec["record_id"] in (34735, 34736, 34737, 2111, 2112)


class Filler:
    """Preallocated output arrays filled chunk by chunk."""

    def __init__(self, header, n: int):
        pf = header.point_format
        self.fmt = pf.id
        self.scales = np.asarray(header.scales, dtype=np.float64)
        self.offsets = np.asarray(header.offsets, dtype=np.float64)
        self.xyz = np.empty((n, 3), dtype=np.float64)
        self.attrs: dict[str, np.ndarray] = {}
        self.std = []
        for name in pf.standard_dimension_names:
            if name in _SKIP:
                continue
            canon = _LAS_TO_ATTR.get(name, name)
            dt = DIMS[canon].dtype if canon in DIMS else np.dtype("f8")
            self.attrs[canon] = np.empty(n, dtype=dt)
            self.std.append((name, canon))
        self.has_rgb = "red" in set(pf.standard_dimension_names)
        if self.has_rgb:
            self.attrs["rgb"] = np.empty((n, 3), dtype=np.uint16)
        self.extra = []
        for d in pf.extra_dimensions:
            scaled = d.scales is not None
            dt = d.dtype
            shape = dt.shape
            base = np.dtype("f8") if scaled else (dt.base if shape else dt)
            key = d.name
            if key in self.attrs or (key in DIMS and (DIMS[key].dtype, DIMS[key].shape) != (base, shape)):
                # a standard name already read, or a canonical name whose table dtype/shape
                # this extra-byte dimension does not have: keep it under a free name
                key = f"extra_{d.name}"
            self.attrs[key] = np.empty((n, *shape), dtype=base)
            self.extra.append((d.name, key, scaled))

    def fill(self, rec, start: int) -> int:
        arr = rec.array
        m = len(arr)
        end = start + m
        for i, c in enumerate("XYZ"):
            np.multiply(arr[c], self.scales[i], out=self.xyz[start:end, i])
            self.xyz[start:end, i] += self.offsets[i]
        for las_name, canon in self.std:
            out = self.attrs[canon][start:end]
            if las_name == "scan_angle":
                np.multiply(arr["scan_angle"], SCAN_ANGLE_UNIT, out=out, casting="unsafe")
            else:
                out[...] = rec[las_name]
        if self.has_rgb:
            rgb = self.attrs["rgb"]
            rgb[start:end, 0] = arr["red"]
            rgb[start:end, 1] = arr["green"]
            rgb[start:end, 2] = arr["blue"]
        for las_name, key, scaled in self.extra:
            self.attrs[key][start:end] = rec[las_name] if scaled else arr[las_name]
        return end


def _allocate(path: Path, header, n: int) -> Filler:
    """The output arrays for ``n`` points (a count already checked against the file)."""
    try:
        return Filler(header, n)
    except MemoryError:
        raise InvalidInputError(f"not enough memory for the header's {n:,} points",
                                "read the file in chunks (iter_chunks) or on a larger machine", path=path,
                                field="point_count") from None


@contextmanager
def _fill_pool():
    """A thread pool for the field copies when more than one core is available, else None."""
    cores = available_cores()
    if cores < 2:
        yield None
        return
    with ThreadPoolExecutor(max_workers=min(cores, 4), thread_name_prefix="las-fill") as pool:
        yield pool


def open_las(path):
    """Open a LAS/LAZ reader; every header problem becomes an InvalidInputError naming the file."""
    laspy = _laspy()
    check_raw_header(path)
    try:
        return laspy.open(str(path))
    except Exception as exc:  # noqa: BLE001 - laspy raises many types (KeyError, struct.error ...) on corrupt headers
        raise wrap_open_error(path, exc) from None


def meta_and_crs(header, path):
    meta = {"las": _header_meta(header, path), "format": "laz" if header.are_points_compressed else "las"}
    return meta, crs_string(header, path)


def raw_records(reader, path, n: int, chunk_size: int):
    """Point records chunk by chunk; corrupt or truncated data becomes an InvalidInputError."""
    got = 0
    it = reader.chunk_iterator(chunk_size)
    while True:
        try:
            rec = next(it)
        except StopIteration:
            break
        except Exception as exc:
            raise InvalidInputError(
                f"point data unreadable after {got:,} of {n:,} points: {exc}",
                "the file is truncated or corrupt; get a complete copy",
                path=path,
            ) from None
        got += len(rec)
        if got > n:
            raise InvalidInputError(f"file holds more points than the header's {n:,}", path=path, field="point_count")
        yield rec
    if got != n:
        raise InvalidInputError(
            f"header says {n:,} points but only {got:,} could be read (truncated)",
            "get a complete copy of the file",
            path=path,
            field="point_count",
        )


def _range_records(reader, path, start: int, stop: int, chunk_size: int):
    """The point records ``start:stop``, chunk by chunk (see :func:`raw_records`)."""
    try:
        reader.seek(start)
        got = start
        while got < stop:
            rec = reader.read_points(min(chunk_size, stop - got))
            if len(rec) == 0:
                break
            got += len(rec)
            yield rec
    except Exception as exc:  # noqa: BLE001 - laspy/lazrs raise many types on corrupt data
        raise InvalidInputError(f"point data unreadable near point {got:,}: {exc}",
                                "the file is truncated or corrupt; get a complete copy", path=path) from None
    if got != stop:
        raise InvalidInputError(f"header says {stop:,} points or more but only {got:,} could be read (truncated)",
                                "get a complete copy of the file", path=path, field="point_count")


def bounds_mask(arr, header, bounds) -> np.ndarray:
    """Which records of ``arr`` (raw LAS records) lie inside ``bounds`` (xmin, ymin, xmax, ymax
    [, zmin, zmax]), by laspy's COPC rule: inclusive, on the integer coordinates the bounds
    round to, so a plain file and its COPC copy give the same points."""
    b = np.asarray(bounds, dtype=np.float64)
    dims = "XYZ"[: len(b) // 2]
    lo = np.round((b[[0, 1, 4][: len(dims)]] - header.offsets[: len(dims)]) / header.scales[: len(dims)])
    hi = np.round((b[[2, 3, 5][: len(dims)]] - header.offsets[: len(dims)]) / header.scales[: len(dims)])
    keep = np.ones(len(arr), dtype=bool)
    for i, c in enumerate(dims):
        keep &= (arr[c] >= lo[i]) & (arr[c] <= hi[i])
    return keep


def _read_inside(path: Path, bounds, chunk_size: int | None) -> Cloud:
    """The points inside ``bounds``: the file streamed chunk by chunk, each chunk's raw records
    filtered, only the kept records held (compact) until one final fill."""
    laspy = _laspy()
    with open_las(path) as reader:
        header = reader.header
        check_point_bytes(path, header)
        n = int(header.point_count)
        size = chunk_size or (CHUNK_LAZ if header.are_points_compressed else CHUNK_LAS)
        kept = [rec.array[bounds_mask(rec.array, header, bounds)] for rec in raw_records(reader, path, n, size)]
        meta, crs = meta_and_crs(header, path)
    arr = np.concatenate(kept) if kept else np.empty(0, header.point_format.dtype())
    rec = laspy.ScaleAwarePointRecord(arr, header.point_format, header.scales, header.offsets)
    filler = _allocate(path, header, len(arr))
    filler.fill(rec, 0)
    meta["las"]["crs"] = crs
    return Cloud.from_owned_arrays(filler.xyz, filler.attrs, crs=crs, meta=meta)


def read(path, *, chunk_size: int | None = None, bounds=None) -> Cloud:
    """Read a LAS or LAZ file.

    Parameters
    ----------
    path : path-like
    chunk_size : int, optional
        Points decoded per step; bounds the temporary memory (default 262,144 for LAS,
        1,048,576 for LAZ).
    bounds : (4,) or (6,) floats, optional
        Only the points inside (xmin, ymin, xmax, ymax[, zmin, zmax]), see :func:`bounds_mask`;
        the file is streamed, never held whole.

    Returns
    -------
    Cloud
        ``xyz`` absolute float64; attributes under canonical names; ``meta["las"]`` with
        everything needed to write the file back exactly.
    """
    path = Path(path)
    if bounds is not None:
        return _read_inside(path, bounds, chunk_size)
    with open_las(path) as reader:
        header = reader.header
        check_point_bytes(path, header)
        n = int(header.point_count)
        if chunk_size is None:
            chunk_size = CHUNK_LAZ if header.are_points_compressed else CHUNK_LAS
        filler = _allocate(path, header, n)
        got = 0
        with _fill_pool() as pool:
            for rec in raw_records(reader, path, n, chunk_size):
                # copy fields in cache-sized slices of a decoded chunk, the slices spread over
                # the cores (numpy releases the GIL while copying; lazrs holds it while decoding,
                # so the copy cannot overlap the decoding, only be shared out)
                m = len(rec)
                starts = range(0, m, FILL_SLICE)
                jobs = [(rec[a : a + FILL_SLICE] if m > FILL_SLICE else rec, got + a) for a in starts]
                if pool is None or len(jobs) == 1:
                    for sub, at in jobs:
                        filler.fill(sub, at)
                else:
                    list(pool.map(lambda job: filler.fill(*job), jobs))
                got += m
        meta, crs = meta_and_crs(header, path)
        if header.version.minor >= 4 and getattr(header, "number_of_evlrs", 0):
            evlrs = reader.evlrs if reader.evlrs is not None else []
            meta["las"]["evlrs"] = vlr_records(evlrs)
    meta["las"]["crs"] = crs
    return Cloud.from_owned_arrays(filler.xyz, filler.attrs, crs=crs, meta=meta)


def read_header(path) -> dict:
    """Header facts without reading points: version, format, count, bounds, CRS, dims."""
    path = Path(path)
    with open_las(path) as reader:
        h = reader.header
        return {
            "version": str(h.version),
            "point_format": int(h.point_format.id),
            "point_count": int(h.point_count),
            "mins": [float(v) for v in h.mins],
            "maxs": [float(v) for v in h.maxs],
            "scales": [float(v) for v in h.scales],
            "offsets": [float(v) for v in h.offsets],
            "compressed": bool(h.are_points_compressed),
            "crs": crs_string(h, path),
            "dimensions": list(h.point_format.dimension_names),
            "generating_software": h.generating_software,
            "system_identifier": h.system_identifier,
        }


def iter_chunks(path, chunk_size: int = 1_000_000, start: int = 0, stop: int | None = None,
                bounds=None) -> Iterator[Cloud]:
    """Stream a LAS/LAZ file as clouds of at most ``chunk_size`` points (memory: one chunk);
    with ``start``/``stop``, only the points of that index range (a LAZ file is sought to the
    compressed chunk that holds ``start``); with ``bounds``, only the points of each chunk
    inside them (:func:`bounds_mask`; a chunk may then be empty)."""
    path = Path(path)
    with open_las(path) as reader:
        header = reader.header
        check_point_bytes(path, header)
        meta, crs = meta_and_crs(header, path)
        meta["las"]["crs"] = crs
        n = int(header.point_count)
        stop = n if stop is None else min(int(stop), n)
        if start or stop < n:
            records = _range_records(reader, path, int(start), stop, chunk_size)
        else:
            records = raw_records(reader, path, n, chunk_size)
        for rec in records:
            if bounds is not None:
                rec = rec[bounds_mask(rec.array, header, bounds)]
            f = Filler(header, len(rec))
            f.fill(rec, 0)
            yield Cloud.from_owned_arrays(f.xyz, f.attrs, crs=crs, meta=meta)


# ---------------------------------------------------------------------------------------
# writing


def _is_geographic(crs: str | None) -> bool:
    if not crs:
        return False
    try:
        import pyproj

        return pyproj.CRS.from_user_input(crs).is_geographic
    except Exception:
        return False


_INT_LIMIT = 2**31 - 1  # LAS stores X, Y, Z as signed 32-bit integers


def _fits(xyz_min, xyz_max, scales, offsets) -> bool:
    lo = (xyz_min - offsets) / scales
    hi = (xyz_max - offsets) / scales
    return bool(np.all(lo >= -_INT_LIMIT) and np.all(hi <= _INT_LIMIT))


def _pow10_floor(v: float) -> float:
    """The largest power of ten <= ``v`` (``v`` > 0), as an exact decimal float (1e-9, 0.001 ...)."""
    return float(f"1e{int(np.floor(np.log10(v) + 1e-9))}")


def _metres_per_unit(crs: str | None) -> float:
    """Horizontal metres per CRS unit (111,320 for degrees; 1 when unknown)."""
    from workstation.io.crs import crs_info

    try:
        info = crs_info(crs)
    except InvalidInputError:
        return 1.0
    return 1.0 if info is None else float(info.metres_per_unit)


def auto_scales(crs: str | None, source_scales=None, source_crs: str | None = None) -> np.ndarray:
    """Scales (x, y, z) for writing coordinates in ``crs``, keeping the source's resolution.

    Without a source: 1e-7 degrees (about 1 cm) for a geographic CRS, else 0.001 units.
    With the ``source_scales`` of a file in ``source_crs``, the horizontal ground resolution
    ``s_xy * metres_per_unit(source)`` is carried over: into degrees at a tenth of it (so a
    projected -> geographic -> projected round trip stays far below the source's quantum:
    0.01 m -> 1e-9 degree), into projected units at the power of ten at or below it (1e-7
    degree -> 0.01 m; 1e-9 degree -> 0.0001 m); between projected CRSs of the same unit the
    scale is kept. The vertical scale is the source's (heights do not change with a
    horizontal reprojection).

    Examples
    --------
    >>> auto_scales("EPSG:4326").tolist(), auto_scales("EPSG:32632").tolist()
    ([1e-07, 1e-07, 0.001], [0.001, 0.001, 0.001])
    >>> auto_scales("EPSG:4326", [0.01, 0.01, 0.01], "EPSG:32632").tolist()
    [1e-09, 1e-09, 0.01]
    >>> auto_scales("EPSG:32632", [1e-7, 1e-7, 0.001], "EPSG:4326").tolist()
    [0.01, 0.01, 0.001]
    """
    geo = _is_geographic(crs)
    if source_scales is None:
        xy = _GEOGRAPHIC_SCALE if geo else _DEFAULT_SCALE
        return np.array([xy, xy, _DEFAULT_SCALE])
    s = np.asarray(source_scales, dtype=np.float64).reshape(3)
    src_unit, dst_unit = _metres_per_unit(source_crs), _metres_per_unit(crs)
    ground = float(min(s[0], s[1])) * src_unit  # metres of one horizontal step of the source
    if geo and not _is_geographic(source_crs):
        xy = _pow10_floor(ground / dst_unit / 10.0)
    elif geo or src_unit == dst_unit:
        xy = float(min(s[0], s[1]))
    else:
        xy = _pow10_floor(ground / dst_unit)
    return np.array([xy, xy, float(s[2])])


def auto_offsets(lo, hi, scales, crs: str | None = None) -> np.ndarray:
    """Offsets at the data's rounded centre: the centre of ``lo``..``hi`` rounded to a step
    that keeps every coordinate within the 32-bit range at ``scales`` (at most 1 degree for
    geographic x/y, 1000 units otherwise), so the integers stay small and the file reads
    naturally (offset -123, 44 for Oregon in degrees; 636000 for metres).

    Examples
    --------
    >>> auto_offsets([-123.07, 44.05, 406.0], [-123.06, 44.06, 520.0], [1e-9, 1e-9, 0.01], "EPSG:4326").tolist()
    [-123.1, 44.1, 0.0]
    """
    lo, hi = np.asarray(lo, dtype=np.float64), np.asarray(hi, dtype=np.float64)
    scales = np.asarray(scales, dtype=np.float64).reshape(3)
    caps = np.array([1.0, 1.0, 1000.0]) if _is_geographic(crs) else np.full(3, 1000.0)
    steps = np.array([min(cap, _pow10_floor(_INT_LIMIT * s / 4.0)) for cap, s in zip(caps, scales)])
    centre = (lo + hi) / 2.0
    return np.round(np.round(centre / steps) * steps, 12)


def fitted_scales(lo, hi, scales) -> np.ndarray:
    """``scales`` coarsened by powers of ten on the axes whose extent cannot fit 32 bits
    around any offset (an automatic scale never makes a file unwritable).

    Examples
    --------
    >>> fitted_scales([0, 0, 0], [1.0, 5.0, 10.0], [1e-10, 1e-10, 0.001]).tolist()
    [1e-09, 1e-08, 0.001]
    """
    lo, hi = np.asarray(lo, dtype=np.float64), np.asarray(hi, dtype=np.float64)
    scales = np.asarray(scales, dtype=np.float64).copy()
    for i in range(3):
        while (hi[i] - lo[i]) / 2.0 > 0.7 * _INT_LIMIT * scales[i]:
            scales[i] = _pow10_floor(scales[i] * 10.0 * 1.0001)
    return scales


def _scales_offsets(cloud: Cloud, las_meta: dict, scales, offsets, bounds=None):
    """The scales and offsets to write ``cloud`` with.

    ``scales``/``offsets`` given by the caller are used as they are (``offsets="auto"`` asks
    for :func:`auto_offsets`); else those the cloud was read with, else :func:`auto_scales`
    and :func:`auto_offsets`. ``bounds`` (lo, hi) stands for the data when the cloud is only
    the first chunk of a stream.
    """
    if bounds is not None:
        lo, hi = (np.asarray(b, dtype=np.float64) for b in bounds)
    elif cloud.n:
        lo, hi = cloud.xyz.min(axis=0), cloud.xyz.max(axis=0)
    else:
        lo = hi = np.zeros(3)
    given = scales is not None
    if scales is None:
        scales = las_meta.get("scales")
        scales = fitted_scales(lo, hi, auto_scales(cloud.crs)) if scales is None else scales
    scales = np.asarray(scales, dtype=np.float64).reshape(3)
    if isinstance(offsets, str) and offsets == "auto":
        offsets = auto_offsets(lo, hi, scales, cloud.crs)
    if offsets is None:
        offsets = las_meta.get("offsets")
        if offsets is None or not _fits(lo, hi, scales, np.asarray(offsets, dtype=float)):
            offsets = auto_offsets(lo, hi, scales, cloud.crs)
    offsets = np.asarray(offsets, dtype=np.float64).reshape(3)
    if not _fits(lo, hi, scales, offsets):
        reach = (_INT_LIMIT * scales).tolist()
        raise InvalidInputError(
            f"coordinates {lo.tolist()} .. {hi.tolist()} do not fit LAS 32-bit integers at scale "
            f"{scales.tolist()} and offset {offsets.tolist()} (reach ±{reach} from the offset)",
            "give a coarser --scale or an --offset near the data (or --offset auto)" if given
            else "give --offset auto or an offset near the data",
            field="xyz",
        )
    return scales, offsets


def _extra_params(laspy, cloud: Cloud, native: set, las_meta: dict):
    defs = {d["name"]: d for d in las_meta.get("extra_dims", [])}
    params = []
    for name, arr in cloud.attrs.items():
        if name in native:
            continue
        las_name = name[len("extra_"):] if name.startswith("extra_") and name[len("extra_"):] in defs else name
        d = defs.get(las_name)
        shape = arr.shape[1:]
        if len(shape) > 1 or (shape and shape[0] > 3):
            raise InvalidInputError(f"per-point shape {shape} cannot be a LAS extra-byte dimension", field=name)
        if d is not None:
            p = laspy.ExtraBytesParams(
                name=las_name, type=d["type"], description=d["description"],
                offsets=None if d["offsets"] is None else np.asarray(d["offsets"]),
                scales=None if d["scales"] is None else np.asarray(d["scales"]),
            )
        else:
            dt = arr.dtype
            if dt.kind == "b":
                dt = np.dtype("u1")
            if dt.kind not in "iuf":
                raise InvalidInputError(f"dtype {dt} cannot be a LAS extra-byte dimension", field=name)
            typ = f"{shape[0]}{dt.str[1:]}" if shape else dt.str[1:]
            p = laspy.ExtraBytesParams(name=las_name, type=typ, description=name[:31])
        params.append((name, las_name, p))
    return params


def _drop_unstorable(cloud: Cloud, fmt: int, native: set) -> Cloud:
    """The cloud without the standard LAS dimensions that point format ``fmt`` has no field for.

    As PDAL's writers.las and laspy's ``convert`` do, a standard dimension (``rgb`` in point
    format 1, ``nir`` in 7, ``gps_time`` in 0 ...) is left out with a warning rather than
    stored as an extra-byte dimension that other programs would not recognise as colour.
    """
    lost = [a for a in cloud.attrs if a in DIMS and DIMS[a].las and a not in native]
    if not lost:
        return cloud
    log.warning("LAS point format %d has no field for %s; not written (choose a point format that holds them "
                "to keep them)", fmt, ", ".join(lost))
    return cloud.without_attrs(*lost)


def _resolve_format(cloud: Cloud, las_meta: dict, point_format, version):
    attrs = set(cloud.attrs)
    known_std = {a for a in attrs if a in DIMS and DIMS[a].las}
    if point_format is None:
        old = las_meta.get("point_format")
        if old is not None and known_std <= _format_attrs(old):
            point_format = old
        else:
            legacy = old is not None and old < 6
            point_format = choose_point_format(known_std, legacy=legacy)
    if not isinstance(point_format, (int, np.integer)) or not 0 <= point_format <= 10:
        raise InvalidInputError(f"LAS point format {point_format!r} does not exist", "use 0-10", field="point_format")
    point_format = int(point_format)
    if version is None:
        version = las_meta.get("version")
    return point_format, _version_for(point_format, version)


def write(
    cloud: Cloud,
    path,
    *,
    point_format: int | None = None,
    version: str | None = None,
    scales=None,
    offsets=None,
    compress: bool | None = None,
    chunk_size: int | None = None,
) -> None:
    """Write a cloud as LAS or LAZ (by suffix unless ``compress`` says).

    Parameters
    ----------
    point_format : int, optional
        0-10; default: the format the cloud was read with when its attributes fit, else the
        smallest LAS 1.4 format holding them (:func:`choose_point_format`). Standard
        attributes the given format has no field for (``rgb`` in format 1) are left out with
        a warning, as PDAL and laspy do.
    version : str, optional
        "1.1"-"1.4" (laspy cannot write 1.0; 1.1 has its layout); raised to what the point
        format needs.
    scales, offsets : (3,) floats, optional
        Coordinate quantisation; default: those read, else :func:`auto_scales` (0.001, or
        1e-7 degree for geographic CRSs) and :func:`auto_offsets` (the rounded centre of the
        data); ``offsets="auto"`` always takes the rounded centre.
    compress : bool, optional
        LAZ when True; default from the suffix of ``path`` (the registry writes to a
        temporary path with the same suffix).
    """
    with ChunkWriter(path, cloud, point_format=point_format, version=version, scales=scales, offsets=offsets,
                     compress=compress, chunk_size=chunk_size) as writer:
        writer.write(cloud)


class ChunkWriter:
    """Write a LAS/LAZ file chunk by chunk, so a streamed command (crop, filter, tile, merge)
    holds one chunk in memory.

    The header (point format, version, scales, offsets, extra bytes, VLRs, CRS) is made from
    ``template``, a cloud with the attributes every chunk will have (the first chunk);
    ``bounds`` (lo, hi) are those of all the data to come, so the automatic offsets fit every
    chunk. Chunks must carry the template's attributes; each is checked against the
    32-bit range before it is written.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "a.las"
    >>> c = Cloud(np.arange(12.0).reshape(4, 3), {"intensity": [1, 2, 3, 4]})
    >>> with ChunkWriter(path, c, bounds=c.bounds) as w:
    ...     w.write(c[:2]); w.write(c[2:])
    >>> read(path).attrs["intensity"].tolist()
    [1, 2, 3, 4]
    """

    def __init__(self, path, template: Cloud, *, point_format=None, version=None, scales=None, offsets=None,
                 compress: bool | None = None, chunk_size: int | None = None, bounds=None):
        laspy = _laspy()
        self.path = Path(path)
        las_meta = dict(template.meta.get("las", {}))
        self.fmt, ver = _resolve_format(template, las_meta, point_format, version)
        scales, offsets = _scales_offsets(template, las_meta, scales, offsets, bounds)
        self.compress = self.path.suffix.lower() == ".laz" if compress is None else compress
        self.chunk_size = chunk_size or (CHUNK_LAZ if self.compress else CHUNK_LAS)
        self.native = _format_attrs(self.fmt)
        self.template = _drop_unstorable(template, self.fmt, self.native)
        self.extras = _extra_params(laspy, self.template, self.native, las_meta)
        self.header = _make_header(laspy, self.template, las_meta, self.fmt, ver, scales, offsets, self.extras)
        self.count = 0
        self._writer = laspy.open(str(self.path), mode="w", header=self.header, do_compress=self.compress)

    def write(self, cloud: Cloud) -> None:
        """Append the points of ``cloud`` (attributes the point format cannot hold are dropped)."""
        cloud = cloud.without_attrs(*[a for a in cloud.attrs if a not in self.template.attrs])
        _check_values(cloud, self.fmt)
        if cloud.n and not _fits(cloud.xyz.min(axis=0), cloud.xyz.max(axis=0), self.header.scales, self.header.offsets):
            raise InvalidInputError(f"points beyond the 32-bit range of scale {list(self.header.scales)} and offset "
                                    f"{list(self.header.offsets)}", "give --offset auto or a coarser --scale",
                                    path=self.path, field="xyz")
        laspy = _laspy()
        for start in range(0, cloud.n, self.chunk_size):
            end = min(cloud.n, start + self.chunk_size)
            self._writer.write_points(_record(laspy, self.header, cloud, start, end, self.fmt, self.native, self.extras))
        self.count += cloud.n

    def close(self) -> None:
        """Write the extended VLRs after the points (laspy writes them only when asked: a CRS
        kept there, as copc-lib does, would be lost) and close the file."""
        evlrs = getattr(self.header, "evlrs", None)
        if evlrs and self.header.version.minor >= 4:
            self._writer.write_evlrs(evlrs)
        self._writer.close()

    def __enter__(self) -> "ChunkWriter":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _make_header(laspy, cloud: Cloud, las_meta: dict, fmt: int, ver: str, scales, offsets, extras):
    """The laspy header: format, version, scales/offsets, extra bytes, identifiers, VLRs, CRS."""
    header = laspy.LasHeader(point_format=fmt, version=ver)
    header.scales = scales
    header.offsets = offsets
    if extras:
        header.add_extra_dims([p for _, _, p in extras])
    for key in ("system_identifier", "generating_software"):
        if las_meta.get(key):
            setattr(header, key, las_meta[key][:32])
    if not las_meta.get("generating_software"):
        header.generating_software = "workstation"
    if las_meta.get("file_source_id"):
        header.file_source_id = int(las_meta["file_source_id"])
    if las_meta.get("global_encoding_gps_standard"):
        header.global_encoding.gps_time_type = laspy.header.GpsTimeType.STANDARD
    if las_meta.get("creation_date"):
        import datetime as _dt

        header.creation_date = _dt.date.fromisoformat(las_meta["creation_date"])

    crs_same = cloud.crs is not None and cloud.crs == las_meta.get("crs")
    for rec in las_meta.get("vlrs", []):
        if _is_crs_vlr(rec) and not crs_same:
            continue
        header.vlrs.append(laspy.VLR(rec["user_id"], rec["record_id"], rec["description"], rec["data"]))
    if cloud.crs and not crs_same:
        import pyproj

        try:
            crs = pyproj.CRS.from_user_input(cloud.crs)
        except Exception as exc:
            raise InvalidInputError(f"CRS cannot be written: {exc}", "give an EPSG code or WKT", field="crs") from None
        try:
            header.add_crs(crs)
        except Exception:  # no GeoTIFF keys for a CRS without EPSG code (legacy formats): a WKT record, as LAS 1.4 has
            from laspy.vlrs.known import WktCoordinateSystemVlr

            header.vlrs.append(WktCoordinateSystemVlr(crs.to_wkt()))
            if fmt >= 6 or ver == "1.4":
                header.global_encoding.wkt = True
    evlrs = [laspy.VLR(r["user_id"], r["record_id"], r["description"], r["data"]) for r in las_meta.get("evlrs", [])]
    if evlrs and ver == "1.4":
        from laspy.vlrs.vlrlist import VLRList

        header.evlrs = VLRList(evlrs)
    return header


def _check_values(cloud: Cloud, fmt: int) -> None:
    """Refuse class codes a legacy point format cannot hold."""
    classification = cloud.attrs.get("classification")
    if fmt < 6 and classification is not None and classification.size and classification.max() > 31:
        raise InvalidInputError(
            f"class code {int(classification.max())} does not fit point format {fmt} (0-31)",
            "write point format 6 or later (LAS 1.4)",
            field="classification",
        )


def _record(laspy, header, cloud: Cloud, start: int, end: int, fmt: int, native: set, extras):
    rec = laspy.ScaleAwarePointRecord.zeros(end - start, header=header)
    arr = rec.array
    xyz = cloud.xyz[start:end]
    for i, c in enumerate("XYZ"):
        arr[c] = np.round((xyz[:, i] - header.offsets[i]) / header.scales[i])
    for name, values in cloud.attrs.items():
        if name not in native:
            continue
        v = values[start:end]
        if name == "rgb":
            arr["red"], arr["green"], arr["blue"] = v[:, 0], v[:, 1], v[:, 2]
        elif name == "scan_angle":
            if fmt >= 6:
                arr["scan_angle"] = np.clip(np.round(v / SCAN_ANGLE_UNIT), -32768, 32767)
            else:
                rec["scan_angle_rank"] = np.clip(np.round(v), -128, 127).astype(np.int8)
        elif name in ("return_number", "number_of_returns"):
            limit = 15 if fmt >= 6 else 7
            if v.size and v.max() > limit:
                raise InvalidInputError(
                    f"value {int(v.max())} does not fit point format {fmt} (max {limit})",
                    "write point format 6 or later" if fmt < 6 else "clip the value",
                    field=name,
                )
            rec[name] = v
        elif name in LAS_FLAGS or name in ("scan_direction_flag", "edge_of_flight_line"):
            rec[name] = v.astype(bool) if name in LAS_FLAGS else v
        else:
            rec[name] = v
    for name, las_name, p in extras:
        rec[las_name] = cloud.attrs[name][start:end]
    return rec
