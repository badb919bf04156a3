"""Slope, aspect and hillshade of a DEM raster (Horn 1981 gradients).

Gradients use Horn's (1981, Proc. IEEE 69(1)) third-order finite difference on the 3×3
neighbourhood, the estimator of GDAL ``gdaldem`` and ESRI; hillshade is the Lambertian
illumination of ESRI/GDAL (Burrough & McDonnell 1998):
``255 · (cos(zenith)·cos(slope) + sin(zenith)·sin(slope)·cos(azimuth − aspect))``, clipped at 0.
Edge cells use replicated borders; cells next to NaN get NaN (no made-up gradient).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.products import Raster


#: The products of a DEM made here: :func:`hillshade`, :func:`slope`, :func:`aspect`.
PRODUCTS = ("hillshade", "slope", "aspect")


@dataclass(frozen=True)
class HillshadeParams:
    """Parameters of :func:`hillshade`.

    Attributes
    ----------
    azimuth : float
        Direction the light comes from, degrees clockwise from north (315 = north-west).
    altitude : float
        Sun elevation above the horizon in degrees.
    z_factor : float
        Vertical exaggeration (dimensionless). Heights and cell sizes in different units
        (feet heights on metre cells, degrees) are converted on top of it from the raster's
        units (:func:`unit_z_factor`), so 1 means true relief in every CRS.
    """

    azimuth: float = 315.0
    altitude: float = 45.0
    z_factor: float = 1.0

    def __post_init__(self):
        if not 0.0 <= self.altitude <= 90.0:
            raise InvalidInputError("altitude must be within 0-90 degrees", field="altitude")
        if not self.z_factor > 0:
            raise InvalidInputError("z factor must be positive", field="z_factor")


def _band(raster: Raster) -> np.ndarray:
    a = np.asarray(raster.array, dtype=np.float64)
    if a.ndim == 3:
        if a.shape[0] != 1:
            raise InvalidInputError("terrain analysis needs a single-band DEM", field="array")
        a = a[0]
    if raster.nodata is not None and not np.isnan(raster.nodata):
        a = np.where(a == raster.nodata, np.nan, a)
    if not np.isfinite(a).any():  # a product of nodata only would look like a success
        raise InvalidInputError(f"the DEM has no valid cell: all {a.size} cells are nodata ({raster.nodata})",
                                "check the DEM (its extent, nodata value and the classes it was built from)",
                                path=raster.meta.get("path"), field="array")
    return a


def horn_gradient(raster: Raster, z_factor: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Horn (1981) gradients dz/dx (east) and dz/dy (north), dimensionless.

    Returns
    -------
    (gx, gy) : two (rows, cols) float64 arrays
        NaN where the 3×3 window touches a NaN cell.
    """
    z = _band(raster) * z_factor
    rx, ry = raster.resolution
    p = np.pad(z, 1, mode="edge")
    a, b, c = p[:-2, :-2], p[:-2, 1:-1], p[:-2, 2:]
    d, f = p[1:-1, :-2], p[1:-1, 2:]
    g, h, i = p[2:, :-2], p[2:, 1:-1], p[2:, 2:]
    gx = ((c + 2 * f + i) - (a + 2 * d + g)) / (8.0 * rx)
    # rows grow southwards: north minus south
    gy = ((a + 2 * b + c) - (g + 2 * h + i)) / (8.0 * ry)
    hole = np.isnan(z)  # Horn's stencil skips the centre; a missing centre stays missing
    gx[hole] = np.nan
    gy[hole] = np.nan
    return gx, gy


def unit_z_factor(raster: Raster) -> float:
    """Cell-size units per height unit of ``raster``: 1 when both are the same unit, 0.3048
    for heights in feet on metre cells, about 1/111,320 for metre heights on degree cells."""
    from workstation.io.crs import raster_units

    return raster_units(raster).z_factor


def slope(raster: Raster, z_factor: float = 1.0, units: str = "degrees") -> Raster:
    """Slope in degrees (or ``units="percent"``) as a float32 raster (NaN nodata); ``z_factor``
    is an exaggeration on top of the unit conversion (:func:`unit_z_factor`)."""
    gx, gy = horn_gradient(raster, z_factor * unit_z_factor(raster))
    g = np.hypot(gx, gy)
    arr = np.degrees(np.arctan(g)) if units == "degrees" else 100.0 * g
    return Raster(arr.astype(np.float32), raster.transform, raster.crs, -9999.0, {"kind": "slope", "units": units})


def aspect(raster: Raster) -> Raster:
    """Aspect: the downslope direction in degrees clockwise from north (0-360); NaN on flats."""
    gx, gy = horn_gradient(raster)
    asp = (np.degrees(np.arctan2(-gx, -gy)) + 360.0) % 360.0
    asp[(gx == 0) & (gy == 0)] = np.nan
    return Raster(asp.astype(np.float32), raster.transform, raster.crs, -9999.0, {"kind": "aspect", "units": "degrees"})


def hillshade(raster: Raster, params: HillshadeParams = HillshadeParams()) -> Raster:
    """Shaded relief, 0-255 (uint8, 0 = nodata; lit values are clipped to 1-255).

    Examples
    --------
    >>> import numpy as np
    >>> from workstation.core.products import Raster
    >>> flat = Raster(np.zeros((5, 5)), (1, 0, 0, 0, -1, 5))
    >>> int(hillshade(flat, HillshadeParams(altitude=45)).array[2, 2])  # 255·cos(45°)
    180
    """
    unit_zf = unit_z_factor(raster)
    gx, gy = horn_gradient(raster, params.z_factor * unit_zf)
    zen = np.radians(90.0 - params.altitude)
    az = np.radians(params.azimuth)
    slp = np.arctan(np.hypot(gx, gy))
    asp = np.arctan2(-gx, -gy)  # downslope direction, clockwise from north
    # a surface facing the light (aspect == azimuth) is lit most
    shade = np.cos(zen) * np.cos(slp) + np.sin(zen) * np.sin(slp) * np.cos(az - asp)
    val = np.clip(255.0 * shade, 0, 255)
    out = np.where(np.isnan(val), 0, np.clip(np.round(val), 1, 255)).astype(np.uint8)
    meta = {"kind": "hillshade", "azimuth": params.azimuth, "altitude": params.altitude, "z_factor": params.z_factor,
            "unit_z_factor": unit_zf}
    return Raster(out, raster.transform, raster.crs, 0, meta)
