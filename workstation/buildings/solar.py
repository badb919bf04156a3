"""Rooftop solar potential: sun positions, clear-sky irradiance, DSM shading, annual sums.

* Sun position: the NOAA solar calculator equations (after Meeus 1991, *Astronomical
  Algorithms*, ch. 25 and 28; NOAA Global Monitoring Laboratory, "General Solar Position
  Calculations"), with atmospheric refraction from NOAA's piecewise formula scaled by pressure
  and temperature (Bennett 1982). Accurate to about 0.01 degrees between 1800 and 2100 against
  the NREL SPA (Reda & Andreas 2004).
* Clear-sky irradiance: the ESRA model (Rigollier, Bauer & Wald 2000, Solar Energy 68(1)),
  the model of PVGIS and GRASS r.sun (Šúri & Hofierka 2004): beam normal
  ``B = G0 exp(-0.8662 TL m dR(m))`` with the Kasten & Young (1989) air mass and the Kasten
  (1996) Rayleigh optical thickness, diffuse horizontal ``D = G0 Trd(TL) Fd(h, TL)``; TL is the
  Linke turbidity factor for air mass 2 (3.5 by default, a typical annual mean for central Europe
  after Remund et al. 2003).
* On a tilted plane: beam by the angle of incidence, diffuse isotropic (Liu & Jordan 1963)
  reduced by the sky view of the DSM horizon, ground reflection with albedo 0.2.
* Shading: the horizon of each roof face (36 azimuth sectors) traced through the DSM of all
  points, as r.sun and SAGA do; the beam counts only while the sun is above it.
* Checked against PVGIS 5 (European Commission JRC), "Daily radiation" tool: its clear-sky global
  irradiance on a fixed plane, Gcs(i), for a 35-degree south-facing plane at 51.64 N 0.51 W (the
  monthly mean-day profiles archived in github.com/michaelstreeter101/solar_farm, files
  Dailydata_51.640_-0.510_SA_<month>_35deg_0deg.json), summed over the year, is compared with
  :func:`plane_irradiation` for the same unshaded plane (tests/buildings/test_solar.py). Both
  are clear-sky quantities; PVGIS varies TL by month where this module keeps one value.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

SOLAR_CONSTANT = 1367.0  # W/m^2 (ESRA)


@dataclass(frozen=True)
class SolarParams:
    """Parameters of :func:`annual_irradiation`.

    Attributes
    ----------
    latitude, longitude : float
        Site position (degrees, north and east positive).
    elevation : float
        Site height above sea level (m), for the air pressure.
    linke_turbidity : float
        Linke turbidity factor TL (air mass 2, dimensionless).
    albedo : float
        Ground reflectance (0-1).
    year : int
        Calendar year simulated.
    step_minutes : float
        Time step of the integration (minutes).
    sectors : int
        Azimuth sectors of the DSM horizon.
    max_distance : float
        Farthest DSM distance searched for obstacles (m).
    """

    latitude: float = 48.0
    longitude: float = 11.0
    elevation: float = 0.0
    linke_turbidity: float = 3.5
    albedo: float = 0.2
    year: int = 2025
    step_minutes: float = 60.0
    sectors: int = 36
    max_distance: float = 150.0


def sun_position(unix_time: np.ndarray, latitude: float, longitude: float, pressure_hpa: float = 1013.25,
                 temperature_c: float = 10.0, refraction: bool = True):
    """Solar zenith and azimuth (degrees; azimuth clockwise from north) at UTC ``unix_time`` (s).

    NOAA solar calculator equations; refraction by NOAA's formula scaled by
    ``(P / 1010) (283 / (273 + T))``.

    Examples
    --------
    The SPA paper's example (Reda & Andreas 2004, table A5.1: 17 Oct 2003 19:30:30 UTC,
    39.742476 N 105.1786 W, 820 hPa, 11 C; zenith 50.11162, azimuth 194.34024):

    >>> import datetime as dt
    >>> t = dt.datetime(2003, 10, 17, 19, 30, 30, tzinfo=dt.timezone.utc).timestamp()
    >>> z, a = sun_position(np.array([t]), 39.742476, -105.1786, 820.0, 11.0)
    >>> round(float(z[0]), 2), round(float(a[0]), 2)
    (50.11, 194.34)
    """
    t = np.asarray(unix_time, float)
    jd = t / 86400.0 + 2440587.5
    jc = (jd - 2451545.0) / 36525.0
    L0 = np.radians((280.46646 + jc * (36000.76983 + jc * 0.0003032)) % 360.0)
    M = np.radians(357.52911 + jc * (35999.05029 - 0.0001537 * jc))
    e = 0.016708634 - jc * (0.000042037 + 0.0000001267 * jc)
    C = np.radians(np.sin(M) * (1.914602 - jc * (0.004817 + 0.000014 * jc)) + np.sin(2 * M) * (0.019993 - 0.000101 * jc)
                   + np.sin(3 * M) * 0.000289)
    omega = np.radians(125.04 - 1934.136 * jc)
    lam = L0 + C - np.radians(0.00569 + 0.00478 * np.sin(omega))
    eps0 = 23.0 + (26.0 + (21.448 - jc * (46.815 + jc * (0.00059 - jc * 0.001813))) / 60.0) / 60.0
    eps = np.radians(eps0 + 0.00256 * np.cos(omega))
    decl = np.arcsin(np.sin(eps) * np.sin(lam))
    y = np.tan(eps / 2) ** 2
    eot = 4 * np.degrees(y * np.sin(2 * L0) - 2 * e * np.sin(M) + 4 * e * y * np.sin(M) * np.cos(2 * L0)
                         - 0.5 * y * y * np.sin(4 * L0) - 1.25 * e * e * np.sin(2 * M))
    minutes = (t % 86400.0) / 60.0
    tst = (minutes + eot + 4 * longitude) % 1440.0
    ha = np.radians(tst / 4.0 - 180.0)
    phi = math.radians(latitude)
    cosz = np.clip(math.sin(phi) * np.sin(decl) + math.cos(phi) * np.cos(decl) * np.cos(ha), -1, 1)
    zen = np.arccos(cosz)
    sinz = np.maximum(np.sin(zen), 1e-12)
    cosaz = np.clip((math.sin(phi) * cosz - np.sin(decl)) / (math.cos(phi) * sinz), -1, 1)
    az = np.where(ha > 0, (np.degrees(np.arccos(cosaz)) + 180.0) % 360.0, (540.0 - np.degrees(np.arccos(cosaz))) % 360.0)
    zen = np.degrees(zen)
    if refraction:
        zen = zen - refraction_deg(90.0 - zen) * (pressure_hpa / 1010.0) * (283.0 / (273.0 + temperature_c))
    return zen, az


def refraction_deg(elevation_deg: np.ndarray) -> np.ndarray:
    """Atmospheric refraction (degrees) at a true solar elevation (degrees), NOAA's formula."""
    h = np.asarray(elevation_deg, float)
    te = np.tan(np.radians(np.clip(h, -89.0, 89.0)))
    arcsec = np.where(h > 85, 0.0,
             np.where(h > 5, 58.1 / te - 0.07 / te ** 3 + 0.000086 / te ** 5,
             np.where(h > -0.575, 1735 + h * (-518.2 + h * (103.4 + h * (-12.79 + h * 0.711))), -20.772 / te)))
    return arcsec / 3600.0


def esra_clear_sky(elevation_deg: np.ndarray, day_of_year: np.ndarray, linke: float, site_elevation: float = 0.0):
    """ESRA clear-sky beam normal and diffuse horizontal irradiance (W/m^2) at solar elevation
    angles (degrees, refracted or not) and days of the year (Rigollier et al. 2000)."""
    h = np.radians(np.asarray(elevation_deg, float))
    g0 = SOLAR_CONSTANT * (1 + 0.03344 * np.cos(2 * np.pi * np.asarray(day_of_year) / 365.25 - 0.048869))
    dh = 0.061359 * (0.1594 + 1.123 * h + 0.065656 * h * h) / (1 + 28.9344 * h + 277.3971 * h * h)
    href = np.degrees(h + dh)
    pp0 = math.exp(-site_elevation / 8434.5)
    up = h > 0
    m = np.where(up, pp0 / (np.sin(np.radians(href)) + 0.50572 * np.maximum(href + 6.07995, 1e-6) ** -1.6364), np.inf)
    dr = np.where(m <= 20, 1 / (6.6296 + 1.7513 * m - 0.1202 * m ** 2 + 0.0065 * m ** 3 - 0.00013 * m ** 4),
                  1 / (10.4 + 0.718 * m))
    beam = np.where(up, g0 * np.exp(-0.8662 * linke * m * dr), 0.0)
    trd = -1.5843e-2 + 3.0543e-2 * linke + 3.797e-4 * linke ** 2
    a1 = -6.1581e-2 * linke + 3.1408e-3 * linke ** 2 + 2.6463e-1
    a1 = 2.2e-3 / trd if a1 * trd < 2.2e-3 else a1
    a2 = 2.0402 + 1.8945e-2 * linke - 1.1161e-2 * linke ** 2
    a3 = -1.3025 + 3.9231e-2 * linke + 8.5079e-3 * linke ** 2
    sh = np.sin(h)
    diffuse = np.where(up, g0 * trd * (a1 + a2 * sh + a3 * sh * sh), 0.0)
    return beam, np.maximum(diffuse, 0.0)


def year_of_sun(params: SolarParams):
    """Sun above the horizon through ``params.year`` at mid-step times: (zenith, azimuth,
    day of year, hours per step), angles in degrees."""
    import datetime as dt

    t0 = dt.datetime(params.year, 1, 1, tzinfo=dt.timezone.utc).timestamp()
    t1 = dt.datetime(params.year + 1, 1, 1, tzinfo=dt.timezone.utc).timestamp()
    step = params.step_minutes * 60.0
    t = np.arange(t0 + step / 2, t1, step)
    pressure = 1013.25 * math.exp(-params.elevation / 8434.5)
    zen, az = sun_position(t, params.latitude, params.longitude, pressure)
    up = zen < 90.0
    doy = np.floor((t[up] - t0) / 86400.0) + 1
    return zen[up], az[up], doy, step / 3600.0


def build_dsm(xyz: np.ndarray, cell: float):
    """Highest point per cell (m), empty cells from the nearest filled one: (z (rows, cols), origin (2,))."""
    from scipy import ndimage

    origin = xyz[:, :2].min(axis=0)
    ij = np.floor((xyz[:, :2] - origin) / cell).astype(np.int64)
    shape = (int(ij[:, 1].max()) + 1, int(ij[:, 0].max()) + 1)
    z = np.full(shape[0] * shape[1], -np.inf)
    np.maximum.at(z, ij[:, 1] * shape[1] + ij[:, 0], xyz[:, 2])
    z = z.reshape(shape)
    empty = ~np.isfinite(z)
    if empty.any():
        _, (ii, jj) = ndimage.distance_transform_edt(empty, return_indices=True)
        z = z[ii, jj]
    return z, origin


def horizon_angles(dsm: np.ndarray, origin: np.ndarray, cell: float, pts: np.ndarray, sectors: int = 36,
                   max_distance: float = 150.0, chunk: int = 256) -> np.ndarray:
    """Horizon elevation (radians) seen from ``pts`` (n, 3) in ``sectors`` azimuths (clockwise
    from north, sector k centred on k * 360 / sectors), tracing the DSM at distances growing by
    8 % per step from two cells to ``max_distance`` (m). Outside the DSM the horizon is 0.

    The DSM is padded with one ring of -inf cells that every ray leaving it is clamped to, and
    the steepest slope of a ray is found before taking one arctangent per ray."""
    az = np.radians(np.arange(sectors) * 360.0 / sectors)
    u = np.column_stack([np.sin(az), np.cos(az)])
    r = 2 * cell * 1.08 ** np.arange(int(math.log(max(max_distance / (2 * cell), 1.0)) / math.log(1.08)) + 1)
    rows, cols = dsm.shape
    flat = np.pad(np.asarray(dsm, float), 1, constant_values=-np.inf).ravel()
    step = u[:, None, :] * (r / cell)[None, :, None]  # (sectors, steps, 2) in cells
    inv_r = 1.0 / r
    out = np.zeros((len(pts), sectors))
    for s in range(0, len(pts), chunk):
        p = pts[s:s + chunk]
        c = (p[:, :2] - origin) / cell + 1.0  # cells in the padded DSM
        ix = np.clip(np.floor(c[:, None, None, 0] + step[None, ..., 0]), 0, cols + 1).astype(np.int64)
        iy = np.clip(np.floor(c[:, None, None, 1] + step[None, ..., 1]), 0, rows + 1).astype(np.int64)
        slope = ((flat[iy * (cols + 2) + ix] - p[:, 2, None, None]) * inv_r).max(axis=2)
        out[s:s + chunk] = np.arctan(np.maximum(slope, 0.0))
    return out


def plane_irradiation(normals: np.ndarray, horizon: np.ndarray | None, params: SolarParams, sun=None) -> np.ndarray:
    """Annual clear-sky irradiation (kWh/m^2/year) on planes with up-pointing unit normals
    (n, 3), shaded by their horizons (n, sectors) in radians (None: unobstructed).

    The beam counts at the sun positions above the horizon of the sector the sun is in. The sun
    positions are sorted by sector, then elevation, and for each distinct normal the suffix sums
    of its beam irradiance taken along that order; the shaded beam of a plane is then, per
    sector, one binary search of its horizon and a difference of two suffix sums, so the cost
    grows with planes times sectors rather than planes times time steps."""
    zen, az, doy, hours = year_of_sun(params) if sun is None else sun
    beam, diff = esra_clear_sky(90.0 - zen, doy, params.linke_turbidity, params.elevation)
    zr, ar = np.radians(zen), np.radians(az)
    s = np.column_stack([np.sin(zr) * np.sin(ar), np.sin(zr) * np.cos(ar), np.cos(zr)])
    ghi = beam * np.cos(zr) + diff
    nsec = params.sectors if horizon is None else horizon.shape[1]
    hor = np.zeros((len(normals), nsec)) if horizon is None else np.asarray(horizon, float)
    sector = np.round(az / (360.0 / nsec)).astype(int) % nsec
    elev = np.radians(90.0 - zen)
    key = sector * 4.0 + elev  # elevations lie in (0, pi/2]: one sorted key for (sector, elevation)
    order = np.argsort(key, kind="stable")
    key, s, beam = key[order], s[order], beam[order]
    ends = np.searchsorted(key, np.arange(1, nsec + 1) * 4.0, side="left")
    uniq, which = np.unique(np.asarray(normals, float), axis=0, return_inverse=True)
    which = which.ravel()
    direct = np.empty(len(normals))
    for c in range(0, len(uniq), 256):
        w = np.maximum(uniq[c:c + 256] @ s.T, 0.0) * beam  # (u, T)
        suffix = np.concatenate([np.cumsum(w[:, ::-1], axis=1)[:, ::-1], np.zeros((len(w), 1))], axis=1)
        idx = np.flatnonzero((which >= c) & (which < c + 256))
        h = np.clip(hor[idx], 0.0, np.pi / 2)  # a horizon below 0 shades nothing, as 0 does
        start = np.searchsorted(key, np.arange(nsec)[None, :] * 4.0 + h, side="right")  # (k, sectors)
        row = (which[idx] - c)[:, None]
        direct[idx] = (suffix[row, start] - suffix[row, ends[None, :]]).sum(axis=1)
    ct = np.clip(np.asarray(normals, float)[:, 2], -1, 1)
    view = 1.0 if horizon is None else _sky_view(np.asarray(normals, float), hor)
    g = direct + diff.sum() * (1 + ct) / 2 * view + ghi.sum() * params.albedo * (1 - ct) / 2
    return g * hours / 1000.0


def _sky_view(normals: np.ndarray, horizon: np.ndarray) -> np.ndarray:
    """Share of the isotropic sky a tilted plane still sees past the obstacles: the sky above
    max(obstacle horizon, the plane's own horizon) over the sky above the plane's own horizon,
    each sector weighted by cos^2 of its horizon elevation (the isotropic sky integral)."""
    k = horizon.shape[1]
    az = np.radians(np.arange(k) * 360.0 / k)
    tilt = np.arccos(np.clip(normals[:, 2], -1, 1))
    face = np.arctan2(normals[:, 0], normals[:, 1])
    own = np.arctan(-np.tan(tilt)[:, None] * np.cos(az[None, :] - face[:, None]))  # uphill is positive
    own = np.maximum(own, 0.0)
    full = np.cos(own) ** 2
    seen = np.cos(np.maximum(horizon, own)) ** 2
    return seen.sum(axis=1) / np.maximum(full.sum(axis=1), 1e-12)


def roof_cells(polygons: list, planes: list, cell: float):
    """Cells of a grid (aligned on multiples of ``cell``) whose centres lie on roof faces seen
    from above: ``polygons`` are the faces' plan rings (k, 2), ``planes`` callables giving each
    face's height at (m, 2) points. Where faces overlap in plan the highest wins.

    Returns (row (c,), col (c,), centre xyz (c, 3), face index (c,), shape (rows, cols),
    upper-left corner (x0, y1))."""
    import shapely

    allxy = np.vstack(polygons)
    x0, y0 = np.floor(allxy.min(axis=0) / cell) * cell
    x1, y1 = np.ceil(allxy.max(axis=0) / cell) * cell
    shape = (max(int(round((y1 - y0) / cell)), 1), max(int(round((x1 - x0) / cell)), 1))
    rows, cols, zs, owner = [], [], [], []
    for i, (poly, zf) in enumerate(zip(polygons, planes)):
        lo, hi = poly.min(axis=0), poly.max(axis=0)
        c = np.arange(int(np.floor((lo[0] - x0) / cell)), int(np.ceil((hi[0] - x0) / cell)))
        r = np.arange(int(np.floor((y1 - hi[1]) / cell)), int(np.ceil((y1 - lo[1]) / cell)))
        cc, rr = np.meshgrid(c, r)
        xy = np.column_stack([x0 + (cc.ravel() + 0.5) * cell, y1 - (rr.ravel() + 0.5) * cell])
        inside = shapely.contains_xy(shapely.Polygon(poly), xy[:, 0], xy[:, 1])
        rows.append(rr.ravel()[inside])
        cols.append(cc.ravel()[inside])
        zs.append(zf(xy[inside]))
        owner.append(np.full(int(inside.sum()), i))
    rows, cols, zs, owner = map(np.concatenate, (rows, cols, zs, owner))
    flat = rows * shape[1] + cols
    order = np.lexsort((-zs, flat))  # per cell, highest face first
    keep = order[np.r_[True, flat[order][1:] != flat[order][:-1]]] if len(order) else order
    rows, cols, owner = rows[keep], cols[keep], owner[keep]
    xyz = np.column_stack([x0 + (cols + 0.5) * cell, y1 - (rows + 0.5) * cell, zs[keep]])
    return rows, cols, xyz, owner, shape, (float(x0), float(y1))


def self_shading_lift(normal: np.ndarray, dsm_cell: float) -> float:
    """Height (m) above a roof face at which its horizon is traced, so the face's own DSM
    roughness over one cell diagonal does not shade it."""
    return float(math.sqrt(2) * dsm_cell * math.hypot(normal[0], normal[1]) / max(normal[2], 1e-3) + 0.05)


MAX_PREVIEW_PIXELS = 2000  # longest side of the solar map preview image (cells)


def solar_map_png(array: np.ndarray, transform, path, overwrite: bool = False, inputs=(), dpi: int = 120):
    """Write a PNG preview of a roof solar map (:func:`workstation.buildings.pipeline.solar_map`):
    cells coloured by annual irradiation (kWh/m^2/year, ``inferno`` from the map's lowest to its
    highest cell) with a colour bar, axes in the map's coordinates (m), cells off the roofs (NaN)
    left white. Maps longer than :data:`MAX_PREVIEW_PIXELS` cells on a side are shown at every
    k-th cell. ``transform`` is the map's (a, b, c, d, e, f) with ``c, f`` its upper-left corner;
    the file is written atomically (``overwrite``, ``inputs`` as :func:`workstation.io.atomic_path`)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from workstation.core.errors import InvalidInputError
    from workstation.io import atomic_path

    a = np.asarray(array, float)
    if a.ndim != 2 or not np.isfinite(a).any():
        raise InvalidInputError("the solar map has no roof cells to draw", field="solar_map")
    step = max(1, -(-max(a.shape) // MAX_PREVIEW_PIXELS))
    a = a[::step, ::step]
    cw, ch = transform[0] * step, transform[4] * step
    x0, y1 = transform[2], transform[5]
    extent = (x0, x0 + cw * a.shape[1], y1 + ch * a.shape[0], y1)
    width = 8.0
    height = float(np.clip(width * a.shape[0] / max(a.shape[1], 1), 3.0, 12.0)) + 0.8
    fig = Figure(figsize=(width + 1.6, height))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    im = ax.imshow(np.ma.masked_invalid(a), extent=extent, cmap="inferno", interpolation="nearest",
                   vmin=float(np.nanmin(a)), vmax=float(np.nanmax(a)))
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.ticklabel_format(useOffset=False, style="plain")
    ax.set_title("Roof solar potential (clear-sky annual irradiation)")
    fig.colorbar(im, ax=ax, label="kWh/m²/year", shrink=0.9)
    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        fig.savefig(tmp, format="png", dpi=dpi, bbox_inches="tight")
    return path
