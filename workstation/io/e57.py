"""ASTM E57 point clouds through pye57 (libE57Format).

Reading takes every scan (or those chosen with ``scans=``), reads all its point fields into
float64 buffers, drops invalid points (``cartesianInvalidState`` or, for spherical-only
scans, ``sphericalInvalidState`` not 0), converts spherical coordinates to Cartesian when a
scan has only those, applies the scan pose (rotation quaternion w, x, y, z then translation)
so every point is in the file's common frame, and concatenates the scans.

================================  =============================================================
E57 field                         ``Cloud``
================================  =============================================================
cartesianX/Y/Z (or spherical*)    ``xyz`` float64, pose applied
intensity                         ``intensity`` u16, scaled from the scan's ``intensityLimits``
colorRed/Green/Blue               ``rgb`` u16, scaled from the scan's ``colorLimits``
                                  (0..255 -> x 257)
returnIndex, returnCount          ``return_number`` (returnIndex + 1), ``number_of_returns``
rowIndex, columnIndex, timeStamp  free attributes ``row_index``, ``column_index``,
                                  ``time_stamp`` (seconds after the scan's acquisition start)
(the scan)                        ``point_source_id`` = scan index
================================  =============================================================

Points flagged ``isIntensityInvalid`` / ``isColorInvalid`` get 0 there. ``meta["e57"]``
lists each scan's name, guid, point counts, pose and limits, and the file's
``coordinate_metadata`` string (the E57 CRS description, free text; not interpreted).
"""

from __future__ import annotations

import uuid
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud, concatenate
from workstation.core.errors import InvalidInputError, MissingDependencyError
from workstation.core.log import get_logger

from ._fields import build_cloud

log = get_logger(__name__)


def _pye57():
    try:
        import pye57
    except ImportError:
        raise MissingDependencyError("pye57", "reading and writing E57 files") from None
    return pye57


def _value(node) -> float:
    return float(node.scaledValue()) if hasattr(node, "scaledValue") else float(node.value())


def _child(node, name):
    try:
        if node.isDefined(name):
            return node[name]
    except Exception:  # noqa: BLE001 - libE57 raises its own exception types for odd nodes
        return None
    return None


def _limits(scan_node, group: str, lo_name: str, hi_name: str) -> tuple[float, float] | None:
    g = _child(scan_node, group)
    if g is None:
        return None
    lo, hi = _child(g, lo_name), _child(g, hi_name)
    if lo is None or hi is None:
        return None
    return _value(lo), _value(hi)


def quaternion_matrix(w: float, x: float, y: float, z: float) -> np.ndarray:
    """(3, 3) rotation matrix of a quaternion (normalised first), E57 order w, x, y, z.

    Examples
    --------
    >>> np.round(quaternion_matrix(np.cos(np.pi / 4), 0, 0, np.sin(np.pi / 4)) @ [1, 0, 0], 12)
    array([0., 1., 0.])
    """
    q = np.array([w, x, y, z], dtype=np.float64)
    norm = np.linalg.norm(q)
    if norm == 0:
        raise InvalidInputError("pose rotation quaternion is zero", field="pose")
    w, x, y, z = q / norm
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def _pose(scan_node) -> tuple[np.ndarray, np.ndarray]:
    """(rotation quaternion w, x, y, z; translation) of a scan; identity when absent."""
    rot = np.array([1.0, 0.0, 0.0, 0.0])
    trans = np.zeros(3)
    pose = _child(scan_node, "pose")
    if pose is not None:
        r = _child(pose, "rotation")
        if r is not None:
            rot = np.array([_value(r[k]) if r.isDefined(k) else 0.0 for k in ("w", "x", "y", "z")])
        t = _child(pose, "translation")
        if t is not None:
            trans = np.array([_value(t[k]) if t.isDefined(k) else 0.0 for k in ("x", "y", "z")])
    return rot, trans


def _scale(v: np.ndarray, limits, name: str, path) -> np.ndarray:
    if limits is None:
        limits = (0.0, 255.0) if name == "colour" and v.size and v.max() <= 255 else (float(v.min()) if v.size else 0.0, float(v.max()) if v.size else 1.0)
        log.info("%s: no %s limits in the scan header; using %s", path, name, limits)
    lo, hi = limits
    if hi <= lo:
        return np.zeros(v.shape, dtype=np.uint16)
    return np.round(np.clip((v - lo) / (hi - lo), 0.0, 1.0) * 65535.0).astype(np.uint16)


def _check_count(n: int, index: int, path) -> None:
    """Refuse a scan record count the file cannot hold (at least one bit per point) before
    any buffer is allocated for it."""
    size = Path(path).stat().st_size
    if n < 0 or n > 8 * size:
        raise InvalidInputError(
            f"scan {index} declares {n:,} points, more than a file of {size:,} bytes can hold",
            "the file is corrupt; get it again", path=path, field="points",
        )


def _read_scan(e, libe57, index: int, path) -> tuple[Cloud, dict]:
    """Scan ``index`` of an open E57 file as a cloud in the file's frame (the scan's pose
    applied), with invalid points dropped, and the facts of the scan for ``meta["e57"]``."""
    header = e.get_header(index)
    node = header.node
    n = int(header.point_count)
    fields = list(header.point_fields)
    _check_count(n, index, path)
    data = _read_fields(e, libe57, header, fields, n, index, path)
    xyz, state = _scan_xyz(data, fields, index, path)
    valid = np.ones(n, dtype=bool) if state is None else state == 0
    all_valid = bool(valid.all())
    rot, trans = _pose(node)
    if not all_valid:
        xyz = xyz[valid]
        data = {k: v[valid] for k, v in data.items()}
    if not (np.array_equal(rot, [1.0, 0.0, 0.0, 0.0]) and not trans.any()):
        xyz = xyz @ quaternion_matrix(*rot).T + trans
    m = xyz.shape[0]
    attrs, ilim, clim = _scan_attrs(data, node, index, m, path)
    name = _child(node, "name")
    guid = _child(node, "guid")
    info = {
        "index": index,
        "name": name.value() if name is not None else None,
        "guid": guid.value() if guid is not None else None,
        "point_count": n,
        "valid_count": m,
        "rotation_wxyz": rot.tolist(),
        "translation": trans.tolist(),
        "intensity_limits": list(ilim) if ilim else None,
        "color_limits": [list(c) if c else None for c in clim] if clim else None,
        "fields": fields,
    }
    return build_cloud(path, xyz, attrs, {}), info


def _read_fields(e, libe57, header, fields: list[str], n: int, index: int, path) -> dict[str, np.ndarray]:
    """Every point field of the scan as a float64 array of ``n`` values, read in one pass of
    libE57's compressed-vector reader (empty arrays for an empty scan)."""
    if not n:
        return {f: np.empty(0) for f in fields}
    data = {}
    buffers = libe57.VectorSourceDestBuffer()
    for f in fields:
        data[f] = np.empty(n, dtype=np.float64)
        buffers.append(libe57.SourceDestBuffer(e.image_file, f, data[f], n, True, True))
    reader = header.points.reader(buffers)
    got = reader.read()
    reader.close()
    if got != n:
        raise InvalidInputError(f"scan {index} declares {n} points but {got} were read", path=path, field="points")
    return data


def _scan_xyz(data: dict, fields: list[str], index: int, path):
    """``(xyz, invalid state or None)`` in the scan's own frame: the cartesian fields, else the
    spherical ones converted (range, azimuth and elevation in radians, E57 convention)."""
    if all(f"cartesian{c}" in data for c in "XYZ"):
        return np.column_stack([data[f"cartesian{c}"] for c in "XYZ"]), data.get("cartesianInvalidState")
    if all(f in data for f in ("sphericalRange", "sphericalAzimuth", "sphericalElevation")):
        r, az, el = data["sphericalRange"], data["sphericalAzimuth"], data["sphericalElevation"]
        xyz = np.column_stack([r * np.cos(el) * np.cos(az), r * np.cos(el) * np.sin(az), r * np.sin(el)])
        return xyz, data.get("sphericalInvalidState")
    raise InvalidInputError(
        f"scan {index} has neither cartesianX/Y/Z nor spherical coordinates (fields: {', '.join(fields)})",
        path=path, field="points",
    )


def _scan_attrs(data: dict, node, index: int, m: int, path):
    """The attributes of the ``m`` valid points: ``point_source_id`` (the scan index),
    ``intensity`` and ``rgb`` scaled by the scan's limits (0 where flagged invalid), returns,
    row/column indices and time stamps. Returns ``(attrs, intensity limits, colour limits)``."""
    attrs: dict[str, np.ndarray] = {"point_source_id": np.full(m, index, dtype=np.uint16)}
    ilim = _limits(node, "intensityLimits", "intensityMinimum", "intensityMaximum")
    if "intensity" in data:
        inten = _scale(data["intensity"], ilim, "intensity", path)
        if "isIntensityInvalid" in data:
            inten[data["isIntensityInvalid"] != 0] = 0
        attrs["intensity"] = inten
    clim = None
    if all(f"color{c}" in data for c in ("Red", "Green", "Blue")):
        chans = []
        clim = []
        for c in ("Red", "Green", "Blue"):
            lim = _limits(node, "colorLimits", f"color{c}Minimum", f"color{c}Maximum")
            clim.append(lim)
            chans.append(_scale(data[f"color{c}"], lim, "colour", path))
        rgb = np.column_stack(chans)
        if "isColorInvalid" in data:
            rgb[data["isColorInvalid"] != 0] = 0
        attrs["rgb"] = rgb
    if "returnIndex" in data:
        attrs["return_number"] = data["returnIndex"] + 1
    if "returnCount" in data:
        attrs["number_of_returns"] = data["returnCount"]
    for src, dst, dt in (("rowIndex", "row_index", np.int64), ("columnIndex", "column_index", np.int64), ("timeStamp", "time_stamp", np.float64)):
        if src in data:
            attrs[dst] = data[src].astype(dt)
    return attrs, ilim, clim


def read(path, *, scans=None) -> Cloud:
    """Read the scans of an E57 file as one cloud in the file's common frame.

    Parameters
    ----------
    path : path-like
        An E57 file.
    scans : sequence of int, optional
        Scan indices to read (default: every scan).

    Returns
    -------
    Cloud
        ``xyz`` (n, 3) float64 after each scan's pose, valid points only; attributes as in
        the module table; ``meta["e57"]["scans"]`` one record per scan read.

    Raises
    ------
    InvalidInputError
        Not an E57 file (libE57 cannot open it), a scan index out of range, a scan without
        coordinates.
    """
    pye57 = _pye57()
    from pye57 import libe57

    path = Path(path)
    try:
        e = pye57.E57(str(path))
    except Exception as exc:  # noqa: BLE001 - libE57 raises E57Exception / RuntimeError variants
        raise InvalidInputError(f"cannot open as E57: {exc}", "check the file type; E57 files start with 'ASTM-E57'", path=path, field="magic") from None
    try:
        node = _child(e.root, "coordinateMetadata")
        coord_meta = node.value() if node is not None else ""
        count = e.scan_count
        idx = list(range(count)) if scans is None else [int(s) for s in scans]
        bad = [s for s in idx if not 0 <= s < count]
        if bad:
            raise InvalidInputError(f"scan {bad[0]} does not exist (the file has {count})", f"use 0..{count - 1}", path=path, field="scans")
        if not idx:
            raise InvalidInputError("no scans to read", "the file has no Data3D scans" if count == 0 else "pass some scan indices", path=path, field="scans")
        parts, infos = [], []
        for s in idx:
            try:
                c, info = _read_scan(e, libe57, s, path)
            except InvalidInputError:
                raise
            except Exception as exc:  # noqa: BLE001
                raise InvalidInputError(f"cannot read scan {s}: {exc}", "the file may be truncated or corrupt", path=path, field="points") from None
            parts.append(c)
            infos.append(info)
    finally:
        e.close()
    cloud = concatenate(parts) if len(parts) > 1 else parts[0]
    return cloud.with_meta(format="e57", e57={"scans": infos, "scan_count": count, "coordinate_metadata": coord_meta})


def write(cloud: Cloud, path, *, name: str = "scan 0") -> None:
    """Write a cloud as one E57 scan: double Cartesian coordinates, intensity, colour.

    Parameters
    ----------
    cloud : Cloud
    path : path-like
    name : str
        Scan name.

    Notes
    -----
    Coordinates are written as 64-bit floats (exact) with an identity pose; ``intensity``
    as integers 0..65535 with ``intensityLimits`` 0..65535; ``rgb`` as 8-bit integers with
    ``colorLimits`` 0..255 when every value is a multiple of 257 (what most viewers expect),
    else as 16-bit with limits 0..65535. Other attributes are not written (E57 has no
    general per-point attribute fields).
    """
    pye57 = _pye57()
    from pye57 import libe57

    if cloud.crs:
        log.warning("%s: the CRS %s is not stored (pye57 cannot set the E57 coordinateMetadata)", Path(path).name, cloud.crs[:60])
    e = pye57.E57(str(path), mode="w")
    try:
        imf = e.image_file
        n = cloud.n
        xyz = np.ascontiguousarray(cloud.xyz)
        lo = xyz.min(axis=0) if n else np.zeros(3)
        hi = xyz.max(axis=0) if n else np.zeros(3)
        scan = libe57.StructureNode(imf)
        scan.set("guid", libe57.StringNode(imf, "{%s}" % uuid.uuid4()))
        scan.set("name", libe57.StringNode(imf, name))
        scan.set("description", libe57.StringNode(imf, "written by workstation"))
        bounds = libe57.StructureNode(imf)
        for i, c in enumerate("xyz"):
            bounds.set(f"{c}Minimum", libe57.FloatNode(imf, float(lo[i])))
            bounds.set(f"{c}Maximum", libe57.FloatNode(imf, float(hi[i])))
        scan.set("cartesianBounds", bounds)
        proto = libe57.StructureNode(imf)
        arrays: dict[str, np.ndarray] = {}
        for i, c in enumerate("XYZ"):
            proto.set(f"cartesian{c}", libe57.FloatNode(imf, float(lo[i]), libe57.E57_DOUBLE, float(lo[i]), float(hi[i])))
            arrays[f"cartesian{c}"] = np.ascontiguousarray(xyz[:, i])
        # every point is valid; the field is written because readers such as pye57 expect it
        proto.set("cartesianInvalidState", libe57.IntegerNode(imf, 0, 0, 2))
        arrays["cartesianInvalidState"] = np.zeros(n, dtype=np.float64)
        if "intensity" in cloud.attrs:
            lim = libe57.StructureNode(imf)
            lim.set("intensityMinimum", libe57.IntegerNode(imf, 0))
            lim.set("intensityMaximum", libe57.IntegerNode(imf, 65535))
            scan.set("intensityLimits", lim)
            proto.set("intensity", libe57.IntegerNode(imf, 0, 0, 65535))
            arrays["intensity"] = cloud.attrs["intensity"].astype(np.float64)
        if "rgb" in cloud.attrs:
            rgb = cloud.attrs["rgb"]
            eight = not np.any(rgb % 257)
            top = 255 if eight else 65535
            lim = libe57.StructureNode(imf)
            for i, c in enumerate(("Red", "Green", "Blue")):
                lim.set(f"color{c}Minimum", libe57.IntegerNode(imf, 0))
                lim.set(f"color{c}Maximum", libe57.IntegerNode(imf, top))
                proto.set(f"color{c}", libe57.IntegerNode(imf, 0, 0, top))
                arrays[f"color{c}"] = ((rgb[:, i] // 257) if eight else rgb[:, i]).astype(np.float64)
            scan.set("colorLimits", lim)
        codecs = libe57.VectorNode(imf, True)
        points = libe57.CompressedVectorNode(imf, proto, codecs)
        scan.set("points", points)
        e.data3d.append(scan)
        if n:
            buffers = libe57.VectorSourceDestBuffer()
            for f, a in arrays.items():
                buffers.append(libe57.SourceDestBuffer(imf, f, a, n, True, True))
            writer = points.writer(buffers)
            writer.write(n)
            writer.close()
    finally:
        e.close()
