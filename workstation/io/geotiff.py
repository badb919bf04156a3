"""GeoTIFF <-> :class:`~workstation.core.products.Raster` (rasterio, imported lazily).

Writes Cloud-Optimized-GeoTIFF-like files: 256×256 internal tiles, DEFLATE compression with a
floating-point or horizontal predictor, internal overviews (powers of two, averaged), the CRS,
the nodata value and ``Raster.meta`` as a JSON tag (``WS_META``) so a round trip keeps the
product's description (kind, resolution reason, vertical accuracy). GDAL's ``COG`` driver lays
out the file (overviews before the full-resolution data) when it is available; otherwise a
tiled GTiff with overviews is written. Writes are atomic through :func:`atomic_path`.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, MissingDependencyError
from workstation.core.log import get_logger
from workstation.core.products import Raster

from .atomic import atomic_path

log = get_logger(__name__)

META_TAG = "WS_META"


def _rasterio():
    try:
        import rasterio
    except ImportError as e:  # pragma: no cover - rasterio is a dependency
        raise MissingDependencyError("rasterio", "GeoTIFF reading and writing") from e
    return rasterio


def _json_meta(meta) -> str:
    def ok(v):
        try:
            json.dumps(v)
            return True
        except TypeError:
            return False

    clean = {}
    for k, v in dict(meta).items():
        if isinstance(v, np.generic):
            v = v.item()
        if isinstance(v, np.ndarray):
            v = v.tolist()
        if ok(v):
            clean[str(k)] = v
    return json.dumps(clean)


def read_raster(path, band: int | None = None, nan_nodata: bool = True) -> Raster:
    """Read a GeoTIFF (or any raster GDAL reads) into a :class:`Raster`.

    Parameters
    ----------
    path : path-like
    band : int, optional
        1-based band to read; all bands when None (a single band gives a 2-D array).
    nan_nodata : bool
        Float rasters: cells equal to the nodata value become NaN (``nodata`` is kept, and
        :func:`write_raster` turns NaN back into it).

    Returns
    -------
    Raster
        ``array`` (rows, cols) or (bands, rows, cols) in the file's dtype, ``transform`` in GDAL
        order, ``crs`` as WKT (EPSG string when it has one), ``nodata``, ``meta`` from the
        ``WS_META`` tag plus ``source``.
    """
    p = Path(path)
    if not p.exists():
        raise InvalidInputError("file not found", "check the path", path=p)
    if p.is_dir():
        raise InvalidInputError("is a folder, not a raster file", "give a GeoTIFF", path=p)
    if p.stat().st_size == 0:
        raise InvalidInputError("file is empty (0 bytes)", "the file was not written completely; get it again", path=p)
    rasterio = _rasterio()
    try:
        src_ctx = rasterio.open(p)
    except Exception as e:  # noqa: BLE001 - GDAL reports unreadable files with several error types
        raise InvalidInputError(f"not a readable raster ({e})",
                                "give a complete GeoTIFF (the file may be truncated, corrupt or of another type)",
                                path=p) from None
    try:
        with src_ctx as src:
            return _read_open(src, p, band, nan_nodata)
    except InvalidInputError as e:
        if e.path is not None:
            raise
        raise InvalidInputError(e.message, e.hint, path=p, field=e.field) from None
    except MemoryError:
        raise InvalidInputError("raster too large to read into memory", "read a band or a window of it", path=p) from None
    except Exception as e:  # noqa: BLE001 - GDAL raises on truncated or corrupt blocks while reading
        raise InvalidInputError(f"cannot read the raster data ({type(e).__name__}: {e})",
                                "the file is truncated or corrupt; get it again", path=p) from None


def _read_open(src, p: Path, band: int | None, nan_nodata: bool) -> Raster:
    """The :class:`Raster` of an open rasterio dataset (see :func:`read_raster`)."""
    if band is not None and not (isinstance(band, (int, np.integer)) and 1 <= band <= src.count):
        raise InvalidInputError(f"band {band!r} does not exist", f"the file has bands 1-{src.count}", path=p, field="band")
    arr = src.read(band) if band is not None else src.read()
    if arr.ndim == 3 and arr.shape[0] == 1:
        arr = arr[0]
    t = src.transform
    crs = None
    if src.crs is not None:
        epsg = src.crs.to_epsg()
        crs = f"EPSG:{epsg}" if epsg else src.crs.to_wkt()
    if nan_nodata and src.nodata is not None and np.issubdtype(arr.dtype, np.floating):
        arr = np.where(arr == np.asarray(src.nodata, arr.dtype), np.nan, arr)
    meta = {}
    tag = src.tags().get(META_TAG)
    if tag:
        try:
            meta = json.loads(tag)
        except (json.JSONDecodeError, RecursionError):
            log.warning("%s: unreadable %s tag ignored", p, META_TAG)
        if not isinstance(meta, dict):
            log.warning("%s: %s tag is not a JSON object; ignored", p, META_TAG)
            meta = {}
    meta["source"] = str(p)
    return Raster(arr, (t.a, t.b, t.c, t.d, t.e, t.f), crs, src.nodata, meta)


def write_raster(
    raster: Raster,
    path,
    *,
    overwrite: bool = False,
    inputs=(),
    blocksize: int = 256,
    compress: str = "DEFLATE",
    overviews: bool = True,
    photometric: str | None = None,
) -> Path:
    """Write a :class:`Raster` as a tiled, compressed GeoTIFF with overviews (atomic).

    Parameters
    ----------
    raster : Raster
        Float rasters keep their dtype; NaN cells are written as ``raster.nodata`` when it is set.
    path : path-like
        Output ``.tif``; refused if it exists unless ``overwrite``.
    blocksize : int
        Internal tile size in pixels (multiple of 16).
    compress : str
        GDAL compression (``DEFLATE``, ``LZW``, ``ZSTD``, ``NONE``).
    overviews : bool
        Build internal overviews (factors 2, 4, 8... until the smaller side is under one tile).
    photometric : str, optional
        ``RGB`` for 3-band 8-bit images (a 4th band is written as alpha).
    """
    rasterio = _rasterio()
    from rasterio.enums import Resampling
    from rasterio.transform import Affine

    arr = np.asarray(raster.array)
    if arr.ndim == 2:
        arr = arr[None]
    bands, rows, cols = arr.shape
    if rows == 0 or cols == 0:
        raise InvalidInputError("raster is empty", field="array")
    nodata = raster.nodata
    if np.issubdtype(arr.dtype, np.floating) and nodata is not None and not np.isnan(nodata):
        arr = np.where(np.isnan(arr), np.asarray(nodata, arr.dtype), arr)
    if arr.dtype == np.float16 or arr.dtype == np.bool_:
        arr = arr.astype(np.float32 if arr.dtype == np.float16 else np.uint8)
    predictor = 3 if np.issubdtype(arr.dtype, np.floating) else 2
    profile = dict(
        driver="GTiff", width=cols, height=rows, count=bands, dtype=arr.dtype.name,
        transform=Affine(*raster.transform), nodata=nodata, tiled=True,
        blockxsize=blocksize, blockysize=blocksize, compress=compress, predictor=predictor,
        BIGTIFF="IF_SAFER",
    )
    if compress.upper() == "NONE":
        profile.pop("predictor")
    if raster.crs:
        profile["crs"] = rasterio.crs.CRS.from_user_input(raster.crs)
    if photometric:
        profile["photometric"] = photometric
        if photometric.upper() == "RGB" and bands == 4:
            profile["alpha"] = "YES"  # 4th band is an alpha mask (0 = no data)
    factors = _overview_factors(rows, cols, blocksize) if overviews else []
    resampling = Resampling.average if np.issubdtype(arr.dtype, np.floating) or bands >= 3 else Resampling.nearest
    def fill(dst):
        dst.write(arr)
        dst.update_tags(**{META_TAG: _json_meta(raster.meta)})

    return _write_tiled(path, profile, fill, factors, resampling, overwrite, inputs)


def _overview_factors(rows: int, cols: int, blocksize: int) -> list[int]:
    factors, f = [], 2
    while min(rows, cols) / f >= blocksize / 2:
        factors.append(f)
        f *= 2
    return factors


def _write_tiled(path, profile: dict, fill, factors, resampling, overwrite: bool, inputs) -> Path:
    """Open a tiled GTiff with ``profile``, let ``fill(dst)`` write its cells, add overviews and
    lay it out as a COG (when GDAL has the driver), all in a temporary file renamed at the end."""
    rasterio = _rasterio()
    has_cog = _cog_available(rasterio)
    compress, predictor = profile["compress"], profile.get("predictor")
    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        stage = tmp.with_name(tmp.stem + ".stage.tif") if has_cog else tmp
        try:
            with rasterio.open(stage, "w", **profile) as dst:
                fill(dst)
                if factors:
                    dst.build_overviews(factors, resampling)
                    dst.update_tags(ns="rio_overview", resampling=resampling.name)
            if has_cog:
                from rasterio.shutil import copy as rio_copy

                opts = dict(COMPRESS=compress, BLOCKSIZE=profile["blockxsize"],
                            OVERVIEWS="FORCE_USE_EXISTING" if factors else "NONE", BIGTIFF="IF_SAFER")
                if compress.upper() != "NONE":
                    opts["PREDICTOR"] = "FLOATING_POINT" if predictor == 3 else "YES"
                rio_copy(stage, tmp, driver="COG", **opts)
        finally:
            if has_cog and stage.exists():
                stage.unlink()
    return Path(path)


def write_mosaic(tiles, transform, shape: tuple, path, *, crs=None, nodata=-9999.0, dtype="float32", meta=None,
                 overwrite: bool = False, blocksize: int = 256) -> Path:
    """Write a Cloud-Optimized GeoTIFF mosaic of GeoTIFF tiles on one grid, a tile at a time.

    Memory is one tile at a time; overviews are averaged (nearest for integer rasters).

    Parameters
    ----------
    tiles : sequence of (path, row_offset, col_offset)
        Tiles on the mosaic's grid (same cell size and alignment), placed at their offsets;
        cells no tile covers are ``nodata``.
    transform : tuple
        The mosaic's affine transform (a, b, c, d, e, f); ``shape`` is (rows, cols).
    """
    rasterio = _rasterio()
    from rasterio.enums import Resampling
    from rasterio.transform import Affine
    from rasterio.windows import Window

    rows, cols = int(shape[0]), int(shape[1])
    floating = np.issubdtype(np.dtype(dtype), np.floating)
    profile = dict(driver="GTiff", width=cols, height=rows, count=1, dtype=np.dtype(dtype).name,
                   transform=Affine(*transform), nodata=nodata, tiled=True, blockxsize=blocksize,
                   blockysize=blocksize, compress="DEFLATE", predictor=3 if floating else 2, BIGTIFF="IF_SAFER")
    if crs:
        profile["crs"] = rasterio.crs.CRS.from_user_input(crs)

    def fill(dst):
        for tile, r0, c0 in tiles:
            with rasterio.open(tile) as src:
                a = src.read(1, masked=True).filled(nodata).astype(dtype)
            dst.write(a, 1, window=Window(c0, r0, a.shape[1], a.shape[0]))
        dst.update_tags(**{META_TAG: _json_meta(meta or {})})

    resampling = Resampling.average if floating else Resampling.nearest
    return _write_tiled(path, profile, fill, _overview_factors(rows, cols, blocksize), resampling, overwrite, ())


def _cog_available(rasterio) -> bool:
    with rasterio.Env() as env:
        return "COG" in env.drivers()
