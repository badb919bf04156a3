"""A static web site of a work folder's products: COPC clouds, raster previews, SfM cameras.

:func:`publish_site` collects what it finds in work or product folders (or in files named
directly): LAS/LAZ clouds (converted to COPC, copied when they already are), GeoTIFF
hillshades, DTMs (shaded here) and orthophotos (PNG previews with their CRS bounds), and the
oriented cameras of ``cameras.json`` / a COLMAP model (frusta). It writes ``SITE/site.json``,
``SITE/index.html`` and the viewer vendored from npm at build time (``viewer/``: three.js, the
``copc`` reader and laz-perf's WASM, with their licences), so the folder works when copied to
any static web server with no network access.

The viewer streams only the octree nodes in view (one HTTP Range request per node), like
Potree and the COPC viewers (copc.io); a server must therefore answer Range requests with
206 Partial Content. Python's ``http.server`` does not, so :func:`make_server` runs a small
Range-capable handler (RFC 9110 §14: one ``bytes=`` range per request; several ranges get the
whole file, which the RFC allows).

``site.json`` (version 1)
-------------------------
``title``; ``crs`` (WKT/EPSG or null) and ``units`` (``m``, ``ft``, ...: the CRS's horizontal
unit); ``origin`` [x, y, z] (CRS units, subtracted by the viewer so that float32 keeps
millimetres); ``bounds`` [xmin, ymin, zmin, xmax, ymax, zmax] of all clouds (CRS units);
``clouds``: one entry per COPC file (``name``, ``url``, ``points``, ``bounds``, ``rgb_bits``
(0 without colour, 8 or 16), ``spacing`` (root point spacing, CRS units), ``levels``,
``nodes``, ``source``);
``classes``: ``code``, ``name``, ``color`` [r, g, b] 0-255 and ``count`` of every ASPRS class
present; ``intensity_range``: the 2nd and 98th percentiles of intensity (raw counts);
``rasters``: ``name``, ``kind`` (hillshade / ortho), ``url`` (PNG), ``cog`` (the GeoTIFF), ``bounds`` [xmin, ymin,
xmax, ymax] (CRS units), ``source``, ``crs``; ``cameras``: ``name``, ``center`` [x, y, z] and
``corners`` (4 × [x, y, z], the image corners at the frustum depth), CRS units;
``tilesets`` (only with ``PublishParams.tiles3d``): the 3D Tiles of
:func:`workstation.publish.tiles3d.publish_tilesets` (``name``, ``kind``, ``url``, ...), each
with ``matrix`` (:func:`tileset_matrix`: 16 numbers, column-major) placing the tileset's
coordinates in the viewer's frame (CRS units minus ``origin``); the viewer draws the meshes.
"""

from __future__ import annotations

import logging
import os
import re
import shutil
import threading
import time
from dataclasses import dataclass, field
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, MissingDependencyError

log = logging.getLogger(__name__)

#: The vendored viewer (built from web/ by `make viewer`).
VIEWER_DIR = Path(__file__).with_name("viewer")
VIEWER_FILES = ("viewer.js", "viewer.css", "laz-perf.wasm")
CLOUD_SUFFIXES = (".las", ".laz")
RASTER_SUFFIXES = (".tif", ".tiff")
SITE_VERSION = 1


@dataclass(frozen=True)
class PublishParams:
    """Parameters of :func:`publish_site`.

    Attributes
    ----------
    title : str or None
        Page title; None uses the name of the first input.
    preview_px : int
        Longest side of a raster preview PNG, pixels (a larger raster is box-filtered down).
    frustum_depth : float or None
        Depth of the drawn camera frusta, CRS units; None uses half the median distance from
        each camera centre to its nearest neighbour (frusta of a block touch without crossing),
        or 2 % of the site's diagonal for a single camera.
    chunk_points : int
        Points read at a time from each cloud (bounds memory).
    copc : CopcParams or None
        Octree parameters of the COPC writer for LAS/LAZ inputs
        (:class:`workstation.publish.copc.CopcParams`); None uses the writer's defaults.
    tiles3d : bool
        Also write a 3D Tiles tileset per cloud and mesh in ``SITE/3dtiles/NAME/``
        (:func:`workstation.publish.tiles3d.publish_tilesets`, same octree as the COPC).
    read_opts : dict or None
        ``bounds``/``resolution``/``level`` (None = not given): publish only the points they
        select from each cloud (:func:`workstation.ops.stream.input_chunks`).
    """

    title: str | None = None
    preview_px: int = 2048
    frustum_depth: float | None = None
    chunk_points: int = 2_000_000
    copc: object | None = None
    tiles3d: bool = False
    read_opts: dict | None = None

    def __post_init__(self):
        if self.preview_px < 16:
            raise InvalidInputError("preview_px must be at least 16 pixels", field="preview_px")
        if self.frustum_depth is not None and not self.frustum_depth > 0:
            raise InvalidInputError("frustum depth must be positive", field="frustum_depth")
        if self.chunk_points < 1:
            raise InvalidInputError("chunk_points must be at least 1", field="chunk_points")


@dataclass(frozen=True)
class Inputs:
    """What :func:`collect_inputs` found: cloud files, (raster file, kind) pairs, camera sources."""

    clouds: tuple = ()
    rasters: tuple = ()
    cameras: tuple = ()


@dataclass(frozen=True)
class SiteResult:
    """What :func:`publish_site` wrote: the site folder, its ``site.json`` document, the total
    number of points and the seconds it took."""

    site: Path
    doc: dict = field(repr=False)
    points: int
    seconds: float


# ---------------------------------------------------------------------------------- inputs
def _raster_kind(path: Path) -> str | None:
    """``hillshade``, ``ortho`` or ``dtm`` from a GeoTIFF's name; None for other rasters."""
    name = path.name.lower()
    for kind in ("hillshade", "ortho", "dtm"):
        if kind in name:
            return kind
    return None


def _is_cloud(path: Path) -> bool:
    return path.suffix.lower() in CLOUD_SUFFIXES


def walk_files(folder: Path, depth: int = 2):
    """Files of ``folder`` and of its sub-folders down to ``depth`` levels, hidden ones skipped,
    in a stable order."""
    for p in sorted(folder.iterdir()):
        if p.name.startswith("."):
            continue
        if p.is_file():
            yield p
        elif p.is_dir() and depth > 0 and not (p / "site.json").exists():
            yield from walk_files(p, depth - 1)


def collect_inputs(paths) -> Inputs:
    """The clouds (LAS/LAZ/COPC), rasters (hillshade, DTM, ortho GeoTIFFs, by name) and camera
    sources in ``paths``. Folders are searched two levels deep, files are taken as they are.
    A DTM is left out where its folder holds a hillshade (the map shows that one). Cameras are
    the ``cameras.json`` files, or else the COLMAP model folders (``cameras.bin``/``.txt``)."""
    clouds, rasters, jsons, models = [], [], [], []
    for raw in paths:
        p = Path(raw)
        if not p.exists():
            raise InvalidInputError("not found", "give a work folder, a products folder or files", path=p)
        for f in [p] if p.is_file() else walk_files(p):
            kind = _raster_kind(f) if f.suffix.lower() in RASTER_SUFFIXES else None
            if _is_cloud(f):
                clouds.append(f)
            elif kind:
                rasters.append((f, kind))
            elif f.name == "cameras.json":
                jsons.append(f)
            elif f.name in ("cameras.bin", "cameras.txt") and f.parent not in models:
                models.append(f.parent)
    shaded = {f.parent for f, kind in rasters if kind == "hillshade"}
    rasters = [(f, kind) for f, kind in rasters if not (kind == "dtm" and f.parent in shaded)]
    return Inputs(tuple(clouds), tuple(rasters), tuple(jsons or models))


# ---------------------------------------------------------------------------------- clouds
class _Stats:
    """Class counts, intensity histogram and largest colour value, accumulated chunk by chunk."""

    def __init__(self):
        self.classes = np.zeros(256, np.int64)
        self.intensity = np.zeros(65536, np.int64)
        self.rgb_max = 0

    def add(self, classification, intensity, rgb) -> None:
        if classification is not None:
            self.classes += np.bincount(np.asarray(classification, np.uint8).ravel(), minlength=256)
        if intensity is not None:
            self.intensity += np.bincount(np.asarray(intensity, np.uint16).ravel(), minlength=65536)
        if rgb is not None and np.size(rgb):
            self.rgb_max = max(self.rgb_max, int(np.max(rgb)))

    def tap(self, chunks):
        """Pass ``chunks`` (Clouds) through, adding each to the statistics."""
        for c in chunks:
            self.add(c.attrs.get("classification"), c.attrs.get("intensity"), c.attrs.get("rgb"))
            yield c

    def result(self) -> dict:
        rgb_bits = 0 if self.rgb_max == 0 else (8 if self.rgb_max <= 255 else 16)
        counts = {int(c): int(self.classes[c]) for c in np.flatnonzero(self.classes)}
        return {"class_counts": counts, "intensity_hist": self.intensity, "rgb_bits": rgb_bits}


def cloud_stats(path, chunk_points: int = 2_000_000) -> dict:
    """Points, bounds, class counts, intensity histogram and colour depth of a LAS/LAZ/COPC
    file in one chunked pass (memory bounded by ``chunk_points``).

    Returns
    -------
    dict
        ``points``; ``bounds`` [xmin, ymin, zmin, xmax, ymax, zmax] (header, CRS units);
        ``class_counts`` {code: n}; ``intensity_hist`` (65536,) int64 counts;
        ``rgb_bits`` 0 (no colour or all black), 8 (every channel ≤ 255) or 16.
    """
    import laspy

    acc = _Stats()
    with laspy.open(str(path)) as f:
        h = f.header
        has_rgb = "red" in set(h.point_format.dimension_names)
        for ch in f.chunk_iterator(chunk_points):
            rgb = np.stack([ch.red, ch.green, ch.blue], axis=-1) if has_rgb else None
            acc.add(ch.classification, ch.intensity, rgb)
    return {"points": int(h.point_count), "bounds": [*map(float, h.mins), *map(float, h.maxs)], **acc.result()}


def _percentiles(hist: np.ndarray, qs) -> list[float]:
    """Percentiles ``qs`` (0-100) of integer values given by their histogram."""
    cdf = np.cumsum(hist)
    if cdf[-1] == 0:
        return [0.0 for _ in qs]
    return [float(np.searchsorted(cdf, q / 100.0 * cdf[-1], side="left")) for q in qs]


def _to_copc(src: Path, dst: Path, params: PublishParams, on_octree=None) -> dict:
    """Copy a COPC file, or convert a LAS/LAZ file (or the points ``params.read_opts`` selects
    from any cloud) to COPC with the package's writer (:func:`workstation.publish.copc.write_copc_chunks`,
    streaming chunks of ``params.chunk_points``, its octree handed to ``on_octree`` when given:
    a copied file calls nothing); the statistics of :func:`cloud_stats`, gathered on the way."""
    import laspy

    from workstation.io.copc import is_copc
    from workstation.ops.stream import input_chunks

    sel = {k: v for k, v in (params.read_opts or {}).items() if v is not None}
    if is_copc(src) and not sel:
        shutil.copyfile(src, dst)
        return cloud_stats(dst, params.chunk_points)
    from workstation.publish.copc import CopcParams, write_copc_chunks

    with laspy.open(str(src)) as f:
        bounds = (np.asarray(f.header.mins), np.asarray(f.header.maxs))
    acc = _Stats()
    write_copc_chunks(acc.tap(input_chunks(src, params.chunk_points, **sel)), dst, params.copc or CopcParams(),
                      bounds=bounds, on_octree=on_octree)
    with laspy.open(str(dst)) as f:
        h = f.header
        return {"points": int(h.point_count), "bounds": [*map(float, h.mins), *map(float, h.maxs)], **acc.result()}


def _publish_cloud(src: Path, folder: Path, name: str, params: PublishParams, on_octree=None) -> tuple[dict, dict]:
    """Write ``folder/NAME.copc.laz`` (``on_octree``: see :func:`_to_copc`); its site.json entry
    and its statistics."""
    from workstation.io.copc import read_info, summary

    dst = folder / f"{name}.copc.laz"
    stats = _to_copc(src, dst, params, on_octree)
    info, tree = read_info(dst), summary(dst)
    entry = {"name": name, "url": f"clouds/{dst.name}", "source": str(src), "points": stats["points"],
             "bounds": stats["bounds"], "rgb_bits": stats["rgb_bits"], "spacing": info.spacing,
             "levels": tree["levels"], "nodes": tree["nodes"]}
    return entry, stats


def unique_names(paths) -> list[str]:
    """File stems without ``.copc``, made unique with ``-2``, ``-3``... and safe for URLs."""
    seen, out = {}, []
    for p in paths:
        stem = re.sub(r"\.copc$", "", Path(p).stem, flags=re.I)
        stem = re.sub(r"[^A-Za-z0-9_.-]+", "_", stem) or "cloud"
        seen[stem] = seen.get(stem, 0) + 1
        out.append(stem if seen[stem] == 1 else f"{stem}-{seen[stem]}")
    return out


def _classes(counts: dict) -> list[dict]:
    from workstation.core.classes import CLASS_COLORS, class_name

    return [{"code": c, "name": class_name(c), "color": list(CLASS_COLORS.get(c, (128, 128, 128))), "count": n}
            for c, n in sorted(counts.items())]


# ---------------------------------------------------------------------------------- rasters
def _raster_bounds(raster) -> list[float]:
    """[xmin, ymin, xmax, ymax] of a north-up raster (CRS units)."""
    a, b, c, d, e, f = raster.transform
    rows, cols = raster.shape
    xs, ys = (c, c + a * cols), (f, f + e * rows)
    return [min(xs), min(ys), max(xs), max(ys)]


def _preview_rgba(raster, kind: str) -> np.ndarray:
    """(rows, cols, 4) uint8 image of a hillshade/DTM (grey) or an ortho (RGB/RGBA); nodata is
    transparent. A DTM is shaded first (:func:`workstation.raster.terrain.hillshade`)."""
    from workstation.raster.terrain import hillshade

    if kind == "dtm":
        raster, kind = hillshade(raster), "hillshade"
    arr = np.asarray(raster.array)
    if arr.ndim == 2:
        valid = np.isfinite(arr) if arr.dtype.kind == "f" else np.ones(arr.shape, bool)
        if raster.nodata is not None:
            valid &= arr != raster.nodata
        grey = np.clip(np.nan_to_num(arr, nan=0.0), 0, 255).astype(np.uint8)
        return np.dstack([grey, grey, grey, np.where(valid, 255, 0).astype(np.uint8)])
    bands = np.moveaxis(arr[:4], 0, -1)
    if bands.dtype != np.uint8:  # 16-bit or float orthos: stretch to 0-255 by the maximum
        top = float(np.nanmax(bands[..., :3])) or 1.0
        bands = np.clip(np.nan_to_num(bands) * (255.0 / top), 0, 255).astype(np.uint8)
    if bands.shape[-1] == 4:
        return bands
    rgb = bands if bands.shape[-1] == 3 else np.repeat(bands[..., :1], 3, axis=-1)
    alpha = np.where((rgb > 0).any(axis=-1), 255, 0).astype(np.uint8)
    return np.dstack([rgb, alpha])


def _publish_raster(src: Path, kind: str, folder: Path, name: str, params: PublishParams) -> dict | None:
    """Write ``folder/NAME.png`` (longest side at most ``preview_px``) and the raster itself as a
    Cloud Optimized GeoTIFF ``folder/NAME.tif`` (tiled, internal overviews: GIS clients read
    only the parts they show); its site.json entry, or None (with a warning) for a rotated
    raster, which a north-up map cannot show."""
    from PIL import Image

    from workstation.io.geotiff import read_raster, write_raster

    raster = read_raster(src)
    if raster.transform[1] or raster.transform[3]:
        log.warning("%s: rotated raster left out of the map (only north-up rasters are shown)", src)
        return None
    rgba = _preview_rgba(raster, kind)
    im = Image.fromarray(rgba, "RGBA")
    scale = params.preview_px / max(im.size)
    if scale < 1:
        im = im.resize((max(1, round(im.width * scale)), max(1, round(im.height * scale))), Image.Resampling.BOX)
    dst = folder / f"{name}.png"
    im.save(dst, optimize=False)
    rgb = kind == "ortho" and raster.array.ndim == 3 and raster.array.shape[0] in (3, 4) and raster.array.dtype == np.uint8
    write_raster(raster, folder / f"{name}.tif", photometric="RGB" if rgb else None)
    return {"name": name, "kind": "hillshade" if kind == "dtm" else kind, "url": f"rasters/{dst.name}",
            "cog": f"rasters/{name}.tif", "bounds": _raster_bounds(raster), "source": str(src), "crs": raster.crs}


# ---------------------------------------------------------------------------------- cameras
def camera_frusta(rec, depth: float | None = None, extent: float = 1.0) -> list[dict]:
    """Camera centres and image-corner rays at ``depth`` of every image of a Reconstruction.

    A pixel (u, v) at depth z in the camera frame is ``((u - cx) z / fx, (v - cy) z / fy, z)``;
    world points follow from the world-to-camera pose x_cam = R X + t as X = Rᵀ (x_cam - t).
    ``depth`` None: half the median nearest-neighbour distance between centres (2 % of
    ``extent`` for one camera). Pixel corners are at -0.5 and size - 0.5 (OpenCV centres).

    Examples
    --------
    >>> import numpy as np
    >>> from workstation.core.products import Camera, Image, Pose, Reconstruction
    >>> cam = Camera(100, 50, fx=100.0, fy=100.0, cx=49.5, cy=24.5)
    >>> rec = Reconstruction({1: cam}, {1: Image("a.png", 1, Pose(np.eye(3), np.array([0.0, 0.0, -10.0])))})
    >>> f = camera_frusta(rec, depth=2.0)[0]
    >>> f["center"], np.round(f["corners"][0], 3).tolist()
    ([0.0, 0.0, 10.0], [-1.0, -0.5, 12.0])
    """
    from scipy.spatial import cKDTree

    ids = sorted(rec.images)
    if not ids:
        return []
    R = np.stack([np.asarray(rec.images[i].pose.R, float) for i in ids])
    t = np.stack([np.asarray(rec.images[i].pose.t, float) for i in ids])
    centers = 0.0 - np.einsum("nji,nj->ni", R, t)
    if depth is None:
        if len(ids) > 1:
            d, _ = cKDTree(centers).query(centers, k=2)
            depth = 0.5 * float(np.median(d[:, 1]))
        depth = depth if depth and depth > 0 else 0.02 * extent
    cams = [rec.cameras[rec.images[i].camera_id] for i in ids]
    K = np.array([[c.fx, c.fy, c.cx, c.cy, c.width, c.height] for c in cams], float)
    lo, w, h = np.full(len(ids), -0.5), K[:, 4] - 0.5, K[:, 5] - 0.5
    u, v = np.stack([lo, w, w, lo], axis=1), np.stack([lo, lo, h, h], axis=1)  # (n, 4) image corners
    xc = np.stack([(u - K[:, 2:3]) * depth / K[:, 0:1], (v - K[:, 3:4]) * depth / K[:, 1:2],
                   np.full(u.shape, depth)], axis=-1)  # (n, 4, 3) camera frame
    world = np.einsum("nji,nkj->nki", R, xc - t[:, None, :])
    return [{"name": rec.images[i].name, "center": centers[k].tolist(), "corners": world[k].tolist()}
            for k, i in enumerate(ids)]


def _read_cameras(sources) -> list:
    """Reconstructions of the camera sources (unreadable ones are skipped with a warning)."""
    from workstation.core.errors import WorkstationError
    from workstation.photogrammetry.sfm import read_reconstruction

    recs = []
    for s in sources:
        try:
            recs.append(read_reconstruction(s))
        except (WorkstationError, OSError, ValueError) as e:
            log.warning("%s: cameras left out (%s)", s, e)
    return recs


# ---------------------------------------------------------------------------------- the site
def _check_site_path(site: Path, inputs) -> None:
    """Refuse a site folder that is, or holds, one of the inputs (``--overwrite`` would delete it)."""
    s = site.resolve()
    for raw in inputs:
        p = Path(raw).resolve()
        if p == s or s in p.parents:
            raise InvalidInputError("the site folder holds an input, which --overwrite would delete",
                                    "write the site to a new folder", path=site)


def _copy_viewer(tmp: Path) -> None:
    """index.html at the top, the bundle and its licences in ``viewer/``."""
    missing = [f for f in (*VIEWER_FILES, "index.html") if not (VIEWER_DIR / f).is_file()]
    if missing:
        raise MissingDependencyError(f"the web viewer is not built ({', '.join(missing)} missing in {VIEWER_DIR})",
                                     "run `make viewer` (needs Node.js and npm)")
    (tmp / "viewer").mkdir()
    shutil.copyfile(VIEWER_DIR / "index.html", tmp / "index.html")
    for f in VIEWER_FILES:
        shutil.copyfile(VIEWER_DIR / f, tmp / "viewer" / f)
    shutil.copytree(VIEWER_DIR / "licenses", tmp / "viewer" / "licenses")


def _site_doc(title, clouds, stats, rasters, cameras, crs) -> dict:
    """The site.json document (see the module docstring)."""
    from workstation.io.crs import unit_symbol

    b = np.array([c["bounds"] for c in clouds], float)
    bounds = [*b[:, :3].min(axis=0), *b[:, 3:].max(axis=0)]
    counts: dict[int, int] = {}
    hist = np.zeros(65536, np.int64)
    for s in stats:
        hist += s["intensity_hist"]
        for k, n in s["class_counts"].items():
            counts[k] = counts.get(k, 0) + n
    lo, hi = _percentiles(hist, (2, 98))
    origin = [round((bounds[0] + bounds[3]) / 2, 0), round((bounds[1] + bounds[4]) / 2, 0), round(bounds[2], 0)]
    return {"version": SITE_VERSION, "title": title, "crs": crs, "units": unit_symbol(crs), "origin": origin,
            "bounds": [float(v) for v in bounds], "clouds": clouds, "classes": _classes(counts),
            "intensity_range": [lo, max(hi, lo + 1.0)], "rasters": rasters, "cameras": cameras}


def tileset_matrix(tileset_json, origin) -> list[float]:
    """The 4x4 affine matrix (column-major, as three.js's ``Matrix4.fromArray`` reads it) that
    takes a tileset's coordinates (z up: those of its bounding boxes and of its contents turned
    z-up, before the root ``transform``) to the viewer's frame, CRS units minus ``origin``.

    Without a CRS (``extras.ws.frame`` ``local``) the tileset is in CRS units relative to
    ``extras.ws.origin``: a translation. With one it is in metres in the east-north-up frame at
    that origin (:class:`workstation.publish.tiles3d.Frame`), which is not affine in the CRS
    (meridian convergence, scale factor, Earth curvature): the matrix is the least-squares affine
    map fitted on a 3x3x3 grid over the root bounding box (the grid is found in CRS coordinates
    by a first fit, then refitted on it). Its error, mostly the Earth's curvature, grows with the
    square of the box's extent: millimetres over a few hundred metres, decimetres over 2 km.

    Examples
    --------
    >>> import json, tempfile, pathlib
    >>> doc = {"root": {"boundingVolume": {"box": [0, 0, 0, 5, 0, 0, 0, 5, 0, 0, 0, 1]}},
    ...        "extras": {"ws": {"crs": None, "origin": [110.0, 220.0, 5.0], "frame": "local"}}}
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "tileset.json"
    >>> _ = p.write_text(json.dumps(doc))
    >>> tileset_matrix(p, [100.0, 200.0, 0.0])[12:]
    [10.0, 20.0, 5.0, 1.0]
    """
    import json

    from workstation.io.crs import crs_units
    from workstation.publish.tiles3d import Frame

    path = Path(tileset_json)
    doc = json.loads(path.read_text())
    ws = (doc.get("extras") or {}).get("ws") or {}
    try:
        box = np.asarray(doc["root"]["boundingVolume"]["box"], float).reshape(4, 3)
        frame_origin = np.asarray(ws["origin"], float).reshape(3)
    except (KeyError, TypeError, ValueError) as e:
        raise InvalidInputError(f"no root box or extras.ws.origin ({e})", path=path, field="root.boundingVolume") from e
    m = np.eye(4)
    frame = Frame(ws.get("crs"), frame_origin)
    if frame.transform is None:
        m[:3, 3] = frame_origin - np.asarray(origin, float)
        return m.T.ravel().tolist()
    grid = np.stack(np.meshgrid(*[[-1.0, 0.0, 1.0]] * 3, indexing="ij"), axis=-1).reshape(-1, 3)
    local = box[0] + grid * np.abs(box[1:]).sum(axis=0)  # the axis-aligned root box, metres
    u = crs_units(ws.get("crs"))
    crs_pts = frame_origin + local / np.array([u.h, u.h, u.v])  # first guess: CRS axes along ENU
    for _ in range(2):
        design = np.column_stack([frame.to_local(crs_pts), np.ones(len(crs_pts))])
        fit, *_ = np.linalg.lstsq(design, crs_pts, rcond=None)  # (4, 3): CRS = [local, 1] @ fit
        crs_pts = np.column_stack([local, np.ones(len(local))]) @ fit
    m[:3, :] = fit.T
    m[:3, 3] -= np.asarray(origin, float)
    return m.T.ravel().tolist()


def _cloud_crs(path: Path):
    from workstation.io.copc import read

    return read(path, level=0).crs


def publish_site(inputs, site, *, overwrite: bool = False, params: PublishParams = PublishParams()) -> SiteResult:
    """Publish the products in ``inputs`` (folders or files) as a static web site in ``site``.

    Clouds become ``site/clouds/*.copc.laz``, rasters ``site/rasters/*.png``; cameras become
    frusta in ``site.json``. The folder is built beside ``site`` and swapped in at the end, so a
    failure leaves no half-written site; an existing ``site`` is replaced only with
    ``overwrite``. Raises :class:`InvalidInputError` when no cloud is found.
    """
    from workstation.core.progress import track
    from workstation.io.atomic import atomic_dir

    t0 = time.perf_counter()
    site = Path(site)
    _check_site_path(site, inputs)
    found = collect_inputs(inputs)
    if not found.clouds:
        raise InvalidInputError("no LAS/LAZ/COPC cloud found", "give a work folder or cloud files", path=Path(inputs[0]))
    title = params.title or Path(inputs[0]).resolve().name
    with atomic_dir(site, overwrite=overwrite) as tmp:
        _copy_viewer(tmp)
        for sub in ("clouds", "rasters"):
            (tmp / sub).mkdir()
        clouds, stats, written = [], [], {}
        pairs = list(zip(found.clouds, unique_names(found.clouds)))
        for src, name in track(pairs, "publishing clouds", unit="clouds"):
            hook = None
            if params.tiles3d:  # the cloud's tileset from the COPC writer's octree: one read and sort for both
                from workstation.publish.tiles3d import tileset_writer

                hook = tileset_writer(tmp / "3dtiles" / name, written, src)
            entry, st = _publish_cloud(src, tmp / "clouds", name, params, hook)
            clouds.append(entry)
            stats.append(st)
        crs = _cloud_crs(tmp / clouds[0]["url"])
        rasters = [r for (src, kind), name in zip(found.rasters, unique_names(p for p, _ in found.rasters))
                   if (r := _publish_raster(src, kind, tmp / "rasters", name, params)) is not None]
        extent = float(np.linalg.norm(np.ptp(np.array([c["bounds"] for c in clouds]).reshape(-1, 3), axis=0)))
        cameras = [f for rec in _read_cameras(found.cameras) for f in camera_frusta(rec, params.frustum_depth, extent)]
        doc = _site_doc(title, clouds, stats, rasters, cameras, crs)
        if params.tiles3d:
            from workstation.publish.tiles3d import publish_tilesets

            doc["tilesets"] = publish_tilesets(inputs, found.clouds, tmp / "3dtiles", crs=crs, params=params.copc,
                                               chunk_points=params.chunk_points, written=written)
        for t in doc.get("tilesets", ()):  # where the viewer draws each tileset
            t["matrix"] = tileset_matrix(tmp / t["url"], doc["origin"])
        from workstation.core.jsonutil import dumps

        (tmp / "site.json").write_text(dumps(doc, indent=1))
    points = sum(c["points"] for c in clouds)
    log.info("published %d clouds (%d points), %d rasters, %d cameras to %s", len(clouds), points, len(rasters),
             len(cameras), site)
    return SiteResult(site, doc, points, time.perf_counter() - t0)


# ---------------------------------------------------------------------------------- serving
_RANGE = re.compile(r"^\s*bytes\s*=\s*(\d*)\s*-\s*(\d*)\s*$")


def parse_range(header: str | None, size: int):
    """The byte range [start, end] (inclusive) a ``Range`` header asks of a ``size``-byte file.

    Returns None to serve the whole file (no header, a malformed one, several ranges, an
    end before the start: RFC 9110 §14.2 lets a server ignore those) and ``"unsatisfiable"``
    for a range starting past the end (answered 416).

    Examples
    --------
    >>> parse_range("bytes=0-99", 1000), parse_range("bytes=900-", 1000), parse_range("bytes=-100", 1000)
    ((0, 99), (900, 999), (900, 999))
    >>> parse_range("bytes=990-2000", 1000), parse_range("bytes=1000-", 1000), parse_range("bytes=0-1,5-9", 1000)
    ((990, 999), 'unsatisfiable', None)
    """
    m = _RANGE.match(header or "")
    if not m or (not m.group(1) and not m.group(2)):
        return None
    if not m.group(1):  # suffix range: the last N bytes
        n = int(m.group(2))
        return (max(0, size - n), size - 1) if n > 0 and size > 0 else "unsatisfiable"
    start = int(m.group(1))
    end = int(m.group(2)) if m.group(2) else size - 1
    if m.group(2) and end < start:
        return None
    if start >= size:
        return "unsatisfiable"
    return start, min(end, size - 1)


class RangeRequestHandler(SimpleHTTPRequestHandler):
    """``SimpleHTTPRequestHandler`` that answers a single-range ``Range: bytes=`` request with
    206 Partial Content (416 past the end), announces ``Accept-Ranges: bytes``, serves .wasm as
    ``application/wasm`` and records every request in ``server.requests`` as (path, Range
    header or None, status)."""

    extensions_map = {**SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".laz": "application/octet-stream", ".json": "application/json", ".js": "text/javascript"}
    _left: int | None = None

    def end_headers(self):
        self.send_header("Accept-Ranges", "bytes")
        super().end_headers()

    def send_head(self):
        self._left = None
        path = self.translate_path(self.path)
        if "Range" not in self.headers or not os.path.isfile(path):
            return super().send_head()
        size = os.path.getsize(path)
        rng = parse_range(self.headers["Range"], size)
        if rng is None:
            return super().send_head()
        if rng == "unsatisfiable":
            self.send_response(416)
            self.send_header("Content-Range", f"bytes */{size}")
            self.send_header("Content-Length", "0")
            self.end_headers()
            return None
        start, end = rng
        f = open(path, "rb")
        f.seek(start)
        self.send_response(206)
        self.send_header("Content-Type", self.guess_type(path))
        self.send_header("Content-Range", f"bytes {start}-{end}/{size}")
        self.send_header("Content-Length", str(end - start + 1))
        self.send_header("Last-Modified", self.date_time_string(int(os.path.getmtime(path))))
        self.end_headers()
        self._left = end - start + 1
        return f

    def copyfile(self, source, outputfile):
        if self._left is None:
            return super().copyfile(source, outputfile)
        left = self._left
        while left > 0:
            buf = source.read(min(left, 1 << 16))
            if not buf:
                break
            outputfile.write(buf)
            left -= len(buf)

    def log_request(self, code="-", size="-"):
        status = getattr(code, "value", code)
        with self.server.lock:
            self.server.requests.append((self.path, self.headers.get("Range"), int(status) if str(status).isdigit() else 0))
        log.debug("%s %s %s %s", self.command, self.path, self.headers.get("Range") or "", status)

    def log_message(self, format, *args):  # noqa: A002 - http.server's signature
        log.debug("%s - %s", self.address_string(), format % args)


def make_server(site, host: str = "127.0.0.1", port: int = 0) -> ThreadingHTTPServer:
    """A threading HTTP server of ``site`` with Range support, not yet serving (call
    ``serve_forever``; port 0 picks a free port, read it from ``server.server_address``)."""
    import functools

    site = Path(site)
    if not (site / "index.html").is_file():
        raise InvalidInputError("no index.html: not a published site", "run ws publish first", path=site)
    handler = functools.partial(RangeRequestHandler, directory=str(site))
    server = ThreadingHTTPServer((host, port), handler)
    server.requests, server.lock = [], threading.Lock()
    server.daemon_threads = True
    return server


def serve_in_thread(site, host: str = "127.0.0.1", port: int = 0) -> ThreadingHTTPServer:
    """:func:`make_server` serving from a daemon thread (stop it with ``server.shutdown()``)."""
    server = make_server(site, host, port)
    threading.Thread(target=server.serve_forever, name="ws-publish-serve", daemon=True).start()
    return server
