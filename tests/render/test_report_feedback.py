"""The report of a folder of plain ws outputs (no JSON): stages from the products' own records,
ground results as their own section, hillshades in grey, a class legend of the classes present
beside the render; ws hillshade --png previews enlarged to a readable size."""

from __future__ import annotations

import base64
import io
import os
import re

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.products import Raster


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    from workstation.io import write_cloud
    from workstation.io.geotiff import write_raster
    from workstation.raster import terrain

    d = tmp_path_factory.mktemp("plain")
    rng = np.random.default_rng(1)
    n = 3000
    xyz = np.column_stack([rng.uniform(0, 30, n) + 500_000, rng.uniform(0, 20, n) + 4e6, rng.uniform(0, 1, n) + 50])
    xyz = np.round(xyz, 3)
    src_cls = np.full(n, ASPRSClass.UNCLASSIFIED, np.uint8)
    src_cls[xyz[:, 0] > 500_025] = ASPRSClass.BUILDING
    write_cloud(Cloud(xyz, {"classification": src_cls}, crs="EPSG:32632"), d / "survey.laz")
    cls = src_cls.copy()
    cls[(xyz[:, 0] <= 500_025) & (xyz[:, 2] < 50.6)] = ASPRSClass.GROUND
    write_cloud(Cloud(xyz, {"classification": cls}, crs="EPSG:32632"), d / "filtered.laz")
    os.utime(d / "survey.laz", (1e9, 1e9))  # the input is older than the filter's output
    yy, xx = np.mgrid[0:12, 0:16]
    dem = Raster((100 + 0.5 * xx + 3 * np.sin(yy / 3)).astype(np.float32), (2.0, 0, 500_000, 0, -2.0, 4_000_020),
                 "EPSG:32632", -9999.0, {"kind": "dtm", "method": "tin", "resolution": 2.0, "points": 1234})
    write_raster(dem, d / "dtm.tif")
    write_raster(terrain.hillshade(dem, terrain.HillshadeParams()), d / "relief.tif")  # no "hillshade" in the name
    return d, int(np.count_nonzero(cls == ASPRSClass.GROUND)), int(np.count_nonzero(cls != src_cls))


@pytest.fixture(scope="module")
def page(folder):
    from workstation.render.report import ReportParams, build_report

    return build_report(folder[0], ReportParams(render_size=(200, 150)))


def _figure(page, caption_start):
    from PIL import Image

    m = re.search(r'<img alt="' + re.escape(caption_start) + r'[^"]*" src="data:image/png;base64,([^"]+)"', page)
    assert m, caption_start
    return np.asarray(Image.open(io.BytesIO(base64.b64decode(m.group(1)))).convert("RGB"))


def test_no_json_folder_still_has_stages(page):
    assert "No JSON records found" not in page and "No records found" not in page
    sec = page.split('<section id="appendix">')[1].split("</section>")[0]  # the records, collapsed
    assert "<summary>Stages and figures" in sec
    assert "dtm.tif" in sec and "tin" in sec and "relief.tif" in sec and "hillshade" in sec


def test_ground_result_is_its_own_section_with_its_numbers(page, folder):
    _, n_ground, n_changed = folder
    assert "the same points as" not in page
    sec = page.split("<h2>Ground</h2>")[1].split("<h2>")[0]
    row = re.search(r"<tr><td>filtered\.laz</td>(.*?)</tr>", sec).group(1)
    assert f"{n_ground:,}" in row and f"{100 * n_ground / 3000:.1f} %" in row
    assert f"{n_changed:,} points vs survey.laz" in row
    assert "<td>survey.laz</td>" not in sec  # the input is not a ground result
    assert page.count("<h3>filtered.laz</h3>") == 1 and page.count("<h3>survey.laz</h3>") == 1  # both drawn


def test_hillshade_is_grey_and_dem_is_tinted(page):
    hs = _figure(page, "relief.tif").astype(int)
    assert "relief.tif: hillshade (grey" in page
    spread = hs.max(axis=2) - hs.min(axis=2)
    assert spread.max() <= 2  # grey everywhere: no tint, no colour bar
    dem = _figure(page, "dtm.tif").astype(int)
    assert (dem.max(axis=2) - dem.min(axis=2)).max() > 30  # the elevation tint


def test_class_legend_lists_present_classes_outside_the_render(page):
    sec = page.split("<h3>filtered.laz</h3>")[1].split("<h3>")[0]
    img = _figure(sec, "filtered.laz: top view")
    assert img.shape[1] > 200 + 60  # the legend strip is beside the 200 px render, not over it
    from workstation.render.report import _class_legend_figure

    import matplotlib.pyplot as plt

    shown = []
    orig = plt.Axes.legend

    def spy(self, *a, **kw):
        shown.extend(h.get_label() for h in kw["handles"])
        return orig(self, *a, **kw)

    plt.Axes.legend = spy
    try:
        _class_legend_figure(np.zeros((50, 60, 3), np.uint8), np.array([2, 2, 6], np.uint8), "t")
    finally:
        plt.Axes.legend = orig
    assert shown == ["2 Ground (2)", "6 Building (1)"]


def test_raster_kind_rules(tmp_path):
    from pathlib import Path

    from workstation.render.report_rasters import raster_kind

    assert raster_kind(Path("a.tif"), {"kind": "hillshade"}) == "hillshade"
    assert raster_kind(Path("dtm_hillshade.tif"), {"kind": "dtm"}) == "elevation"
    assert raster_kind(Path("x.tif"), {}, "uint8", 0) == "hillshade"
    assert raster_kind(Path("slope.tif"), {}) == "slope"
    assert raster_kind(Path("dod_errors.tif"), {}) == "error"
    assert raster_kind(Path("dsm.tif"), {}, "float32", -9999) == "elevation"
    assert raster_kind(Path("o.tif"), {"kind": "ortho"}) == raster_kind(Path("site_ortho.tif"), {}) == "image"
    assert raster_kind(Path("density.tif"), {"kind": "qc"}) == raster_kind(Path("d.tif"), {"kind": "density"}) == "density"
    assert raster_kind(Path("voids.tif"), {"kind": "qc"}) == "map"


def test_hillshade_png_preview_is_enlarged(tmp_path):
    from PIL import Image

    from workstation.cli.hillshade import PREVIEW_MIN_PX, preview_image
    from workstation.cli.main import main
    from workstation.io.geotiff import write_raster

    yy, xx = np.mgrid[0:30, 0:40]
    write_raster(Raster((10 + 0.3 * xx + np.sin(yy / 4)).astype(np.float32), (1.0, 0, 0, 0, -1.0, 30), "EPSG:32632",
                        -9999.0, {"kind": "dtm"}), tmp_path / "dtm.tif")
    assert main(["hillshade", str(tmp_path / "dtm.tif"), "-o", str(tmp_path / "hs.tif"), "--png", str(tmp_path / "hs.png")]) == 0
    w, h = Image.open(tmp_path / "hs.png").size
    assert max(w, h) >= PREVIEW_MIN_PX and (w, h) == (40 * 20, 30 * 20)
    big = np.full((900, 1000), 128, np.uint8)
    assert preview_image(big, "hillshade").shape == (900, 1000)  # large rasters kept cell for pixel
