"""Exports of building models: CityJSON 2.0, GeoJSON footprints and roof faces, glTF (GLB),
Wavefront OBJ (with an MTL of one material per semantic surface), and reading given footprints.

CityJSON follows the 2.0 specification (https://www.cityjson.org/specs/2.0.1/): integer
vertices with a ``transform``, one ``Building`` per model with a LoD1.2 ``Solid`` and a LoD2.2
``Solid`` (or ``CompositeSolid`` for several parts) carrying ``RoofSurface`` / ``WallSurface`` /
``GroundSurface`` semantics. :func:`validate_cityjson` checks the rules that can be checked
offline (structure, types, index ranges, semantics arrays, and that every solid shell is closed
and consistently oriented: each directed edge used once and its reverse once).
"""

from __future__ import annotations

import numpy as np

from workstation.core.errors import InvalidInputError

SCALE = 0.001  # m per CityJSON integer unit
SURFACE_TYPES = {"RoofSurface", "WallSurface", "GroundSurface", "ClosureSurface", "OuterCeilingSurface",
                 "OuterFloorSurface", "Window", "Door", "InteriorWallSurface", "CeilingSurface", "FloorSurface"}
GEOMETRY_TYPES = {"MultiPoint", "MultiLineString", "MultiSurface", "CompositeSurface", "Solid", "MultiSolid",
                  "CompositeSolid", "GeometryInstance"}
OBJECT_TYPES = {"Building", "BuildingPart", "BuildingInstallation", "BuildingStorey", "BuildingRoom", "BuildingUnit"}


def _epsg_url(crs) -> str | None:
    if not crs:
        return None
    s = str(crs)
    if s.upper().startswith("EPSG:") and s[5:].isdigit():
        return f"https://www.opengis.net/def/crs/EPSG/0/{s[5:]}"
    try:
        from pyproj import CRS

        code = CRS.from_user_input(s).to_epsg()
        return f"https://www.opengis.net/def/crs/EPSG/0/{code}" if code else None
    except Exception:
        return None


class _Vertices:
    """Shared integer vertex list of a CityJSON file (duplicates merged)."""

    def __init__(self, translate: np.ndarray):
        self.translate = translate
        self.index: dict = {}
        self.rows: list = []

    def add(self, xyz: np.ndarray) -> np.ndarray:
        q = np.round((np.asarray(xyz, float) - self.translate) / SCALE).astype(np.int64)
        out = np.empty(len(q), np.int64)
        for i, row in enumerate(map(tuple, q)):
            j = self.index.get(row)
            if j is None:
                j = self.index[row] = len(self.rows)
                self.rows.append(row)
            out[i] = j
        return out


def _shell(solid, verts: _Vertices):
    """(shell boundaries, semantic values) of a Solid with vertex indices into ``verts``."""
    vid = verts.add(solid.vertices)
    kinds = sorted(set(solid.semantics))
    shell = [[[int(vid[v]) for v in ring] for ring in face] for face in solid.faces]
    values = [kinds.index(s) for s in solid.semantics]
    return _dedupe_rings(shell), kinds, values


def _dedupe_rings(shell):
    """Drop consecutive repeats that integer rounding may create (mm grid)."""
    out = []
    for face in shell:
        rings = []
        for r in face:
            r = [v for i, v in enumerate(r) if v != r[i - 1]] if len(r) > 1 else r
            rings.append(r)
        out.append(rings)
    return out


def _geometry(solids, lod: str, verts: _Vertices) -> dict:
    shells = [_shell(s, verts) for s in solids]
    kinds = sorted({k for _, ks, _ in shells for k in ks})
    surfaces = [{"type": k} for k in kinds]
    if len(shells) == 1:
        sh, ks, vals = shells[0]
        return {"type": "Solid", "lod": lod, "boundaries": [sh],
                "semantics": {"surfaces": surfaces, "values": [[kinds.index(ks[v]) for v in vals]]}}
    return {"type": "CompositeSolid", "lod": lod, "boundaries": [[sh] for sh, _, _ in shells],
            "semantics": {"surfaces": surfaces, "values": [[[kinds.index(ks[v]) for v in vals]] for _, ks, vals in shells]}}


def cityjson_document(models: list, solar: list, crs=None) -> dict:
    """CityJSON 2.0 document of building models (LoD1.2 and LoD2.2 per building)."""
    allv = np.vstack([s.vertices for m in models for s in [m.lod1, *m.lod2]])
    lo, hi = allv.min(axis=0), allv.max(axis=0)
    translate = model_origin(models)
    verts = _Vertices(translate)
    objects = {}
    for m, sol in zip(models, solar):
        attrs = {"height_m": round(m.height - m.ground, 3), "roof_elevation_m": round(m.height, 3),
                 "ground_height_m": round(m.ground, 3), "roof_type": m.roof_type, "roof_faces": len(m.roofs),
                 "parts": len(m.lod2)}
        if len(sol) and np.isfinite(sol).any():
            area = np.array([f.area_m2 for f in m.roofs])
            attrs["solar_kwh_year"] = round(float(np.nansum(sol * area)), 1)
        objects[f"building_{m.id}"] = {"type": "Building", "attributes": attrs,
                                       "geometry": [_geometry([m.lod1], "1.2", verts), _geometry(m.lod2, "2.2", verts)]}
    doc = {"type": "CityJSON", "version": "2.0",
           "transform": {"scale": [SCALE] * 3, "translate": translate.tolist()},
           "metadata": {"geographicalExtent": [*lo.tolist(), *hi.tolist()]},
           "CityObjects": objects, "vertices": [list(map(int, r)) for r in verts.rows]}
    url = _epsg_url(crs)
    if url:
        doc["metadata"]["referenceSystem"] = url
    return doc


def validate_cityjson(doc: dict) -> list[str]:
    """Errors found in a CityJSON 2.0 document (empty when valid for the checks made)."""
    err = []
    if doc.get("type") != "CityJSON" or doc.get("version") != "2.0":
        err.append("type must be 'CityJSON' and version '2.0'")
    tr = doc.get("transform")
    if not tr or len(tr.get("scale", [])) != 3 or len(tr.get("translate", [])) != 3:
        err.append("transform needs scale and translate of 3 numbers")
    verts = doc.get("vertices", [])
    if not all(isinstance(v, list) and len(v) == 3 and all(isinstance(c, int) for c in v) for v in verts):
        err.append("vertices must be lists of 3 integers")
    n = len(verts)
    for oid, obj in doc.get("CityObjects", {}).items():
        if obj.get("type") not in OBJECT_TYPES:
            err.append(f"{oid}: unknown type {obj.get('type')}")
        for g in obj.get("geometry", []):
            err += [f"{oid} lod {g.get('lod')}: {e}" for e in _check_geometry(g, n)]
    return err


def _check_geometry(g: dict, n: int) -> list[str]:
    err = []
    if g.get("type") not in GEOMETRY_TYPES:
        return [f"unknown geometry type {g.get('type')}"]
    if not isinstance(g.get("lod"), str):
        err.append("lod must be a string")
    solids = [g["boundaries"]] if g["type"] == "Solid" else g["boundaries"] if g["type"] == "CompositeSolid" else []
    vals = g.get("semantics", {}).get("values")
    surfaces = g.get("semantics", {}).get("surfaces", [])
    if any(s.get("type") not in SURFACE_TYPES for s in surfaces):
        err.append("unknown semantic surface type")
    for si, solid in enumerate(solids):
        sv = None if vals is None else (vals[0] if g["type"] == "Solid" else vals[si][0]) if vals else None
        for shi, shell in enumerate(solid):
            if sv is not None and shi == 0 and len(sv) != len(shell):
                err.append(f"solid {si}: {len(shell)} surfaces but {len(sv)} semantic values")
            if sv is not None and any(v is not None and not 0 <= v < len(surfaces) for v in sv):
                err.append(f"solid {si}: semantic value out of range")
            err += [f"solid {si} shell {shi}: {e}" for e in _check_shell(shell, n)]
    return err


def _check_shell(shell, n: int) -> list[str]:
    """Ring sizes, index ranges and closure: every directed edge matched by its reverse once."""
    err = []
    edges = {}
    for face in shell:
        for ring in face:
            if len(ring) < 3:
                err.append("ring with fewer than 3 vertices")
            if any(not 0 <= v < n for v in ring):
                err.append("vertex index out of range")
                continue
            for a, b in zip(ring, ring[1:] + ring[:1]):
                edges[(a, b)] = edges.get((a, b), 0) + 1
    bad = [e for e, c in edges.items() if c != 1 or edges.get((e[1], e[0]), 0) != 1]
    if bad:
        err.append(f"shell not closed or not consistently oriented ({len(bad)} edges)")
    return err


def footprints_geojson(models: list, crs=None) -> dict:
    """FeatureCollection: one polygon per building with ``id``, ``height`` (above ground, m),
    ``ground_height`` and ``roof_elevation`` (m), ``roof_type``."""
    feats = []
    for m in models:
        ring = np.vstack([m.footprint, m.footprint[:1]])
        feats.append({"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [ring.round(3).tolist()]},
                      "properties": {"id": m.id, "height": round(m.height - m.ground, 3), "ground_height": round(m.ground, 3),
                                     "roof_elevation": round(m.height, 3), "roof_type": m.roof_type,
                                     "area_m2": round(float(_area(m.footprint)), 2)}})
    return _collection(feats, crs)


def roofs_geojson(models: list, solar: list, crs=None) -> dict:
    """FeatureCollection: one 3-D polygon per roof face with ``building_id``, ``part``,
    ``tilt_deg``, ``azimuth_deg`` (clockwise from north), ``area_m2`` (sloped) and
    ``solar_kwh_m2_year``."""
    feats = []
    for m, sol in zip(models, solar):
        for f, s in zip(m.roofs, sol):
            xy = np.vstack([f.polygon, f.polygon[:1]])
            ring = np.column_stack([xy, f.z(xy)]).round(3)
            feats.append({"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [ring.tolist()]},
                          "properties": {"building_id": m.id, "part": f.part, "tilt_deg": round(f.tilt_deg, 2),
                                         "azimuth_deg": round(f.azimuth_deg, 2), "area_m2": round(f.area_m2, 2),
                                         "solar_kwh_m2_year": None if not np.isfinite(s) else round(float(s), 1)}})
    return _collection(feats, crs)


def _area(p):
    return 0.5 * abs(np.dot(p[:, 0], np.roll(p[:, 1], -1)) - np.dot(p[:, 1], np.roll(p[:, 0], -1)))


def _collection(feats, crs):
    doc = {"type": "FeatureCollection", "features": feats}
    if crs:
        doc["crs"] = {"type": "name", "properties": {"name": str(crs) if len(str(crs)) < 64 else "unknown"}}
    return doc


COLORS = {"RoofSurface": (200, 70, 60, 255), "WallSurface": (235, 230, 220, 255), "GroundSurface": (90, 90, 90, 255)}


def glb_scene(models: list):
    """trimesh Scene of the LoD2.2 models (one mesh per building, faces coloured by semantics,
    vertices not shared between faces so the colours stay crisp), in a local frame: the
    scene's ``metadata['origin']`` is the subtracted origin (m)."""
    import trimesh

    from .models import triangulate

    origin = np.floor(np.vstack([m.lod1.vertices for m in models]).min(axis=0))
    scene = trimesh.Scene()
    for m in models:
        vs, fs, cs, off = [], [], [], 0
        for s in m.lod2:
            tris, owner = triangulate(s)
            vs.append(s.vertices - origin)
            fs.append(tris + off)
            cs.append(np.array([COLORS.get(s.semantics[o], (180, 180, 180, 255)) for o in owner], np.uint8).reshape(-1, 4))
            off += len(s.vertices)
        mesh = trimesh.Trimesh(np.vstack(vs), np.vstack(fs), face_colors=np.vstack(cs), process=False)
        mesh.unmerge_vertices()  # glTF colours vertices: each face its own, so roofs and walls stay apart
        scene.add_geometry(mesh, node_name=f"building_{m.id}", geom_name=f"building_{m.id}")
    scene.metadata["origin"] = origin.tolist()
    return scene


def read_footprints(path, cloud_crs=None) -> list:
    """Outer rings (list of (k, 2) arrays, closing vertex dropped) of the polygons of a GeoJSON
    (.geojson, .json) or GeoPackage (.gpkg, its first feature table) file, read by
    :func:`workstation.ops.vector.read_polygons`. When the file and ``cloud_crs`` both name a
    CRS they must be the same one, or the cloud's horizontal part (:func:`workstation.io.crs.same_crs`)."""
    from pathlib import Path

    from workstation.io.crs import same_crs
    from workstation.ops.vector import read_polygons

    p = Path(path)
    if p.suffix.lower() not in (".geojson", ".json", ".gpkg"):
        raise InvalidInputError("footprints must be GeoJSON (.geojson, .json) or GeoPackage (.gpkg)",
                                "convert with ogr2ogr -f GPKG", path=p)
    polys = read_polygons(p)
    if polys.crs and cloud_crs and not same_crs(polys.crs, cloud_crs, horizontal=True):
        raise InvalidInputError(f"footprints are in {polys.crs} but the cloud is in {cloud_crs}",
                                f"reproject them, e.g. ogr2ogr -t_srs {cloud_crs}", path=p)
    rings = []
    for poly in polys.polygons:
        r = np.asarray(poly.exterior, float)[:, :2]
        r = r[:-1] if len(r) > 1 and np.allclose(r[0], r[-1]) else r
        if len(r) >= 3:
            rings.append(r)
    if not rings:
        raise InvalidInputError("no polygon with three or more vertices", path=p)
    return rings


MTL = {"RoofSurface": (0.78, 0.27, 0.24), "WallSurface": (0.92, 0.90, 0.86), "GroundSurface": (0.35, 0.35, 0.35)}


def model_origin(models: list) -> np.ndarray:
    """Local origin (m) shared by the CityJSON ``transform.translate`` and the OBJ files: the
    floor of the lowest corner of every model's vertices."""
    return np.floor(np.vstack([s.vertices for m in models for s in [m.lod1, *m.lod2]]).min(axis=0))


def mtl_text() -> str:
    """Wavefront material library: one diffuse material per semantic surface type."""
    out = ["# ws buildings: materials by CityJSON semantic surface"]
    for name, (r, g, b) in MTL.items():
        out += [f"newmtl {name}", f"Kd {r:.3f} {g:.3f} {b:.3f}", "Ka 0.000 0.000 0.000", "illum 1", ""]
    return "\n".join(out)


def obj_text(models: list, lod: str = "2.2", mtl_name: str = "buildings.mtl", crs=None) -> str:
    """Wavefront OBJ of the LoD2.2 (``lod='2.2'``) or LoD1.2 (``'1.2'``) models: one object
    ``building_<id>`` per building (``building_<id>_part<k>`` per LoD2.2 part), triangles
    (as in the glTF) grouped by ``usemtl RoofSurface|WallSurface|GroundSurface``, vertices shared
    within each solid so every shell stays closed. Vertices are in a local frame to 1 mm: add the
    origin written in the ``# origin`` comment (:func:`model_origin`) for absolute coordinates."""
    import io

    from .models import triangulate

    if lod not in ("1.2", "2.2"):
        raise InvalidInputError(f"OBJ level of detail must be '1.2' or '2.2', not {lod!r}", field="lod")
    origin = model_origin(models)
    buf = io.StringIO()
    buf.write(f"# ws buildings LoD{lod}\n# origin {origin[0]:.3f} {origin[1]:.3f} {origin[2]:.3f}\n")
    if crs:
        buf.write(f"# crs {crs}\n")
    buf.write(f"mtllib {mtl_name}\n")
    base = 1
    for m in models:
        solids = [m.lod1] if lod == "1.2" else m.lod2
        for k, s in enumerate(solids):
            tris, owner = triangulate(s)
            sem = np.array(s.semantics, dtype=object)[owner]
            order = np.argsort(sem.astype(str), kind="stable")
            tris, sem = tris[order] + base, sem[order]
            name = f"building_{m.id}" if len(solids) == 1 else f"building_{m.id}_part{k}"
            buf.write(f"o {name}\n")
            np.savetxt(buf, s.vertices - origin, fmt="v %.3f %.3f %.3f")
            starts = np.flatnonzero(np.r_[True, sem[1:] != sem[:-1]])
            for a, b in zip(starts, [*starts[1:], len(sem)]):
                buf.write(f"usemtl {sem[a]}\n")
                np.savetxt(buf, tris[a:b], fmt="f %d %d %d")
            base += len(s.vertices)
    return buf.getvalue()
