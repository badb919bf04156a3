"""Hillshade/slope/aspect (Horn) and contour lines."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.core.errors import StageError
from workstation.core.products import Raster
from workstation.raster.contours import ContourParams, choose_interval, contour_lines, write_geojson
from workstation.raster.terrain import HillshadeParams, aspect, hillshade, horn_gradient, slope


def plane(gx, gy, res=2.0, n=20):
    tr = (res, 0.0, 1000.0, 0.0, -res, 2000.0)
    X, Y = Raster(np.zeros((n, n)), tr).cell_centers()
    return Raster(10.0 + gx * X + gy * Y, tr, "EPSG:32632")


def test_horn_gradient_slope_aspect_of_planes():
    r = plane(0.5, 0.0)
    gx, gy = horn_gradient(r)
    np.testing.assert_allclose(gx[1:-1, 1:-1], 0.5)
    np.testing.assert_allclose(gy[1:-1, 1:-1], 0.0, atol=1e-12)
    np.testing.assert_allclose(slope(r).array[5, 5], np.degrees(np.arctan(0.5)), rtol=1e-5)
    assert slope(r, units="percent").array[5, 5] == pytest.approx(50.0)
    # rising to the east -> faces (falls towards) west = 270°; rising north -> faces south = 180°
    assert aspect(r).array[5, 5] == pytest.approx(270.0)
    assert aspect(plane(0.0, 0.3)).array[5, 5] == pytest.approx(180.0)
    assert np.isnan(aspect(plane(0.0, 0.0)).array[5, 5])


def test_hillshade_values_and_nodata():
    flat = plane(0.0, 0.0)
    hs = hillshade(flat, HillshadeParams(azimuth=315, altitude=30))
    assert hs.array.dtype == np.uint8 and abs(int(hs.array[5, 5]) - 255 * np.sin(np.radians(30))) <= 0.51
    # a slope facing the light is brighter than one facing away
    east_facing = plane(-0.5, 0.0)  # falls towards the east
    lit = hillshade(east_facing, HillshadeParams(azimuth=90, altitude=45)).array[5, 5]
    dark = hillshade(east_facing, HillshadeParams(azimuth=270, altitude=45)).array[5, 5]
    assert lit > 240 > 100 > dark
    a = flat.array.copy()
    a[10, 10] = np.nan
    h = hillshade(Raster(a, flat.transform)).array
    assert h[10, 10] == 0 and h[9, 9] == 0 and h[5, 5] > 0  # NaN poisons its 3×3 window only


def cone(n=101, res=1.0):
    tr = (res, 0.0, 0.0, 0.0, -res, n * res)
    X, Y = Raster(np.zeros((n, n)), tr).cell_centers()
    c = n * res / 2
    return Raster(50.0 - np.hypot(X - c, Y - c) * 0.5, tr, "EPSG:32632"), c


def test_contours_of_a_cone_are_closed_circles():
    r, c = cone()
    cs = contour_lines(r, ContourParams(interval=2.0))
    radii = (50.0 - cs.levels) / 0.5
    inner = radii < c - 1.0  # circles inside the grid close; larger ones are cut by the edge
    assert inner.sum() > 5 and cs.closed[inner].all() and not cs.closed[radii > c + 1.0].any()
    for pts, radius in zip(cs.lines, radii):
        d = np.hypot(pts[:, 0] - c, pts[:, 1] - c)
        assert np.abs(d - radius).max() < 0.05 * radius + 0.2
    # index contours at multiples of 5 × 2 m
    assert set(cs.levels[cs.index] % 10.0) == {0.0}
    assert cs.index.any() and not cs.index.all()


def test_open_lines_on_a_plane_and_smoothing_keeps_ends():
    r = plane(0.2, 0.1)
    cs = contour_lines(r, ContourParams(interval=1.0))
    assert not cs.closed.any()
    sm = contour_lines(r, ContourParams(interval=1.0, smooth=2))
    for a, b in zip(cs.lines, sm.lines):
        np.testing.assert_allclose(a[[0, -1]], b[[0, -1]])
        assert len(b) >= len(a)
        # points lie on the level line of the plane: 10 + 0.2 x + 0.1 y = level
    lev = 10 + 0.2 * cs.lines[0][:, 0] + 0.1 * cs.lines[0][:, 1]
    np.testing.assert_allclose(lev, cs.levels[0], atol=1e-6)


def test_interval_defaults_to_three_times_vertical_rmse(tmp_path):
    r, _ = cone()
    r = Raster(r.array, r.transform, r.crs, None, {"vertical_rmse": 0.15})
    iv, why = choose_interval(r, None)
    assert iv == 0.5 and "3 × vertical RMSE" in why
    cs = contour_lines(r)
    assert cs.interval == 0.5
    out = write_geojson(cs, tmp_path / "c.geojson")
    doc = json.loads(out.read_text())
    assert doc["type"] == "FeatureCollection" and len(doc["features"]) == len(cs)
    f = doc["features"][0]
    assert f["geometry"]["type"] == "LineString" and set(f["properties"]) == {"elevation", "index", "closed"}
    assert doc["crs"]["properties"]["name"].endswith("32632")
    with pytest.raises(StageError):
        contour_lines(Raster(np.full((5, 5), 1.5), r.transform), ContourParams(interval=1.0))


def test_contours_respect_nodata():
    r, _ = cone()
    a = r.array.copy()
    a[:, 50:] = np.nan
    cs = contour_lines(Raster(a, r.transform), ContourParams(interval=2.0))
    assert not cs.closed.any()
    assert max(p[:, 0].max() for p in cs.lines) <= 50.5
