"""3D Tiles 1.1 tilesets (https://docs.ogc.org/cs/22-025r4/22-025r4.html) of point clouds and meshes.

A tileset is a folder with ``tileset.json`` (asset version ``1.1``, an explicit tree of tiles)
and one glTF 2.0 binary (``.glb``) per tile with content, as CesiumJS and the three.js 3D
Tiles renderers stream them.

Point clouds
------------
The tile tree is the COPC writer's octree (:mod:`workstation.publish.copc`): the records are
staged the same way, sorted by Morton code (:func:`~workstation.publish.copc.build_octree`)
and split into levels by
:func:`~workstation.publish.copc.assign_levels` (a node keeps one point per cell of a
``cells``³ grid and passes the rest to its eight children), so a tile is exactly a COPC node
and every point is in exactly one tile. Tiles refine by ``ADD`` (a child adds its points to
its parents'). A tile's ``geometricError`` is its level's point spacing in metres
(``side / cells / 2**level``), halving per level; a leaf, which holds every point left to it,
has 0. Bounding volumes are boxes around the tile's points and those of its descendants, so a
parent's box holds its children's. When a site publishes a cloud as COPC and 3D Tiles
(:func:`publish_tilesets` with ``staged``), the tileset is written from the COPC writer's own
staged records and octree (its ``on_octree`` callback, :func:`write_octree_tileset`), so the
cloud is read, staged and sorted once for both.

Each tile is a glTF mesh of one ``POINTS`` primitive: ``POSITION`` (float32, relative to the
node's ``translation``, the centre of the tile's box), ``COLOR_0`` (unsigned bytes,
normalised: the RGB of the cloud when it has some, else the ASPRS class colour when it is
classified, else an elevation ramp) and ``_CLASSIFICATION`` (the ASPRS class, unsigned byte, padded
to 4 bytes as glTF aligns vertex attributes) when some point has a class other than 0.

Meshes
------
A mesh (OBJ with its MTL and texture as ``ws mesh`` / texturing write them, PLY with vertex
colours) is split into a tile tree by its triangles' centroids (:func:`split_faces`: a node
with more than ``max_faces`` triangles is halved along its long axes, so terrain makes a
quadtree and a compact object an octree; a triangle is never cut, it goes whole to one tile
and the tile's box grows to hold it). Each leaf is a ``.glb`` of its triangles at full
resolution (``TEXCOORD_0`` and a texture of only the texels its UVs reach: its charts cut
from the mesh's texture and packed into a sub-atlas, :func:`sub_atlas`, embedded as PNG; or
``COLOR_0``); each inner tile a quadric-decimated copy of its subtree's triangles
(:func:`workstation.mesh.simplify.decimate`, to ``max_faces``, open borders kept, colours
sampled from the texture at the vertices), refined by ``REPLACE`` into its children. An
inner tile's ``geometricError`` (metres) is the larger of the Hausdorff distance (at the
vertices, both ways) between its simplified mesh and its subtree's full-resolution triangles
and the simplified mesh's median edge length (vertex colours carry no detail finer than the
edges they span), and at least its children's; leaves have 0.

Georeferencing
--------------
With a CRS, the root tile's ``transform`` is the east-north-up frame at the data's centre
expressed in Earth-centred Earth-fixed coordinates (EPSG:4978): columns east, north, up, and
the centre's ECEF position. Every coordinate is converted with pyproj from the CRS (its
horizontal part, the height taken as an ellipsoidal height in metres after the CRS's vertical
unit is applied: geoid heights are not corrected) to ECEF and then into that ENU frame, so
contents are in metres also for CRSs in feet. Without a CRS there is no transform: contents
are in the cloud's own units relative to its centre, which ``tileset.json`` records in
``extras.ws.origin``. glTF is y-up and 3D Tiles turns it z-up at run time, so a local ENU
point (e, n, u) is stored as the glTF point (e, u, -n).
"""

from __future__ import annotations

import json
import os
import struct
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger

log = get_logger(__name__)

TILESET_VERSION = "1.1"
GLB_MAGIC, JSON_CHUNK, BIN_CHUNK = 0x46546C67, 0x4E4F534A, 0x004E4942
_FLOAT, _UBYTE, _UINT = 5126, 5121, 5125
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963
_PAD = 1e-3  # bounding boxes grow by this on every side, metres: they hold the float32 positions and are never flat
MESH_SUFFIXES = (".obj", ".ply")


@dataclass(frozen=True)
class TilesetResult:
    """What was written: the tileset folder, the number of ``points`` (clouds) or ``faces``
    (meshes), ``tiles`` with content, tree ``levels``, ``bytes`` of the folder and ``seconds``."""

    path: Path
    points: int
    faces: int
    tiles: int
    levels: int
    bytes: int
    seconds: float

    def to_dict(self) -> dict:
        return {"path": str(self.path), "points": self.points, "faces": self.faces, "tiles": self.tiles,
                "levels": self.levels, "bytes": self.bytes, "seconds": self.seconds}


# ------------------------------------------------------------------------------- frames
class Frame:
    """The tileset's frame: CRS coordinates -> local metres (ENU at ``origin`` with a CRS,
    else the CRS units relative to ``origin``) and the root ``transform`` (4x4 ENU -> ECEF,
    None without a CRS).

    Examples
    --------
    >>> f = Frame(None, np.array([10.0, 20.0, 5.0]))
    >>> f.to_local(np.array([[11.0, 20.0, 5.5]])).tolist(), f.transform is None
    ([[1.0, 0.0, 0.5]], True)
    """

    def __init__(self, crs, origin):
        self.crs, self.origin = crs, np.asarray(origin, float)
        self.transform = None
        if not crs:
            return
        import pyproj

        from workstation.io.crs import crs_units, parse_crs

        c = parse_crs(crs)
        horiz = c.sub_crs_list[0] if c.is_compound else c
        if horiz.is_geocentric:
            raise InvalidInputError("a geocentric CRS cannot be a tileset's frame", field="crs")
        self._zscale = 1.0 if len(horiz.axis_info) == 3 else float(crs_units(crs).v)
        self._to_ecef = pyproj.Transformer.from_crs(horiz.to_3d(), "EPSG:4978", always_xy=True)
        ecef = self._ecef(self.origin[None, :])[0]
        lon, lat, _ = pyproj.Transformer.from_crs("EPSG:4978", "EPSG:4979", always_xy=True).transform(*ecef)
        self.rotation = enu_rotation(lon, lat)
        self.ecef_origin = ecef
        m = np.eye(4)
        m[:3, :3], m[:3, 3] = self.rotation, ecef
        self.transform = m

    def _ecef_columns(self, xyz: np.ndarray) -> list:
        """ECEF x, y, z arrays of (n, 3) CRS coordinates (pyproj, transformed in place)."""
        cols = [np.array(xyz[:, i], float) for i in range(3)]
        cols[2] *= self._zscale
        self._to_ecef.transform(*cols, inplace=True)
        if not all(np.isfinite(c).all() for c in cols):
            raise InvalidInputError("coordinates outside the CRS's domain", "check the CRS of the data", field="crs")
        return cols

    def _ecef(self, xyz: np.ndarray) -> np.ndarray:
        return np.column_stack(self._ecef_columns(xyz))

    def to_local(self, xyz: np.ndarray) -> np.ndarray:
        """(n, 3) CRS coordinates -> (n, 3) float64 tileset coordinates (z up)."""
        if self.transform is None:
            return np.asarray(xyz, float) - self.origin
        d = [c - o for c, o in zip(self._ecef_columns(xyz), self.ecef_origin)]
        out = np.empty((len(xyz), 3))
        for j in range(3):  # (ecef - origin) @ rotation, column by column
            out[:, j] = d[0] * self.rotation[0, j] + d[1] * self.rotation[1, j] + d[2] * self.rotation[2, j]
        return out

    def extras(self) -> dict:
        """``{"ws": {crs, origin (CRS units), frame ("enu" or "local")}}`` for tileset.json."""
        return {"ws": {"crs": self.crs, "origin": self.origin.tolist(), "frame": "enu" if self.crs else "local"}}


def enu_rotation(lon_deg: float, lat_deg: float) -> np.ndarray:
    """3x3 rotation whose columns are the east, north and up unit vectors (ECEF) at a
    geodetic longitude/latitude (degrees).

    Examples
    --------
    >>> (np.round(enu_rotation(0.0, 0.0), 6) + 0.0).tolist()  # east = y, north = z, up = x
    [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    """
    lo, la = np.radians(lon_deg), np.radians(lat_deg)
    east = [-np.sin(lo), np.cos(lo), 0.0]
    north = [-np.sin(la) * np.cos(lo), -np.sin(la) * np.sin(lo), np.cos(la)]
    up = [np.cos(la) * np.cos(lo), np.cos(la) * np.sin(lo), np.sin(la)]
    return np.array([east, north, up]).T


def _yup(p: np.ndarray) -> np.ndarray:
    """z-up tileset coordinates (e, n, u) -> glTF's y-up (e, u, -n)."""
    return np.column_stack([p[:, 0], p[:, 2], -p[:, 1]])


def _box(lo: np.ndarray, hi: np.ndarray) -> list[float]:
    """A 3D Tiles ``box`` (centre, then the x, y, z half axes) of an axis-aligned box grown
    by ``_PAD`` on every side."""
    c, h = (lo + hi) / 2.0, (hi - lo) / 2.0 + _PAD
    return [*c.tolist(), h[0], 0.0, 0.0, 0.0, h[1], 0.0, 0.0, 0.0, h[2]]


# ------------------------------------------------------------------------------- glTF
class _Glb:
    """A glTF 2.0 document and its single binary buffer, built view by view."""

    def __init__(self):
        self.doc = {"asset": {"version": "2.0", "generator": "workstation"}, "bufferViews": [], "accessors": []}
        self.parts, self.size = [], 0

    def view(self, data: bytes, target: int | None = None, stride: int | None = None) -> int:
        """Append ``data`` (4-byte aligned) as a buffer view; its index."""
        v = {"buffer": 0, "byteOffset": self.size, "byteLength": len(data)}
        if target is not None:
            v["target"] = target
        if stride is not None:
            v["byteStride"] = stride
        pad = (-len(data)) % 4
        self.parts.append(data + bytes(pad))
        self.size += len(data) + pad
        self.doc["bufferViews"].append(v)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, array: np.ndarray, ctype: int, kind: str, *, target: int | None = _ARRAY_BUFFER,
                 normalized: bool = False, minmax: bool = False, stride: int | None = None) -> int:
        """A view of ``array`` (rows = elements) and its accessor; its index. ``stride`` pads
        each element to that many bytes (vertex attributes must be 4-byte aligned)."""
        a = np.ascontiguousarray(array)
        data = a.tobytes()
        if stride is not None and stride != a.itemsize * (a.shape[1] if a.ndim > 1 else 1):
            padded = np.zeros((len(a), stride), np.uint8)
            raw = a.reshape(len(a), -1).view(np.uint8)
            padded[:, : raw.shape[1]] = raw
            data = padded.tobytes()
        acc = {"bufferView": self.view(data, target, stride), "componentType": ctype, "count": int(len(a)),
               "type": kind}
        if normalized:
            acc["normalized"] = True
        if minmax:
            acc["min"], acc["max"] = a.min(axis=0).tolist(), a.max(axis=0).tolist()
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def bytes(self) -> bytes:
        """The GLB file: 12-byte header, JSON chunk (space padded), BIN chunk (zero padded)."""
        self.doc["buffers"] = [{"byteLength": self.size}]
        js = json.dumps(self.doc, separators=(",", ":")).encode()
        js += b" " * ((-len(js)) % 4)
        body = b"".join(self.parts)
        total = 12 + 8 + len(js) + 8 + len(body)
        return (struct.pack("<III", GLB_MAGIC, 2, total) + struct.pack("<II", len(js), JSON_CHUNK) + js
                + struct.pack("<II", len(body), BIN_CHUNK) + body)


def points_glb(local: np.ndarray, rgb: np.ndarray, classes: np.ndarray | None, centre: np.ndarray) -> bytes:
    """A GLB of one POINTS primitive: tileset coordinates ``local`` (n, 3) stored relative to
    ``centre`` (the node translation), colours ``rgb`` (n, 3) uint8, optional classes (n,)."""
    g = _Glb()
    pos = _yup(local - centre).astype(np.float32)
    attrs = {"POSITION": g.accessor(pos, _FLOAT, "VEC3", minmax=True),
             "COLOR_0": g.accessor(np.asarray(rgb, np.uint8), _UBYTE, "VEC3", normalized=True, stride=4)}
    if classes is not None:
        attrs["_CLASSIFICATION"] = g.accessor(np.asarray(classes, np.uint8), _UBYTE, "SCALAR", stride=4)
    g.doc.update(scene=0, scenes=[{"nodes": [0]}], nodes=[{"mesh": 0, "translation": _yup(centre[None])[0].tolist()}],
                 meshes=[{"primitives": [{"attributes": attrs, "mode": 0}]}])
    return g.bytes()


def read_glb(data: bytes) -> tuple[dict, bytes]:
    """(glTF JSON, BIN chunk) of a GLB file's bytes; raises :class:`InvalidInputError` on a
    malformed header or chunk layout (glTF 2.0 §4.4)."""
    if len(data) < 20:
        raise InvalidInputError("GLB too short", field="glb")
    magic, version, total = struct.unpack_from("<III", data, 0)
    if magic != GLB_MAGIC or version != 2 or total != len(data):
        raise InvalidInputError(f"bad GLB header (magic {magic:#x}, version {version}, length {total})", field="glb")
    jlen, jtype = struct.unpack_from("<II", data, 12)
    if jtype != JSON_CHUNK or jlen % 4:
        raise InvalidInputError("the first GLB chunk is not a 4-byte aligned JSON chunk", field="glb")
    doc = json.loads(data[20 : 20 + jlen])
    rest = 20 + jlen
    if rest == len(data):
        return doc, b""
    blen, btype = struct.unpack_from("<II", data, rest)
    if btype != BIN_CHUNK or rest + 8 + blen != len(data):
        raise InvalidInputError("the second GLB chunk is not a BIN chunk ending the file", field="glb")
    return doc, data[rest + 8 : rest + 8 + blen]


# ------------------------------------------------------------------------------- colours
_RAMP = np.array([[0.0, 48, 18, 140], [0.25, 30, 130, 230], [0.5, 60, 190, 110], [0.75, 240, 200, 40],
                  [1.0, 200, 40, 30]])


def elevation_colors(z: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """(n, 3) uint8 colours of heights ``z`` on a blue-green-yellow-red ramp over [lo, hi].

    Examples
    --------
    >>> elevation_colors(np.array([0.0, 10.0]), 0.0, 10.0).tolist()
    [[48, 18, 140], [200, 40, 30]]
    """
    t = np.clip((np.asarray(z, float) - lo) / max(hi - lo, 1e-9), 0.0, 1.0)
    return np.column_stack([np.interp(t, _RAMP[:, 0], _RAMP[:, k]) for k in (1, 2, 3)]).round().astype(np.uint8)


# ------------------------------------------------------------------------------- clouds
def _record_stats(records: np.ndarray) -> tuple[int, int]:
    """(largest RGB value, largest class code) of the staged records, slice by slice (0 for a
    field the point format lacks)."""
    from workstation.publish.copc import SLICE_POINTS

    names = records.dtype.names
    rgb_max = class_max = 0
    for s in range(0, len(records), SLICE_POINTS):
        part = records[s : s + SLICE_POINTS]
        if "red" in names:
            rgb_max = max(rgb_max, *(int(part[c].max()) for c in ("red", "green", "blue")))
        class_max = max(class_max, int(part["classification"].max()))
    return rgb_max, class_max


def _colour_mode(rgb_max: int, class_max: int) -> tuple[str, int]:
    """(``rgb``, ``class`` or ``elevation``; the right shift of RGB to 8 bits): RGB when some
    colour is non-zero, else classes when some point is classified (class > 1), else
    elevation."""
    if rgb_max:
        return "rgb", 8 if rgb_max > 255 else 0
    return ("class" if class_max > 1 else "elevation"), 0


def _node_points(records, tree, s: int, e: int, scales, offsets):
    """(CRS xyz (n, 3) float64, records) of the points of the node run ``s:e`` of the
    :class:`~workstation.publish.copc.Octree` ``tree``."""
    rec = np.asarray(records[np.sort(tree.src[s:e])])
    xyz = np.column_stack([rec[c] * scales[i] + offsets[i] for i, c in enumerate("XYZ")])
    return xyz, rec


def _node_colours(rec, xyz, mode: tuple, zrange) -> np.ndarray:
    """(n, 3) uint8 colours of a node's records by the colour ``mode`` of
    :func:`_colour_mode` (``zrange``: the cloud's height range for the ramp)."""
    from workstation.core.classes import class_colors

    kind, shift = mode
    if kind == "rgb":
        return np.column_stack([rec[c] >> shift for c in ("red", "green", "blue")]).astype(np.uint8)
    if kind == "class":
        return class_colors(rec["classification"])
    return elevation_colors(xyz[:, 2], *zrange)


def _write_tile(staged, frame: Frame, folder: Path, node: tuple, mode, zrange, with_classes: bool):
    """Write the GLB of one node (index, start, end, URI) of the
    :class:`~workstation.publish.copc.StagedOctree`; its points' box (lo, hi) and count."""
    _, s, e, uri = node
    scales, offsets = np.asarray(staged.header.scales, float), np.asarray(staged.header.offsets, float)
    xyz, rec = _node_points(staged.records, staged.tree, s, e, scales, offsets)
    local = frame.to_local(xyz)
    lo, hi = local.min(axis=0), local.max(axis=0)
    glb = points_glb(local, _node_colours(rec, xyz, mode, zrange), rec["classification"] if with_classes else None,
                     (lo + hi) / 2.0)
    (folder / uri).write_bytes(glb)
    return lo, hi, e - s


def _write_tiles(staged, frame: Frame, folder: Path, mode, zrange, with_classes: bool, workers: int | None = None):
    """Write one GLB per node into ``folder/tiles``, ``workers`` nodes at a time in threads
    (pyproj, most numpy work and the file writes release the GIL; default: the CPU count);
    (node boxes lo, hi (k, 3), URIs)."""
    from concurrent.futures import ThreadPoolExecutor

    from workstation.core.progress import progress_bar
    from workstation.publish.copc import compact1by2

    (folder / "tiles").mkdir()
    tree = staged.tree
    k = len(tree.starts)
    ends = np.r_[tree.starts[1:], len(tree.src)].astype(np.int64)
    keys = np.column_stack([compact1by2(tree.prefix >> np.uint64(i)).astype(np.int64) for i in range(3)])
    uris = ["tiles/{}-{}-{}-{}.glb".format(int(d), *key) for d, key in zip(tree.level.tolist(), keys.tolist())]
    nodes = list(zip(range(k), tree.starts.tolist(), ends.tolist(), uris))
    lo, hi = np.empty((k, 3)), np.empty((k, 3))
    workers = max(1, workers or os.cpu_count() or 1)
    with ThreadPoolExecutor(workers) as pool, progress_bar("3D Tiles", total=len(tree.src), unit="points") as advance:
        jobs = pool.map(lambda node: _write_tile(staged, frame, folder, node, mode, zrange, with_classes), nodes)
        for i, (a, b, n) in enumerate(jobs):
            lo[i], hi[i] = a, b
            advance(n)
    return lo, hi, uris


def _tile_tree(tree, lo, hi, uris, spacing_m: float) -> dict:
    """The nested tile dicts of the octree: boxes grown to hold every descendant, geometric
    error = the level's spacing (0 for leaves), children in Morton order."""
    k = len(uris)
    index = {(int(d), int(p)): i for i, (d, p) in enumerate(zip(tree.level.tolist(), tree.prefix.tolist()))}
    parent = np.array([index.get((int(d) - 1, int(p) >> 3), -1)
                       for d, p in zip(tree.level.tolist(), tree.prefix.tolist())])
    if (parent[tree.level > 0] < 0).any():
        raise StageError("3dtiles", "an octree node has no parent node")
    lo, hi = lo.copy(), hi.copy()
    for i in np.argsort(-tree.level.astype(np.int64), kind="stable").tolist():  # deepest first
        if parent[i] >= 0:
            lo[parent[i]] = np.minimum(lo[parent[i]], lo[i])
            hi[parent[i]] = np.maximum(hi[parent[i]], hi[i])
    has_child = np.zeros(k, bool)
    has_child[parent[parent >= 0]] = True
    tiles = [{"boundingVolume": {"box": _box(lo[i], hi[i])},
              "geometricError": float(spacing_m / 2.0 ** int(tree.level[i])) if has_child[i] else 0.0,
              "content": {"uri": uris[i]}} for i in range(k)]
    for i in range(k):
        if parent[i] >= 0:
            tiles[parent[i]].setdefault("children", []).append(tiles[i])
    roots = np.flatnonzero(parent < 0)
    if len(roots) != 1:
        raise StageError("3dtiles", f"the octree has {len(roots)} root nodes")
    return tiles[int(roots[0])]


def _tileset_json(root: dict, frame: Frame, geometric_error: float, refine: str) -> dict:
    """The tileset.json document: the root tile with its ``refine`` and the frame's
    ``transform`` (column-major, as 3D Tiles stores matrices), the frame in ``extras``."""
    root = {**root, "refine": refine}
    if frame.transform is not None:
        root["transform"] = frame.transform.T.ravel().tolist()  # column-major
    return {"asset": {"version": TILESET_VERSION, "generator": "workstation"}, "geometricError": float(geometric_error),
            "root": root, "extras": frame.extras()}


def _stage(src: Path, tmp_dir: Path, chunk_points: int):
    """Stage the cloud file ``src`` as a plain LAS in ``tmp_dir`` with the COPC writer's
    staging (chunk by chunk); (header, staged path, CRS)."""
    import laspy

    from workstation.io import iter_chunks
    from workstation.publish.copc import copc_point_format, stage_records

    with laspy.open(str(src)) as f:
        bounds = (np.asarray(f.header.mins), np.asarray(f.header.maxs))
    chunks = iter_chunks(src, chunk_points)
    first = next(chunks, None)
    if first is None or first.n == 0:
        raise InvalidInputError("the cloud has no points", "a tileset needs at least one point", path=src)
    staged = tmp_dir / "records.las"
    header = stage_records(first, chunks, staged, copc_point_format(first.attrs), bounds, None, None)
    return header, staged, first.crs


def write_cloud_tileset(src, folder, *, params=None, chunk_points: int = 2_000_000) -> TilesetResult:
    """Write the cloud file ``src`` (LAS/LAZ/COPC, read in chunks of ``chunk_points``) as a 3D
    Tiles tileset in ``folder`` (this exact folder, which must not exist; see
    :func:`save_tileset` for an atomic write). ``params`` is the octree's
    :class:`~workstation.publish.copc.CopcParams` (its defaults when None)."""
    from workstation.publish.copc import CopcParams, StagedOctree, build_octree, staged_records

    src, folder = Path(src), Path(folder)
    params = params or CopcParams()
    folder.mkdir(parents=True)
    with tempfile.TemporaryDirectory(prefix=".stage.", dir=folder.parent) as tmp:
        header, staged, crs = _stage(src, Path(tmp), chunk_points)
        records = staged_records(staged, header)
        res = write_octree_tileset(StagedOctree(records, header, build_octree(records, header, params), crs, params),
                                   folder)
        del records
    return res


def write_octree_tileset(staged, folder) -> TilesetResult:
    """Write the :class:`~workstation.publish.copc.StagedOctree` ``staged`` (the COPC writer's
    records and octree, e.g. from its ``on_octree`` callback) as a 3D Tiles tileset in
    ``folder`` (created when missing; it must hold nothing else): one tile per octree node."""
    from workstation.io.crs import crs_units

    t0 = time.perf_counter()
    folder, header, tree, crs = Path(folder), staged.header, staged.tree, staged.crs
    if header.point_count == 0:
        raise InvalidInputError("the cloud has no points", "a tileset needs at least one point", field="points")
    folder.mkdir(parents=True, exist_ok=True)
    rgb_max, class_max = _record_stats(staged.records)
    mins, maxs = np.asarray(header.mins, float), np.asarray(header.maxs, float)
    frame = Frame(crs, (mins + maxs) / 2.0)
    lo, hi, uris = _write_tiles(staged, frame, folder, _colour_mode(rgb_max, class_max), (mins[2], maxs[2]),
                                class_max > 0)
    unit = float(crs_units(crs).h) if crs else 1.0
    side = tree.cube.side
    root = _tile_tree(tree, lo, hi, uris, side / staged.params.cells * unit)
    doc = _tileset_json(root, frame, side * unit, "ADD")
    (folder / "tileset.json").write_text(json.dumps(doc, indent=1))
    size = sum(p.stat().st_size for p in folder.rglob("*") if p.is_file())
    res = TilesetResult(folder, int(len(tree.src)), 0, len(uris), int(tree.level.max()) + 1, size,
                        time.perf_counter() - t0)
    log.info("3D Tiles %s: %d points in %d tiles over %d levels (%.1f s)", folder, res.points, res.tiles, res.levels,
             res.seconds)
    return res


def save_tileset(src, folder, *, overwrite: bool = False, **options) -> TilesetResult:
    """Write the cloud or mesh file ``src`` (a mesh when :func:`is_mesh_file`) as a tileset in
    ``folder`` atomically: built in a temporary folder beside it and renamed onto it at the
    end; an existing ``folder`` is refused unless ``overwrite``. ``options`` go to
    :func:`write_cloud_tileset` or :func:`write_mesh_tileset`."""
    import dataclasses

    from workstation.io.atomic import atomic_dir

    writer = write_mesh_tileset if is_mesh_file(src) else write_cloud_tileset
    with atomic_dir(folder, overwrite=overwrite) as tmp:
        res = writer(src, Path(tmp) / "tileset", **options)
        for p in sorted((Path(tmp) / "tileset").iterdir()):
            os.replace(p, Path(tmp) / p.name)
        (Path(tmp) / "tileset").rmdir()
    return dataclasses.replace(res, path=Path(folder))


# ------------------------------------------------------------------------------- meshes
def _mesh_crs(path: Path) -> str | None:
    """The CRS a PLY written by the workstation records in a ``comment crs`` header line."""
    if path.suffix.lower() != ".ply":
        return None
    from workstation.io._fields import crs_from_comment

    with open(path, "rb") as f:
        head = f.read(1 << 16).split(b"end_header")[0].decode("ascii", "replace")
    lines = [ln[len("comment "):] for ln in head.splitlines() if ln.startswith("comment ")]
    return next((c for c in map(crs_from_comment, lines) if c), None)


def _texture_png(texture: np.ndarray) -> bytes:
    """The texture image (h, w, 3|4) uint8 as PNG bytes (lossless)."""
    import io

    from PIL import Image

    buf = io.BytesIO()
    Image.fromarray(np.asarray(texture, np.uint8)).save(buf, format="PNG")
    return buf.getvalue()


def _texture_at(texture: np.ndarray, uv: np.ndarray) -> np.ndarray:
    """(n, 3) uint8 texel colours at OBJ-convention ``uv`` (origin bottom left), nearest texel."""
    tex = np.asarray(texture)
    h, w = tex.shape[:2]
    col = np.clip(np.floor(uv[:, 0] * w), 0, w - 1).astype(np.int64)
    row = np.clip(np.floor((1.0 - uv[:, 1]) * h), 0, h - 1).astype(np.int64)
    px = tex[row, col]
    return (px[:, :3] if px.ndim == 2 else np.repeat(px[:, None], 3, axis=1)).astype(np.uint8)


def _triangles_glb(local: np.ndarray, faces: np.ndarray, *, uv=None, texture=None, rgb=None) -> bytes:
    """A GLB of the triangles ``faces`` over tileset coordinates ``local`` (n, 3), stored
    relative to the centre of their box: with ``TEXCOORD_0`` (OBJ
    convention ``uv``) and ``texture`` embedded as PNG, or ``COLOR_0`` (``rgb``), in a
    double-sided, non-metallic, fully rough material."""
    from workstation.core.color import rgb_to_u8

    lo, hi = local.min(axis=0), local.max(axis=0)
    centre = (lo + hi) / 2.0
    g = _Glb()
    attrs = {"POSITION": g.accessor(_yup(local - centre).astype(np.float32), _FLOAT, "VEC3", minmax=True)}
    pbr = {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}
    if uv is not None and texture is not None:
        uv = np.asarray(uv, np.float32).copy()
        uv[:, 1] = 1.0 - uv[:, 1]  # glTF's texture origin is the top left
        attrs["TEXCOORD_0"] = g.accessor(uv, _FLOAT, "VEC2")
        g.doc.update(images=[{"bufferView": g.view(_texture_png(texture)), "mimeType": "image/png"}],
                     samplers=[{"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 33071}],
                     textures=[{"sampler": 0, "source": 0}])
        pbr["baseColorTexture"] = {"index": 0}
    elif rgb is not None:
        attrs["COLOR_0"] = g.accessor(rgb_to_u8(np.asarray(rgb)), _UBYTE, "VEC3", normalized=True, stride=4)
    indices = g.accessor(np.asarray(faces, np.uint32).ravel(), _UINT, "SCALAR", target=_ELEMENT_ARRAY_BUFFER)
    g.doc.update(scene=0, scenes=[{"nodes": [0]}], nodes=[{"mesh": 0, "translation": _yup(centre[None])[0].tolist()}],
                 materials=[{"name": "surface", "pbrMetallicRoughness": pbr, "doubleSided": True}],
                 meshes=[{"primitives": [{"attributes": attrs, "indices": indices, "material": 0, "mode": 4}]}])
    return g.bytes()


def _mesh_colours(mesh):
    """The mesh's (uv, texture, rgb) for :func:`_triangles_glb`: UVs and the texture of a
    textured mesh, else its vertex colours (None where absent)."""
    tex = mesh.meta.get("texture")
    if "uv" in mesh.vertex_attrs and tex is not None:
        return np.asarray(mesh.vertex_attrs["uv"], float), np.asarray(tex), None
    return None, None, mesh.vertex_attrs.get("rgb")


def _charts(faces: np.ndarray, n_vertices: int) -> np.ndarray:
    """The chart (connected set of faces sharing vertices, so sharing UVs) of every vertex."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    a = np.concatenate([faces[:, 0], faces[:, 1]])
    b = np.concatenate([faces[:, 1], faces[:, 2]])
    graph = coo_matrix((np.ones(len(a), np.int8), (a, b)), shape=(n_vertices, n_vertices))
    return connected_components(graph, directed=False)[1]


def _shelf_pack(w: np.ndarray, h: np.ndarray, width: int) -> tuple[np.ndarray, np.ndarray, int]:
    """(x, y of each rectangle, total height): rectangles ``w`` x ``h`` (pixels, each at most
    ``width`` wide) packed tallest first into rows (shelves) of ``width``; a loop over rows."""
    order = np.lexsort((np.arange(len(h)), -h))
    cum = np.concatenate([[0], np.cumsum(w[order])])
    x, y = np.empty(len(w), np.int64), np.empty(len(w), np.int64)
    s, top = 0, 0
    while s < len(order):
        e = max(int(np.searchsorted(cum, cum[s] + width, side="right")) - 1, s + 1)
        x[order[s:e]] = cum[s:e] - cum[s]
        y[order[s:e]] = top
        top += int(h[order[s]])
        s = e
    return x, y, top


def sub_atlas(texture: np.ndarray, uv: np.ndarray, faces: np.ndarray, margin: int = 0):
    """(a texture holding only the texels that the triangles ``faces`` reach through their
    OBJ-convention ``uv`` (n, 2), their UVs in it): the faces' charts (faces joined by shared
    vertices) are cut from ``texture`` as the boxes of texels a bilinear lookup at their UVs
    reads, grown by ``margin`` texels, and packed into a new image, so every UV samples the
    same colours. UVs outside [0, 1] (a repeating texture) keep the whole texture.

    Examples
    --------
    >>> tex = np.arange(80 * 100 * 3).reshape(80, 100, 3).astype(np.uint8)
    >>> uv = np.array([[0.1, 0.5], [0.3, 0.5], [0.1, 0.7], [0.8, 0.1], [0.9, 0.1], [0.8, 0.2]])
    >>> sub, uv2 = sub_atlas(tex, uv, np.array([[0, 1, 2], [3, 4, 5]]))
    >>> sub.shape
    (28, 25, 3)
    """
    uv = np.asarray(uv, float)
    if not len(uv) or uv.min() < 0.0 or uv.max() > 1.0:
        return texture, uv
    h, w = texture.shape[:2]
    col, row = uv[:, 0] * w, (1.0 - uv[:, 1]) * h  # texel coordinates, rows from the top
    chart = _charts(np.asarray(faces), len(uv))
    k = int(chart.max()) + 1
    lo_c, hi_c = _group(np.minimum, chart, col, k, np.inf), _group(np.maximum, chart, col, k, -np.inf)
    lo_r, hi_r = _group(np.minimum, chart, row, k, np.inf), _group(np.maximum, chart, row, k, -np.inf)
    # bilinear at t reads texels floor(t - 0.5) and, with a weight above 0, the next one
    c0 = np.maximum(np.floor(lo_c - 0.5).astype(np.int64) - margin, 0)
    c1 = np.minimum(np.ceil(hi_c - 0.5).astype(np.int64) + 1 + margin, w)
    r0 = np.maximum(np.floor(lo_r - 0.5).astype(np.int64) - margin, 0)
    r1 = np.minimum(np.ceil(hi_r - 0.5).astype(np.int64) + 1 + margin, h)
    boxes, box = np.unique(np.column_stack([c0, c1, r0, r1]), axis=0, return_inverse=True)
    outer = _outer_boxes(boxes)[box.reshape(-1)]  # a chart whose box lies in another's is cut with it
    kept, box = np.unique(outer, return_inverse=True)
    box = box.reshape(-1)
    c0, c1, r0, r1 = boxes[kept].T
    cw, ch = c1 - c0, r1 - r0
    width = int(max(cw.max(), np.ceil(np.sqrt(float((cw * ch).sum())) * 1.1)))
    x, y, height = _shelf_pack(cw, ch, width)
    area = cw * ch
    owner = np.repeat(np.arange(len(area)), area)  # every texel of every box, box by box
    i = np.arange(len(owner)) - np.repeat(np.cumsum(area) - area, area)
    dx, dy = i % cw[owner], i // cw[owner]
    out = np.zeros((height, width, *texture.shape[2:]), texture.dtype)
    out[y[owner] + dy, x[owner] + dx] = texture[r0[owner] + dy, c0[owner] + dx]
    at = box[chart]
    new_col, new_row = col - c0[at] + x[at], row - r0[at] + y[at]
    return out, np.column_stack([new_col / width, 1.0 - new_row / height])


def _outer_boxes(boxes: np.ndarray) -> np.ndarray:
    """For texel boxes (k, 4: c0, c1, r0, r1, distinct), the index of a box that holds each
    one: itself, or a larger box that contains it. The boxes are painted smallest first onto
    a label image, so each texel ends with the largest box over it; a box whose first and
    last texels carry the same other box, which contains them both, lies inside it."""
    c0, c1, r0, r1 = boxes.T
    oc, orow = int(c0.min()), int(r0.min())
    label = np.full((int(r1.max()) - orow, int(c1.max()) - oc), -1, np.int64)
    area = (c1 - c0) * (r1 - r0)
    order = np.argsort(area, kind="stable")
    owner = np.repeat(order, area[order])
    i = np.arange(len(owner)) - np.repeat(np.cumsum(area[order]) - area[order], area[order])
    w = (c1 - c0)[owner]
    label[r0[owner] + i // w - orow, c0[owner] + i % w - oc] = owner  # later (larger) boxes overwrite
    a, b = label[r0 - orow, c0 - oc], label[r1 - 1 - orow, c1 - 1 - oc]
    inside = (a == b) & (c0[a] <= c0) & (c1[a] >= c1) & (r0[a] <= r0) & (r1[a] >= r1)
    return np.where(inside, a, np.arange(len(boxes)))


def _group(op, key: np.ndarray, values: np.ndarray, k: int, fill: float) -> np.ndarray:
    """``op`` (np.minimum or np.maximum) of ``values`` per group ``key`` in 0..k-1."""
    out = np.full(k, fill)
    op.at(out, key, values)
    return out


def _submesh(mesh, faces: np.ndarray):
    """The mesh of the faces with indices ``faces``: (its vertex indices into ``mesh``, the
    :class:`~workstation.core.products.Mesh` with those vertices and their attributes)."""
    from workstation.core.products import Mesh

    used, inv = np.unique(mesh.faces[faces].ravel(), return_inverse=True)
    attrs = {k: np.asarray(v)[used] for k, v in mesh.vertex_attrs.items()}
    return used, Mesh(mesh.vertices[used], inv.reshape(-1, 3), attrs, crs=mesh.crs, meta=mesh.meta)


def weld_ids(vertices: np.ndarray) -> np.ndarray:
    """An id per vertex, equal for vertices at the same place (one lexicographic sort).

    Examples
    --------
    >>> weld_ids(np.array([[1.0, 0, 0], [0, 0, 0], [1, 0, 0]])).tolist()
    [1, 0, 1]
    """
    v = np.asarray(vertices)
    order = np.lexsort((v[:, 2], v[:, 1], v[:, 0]))
    s = v[order]
    new = np.r_[True, (s[1:] != s[:-1]).any(axis=1)] if len(v) else np.zeros(0, bool)
    ids = np.empty(len(v), np.int64)
    ids[order] = np.cumsum(new) - 1
    return ids


def _lod_mesh(mesh, target: int, weld: np.ndarray):
    """The quadric-decimated mesh (about ``target`` faces; open borders kept in place, so a
    tile meets its neighbours at any level) with vertex colours (from the texture at its
    vertices when textured), or None when decimation does not reduce it. Vertices with the
    same ``weld`` id (:func:`weld_ids`) become one first (a textured mesh has one vertex per
    face corner, which leaves every edge a border that decimation could not collapse)."""
    from workstation.core.products import Mesh
    from workstation.mesh.simplify import DecimateParams, decimate

    if target < 4:
        return None
    uv, tex, rgb = _mesh_colours(mesh)
    colours = _texture_at(tex, uv) if tex is not None else rgb
    _, first, inv = np.unique(weld, return_index=True, return_inverse=True)  # first: a vertex at each place
    faces = inv.reshape(-1)[mesh.faces]
    faces = faces[(faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])]
    if len(faces) < 4:
        return None
    va = {"rgb": np.asarray(colours)[first]} if colours is not None else {}
    plain = Mesh(mesh.vertices[first], faces, va, crs=mesh.crs)
    coarse, _ = decimate(plain, DecimateParams(target_faces=target, preserve_normal=False))
    return coarse if coarse.n_faces < len(faces) else None


def _surface_distance(full: np.ndarray, full_faces: np.ndarray, coarse: np.ndarray, coarse_faces: np.ndarray) -> float:
    """The Hausdorff distance between the vertices of two meshes (tileset metres) and the
    other mesh's surface, both ways (MeshLab's sampling filter, every vertex a sample): how
    far the simplified surface is from the full one at most."""
    from workstation.interop.pymeshlab import import_pymeshlab, meshset_with

    pml = import_pymeshlab()
    far = pml.PureValue(float(np.ptp(np.vstack([full, coarse]), axis=0).max()) * 2.0 + 1.0)
    ms = meshset_with(pml.Mesh(full, np.asarray(full_faces, np.int32)), pml.Mesh(coarse, np.asarray(coarse_faces, np.int32)))
    d = 0.0
    for a, b, n in ((0, 1, len(full)), (1, 0, len(coarse))):
        r = ms.get_hausdorff_distance(sampledmesh=a, targetmesh=b, samplevert=True, sampleedge=False,
                                      sampleface=False, samplenum=int(n), maxdist=far)
        d = max(d, float(r["max"]))
    return d


def split_faces(centroids: np.ndarray, max_faces: int) -> dict:
    """The spatial tile tree of triangles by their ``centroids`` (m, 3): a node holds the
    face indices ``faces`` of its subtree and, when it has more than ``max_faces``, is split
    at the middle of its centroids' box along every axis at least half as long as the
    longest (8 children for a compact object, 4 for terrain, 2 for a long strip); a triangle
    goes whole to the child of its centroid. Nodes are dicts ``{faces, path, children}``;
    ``path`` is the root ``r`` followed by the child numbers.

    Every split has at least two non-empty children (the centroids at the two ends of the
    longest axis fall on both sides), so the tree is finite for any input.

    Examples
    --------
    >>> c = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.1]])
    >>> t = split_faces(c, 1)
    >>> [(k["path"], k["faces"].tolist()) for k in t["children"]]
    [('r0', [0]), ('r1', [1]), ('r2', [2]), ('r3', [3])]
    """
    def split(idx: np.ndarray, path: str) -> dict:
        node = {"faces": idx, "path": path, "children": []}
        c = centroids[idx]
        lo, hi = c.min(axis=0), c.max(axis=0)
        ext = hi - lo
        if len(idx) <= max_faces or ext.max() <= 0:
            return node
        axes = np.flatnonzero(ext >= ext.max() / 2.0)
        mid = (lo + hi) / 2.0
        code = np.zeros(len(idx), np.int64)
        for k, a in enumerate(axes.tolist()):
            code |= (c[:, a] >= mid[a]).astype(np.int64) << k
        order = np.argsort(code, kind="stable")
        bounds = np.searchsorted(code[order], np.arange((1 << len(axes)) + 1))
        for child, (s, e) in enumerate(zip(bounds[:-1].tolist(), bounds[1:].tolist())):
            if e > s:
                node["children"].append(split(idx[order[s:e]], f"{path}{child}"))
        return node

    if max_faces < 1:
        raise InvalidInputError(f"max_faces {max_faces} must be at least 1", field="max_faces")
    return split(np.arange(len(centroids)), "r")


def _mesh_tile(mesh, local: np.ndarray, weld: np.ndarray, node: dict, frame: Frame, folder: Path, max_faces: int):
    """Write the GLB of ``node`` of :func:`split_faces` and those of its subtree into
    ``folder/tiles``; (its tile dict, geometric error, box lo, box hi). A leaf holds its
    triangles at full resolution with the part of the texture they use; an inner node the
    quadric simplification of its subtree's triangles to ``max_faces`` (vertex colours),
    whose error is the larger of the Hausdorff distance between it and the full-resolution
    triangles (:func:`_surface_distance`) and its median edge length (its vertex colours show
    no detail finer than its edges, where the leaves show the texture), and at least its
    children's. ``weld``: :func:`weld_ids`."""
    kids = [_mesh_tile(mesh, local, weld, k, frame, folder, max_faces) for k in node["children"]]
    used, sub = _submesh(mesh, node["faces"])
    full = local[used]
    lo, hi = full.min(axis=0), full.max(axis=0)
    coarse = _lod_mesh(sub, max_faces, weld[used]) if kids else None
    if coarse is None:  # a leaf, or an inner node that decimation cannot reduce
        uv, tex, rgb = _mesh_colours(sub)
        if tex is not None:
            tex, uv = sub_atlas(tex, uv, sub.faces)
        glb = _triangles_glb(full, sub.faces, uv=uv, texture=tex, rgb=rgb)
        error = 0.0
    else:
        clocal = frame.to_local(coarse.vertices)
        glb = _triangles_glb(clocal, coarse.faces, rgb=coarse.vertex_attrs.get("rgb"))
        edges = np.linalg.norm(clocal[coarse.faces] - clocal[np.roll(coarse.faces, 1, axis=1)], axis=2)
        error = max(_surface_distance(full, sub.faces, clocal, coarse.faces), float(np.median(edges)))
        lo, hi = np.minimum(lo, clocal.min(axis=0)), np.maximum(hi, clocal.max(axis=0))
    if kids:
        error = max(error, _PAD, *(k[1] for k in kids))
        lo = np.min([lo, *(k[2] for k in kids)], axis=0)
        hi = np.max([hi, *(k[3] for k in kids)], axis=0)
    uri = f"tiles/{node['path']}.glb"
    (folder / uri).write_bytes(glb)
    tile = {"boundingVolume": {"box": _box(lo, hi)}, "geometricError": float(error), "content": {"uri": uri}}
    if kids:
        tile["children"] = [k[0] for k in kids]
    return tile, error, lo, hi


def write_mesh_tileset(src, folder, *, crs=None, max_faces: int = 50_000) -> TilesetResult:
    """Write the mesh file ``src`` (OBJ + MTL + texture, or PLY with faces) as a 3D Tiles tileset in
    ``folder`` (which must not exist): the triangles split into a tile tree
    (:func:`split_faces`) of leaves of at most ``max_faces`` full-resolution triangles under
    simplified inner tiles, refined by REPLACE, one GLB per tile in ``folder/tiles``. ``crs``
    is used when the file records none (a PLY's ``comment crs``)."""
    from workstation.io.mesh import read_mesh

    t0 = time.perf_counter()
    src, folder = Path(src), Path(folder)
    if max_faces < 1:
        raise InvalidInputError(f"max_faces {max_faces} must be at least 1", field="max_faces")
    mesh = read_mesh(src)
    if mesh.n_faces == 0:
        raise InvalidInputError("the mesh has no faces", "a mesh tileset needs triangles", path=src)
    crs = _mesh_crs(src) or crs
    frame = Frame(crs, (mesh.vertices.min(axis=0) + mesh.vertices.max(axis=0)) / 2.0)
    local = frame.to_local(mesh.vertices)
    tree = split_faces(local[mesh.faces].mean(axis=1), max_faces)
    (folder / "tiles").mkdir(parents=True)
    root, error, lo, hi = _mesh_tile(mesh, local, weld_ids(mesh.vertices), tree, frame, folder, max_faces)
    top = 2.0 * error if root.get("children") else float(np.linalg.norm(hi - lo)) / 100.0
    doc = _tileset_json(root, frame, top, "REPLACE")
    (folder / "tileset.json").write_text(json.dumps(doc, indent=1))
    paths = [t["content"]["uri"] for t in _walk_tiles(root)]
    size = sum(p.stat().st_size for p in folder.rglob("*") if p.is_file())
    res = TilesetResult(folder, 0, mesh.n_faces, len(paths), max(len(Path(p).stem) for p in paths), size,
                        time.perf_counter() - t0)
    log.info("3D Tiles %s: %d faces in %d tiles over %d levels (%.1f s)", folder, res.faces, res.tiles, res.levels,
             res.seconds)
    return res


def _walk_tiles(tile: dict):
    """Every tile of a tile tree, depth first."""
    yield tile
    for child in tile.get("children", []):
        yield from _walk_tiles(child)


def is_mesh_file(path) -> bool:
    """An OBJ, or a PLY whose header declares faces (a PLY of points is a cloud)."""
    p = Path(path)
    if p.suffix.lower() == ".obj":
        return True
    if p.suffix.lower() != ".ply":
        return False
    with open(p, "rb") as f:
        head = f.read(1 << 16).split(b"end_header")[0]
    return any(ln.split()[:2] == [b"element", b"face"] and int(ln.split()[2]) > 0
               for ln in head.splitlines() if len(ln.split()) >= 3)


# ------------------------------------------------------------------------------- sites
def find_meshes(paths) -> list[Path]:
    """The mesh files (:func:`is_mesh_file`) among ``paths`` (files, or folders searched two
    levels deep as :func:`workstation.publish.site.collect_inputs` does)."""
    from workstation.publish.site import walk_files

    found = []
    for raw in paths:
        p = Path(raw)
        found += [f for f in ([p] if p.is_file() else walk_files(p)) if is_mesh_file(f)]
    return found


def tileset_writer(folder, results: dict, key):
    """An ``on_octree`` callback for :func:`workstation.publish.copc.write_copc_chunks` that
    writes the COPC writer's octree as a tileset in ``folder`` (:func:`write_octree_tileset`)
    and stores its :class:`TilesetResult` in ``results[key]``."""

    def write(staged) -> None:
        results[key] = write_octree_tileset(staged, folder)

    return write


def publish_tilesets(inputs, clouds, folder, *, crs=None, params=None, chunk_points: int = 2_000_000,
                     written=None) -> list[dict]:
    """Write ``folder/NAME/tileset.json`` for every cloud file in ``clouds`` and every mesh
    found in ``inputs`` (meshes without a CRS of their own take ``crs``, the site's); their
    ``site.json`` entries (``name``, ``kind`` cloud/mesh, ``url`` relative to the site,
    ``source``, ``tiles``, ``points``, ``faces``). ``written`` maps cloud files whose tileset
    is already in ``folder/NAME`` (by :func:`tileset_writer` while their COPC was written,
    NAME as given here: clouds are named first, in order) to its :class:`TilesetResult`; they
    are not read again."""
    from workstation.core.progress import track
    from workstation.publish.site import unique_names

    folder, written = Path(folder), written or {}
    folder.mkdir(exist_ok=bool(written))
    meshes = [m for m in find_meshes(inputs) if m not in set(map(Path, clouds))]
    names = unique_names([*clouds, *meshes])
    kinds = ["cloud"] * len(clouds) + ["mesh"] * len(meshes)
    jobs = list(zip([*clouds, *meshes], names, kinds))
    entries = []
    for src, name, kind in track(jobs, "3D Tiles", unit="tilesets"):
        if kind == "cloud" and src in written:
            res = written[src]
        elif kind == "cloud":
            res = write_cloud_tileset(src, folder / name, params=params, chunk_points=chunk_points)
        else:
            res = write_mesh_tileset(src, folder / name, crs=crs)
        entries.append({"name": name, "kind": kind, "url": f"{folder.name}/{name}/tileset.json", "source": str(src),
                        "tiles": res.tiles, "points": res.points, "faces": res.faces})
    return entries
