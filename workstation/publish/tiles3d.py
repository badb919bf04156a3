"""3D Tiles 1.1 tilesets (https://docs.ogc.org/cs/22-025r4/22-025r4.html) of point clouds and meshes.

A tileset is a folder with ``tileset.json`` (asset version ``1.1``, an explicit tree of tiles)
and one glTF 2.0 binary (``.glb``) per tile with content, as CesiumJS and the three.js 3D
Tiles renderers stream them.

Point clouds
------------
The tile tree is the COPC writer's octree (:mod:`workstation.publish.copc`): the records are
staged the same way, sorted by Morton code and split into levels by
:func:`~workstation.publish.copc.assign_levels` (a node keeps one point per cell of a
``cells``³ grid and passes the rest to its eight children), so a tile is exactly a COPC node
and every point is in exactly one tile. Tiles refine by ``ADD`` (a child adds its points to
its parents'). A tile's ``geometricError`` is its level's point spacing in metres
(``side / cells / 2**level``), halving per level; a leaf, which holds every point left to it,
has 0. Bounding volumes are boxes around the tile's points and those of its descendants, so a
parent's box holds its children's.

Each tile is a glTF mesh of one ``POINTS`` primitive: ``POSITION`` (float32, relative to the
node's ``translation``, the centre of the tile's box), ``COLOR_0`` (unsigned bytes,
normalised: the RGB of the cloud when it has some, else the ASPRS class colour when it is
classified, else an elevation ramp) and ``_CLASSIFICATION`` (the ASPRS class, unsigned byte, padded
to 4 bytes as glTF aligns vertex attributes) when some point has a class other than 0.

Meshes
------
A mesh (OBJ with its MTL and texture as ``ws mesh`` / texturing write them, PLY with vertex
colours) becomes one ``.glb`` (triangles, ``TEXCOORD_0`` and the texture embedded as PNG, or
``COLOR_0``) in a tileset whose root is a quadric-decimated copy
(:func:`workstation.mesh.simplify.decimate`, colours sampled from the texture at the
vertices) refined by ``REPLACE`` into the full mesh. The root's ``geometricError`` is the
largest distance from a vertex of the full mesh to the nearest vertex of the simplified one
(an upper bound of how far its surface moved, in metres).

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


class _ChunkStats:
    """Largest RGB value and class code of the chunks passed through :meth:`tap`."""

    def __init__(self):
        self.rgb_max, self.class_max = 0, 0

    def tap(self, chunks):
        for c in chunks:
            if "rgb" in c.attrs and c.n:
                self.rgb_max = max(self.rgb_max, int(np.max(c.attrs["rgb"])))
            if "classification" in c.attrs and c.n:
                self.class_max = max(self.class_max, int(np.max(c.attrs["classification"])))
            yield c

    def colour_mode(self) -> tuple[str, int]:
        """(``rgb``, ``class`` or ``elevation``; the right shift of RGB to 8 bits): RGB when
        some colour is non-zero, else classes when some point is classified (class > 1), else
        elevation."""
        if self.rgb_max:
            return "rgb", 8 if self.rgb_max > 255 else 0
        return ("class" if self.class_max > 1 else "elevation"), 0


# ------------------------------------------------------------------------------- clouds
@dataclass(frozen=True)
class _Octree:
    """The COPC octree of the staged records: ``src`` (record index per point, node by node),
    ``starts`` (first index of each node in ``src``), node ``level`` and Morton ``prefix``,
    the cube (``corner``, ``side``) and the records' ``scales``/``offsets``."""

    src: np.ndarray
    starts: np.ndarray
    level: np.ndarray
    prefix: np.ndarray
    side: float
    scales: np.ndarray
    offsets: np.ndarray


def _octree(records: np.ndarray, header, params) -> _Octree:
    """The octree of :mod:`workstation.publish.copc` over the staged records."""
    from workstation.publish.copc import _compact_index, _cube, _morton_codes, _node_runs, assign_levels

    cube = _cube(header)
    codes, _, _ = _morton_codes(records, header, cube)
    perm = _compact_index(np.argsort(codes, kind="stable"))
    codes = codes[perm]
    order, starts, level, prefix = _node_runs(codes, assign_levels(codes, params))
    del codes
    return _Octree(perm[order], starts, level, prefix, cube.side, np.asarray(header.scales, float),
                   np.asarray(header.offsets, float))


def _node_points(records, tree: _Octree, s: int, e: int):
    """(CRS xyz (n, 3) float64, records) of the points of the node run ``s:e``."""
    rec = np.asarray(records[np.sort(tree.src[s:e])])
    xyz = np.column_stack([rec[c] * tree.scales[i] + tree.offsets[i] for i, c in enumerate("XYZ")])
    return xyz, rec


def _node_colours(rec, xyz, mode: tuple, zrange) -> np.ndarray:
    """(n, 3) uint8 colours of a node's records by the colour ``mode`` of
    :meth:`_ChunkStats.colour_mode` (``zrange``: the cloud's height range for the ramp)."""
    from workstation.core.classes import class_colors

    kind, shift = mode
    if kind == "rgb":
        return np.column_stack([rec[c] >> shift for c in ("red", "green", "blue")]).astype(np.uint8)
    if kind == "class":
        return class_colors(rec["classification"])
    return elevation_colors(xyz[:, 2], *zrange)


def _write_tile(records, tree: _Octree, frame: Frame, folder: Path, node: tuple, mode, zrange, with_classes: bool):
    """Write the GLB of one node (index, start, end, URI); its points' box (lo, hi) and count."""
    _, s, e, uri = node
    xyz, rec = _node_points(records, tree, s, e)
    local = frame.to_local(xyz)
    lo, hi = local.min(axis=0), local.max(axis=0)
    glb = points_glb(local, _node_colours(rec, xyz, mode, zrange), rec["classification"] if with_classes else None,
                     (lo + hi) / 2.0)
    (folder / uri).write_bytes(glb)
    return lo, hi, e - s


def _write_tiles(records, tree: _Octree, frame: Frame, folder: Path, mode, zrange, with_classes: bool,
                 workers: int | None = None):
    """Write one GLB per node into ``folder/tiles``, ``workers`` nodes at a time in threads
    (pyproj, most numpy work and the file writes release the GIL; default: the CPU count);
    (node boxes lo, hi (k, 3), URIs)."""
    from concurrent.futures import ThreadPoolExecutor

    from workstation.core.progress import progress_bar
    from workstation.publish.copc import _compact1by2

    (folder / "tiles").mkdir()
    k = len(tree.starts)
    ends = np.r_[tree.starts[1:], len(tree.src)].astype(np.int64)
    keys = np.column_stack([_compact1by2(tree.prefix >> np.uint64(i)).astype(np.int64) for i in range(3)])
    uris = ["tiles/{}-{}-{}-{}.glb".format(int(d), *key) for d, key in zip(tree.level.tolist(), keys.tolist())]
    nodes = list(zip(range(k), tree.starts.tolist(), ends.tolist(), uris))
    lo, hi = np.empty((k, 3)), np.empty((k, 3))
    workers = max(1, workers or os.cpu_count() or 1)
    with ThreadPoolExecutor(workers) as pool, progress_bar("3D Tiles", total=len(tree.src), unit="points") as advance:
        jobs = pool.map(lambda node: _write_tile(records, tree, frame, folder, node, mode, zrange, with_classes), nodes)
        for i, (a, b, n) in enumerate(jobs):
            lo[i], hi[i] = a, b
            advance(n)
    return lo, hi, uris


def _tile_tree(tree: _Octree, lo, hi, uris, spacing_m: float) -> dict:
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
    staging (chunk by chunk); (header, staged path, CRS, :class:`_ChunkStats` of the chunks)."""
    import laspy

    from workstation.io import iter_chunks
    from workstation.publish.copc import _stage_records, copc_point_format

    with laspy.open(str(src)) as f:
        bounds = (np.asarray(f.header.mins), np.asarray(f.header.maxs))
    stats = _ChunkStats()
    chunks = stats.tap(iter_chunks(src, chunk_points))
    first = next(chunks, None)
    if first is None or first.n == 0:
        raise InvalidInputError("the cloud has no points", "a tileset needs at least one point", path=src)
    staged = tmp_dir / "records.las"
    header = _stage_records(first, chunks, staged, copc_point_format(first.attrs), bounds, None, None)
    return header, staged, first.crs, stats


def write_cloud_tileset(src, folder, *, params=None, chunk_points: int = 2_000_000) -> TilesetResult:
    """Write the cloud file ``src`` (LAS/LAZ/COPC, read in chunks of ``chunk_points``) as a 3D
    Tiles tileset in ``folder`` (this exact folder, which must not exist; see
    :func:`save_tileset` for an atomic write). ``params`` is the octree's
    :class:`~workstation.publish.copc.CopcParams` (its defaults when None)."""
    from workstation.io.crs import crs_units
    from workstation.publish.copc import CopcParams, _records

    t0 = time.perf_counter()
    src, folder = Path(src), Path(folder)
    params = params or CopcParams()
    folder.mkdir(parents=True)
    with tempfile.TemporaryDirectory(prefix=".stage.", dir=folder.parent) as tmp:
        header, staged, crs, stats = _stage(src, Path(tmp), chunk_points)
        records = _records(staged, header)
        tree = _octree(records, header, params)
        mins, maxs = np.asarray(header.mins, float), np.asarray(header.maxs, float)
        frame = Frame(crs, (mins + maxs) / 2.0)
        lo, hi, uris = _write_tiles(records, tree, frame, folder, stats.colour_mode(), (mins[2], maxs[2]),
                                    stats.class_max > 0)
        del records
    unit = float(crs_units(crs).h) if crs else 1.0
    spacing_m = tree.side / params.cells * unit
    root = _tile_tree(tree, lo, hi, uris, spacing_m)
    doc = _tileset_json(root, frame, tree.side * unit, "ADD")
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


def mesh_glb(mesh, frame: Frame) -> tuple[bytes, np.ndarray, np.ndarray]:
    """(GLB of the whole mesh in the tileset frame, box lo, box hi): triangles with
    ``TEXCOORD_0`` and the texture embedded as PNG (a textured mesh), or ``COLOR_0``
    (vertex colours), in a double-sided, non-metallic, fully rough material."""
    from workstation.core.color import rgb_to_u8

    local = frame.to_local(mesh.vertices)
    lo, hi = local.min(axis=0), local.max(axis=0)
    centre = (lo + hi) / 2.0
    g = _Glb()
    attrs = {"POSITION": g.accessor(_yup(local - centre).astype(np.float32), _FLOAT, "VEC3", minmax=True)}
    pbr = {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}
    tex = mesh.meta.get("texture")
    if "uv" in mesh.vertex_attrs and tex is not None:
        uv = np.asarray(mesh.vertex_attrs["uv"], np.float32).copy()
        uv[:, 1] = 1.0 - uv[:, 1]  # glTF's texture origin is the top left
        attrs["TEXCOORD_0"] = g.accessor(uv, _FLOAT, "VEC2")
        g.doc.update(images=[{"bufferView": g.view(_texture_png(tex)), "mimeType": "image/png"}],
                     samplers=[{"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 33071}],
                     textures=[{"sampler": 0, "source": 0}])
        pbr["baseColorTexture"] = {"index": 0}
    elif "rgb" in mesh.vertex_attrs:
        attrs["COLOR_0"] = g.accessor(rgb_to_u8(np.asarray(mesh.vertex_attrs["rgb"])), _UBYTE, "VEC3",
                                      normalized=True, stride=4)
    indices = g.accessor(np.asarray(mesh.faces, np.uint32).ravel(), _UINT, "SCALAR", target=_ELEMENT_ARRAY_BUFFER)
    g.doc.update(scene=0, scenes=[{"nodes": [0]}], nodes=[{"mesh": 0, "translation": _yup(centre[None])[0].tolist()}],
                 materials=[{"name": "surface", "pbrMetallicRoughness": pbr, "doubleSided": True}],
                 meshes=[{"primitives": [{"attributes": attrs, "indices": indices, "material": 0, "mode": 4}]}])
    return g.bytes(), lo, hi


def _lod_mesh(mesh, fraction: float):
    """The quadric-decimated mesh (about ``fraction`` of the faces) with vertex colours (from
    the texture at its vertices when textured), or None when decimation does not reduce it."""
    from workstation.core.products import Mesh
    from workstation.mesh.simplify import DecimateParams, decimate

    target = int(mesh.n_faces * fraction)
    if target < 4:
        return None
    va = {}
    tex = mesh.meta.get("texture")
    if "uv" in mesh.vertex_attrs and tex is not None:
        va["rgb"] = _texture_at(tex, np.asarray(mesh.vertex_attrs["uv"], float))
    elif "rgb" in mesh.vertex_attrs:
        va["rgb"] = mesh.vertex_attrs["rgb"]
    plain = Mesh(mesh.vertices, mesh.faces, va, crs=mesh.crs)
    coarse, _ = decimate(plain, DecimateParams(target_faces=target, preserve_normal=False))
    return coarse if coarse.n_faces < mesh.n_faces else None


def _vertex_distance(full, coarse, frame: Frame) -> float:
    """Largest distance from a vertex of ``full`` to the nearest vertex of ``coarse``, metres."""
    from scipy.spatial import cKDTree

    d, _ = cKDTree(frame.to_local(coarse.vertices)).query(frame.to_local(full.vertices))
    return float(d.max())


def write_mesh_tileset(src, folder, *, crs=None, lod_fraction: float = 0.1) -> TilesetResult:
    """Write the mesh file ``src`` (OBJ + MTL + texture, or PLY with faces) as a 3D Tiles tileset in
    ``folder`` (which must not exist): ``mesh.glb`` (the whole mesh), under a root
    ``mesh_lod.glb`` decimated to ``lod_fraction`` of the faces (0 for none) refined by
    REPLACE. ``crs`` is used when the file records none (a PLY's ``comment crs``)."""
    from workstation.io.mesh import read_mesh

    t0 = time.perf_counter()
    src, folder = Path(src), Path(folder)
    if not 0.0 <= lod_fraction < 1.0:
        raise InvalidInputError(f"lod_fraction {lod_fraction} must be in [0, 1)", field="lod_fraction")
    mesh = read_mesh(src)
    crs = _mesh_crs(src) or crs
    frame = Frame(crs, (mesh.vertices.min(axis=0) + mesh.vertices.max(axis=0)) / 2.0)
    folder.mkdir(parents=True)
    glb, lo, hi = mesh_glb(mesh, frame)
    (folder / "mesh.glb").write_bytes(glb)
    full = {"boundingVolume": {"box": _box(lo, hi)}, "geometricError": 0.0, "content": {"uri": "mesh.glb"}}
    coarse = _lod_mesh(mesh, lod_fraction) if lod_fraction > 0 else None
    edge = float(np.linalg.norm(hi - lo))
    if coarse is None:
        root, error, tiles, levels = full, edge / 100.0, 1, 1
    else:
        cglb, clo, chi = mesh_glb(coarse, frame)
        (folder / "mesh_lod.glb").write_bytes(cglb)
        error = max(_vertex_distance(mesh, coarse, frame), _PAD)
        box = _box(np.minimum(lo, clo), np.maximum(hi, chi))
        root = {"boundingVolume": {"box": box}, "geometricError": error, "content": {"uri": "mesh_lod.glb"},
                "children": [full]}
        error, tiles, levels = 2.0 * error, 2, 2
    doc = _tileset_json(root, frame, error, "REPLACE")
    (folder / "tileset.json").write_text(json.dumps(doc, indent=1))
    size = sum(p.stat().st_size for p in folder.rglob("*") if p.is_file())
    return TilesetResult(folder, 0, mesh.n_faces, tiles, levels, size, time.perf_counter() - t0)


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
    from workstation.publish.site import _walk

    found = []
    for raw in paths:
        p = Path(raw)
        found += [f for f in ([p] if p.is_file() else _walk(p)) if is_mesh_file(f)]
    return found


def publish_tilesets(inputs, clouds, folder, *, crs=None, params=None, chunk_points: int = 2_000_000) -> list[dict]:
    """Write ``folder/NAME/tileset.json`` for every cloud file in ``clouds`` and every mesh
    found in ``inputs`` (meshes without a CRS of their own take ``crs``, the site's); their
    ``site.json`` entries (``name``, ``kind`` cloud/mesh, ``url`` relative to the site,
    ``source``, ``tiles``, ``points``, ``faces``)."""
    from workstation.core.progress import track
    from workstation.publish.site import _unique_names

    folder = Path(folder)
    folder.mkdir()
    meshes = [m for m in find_meshes(inputs) if m not in set(map(Path, clouds))]
    names = _unique_names([*clouds, *meshes])
    kinds = ["cloud"] * len(clouds) + ["mesh"] * len(meshes)
    jobs = list(zip([*clouds, *meshes], names, kinds))
    entries = []
    for src, name, kind in track(jobs, "3D Tiles", unit="tilesets"):
        if kind == "cloud":
            res = write_cloud_tileset(src, folder / name, params=params, chunk_points=chunk_points)
        else:
            res = write_mesh_tileset(src, folder / name, crs=crs)
        entries.append({"name": name, "kind": kind, "url": f"{folder.name}/{name}/tileset.json", "source": str(src),
                        "tiles": res.tiles, "points": res.points, "faces": res.faces})
    return entries
