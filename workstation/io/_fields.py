"""Shared helpers of the non-LAS readers and writers (PLY, PCD, text, E57).

Translation between a file's field names and the canonical names of
:mod:`workstation.core.dims` happens here, with casts that are done only when every value
fits the canonical dtype exactly, so no reader silently changes a value.
"""

from __future__ import annotations

import codecs
import re

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.dims import DIMS
from workstation.core.errors import InvalidInputError

# Scalar canonical dimensions a file field can map to by (case-insensitive) name.
SCALAR_DIMS = {name for name, d in DIMS.items() if d.shape == ()}


def fits_exactly(values: np.ndarray, dtype) -> bool:
    """True when every value converts to ``dtype`` without change (range, integrality, finiteness).

    Parameters
    ----------
    values : ndarray
        Any numeric array.
    dtype : numpy dtype
        Target dtype.

    Examples
    --------
    >>> fits_exactly(np.array([0.0, 255.0]), np.uint8), fits_exactly(np.array([0.5]), np.uint8)
    (True, False)
    """
    dtype = np.dtype(dtype)
    values = np.asarray(values)
    if values.size == 0:
        return True
    if dtype.kind in "iu":
        if values.dtype.kind == "b":
            return True
        if values.dtype.kind == "f":
            if not np.all(np.isfinite(values)) or not np.array_equal(values, np.trunc(values)):
                return False
        elif values.dtype.kind not in "iu":
            return False
        info = np.iinfo(dtype)
        return bool(values.min() >= info.min and values.max() <= info.max)
    if dtype.kind == "f":
        if values.dtype.kind == "f" and values.dtype.itemsize <= dtype.itemsize:
            return True
        with np.errstate(over="ignore", invalid="ignore"):
            back = values.astype(dtype).astype(values.dtype)
        return bool(np.array_equal(back, values, equal_nan=values.dtype.kind == "f"))
    return values.dtype == dtype


def free_name(source_name: str, canonical: str) -> str:
    """Name under which a field that does not fit its canonical dtype is kept as a free attribute.

    The source name when it differs from the canonical name (``scalar_intensity``), else
    ``<canonical>_raw`` (a free attribute may not reuse a canonical name).
    """
    return source_name if source_name != canonical and source_name not in DIMS else f"{canonical}_raw"


def rgb_to_u16(values: np.ndarray, source_dtype) -> np.ndarray:
    """Colour channels in a file's type to the canonical 16-bit ``rgb``.

    8-bit values are multiplied by 257 (255 -> 65535), 16-bit kept, floats in [0, 1] scaled
    by 65535 and rounded; anything else is clipped to 0..65535.
    """
    dt = np.dtype(source_dtype)
    v = np.asarray(values)
    if dt.kind in "iu" and dt.itemsize == 1:
        return v.astype(np.uint16) * np.uint16(257)
    if dt.kind == "f":
        if v.size and np.nanmax(v) <= 1.0:
            return np.round(np.clip(v, 0, 1) * 65535.0).astype(np.uint16)
        return np.round(np.clip(v, 0, 65535)).astype(np.uint16)
    return np.clip(v, 0, 65535).astype(np.uint16)


def rgb_from_u16(rgb: np.ndarray, source_dtype) -> np.ndarray | None:
    """Inverse of :func:`rgb_to_u16` when exact, else None (the writer then keeps 16 bits)."""
    dt = np.dtype(source_dtype)
    if dt.kind in "iu" and dt.itemsize == 1:
        return (rgb // 257).astype(dt) if not np.any(rgb % 257) else None
    if dt.kind == "f":
        out = (rgb.astype(np.float64) / 65535.0).astype(dt)
        return out if np.array_equal(np.round(out.astype(np.float64) * 65535.0), rgb) else None
    return rgb.astype(dt) if fits_exactly(rgb, dt) else None


def scalar_canonical(name: str) -> str | None:
    """Canonical scalar dimension for a file field name (case-insensitive), else None."""
    low = name.lower()
    return low if low in SCALAR_DIMS else None


def build_cloud(path, xyz, attrs, meta, crs: str | None = None) -> Cloud:
    """Build a :class:`Cloud`, re-raising validation errors with the file named."""
    try:
        return Cloud(xyz, attrs, crs=crs, meta=meta)
    except InvalidInputError as e:
        if e.path is not None:
            raise
        err = InvalidInputError(e.message, e.hint, path=path)
        err.field = e.field
        raise err from None


def crs_line(crs: str | None) -> str | None:
    """The CRS as one line for a header comment (``crs EPSG:32632`` or flattened WKT)."""
    if not crs:
        return None
    return "crs " + " ".join(crs.split())


def crs_from_comment(comment: str) -> str | None:
    """Inverse of :func:`crs_line` for a comment's text, else None."""
    text = comment.strip()
    return text[4:].strip() or None if text.startswith("crs ") else None


def mapped_attr(attrs: dict, types: dict, canonical: str, source_name: str, values, source_type: str) -> None:
    """Store ``values`` under ``canonical`` when they fit its dtype, else as a free attribute.

    ``types`` receives ``{attr name: [source name, source type]}`` for the writer.
    """
    dt = DIMS[canonical].dtype
    values = np.asarray(values)
    if dt.kind == "f" and values.dtype.kind in "fiu":
        with np.errstate(over="ignore"):
            cast = values.astype(dt)  # a float dimension keeps its table precision
        if np.array_equal(np.isfinite(cast), np.isfinite(values)):
            attrs[canonical] = cast
            types[canonical] = [source_name, source_type]
            return
    if fits_exactly(values, dt):
        attrs[canonical] = np.asarray(values).astype(dt)
        types[canonical] = [source_name, source_type]
    else:
        name = free_name(source_name, canonical)
        attrs[name] = np.asarray(values)
        types[name] = [source_name, source_type]


def writable_columns(cloud: Cloud, allowed_kinds: str = "biuf") -> list[tuple[str, np.ndarray]]:
    """Every attribute as (name, (n,) array) columns; (n, k) free attributes become ``name_0..``."""
    out = []
    for name, arr in cloud.attrs.items():
        if arr.dtype.kind not in allowed_kinds:
            raise InvalidInputError(f"dtype {arr.dtype} cannot be written", "cast it to a number", field=name)
        if arr.ndim == 1:
            out.append((name, arr))
        else:
            flat = arr.reshape(arr.shape[0], -1)
            out.extend((f"{name}_{i}", flat[:, i]) for i in range(flat.shape[1]))
    return out


def format_rows(columns: list[np.ndarray], formats: list[str], sep: str) -> str:
    """Rows of text, one per point, joined by newlines (with a final newline).

    The formatting runs in C (``str.__mod__`` mapped over zipped column lists), not in a
    Python loop per point.
    """
    if not columns or len(columns[0]) == 0:
        return ""
    fmt = sep.join(formats)
    lists = [c.tolist() for c in columns]
    return "\n".join(map(fmt.__mod__, zip(*lists))) + "\n"


def loadtxt_error_line(message: str, first_line: int) -> int | None:
    """1-based file line of a ``np.loadtxt`` error, given the file line of its first row.

    numpy counts rows from 0 in conversion errors and from 1 in column-count errors (blank
    lines are not counted, so the line is exact for files without blank lines).
    """
    import re

    m = re.search(r"at row (\d+)", message)
    if m is None:
        return None
    row = int(m.group(1))
    return first_line + row - (0 if "could not convert" in message else 1)


def number_format(dtype) -> str:
    """A printf format that writes a value of ``dtype`` so it reads back exactly."""
    dt = np.dtype(dtype)
    if dt.kind in "iub":
        return "%d"
    if dt.kind == "f" and dt.itemsize <= 4:
        return "%.9g"
    return "%r"


_NUMBER_BYTES = np.zeros(256, dtype=bool)
_NUMBER_BYTES[list(b"0123456789+-.eEinfaINFA \t\r\n")] = True


def looks_like_numbers(body) -> bool:
    """True when the first 64 KB of a body hold only the characters of ascii numbers
    (a binary body labelled so by mistake almost never does)."""
    head = np.frombuffer(memoryview(body)[: 1 << 16], dtype=np.uint8)
    return bool(head.size) and bool(_NUMBER_BYTES[head].all())


_TEXT_CHARS = bytes(range(0x20, 0x7F)) + b"\t\n\r"


def first_non_ascii(body: bytes) -> tuple[int, int] | None:
    """(offset, value) of the first byte of ``body`` that is not printable ascii text
    (tab, CR and LF allowed), else None. ``bytes.translate`` drops the text bytes in C, so
    only the offending bytes are copied."""
    rest = body.translate(None, _TEXT_CHARS)
    if not rest:
        return None
    return body.find(rest[:1]), rest[0]


def count_data_lines(body: bytes) -> int:
    """Number of lines of ``body`` that hold more than whitespace (what ``np.loadtxt`` parses)."""
    stripped = body.strip()
    if not stripped:
        return 0
    blank = len(re.findall(rb"\n[ \t\r]*(?=\n)", stripped))
    return stripped.count(b"\n") + 1 - blank


def check_utf8(data: bytes, path) -> None:
    """Raise :class:`InvalidInputError` naming the file, line and byte when ``data`` is not UTF-8.

    Pure-ascii data is accepted at once (``bytes.isascii`` runs in C); other data is decoded
    in 16 MB slices so that no second copy of a large file is held.
    """
    if data.isascii():
        return
    dec = codecs.getincrementaldecoder("utf-8")()
    view = memoryview(data)
    step = 1 << 24
    for start in range(0, len(data), step):
        pending = len(dec.getstate()[0])
        try:
            dec.decode(view[start : start + step], final=start + step >= len(data))
        except UnicodeDecodeError as e:
            at = start - pending + e.start
            line = data.count(b"\n", 0, at) + 1
            raise InvalidInputError(
                f"is not UTF-8 text: byte 0x{data[at]:02x} at line {line} (offset {at:,}) is not valid UTF-8",
                "save the file as UTF-8 (or plain ascii) text", path=path, field="encoding",
            ) from None
