"""GeoTIFF round trips and the ws dem / hillshade / contours / ortho commands."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import OutputExistsError
from workstation.core.products import Raster
from workstation.io.geotiff import read_raster, write_raster


def test_geotiff_round_trip_layout(tmp_path):
    rasterio = pytest.importorskip("rasterio")
    a = np.random.default_rng(0).normal(100, 5, (600, 700)).astype(np.float32)
    a[3, 4] = np.nan
    r = Raster(a, (0.5, 0, 500000.0, 0, -0.5, 5000300.0), "EPSG:32632", -9999.0, {"kind": "dtm", "vertical_rmse": 0.1})
    p = write_raster(r, tmp_path / "d.tif")
    b = read_raster(p)
    assert b.crs == "EPSG:32632" and b.nodata == -9999.0 and b.transform == r.transform
    assert np.isnan(b.array[3, 4]) and np.array_equal(np.isnan(a), np.isnan(b.array))
    np.testing.assert_array_equal(b.array[np.isfinite(a)], a[np.isfinite(a)])
    assert b.meta["kind"] == "dtm" and b.meta["vertical_rmse"] == 0.1
    with rasterio.open(p) as src:
        assert src.profile["tiled"] and src.profile["blockxsize"] == 256
        assert src.compression.name.lower() == "deflate"
        assert src.overviews(1) == [2, 4]
        assert src.tags(ns="IMAGE_STRUCTURE").get("LAYOUT") == "COG"
        assert src.read(1)[3, 4] == -9999.0
    with pytest.raises(OutputExistsError):
        write_raster(r, p)
    write_raster(r, p, overwrite=True)


def test_rgba_written_with_alpha(tmp_path):
    rasterio = pytest.importorskip("rasterio")
    a = np.zeros((4, 50, 60), np.uint8)
    a[:3] = 120
    a[3, :, :30] = 255
    p = write_raster(Raster(a, (1, 0, 0, 0, -1, 50), "EPSG:32632"), tmp_path / "o.tif", photometric="RGB")
    with rasterio.open(p) as src:
        assert src.count == 4 and src.colorinterp[3].name == "alpha"
    assert read_raster(p).array.shape == (4, 50, 60)


@pytest.fixture
def las_file(tmp_path):
    from workstation.io import write_cloud

    rng = np.random.default_rng(3)
    n = 40_000
    x, y = rng.uniform(0, 80, n), rng.uniform(0, 80, n)
    z = 50 + 0.1 * x + np.sin(y / 10)
    bld = (x > 30) & (x < 50) & (y > 30) & (y < 50)
    z = np.where(bld, 65.0, z) + rng.normal(0, 0.03, n)
    cls = np.where(bld, ASPRSClass.BUILDING, ASPRSClass.GROUND).astype(np.uint8)
    c = Cloud(np.column_stack([x + 500000, y + 5000000, z]), {"classification": cls, "return_number": np.ones(n, np.uint8),
              "number_of_returns": np.ones(n, np.uint8)}, crs="EPSG:32632")
    p = tmp_path / "in.laz"
    write_cloud(c, p)
    return p


def test_cli_dem_hillshade_contours(tmp_path, las_file, capsys):
    dtm, dsm, chm = tmp_path / "dtm.tif", tmp_path / "dsm.tif", tmp_path / "chm.tif"
    assert main(["dem", str(las_file), "-o", str(dtm), "--kind", "dtm", "--resolution", "auto", "--vertical-rmse", "0.2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["resolution"] == 1.0 and "3 × vertical RMSE" in out["resolution_reason"]
    assert main(["dem", str(las_file), "-o", str(dsm), "--kind", "dsm", "--resolution", "1"]) == 0
    assert main(["dem", str(las_file), "-o", str(chm), "--kind", "chm", "--resolution", "1"]) == 0
    d, s, c = read_raster(dtm), read_raster(dsm), read_raster(chm)
    assert d.crs == "EPSG:32632" and d.meta["vertical_rmse"] == 0.2
    assert np.nanmax(s.array) > 64 and np.nanmax(d.array) < 60
    assert 9 < np.nanmax(c.array) < 15  # roof 65 m over ground of 52-56 m
    capsys.readouterr()
    assert main(["hillshade", str(dtm), "-o", str(tmp_path / "hs.tif"), "--png", str(tmp_path / "hs.png")]) == 0
    assert read_raster(tmp_path / "hs.tif").array.dtype == np.uint8 and (tmp_path / "hs.png").stat().st_size > 0
    assert main(["hillshade", str(dtm), "-o", str(tmp_path / "slope.tif"), "--product", "slope"]) == 0
    assert main(["contours", str(dtm), "-o", str(tmp_path / "c.geojson"), "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    assert res["interval"] == 1.0 and "3 × vertical RMSE" in res["interval_reason"]  # 3 × 0.2 -> 1 m
    doc = json.loads((tmp_path / "c.geojson").read_text())
    assert len(doc["features"]) == res["lines"] > 0
    # refuses to overwrite; usage errors
    assert main(["dem", str(las_file), "-o", str(dtm)]) == 1
    assert main(["dem", str(las_file), "-o", str(tmp_path / "x.tif"), "--resolution", "-1"]) == 2


def test_cli_ortho(tmp_path, capsys):
    from workstation.raster.synthetic_aerial import AerialRig, AerialScene, make_dataset

    sc = AerialScene(size=60.0, buildings=((20.0, 20.0, 35.0, 32.0, 10.0),))
    rig = AerialRig(height=50.0, width=120, height_px=90, focal_px=120.0)
    js = make_dataset(tmp_path / "w", sc, rig)
    write_raster(sc.true_dsm(0.5), tmp_path / "dsm.tif")
    rc = main(["ortho", str(js.parent), "--dsm", str(tmp_path / "dsm.tif"), "-o", str(tmp_path / "o.tif"),
               "--resolution", "0.5", "--accuracy", str(tmp_path / "acc.tif"), "--dsm-rmse", "0.1", "--json"])
    assert rc == 0
    meta = json.loads(capsys.readouterr().out)
    assert meta["coverage"] > 0.8 and meta["accuracy_rms_m"] > 0
    o = read_raster(tmp_path / "o.tif").array
    truth = sc.true_ortho(0.5)
    seen = o[3] > 0
    assert np.abs(o[:3].transpose(1, 2, 0).astype(float) - truth)[seen].mean() < 12
    acc = read_raster(tmp_path / "acc.tif").array
    assert np.nanmax(acc) < 0.1 * np.tan(np.radians(45)) + 1e-6  # σ_z · tan θ with θ ≤ 45°
