"""LAS/LAZ format validation for ``ws qc``, after LAStools' ``lasvalidate``.

The rules are those of the LAS Specification 1.4 R15 (ASPRS, 2019): the public header block
(§2.4), variable length records (§2.5), point data records (§2.6, formats 0-10), extended
variable length records (§2.8) and the ASPRS standard point classes (Table 9 for formats 0-5,
Table 17 for formats 6-10), plus what the USGS Lidar Base Specification 2024 (v2.x) asks of a
delivery (adjusted standard GPS time, a WKT coordinate reference system).

The header is parsed from its raw bytes: laspy normalises away several of the things a
validator must see (the legacy point counts of a LAS 1.4 file, a header or VLR block whose
sizes disagree with its offsets, extra bytes no Extra Bytes VLR describes). The point checks
accumulate over chunks of :func:`workstation.io.registry.iter_chunks`: counts by return,
bounds, classes, return numbers, scan angles, GPS times, flags and duplicate positions. Memory
is one chunk plus 8 bytes a point for the duplicate search (16 while the duplicates are
counted at the end), which :class:`FormatParams` can switch off.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.qc.context import Finding

#: Bytes of each point data record format without extra bytes (LAS 1.4 R15, §2.6).
RECORD_LENGTH = {0: 20, 1: 28, 2: 26, 3: 34, 4: 57, 5: 63, 6: 30, 7: 36, 8: 38, 9: 59, 10: 67}
#: Public header block size of each minor version of LAS 1.x.
HEADER_SIZE = {0: 227, 1: 227, 2: 227, 3: 235, 4: 375}
#: Seconds in a GPS week: the range of GPS week time.
GPS_WEEK_S = 604_800.0
#: Adjusted standard GPS time is GPS time minus 1e9 s; values beyond ±1e9 s fall before the
#: GPS epoch (1980) or after 2043.
ADJUSTED_GPS_LIMIT_S = 1e9
#: Formats 6-10 store the scan angle in units of 0.006°, valid range ±30 000 (±180°).
SCAN_ANGLE_UNIT = 0.006
_MAX_FORMAT = {0: 1, 1: 1, 2: 3, 3: 5, 4: 10}  # the highest point format of each LAS 1.x
_GPS_FORMATS = {1, 3, 4, 5, 6, 7, 8, 9, 10}
_CRS_RECORDS = {34735: "GeoKeyDirectoryTag", 2112: "OGC WKT"}
_EXTRA_BYTES = ("LASF_Spec", 4)
#: Fields whose error leaves the point records uninterpretable: no point checks then.
_FATAL = {"point_format", "point_record_length", "header", "header_size"}
_TYPE_SIZE = (1, 1, 2, 2, 4, 4, 8, 8, 4, 8)  # Extra Bytes data types 1-10 (Table 24)


@dataclass(frozen=True)
class FormatParams:
    """What the format check looks for beyond the header.

    Attributes
    ----------
    duplicates : bool
        Search duplicate points (identical scaled integer X, Y, Z): 8 bytes of memory a point
        while streaming, 16 while counting at the end.
    duplicate_examples : int
        How many duplicated positions to report (file indices, coordinates in CRS units).
    """

    duplicates: bool = True
    duplicate_examples: int = 5


# ---------------------------------------------------------------------------------------
# the raw header


@dataclass(frozen=True)
class _Header:
    """The public header block as stored (LAS 1.4 R15 Table 3), every field from its bytes."""

    minor: int
    global_encoding: int
    header_size: int
    offset_to_points: int
    n_vlrs: int
    point_format: int
    compressed: bool
    record_length: int
    legacy_count: int
    legacy_by_return: tuple
    scales: np.ndarray
    offsets: np.ndarray
    mins: np.ndarray
    maxs: np.ndarray
    waveform_start: int
    evlr_start: int
    n_evlrs: int
    count64: int
    by_return64: tuple

    @property
    def count(self) -> int:
        """The point count readers use (the 64-bit field from LAS 1.4 on)."""
        return self.count64 if self.minor >= 4 else self.legacy_count

    @property
    def by_return(self) -> tuple:
        return self.by_return64 if self.minor >= 4 else self.legacy_by_return


def _parse_header(head: bytes) -> _Header:
    """The header fields of ``head`` (the first 375 bytes of the file, or fewer for LAS < 1.4)."""
    minor = head[25]
    u = lambda fmt, at: struct.unpack_from("<" + fmt, head, at)  # noqa: E731
    bounds = np.array(u("6d", 179))  # max x, min x, max y, min y, max z, min z
    big = minor >= 4 and len(head) >= 375
    return _Header(
        minor=minor, global_encoding=u("H", 6)[0], header_size=u("H", 94)[0], offset_to_points=u("I", 96)[0],
        n_vlrs=u("I", 100)[0], point_format=head[104] & 0x3F, compressed=bool(head[104] & 0xC0),
        record_length=u("H", 105)[0], legacy_count=u("I", 107)[0], legacy_by_return=u("5I", 111),
        scales=np.array(u("3d", 131)), offsets=np.array(u("3d", 155)), mins=bounds[1::2], maxs=bounds[0::2],
        waveform_start=u("Q", 227)[0] if minor >= 3 and len(head) >= 235 else 0,
        evlr_start=u("Q", 235)[0] if big else 0, n_evlrs=u("I", 243)[0] if big else 0,
        count64=u("Q", 247)[0] if big else 0, by_return64=u("15Q", 255) if big else (0,) * 15,
    )


@dataclass(frozen=True)
class _Record:
    """One VLR or EVLR: its ids and where its payload lies in the file."""

    user_id: str
    record_id: int
    start: int
    size: int


def _walk_records(f, start: int, count: int, limit: int, extended: bool):
    """The (E)VLR headers from ``start`` (54-byte VLR or 60-byte EVLR headers, §2.5 and §2.8):
    (records, end offset, problem or None). The walk stops at the first record that would
    cross ``limit`` (the point data for VLRs, the end of the file for EVLRs)."""
    head = 60 if extended else 54
    kind = "EVLR" if extended else "VLR"
    records, pos = [], start
    for i in range(count):
        f.seek(pos)
        raw = f.read(head)
        if len(raw) < head or pos + head > limit:
            return records, pos, f"{kind} {i} header at byte {pos} runs past byte {limit}"
        size = struct.unpack_from("<Q" if extended else "<H", raw, 20)[0]
        if pos + head + size > limit:
            return records, pos, f"{kind} {i} ({size} bytes at byte {pos + head}) runs past byte {limit}"
        user = raw[2:18].split(b"\0")[0].decode("ascii", "replace")
        records.append(_Record(user, struct.unpack_from("<H", raw, 18)[0], pos + head, size))
        pos += head + size
    return records, pos, None


def _described_extra_bytes(f, rec: _Record) -> int:
    """Bytes per point an Extra Bytes VLR describes (192-byte descriptors, LAS 1.4 R15 Table 24;
    data type 0 is ``options`` undocumented bytes, 11-30 the deprecated 2- and 3-element arrays)."""
    f.seek(rec.start)
    payload = f.read(rec.size)
    total = 0
    for at in range(0, len(payload) - 191, 192):
        dtype, options = payload[at + 2], payload[at + 3]
        if dtype == 0:
            total += options
        elif dtype <= 30:
            total += _TYPE_SIZE[(dtype - 1) % 10] * (1 + (dtype - 1) // 10)
    return total


# ---------------------------------------------------------------------------------------
# header checks: each returns a list of (severity, field, expected, found, message)


def _check_layout(h: _Header, version: str) -> list:
    """Header size for the version, the point format and its record length."""
    out = []
    want = HEADER_SIZE[h.minor]
    if h.header_size < want:
        out.append(("error", "header_size", f"{want} bytes (LAS {version})", str(h.header_size),
                    f"the header is shorter than LAS {version} requires"))
    elif h.header_size > want:
        out.append(("warning", "header_size", f"{want} bytes (LAS {version})", str(h.header_size),
                    "the header is extended by user data, which LAS discourages (use VLRs)"))
    if h.point_format > _MAX_FORMAT[h.minor]:
        out.append(("error", "point_format", f"a point format defined by LAS {version}", str(h.point_format),
                    f"point data record format {h.point_format} does not exist in LAS {version}"))
    elif h.record_length < RECORD_LENGTH[h.point_format]:
        out.append(("error", "point_record_length", f">= {RECORD_LENGTH[h.point_format]} bytes",
                    str(h.record_length), f"records are too short for point format {h.point_format}"))
    return out


def _check_counts(h: _Header) -> list:
    """Legacy counts against the 64-bit counts of LAS 1.4 (R15 §2.4: zero for formats 6-10 and
    for writers not keeping legacy compatibility, else equal)."""
    if h.minor < 4:
        return []
    out = []
    pairs = [("legacy_point_count", h.legacy_count, h.count64)]
    pairs += [(f"legacy_points_by_return[{i + 1}]", h.legacy_by_return[i], h.by_return64[i]) for i in range(5)]
    for field, legacy, full in pairs:
        if h.point_format >= 6 and legacy != 0:
            out.append(("error", field, "0 (point formats 6-10)", str(legacy),
                        "LAS 1.4 requires the legacy counts to be zero for point formats 6-10"))
        elif h.point_format < 6 and legacy not in (0, full if full <= 0xFFFFFFFF else 0):
            out.append(("error", field, f"{full if full <= 0xFFFFFFFF else 0} (or 0)", str(legacy),
                        "the legacy count disagrees with the 64-bit count"))
    return out


def _check_encoding(h: _Header) -> list:
    """Global encoding bits (R15 Table 4): waveform bits exclusive, WKT for formats 6-10,
    adjusted standard GPS time in LAS 1.4 (USGS LBS 2024)."""
    out = []
    if h.global_encoding & 0b110 == 0b110:
        out.append(("error", "global_encoding.waveform", "internal or external", "both bits set",
                    "waveform packets cannot be both internal and external"))
    if h.point_format >= 6 and not h.global_encoding & 0b10000:
        out.append(("error", "global_encoding.wkt", "set (point formats 6-10)", "not set",
                    "LAS 1.4 requires WKT coordinate systems for point formats 6-10"))
    if h.minor >= 4 and h.point_format in _GPS_FORMATS and not h.global_encoding & 1:
        out.append(("warning", "global_encoding.gps_time_type", "adjusted standard GPS time (bit 0 set)",
                    "GPS week time", "LAS 1.4 deliveries use adjusted standard GPS time (USGS LBS)"))
    return out


def _check_extra_bytes(h: _Header, f, vlrs: list[_Record]) -> list:
    """Bytes beyond the point format's record must be described by one Extra Bytes VLR
    (R15 §2.5.9: more described than present is an 'extra bytes mismatch')."""
    if h.point_format not in RECORD_LENGTH:
        return []
    extra = h.record_length - RECORD_LENGTH[h.point_format]
    eb = [r for r in vlrs if (r.user_id, r.record_id) == _EXTRA_BYTES]
    out = []
    if len(eb) > 1:
        out.append(("warning", "extra_bytes_vlr", "at most 1", str(len(eb)),
                    "several Extra Bytes VLRs (LAS defines one; laspy reads the first only)"))
    described = sum(_described_extra_bytes(f, r) for r in eb)
    if described > extra:
        out.append(("error", "extra_bytes", f"{extra} extra bytes a point", f"{described} described",
                    "the Extra Bytes VLR describes more bytes than each record holds (extra bytes mismatch)"))
    elif described < extra:
        sev = "error" if h.minor >= 4 else "warning"
        out.append((sev, "extra_bytes", f"{extra} bytes described by an Extra Bytes VLR",
                    f"{described} described", f"{extra - described} undocumented extra bytes a point"))
    return out


def _check_crs(h: _Header, vlrs: list[_Record], evlrs: list[_Record], crs_text, parsed: bool) -> list:
    """A CRS must be present (GeoKeys or WKT, user id LASF_Projection) and readable (``crs_text``
    None when laspy's reading of it failed; ``parsed`` False when laspy could not read the
    header at all); the WKT bit says which record readers look for (R15 §2.4, Table 4)."""
    ids = {r.record_id for r in vlrs + evlrs if r.user_id == "LASF_Projection" and r.record_id in _CRS_RECORDS}
    wkt_bit = h.minor >= 4 and bool(h.global_encoding & 0b10000)
    if not ids:
        return [("warning", "crs", "a GeoKeyDirectoryTag or OGC WKT record (LASF_Projection)", "none",
                 "the file has no coordinate reference system")]
    if wkt_bit and 2112 not in ids:
        return [("error", "crs", "an OGC WKT record (the WKT bit is set)", "GeoKeys only",
                 "the global encoding says WKT but there is no WKT record")]
    if parsed and crs_text is None:
        return [("warning", "crs", "a CRS readers can parse",
                 ", ".join(_CRS_RECORDS[i] for i in sorted(ids)) + " present but empty or unparsable",
                 "the coordinate reference system records cannot be read")]
    if not wkt_bit and h.point_format < 6 and 34735 not in ids:
        return [("warning", "crs", "a GeoKeyDirectoryTag (the WKT bit is not set)", "OGC WKT only",
                 "legacy readers look for GeoKeys when the WKT bit is not set")]
    return []


def _check_point_data(h: _Header, size: int, laz_counts) -> list:
    """The header's point count against the points the file holds: its bytes for LAS (up to the
    first EVLR or internal waveform data), the chunk table for LAZ (``laz_counts`` from
    :func:`workstation.io.las.laz_chunk_counts`: per-chunk counts, the last one exact or an
    upper bound)."""
    if h.compressed:
        if laz_counts is None:
            return []
        counts, exact = laz_counts
        hi = sum(counts)
        lo = hi if exact else hi - counts[-1] + 1
        found, rest = (str(hi) if exact else f"{lo}-{hi}"), 0
    else:
        end = size
        if h.minor >= 4 and h.n_evlrs and h.evlr_start:
            end = min(end, h.evlr_start)
        if h.minor >= 3 and h.global_encoding & 0b10 and h.waveform_start:
            end = min(end, h.waveform_start)
        lo = hi = max(0, end - h.offset_to_points) // max(h.record_length, 1)
        rest = max(0, end - h.offset_to_points) - hi * h.record_length
        found = str(hi)
    out = []
    if not lo <= h.count <= hi:
        what = "truncated: fewer points than the header says" if h.count > hi else "more points than the header says"
        out.append(("error", "point_count", str(h.count), found, f"the file holds {what}"))
    if rest:
        out.append(("warning", "point_data", f"a multiple of {h.record_length} bytes", f"{rest} bytes left over",
                    "bytes after the last whole point record"))
    return out


def _laspy_header(path: Path):
    """laspy's header (VLRs and EVLRs parsed), or an InvalidInputError."""
    import laspy

    from workstation.io.las import wrap_open_error

    try:
        with open(path, "rb") as f:
            return laspy.LasHeader.read_from(f, read_evlrs=True)
    except Exception as exc:  # noqa: BLE001 - laspy raises many types on corrupt headers
        raise wrap_open_error(path, exc) from None


def _check_raw(head: bytes) -> tuple | None:
    """The fault that stops all parsing: signature, header too short, unknown version, or
    scale/offset fields that make every coordinate meaningless."""
    if head[:4] != b"LASF":
        return ("error", "signature", "LASF", repr(head[:4]), "not a LAS/LAZ file")
    if len(head) < 227:
        return ("error", "header_size", ">= 227 bytes", f"{len(head)} bytes in the file", "the file is truncated")
    if head[24] != 1 or head[25] > 4:
        return ("error", "version", "1.0-1.4", f"{head[24]}.{head[25]}", "not a LAS version this check knows")
    values = struct.unpack_from("<6d", head, 131)
    for i, v in enumerate(values):
        kind, axis = ("scale", "offset")[i // 3], "xyz"[i % 3]
        if not np.isfinite(v) or (kind == "scale" and v == 0):
            return ("error", f"{axis}_{kind}", "finite" + (", non-zero" if kind == "scale" else ""), repr(v),
                    f"the {axis} {kind} makes every coordinate meaningless")
    return None


def _check_records(h: _Header, f, size: int):
    """VLR and EVLR integrity from the raw bytes (R15 §2.5, §2.8): the VLRs fill the space from
    the header to the point data, the EVLRs start after the points and end inside the file, a
    LAZ file has its LASzip VLR. Returns (findings, VLRs, EVLRs)."""
    out = []
    vlrs, end, problem = _walk_records(f, h.header_size, h.n_vlrs, min(h.offset_to_points, size), False)
    if problem:
        out.append(("error", "vlr", f"{h.n_vlrs} VLRs between byte {h.header_size} and the point data at byte "
                    f"{h.offset_to_points}", problem, "the VLR block is inconsistent with the offset to point data"))
    elif end != h.offset_to_points and not (h.minor == 0 and h.offset_to_points - end == 2):  # LAS 1.0 start signature
        out.append(("warning", "offset_to_point_data", str(end), str(h.offset_to_points),
                    f"{h.offset_to_points - end} unaccounted bytes between the VLRs and the point data"))
    evlrs = []
    if h.minor >= 4 and h.n_evlrs:
        data_end = h.offset_to_points + (0 if h.compressed else h.count * h.record_length)
        if not data_end <= h.evlr_start < size:
            out.append(("error", "start_of_first_evlr", f"between {data_end} and {size}", str(h.evlr_start),
                        "the EVLRs do not start after the point data and inside the file"))
        else:
            evlrs, _, problem = _walk_records(f, h.evlr_start, h.n_evlrs, size, True)
            if problem:
                out.append(("error", "evlr", f"{h.n_evlrs} EVLRs inside the file", problem,
                            "the EVLR block is inconsistent with the file size"))
    if h.compressed and not any(r.user_id == "laszip encoded" for r in vlrs):
        out.append(("error", "laszip_vlr", "a 'laszip encoded' VLR", "none",
                    "the point format says compressed but the LASzip VLR is missing"))
    return out, vlrs, evlrs


# ---------------------------------------------------------------------------------------
# duplicate positions


def _mix(x: np.ndarray) -> np.ndarray:
    """The splitmix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix."""
    x = (x ^ (x >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    x = (x ^ (x >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return x ^ (x >> np.uint64(31))


def _hash(ints: np.ndarray) -> np.ndarray:
    """A 64-bit hash of (m, 3) int64 positions."""
    u = ints.astype(np.int64).view(np.uint64)
    h = _mix(u[:, 0] + np.uint64(0x9E3779B97F4A7C15))
    h = _mix(h ^ u[:, 1])
    return _mix(h ^ u[:, 2])


class _Positions:
    """One 64-bit key per point, in file order, for the duplicate search.

    While the positions fit the header's integer box in 64 bits, the key packs X, Y, Z
    relative to the box's corner (exact, decodable); else, or once a point falls outside the
    box, every key becomes a 64-bit hash (a chance of about n²/2⁶⁵ of a false match).
    """

    def __init__(self, lo, hi, capacity: int):
        self.lo = lo
        span = hi - lo if lo is not None else None
        self.bits = None if span is None or (span < 0).any() else [max(int(s).bit_length(), 1) for s in span]
        self.exact = self.bits is not None and sum(self.bits) <= 64
        self.keys = np.empty(capacity, dtype=np.uint64)
        self.n = 0

    def _pack(self, ints):
        rel = (ints - self.lo).view(np.uint64)
        by, bz = self.bits[1], self.bits[2]
        return (rel[:, 0] << np.uint64(by + bz)) | (rel[:, 1] << np.uint64(bz)) | rel[:, 2]

    def unpack(self, keys):
        by, bz = self.bits[1], self.bits[2]
        rel = np.column_stack([keys >> np.uint64(by + bz), (keys >> np.uint64(bz)) & np.uint64((1 << by) - 1),
                               keys & np.uint64((1 << bz) - 1)])
        return rel.astype(np.int64) + self.lo

    def add(self, ints: np.ndarray) -> None:
        if self.exact and ((ints < self.lo).any() or (ints >= self.lo + (np.int64(1) << self.bits)).any()):
            for a in range(0, self.n, 1 << 20):  # the box was wrong: rehash what is stored
                b = min(a + (1 << 20), self.n)
                self.keys[a:b] = _hash(self.unpack(self.keys[a:b]))
            self.exact = False
        keys = self._pack(ints) if self.exact else _hash(ints)
        if self.n + len(keys) > len(self.keys):
            grown = np.empty(max(self.n + len(keys), 2 * len(self.keys)), dtype=np.uint64)
            grown[: self.n] = self.keys[: self.n]
            self.keys = grown
        self.keys[self.n : self.n + len(keys)] = keys
        self.n += len(keys)

    def summary(self, examples: int) -> dict:
        """{points (repeats of an earlier point), positions (repeated positions), exact,
        examples: [{indices, ints}]} (ints: the scaled integers when exact, else None)."""
        keys = self.keys[: self.n]
        s = np.sort(keys)
        same = s[1:] == s[:-1]
        first = same & ~np.concatenate([[False], same[:-1]])
        vals = s[1:][first]
        summary = {"points": int(same.sum()), "positions": int(len(vals)), "exact": self.exact}
        del s, same, first
        vals = vals[:examples]
        idx = np.flatnonzero(np.isin(keys, vals))
        groups = sorted((idx[keys[idx] == v] for v in vals), key=lambda g: g[0])
        summary["examples"] = [{"indices": g[:10].tolist(),
                                "ints": self.unpack(keys[g[:1]])[0].tolist() if self.exact else None} for g in groups]
        return summary


# ---------------------------------------------------------------------------------------
# point checks


def _reserved_classes(minor: int) -> np.ndarray:
    """(256,) bool: the codes LAS reserves. LAS 1.4 R15 (Tables 9 and 17): 8, 12 and 23-63; for
    formats 0-5 only 0-31 can be stored. LAS 1.1-1.3 gave 8 (model key-point) and 12 (overlap)
    meanings, so there only 23-31 count (codes 13-22 are read with their LAS 1.4 meaning)."""
    reserved = np.zeros(256, dtype=bool)
    reserved[23:64] = True
    if minor >= 4:
        reserved[[ASPRSClass.RESERVED_8, ASPRSClass.RESERVED_12]] = True
    return reserved


class _PointStats:
    """Running sums of the point checks over chunks (memory: a few 256-bin histograms plus the
    duplicate keys)."""

    def __init__(self, h: _Header, params: FormatParams, capacity: int):
        self.h = h
        self.lo = np.full(3, np.iinfo(np.int64).max)
        self.hi = np.full(3, np.iinfo(np.int64).min)
        self.returns = np.zeros(256, dtype=np.int64)
        self.classes = np.zeros(256, dtype=np.int64)
        self.bad = dict.fromkeys(("rn_gt_nr", "rn0", "nr0", "over5", "scan", "gps"), 0)
        self.flags = dict.fromkeys(("withheld", "overlap", "synthetic", "key_point"), 0)
        self.scan = [np.inf, -np.inf]
        self.gps = [np.inf, -np.inf]
        self.gps_standard = h.minor >= 2 and bool(h.global_encoding & 1)
        self.positions = None
        if params.duplicates:
            with np.errstate(all="ignore"):
                lo, hi = (np.rint((v - h.offsets) / h.scales) for v in (h.mins, h.maxs))
            ok = np.isfinite(lo).all() and np.isfinite(hi).all() and np.abs([lo, hi]).max() < 2**40
            box = (lo.astype(np.int64), hi.astype(np.int64)) if ok else (None, None)
            self.positions = _Positions(*box, capacity)

    def add(self, chunk: Cloud) -> None:
        ints = np.rint((chunk.xyz - self.h.offsets) / self.h.scales).astype(np.int64)
        self.lo = np.minimum(self.lo, ints.min(axis=0))
        self.hi = np.maximum(self.hi, ints.max(axis=0))
        a = chunk.attrs
        self._returns(a.get("return_number"), a.get("number_of_returns"))
        if "classification" in a:
            self.classes += np.bincount(a["classification"], minlength=256)[:256]
        if "scan_angle" in a:
            self._scan_angle(a["scan_angle"])
        if "gps_time" in a and self.h.point_format in _GPS_FORMATS:
            self._gps_time(a["gps_time"])
        for name in self.flags:
            if name in a:
                self.flags[name] += int(np.count_nonzero(a[name]))
        if self.positions is not None:
            self.positions.add(ints)

    def _returns(self, rn, nr) -> None:
        if rn is None or nr is None:
            return
        self.returns += np.bincount(rn, minlength=256)[:256]
        self.bad["rn_gt_nr"] += int(np.count_nonzero(rn > nr))
        self.bad["rn0"] += int(np.count_nonzero(rn == 0))
        self.bad["nr0"] += int(np.count_nonzero(nr == 0))
        if self.h.point_format < 6:
            self.bad["over5"] += int(np.count_nonzero((rn > 5) | (nr > 5)))

    def _scan_angle(self, deg) -> None:
        limit = 90.0 if self.h.point_format < 6 else 180.0 + SCAN_ANGLE_UNIT / 2
        self.bad["scan"] += int(np.count_nonzero(np.abs(deg) > limit))
        self.scan = [min(self.scan[0], float(deg.min())), max(self.scan[1], float(deg.max()))]

    def _gps_time(self, t) -> None:
        if self.gps_standard:
            outside = np.abs(t) >= ADJUSTED_GPS_LIMIT_S
        else:
            outside = (t < 0) | (t >= GPS_WEEK_S)
        self.bad["gps"] += int(np.count_nonzero(outside))
        self.gps = [min(self.gps[0], float(t.min())), max(self.gps[1], float(t.max()))]


def _decimals(scale: float) -> int:
    """The decimals a scale factor resolves (0.01 -> 2)."""
    return max(0, int(-np.floor(np.log10(abs(scale)) + 1e-9)))


def _fmt(v: float, scale: float) -> str:
    """A coordinate with the decimals its scale resolves."""
    return f"{v:.{_decimals(scale)}f}"


def _bounds_findings(h: _Header, st: _PointStats) -> list:
    """Header min/max against the points' (R15 §2.4: 'the actual unscaled extents'), within
    half a scale step: points outside the box are an error, a loose box a warning."""
    out = []
    for i, axis in enumerate("xyz"):
        tol = 0.5 * h.scales[i] + 1e-9 * max(abs(h.mins[i]), abs(h.maxs[i]), 1.0)
        lo, hi = st.lo[i] * h.scales[i] + h.offsets[i], st.hi[i] * h.scales[i] + h.offsets[i]
        for side, head, data, outside in (("min", h.mins[i], lo, h.mins[i] > lo + tol),
                                          ("max", h.maxs[i], hi, h.maxs[i] < hi - tol)):
            if outside:
                out.append(("error", f"{side}_{axis}", _fmt(head, h.scales[i]), _fmt(data, h.scales[i]),
                            f"points lie outside the header's {side} {axis} (CRS units)"))
            elif abs(head - data) > tol:
                out.append(("warning", f"{side}_{axis}", _fmt(head, h.scales[i]), _fmt(data, h.scales[i]),
                            f"the header's {side} {axis} is not the points' {side} (a loose bounding box)"))
    return out


def _return_findings(h: _Header, st: _PointStats) -> list:
    """Counts by return against the header (R15 §2.4), and return numbers 1..number of returns
    (§2.6: 1-15, at most 5 in formats 0-5)."""
    out = []
    head = list(h.by_return)
    data = [int(v) for v in st.returns[1 : len(head) + 1]]
    if head != data:
        wrong = [str(i + 1) for i in range(len(head)) if head[i] != data[i]]
        last = max(i + 1 for i in range(len(head)) if head[i] or data[i])
        out.append(("error", "points_by_return", str(head[:last]), str(data[:last]),
                    f"the header's counts of return {', '.join(wrong)} disagree with the points"))
    rules = (("rn_gt_nr", "error", "return_number", "<= number_of_returns",
              "return number above the number of returns"),
             ("over5", "warning", "return_number", "1-5 (point formats 0-5)",
              "more than 5 returns in a legacy point format"),
             ("rn0", "warning", "return_number", "1-15", "return number 0"),
             ("nr0", "warning", "number_of_returns", "1-15", "number of returns 0"))
    for key, sev, field, expected, what in rules:
        if st.bad[key]:
            out.append((sev, field, expected, f"{st.bad[key]} points", f"{st.bad[key]} points with {what}"))
    return out


def _class_findings(h: _Header, st: _PointStats) -> list:
    """Reserved ASPRS codes (LAS 1.4 R15 Tables 9 and 17) and codes formats 0-5 cannot hold."""
    out = []
    used = np.flatnonzero(st.classes)
    reserved = used[_reserved_classes(h.minor)[used]]
    if len(reserved):
        found = ", ".join(f"class {c}: {st.classes[c]} points" for c in reserved)
        out.append(("error", "classification", "ASPRS codes 0-7, 9-11, 13-22 or user codes 64-255"
                    if h.minor >= 4 else "ASPRS codes 0-22", found, "points carry reserved class codes"))
    if h.point_format < 6 and used.size and used.max() > 31:
        found = ", ".join(f"class {c}: {st.classes[c]} points" for c in used[used > 31])
        out.append(("error", "classification", "0-31 (point formats 0-5)", found,
                    "class codes above 31 do not fit the 5 bits of formats 0-5"))
    return out


def _value_findings(h: _Header, st: _PointStats) -> list:
    """Scan angle range (formats 0-5: ±90°; 6-10: ±30 000 × 0.006° = ±180°), GPS times
    plausible for the time type, withheld and overlap flags."""
    out = []
    if st.bad["scan"]:
        want = "-90..+90 degrees" if h.point_format < 6 else "-180..+180 degrees (±30000 × 0.006°)"
        out.append(("error", "scan_angle", want, f"{st.bad['scan']} points, range {st.scan[0]:g}..{st.scan[1]:g}",
                    "scan angles outside the range the point format allows"))
    lo, hi = st.gps
    if st.bad["gps"] and not st.gps_standard:
        out.append(("error", "gps_time", f"0 <= t < {GPS_WEEK_S:.0f} s (GPS week time)",
                    f"{st.bad['gps']} points, range {lo:.6f}..{hi:.6f}", "GPS times outside a GPS week"))
    elif st.bad["gps"]:
        out.append(("warning", "gps_time", f"|t| < {ADJUSTED_GPS_LIMIT_S:.0e} s (adjusted standard GPS time)",
                    f"{st.bad['gps']} points, range {lo:.6f}..{hi:.6f}",
                    "GPS times not plausible as adjusted standard GPS time (GPS seconds minus 1e9)"))
    elif st.gps_standard and 0 <= lo and hi < GPS_WEEK_S:
        out.append(("warning", "gps_time", "adjusted standard GPS time", f"range {lo:.6f}..{hi:.6f} s",
                    "the times look like GPS week seconds although the header says adjusted standard time"))
    if st.flags["withheld"]:
        out.append(("warning", "withheld", "0 points (withheld points are normally removed)",
                    f"{st.flags['withheld']} points", "points flagged withheld"))
    if st.flags["overlap"]:
        out.append(("info", "overlap", "-", f"{st.flags['overlap']} points", "points flagged overlap"))
    return out


# ---------------------------------------------------------------------------------------
# the check


class FormatCheck:
    """Streaming validation of one LAS/LAZ/COPC file, as LAStools' ``lasvalidate``.

    Creating it reads the header, the VLRs and the EVLRs (from their raw bytes, and with laspy
    for the CRS) and runs the header checks; :meth:`add` takes the file's chunks in file order
    (:func:`workstation.io.registry.iter_chunks`) and accumulates the point checks;
    :meth:`findings` and :meth:`result` may be called at any time and say what was seen so far.
    A file of another format gets a single "info" finding; a LAS file whose header cannot be
    parsed gets an "error" finding, never an exception.

    Parameters
    ----------
    path : path-like
        The file. A missing path raises :class:`InvalidInputError`.
    params : FormatParams

    Notes
    -----
    ``iter_chunks`` itself refuses a file whose point count disagrees with its bytes; the
    header checks report that case as a ``point_count`` error before any chunk is read.
    """

    def __init__(self, path, params: FormatParams = FormatParams()):
        from workstation.io.registry import FORMATS, check_readable

        self.path = Path(path)
        if not self.path.is_file():
            check_readable(self.path)
        self.params = params
        self._n = 0
        self._chunks = 0
        self._header: _Header | None = None
        self._stats: _PointStats | None = None
        self._dups: tuple[int, dict] | None = None
        self._head_findings: list[tuple] = []
        kind = FORMATS.get(self.path.suffix.lower(), (None,))[0]
        if kind in ("las", "laz"):
            self._read_header()
        else:
            self._head_findings.append(("info", "format", "LAS or LAZ", kind or self.path.suffix or "(no extension)",
                                        "format checks apply to LAS/LAZ"))

    def _read_header(self) -> None:
        size = self.path.stat().st_size
        with open(self.path, "rb") as f:
            head = f.read(375)
            fatal = _check_raw(head)
            if fatal:
                self._head_findings.append(fatal)
                return
            h = self._header = _parse_header(head)
            found = _check_layout(h, f"1.{h.minor}")
            records, vlrs, evlrs = _check_records(h, f, size)
            found += records
            if not any(x[0] == "error" for x in found):
                found += _check_extra_bytes(h, f, vlrs)
        found += _check_counts(h) + _check_encoding(h)
        lh, crs = self._laspy(found)
        found += _check_crs(h, vlrs, evlrs, crs, lh is not None)
        laz = None
        if h.compressed and lh is not None:
            from workstation.io.las import laz_chunk_counts

            laz = laz_chunk_counts(self.path, lh)
        found += _check_point_data(h, size, laz)
        self._head_findings += found
        if not any(x[0] == "error" and x[1] in _FATAL for x in found):
            consistent = not any(x[1] == "point_count" for x in found)
            self._stats = _PointStats(h, self.params, h.count if consistent else 0)

    def _laspy(self, found: list):
        """laspy's header and the CRS string it parses ((None, None) when laspy cannot read it)."""
        from workstation.io.las import crs_string

        try:
            lh = _laspy_header(self.path)
        except InvalidInputError as exc:
            if not any(x[0] == "error" for x in found):
                found.append(("error", "header", "a header LAS readers can parse", exc.message,
                              "laspy cannot read the header"))
            return None, None
        return lh, crs_string(lh, self.path)

    def add(self, chunk: Cloud, source=None) -> None:
        """Accumulate the point checks over ``chunk``, the next points of this file (``source``,
        when given, must be this file)."""
        if source is not None and Path(source).resolve() != self.path.resolve():
            raise InvalidInputError(f"a chunk of {source} was given to the format check of {self.path}",
                                    "give each file's chunks to its own FormatCheck", path=source)
        self._n += chunk.n
        self._chunks += 1
        if self._stats is not None and chunk.n:
            self._stats.add(chunk)

    def _duplicates(self) -> dict | None:
        pos = None if self._stats is None else self._stats.positions
        if pos is None:
            return None
        if self._dups is None or self._dups[0] != self._n:
            d = pos.summary(self.params.duplicate_examples)
            h = self._header
            for ex in d["examples"]:
                ints = ex.pop("ints")
                xyz = None if ints is None else np.asarray(ints) * h.scales + h.offsets
                ex["xyz"] = None if xyz is None else [round(float(v), _decimals(s)) for v, s in zip(xyz, h.scales)]
            self._dups = (self._n, d)
        return self._dups[1]

    def _point_findings(self) -> list:
        h, st = self._header, self._stats
        if st is None or not self._chunks:
            return []
        out = []
        if self._n != h.count:
            out.append(("error", "point_count", str(h.count), str(self._n),
                        "the points read disagree with the header's point count"))
        elif self._n:
            out += _return_findings(h, st) + _bounds_findings(h, st)
        out += _class_findings(h, st) + _value_findings(h, st)
        d = self._duplicates()
        if d and d["points"]:
            ex = d["examples"][0]
            at = "" if ex["xyz"] is None else ", ".join(_fmt(v, s) for v, s in zip(ex["xyz"], h.scales))
            where = f" at ({at})" if at else ""
            out.append(("warning", "duplicate_points", "0", f"{d['points']} points",
                        f"{d['points']} points repeat an earlier point's X, Y, Z ({d['positions']} positions), "
                        f"e.g. points {ex['indices']}{where}"))
        return out

    def findings(self) -> list[Finding]:
        """What is wrong or worth knowing, header checks first (``check="format"``)."""
        rows = self._head_findings + self._point_findings()
        return [Finding("format", sev, str(self.path), field, expected, found, message)
                for sev, field, expected, found, message in rows]

    def result(self) -> dict:
        """{file, version ("1.4"), point_format, compressed, points (read through :meth:`add`),
        header_points, errors, warnings, infos, pass (no error), flags ({withheld, overlap,
        synthetic, key_point}: point counts), duplicates ({points, positions, exact, examples:
        [{indices, xyz}]}, xyz in CRS units, or None)}. Only counts: no lengths."""
        sev = [f.severity for f in self.findings()]
        h = self._header
        return {
            "file": str(self.path),
            "version": None if h is None else f"1.{h.minor}",
            "point_format": None if h is None else h.point_format,
            "compressed": None if h is None else h.compressed,
            "points": self._n,
            "header_points": None if h is None else h.count,
            "errors": sev.count("error"),
            "warnings": sev.count("warning"),
            "infos": sev.count("info"),
            "pass": "error" not in sev,
            "flags": None if self._stats is None else dict(self._stats.flags),
            "duplicates": self._duplicates(),
        }

