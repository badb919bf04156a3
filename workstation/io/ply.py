"""PLY point clouds (Stanford polygon format): ascii, binary_little_endian, binary_big_endian.

Our own vectorised parser: the ``vertex`` element is read with one structured numpy dtype
(``np.fromfile`` for binary, ``np.loadtxt`` over the whole ascii body), never a Python loop
per point. CRLF line endings are tolerated in the header and the body. Other elements (faces,
range grids) are skipped, list properties included.

Property names map to canonical attributes:

=================================================  ==========================================
PLY vertex property                                ``Cloud``
=================================================  ==========================================
x, y, z (float or double)                          ``xyz`` (float64)
red, green, blue (also r/g/b, diffuse_red...)      ``rgb`` u16: uchar x 257, ushort kept
nx, ny, nz (also normal_x...)                      ``normal`` f32
intensity, scalar_intensity                        ``intensity`` u16 when every value fits
classification, label, scalar_classification       ``classification`` u8 when every value fits
a canonical scalar name (gps_time, ...)            that attribute when every value fits
anything else                                      a free attribute under its own name
=================================================  ==========================================

A value that does not fit its canonical dtype (a float intensity in 0..1) is kept as a free
attribute (``scalar_intensity``, or ``intensity_raw`` for a property named ``intensity``).
The CRS, which PLY has no field for, is written and read as a header line
``comment crs EPSG:32632`` (or one-line WKT); other programs ignore comments.
``meta["ply"]`` records the format, comments and the source name and type of every
attribute, so that writing the cloud again gives the same property types (uchar colours stay
uchar).
"""

from __future__ import annotations

import io
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, UnsupportedFormatError
from workstation.core.log import get_logger

from ._fields import (
    build_cloud,
    crs_from_comment,
    crs_line,
    first_non_ascii,
    fits_exactly,
    loadtxt_error_line,
    looks_like_numbers,
    format_rows,
    mapped_attr,
    number_format,
    rgb_from_u16,
    rgb_to_u16,
    scalar_canonical,
)

log = get_logger(__name__)

#: PLY type names -> numpy type codes (both the 1996 names and the sized names).
PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}  # fmt: skip
_NUMPY_TO_PLY = {"i1": "char", "u1": "uchar", "i2": "short", "u2": "ushort", "i4": "int", "u4": "uint", "f4": "float", "f8": "double"}
_FORMATS = {"ascii": None, "binary_little_endian": "<", "binary_big_endian": ">"}

_RGB_NAMES = (("red", "green", "blue"), ("r", "g", "b"), ("diffuse_red", "diffuse_green", "diffuse_blue"))
_NORMAL_NAMES = (("nx", "ny", "nz"), ("normal_x", "normal_y", "normal_z"))
_INTENSITY_NAMES = ("intensity", "scalar_intensity")
_CLASS_NAMES = ("classification", "label", "scalar_classification", "class")
_MAX_HEADER = 1 << 20


@dataclass
class _Property:
    name: str
    type: str  # PLY type name of a scalar, or of the items of a list
    count_type: str | None = None  # set for list properties


@dataclass
class _Element:
    name: str
    count: int
    props: list[_Property] = field(default_factory=list)

    @property
    def has_lists(self) -> bool:
        return any(p.count_type for p in self.props)

    def dtype(self, endian: str) -> np.dtype:
        return np.dtype([(p.name, endian + PLY_TYPES[p.type]) for p in self.props])


@dataclass
class _Header:
    format: str
    elements: list[_Element]
    comments: list[str]
    obj_info: list[str]
    body_offset: int
    n_lines: int  # header lines, for line numbers in ascii errors


def _read_header(path: Path) -> _Header:
    with open(path, "rb") as f:
        head = f.read(_MAX_HEADER)
    if not head.startswith(b"ply") or head[3:4] not in (b"\n", b"\r"):
        raise InvalidInputError(
            "not a PLY file: the first line is not 'ply'", "check the file type; PLY files start with the line 'ply'",
            path=path, field="magic",
        )
    m = re.search(rb"end_header[ \t]*\r?\n", head)
    if m is None:
        raise InvalidInputError("no 'end_header' line in the PLY header", "the file is truncated or not PLY", path=path, field="header")
    text = head[: m.start()].decode("ascii", errors="replace")
    lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    fmt = None
    elements: list[_Element] = []
    comments, obj_info = [], []
    for lineno, raw in enumerate(lines[1:], start=2):
        tok = raw.split()
        if not tok:
            continue
        key = tok[0]
        try:
            if key == "format":
                if len(tok) < 2 or tok[1] not in _FORMATS:
                    raise InvalidInputError(
                        f"unknown format line '{raw.strip()}' (line {lineno})",
                        "PLY format must be ascii, binary_little_endian or binary_big_endian",
                        path=path, field="format",
                    )
                fmt = tok[1]
            elif key == "comment":
                comments.append(raw.strip()[8:])
            elif key == "obj_info":
                obj_info.append(raw.strip()[9:])
            elif key == "element":
                elements.append(_Element(tok[1], int(tok[2])))
                if elements[-1].count < 0:
                    raise ValueError("negative count")
            elif key == "property":
                if not elements:
                    raise ValueError("property before any element")
                if tok[1] == "list":
                    prop = _Property(tok[4], tok[3], tok[2])
                    bad = [t for t in (tok[2], tok[3]) if t not in PLY_TYPES]
                    if not bad and PLY_TYPES[tok[2]][0] == "f":
                        raise ValueError(f"list length type {tok[2]} is not an integer type")
                else:
                    prop = _Property(tok[2], tok[1])
                    bad = [tok[1]] if tok[1] not in PLY_TYPES else []
                if bad:
                    raise InvalidInputError(
                        f"unknown property type '{bad[0]}' (line {lineno})",
                        "PLY types are char uchar short ushort int uint float double (or int8..float64)",
                        path=path, field=prop.name,
                    )
                if any(q.name == prop.name for q in elements[-1].props):
                    raise InvalidInputError(
                        f"property '{prop.name}' appears twice in element '{elements[-1].name}' (line {lineno})",
                        "rename one of them", path=path, field=prop.name,
                    )
                elements[-1].props.append(prop)
            else:
                raise ValueError(f"unknown keyword '{key}'")
        except (IndexError, ValueError) as e:
            if isinstance(e, InvalidInputError):
                raise
            raise InvalidInputError(
                f"bad header line {lineno}: '{raw.strip()}' ({e})", "repair the header", path=path, field="header"
            ) from None
    if fmt is None:
        raise InvalidInputError("no 'format' line in the PLY header", path=path, field="format")
    return _Header(fmt, elements, comments, obj_info, m.end(), text.count("\n") + 1)


def _vertex(header: _Header, path: Path) -> tuple[int, _Element]:
    for i, el in enumerate(header.elements):
        if el.name == "vertex":
            if el.has_lists:
                raise UnsupportedFormatError(
                    "the vertex element has a list property", "point clouds need fixed-size vertex records",
                    path=path, field="vertex",
                )
            return i, el
    raise InvalidInputError("no 'vertex' element in the PLY header", "the file has no points", path=path, field="vertex")


def _truncated(el: _Element, path: Path, have: int | None = None) -> InvalidInputError:
    what = "vertices" if el.name == "vertex" else f"'{el.name}' elements"
    holds = "ends before all of them" if have is None else f"holds only {have:,}"
    return InvalidInputError(
        f"header declares {el.count:,} {what} but the body {holds}",
        "the file is truncated or its element count is wrong; get the file again", path=path, field=el.name,
    )


def _min_size(el: _Element) -> int:
    """Fewest bytes one binary instance of ``el`` takes (its size when it has no lists)."""
    return sum(np.dtype(PLY_TYPES[p.count_type or p.type]).itemsize for p in el.props)


def _skip_binary_element(el: _Element, buf: np.ndarray, pos: int, endian: str, path: Path) -> int:
    """Byte offset after ``el`` starting at ``pos`` (lists skipped; uniform lists vectorised).

    The count is checked against the bytes left before any walk, so a corrupt count fails
    at once instead of looping over billions of instances.
    """
    smallest = _min_size(el)
    if not el.has_lists:
        if pos + el.count * smallest > buf.size:
            raise _truncated(el, path, max(buf.size - pos, 0) // max(smallest, 1))
        return pos + el.count * smallest
    if el.count * smallest > buf.size - pos:
        raise _truncated(el, path)
    if el.count == 0:
        return pos
    # Fast path: one list property whose every instance has the same count (triangles).
    if len(el.props) == 1:
        p = el.props[0]
        cdt = np.dtype(endian + PLY_TYPES[p.count_type])
        idt = np.dtype(endian + PLY_TYPES[p.type])
        k = int(buf[pos : pos + cdt.itemsize].view(cdt)[0])
        stride = cdt.itemsize + max(k, 0) * idt.itemsize
        end = pos + el.count * stride
        if k >= 0 and end <= buf.size:
            counts = np.ndarray((el.count,), dtype=cdt, buffer=buf, offset=pos, strides=(stride,))
            if np.all(counts == k):
                return end
    # General case: walk the instances (elements other than points, which are few or rare).
    for _ in range(el.count):
        for p in el.props:
            if p.count_type is None:
                pos += np.dtype(PLY_TYPES[p.type]).itemsize
                continue
            cdt = np.dtype(endian + PLY_TYPES[p.count_type])
            if pos + cdt.itemsize > buf.size:
                raise _truncated(el, path)
            k = int(buf[pos : pos + cdt.itemsize].view(cdt)[0])
            if k < 0:
                raise InvalidInputError(f"negative list length {k} in element '{el.name}'", "the file is corrupt",
                                        path=path, field=p.name)
            pos += cdt.itemsize + k * np.dtype(PLY_TYPES[p.type]).itemsize
    if pos > buf.size:
        raise _truncated(el, path)
    return pos


def _body(path: Path, offset: int) -> np.ndarray:
    """The bytes after the header as a read-only memory map (no copy; empty when there are none)."""
    if path.stat().st_size <= offset:
        return np.zeros(0, dtype=np.uint8)
    return np.memmap(path, dtype=np.uint8, mode="r", offset=offset)


def _element_offsets(header: _Header, buf: np.ndarray, endian: str, path: Path, upto: int | None = None) -> list[int]:
    """Start offset of every element in the body (of the first ``upto + 1`` with ``upto``), then
    the end of the last one walked."""
    offsets = [0]
    for el in header.elements[: None if upto is None else upto + 1]:
        offsets.append(_skip_binary_element(el, buf, offsets[-1], endian, path))
    return offsets


def _read_binary(path: Path, header: _Header, vi: int, vel: _Element) -> np.ndarray:
    """The vertex records of a binary body, after checking that the elements fill it exactly."""
    endian = _FORMATS[header.format]
    dt = vel.dtype(endian)
    buf = _body(path, header.body_offset)
    text = looks_like_numbers(buf)
    # Faces with mixed list lengths after the vertices can only be walked instance by instance:
    # stop at the vertices then (their bytes are still bounded), and check the whole body otherwise.
    tail_lists = any(el.has_lists for el in header.elements[vi + 1:])
    try:
        offsets = _element_offsets(header, buf, endian, path, upto=vi if tail_lists else None)
    except InvalidInputError:
        if text:
            raise _mismatch(path, header.format) from None
        raise
    extra = 0 if tail_lists else buf.size - offsets[-1]
    if text and (extra or tail_lists):
        raise _mismatch(path, header.format)
    last = header.elements[-1]
    if extra >= max(_min_size(last), 1):
        raise InvalidInputError(
            f"the body holds {extra:,} bytes more than the header's elements "
            f"({', '.join(f'{e.count:,} {e.name}' for e in header.elements)})",
            "the element counts in the header are wrong; fix them to match the data", path=path, field=last.name,
        )
    if extra:
        log.warning("%s: %d bytes after the last element are ignored", path, extra)
    start = offsets[vi]
    arr = np.frombuffer(buf, dtype=dt, count=vel.count, offset=start) if vel.count else np.zeros(0, dtype=dt)
    return arr.astype(dt.newbyteorder("="))


def _mismatch(path: Path, fmt: str) -> InvalidInputError:
    return InvalidInputError(
        f"the header says format {fmt} but the body is ascii text",
        "fix the 'format' line of the header (format ascii 1.0)", path=path, field="format",
    )


def _not_text(path: Path, body: bytes) -> InvalidInputError | None:
    """An error when an ascii body holds bytes that are not printable ascii, else None."""
    bad = first_non_ascii(body)
    if bad is None:
        return None
    return InvalidInputError(
        f"the header says format ascii but the body is not ascii text (byte 0x{bad[1]:02x} at body offset {bad[0]:,})",
        "the file is binary (fix the 'format' line) or corrupt", path=path, field="format",
    )


def _read_ascii(path: Path, header: _Header, vi: int, vel: _Element) -> np.ndarray:
    with open(path, "rb") as f:
        f.seek(header.body_offset)
        body = f.read()
    err = _not_text(path, body)
    if err is not None:
        raise err
    skip = sum(el.count for el in header.elements[:vi])
    # Coordinates are parsed as double whatever their declared type, keeping the text values.
    dt = np.dtype([(p.name, "f8" if p.name in ("x", "y", "z") else PLY_TYPES[p.type]) for p in vel.props])
    stripped = body.rstrip()
    n_lines = stripped.count(b"\n") + 1 if stripped else 0
    declared = sum(el.count for el in header.elements)
    if skip + vel.count > n_lines:
        raise InvalidInputError(
            f"header declares {vel.count:,} vertices but the body holds only {max(n_lines - skip, 0):,} lines for them",
            "the file is truncated or its vertex count is wrong; get the file again",
            path=path, field="vertex",
        )
    try:
        if vel.count == 0:  # an empty cloud (loadtxt would warn that there is no data)
            arr = np.zeros(0, dtype=dt)
        else:
            arr = np.loadtxt(io.BytesIO(body), dtype=dt, skiprows=skip, max_rows=vel.count, ndmin=1, comments=None)
    except (ValueError, OverflowError) as e:
        msg = str(e)
        line = loadtxt_error_line(msg, header.n_lines + skip + 1)
        where = f" (line {line})" if line else ""
        raise InvalidInputError(
            f"cannot parse vertex data{where}: {msg}",
            f"each vertex line needs {len(vel.props)} numbers: {' '.join(p.name for p in vel.props)}",
            path=path, field="vertex",
        ) from None
    if arr.shape[0] < vel.count:
        raise InvalidInputError(
            f"header declares {vel.count} vertices but the body holds only {arr.shape[0]}",
            "the file is truncated or its vertex count is wrong; get the file again",
            path=path, field="vertex",
        )
    if n_lines > declared:
        raise InvalidInputError(
            f"the body has {n_lines} lines but the header declares {declared} element lines "
            f"({', '.join(f'{e.count} {e.name}' for e in header.elements)})",
            "the vertex count in the header is wrong; fix it to match the data",
            path=path, field="vertex",
        )
    return arr


def read(path, *, keep_unknown: bool = True) -> Cloud:
    """Read the vertices of a PLY file as a cloud.

    Parameters
    ----------
    path : path-like
        An ascii or binary PLY file (CRLF line endings tolerated).
    keep_unknown : bool
        Keep vertex properties with no canonical meaning as free attributes (default True).

    Returns
    -------
    Cloud
        ``xyz`` (n, 3) float64 and attributes as in the module table; ``meta["ply"]`` with
        ``format``, ``comments``, ``obj_info``, ``elements`` (name -> count) and ``types``
        (attribute -> [source names, PLY type]).

    Raises
    ------
    InvalidInputError
        Bad magic, unknown format, a vertex count that disagrees with the data, a missing
        x/y/z property, unparsable numbers, NaN coordinates; the message names the file.
    """
    path = Path(path)
    header = _read_header(path)
    vi, vel = _vertex(header, path)
    names = [p.name for p in vel.props]
    for c in ("x", "y", "z"):
        if c not in names:
            raise InvalidInputError(
                f"the vertex element has no '{c}' property (it has {', '.join(names) or 'none'})",
                "a point cloud PLY needs x, y and z", path=path, field=c,
            )
    arr = _read_binary(path, header, vi, vel) if header.format != "ascii" else _read_ascii(path, header, vi, vel)
    ptype = {p.name: p.type for p in vel.props}
    xyz = np.empty((vel.count, 3), dtype=np.float64)
    for i, c in enumerate("xyz"):
        xyz[:, i] = arr[c]
    attrs, types = _attributes(arr, names, ptype, keep_unknown)
    meta = {
        "format": "ply",
        "ply": {
            "format": header.format,
            "comments": header.comments,
            "obj_info": header.obj_info,
            "elements": {el.name: el.count for el in header.elements},
            "types": types,
        },
    }
    crs = next((c for c in map(crs_from_comment, header.comments) if c), None)
    return build_cloud(path, xyz, attrs, meta, crs=crs)


def _attributes(arr: np.ndarray, names: list[str], ptype: dict, keep_unknown: bool) -> tuple[dict, dict]:
    """Map the vertex properties other than x, y, z onto cloud attributes: the first complete
    colour and normal triples (names matched case-insensitively, :data:`_RGB_NAMES`,
    :data:`_NORMAL_NAMES`), intensity and classification by their aliases, other properties
    under their canonical name when they have one, else (``keep_unknown``) their own (``_ply``
    added on a clash). Returns ``(attrs, types)``; ``types`` maps each attribute to its source
    properties and PLY type."""
    lower = {n.lower(): n for n in names}
    used = {"x", "y", "z"}
    attrs: dict[str, np.ndarray] = {}
    types: dict[str, list] = {"xyz": [["x", "y", "z"], ptype["x"]]}
    for trio in _RGB_NAMES:
        if all(t in lower for t in trio):
            src = [lower[t] for t in trio]
            attrs["rgb"] = np.column_stack([rgb_to_u16(arr[s], PLY_TYPES[ptype[s]]) for s in src])
            types["rgb"] = [src, ptype[src[0]]]
            used.update(src)
            break
    for trio in _NORMAL_NAMES:
        if all(t in lower for t in trio):
            src = [lower[t] for t in trio]
            attrs["normal"] = np.column_stack([arr[s] for s in src]).astype(np.float32)
            types["normal"] = [src, ptype[src[0]]]
            used.update(src)
            break
    for canonical, aliases in (("intensity", _INTENSITY_NAMES), ("classification", _CLASS_NAMES)):
        src = next((lower[a] for a in aliases if a in lower and lower[a] not in used), None)
        if src is not None:
            mapped_attr(attrs, types, canonical, src, arr[src], ptype[src])
            used.add(src)
    for name in names:
        if name in used:
            continue
        canonical = scalar_canonical(name)
        if canonical is not None and canonical not in attrs:
            mapped_attr(attrs, types, canonical, name, arr[name], ptype[name])
        elif keep_unknown:
            key = name if name not in attrs else f"{name}_ply"
            attrs[key] = np.ascontiguousarray(arr[name])
            types[key] = [name, ptype[name]]
    return attrs, types


def _ply_type(dtype) -> str:
    dt = np.dtype(dtype)
    if dt.kind == "b":
        return "uchar"
    key = f"{dt.kind}{dt.itemsize}"
    if key == "f2":
        return "float"
    return _NUMPY_TO_PLY.get(key, "")


def _safe_name(name: str) -> str:
    return re.sub(r"\s+", "_", name) or "unnamed"


def _columns(cloud: Cloud, xyz_type: str) -> list[tuple[str, str, np.ndarray]]:
    """(property name, PLY type, values) for every property to write."""
    types = dict((cloud.meta.get("ply") or {}).get("types", {}))
    cols: list[tuple[str, str, np.ndarray]] = [(c, xyz_type, cloud.xyz[:, i]) for i, c in enumerate("xyz")]
    for name, arr in cloud.attrs.items():
        src = types.get(name)
        if name == "rgb":
            if src and isinstance(src[0], list) and len(src[0]) == 3:
                back = rgb_from_u16(arr, PLY_TYPES.get(src[1], "u2"))
                if back is not None:
                    cols.extend((_safe_name(s), src[1], back[:, i]) for i, s in enumerate(src[0]))
                    continue
            cols.extend((c, "ushort", arr[:, i]) for i, c in enumerate(("red", "green", "blue")))
        elif name == "normal":
            cols.extend((c, "float", arr[:, i]) for i, c in enumerate(("nx", "ny", "nz")))
        elif arr.ndim == 1:
            if src and isinstance(src[0], str) and src[1] in PLY_TYPES and fits_exactly(arr, PLY_TYPES[src[1]]):
                cols.append((_safe_name(src[0]), src[1], arr))
                continue
            t = _ply_type(arr.dtype)
            if not t:
                if fits_exactly(arr, np.int32):
                    t = "int"
                elif fits_exactly(arr, np.uint32):
                    t = "uint"
                elif fits_exactly(arr, np.float64):
                    t = "double"
                else:
                    raise InvalidInputError(f"dtype {arr.dtype} has no PLY type that holds its values", field=name)
            cols.append((_safe_name(name), t, arr))
        else:
            flat = arr.reshape(arr.shape[0], -1)
            t = _ply_type(arr.dtype) or "double"
            cols.extend((_safe_name(f"{name}_{i}"), t, flat[:, i]) for i in range(flat.shape[1]))
    seen: set[str] = set()
    for name, _, _ in cols:
        if name in seen:
            raise InvalidInputError(f"two attributes would both be written as PLY property '{name}'", field=name)
        seen.add(name)
    return cols


def write(cloud: Cloud, path, *, ascii: bool = False, big_endian: bool = False, xyz_type: str = "double") -> None:
    """Write a cloud as PLY (a vertex element only).

    Parameters
    ----------
    cloud : Cloud
    path : path-like
        Written as given (``write_cloud`` passes a temporary path and renames it).
    ascii : bool
        Text body (default: binary little endian).
    big_endian : bool
        Binary big endian instead of little endian.
    xyz_type : {"double", "float"}
        Coordinate type; ``double`` (default) keeps every coordinate exactly.

    Notes
    -----
    ``rgb`` is written as uchar when ``meta["ply"]`` says it came from uchar and every value
    is a multiple of 257, else as ushort; ``normal`` as float nx, ny, nz; other attributes
    with their source name and type when recorded and the values still fit, else with their
    own name and dtype; (n, k) free attributes as ``name_0 .. name_{k-1}``.
    """
    if xyz_type not in ("double", "float"):
        raise InvalidInputError(f"xyz_type must be 'double' or 'float', got {xyz_type!r}", field="xyz_type")
    cols = _columns(cloud, xyz_type)
    fmt = "ascii" if ascii else ("binary_big_endian" if big_endian else "binary_little_endian")
    head = ["ply", f"format {fmt} 1.0", "comment written by workstation"]
    if cloud.crs:
        head.append(f"comment {crs_line(cloud.crs)}")
    head.append(f"element vertex {cloud.n}")
    head.extend(f"property {t} {name}" for name, t, _ in cols)
    head.append("end_header")
    header = ("\n".join(head) + "\n").encode("ascii")
    with open(path, "wb") as f:
        f.write(header)
        if ascii:
            arrays = [np.asarray(v).astype(PLY_TYPES[t]) for _, t, v in cols]
            f.write(format_rows(arrays, [number_format(a.dtype) for a in arrays], " ").encode("ascii"))
        else:
            endian = ">" if big_endian else "<"
            rec = np.empty(cloud.n, dtype=[(name, endian + PLY_TYPES[t]) for name, t, _ in cols])
            for name, _, v in cols:
                rec[name] = v
            rec.tofile(f)
