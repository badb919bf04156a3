"""Height above ground (``hag``) from a TIN of the ground points.

Each point's height minus the linear interpolation of the ground points' Delaunay TIN at its
position (nearest ground height outside the TIN's hull), as PDAL's ``filters.hag_delaunay``.
Heights are in the CRS's vertical unit, stored as float32 in the ``hag`` dimension.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import StageError

from . import common

STAGE = "ground.hag"


@dataclass(frozen=True)
class HAGParams:
    """Height-above-ground parameters.

    Attributes
    ----------
    ground_classes : tuple of int
        Classes used as ground ((2,)).
    clamp_negative : bool
        Set negative heights to 0 (False).
    """

    ground_classes: tuple = (int(ASPRSClass.GROUND),)
    clamp_negative: bool = False


def height_above_ground(cloud: Cloud, params: HAGParams | None = None, **overrides) -> Cloud:
    """A new cloud with ``hag`` (f4, CRS vertical unit): height above the ground TIN.

    Raises
    ------
    StageError
        When the cloud has no classification or fewer than 3 ground points.
    """
    p = replace(params or HAGParams(), **overrides)
    t0 = time.perf_counter()
    cls = cloud.attrs.get("classification")
    if cls is None:
        raise StageError(STAGE, "the cloud has no classification", "run ws ground first")
    g = np.isin(cls, p.ground_classes)
    if g.sum() < 3:
        raise StageError(STAGE, f"only {int(g.sum())} ground point(s)", "run ws ground first, or check --ground-classes")
    xyz = cloud.xyz
    o = xyz[:, :2].min(axis=0)
    zt = common.tin_interpolate(xyz[g, :2] - o, xyz[g, 2], xyz[:, :2] - o)
    hag = xyz[:, 2] - zt
    if p.clamp_negative:
        hag = np.maximum(hag, 0.0)
    out = cloud.with_attrs(hag=hag.astype(np.float32))
    return out.with_history(STAGE, {"ground_classes": list(p.ground_classes), "clamp_negative": p.clamp_negative},
                            time.perf_counter() - t0)
