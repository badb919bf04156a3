"""What a LAS/LAZ/COPC header says, without reading a point: ``ws info --summary`` and
``ws info --metadata`` (a document shaped like ``pdal info --metadata``).

Reads the public header, the VLRs and EVLRs (laspy ``LasHeader.read_from``) and, for COPC, the
octree hierarchy pages (:func:`workstation.io.copc.summary`): a few KB whatever the point count.
"""

from __future__ import annotations

import base64
from pathlib import Path

from workstation.core.errors import InvalidInputError
from workstation.io import copc
from workstation.io.crs import crs_info
from workstation.io.registry import check_readable, format_of


def _read_header(path: Path):
    """The laspy header of ``path`` (VLRs and EVLRs included), after the raw-byte checks."""
    import laspy

    from workstation.io.las import check_raw_header, wrap_open_error

    if format_of(path)[0] not in ("las", "laz"):
        raise InvalidInputError("--summary and --metadata read LAS/LAZ headers; this format has no point-free summary",
                                "run ws info without --summary/--metadata", path=path, field="--summary")
    check_raw_header(path)
    try:
        with open(path, "rb") as f:
            return laspy.LasHeader.read_from(f, read_evlrs=True)
    except Exception as exc:  # noqa: BLE001 - laspy raises many types on corrupt headers
        raise wrap_open_error(path, exc) from None


def _vlr_rows(vlrs) -> list[dict]:
    """user_id, record_id, description and size of each (E)VLR."""
    rows = []
    for v in vlrs or []:
        data = _vlr_bytes(v)
        rows.append({"user_id": v.user_id, "record_id": int(v.record_id), "description": v.description,
                     "size": None if data is None else len(data)})
    return rows


def _vlr_bytes(v) -> bytes | None:
    """The payload of a VLR as stored (None when laspy parsed it and cannot give it back)."""
    for attr in ("record_data", "bytes"):
        data = getattr(v, attr, None)
        if isinstance(data, (bytes, bytearray)):
            return bytes(data)
    if (v.user_id, int(v.record_id)) == copc.COPC_INFO:  # parsed by laspy, which cannot write it back
        return _copc_info_bytes(v)
    try:
        return bytes(v.record_data_bytes())
    except Exception:  # noqa: BLE001 - a known VLR laspy parsed and cannot serialise
        return None


def _copc_info_bytes(v) -> bytes:
    """The 160-byte COPC info record rebuilt from laspy's parsed fields (reserved bytes are 0)."""
    import struct

    return struct.pack("<5d2Q2d", *v.center, v.halfsize, v.spacing, v.hierarchy_root_offset,
                       v.hierarchy_root_size, v.gps_min, v.gps_max) + bytes(88)


def _crs(h, path):
    from workstation.io.las import crs_string

    crs = crs_string(h, path, identify=False)
    info = crs_info(crs, identify=False)  # the code the file states: a database search takes 0.5 s
    if info is None:
        return crs, None
    return crs, {"name": info.name, "epsg": info.epsg, "unit": info.unit, "vertical_unit": info.vertical_unit,
                 "metres_per_unit": info.metres_per_unit}


def header_summary(path) -> dict:
    """Header facts of a LAS/LAZ/COPC file in milliseconds (no point is read).

    Returns
    -------
    dict
        ``file``, ``format`` (las/laz/copc), ``format_version`` ("LAZ 1.4 PDRF 6", "COPC 1.0
        (LAZ 1.4 PDRF 6)"), ``version``, ``point_format``, ``point_count``,
        ``points_by_return`` ({"1": n, ...}, the header's counts), ``bounds`` ({min, max}),
        ``scales``, ``offsets``, ``crs`` ({name, epsg, unit, vertical_unit,
        metres_per_unit} or None), ``vlrs`` and ``evlrs`` ([{user_id, record_id, description,
        size}]), ``generating_software``, ``copc`` (see :func:`workstation.io.copc.summary`, or None).
    """
    p = check_readable(path)
    h = _read_header(p)
    crs, info = _crs(h, p)
    c = copc.summary(p)
    kind = "LAZ" if h.are_points_compressed else "LAS"
    fv = f"{kind} {h.version} PDRF {h.point_format.id}"
    by_return = [int(v) for v in h.number_of_points_by_return]
    return {
        "file": str(p),
        "format": "copc" if c else kind.lower(),
        "format_version": f"COPC {c['version']} ({fv})" if c else fv,
        "version": str(h.version),
        "point_format": int(h.point_format.id),
        "point_count": int(h.point_count),
        "points_by_return": {str(i + 1): n for i, n in enumerate(by_return) if n},
        "bounds": {"min": [float(v) for v in h.mins], "max": [float(v) for v in h.maxs]},
        "scales": [float(v) for v in h.scales],
        "offsets": [float(v) for v in h.offsets],
        "crs": info,
        "crs_string": crs,
        "vlrs": _vlr_rows(h.vlrs),
        "evlrs": _vlr_rows(h.evlrs),
        "extra_dims": [d.name for d in h.point_format.extra_dimensions],
        "generating_software": h.generating_software,
        "system_identifier": h.system_identifier,
        "creation_date": None if h.creation_date is None else h.creation_date.isoformat(),
        "copc": c,
    }


def _srs(crs: str | None) -> dict:
    """PDAL's ``srs`` block: wkt, horizontal, vertical (WKT of each part), units, epsg flags."""
    if not crs:
        return {"wkt": "", "horizontal": "", "vertical": "", "units": {"horizontal": "", "vertical": ""},
                "isgeographic": False, "isgeocentric": False}
    from workstation.io.crs import parse_crs

    c = parse_crs(crs)
    horiz = c.sub_crs_list[0] if c.is_compound else c
    vert = c.sub_crs_list[1] if c.is_compound and len(c.sub_crs_list) > 1 else None
    info = crs_info(crs)
    return {
        "wkt": c.to_wkt(),
        "horizontal": horiz.to_wkt(),
        "vertical": "" if vert is None else vert.to_wkt(),
        "units": {"horizontal": info.unit, "vertical": info.vertical_unit if vert is not None or len(c.axis_info) == 3 else ""},
        "isgeographic": info.is_geographic,
        "isgeocentric": info.is_geocentric,
        "epsg": info.epsg,
    }


def _head(path: Path) -> bytes:
    with open(path, "rb") as f:
        return f.read(227)


def pdal_metadata(path) -> dict:
    """The header as ``pdal info --metadata`` prints it for readers.las / readers.copc: keys named
    as PDAL names them (``count``, ``minx``..``maxz``, ``scale_x``, ``offset_x``,
    ``dataformat_id``, ``major_version``, ``minor_version``, ``srs``, ``copc``, ``copc_info``,
    ``vlr_0``...), plus ``vlrs``/``evlrs`` lists and ``points_by_return``."""
    p = check_readable(path)
    h = _read_header(p)
    from workstation.io.las import crs_string

    c = copc.summary(p)
    md = {
        "compressed": bool(h.are_points_compressed),
        "copc": c is not None,
        "count": int(h.point_count),
        "creation_doy": None if h.creation_date is None else h.creation_date.timetuple().tm_yday,
        "creation_year": None if h.creation_date is None else h.creation_date.year,
        "dataformat_id": int(h.point_format.id),
        "dataoffset": int(h.offset_to_point_data),
        "filesource_id": int(h.file_source_id),
        "global_encoding": int(h.global_encoding.value),
        "header_size": int.from_bytes(_head(p)[94:96], "little"),
        "major_version": int(h.version.major),
        "minor_version": int(h.version.minor),
        "point_length": int(h.point_format.size),
        "software_id": h.generating_software,
        "system_id": h.system_identifier,
        "points_by_return": [int(v) for v in h.number_of_points_by_return],
        "srs": _srs(crs_string(h, p)),
    }
    for i, axis in enumerate("xyz"):
        md[f"min{axis}"], md[f"max{axis}"] = float(h.mins[i]), float(h.maxs[i])
        md[f"scale_{axis}"], md[f"offset_{axis}"] = float(h.scales[i]), float(h.offsets[i])
    if c is not None:
        info = copc.read_info(p)
        md["copc_info"] = {"center_x": info.center[0], "center_y": info.center[1], "center_z": info.center[2],
                           "halfsize": info.halfsize, "spacing": info.spacing, "root_hier_offset": info.root_offset,
                           "root_hier_size": info.root_size, "gpstime_minimum": info.gps_min,
                           "gpstime_maximum": info.gps_max}
        md["copc_hierarchy"] = {k: c[k] for k in ("levels", "nodes", "points_per_level", "spacing_per_level")}
    for i, v in enumerate(h.vlrs):
        data = _vlr_bytes(v)
        md[f"vlr_{i}"] = {"user_id": v.user_id, "record_id": int(v.record_id), "description": v.description,
                          "data": None if data is None else base64.b64encode(data).decode("ascii")}
    md["vlrs"] = _vlr_rows(h.vlrs)
    md["evlrs"] = _vlr_rows(h.evlrs)
    return {"filename": str(p), "file_size": p.stat().st_size,
            "reader": "readers.copc" if c is not None else "readers.las", "metadata": md}
