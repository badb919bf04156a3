"""`ws report` as a quality report: the summary page first (what was processed, key accuracies,
the QC verdict, the list of figures), SfM figures from a COLMAP work folder, GCP residuals,
registration residuals, ground evaluation, the JSON records only in a collapsed appendix, and
the PDF printed by headless Chromium."""

from __future__ import annotations

import json
import re
import shutil

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.products import Raster


def _sfm_folder(d):
    """A tiny SfM work folder: a synthetic COLMAP reconstruction (6 images, 150 points, 0.7 px
    image noise) in sparse/0, its stage record and a georeferencing report with known residuals.
    Returns the mean reprojection error pycolmap computes and the check RMSE 3-D."""
    import pycolmap

    from workstation.io.reconstruction import stage_record, write_stage_record

    o = pycolmap.SyntheticDatasetOptions()
    o.num_rigs, o.num_cameras_per_rig, o.num_frames_per_rig, o.num_points3D = 1, 1, 6, 150
    rec = pycolmap.synthesize_dataset(o)
    noise = pycolmap.SyntheticNoiseOptions()
    noise.point2D_stddev = 0.7
    pycolmap.synthesize_noise(noise, rec)
    (d / "sparse" / "0").mkdir(parents=True)
    rec.write(str(d / "sparse" / "0"))
    write_stage_record(stage_record("sfm", {"images": 7, "registered": 6, "points": rec.num_points3D(),
                                            "unregistered": ["IMG_7.JPG"]},
                                    inputs={"image_dir": "/survey/photos"}, params={}, outputs=[], seconds=1.0),
                       d / "summary.json")
    res = np.array([[0.01, -0.02, 0.03], [-0.02, 0.01, -0.01], [0.0, 0.02, 0.02], [0.03, 0.0, -0.04],
                    [0.05, -0.01, 0.06], [-0.04, 0.03, -0.02]])
    roles = ["control"] * 3 + ["check"] * 3
    chk = res[3:]
    rmse3d = float(np.sqrt(np.mean(np.sum(chk**2, axis=1))))
    pts = [{"name": f"GCP{i}", "role": r, "X": 500000.0 + 10 * i, "Y": 4e6 + 7 * (i % 3), "Z": 100.0,
            "dX": a, "dY": b, "dZ": c} for i, (r, (a, b, c)) in enumerate(zip(roles, res))]
    metrics = {"control_n": 3, "check_n": 3, "control_rmse_3d": float(np.sqrt(np.mean(np.sum(res[:3]**2, axis=1)))),
               "check_rmse_3d": rmse3d, "check_rmse_z": float(np.sqrt(np.mean(chk[:, 2]**2)))}
    (d / "georef_report.json").write_text(json.dumps({"adjustment": "similarity", "metrics": metrics, "points": pts,
                                                      "notes": []}))
    return rec.compute_mean_reprojection_error(), rmse3d


def _registration(d, rng):
    """A real registration of a shifted copy of a ridge surface, written as ws register writes it."""
    from workstation.registration.register import RegisterParams, register

    def surface(n):
        x, y = rng.uniform(0, 20, (2, n))
        return np.c_[x, y, np.sin(x / 3) + 0.5 * np.cos(y / 2) + rng.normal(0, 0.01, n)]

    tgt, src = Cloud(surface(4000)), Cloud(surface(4000) + [0.3, -0.2, 0.1])  # two samplings of one surface
    r = register(src, tgt, RegisterParams(method="icp"), init=np.eye(4))
    (d / "registration.json").write_text(json.dumps(r.to_dict(), default=float))
    return r.inlier_rmse


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    """A work folder with a classified cloud, a DTM, an SfM folder, a ws qc result, a
    registration record and a ground evaluation."""
    from workstation.ground.evaluate import ground_errors
    from workstation.io import write_cloud
    from workstation.io.geotiff import write_raster
    from workstation.qc.run import QCParams, write_qc

    d = tmp_path_factory.mktemp("quality")
    rng = np.random.default_rng(5)
    xs, ys = np.meshgrid(np.arange(0, 40, 1.0), np.arange(0, 30, 1.0))
    xyz = np.c_[xs.ravel() + 500_000, ys.ravel() + 4e6, 50 + 0.02 * xs.ravel()]
    cls = np.where(xyz[:, 0] > 500_030, ASPRSClass.BUILDING, ASPRSClass.GROUND).astype(np.uint8)
    write_cloud(Cloud(np.round(xyz, 3), {"classification": cls}, crs="EPSG:32632"), d / "cloud.las")
    yy, xx = np.mgrid[0:15, 0:20]
    write_raster(Raster((50 + 0.04 * xx + 0 * yy).astype(np.float32), (2.0, 0, 500_000, 0, -2.0, 4_000_030),
                        "EPSG:32632", -9999.0, {"kind": "dtm", "resolution": 2.0}), d / "dtm.tif")
    rgb = np.stack([np.tile(np.linspace(0, 250, 20), (15, 1)), np.full((15, 20), 200.0), np.zeros((15, 20))])
    write_raster(Raster(rgb.astype(np.uint8), (2.0, 0, 500_000, 0, -2.0, 4_000_030), "EPSG:32632", None,
                        {"kind": "ortho"}), d / "ortho.tif")
    mean_px, check_rmse = _sfm_folder(d / "sfm")
    write_qc([d / "cloud.las"], d / "qc", QCParams(spec="usgs-ql2"))
    icp_rmse = _registration(d, rng)
    ref = rng.random(500) < 0.6
    pred = ref ^ (rng.random(500) < 0.1)
    ev = ground_errors(ref, pred).to_dict()
    (d / "ground_eval.json").write_text(json.dumps(ev))
    qc = json.loads((d / "qc" / "qc.json").read_text())
    return d, {"mean_px": mean_px, "check_rmse": check_rmse, "icp_rmse": icp_rmse, "ev": ev, "qc": qc}


@pytest.fixture(scope="module")
def report(work, tmp_path_factory):
    """`ws report WORK -o report.html`, with --pdf when Chromium is here: (html, pdf or None)."""
    from workstation.cli.main import main
    from workstation.render.report_pdf import find_chromium

    out = tmp_path_factory.mktemp("rep") / "report.html"
    pdf = ["--pdf"] if find_chromium() else []
    assert main(["report", str(work[0]), "-o", str(out), "--render-size", "160x120", "--max-points", "20000", *pdf]) == 0
    return out, (out.with_suffix(".pdf") if pdf else None)


@pytest.fixture(scope="module")
def page(report):
    return report[0].read_text()


def _section(page, anchor):
    m = re.search(rf'<section id="{anchor}"[^>]*>(.*?)</section>', page, re.S)
    assert m, anchor
    return m.group(1)


def _row(html_text, name):
    m = re.search(r"<tr><t[hd]>" + re.escape(name) + r"</t[hd]><td>([^<]*)</td>", html_text)
    assert m, name
    return m.group(1)


def test_summary_comes_first_with_qc_verdict_and_figure_list(page, work):
    _, truth = work
    assert page.index('<section id="summary"') < page.index("<figure>")
    summ = _section(page, "summary")
    word = "PASS" if truth["qc"]["verdict"]["pass"] else "FAIL"
    assert re.search(rf'QC usgs-ql2: <span class="(pass|fail)">{word}</span>', summ)
    assert not truth["qc"]["verdict"]["pass"]  # 1 point/m² is below the QL2 density
    listed = re.findall(r"<li>([^<]*)</li>", summ)
    for cap in ("Reprojection error histogram: sfm", "Camera positions over the sparse cloud (top view): sfm",
                "GCP and check point residuals: sfm/georef_report.json", "Registration residuals: registration.json",
                "dtm.tif: hillshade (315°/45°) with elevation tint", "cloud.las: top view, colour class"):
        assert cap in listed, cap
    captions = re.findall(r"<figcaption>([^<]*)</figcaption>", page)
    assert sorted(listed) == sorted(captions)  # every figure listed, nothing else
    assert _row(summ, "photos").startswith("6 of 7 registered")
    assert "/survey/photos" in _row(summ, "inputs (stage records)")
    assert "EPSG:32632" in _row(summ, "CRS")
    prev = re.findall(r"<figcaption>([^<]*)</figcaption>", _section(page, "previews"))
    assert prev[0] == "ortho.tif: orthophoto"  # the ortho first, in colour (below)
    assert _row(summ, "area covered").startswith("1,200 m²")  # 15 × 20 cells of 2 m


def test_ortho_preview_is_in_colour(page):
    import base64
    import io

    from PIL import Image

    m = re.search(r'<img alt="ortho.tif: orthophoto" src="data:image/png;base64,([^"]+)"', page)
    im = np.asarray(Image.open(io.BytesIO(base64.b64decode(m.group(1)))).convert("RGB")).astype(int)
    assert ((im[..., 1] - im[..., 2]) > 150).mean() > 0.3  # green over blue: the bands drawn as colour


def test_key_accuracies_match_their_sources(page, work):
    _, truth = work
    summ = _section(page, "summary")
    rows = dict(re.findall(r"<tr><td>([^<]*)</td><td>([^<]*)</td><td>[^<]*</td></tr>", summ))
    # the reprojection errors recomputed from the model equal pycolmap's own mean
    value = lambda key, unit: float(rows[key].removesuffix(f" {unit}"))  # noqa: E731
    assert value("SfM mean reprojection error", "px") == pytest.approx(truth["mean_px"], rel=1e-3)
    assert value("check point RMSE 3D (3 points)", "m") == pytest.approx(truth["check_rmse"], rel=1e-3)
    assert value("registration inlier RMSE", "m") == pytest.approx(truth["icp_rmse"], rel=1e-3)
    assert value("ground filter total error", "%") / 100 == pytest.approx(truth["ev"]["total_error"], abs=1e-5)
    assert rows["SfM registered images"] == "6 of 7 registered"


def test_json_records_only_in_collapsed_appendix(page):
    sections = re.findall(r'<section id="([^"]+)"', page)
    assert sections[0] == "summary" and sections[-1] == "appendix"
    assert {"previews", "photogrammetry", "registration", "ground", "clouds"} <= set(sections)
    app = _section(page, "appendix")
    before = page[: page.index('<section id="appendix"')]
    assert "<details" not in before and "<details open" not in app
    assert app.count("<details>") >= 2  # products, records
    assert "transform" in app and "transform" not in before  # the registration JSON is in the appendix only


def test_pdf_is_printed_by_chromium(report):
    if report[1] is None:
        pytest.skip("chromium is not installed (Debian: apt-get install -y chromium)")
    pdf = report[1]
    assert pdf.read_bytes()[:5] == b"%PDF-" and pdf.stat().st_size > 50_000
    assert sorted(p.name for p in pdf.parent.iterdir()) == ["report.html", "report.pdf"]  # no page left behind


def test_pdf_without_chromium_is_a_clear_error(work, tmp_path, monkeypatch, capsys):
    from workstation.cli.main import main

    monkeypatch.setenv("PATH", str(tmp_path))
    monkeypatch.delenv("WS_CHROMIUM", raising=False)
    assert main(["report", str(work[0]), "-o", str(tmp_path / "r.html"), "--pdf"]) != 0
    err = capsys.readouterr().err
    assert "chromium" in err.lower() and "apt-get install" in err
    assert not (tmp_path / "r.html").exists()  # refused before anything is written
    assert shutil.which("chromium") is None
