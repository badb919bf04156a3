"""CRS helpers through pyproj: names, EPSG codes, linear units, reprojection of clouds."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

log = get_logger(__name__)

METRES_PER_DEGREE = 111_320.0  # at the equator; scaled by cos(latitude) for eastings


@dataclass(frozen=True)
class CRSInfo:
    """Facts about a CRS.

    Attributes
    ----------
    name : str
    epsg : int or None
    is_geographic : bool
    unit : str
        Name of the horizontal linear unit ("metre", "US survey foot", "degree").
    metres_per_unit : float
        Horizontal unit in metres (for geographic CRSs, metres per degree of latitude).
    vertical_metres_per_unit : float
        Height unit in metres: the vertical sub-CRS of a compound CRS, the third axis of a 3-D
        CRS, else the horizontal unit of a projected CRS (LAS custom) or metres (geographic).
    vertical_unit : str
        Name of that height unit.
    is_geocentric : bool
        Earth-centred cartesian coordinates (EPSG:4978 and the like).
    """

    name: str
    epsg: int | None
    is_geographic: bool
    unit: str
    metres_per_unit: float
    vertical_metres_per_unit: float
    vertical_unit: str = ""
    is_geocentric: bool = False

    def to_dict(self) -> dict:
        return {"name": self.name, "epsg": self.epsg, "is_geographic": self.is_geographic, "unit": self.unit,
                "metres_per_unit": self.metres_per_unit}


def parse_crs(crs: str, what: str = "crs"):
    """A pyproj CRS from a user string (EPSG:code, WKT, PROJ string) with a clear error."""
    import pyproj

    try:
        return pyproj.CRS.from_user_input(crs)
    except Exception as exc:
        raise InvalidInputError(f"'{str(crs)[:60]}' is not a CRS pyproj knows ({exc})",
                                "give e.g. EPSG:32632 or a WKT string", field=what) from None


@lru_cache(maxsize=128)
def same_crs(a, b, horizontal: bool = False) -> bool:
    """Whether two CRS descriptions (EPSG:code, WKT, PROJ string, pyproj CRS) name the same
    CRS: equal text, or equal to pyproj with the axis order ignored (EPSG:4326 and OGC:CRS84
    hold the same coordinates, x = longitude, in LAS and GeoJSON alike). A description that
    pyproj cannot parse equals only the same text. ``horizontal``: compare only the horizontal
    part of compound CRSs (2-D footprints against a cloud in, e.g., EPSG:28992 + NAP height).

    >>> same_crs("EPSG:7415", "EPSG:28992"), same_crs("EPSG:7415", "EPSG:28992", horizontal=True)
    (False, True)
    """
    if a == b:
        return True
    from pyproj import CRS

    try:
        ca, cb = CRS.from_user_input(a), CRS.from_user_input(b)
    except Exception:  # noqa: BLE001 - an unparsable CRS string is compared as text
        return False
    if horizontal:
        ca, cb = (c.sub_crs_list[0] if c.is_compound else c for c in (ca, cb))
    return ca.equals(cb, ignore_axis_order=True)


@lru_cache(maxsize=128)
def crs_info(crs: str | None, identify: bool = True) -> CRSInfo | None:
    """Name, EPSG code and units of a CRS string; None when ``crs`` is None.

    ``identify``: a WKT without an EPSG identifier is matched against PROJ's database (about
    0.5 s); with False only an identifier the CRS states is reported (the header summary's
    "milliseconds" promise).

    Examples
    --------
    >>> i = crs_info("EPSG:2994")
    >>> i.unit, round(i.metres_per_unit, 6)
    ('foot', 0.3048)
    """
    if not crs:
        return None
    c = parse_crs(crs)
    epsg = c.to_epsg(min_confidence=70) if identify else stated_epsg(c)
    horiz = c.sub_crs_list[0] if c.is_compound else c
    axis = horiz.axis_info[0] if horiz.axis_info else None
    if horiz.is_geographic:
        unit, factor = "degree", METRES_PER_DEGREE
    elif axis is not None and axis.unit_conversion_factor:
        unit, factor = axis.unit_name, float(axis.unit_conversion_factor)
    else:
        unit, factor = "metre", 1.0
    vaxis = _vertical_axis(c)
    if vaxis is not None and vaxis.unit_conversion_factor:
        vunit, vfactor = vaxis.unit_name, float(vaxis.unit_conversion_factor)
    else:  # no height axis: LAS practice is heights in the horizontal unit (metres for lon/lat)
        vunit, vfactor = ("metre", 1.0) if horiz.is_geographic else (unit, factor)
    return CRSInfo(c.name, epsg, bool(horiz.is_geographic), unit, factor, vfactor, vunit, bool(c.is_geocentric))


def stated_epsg(c) -> int | None:
    """The EPSG code a CRS carries as its own identifier (no database search)."""
    ident = c.to_json_dict().get("id") or {}
    if ident.get("authority") == "EPSG":
        try:
            return int(ident.get("code"))
        except (TypeError, ValueError):
            return None
    return None


def _vertical_axis(c):
    """The height axis of a compound CRS (its vertical part) or of a 3-D CRS, else None."""
    if c.is_compound:
        for sub in c.sub_crs_list[1:]:
            if sub.axis_info:
                return sub.axis_info[0]
        return None
    if len(c.axis_info) == 3 and not c.is_geocentric:
        return c.axis_info[2]
    return None


def metres_to_crs_units(value_m: float, crs: str | None) -> float:
    """A horizontal length in metres expressed in the CRS's linear unit (metres when unknown)."""
    info = crs_info(crs)
    return value_m if info is None else value_m / info.metres_per_unit


def reproject(cloud: Cloud, to_crs: str) -> Cloud:
    """Transform coordinates into ``to_crs`` (heights too when both CRSs define them).

    LAS scales and offsets from the source no longer apply and are dropped from the metadata
    so the writer chooses new ones for the target units.
    """
    import pyproj

    if not cloud.crs:
        raise InvalidInputError("the cloud has no CRS to reproject from", "assign one first with --crs", field="crs")
    src, dst = parse_crs(cloud.crs, "crs"), parse_crs(to_crs, "to_crs")
    tr = pyproj.Transformer.from_crs(src, dst, always_xy=True)
    x, y, z = tr.transform(cloud.xyz[:, 0], cloud.xyz[:, 1], cloud.xyz[:, 2])
    xyz = np.column_stack([x, y, z])
    if not np.isfinite(xyz).all():
        raise InvalidInputError(
            f"{int((~np.isfinite(xyz).all(axis=1)).sum())} points fall outside the area of use of {to_crs}",
            "choose a target CRS that covers the data", field="to_crs")
    epsg = dst.to_epsg(min_confidence=100)
    las = {k: v for k, v in dict(cloud.meta.get("las", {})).items() if k not in ("scales", "offsets", "crs")}
    out = cloud.with_xyz(xyz).with_crs(f"EPSG:{epsg}" if epsg else dst.to_wkt()).with_meta(las=las)
    return out.with_history("reproject", {"from": cloud.crs[:80], "to": to_crs})


# --------------------------------------------------------------------------- the unit model
@lru_cache(maxsize=128)
def unit_symbol(crs: str | None) -> str:
    """Short symbol of a CRS's horizontal unit: "m", "ft", "usft", "°", another unit's name,
    or "" when it has none (metres are assumed without a CRS: "m")."""
    name = crs_units(crs).h_name
    return {"metre": "m", "meter": "m", "foot": "ft", "US survey foot": "usft", "degree": "°"}.get(name, name or "")


def crs_units(crs: str | None):
    """Horizontal and vertical units of a CRS string as :class:`workstation.core.units.Units`.

    The one place where a CRS becomes metres-per-unit factors (pyproj): compound CRSs take
    their heights' unit from the vertical part, 3-D CRSs from the third axis. None or an
    unparseable CRS gives metres with ``known=False`` (a warning is logged for the latter).

    Examples
    --------
    >>> u = crs_units("EPSG:2994")
    >>> u.h, u.h_name
    (0.3048, 'foot')
    >>> crs_units("EPSG:26910+6360").v_name
    'US survey foot'
    """
    from workstation.core.units import UNKNOWN, Units

    if not crs:
        return UNKNOWN
    try:
        info = crs_info(crs)
    except InvalidInputError:
        log.warning("cannot parse the CRS %r; assuming metres", str(crs)[:60])
        return UNKNOWN
    return Units(info.metres_per_unit, info.vertical_metres_per_unit, info.unit, info.vertical_unit or info.unit,
                 info.is_geographic)


#: GeoTIFF keys of a LAS GeoKeyDirectory VLR that override the units of the coded CRS.
PROJ_LINEAR_UNITS_GEOKEY = 3076
VERTICAL_UNITS_GEOKEY = 4099


@lru_cache(maxsize=1)
def _epsg_linear_units() -> dict:
    """EPSG linear unit code -> (name, metres per unit), from the PROJ database."""
    from pyproj.database import get_units_map

    return {int(u.code): (u.name, float(u.conv_factor))
            for u in get_units_map(auth_name="EPSG", category="linear").values() if u.code.isdigit()}


def unit_geokeys(vlrs) -> dict:
    """``{3076: code, 4099: code}`` from the GeoKeyDirectory VLR (34735) among ``vlrs``.

    Only keys stored inline (``tiff_tag_location == 0``) carry a unit code. Returns {} when
    a WKT VLR (2112) is present too: the WKT is then authoritative (LAS 1.4 R15 §2.5).
    """
    keys = {}
    has_wkt = False
    for v in vlrs:
        rid = int(getattr(v, "record_id", -1))
        has_wkt |= rid == 2112 and getattr(v, "user_id", "") == "LASF_Projection"
        for k in getattr(v, "geo_keys", []) if rid == 34735 else []:
            if k.id in (PROJ_LINEAR_UNITS_GEOKEY, VERTICAL_UNITS_GEOKEY) and k.tiff_tag_location == 0:
                keys[int(k.id)] = int(k.value_offset)
    return {} if has_wkt else keys


def _linear_unit_json(code: int) -> dict | None:
    """PROJJSON of EPSG linear unit ``code``; None (with a warning) when PROJ does not know it."""
    unit = _epsg_linear_units().get(int(code))
    if unit is None:
        log.warning("GeoKey unit code %s is not an EPSG linear unit; ignored", code)
        return None
    return {"type": "LinearUnit", "name": unit[0], "conversion_factor": unit[1],
            "id": {"authority": "EPSG", "code": int(code)}}


def override_units(crs, h_code: int | None = None, v_code: int | None = None):
    """``crs`` (pyproj) with its horizontal and/or vertical unit replaced by EPSG unit codes.

    This is what ``ProjLinearUnitsGeoKey`` (3076) and ``VerticalUnitsGeoKey`` (4099) mean in a
    GeoTIFF/LAS key directory: the coordinates are in that unit whatever the unit of the
    EPSG code in ``ProjectedCSTypeGeoKey``. A differing vertical unit on a CRS without a
    height axis becomes a compound CRS with an unnamed vertical part in that unit. Codes that
    match the CRS already leave it unchanged (and keep its EPSG code).
    """
    import pyproj

    info = crs_info(crs.to_wkt())
    d = crs.to_json_dict()
    horiz = d["components"][0] if d.get("type") == "CompoundCRS" else d
    changed = False
    hu = _linear_unit_json(h_code) if h_code and not crs.is_geographic else None
    if hu is not None and abs(hu["conversion_factor"] - info.metres_per_unit) > 1e-12:
        for ax in horiz["coordinate_system"]["axis"][:2]:
            ax["unit"] = hu
        horiz.pop("id", None)
        horiz["name"] = f"{horiz['name']} ({hu['name']})"
        changed = True
    vu = _linear_unit_json(v_code) if v_code else None
    hfac = hu["conversion_factor"] if changed else info.metres_per_unit
    vfac = info.vertical_metres_per_unit if _vertical_axis(crs) is not None else hfac
    if vu is not None and abs(vu["conversion_factor"] - vfac) > 1e-12:
        vert = {"type": "VerticalCRS", "name": f"unknown height ({vu['name']})",
                "datum": {"type": "VerticalReferenceFrame", "name": "unknown"},
                "coordinate_system": {"subtype": "vertical", "axis": [
                    {"name": "Gravity-related height", "abbreviation": "H", "direction": "up", "unit": vu}]}}
        if d.get("type") == "CompoundCRS":
            d["components"][1]["coordinate_system"]["axis"][0]["unit"] = vu
            d["components"][1].pop("id", None)
        else:
            d = {"type": "CompoundCRS", "name": f"{horiz['name']} + {vert['name']}", "components": [horiz, vert]}
        changed = True
    if not changed:
        return crs
    d.pop("id", None)
    return pyproj.CRS.from_json_dict(d)


def apply_unit_geokeys(crs, vlrs):
    """The CRS a LAS file means: ``crs`` (pyproj, parsed by laspy from the EPSG code) with the
    unit overrides of its GeoKeyDirectory VLR applied (see :func:`override_units`)."""
    if crs is None:
        return None
    keys = unit_geokeys(vlrs)
    if not keys:
        return crs
    try:
        return override_units(crs, keys.get(PROJ_LINEAR_UNITS_GEOKEY), keys.get(VERTICAL_UNITS_GEOKEY))
    except Exception as exc:  # noqa: BLE001 - pyproj raises CRSError or KeyError on odd CRSs
        log.warning("GeoKey unit overrides %s could not be applied (%s); units of the EPSG code kept", keys, exc)
        return crs


# --------------------------------------------------------------------------- plausibility
#: Earth radius range (m) a point near the surface has in a geocentric CRS: deepest trench to
#: highest airborne survey, with the ellipsoid's flattening.
_GEOCENTRIC_RADIUS = (6_330_000.0, 6_420_000.0)


def crs_warnings(crs: str | None, bounds) -> list[str]:
    """Reasons why ``crs`` does not fit coordinates in ``bounds`` (empty when it fits).

    Checks: a geocentric CRS on points whose distance from the Earth's centre is not about
    6,371 km (projected eastings/northings look like that); a geographic CRS with |lon| > 180
    or |lat| > 90; a projected CRS whose coordinates lie far (more than half the area's own
    size) outside its area of use; heights in feet under metre eastings (a note, not an error).

    Parameters
    ----------
    crs : str or None
    bounds : ((3,) min, (3,) max) or ((2,) min, (2,) max)
        Coordinate bounds in the CRS's units.

    Examples
    --------
    >>> crs_warnings("EPSG:4978", ([500000, 5000000, 100], [500100, 5000100, 130]))[0][:40]
    'EPSG:4978 is geocentric (Earth-centred X'
    """
    if not crs:
        return []
    try:
        info = crs_info(crs)
        c = parse_crs(crs)
    except InvalidInputError as exc:
        return [str(exc)]
    lo, hi = np.asarray(bounds[0], float), np.asarray(bounds[1], float)
    out = []
    label = f"EPSG:{info.epsg}" if info.epsg else info.name
    if info.is_geocentric:
        corners = np.array([[a, b, c_] for a in (lo[0], hi[0]) for b in (lo[1], hi[1])
                            for c_ in ((lo[2], hi[2]) if len(lo) > 2 else (0.0,))])
        r = np.linalg.norm(corners, axis=1)
        if r.min() < _GEOCENTRIC_RADIUS[0] or r.max() > _GEOCENTRIC_RADIUS[1]:
            out.append(f"{label} is geocentric (Earth-centred X, Y, Z), but the points lie {r.min() / 1000:,.0f}-"
                       f"{r.max() / 1000:,.0f} km from the Earth's centre instead of about 6,371 km: the coordinates "
                       f"look projected (eastings, northings); assign the projected CRS they are in")
    elif info.is_geographic:
        if max(abs(lo[0]), abs(hi[0])) > 180 or max(abs(lo[1]), abs(hi[1])) > 90:
            out.append(f"{label} is geographic, but x spans {lo[0]:.6g}..{hi[0]:.6g} and y {lo[1]:.6g}..{hi[1]:.6g}: "
                       f"longitudes lie within ±180 and latitudes within ±90, so these look projected")
    else:
        far = _outside_area_of_use(c, lo, hi)
        if far:
            out.append(f"{label} coordinates {far}")
    if info.vertical_metres_per_unit != info.metres_per_unit and not info.is_geographic:
        out.append(f"heights are in {info.vertical_unit} under a horizontal CRS in {info.unit}: "
                   f"lengths and heights are converted separately")
    return out


def _outside_area_of_use(c, lo, hi) -> str:
    """Words saying how far the bounds fall outside the CRS's area of use; '' when inside or
    unknown. The area is projected into the CRS and widened by half its size each way."""
    import pyproj

    aou = c.area_of_use
    if aou is None:
        return ""
    try:
        geod = c.geodetic_crs
        tr = pyproj.Transformer.from_crs(geod, c.sub_crs_list[0] if c.is_compound else c, always_xy=True)
        x0, y0, x1, y1 = tr.transform_bounds(aou.west, aou.south, aou.east, aou.north, densify_pts=21)
    except Exception:  # noqa: BLE001 - projections that cannot map their whole area
        return ""
    if not all(np.isfinite([x0, y0, x1, y1])):
        return ""
    mx, my = 0.5 * (x1 - x0), 0.5 * (y1 - y0)
    if lo[0] >= x0 - mx and hi[0] <= x1 + mx and lo[1] >= y0 - my and hi[1] <= y1 + my:
        return ""
    return (f"x {lo[0]:,.0f}..{hi[0]:,.0f}, y {lo[1]:,.0f}..{hi[1]:,.0f} fall far outside its area of use "
            f"({aou.name[:60]}: x {x0:,.0f}..{x1:,.0f}, y {y0:,.0f}..{y1:,.0f} in its units): wrong CRS, or "
            f"coordinates in another unit (feet read as metres)?")


def raster_units(raster):
    """Units of a raster: those its producer recorded in ``meta['units']`` (``ws dem`` does:
    a GeoTIFF's CRS may not keep a vertical unit), else those of its CRS."""
    from workstation.core.units import Units

    return Units.from_dict((raster.meta or {}).get("units")) or crs_units(raster.crs)
