"""Polygons for cropping: GeoJSON and GeoPackage read without GDAL, tested point by point.

A :class:`PolygonSet` holds polygons (each an exterior ring and its holes) and the CRS they
are in. Point-in-polygon is vectorised: each polygon's bounding box first, then the
even-odd crossing rule (a point is inside when a ray towards +x crosses the ring an odd
number of times) on the exterior minus the holes. Points are grouped into horizontal strips
and each strip is tested against only the edges that span it, so the work is about
points x (edges per strip) rather than points x edges: a million points against a ring of a
thousand vertices in well under a second. GeoPackage geometries are parsed from their WKB (with the GeoPackage header) using
only :mod:`sqlite3`, so neither GDAL nor shapely is needed.
"""

from __future__ import annotations

import json
import sqlite3
import struct
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError


def ring_contains(ring: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """(n,) bool: points ``pts`` (n, 2) inside the closed ``ring`` (m, 2), even-odd rule.

    Examples
    --------
    >>> sq = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], float)
    >>> ring_contains(sq, np.array([[1.0, 1.0], [5.0, 1.0], [2.0, 3.9]])).tolist()
    [True, False, True]
    """
    r = np.asarray(ring, dtype=np.float64)
    if not np.array_equal(r[0], r[-1]):
        r = np.vstack([r, r[:1]])
    x0, y0, x1, y1 = r[:-1, 0], r[:-1, 1], r[1:, 0], r[1:, 1]
    ylo, yhi = np.minimum(y0, y1), np.maximum(y0, y1)
    inside = np.zeros(len(pts), dtype=bool)
    if len(pts) == 0:
        return inside
    nstrips = int(np.clip(len(x0) // 2, 1, 4096))
    bottom, top = float(ylo.min()), float(yhi.max())
    height = (top - bottom) / nstrips or 1.0
    strip = np.clip(((pts[:, 1] - bottom) / height).astype(np.int64), 0, nstrips - 1)
    order = np.argsort(strip, kind="stable")
    starts = np.searchsorted(strip[order], np.arange(nstrips + 1))
    for k in np.flatnonzero(np.diff(starts)):
        sel = order[starts[k]:starts[k + 1]]
        e = np.flatnonzero((ylo <= bottom + (k + 1) * height) & (yhi >= bottom + k * height))
        if e.size == 0:
            continue
        px, py = pts[sel, 0:1], pts[sel, 1:2]
        spans = (y0[e] > py) != (y1[e] > py)
        with np.errstate(divide="ignore", invalid="ignore"):
            xcross = x0[e] + (py - y0[e]) * (x1[e] - x0[e]) / (y1[e] - y0[e])
        inside[sel] = np.count_nonzero(spans & (px < xcross), axis=1) % 2 == 1
    return inside


@dataclass(frozen=True)
class Polygon:
    """One polygon: ``exterior`` (m, 2) float ring and ``holes``, a tuple of (k, 2) rings,
    in the units of the owning :class:`PolygonSet`'s CRS."""

    exterior: np.ndarray
    holes: tuple = ()

    def rings(self) -> list[np.ndarray]:
        return [self.exterior, *self.holes]

    def contains(self, xy: np.ndarray) -> np.ndarray:
        """(n,) bool: inside the exterior and outside every hole (boundary points may go either way)."""
        lo, hi = self.exterior.min(axis=0), self.exterior.max(axis=0)
        cand = np.flatnonzero((xy[:, 0] >= lo[0]) & (xy[:, 0] <= hi[0]) & (xy[:, 1] >= lo[1]) & (xy[:, 1] <= hi[1]))
        out = np.zeros(len(xy), dtype=bool)
        if cand.size == 0:
            return out
        pts = xy[cand]
        inside = ring_contains(self.exterior, pts)
        for hole in self.holes:
            inside &= ~ring_contains(hole, pts)
        out[cand] = inside
        return out


@dataclass(frozen=True)
class PolygonSet:
    """Polygons and their CRS (None: the cloud's). A point is inside when it is inside any polygon."""

    polygons: tuple
    crs: str | None = None

    def contains(self, xy: np.ndarray) -> np.ndarray:
        """(n,) bool for points ``xy`` (n, 2) in the polygons' CRS."""
        xy = np.asarray(xy, dtype=np.float64)
        out = np.zeros(len(xy), dtype=bool)
        for poly in self.polygons:
            rest = ~out
            out[rest] = poly.contains(xy[rest])
        return out

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        pts = np.concatenate([p.exterior for p in self.polygons])
        return pts.min(axis=0), pts.max(axis=0)

    def to_crs(self, crs: str | None) -> "PolygonSet":
        """The polygons in ``crs`` (vertices transformed with pyproj); unchanged if either CRS is unknown."""
        if not crs or not self.crs or self.crs == crs:
            return self
        import pyproj

        from workstation.io.crs import parse_crs

        tr = pyproj.Transformer.from_crs(parse_crs(self.crs, "polygon_crs"), parse_crs(crs, "crs"), always_xy=True)

        def move(ring):
            x, y = tr.transform(ring[:, 0], ring[:, 1])
            return np.column_stack([x, y])

        polys = tuple(Polygon(move(p.exterior), tuple(move(h) for h in p.holes)) for p in self.polygons)
        return PolygonSet(polys, crs)

    def to_wkt(self, decimals: int = 6) -> str:
        """One WKT (POLYGON or MULTIPOLYGON) of all polygons, as PDAL's ``filters.crop`` ``polygon`` takes."""
        def ring(r):
            return "(" + ", ".join(f"{x:.{decimals}f} {y:.{decimals}f}" for x, y in r) + ")"

        parts = ["(" + ", ".join(ring(r) for r in p.rings()) + ")" for p in self.polygons]
        return f"POLYGON {parts[0]}" if len(parts) == 1 else "MULTIPOLYGON (" + ", ".join(parts) + ")"


def _ring(coords, path, what) -> np.ndarray:
    r = np.asarray(coords, dtype=np.float64)
    if r.ndim != 2 or r.shape[1] < 2 or len(r) < 3 or not np.isfinite(r[:, :2]).all():
        raise InvalidInputError(f"{what} has a ring that is not 3 or more finite (x, y) positions", path=path)
    return r[:, :2]


def _from_geojson_geometry(geom, path) -> list[Polygon]:
    """Polygons of a GeoJSON geometry (Polygon, MultiPolygon, GeometryCollection)."""
    if not isinstance(geom, dict):
        return []
    kind = geom.get("type")
    if kind == "Polygon":
        rings = [_ring(r, path, "a Polygon") for r in geom.get("coordinates") or []]
        return [Polygon(rings[0], tuple(rings[1:]))] if rings else []
    if kind == "MultiPolygon":
        return [p for c in geom.get("coordinates") or [] for p in _from_geojson_geometry({"type": "Polygon", "coordinates": c}, path)]
    if kind == "GeometryCollection":
        return [p for g in geom.get("geometries") or [] for p in _from_geojson_geometry(g, path)]
    return []


def _geojson_crs(doc) -> str | None:
    """The CRS of a GeoJSON document's (pre-RFC 7946) ``crs`` member, e.g. ``EPSG:2154``."""
    name = ((doc.get("crs") or {}).get("properties") or {}).get("name") if isinstance(doc, dict) else None
    if not name:
        return None
    if "CRS84" in name:
        return "OGC:CRS84"
    if "EPSG" in name.upper():
        return "EPSG:" + name.replace("::", ":").split(":")[-1]
    return name


def read_geojson(path) -> PolygonSet:
    """Polygons of a GeoJSON FeatureCollection, Feature or geometry (other geometries ignored)."""
    from workstation.io.textfile import read_text

    p = Path(path)
    try:
        doc = json.loads(read_text(p))
    except (OSError, ValueError) as e:
        raise InvalidInputError(f"cannot read GeoJSON: {e}", path=p) from None
    if not isinstance(doc, dict):
        raise InvalidInputError("not a GeoJSON object", path=p)
    if doc.get("type") == "FeatureCollection":
        geoms = [f.get("geometry") for f in doc.get("features") or [] if isinstance(f, dict)]
    elif doc.get("type") == "Feature":
        geoms = [doc.get("geometry")]
    else:
        geoms = [doc]
    polys = [poly for g in geoms for poly in _from_geojson_geometry(g, p)]
    return PolygonSet(tuple(polys), _geojson_crs(doc))


# --- GeoPackage ---------------------------------------------------------------------------

_ENVELOPE_BYTES = {0: 0, 1: 32, 2: 48, 3: 48, 4: 64}


def _gpkg_wkb(blob: bytes, path) -> bytes:
    """The WKB inside a GeoPackage geometry blob ('GP', version, flags, srs_id, envelope, WKB)."""
    if blob[:2] != b"GP" or len(blob) < 8:
        raise InvalidInputError("a geometry is not a GeoPackage blob", path=path)
    env = (blob[3] >> 1) & 0x07
    if env not in _ENVELOPE_BYTES:
        raise InvalidInputError(f"a geometry has an unknown envelope code {env}", path=path)
    return blob[8 + _ENVELOPE_BYTES[env]:]


def _wkb_polygons(buf: bytes, pos: int, path) -> tuple[list[Polygon], int]:
    """Polygons of the WKB geometry at ``pos`` (Polygon, MultiPolygon, collection; Z/M dropped)."""
    order = "<" if buf[pos] == 1 else ">"
    (code,) = struct.unpack_from(order + "I", buf, pos + 1)
    pos += 5
    dims = 2
    if code & 0x80000000:  # EWKB Z flag
        dims += 1
    if code & 0x40000000:  # EWKB M flag
        dims += 1
    if code & 0x20000000:  # EWKB SRID
        pos += 4
    code &= 0x0FFFFFFF
    base, iso = code % 1000, code // 1000
    dims += {0: 0, 1: 1, 2: 1, 3: 2}.get(iso, 0)
    if base == 3:
        (nrings,) = struct.unpack_from(order + "I", buf, pos)
        pos += 4
        rings = []
        for _ in range(nrings):
            (npts,) = struct.unpack_from(order + "I", buf, pos)
            pos += 4
            arr = np.frombuffer(buf, dtype=order + "f8", count=npts * dims, offset=pos).reshape(npts, dims)
            pos += 8 * npts * dims
            rings.append(_ring(arr, path, "a polygon"))
        return ([Polygon(rings[0], tuple(rings[1:]))] if rings else []), pos
    if base in (6, 7):  # MultiPolygon, GeometryCollection
        (n,) = struct.unpack_from(order + "I", buf, pos)
        pos += 4
        out = []
        for _ in range(n):
            polys, pos = _wkb_polygons(buf, pos, path)
            out += polys
        return out, pos
    raise InvalidInputError(f"WKB geometry type {code} is not a polygon", "give a polygon layer", path=path)


def read_gpkg(path, layer: str | None = None) -> PolygonSet:
    """Polygons of a GeoPackage feature table (``layer``, or the only/first feature table)."""
    p = Path(path)
    try:
        con = sqlite3.connect(f"file:{p}?mode=ro", uri=True)
    except sqlite3.Error as e:
        raise InvalidInputError(f"cannot open GeoPackage: {e}", path=p) from None
    try:
        rows = con.execute("SELECT c.table_name, g.column_name, c.srs_id FROM gpkg_contents c JOIN "
                           "gpkg_geometry_columns g ON g.table_name = c.table_name WHERE c.data_type = 'features'").fetchall()
        if not rows:
            raise InvalidInputError("has no feature table", path=p)
        names = [r[0] for r in rows]
        if layer is not None and layer not in names:
            raise InvalidInputError(f"has no layer '{layer}'", f"layers: {', '.join(names)}", path=p, field="layer")
        table, column, srs_id = rows[names.index(layer)] if layer else rows[0]
        blobs = con.execute(f'SELECT "{column}" FROM "{table}"').fetchall()
        srs = con.execute("SELECT organization, organization_coordsys_id FROM gpkg_spatial_ref_sys WHERE srs_id = ?",
                          (srs_id,)).fetchone()
    except sqlite3.Error as e:
        raise InvalidInputError(f"not a readable GeoPackage: {e}", path=p) from None
    finally:
        con.close()
    polys = []
    for (blob,) in blobs:
        if blob is not None:
            polys += _wkb_polygons(_gpkg_wkb(bytes(blob), p), 0, p)[0]
    crs = f"{srs[0].upper()}:{srs[1]}" if srs and srs[0] and srs[1] and int(srs[1]) > 0 else None
    return PolygonSet(tuple(polys), crs)


def read_polygons(path, layer: str | None = None) -> PolygonSet:
    """Polygons of a GeoJSON (.geojson/.json) or GeoPackage (.gpkg) file; refuses a file without any."""
    p = Path(path)
    if not p.is_file():
        raise InvalidInputError("file not found", "check the path", path=p)
    ext = p.suffix.lower()
    if ext in (".geojson", ".json"):
        if layer is not None:
            raise InvalidInputError("--layer applies to GeoPackage files only", path=p, field="layer")
        out = read_geojson(p)
    elif ext == ".gpkg":
        out = read_gpkg(p, layer)
    else:
        raise InvalidInputError(f"unknown polygon file type '{ext}'", "give a .geojson or .gpkg file", path=p)
    if not out.polygons:
        raise InvalidInputError("holds no Polygon or MultiPolygon", "give a file with polygon features", path=p)
    return out
