"""Raster previews of the work-folder report: what a GeoTIFF holds and its picture.

An ortho is drawn in colour, a hillshade in grey (its 0-255 shading, never tinted), an
elevation (DSM, DTM, CHM) as a hillshade with an elevation tint, slope, aspect, density and an
ortho's accuracy map with their scales, an error map with a diverging scale. Rasters are read
decimated to at most :data:`MAX_PREVIEW_PX` on their longer side.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .html import fig_b64 as _fig_b64

def hillshade(z: np.ndarray, cell: float, azimuth_deg: float = 315.0, altitude_deg: float = 45.0) -> np.ndarray:
    """Hillshade (rows, cols) in [0, 1] of an elevation grid (Horn's gradient via numpy).

    Parameters
    ----------
    z : (rows, cols) float, NaN for no data
    cell : float
        Cell size in the elevation's units.
    """
    z = np.asarray(z, dtype=np.float64)
    zf = np.where(np.isfinite(z), z, np.nanmean(z) if np.isfinite(z).any() else 0.0)
    gy, gx = np.gradient(zf, cell)
    slope = np.arctan(np.hypot(gx, gy))
    aspect = np.arctan2(-gx, gy)
    az, alt = np.radians(360.0 - azimuth_deg + 90.0), np.radians(altitude_deg)
    hs = np.sin(alt) * np.cos(slope) + np.cos(alt) * np.sin(slope) * np.cos(az - aspect)
    return np.where(np.isfinite(z), np.clip(hs, 0, 1), np.nan)


def raster_kind(path: Path, meta: dict | None = None, dtype=None, nodata=None) -> str:
    """What a GeoTIFF holds: ``"hillshade"`` (0-255 shading), ``"slope"``, ``"aspect"``,
    ``"error"``, ``"image"`` (an ortho, or several bands), ``"density"`` (points per area),
    ``"accuracy"`` (an ortho's accuracy map), ``"map"`` (a ``ws qc`` map) or ``"elevation"``
    (DSM, DTM, CHM, anything else).

    The ``kind`` written in the file's metadata by ``ws`` decides; without it, the name
    (``hillshade``, ``shade``, ``_hs``; ``slope``; ``aspect``; ``error``, ``diff``...;
    ``density``; ``ortho``) and an 8-bit single band with nodata 0 (how ``ws hillshade`` writes
    one).
    """
    kind = str((meta or {}).get("kind", "")).lower()
    named = {"hillshade": "hillshade", "slope": "slope", "aspect": "aspect", "density": "density", "ortho": "image",
             "ortho_accuracy": "accuracy", "swath dz": "image", "dsm": "elevation", "dtm": "elevation", "chm": "elevation", "dem": "elevation"}
    if kind in named:
        return named[kind]
    name = path.stem.lower()
    if kind == "qc":  # the maps of ws qc: density, voids, dz values
        return "density" if "density" in name else "map"
    if any(w in name for w in ("error", "diff", "residual", "dod")):
        return "error"
    if "shade" in name or name.endswith("_hs") or name == "hs":
        return "hillshade"
    for k in ("slope", "aspect", "density"):
        if k in name:
            return k
    if "ortho" in name:
        return "image"
    if dtype is not None and np.dtype(dtype) == np.uint8 and nodata == 0:
        return "hillshade"
    return "elevation"


MAX_PREVIEW_PX = 1500  # the longer side of a raster as read for its preview (decimated above)


def _tags_meta(ds) -> dict:
    """The ``ws`` metadata of an open GeoTIFF ({} when none or not a JSON object)."""
    from workstation.io.geotiff import META_TAG

    try:
        meta = json.loads(ds.tags().get(META_TAG) or "{}")
    except ValueError:
        return {}
    return meta if isinstance(meta, dict) else {}


def _read_preview(path: Path):
    """(bands (b, h, w) float with NaN for no data, cell size, dtype, nodata, ``ws`` metadata)
    of a GeoTIFF, decimated so that its longer side is at most :data:`MAX_PREVIEW_PX`; the
    metadata comes from the same open file."""
    import rasterio

    with rasterio.open(path) as ds:
        step = max(1, -(-max(ds.height, ds.width) // MAX_PREVIEW_PX))
        shape = (min(ds.count, 3), max(1, ds.height // step), max(1, ds.width // step))
        a = ds.read(list(range(1, shape[0] + 1)), out_shape=shape, masked=True).astype(np.float64).filled(np.nan)
        cell = (abs(ds.transform.a) or 1.0) * ds.width / shape[2]
        dtype, nodata, meta = ds.dtypes[0], ds.nodata, _tags_meta(ds)
    return a, cell, dtype, nodata, meta


def _rgb(a: np.ndarray, dtype) -> np.ndarray:
    """(h, w, 3|4) float image in [0, 1] of 3 bands: 8-bit values as they are, others stretched
    between their 2nd and 98th percentiles; no-data cells transparent."""
    valid = np.isfinite(a).all(axis=0)
    if np.dtype(dtype) == np.uint8:
        rgb = a / 255.0
    else:
        lo, hi = (np.nanpercentile(a[:, valid], q, axis=1)[:, None, None] for q in (2, 98)) if valid.any() else (0, 1)
        rgb = (a - lo) / np.maximum(hi - lo, 1e-12)
    rgb = np.clip(np.nan_to_num(np.moveaxis(rgb, 0, -1)), 0, 1)
    return np.dstack([rgb, valid.astype(float)])


def plot_raster(path: Path) -> tuple[str, str] | None:
    """(caption, b64 png) for a GeoTIFF: an ortho (3 bands) in colour, hillshades in grey
    (0-255 shading, never tinted), elevations as a hillshade with an elevation tint, slope,
    aspect, density and accuracy with their scales, diverging map for errors. The kind comes
    from the file's ``ws`` metadata, read from the file opened for the picture."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    bands, cell, dtype, nodata, meta = _read_preview(path)
    kind = "image" if bands.shape[0] >= 3 else raster_kind(path, meta, dtype, nodata)
    a = bands[0]
    fig, ax = plt.subplots(figsize=(6, 6 * a.shape[0] / max(a.shape[1], 1) + 0.5))
    scales = {"slope": ("magma", 0, 90, "slope (degrees)"), "aspect": ("twilight", 0, 360, "aspect (degrees)"),
              "density": ("viridis", None, None, "points per unit²"), "accuracy": ("viridis", None, None, "accuracy"),
              "map": ("viridis", None, None, "value")}
    if kind == "hillshade":
        ax.imshow(a, cmap="gray", vmin=0, vmax=255, interpolation="nearest")
        cap = f"{path.name}: hillshade (grey, 0-255)"
    elif kind in scales:
        cmap, lo, hi, label = scales[kind]
        im = ax.imshow(a, cmap=cmap, vmin=lo, vmax=hi, interpolation="nearest")
        fig.colorbar(im, ax=ax, shrink=0.7, label=label)
        cap = f"{path.name}: {'density map' if kind == 'density' else kind}"
    elif kind == "error":
        lim = np.nanpercentile(np.abs(a), 98) if np.isfinite(a).any() else 1.0
        im = ax.imshow(a, cmap="RdBu_r", vmin=-lim, vmax=lim)
        fig.colorbar(im, ax=ax, shrink=0.7, label="error")
        cap = f"{path.name}: error map"
    elif kind == "image":
        ax.imshow(_rgb(bands, dtype) if bands.shape[0] >= 3 else a, cmap="gray")
        ortho = str(meta.get("kind", "")).lower() == "ortho" or "ortho" in path.stem.lower()
        cap = f"{path.name}: {'orthophoto' if ortho else 'colour image' if bands.shape[0] >= 3 else 'band 1'}"
    else:
        ax.imshow(hillshade(a, cell), cmap="gray", vmin=0, vmax=1)
        im = ax.imshow(a, cmap="terrain", alpha=0.45)
        fig.colorbar(im, ax=ax, shrink=0.7, label="elevation")
        cap = f"{path.name}: hillshade (315°/45°) with elevation tint"
    ax.set_axis_off()
    return cap, _fig_b64(fig)


def raster_meta(path: Path) -> dict:
    """The ``ws`` metadata of a GeoTIFF ({} when none or unreadable)."""
    try:
        import rasterio

        with rasterio.open(path) as ds:
            return _tags_meta(ds)
    except Exception:  # noqa: BLE001 - a report shows what it can read
        return {}


def raster_metas():
    """A :func:`raster_meta` that reads each file once: a report asks for a raster's
    metadata in several places (preview order and picture, the summary's DTM, the appendix's
    product records), and one such reader, passed down, opens the file for it only once.
    The dicts it returns are shared, read-only."""
    from functools import lru_cache

    return lru_cache(maxsize=None)(raster_meta)


# Order of the raster previews: ortho first, then shaded terrain, elevation, density, the rest.
_PREVIEW_ORDER = {"image": 0, "hillshade": 1, "elevation": 2, "density": 3}


def preview_rasters(root: Path, rasters: list[Path], limit: int, meta_of=raster_meta) -> list[Path]:
    """The rasters worth a preview, ortho first: tiles of a mosaic (a ``tiles`` folder) and a
    second file of one name (a copy in a published site) left out. ``meta_of(path)`` gives a
    raster's ``ws`` metadata (:func:`raster_metas` to read each file once)."""
    seen, keep = set(), []
    for p in rasters:
        if "tiles" in p.relative_to(root).parts[:-1] or p.name in seen:
            continue
        seen.add(p.name)
        keep.append(p)
    rank = {p: _PREVIEW_ORDER.get(raster_kind(p, meta_of(p)), 4) for p in keep}
    return sorted(keep, key=lambda p: (rank[p], "dtm" not in p.stem.lower(), len(p.parts)))[:limit]
