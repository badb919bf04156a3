"""PCL PCD point clouds (v0.7, also v0.5/0.6 headers): DATA ascii, binary and binary_compressed.

Binary bodies are read with one structured numpy dtype (``np.frombuffer``); ascii bodies with
one ``np.loadtxt`` call; ``binary_compressed`` bodies (LZF, column-major) are decompressed by
:func:`lzf_decompress` (liblzf's C decoder through ``python-lzf``, or a pure-Python fallback)
and each field is then a contiguous array.

Field names map to canonical attributes:

=============================================  ==============================================
PCD field                                      ``Cloud``
=============================================  ==============================================
x, y, z                                        ``xyz`` (float64)
rgb (packed F 4 or U 4), rgba (U 4)            ``rgb`` u16 (8-bit channels x 257); the alpha of
                                               ``rgba`` becomes the free attribute ``alpha``
r16, g16, b16 (U 2, written by us)             ``rgb`` exactly, for colour that is not 8-bit
normal_x, normal_y, normal_z                   ``normal`` f32
intensity                                      ``intensity`` u16 when every value fits
label                                          ``classification`` u8 when every value fits
a canonical scalar name (gps_time, ...)        that attribute when every value fits
anything else (curvature, FPFH with COUNT 33)  a free attribute under its own name, (n, COUNT)
=============================================  ==============================================

Points whose coordinates are NaN (PCL marks invalid points of organised clouds so,
``is_dense`` false) are dropped with a warning; ``meta["pcd"]["dropped_invalid"]`` counts
them. The CRS, which PCD has no field for, is written and read as a header comment
``# crs EPSG:32632`` (PCL ignores comment lines). ``VIEWPOINT``, ``WIDTH``, ``HEIGHT`` and the field types are kept in ``meta["pcd"]``.
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, UnsupportedFormatError
from workstation.core.log import get_logger

from ._fields import (
    build_cloud,
    crs_from_comment,
    count_data_lines,
    crs_line,
    first_non_ascii,
    fits_exactly,
    format_rows,
    loadtxt_error_line,
    looks_like_numbers,
    mapped_attr,
    number_format,
    rgb_to_u16,
    scalar_canonical,
)

try:  # liblzf's C decoder (PyPI python-lzf); lzf_decompress_py is the fallback
    import lzf as _lzf_c
except ImportError:  # pragma: no cover - python-lzf is a declared dependency
    _lzf_c = None

log = get_logger(__name__)

_TYPE = {("I", 1): "i1", ("I", 2): "i2", ("I", 4): "i4", ("I", 8): "i8",
         ("U", 1): "u1", ("U", 2): "u2", ("U", 4): "u4", ("U", 8): "u8",
         ("F", 4): "f4", ("F", 8): "f8"}  # fmt: skip
_KEYS = ("VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA")
_NORMALS = ("normal_x", "normal_y", "normal_z")
_LZF_MAX_RATIO = 88  # an LZF back reference of 3 bytes yields at most 264 bytes


def lzf_decompress(src: bytes, out_len: int) -> bytes:
    """Decompress an LZF stream (liblzf format, as PCL writes it) to exactly ``out_len`` bytes.

    Uses liblzf's C decoder from ``python-lzf`` (module ``lzf``) when it is installed, else
    :func:`lzf_decompress_py` (the same bytes, tens of times slower). A stream the C decoder
    refuses is decoded again in Python, so the error raised names what is wrong.

    Raises
    ------
    ValueError
        When the stream is corrupt or does not decompress to ``out_len`` bytes.

    Examples
    --------
    >>> lzf_decompress(bytes([2]) + b"abc" + bytes([0xA0, 2]), 10)  # 'abc', then 7 bytes from 3 back
    b'abcabcabca'
    """
    if _lzf_c is not None and out_len > 0 and len(src) > 0:
        try:
            out = _lzf_c.decompress(bytes(src), out_len)
        except ValueError:  # corrupt: the Python decoder below says where
            out = None
        if out is not None and len(out) == out_len:
            return out
    return lzf_decompress_py(src, out_len)


def lzf_decompress_py(src: bytes, out_len: int) -> bytes:
    """Pure-Python :func:`lzf_decompress`, the fallback without ``python-lzf``.

    The loop runs once per LZF token (a literal run of up to 32 bytes or a back reference),
    copying whole slices; overlapping back references are expanded as repeated patterns.

    Raises
    ------
    ValueError
        When the stream is corrupt or does not decompress to ``out_len`` bytes.

    Examples
    --------
    >>> lzf_decompress_py(bytes([2]) + b"abc" + bytes([0xA0, 2]), 10)
    b'abcabcabca'
    """
    out = bytearray(out_len)
    ip, op, n = 0, 0, len(src)
    while ip < n:
        ctrl = src[ip]
        ip += 1
        if ctrl < 32:
            ln = ctrl + 1
            if ip + ln > n or op + ln > out_len:
                raise ValueError("literal run past the end of the data")
            out[op : op + ln] = src[ip : ip + ln]
            ip += ln
            op += ln
            continue
        ln = ctrl >> 5
        ref = op - ((ctrl & 0x1F) << 8) - 1
        if ln == 7:
            if ip >= n:
                raise ValueError("back reference past the end of the data")
            ln += src[ip]
            ip += 1
        if ip >= n:
            raise ValueError("back reference past the end of the data")
        ref -= src[ip]
        ip += 1
        ln += 2
        if ref < 0 or op + ln > out_len:
            raise ValueError("back reference outside the output")
        dist = op - ref
        if dist >= ln:
            out[op : op + ln] = out[ref : ref + ln]
        else:
            pat = bytes(out[ref:op])
            out[op : op + ln] = (pat * (ln // dist + 1))[:ln]
        op += ln
    if op != out_len:
        raise ValueError(f"decompressed {op} bytes, expected {out_len}")
    return bytes(out)


def _parse_header(path: Path):
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    fields: dict[str, list[str]] = {}
    pos = 0
    lineno = 0
    while True:
        nl = head.find(b"\n", pos)
        if nl < 0:
            raise InvalidInputError(
                "no DATA line in the PCD header" if fields else "not a PCD file (no PCD header keywords)",
                "check the file type; PCD files start with VERSION/FIELDS/... lines", path=path,
                field="DATA" if fields else "magic",
            )
        line = head[pos:nl].decode("ascii", errors="replace").strip()
        pos = nl + 1
        lineno += 1
        if not line:
            continue
        if line.startswith("#"):
            crs = crs_from_comment(line[1:])
            if crs:
                fields["#crs"] = [crs]
            continue
        tok = line.split()
        key = tok[0].upper()
        if key not in _KEYS:
            raise InvalidInputError(
                f"not a PCD file: unexpected header line {lineno} '{line[:40]}'",
                "check the file type", path=path, field="magic" if not fields else "header",
            )
        fields[key] = tok[1:]
        if key == "DATA":
            return fields, pos, lineno


def _layout(h: dict, path: Path):
    names = h.get("FIELDS") or h.get("COLUMNS")
    if not names:
        raise InvalidInputError("no FIELDS line in the PCD header", path=path, field="FIELDS")
    nf = len(names)
    sizes = h.get("SIZE", ["4"] * nf)
    types = h.get("TYPE", ["F"] * nf)
    counts = h.get("COUNT", ["1"] * nf)
    if not (len(sizes) == len(types) == len(counts) == nf):
        raise InvalidInputError(
            f"FIELDS has {nf} names but SIZE/TYPE/COUNT have {len(sizes)}/{len(types)}/{len(counts)} entries",
            "repair the header", path=path, field="FIELDS",
        )
    out = []
    for name, s, t, c in zip(names, sizes, types, counts):
        try:
            code = _TYPE[(t.upper(), int(s))]
        except (KeyError, ValueError):
            raise InvalidInputError(f"unsupported TYPE {t} SIZE {s}", "PCD types are I/U 1,2,4,8 and F 4,8", path=path, field=name) from None
        count = _header_int(c, path, "COUNT")
        if count < 1 or (name in ("x", "y", "z") and count != 1):
            raise InvalidInputError(f"COUNT {count} for field '{name}'", "COUNT is 1 or more (exactly 1 for x, y, z)",
                                    path=path, field="COUNT")
        out.append((name, code, count))
    width = _header_int((h.get("WIDTH") or ["0"])[0], path, "WIDTH")
    height = _header_int((h.get("HEIGHT") or ["1"])[0], path, "HEIGHT")
    points = _header_int(h["POINTS"][0], path, "POINTS") if h.get("POINTS") else width * height
    if h.get("WIDTH") and width * height != points:
        raise InvalidInputError(
            f"WIDTH {width:,} x HEIGHT {height:,} is not POINTS {points:,}",
            "PCL requires WIDTH x HEIGHT = POINTS (HEIGHT 1 for an unorganised cloud); repair the header",
            path=path, field="WIDTH",
        )
    try:
        viewpoint = [float(v) for v in h.get("VIEWPOINT", ["0", "0", "0", "1", "0", "0", "0"])]
    except ValueError as e:
        raise InvalidInputError(f"bad VIEWPOINT ({e})", "VIEWPOINT is tx ty tz qw qx qy qz", path=path, field="VIEWPOINT") from None
    return out, width, height, points, viewpoint


def _header_int(text: str, path: Path, key: str) -> int:
    """A non-negative decimal integer of the header (``key`` names it in the error)."""
    if not text.isascii() or not text.isdigit():
        raise InvalidInputError(f"{key} is {text[:20]!r}, not a non-negative integer", "repair the header",
                                path=path, field=key)
    return int(text)


def _dtype(layout) -> np.dtype:
    return np.dtype([(name if name != "_" else f"_pad{i}", "<" + code, (count,) if count > 1 else ()) for i, (name, code, count) in enumerate(layout)])


def _check_ascii_body(path, body: bytes, points: int) -> None:
    """An ascii body must be text with exactly ``points`` non-empty lines (checked before parsing)."""
    bad = first_non_ascii(body)
    if bad is not None:
        raise InvalidInputError(
            f"DATA ascii but the body is not ascii text (byte 0x{bad[1]:02x} at body offset {bad[0]:,})",
            "the file is binary (fix the DATA line) or corrupt", path=path, field="DATA",
        )
    lines = count_data_lines(body)
    if lines != points:
        raise InvalidInputError(
            f"POINTS says {points:,} but the body holds {'only ' if lines < points else ''}{lines:,} lines",
            "the file is truncated or POINTS is wrong" if lines < points else "POINTS is wrong; fix it to match the data",
            path=path, field="POINTS",
        )


def _read_ascii(path, body: bytes, layout, points: int, first_line: int) -> dict[str, np.ndarray]:
    total = sum(c for _, _, c in layout)
    _check_ascii_body(path, body, points)
    try:
        arr = np.loadtxt(io.BytesIO(body), dtype=np.float64, ndmin=2, max_rows=points, comments=None)
    except (ValueError, OverflowError) as e:
        line = loadtxt_error_line(str(e), first_line)
        raise InvalidInputError(
            f"cannot parse{f' line {line}' if line else ''}: {e}", f"each point line needs {total} numbers",
            path=path, field="DATA",
        ) from None
    if arr.shape[0] < points:
        raise InvalidInputError(
            f"POINTS says {points} but the body holds only {arr.shape[0]} lines",
            "the file is truncated or POINTS is wrong", path=path, field="POINTS",
        )
    if points and arr.shape[1] != total:
        raise InvalidInputError(f"lines have {arr.shape[1]} values but the fields need {total}", path=path, field="FIELDS")
    out = {}
    col = 0
    for name, code, count in layout:
        v = arr[:, col : col + count] if count > 1 else arr[:, col]
        col += count
        if name == "_":
            continue
        if name in ("rgb", "rgba"):
            # PCL writes packed colours as unsigned integers in ascii, older writers as floats.
            if v.size and np.all(np.isfinite(v)) and np.array_equal(v, np.trunc(v)) and v.min() >= 0 and v.max() < 2**32:
                v = v.astype(np.uint32)
            else:
                v = v.astype(np.float32).view(np.uint32)
        elif np.dtype(code).kind in "iu":
            v = v.astype(code)
        else:
            v = v.astype(code) if code == "f4" else v
        out[name] = v
    return out


def _read_binary(path, data: bytes, layout, points: int) -> dict[str, np.ndarray]:
    dt = _dtype(layout)
    need = points * dt.itemsize
    if len(data) != need and looks_like_numbers(data):
        raise InvalidInputError("DATA binary but the body is ascii text", "fix the DATA line (DATA ascii)", path=path, field="DATA")
    if len(data) < need:
        raise InvalidInputError(
            f"POINTS says {points} ({need} bytes) but the body holds only {len(data) // max(dt.itemsize, 1)} points",
            "the file is truncated or POINTS is wrong", path=path, field="POINTS",
        )
    if len(data) - need >= dt.itemsize:
        raise InvalidInputError(
            f"POINTS says {points:,} but the body holds {len(data) // dt.itemsize:,} points",
            "POINTS is wrong; fix it to match the data", path=path, field="POINTS",
        )
    rec = np.frombuffer(data, dtype=dt, count=points)
    return {name: rec[name] for name, _, _ in layout if name != "_"}


def _read_compressed(path, data: bytes, layout, points: int) -> dict[str, np.ndarray]:
    if len(data) < 8:
        raise InvalidInputError("binary_compressed body shorter than its 8-byte size header", path=path, field="DATA")
    csize, usize = (int(v) for v in np.frombuffer(data[:8], "<u4"))
    sizes = [np.dtype(code).itemsize * count for _, code, count in layout]
    if usize != points * sum(sizes):
        raise InvalidInputError(
            f"compressed body holds {usize} bytes, but {points} points of {sum(sizes)} bytes need {points * sum(sizes)}",
            "POINTS or the fields are wrong", path=path, field="POINTS",
        )
    if len(data) - 8 < csize:
        raise InvalidInputError("binary_compressed body is truncated", "get the file again", path=path, field="DATA")
    if usize > _LZF_MAX_RATIO * csize:
        raise InvalidInputError(
            f"{csize:,} compressed bytes cannot hold {usize:,} bytes of points (LZF expands at most {_LZF_MAX_RATIO}x)",
            "POINTS or the compressed size is wrong; the file is corrupt", path=path, field="POINTS",
        )
    try:
        raw = lzf_decompress(data[8 : 8 + csize], usize)
    except ValueError as e:
        raise InvalidInputError(f"corrupt LZF data: {e}", "get the file again", path=path, field="DATA") from None
    out = {}
    off = 0
    for (name, code, count), size in zip(layout, sizes):
        if name != "_":
            v = np.frombuffer(raw, dtype="<" + code, count=points * count, offset=off)
            out[name] = v.reshape(points, count) if count > 1 else v
        off += points * size
    return out


def read(path) -> Cloud:
    """Read a PCD file as a cloud.

    Parameters
    ----------
    path : path-like
        A PCD file (DATA ascii, binary or binary_compressed).

    Returns
    -------
    Cloud
        Attributes as in the module table; ``meta["pcd"]`` with ``version``, ``data``,
        ``width``, ``height``, ``viewpoint`` (tx ty tz qw qx qy qz), ``types``
        (attribute -> [field, TYPE+SIZE]) and ``dropped_invalid``.

    Raises
    ------
    InvalidInputError
        Not a PCD header, inconsistent FIELDS/SIZE/TYPE/COUNT, POINTS disagreeing with the
        data, missing x/y/z, unparsable values; the message names the file and field.
    """
    path = Path(path)
    h, body_off, nlines = _parse_header(path)
    layout, width, height, points, viewpoint = _layout(h, path)
    names = [n for n, _, _ in layout]
    for c in "xyz":
        if c not in names:
            raise InvalidInputError(
                f"no '{c}' field (fields: {' '.join(names)})", "a point cloud PCD needs x, y and z", path=path, field=c
            )
    mode = (h["DATA"] or [""])[0].lower()
    cols = _read_body(path, mode, body_off, nlines, layout, points)
    ftype = {n: ({"i": "I", "u": "U", "f": "F"}[code[0]] + str(np.dtype(code).itemsize)) for n, code, _ in layout}
    xyz = np.column_stack([cols[c].astype(np.float64) for c in "xyz"]) if points else np.empty((0, 3))
    valid = np.isfinite(xyz).all(axis=1)
    dropped = int(points - np.count_nonzero(valid))
    if dropped:
        log.warning("%s: %d of %d points have NaN coordinates (invalid, PCL convention) and are dropped", path, dropped, points)
        xyz = xyz[valid]
    attrs, types = _attributes(cols, names, ftype, valid if dropped else None)
    meta = {
        "format": "pcd",
        "pcd": {
            "version": (h.get("VERSION") or ["?"])[0],
            "data": mode,
            "width": width,
            "height": height,
            "viewpoint": viewpoint,
            "types": types,
            "dropped_invalid": dropped,
        },
    }
    return build_cloud(path, xyz, attrs, meta, crs=(h.get("#crs") or [None])[0])


def _read_body(path: Path, mode: str, body_off: int, nlines: int, layout, points: int) -> dict[str, np.ndarray]:
    """The fields of the body after the header (``body_off`` bytes, ``nlines`` lines), by its
    DATA ``mode``: ascii, binary or binary_compressed; an empty cloud gives empty fields."""
    with open(path, "rb") as f:
        f.seek(body_off)
        data = f.read()
    if points == 0 and (mode != "ascii" or not data.strip()) and (mode != "binary" or len(data) < _dtype(layout).itemsize):
        return {n: np.empty((0, c) if c > 1 else 0, dtype=code) for n, code, c in layout}
    if mode == "ascii":
        return _read_ascii(path, data, layout, points, nlines + 1)
    if mode == "binary":
        return _read_binary(path, data, layout, points)
    if mode == "binary_compressed":
        return _read_compressed(path, data, layout, points)
    raise UnsupportedFormatError(
        f"unknown DATA type '{mode}'", "PCD DATA is ascii, binary or binary_compressed", path=path, field="DATA"
    )


def _sel(v, keep: np.ndarray | None) -> np.ndarray:
    """``v`` as an array, restricted to the points with valid coordinates when some were dropped."""
    v = np.asarray(v)
    return v if keep is None else v[keep]


def _attributes(cols: dict, names: list[str], ftype: dict, keep: np.ndarray | None) -> tuple[dict, dict]:
    """Map the PCD fields other than x, y, z onto cloud attributes: colour (:func:`_colour`),
    normals, ``intensity`` and ``label`` (-> ``classification``), other fields under their
    canonical name when they have one, else their own (``_pcd`` added on a clash). Returns
    ``(attrs, types)``; ``types`` maps each attribute to its PCD field(s) and TYPE+SIZE."""
    attrs: dict[str, np.ndarray] = {}
    types: dict[str, list] = {"xyz": [["x", "y", "z"], ftype["x"]]}
    used = {"x", "y", "z", "_"}
    _colour(cols, ftype, keep, attrs, types, used)
    if all(c in cols for c in _NORMALS):
        attrs["normal"] = np.column_stack([_sel(cols[c], keep) for c in _NORMALS]).astype(np.float32)
        types["normal"] = [list(_NORMALS), ftype["normal_x"]]
        used.update(_NORMALS)
    for src, canonical in (("intensity", "intensity"), ("label", "classification")):
        if src in cols and np.ndim(cols[src]) == 1:
            mapped_attr(attrs, types, canonical, src, _sel(cols[src], keep), ftype[src])
            used.add(src)
    for name in names:
        if name in used:
            continue
        v = _sel(cols[name], keep)
        canonical = scalar_canonical(name)
        if canonical is not None and canonical not in attrs and v.ndim == 1:
            mapped_attr(attrs, types, canonical, name, v, ftype[name])
        else:
            key = name if name not in attrs else f"{name}_pcd"
            attrs[key] = np.ascontiguousarray(v)
            types[key] = [name, ftype[name]]
    return attrs, types


def _colour(cols: dict, ftype: dict, keep: np.ndarray | None, attrs: dict, types: dict, used: set) -> None:
    """Fill ``rgb`` (uint16) and ``alpha`` from 16-bit ``r16 g16 b16`` fields (this writer's, for
    colour that is not 8-bit) or from PCL's packed ``rgb``/``rgba`` (one 32-bit value: alpha,
    red, green, blue bytes; float or integer typed), recording the fields in ``types``/``used``."""
    if all(f"{ch}16" in cols for ch in "rgb"):
        attrs["rgb"] = np.column_stack([_sel(cols[f"{ch}16"], keep).astype(np.uint16) for ch in "rgb"])
        types["rgb"] = [["r16", "g16", "b16"], "U2"]
        used.update(("r16", "g16", "b16", "rgb"))
        if "rgba" in cols:
            attrs["alpha"] = ((_sel(cols["rgba"], keep).astype(np.uint32) >> 24) & 0xFF).astype(np.uint8)
            used.add("rgba")
    for packed in ("rgb", "rgba"):
        if packed in cols and "rgb" not in attrs:
            p = _sel(cols[packed], keep)
            p = p.view(np.uint32) if p.dtype.itemsize == 4 else p.astype(np.uint32)
            attrs["rgb"] = np.column_stack([rgb_to_u16(((p >> s) & 0xFF).astype(np.uint8), np.uint8) for s in (16, 8, 0)])
            types["rgb"] = [packed, ftype[packed]]
            if packed == "rgba":
                attrs["alpha"] = ((p >> 24) & 0xFF).astype(np.uint8)
            used.add(packed)


def _field_type(dtype) -> tuple[str, int]:
    dt = np.dtype(dtype)
    if dt.kind == "b":
        return "U", 1
    if dt.kind == "f":
        return "F", max(dt.itemsize, 4)
    if dt.kind in "iu":
        return ("I" if dt.kind == "i" else "U"), dt.itemsize
    raise InvalidInputError(f"dtype {dt} has no PCD type", "cast it to a number")


def _fields(cloud: Cloud, xyz_type: str, ascii: bool):
    """(name, TYPE, SIZE, values (n,) or (n, k)) for every field to write."""
    types = dict((cloud.meta.get("pcd") or {}).get("types", {}))
    if xyz_type == "auto":
        xyz_type = "float" if fits_exactly(cloud.xyz, np.float32) else "double"
    size = 8 if xyz_type == "double" else 4
    out = [(c, "F", size, cloud.xyz[:, i]) for i, c in enumerate("xyz")]
    for name, arr in cloud.attrs.items():
        if name == "rgb":
            exact8 = not np.any(arr % 257)
            if exact8:
                c8 = (arr // 257).astype(np.uint32)
            else:
                # PCL colour is 8-bit: pack what a viewer should show (values already below 256
                # are 8-bit colour stored in 16-bit fields, as in many LAS files), and keep the
                # exact 16-bit values in r16/g16/b16 fields that this reader prefers.
                c8 = (arr if arr.max(initial=0) <= 255 else np.round(arr / 257.0)).astype(np.uint32)
                out.extend((f"{ch}16", "U", 2, arr[:, i]) for i, ch in enumerate("rgb"))
            packed = (c8[:, 0] << 16) | (c8[:, 1] << 8) | c8[:, 2]
            if "alpha" in cloud.attrs and cloud.attrs["alpha"].ndim == 1:
                packed |= cloud.attrs["alpha"].astype(np.uint32) << 24
                out.append(("rgba", "U", 4, packed))
            elif ascii:
                out.append(("rgb", "U", 4, packed))  # an integer in the text, as PCL writes it
            else:
                out.append(("rgb", "F", 4, packed.view(np.float32)))
        elif name == "alpha" and "rgb" in cloud.attrs:
            continue
        elif name == "normal":
            out.extend((c, "F", 4, arr[:, i]) for i, c in enumerate(_NORMALS))
        else:
            src = types.get(name)
            if src and isinstance(src[0], str) and src[1][0] in "IUF":
                code = _TYPE.get((src[1][0], int(src[1][1:])))
                if code and fits_exactly(arr, code):
                    out.append((src[0], src[1][0], int(src[1][1:]), arr))
                    continue
            if name == "intensity":
                out.append(("intensity", "F", 4, arr))
            elif name == "classification":
                out.append(("label", "U", 4, arr))
            else:
                t, s = _field_type(arr.dtype)
                out.append((name.replace(" ", "_"), t, s, arr))
    seen = set()
    for name, *_ in out:
        if name in seen:
            raise InvalidInputError(f"two attributes would both be written as PCD field '{name}'", field=name)
        seen.add(name)
    return out


def write(cloud: Cloud, path, *, ascii: bool = False, xyz_type: str = "auto") -> None:
    """Write a cloud as PCD v0.7 (unorganised: WIDTH = points, HEIGHT = 1).

    Parameters
    ----------
    cloud : Cloud
    path : path-like
    ascii : bool
        DATA ascii instead of binary (default binary).
    xyz_type : {"auto", "double", "float"}
        Coordinates as F 8 or F 4 (what PCL point types such as ``PointXYZ`` expect).
        ``auto`` (default) writes F 4 when every coordinate is a float32 value (nothing is
        lost), else F 8, so georeferenced coordinates stay exact.

    Notes
    -----
    ``rgb`` is packed into the PCL ``rgb`` field (8 bits per channel; F 4 in binary, U 4 so
    that the text holds the integer in ascii), or into ``rgba`` (U 4) with the ``alpha`` attribute; ``normal`` becomes
    normal_x/y/z; ``intensity`` F 4 and ``classification`` as ``label`` U 4 unless the source
    types are recorded in ``meta["pcd"]``; other attributes keep their name and dtype
    ((n, k) attributes as one field with COUNT k). The VIEWPOINT in ``meta["pcd"]`` is kept.
    Colour that is not 8-bit (values not multiples of 257) is also written exactly as
    ``r16 g16 b16`` (U 2) fields; the packed field then holds the values themselves when
    all are below 256 (8-bit colour kept in 16-bit fields, common in LAS), else value / 257.
    """
    if xyz_type not in ("auto", "double", "float"):
        raise InvalidInputError(f"xyz_type must be 'auto', 'double' or 'float', got {xyz_type!r}", field="xyz_type")
    fields = _fields(cloud, xyz_type, ascii)
    counts = [1 if np.ndim(v) == 1 else int(np.prod(np.shape(v)[1:])) for *_, v in fields]
    viewpoint = (cloud.meta.get("pcd") or {}).get("viewpoint") or [0, 0, 0, 1, 0, 0, 0]
    head = [
        "# .PCD v0.7 - Point Cloud Data file format (written by workstation)",
        *([f"# {crs_line(cloud.crs)}"] if cloud.crs else []),
        "VERSION 0.7",
        "FIELDS " + " ".join(f[0] for f in fields),
        "SIZE " + " ".join(str(f[2]) for f in fields),
        "TYPE " + " ".join(f[1] for f in fields),
        "COUNT " + " ".join(map(str, counts)),
        f"WIDTH {cloud.n}",
        "HEIGHT 1",
        "VIEWPOINT " + " ".join(repr(float(v)) if float(v) != int(float(v)) else str(int(float(v))) for v in viewpoint),
        f"POINTS {cloud.n}",
        f"DATA {'ascii' if ascii else 'binary'}",
    ]
    with open(path, "wb") as f:
        f.write(("\n".join(head) + "\n").encode("ascii"))
        if ascii:
            arrays, formats = [], []
            for (name, t, s, v), k in zip(fields, counts):
                v = np.asarray(v)
                v = v.astype(_TYPE[(t, s)])
                flat = v.reshape(len(v), k)
                for j in range(flat.shape[1]):
                    arrays.append(flat[:, j])
                    formats.append(number_format(flat.dtype))
            f.write(format_rows(arrays, formats, " ").encode("ascii"))
        else:
            dt = np.dtype([(f"f{i}", "<" + _TYPE[(t, s)], (k,) if k > 1 else ()) for i, ((_, t, s, _), k) in enumerate(zip(fields, counts))])
            rec = np.empty(cloud.n, dtype=dt)
            for i, ((_, _, _, v), k) in enumerate(zip(fields, counts)):
                rec[f"f{i}"] = np.asarray(v).reshape(cloud.n, k) if k > 1 else v
            rec.tofile(f)
