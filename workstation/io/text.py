"""Delimited text point clouds: XYZ, TXT, CSV and PTS with a column spec.

Reading
-------
The delimiter is detected from the first data line (semicolon, then comma, else any run
of tabs and spaces). A first line that is not all numbers is a header (a leading ``//`` or
``#`` is dropped); it names the columns when no ``columns=`` spec is given. A ``.pts`` file
may start with a line holding only the point count. The body is parsed in one call of
``np.loadtxt`` (C), never a Python loop per line.

Column names (case-insensitive), in a ``columns="x,y,z,label"`` spec or a header:

=================================  ===========================================================
name                               meaning
=================================  ===========================================================
x, y, z                            coordinates (required)
r, g, b / red, green, blue         ``rgb``: 8-bit values (x 257) unless ``rgb_bits=16`` or a
                                   value exceeds 255
r16, g16, b16                      ``rgb`` as 16-bit values (the writer's names for colour that
                                   is not 8-bit, so a file reads back exactly)
nx, ny, nz / normal_x ..           ``normal``
intensity, classification,         the canonical attribute when every value fits its dtype,
gps_time, return_number, ...       else a free float attribute (``intensity_raw``)
label                              a free attribute ``label`` with the raw values (int32 when
                                   integral), never remapped to ASPRS classes
attr:NAME                          a free float attribute ``NAME``
skip (or _)                        ignore this column
=================================  ===========================================================

An unknown name in a ``columns`` spec is an error; an unknown name in a header becomes a
free attribute. Without a spec or header the default depends on the column count:
3: ``x,y,z``; 4: ``x,y,z,intensity``; 6: ``x,y,z,r,g,b``; 7: ``x,y,z,intensity,r,g,b``
(the usual XYZ, XYZI, XYZRGB and PTS layouts); other counts need a spec.
"""

from __future__ import annotations

import io
import math
import re
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.dims import canonical_name
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

from ._fields import SCALAR_DIMS, build_cloud, check_utf8, format_rows, loadtxt_error_line, mapped_attr, number_format

log = get_logger(__name__)

#: Column layout assumed when a file has neither a spec nor a header, by column count.
DEFAULT_COLUMNS = {
    3: ("x", "y", "z"),
    4: ("x", "y", "z", "intensity"),
    6: ("x", "y", "z", "r", "g", "b"),
    7: ("x", "y", "z", "intensity", "r", "g", "b"),
}
_XYZ = {"x": 0, "y": 1, "z": 2}
_RGB = {"r": 0, "g": 1, "b": 2, "red": 0, "green": 1, "blue": 2}
_RGB16 = {"r16": 0, "g16": 1, "b16": 2, "red16": 0, "green16": 1, "blue16": 2}
_NORMAL = {"nx": 0, "ny": 1, "nz": 2, "normal_x": 0, "normal_y": 1, "normal_z": 2}
_SKIP = {"skip", "_"}
_SNIFF_BYTES = 1 << 16


def _is_number(tok: str) -> bool:
    try:
        float(tok)
    except ValueError:
        return False
    return True


def _resolve(name: str, *, strict: bool, path) -> tuple[str, object]:
    """(kind, target) of one column name: kinds xyz, rgb, normal, dim, label, free, skip."""
    raw = name.strip()
    low = raw.lower()
    if low in _SKIP:
        return "skip", None
    if low in _XYZ:
        return "xyz", _XYZ[low]
    if low in _RGB:
        return "rgb", _RGB[low]
    if low in _RGB16:
        return "rgb16", _RGB16[low]
    if low in _NORMAL:
        return "normal", _NORMAL[low]
    if low == "label":
        return "label", "label"
    if low.startswith("attr:") and len(raw) > 5:
        return "free", raw[5:]
    canon = canonical_name(low)
    if canon in SCALAR_DIMS:
        return "dim", canon
    if strict:
        known = sorted({"x", "y", "z", "r", "g", "b", "nx", "ny", "nz", "label", "skip", *SCALAR_DIMS})
        raise InvalidInputError(
            f"unknown column name '{raw}' in the column spec",
            f"use one of {', '.join(known)}, or attr:NAME to keep a column under your own name",
            path=path, field=raw,
        )
    return "free", raw


def _split(line: str, delimiter: str | None) -> list[str]:
    return [t.strip() for t in (line.split(delimiter) if delimiter else line.split())]


def _sniff(head: str, path: Path, delimiter: str | None):
    """(first data line index, header names or None, delimiter, column count, pts count)."""
    lines = head.splitlines()
    i = 0
    while i < len(lines) and not lines[i].strip():
        i += 1
    if i == len(lines):
        raise InvalidInputError("no data lines", "the file holds no points", path=path)
    header = None
    pts_count = None
    first = lines[i].strip()
    toks = first.split()
    if len(toks) == 1 and re.fullmatch(r"\d+", toks[0]) and i + 1 < len(lines) and len(lines[i + 1].split()) > 1:
        pts_count = int(toks[0])  # Leica PTS: a point count line
        i += 1
    else:
        stripped = re.sub(r"^(//|#)\s*", "", first)
        d = delimiter if delimiter is not None else _detect_delimiter(stripped)
        if not all(_is_number(t) for t in _split(stripped, d) if t):
            header = [t for t in _split(stripped, d) if t]
            i += 1
    while i < len(lines) and not lines[i].strip():
        i += 1
    if i == len(lines):
        raise InvalidInputError("no data lines after the header", "the file holds no points", path=path)
    data_line = lines[i]
    d = delimiter if delimiter is not None else _detect_delimiter(data_line)
    ncols = len(_split(data_line.strip(), d))
    return i, header, d, ncols, pts_count


def _detect_delimiter(line: str) -> str | None:
    for d in (";", ",", "\t"):
        if d in line:
            return d if d != "\t" else None
    return None


def read(path, *, columns=None, delimiter: str | None = None, rgb_bits: int | None = None) -> Cloud:
    """Read a delimited text point cloud.

    Parameters
    ----------
    path : path-like
        .xyz, .txt, .csv or .pts file.
    columns : str or sequence of str, optional
        Column spec, comma separated (``"x,y,z,label"``); names as in the module table. It
        may name fewer columns than the file has (the rest are ignored), not more.
    delimiter : str, optional
        Column separator; detected when omitted (None also means any whitespace).
    rgb_bits : {8, 16}, optional
        Bit depth of r, g, b columns; detected when omitted (16 when a value exceeds 255).

    Returns
    -------
    Cloud
        ``meta["text"]`` holds the resolved ``columns``, ``delimiter``, ``header`` and
        ``rgb_bits``.

    Raises
    ------
    InvalidInputError
        A spec naming more columns than the file has, an unknown spec name, a missing x/y/z,
        a non-numeric value or a ragged line (the message gives the line number).
    """
    path = Path(path)
    data = path.read_bytes()
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    check_utf8(data, path)
    head = data[:_SNIFF_BYTES].decode("utf-8", errors="replace")
    first, header, delim, ncols, pts_count = _sniff(head, path, delimiter)
    names, strict = _column_names(columns, header, ncols, path)
    kinds = _resolve_columns(names, strict, path)
    use = [i for i, (k, _) in enumerate(kinds) if k != "skip"]
    arr = _load_numbers(data, delim, first, use, ncols, path)
    n = arr.shape[0]
    if pts_count is not None and pts_count != n:
        log.warning("%s: the count line says %d points but %d were read", path, pts_count, n)
    xyz, attrs, bits = _columns_to_fields(kinds, names, {i: arr[:, j] for j, i in enumerate(use)}, n, rgb_bits, path)
    meta = {
        "format": path.suffix.lower().lstrip(".") or "txt",
        "text": {"columns": names, "delimiter": delim, "header": header is not None, "rgb_bits": bits},
    }
    return build_cloud(path, xyz, attrs, meta)


def _column_names(columns, header: list[str] | None, ncols: int, path: Path) -> tuple[list[str], bool]:
    """The column names and whether unknown names are errors: a given spec (strict), else the
    file's header, else :data:`DEFAULT_COLUMNS` by column count. A spec or header naming more
    columns than the file has is an error."""
    if columns is not None:
        names = [c.strip() for c in columns.split(",")] if isinstance(columns, str) else [str(c).strip() for c in columns]
        strict = True
    elif header is not None:
        names, strict = header, False
    elif ncols in DEFAULT_COLUMNS:
        names, strict = list(DEFAULT_COLUMNS[ncols]), False
    else:
        raise InvalidInputError(
            f"cannot guess the meaning of {ncols} columns",
            "pass a column spec, e.g. columns='x,y,z,intensity,skip' (see workstation.io.text)",
            path=path, field="columns",
        )
    if len(names) > ncols:
        raise InvalidInputError(
            f"missing column '{names[ncols]}' (file has {ncols} columns)",
            f"the spec names {len(names)} columns: {','.join(names)}",
            path=path, field=names[ncols],
        )
    return names, strict


def _resolve_columns(names: list[str], strict: bool, path: Path) -> list[tuple[str, object]]:
    """``(kind, target)`` of every column (:func:`_resolve`); x, y and z must all be present."""
    kinds = [_resolve(n, strict=strict, path=path) for n in names]
    for axis, c in enumerate("xyz"):
        if not any(k == "xyz" and t == axis for k, t in kinds):
            raise InvalidInputError(
                f"no '{c}' column (columns: {','.join(names)})", "name the coordinate columns x, y and z",
                path=path, field=c,
            )
    return kinds


def _load_numbers(data: bytes, delim: str | None, first: int, use: list[int], ncols: int, path: Path) -> np.ndarray:
    """The used columns of the body as an (n, len(use)) float64 array, parsed by one call of
    ``np.loadtxt`` (C); a parse error names the file's line number."""
    try:
        return np.loadtxt(
            io.BytesIO(data), delimiter=delim, skiprows=first, usecols=use, dtype=np.float64, ndmin=2, comments="#",
            encoding="utf-8",
        )
    except ValueError as e:
        msg = str(e)
        line = loadtxt_error_line(msg, first + 1)
        raise InvalidInputError(
            f"cannot parse{f' line {line}' if line else ''}: {msg}",
            f"every line needs {ncols} numeric columns separated by {delim or 'whitespace'!r}",
            path=path, field="columns",
        ) from None


def _columns_to_fields(kinds, names: list[str], cols: dict[int, np.ndarray], n: int, rgb_bits: int | None,
                       path: Path) -> tuple[np.ndarray, dict[str, np.ndarray], int | None]:
    """Route each parsed column to its field: ``xyz``, the ``rgb`` and ``normal`` triples,
    canonical attributes (:func:`mapped_attr`), ``label`` (int32 when integral) and free
    attributes. Returns ``(xyz, attrs, rgb_bits)``; ``rgb_bits`` is None without colour."""
    xyz = np.empty((n, 3))
    rgb = np.zeros((n, 3))
    normal = np.zeros((n, 3), dtype=np.float32)
    have_rgb, have_normal = set(), set()
    attrs: dict[str, np.ndarray] = {}
    types: dict[str, list] = {}
    for i, (kind, target) in enumerate(kinds):
        if kind == "skip":
            continue
        v = cols[i]
        if kind == "xyz":
            xyz[:, target] = v
        elif kind in ("rgb", "rgb16"):
            rgb[:, target] = v
            have_rgb.add(target)
            if kind == "rgb16":
                rgb_bits = 16
        elif kind == "normal":
            normal[:, target] = v
            have_normal.add(target)
        elif kind == "dim":
            mapped_attr(attrs, types, target, names[i], v, "f8")
        elif kind == "label":
            attrs["label"] = v.astype(np.int32) if np.array_equal(v, np.trunc(v)) and np.all(np.abs(v) < 2**31) else v
        else:
            attrs[target] = v
    bits = None
    if have_rgb:
        attrs["rgb"], bits = _rgb_attr(rgb, have_rgb, rgb_bits, path)
    if have_normal:
        if have_normal != {0, 1, 2}:
            raise InvalidInputError("normals need all of nx, ny and nz columns", path=path, field="normal")
        attrs["normal"] = normal
    return xyz, attrs, bits


def _rgb_attr(rgb: np.ndarray, have_rgb: set, rgb_bits: int | None, path: Path) -> tuple[np.ndarray, int]:
    """The uint16 ``rgb`` attribute from the r, g, b columns: 8-bit values (x 257) unless
    ``rgb_bits`` is 16 or a value exceeds 255; values must be integers within the bit depth."""
    if have_rgb != {0, 1, 2}:
        raise InvalidInputError("colour needs all of r, g and b columns", path=path, field="rgb")
    bits = rgb_bits or (16 if rgb.size and rgb.max() > 255 else 8)
    if rgb.size and (rgb.min() < 0 or rgb.max() > (255 if bits == 8 else 65535) or not np.array_equal(rgb, np.trunc(rgb))):
        raise InvalidInputError(
            f"colour values {rgb.min()}..{rgb.max()} are not {bits}-bit integers", "check the column spec",
            path=path, field="rgb",
        )
    return rgb.astype(np.uint16) * np.uint16(257 if bits == 8 else 1), bits


def _precision_from_meta(cloud: Cloud) -> int | None:
    scales = (cloud.meta.get("las") or {}).get("scales")
    if not scales:
        return None
    try:
        return max(0, max(math.ceil(-math.log10(float(s)) - 1e-9) for s in scales))
    except (TypeError, ValueError):
        return None


def _default_columns(cloud: Cloud, header: bool) -> list[str]:
    cols = ["x", "y", "z"]
    if "intensity" in cloud.attrs:
        cols.append("intensity")
    if "rgb" in cloud.attrs:
        cols += ["r", "g", "b"]
    if not header:
        # Without a header only the layouts the reader recognises by column count are written.
        rest = [k for k in cloud.attrs if k not in ("intensity", "rgb")]
        if rest:
            log.info("a text file without header holds x,y,z[,intensity][,r,g,b]; not written: %s "
                     "(write .csv/.txt or pass header=True to keep them)", ", ".join(rest))
        return cols
    if "normal" in cloud.attrs:
        cols += ["nx", "ny", "nz"]
    for name, arr in cloud.attrs.items():
        if name in ("intensity", "rgb", "normal"):
            continue
        if arr.ndim == 1:
            cols.append(name)
        else:
            log.warning("attribute '%s' has per-point shape %s and is not written to text", name, arr.shape[1:])
    return cols


def write(
    cloud: Cloud,
    path,
    *,
    columns=None,
    header: bool | None = None,
    precision: int | str | None = None,
    delimiter: str | None = None,
) -> None:
    """Write a cloud as delimited text.

    Parameters
    ----------
    cloud : Cloud
    path : path-like
    columns : str or sequence of str, optional
        Columns to write, names as for :func:`read` (``attr:NAME`` or the plain name for a
        free attribute). Default with a header: x, y, z, intensity, r, g, b, nx, ny, nz when
        present, then every other scalar attribute; without a header only x, y, z,
        intensity, r, g, b (the layouts :data:`DEFAULT_COLUMNS` reads back).
    header : bool, optional
        Write a header line of column names; default True for .csv and .txt, False for .xyz
        and .pts (a .pts file starts with its point count instead).
    precision : int or "exact", optional
        Decimals of the coordinates (``%.{precision}f``). Default: from the LAS scales in
        ``meta["las"]`` when present (0.01 -> 2), else 4. ``"exact"`` writes the shortest
        text that reads back to the same float64.
    delimiter : str, optional
        Default ``,`` for .csv, a space otherwise.

    Notes
    -----
    ``rgb`` is written as 8-bit values (header r, g, b) when every value is a multiple of
    257, else as 16-bit values (header r16, g16, b16).
    Attribute values are written exactly (integers as integers, float32 with 9 significant
    digits, float64 as the shortest exact text).
    """
    path = Path(path)
    ext = path.suffix.lower()
    if header is None:
        header = ext in (".csv", ".txt")
    if delimiter is None:
        delimiter = "," if ext == ".csv" else " "
    coord_fmt = _coord_format(cloud, precision)
    names = _default_columns(cloud, header) if columns is None else (
        [c.strip() for c in columns.split(",")] if isinstance(columns, str) else [str(c) for c in columns]
    )
    arrays, formats, head = _write_columns(cloud, names, coord_fmt, header, path)
    if cloud.crs:
        log.warning("%s: text point files have no place for a CRS; %s is not stored", path.name, cloud.crs[:60])
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        if ext == ".pts" and not header:
            f.write(f"{cloud.n}\n")
        if header:
            f.write(delimiter.join(head) + "\n")
        f.write(format_rows(arrays, formats, delimiter))


def _coord_format(cloud: Cloud, precision: int | str | None) -> str:
    """The printf format of the coordinates: ``%.{precision}f`` (default from the LAS scales in
    ``meta["las"]``, else 4 decimals) or ``%r`` for ``"exact"`` (shortest round-trip text)."""
    if precision is None:
        precision = _precision_from_meta(cloud)
        precision = 4 if precision is None else precision
    if precision == "exact":
        return "%r"
    if isinstance(precision, int) and not isinstance(precision, bool) and 0 <= precision <= 17:
        return f"%.{precision}f"
    raise InvalidInputError(f"precision must be 0..17 or 'exact', got {precision!r}", field="precision")


def _write_columns(cloud: Cloud, names: list[str], coord_fmt: str, header: bool,
                   path: Path) -> tuple[list[np.ndarray], list[str], list[str]]:
    """``(arrays, formats, header names)`` of the columns to write, one per name: coordinates in
    ``coord_fmt``, colour and normal components (:func:`_vector_column`) and scalar attributes
    (:func:`_attr_column`) in their dtype's exact format."""
    rgb = cloud.attrs.get("rgb")
    rgb8 = rgb is not None and not np.any(rgb % 257)
    arrays: list[np.ndarray] = []
    formats: list[str] = []
    head: list[str] = []
    for name in names:
        kind, target = _resolve(name, strict=False, path=path)
        if kind == "xyz":
            arrays.append(cloud.xyz[:, target])
            formats.append(coord_fmt)
        elif kind in ("rgb", "rgb16", "normal"):
            v, name = _vector_column(cloud, kind, target, name, rgb8, header)
            arrays.append(v)
            formats.append(number_format(v.dtype))
        elif kind == "skip":
            raise InvalidInputError("'skip' is for reading; leave the column out", field=name)
        else:
            v = _attr_column(cloud, kind, target, name)
            arrays.append(v)
            formats.append(number_format(v.dtype))
        head.append(name)
    return arrays, formats, head


def _vector_column(cloud: Cloud, kind: str, target: int, name: str, rgb8: bool, header: bool) -> tuple[np.ndarray, str]:
    """One component of ``rgb`` or ``normal`` and its header name: colour as 8-bit values when
    every value is a multiple of 257 (``rgb8``), else as 16-bit values named ``r16``/``g16``/``b16``."""
    src = cloud.attrs.get("rgb" if kind == "rgb16" else kind)
    if src is None:
        raise InvalidInputError(f"column '{name}' asked for but the cloud has no {kind}", field=name)
    v = src[:, target]
    if kind != "normal":
        if rgb8 and kind == "rgb":
            v = v // 257
        else:
            name = "rgb"[target] + "16"  # 16-bit colour says so in the header
            if not header and v.size and v.max() <= 255:
                log.warning("16-bit colours below 256 in a text file without header read back as 8-bit")
    return v, name


def _attr_column(cloud: Cloud, kind: str, target, name: str) -> np.ndarray:
    """The scalar attribute a column names (canonical, ``label`` or free); it must exist and hold
    one value per point."""
    attr = target if kind != "label" else "label"
    if attr not in cloud.attrs:
        raise InvalidInputError(
            f"column '{name}' asked for but the cloud has no such attribute (it has {', '.join(cloud.attrs) or 'none'})",
            field=name,
        )
    v = cloud.attrs[attr]
    if v.ndim != 1:
        raise InvalidInputError(f"attribute has per-point shape {v.shape[1:]}; text holds scalars", field=name)
    return v
