"""Crop a cloud by a box or polygons (PDAL ``filters.crop``): keep the points inside, or outside.

A box is (xmin, ymin, xmax, ymax) or (xmin, ymin, xmax, ymax, zmin, zmax), bounds included
as in PDAL. Polygons (with holes, multipolygons) come from :mod:`workstation.ops.vector` and
are moved into the cloud's CRS when both CRSs are known.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError

from .vector import PolygonSet

STAGE = "crop"


@dataclass(frozen=True)
class CropParams:
    """Parameters of :func:`crop`.

    Attributes
    ----------
    bounds : tuple of 4 or 6 floats, optional
        (xmin, ymin, xmax, ymax[, zmin, zmax]) in CRS units, bounds included.
    polygons : PolygonSet, optional
        Keep points inside any polygon (in the cloud's CRS, or moved into it).
    invert : bool
        Keep the points outside instead (PDAL's ``outside``).
    """

    bounds: tuple | None = None
    polygons: PolygonSet | None = None
    invert: bool = False

    def __post_init__(self):
        if (self.bounds is None) == (self.polygons is None):
            raise InvalidInputError("give either bounds or polygons", field="crop")
        if self.bounds is not None:
            b = np.asarray(self.bounds, dtype=float)
            if b.shape not in ((4,), (6,)) or not np.isfinite(b).all():
                raise InvalidInputError(f"bounds need 4 or 6 finite numbers, got {list(self.bounds)}",
                                        "xmin,ymin,xmax,ymax[,zmin,zmax]", field="bounds")
            if b[2] < b[0] or b[3] < b[1] or (b.size == 6 and b[5] < b[4]):
                raise InvalidInputError(f"bounds {list(self.bounds)} have a maximum below a minimum",
                                        "order them xmin,ymin,xmax,ymax[,zmin,zmax]", field="bounds")


def parse_bounds(text: str) -> tuple:
    """``"xmin,ymin,xmax,ymax[,zmin,zmax]"`` (or PDAL's ``([xmin,xmax],[ymin,ymax][,[zmin,zmax]])``) as a tuple.

    Examples
    --------
    >>> parse_bounds("0,1,10,11"), parse_bounds("([0, 10], [1, 11], [2, 3])")
    ((0.0, 1.0, 10.0, 11.0), (0.0, 1.0, 10.0, 11.0, 2.0, 3.0))
    """
    s = text.strip()
    pdal = s.startswith("(")
    try:
        vals = [float(v) for v in s.replace("(", "").replace(")", "").replace("[", "").replace("]", "").split(",")]
    except ValueError:
        raise InvalidInputError(f"'{text}' is not a list of numbers", "xmin,ymin,xmax,ymax[,zmin,zmax]",
                                field="bounds") from None
    if pdal and len(vals) in (4, 6):  # ([xmin, xmax], [ymin, ymax], [zmin, zmax])
        vals = [vals[0], vals[2], vals[1], vals[3], *vals[4:]]
    return tuple(vals)


def crop_mask(cloud: Cloud, params: CropParams) -> np.ndarray:
    """(n,) bool: the points :func:`crop` keeps."""
    xyz = cloud.xyz
    if params.bounds is not None:
        b = params.bounds
        inside = (xyz[:, 0] >= b[0]) & (xyz[:, 0] <= b[2]) & (xyz[:, 1] >= b[1]) & (xyz[:, 1] <= b[3])
        if len(b) == 6:
            inside &= (xyz[:, 2] >= b[4]) & (xyz[:, 2] <= b[5])
    else:
        inside = params.polygons.to_crs(cloud.crs).contains(xyz[:, :2])
    return ~inside if params.invert else inside


def crop(cloud: Cloud, params: CropParams) -> Cloud:
    """The points of ``cloud`` inside (or with ``invert`` outside) the box or polygons.

    Examples
    --------
    >>> c = Cloud(np.array([[0.0, 0, 0], [5, 5, 1], [20, 0, 0]]))
    >>> crop(c, CropParams(bounds=(0, 0, 10, 10))).n, crop(c, CropParams(bounds=(0, 0, 10, 10), invert=True)).n
    (2, 1)
    """
    out = cloud[crop_mask(cloud, params)]
    if out.n == 0:
        raise StageError(STAGE, "no point left", "check that the bounds or polygons overlap the data and are in its CRS")
    return out.with_history(STAGE, {"bounds": params.bounds, "polygons": None if params.polygons is None
                                    else len(params.polygons.polygons), "invert": params.invert})
