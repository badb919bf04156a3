"""Roof planes of one building of a simulated district, and their distance to its true faces
(shared by the small-face and regularity tests)."""

from __future__ import annotations

import numpy as np

from workstation.buildings import synth
from workstation.buildings.planes import segment_planes


def segment_building(seed: int, index: int, kind: str = "dormer"):
    """``(building, its class-6 points, segment_planes result)`` for building ``index`` of the
    40-building complex district of ``seed`` (10 points/m², 3 cm noise)."""
    xyz, cls, blds = synth.district(40, seed=seed, density=10.0, noise=0.03, kinds=synth.COMPLEX_KINDS)
    b = blds[index]
    assert b.kind == kind
    pts = xyz[cls == 6]
    pts = pts[b.inside(pts[:, :2])]
    return b, pts, segment_planes(pts)


def true_face_misfits(b, r) -> list[tuple[float, float, float]]:
    """For each true face ``(tilt, azimuth)``: the smallest combined tilt/azimuth difference
    (degrees) to a found plane, as ``(tilt, azimuth, misfit)``."""
    found = np.column_stack([r.tilt_deg, r.azimuth_deg])
    return [(tilt, az, float(np.hypot(found[:, 0] - tilt, (found[:, 1] - az + 180) % 360 - 180).min()))
            for tilt, az in b.true_tilt_azimuth()]
