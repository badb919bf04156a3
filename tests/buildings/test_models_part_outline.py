"""Outlines of small building parts (dormers): the regularised outline keeps their corners."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.buildings.footprints import regularize, trace_outline
from workstation.buildings.models import _part_outline

CELL = 0.3


def _traced(poly):
    """The outline traced from ``poly`` rasterised at CELL, as part_polygons traces a part."""
    import shapely

    x0, y0, x1, y1 = poly.bounds
    o = np.array([x0 - 2 * CELL, y0 - 2 * CELL])
    cx, cy = np.meshgrid(o[0] + (np.arange(int((x1 - x0) / CELL) + 5) + 0.5) * CELL,
                         o[1] + (np.arange(int((y1 - y0) / CELL) + 5) + 0.5) * CELL)
    return trace_outline(shapely.contains_xy(poly, cx, cy).astype(float), o, CELL)


@pytest.mark.parametrize("yaw", [0.0, 0.4, 1.0])
@pytest.mark.parametrize("dormer", [[(0, 0), (3.6, 0), (3.6, 1.16), (1.8, 2.78), (0, 1.16)],
                                    [(0, 0), (4.0, 0), (4.0, 1.0), (2.0, 3.2), (0, 1.0)]])
def test_dormer_outline_stays_within_half_a_cell(dormer, yaw):
    """A dormer seen from above (front, two cheeks, two valleys to its ridge's end) a few metres
    across: its outline stays on average within half a raster cell of the true one."""
    import shapely

    poly = shapely.affinity.rotate(shapely.Polygon(dormer), yaw, origin=(0, 0), use_radians=True)
    out = shapely.Polygon(_part_outline(_traced(poly), CELL, yaw))
    assert out.is_valid and out.symmetric_difference(poly).area / poly.length < 0.5 * CELL


@pytest.mark.parametrize("yaw", [0.0, 0.4])
def test_large_part_outline_is_the_footprint_regularisation(yaw):
    import shapely

    poly = shapely.affinity.rotate(shapely.box(0, 0, 20, 10), yaw, origin=(0, 0), use_radians=True)
    t = _traced(poly)
    assert np.array_equal(_part_outline(t, CELL, yaw), regularize(t, CELL, direction=yaw))


@pytest.mark.parametrize("yaw", [0.2, 0.4, 1.0])
def test_fitted_outline_keeps_the_corners_the_points_show(yaw):
    """A dormer 3 m above the roof around it, seen as points: of the candidate outlines the one
    with the least squared height error at the points is taken; it follows the true outline
    closer than the footprint-tolerance regularisation, which cuts its corners at these headings."""
    import shapely

    from workstation.buildings.models import _fitted_outline, _side_cost

    poly = shapely.affinity.rotate(shapely.Polygon([(0, 0), (4.0, 0), (4.0, 1.0), (2.0, 3.2), (0, 1.0)]), yaw,
                                   origin=(0, 0), use_radians=True)
    footprint = poly.buffer(3.0, join_style="mitre")
    rng = np.random.default_rng(3)
    x0, y0, x1, y1 = footprint.bounds
    xy = rng.uniform([x0, y0], [x1, y1], (int(10 * footprint.envelope.area), 2))
    xy = xy[shapely.contains_xy(footprint, xy[:, 0], xy[:, 1])]
    part = np.where(shapely.contains_xy(poly, xy[:, 0], xy[:, 1]), 0, 1)
    dz = np.column_stack([np.where(part == 0, 0.0, -3.0), np.where(part == 0, 3.0, 0.0)])  # above planes 0, 1
    cost = _side_cost(dz, np.array([True, False]), part == 0)
    assert np.allclose(cost, 3.0)
    traced = _traced(poly)
    out = shapely.Polygon(_fitted_outline(traced, CELL, yaw, footprint, xy, part, 0, cost))
    coarse = shapely.Polygon(regularize(traced, CELL, direction=yaw))
    assert out.is_valid
    assert out.symmetric_difference(poly).area < coarse.symmetric_difference(poly).area
    assert out.symmetric_difference(poly).area / poly.length < 0.5 * CELL
