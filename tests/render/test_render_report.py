"""`ws render` and `ws report`: files, a self-contained page, and every image loading in Chromium."""

from __future__ import annotations

import base64
import json
import re
import shutil
import subprocess

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.products import Mesh


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    """A small work folder: a classified LAS cloud, a PLY mesh, a run.json, a confusion
    matrix record and a DEM GeoTIFF."""
    import rasterio
    from rasterio.transform import Affine  # from_origin multiplies with `*`, which affine 3.1 deprecates

    from workstation.io import write_cloud
    from workstation.io.mesh import write_mesh

    d = tmp_path_factory.mktemp("work")
    rng = np.random.default_rng(0)
    n = 5000
    xyz = np.column_stack([rng.uniform(0, 40, n) + 500_000, rng.uniform(0, 30, n) + 4e6, rng.uniform(0, 2, n) + 50])
    cls = np.where(xyz[:, 0] > 500_020, ASPRSClass.BUILDING, ASPRSClass.GROUND).astype(np.uint8)
    c = Cloud(np.round(xyz, 3), {"classification": cls}, crs="EPSG:32632").with_history("ground.csf", {"cloth_resolution": 0.5}, 1.25)
    write_cloud(c, d / "cloud.las")
    import pymeshlab

    ms = pymeshlab.MeshSet()
    ms.create_sphere(subdiv=3)
    write_mesh(Mesh(ms.current_mesh().vertex_matrix(), ms.current_mesh().face_matrix()), d / "mesh.ply")
    (d / "run.json").write_text(json.dumps({"stages": [
        {"name": "ground", "params": {"method": "csf", "cloth_resolution": 0.5}, "seconds": 1.25,
         "summary": {"ground_points": 2500}},
        {"name": "mesh", "params": {"depth": 9}, "seconds": 3.5}]}))
    (d / "evaluation.json").write_text(json.dumps({"kappa": 0.91, "confusion_matrix": [[90, 10], [5, 95]],
                                                   "labels": ["ground", "object"]}))
    yy, xx = np.mgrid[0:40, 0:50]
    dem = (100 + 0.5 * xx + 5 * np.sin(yy / 6)).astype(np.float32)
    with rasterio.open(d / "dtm.tif", "w", driver="GTiff", width=50, height=40, count=1, dtype="float32",
                       transform=Affine(1.0, 0.0, 500_000, 0.0, -1.0, 4_000_030), crs="EPSG:32632", nodata=-9999) as ds:
        ds.write(dem, 1)
    return d


@pytest.fixture(scope="module")
def report_html(workdir, tmp_path_factory):
    from workstation.cli.main import main

    out = tmp_path_factory.mktemp("rep") / "report.html"
    assert main(["report", str(workdir), "-o", str(out), "--render-size", "320x240"]) == 0
    return out


def test_report_is_self_contained_with_every_section(report_html):
    from PIL import Image
    import io

    text = report_html.read_text()
    imgs = re.findall(r'src="data:image/png;base64,([^"]+)"', text)
    # cloud render + class histogram + mesh render + confusion matrix + hillshade
    assert len(imgs) == 5
    assert text.index('<section id="summary"') < text.index("<img")  # the summary page comes first
    for b in imgs:
        im = Image.open(io.BytesIO(base64.b64decode(b)))
        assert im.size[0] > 50 and im.size[1] > 50
    assert not re.search(r'(src|href)="(?!data:|#)', text)  # no external file (links inside the page only)
    for needle in ("ground", "cloth_resolution", "mesh.ply", "cloud.las", "dtm.tif", "kappa", "2500"):
        assert needle in text


def test_report_opens_in_headless_chromium_with_all_images(report_html, tmp_path):
    exe = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if exe is None:
        pytest.skip("chromium is not installed (Debian: apt-get install -y chromium)")
    probe = tmp_path / "probe.html"
    script = ("<script>window.addEventListener('load',()=>{const im=[...document.images];"
              "document.title='IMAGES '+im.filter(i=>i.complete&&i.naturalWidth>0).length+'/'+im.length;});</script>")
    probe.write_text(report_html.read_text().replace("</body>", script + "</body>"))
    r = subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu", "--virtual-time-budget=10000",
                        "--dump-dom", probe.as_uri()], capture_output=True, text=True, timeout=120)
    m = re.search(r"<title>IMAGES (\d+)/(\d+)</title>", r.stdout)
    assert m, r.stderr[-2000:]
    assert m.group(1) == m.group(2) == "5"


def test_ws_render_cli_png_and_turntable(workdir, tmp_path, capsys):
    from PIL import Image

    from workstation.cli.main import main

    out = tmp_path / "top.png"
    rc = main(["render", str(workdir / "cloud.las"), "-o", str(out), "--view", "top", "--color", "class",
               "--size", "300x200", "--json"])
    assert rc == 0
    assert json.loads(capsys.readouterr().out)["files"] == [str(out)]
    im = np.asarray(Image.open(out).convert("RGB"))
    assert im.shape == (200, 300, 3)
    assert main(["render", str(workdir / "cloud.las"), "-o", str(out)]) == 1  # exists
    assert main(["render", str(workdir / "mesh.ply"), "-o", str(tmp_path / "m.gif"), "--turntable", "3",
                 "--size", "80x60"]) == 0
    with Image.open(tmp_path / "m.gif") as g:
        assert g.n_frames == 3
    assert main(["render", str(workdir / "mesh.ply"), "-o", str(tmp_path / "seq.png"), "--turntable", "2",
                 "--size", "80x60"]) == 0
    assert (tmp_path / "seq_000.png").exists() and (tmp_path / "seq_001.png").exists()
    assert main(["render", str(workdir / "cloud.las"), "-o", str(tmp_path / "x.gif")]) == 1  # gif needs frames
    assert main(["render", str(workdir / "cloud.las"), "-o", str(tmp_path / "y.png"), "--size", "big"]) == 2
