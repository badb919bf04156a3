"""CRS helpers through pyproj: names, EPSG codes, linear units, reprojection of clouds."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError

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
        Height unit in metres (the horizontal one when the CRS has no vertical axis).
    """

    name: str
    epsg: int | None
    is_geographic: bool
    unit: str
    metres_per_unit: float
    vertical_metres_per_unit: float

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


def crs_info(crs: str | None) -> CRSInfo | None:
    """Name, EPSG code and units of a CRS string; None when ``crs`` is None.

    Examples
    --------
    >>> i = crs_info("EPSG:2994")
    >>> i.unit, round(i.metres_per_unit, 6)
    ('foot', 0.3048)
    """
    if not crs:
        return None
    c = parse_crs(crs)
    epsg = c.to_epsg(min_confidence=70)
    horiz = c
    vert_factor = None
    if c.is_compound:
        subs = c.sub_crs_list
        horiz = subs[0]
        for s in subs[1:]:
            if s.axis_info:
                vert_factor = s.axis_info[0].unit_conversion_factor
    axis = horiz.axis_info[0] if horiz.axis_info else None
    if horiz.is_geographic:
        unit, factor = "degree", METRES_PER_DEGREE
    elif axis is not None and axis.unit_conversion_factor:
        unit, factor = axis.unit_name, float(axis.unit_conversion_factor)
    else:
        unit, factor = "metre", 1.0
    if vert_factor is None:
        vert_factor = 1.0 if horiz.is_geographic else factor
    return CRSInfo(c.name, epsg, bool(horiz.is_geographic), unit, factor, float(vert_factor))


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
