"""Write a minimal GeoPackage polygon layer for tests, as GDAL lays it out: the three required
tables and geometry blobs with the 'GP' header (version 0, little endian, an xy envelope)
before little-endian WKB. The project reads GeoPackages without GDAL (workstation/ops/vector.py),
so tests build them with sqlite3."""

from __future__ import annotations

import sqlite3
import struct

import numpy as np


def wkb_polygon(rings) -> bytes:
    """Little-endian WKB of a polygon given as closed rings (k, 2), the first the outer one."""
    out = struct.pack("<BII", 1, 3, len(rings))
    for r in rings:
        out += struct.pack("<I", len(r)) + np.asarray(r, "<f8").tobytes()
    return out


def write_gpkg(path, polygons, srs_id: int = 32632, layer: str = "zones"):
    """A GeoPackage at ``path`` with one polygon layer ``layer`` in EPSG ``srs_id``: one feature
    per polygon of ``polygons`` (each a list of closed rings). Returns ``path``."""
    con = sqlite3.connect(path)
    con.executescript(f"""
        CREATE TABLE gpkg_spatial_ref_sys (srs_name TEXT, srs_id INTEGER PRIMARY KEY, organization TEXT,
            organization_coordsys_id INTEGER, definition TEXT, description TEXT);
        CREATE TABLE gpkg_contents (table_name TEXT PRIMARY KEY, data_type TEXT, identifier TEXT, srs_id INTEGER);
        CREATE TABLE gpkg_geometry_columns (table_name TEXT, column_name TEXT, geometry_type_name TEXT,
            srs_id INTEGER, z INTEGER, m INTEGER);
        CREATE TABLE {layer} (fid INTEGER PRIMARY KEY, geom BLOB);""")
    con.execute("INSERT INTO gpkg_spatial_ref_sys VALUES ('utm', ?, 'EPSG', ?, '', '')", (srs_id, srs_id))
    con.execute(f"INSERT INTO gpkg_contents VALUES ('{layer}', 'features', '{layer}', ?)", (srs_id,))
    con.execute(f"INSERT INTO gpkg_geometry_columns VALUES ('{layer}', 'geom', 'POLYGON', ?, 0, 0)", (srs_id,))
    for rings in polygons:
        env = np.asarray(rings[0], float)
        header = b"GP" + bytes([0, 0b011]) + struct.pack("<i", srs_id) + struct.pack(
            "<4d", env[:, 0].min(), env[:, 0].max(), env[:, 1].min(), env[:, 1].max())
        con.execute(f"INSERT INTO {layer} (geom) VALUES (?)", (header + wkb_polygon(rings),))
    con.commit()
    con.close()
    return path
