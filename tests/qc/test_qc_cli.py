"""`ws qc` end to end: a small synthetic delivery with known answers, the JSON the issue asks for,
the report folder, the verdict, refusals, and the report page in headless Chromium."""

from __future__ import annotations

import json
import re
import shutil
import subprocess

import numpy as np
import pytest

from workstation.cli.main import main

SHIFT = 0.08  # metres: swath 2 is this much higher than swath 1


def _swath(rng, x0, x1, y0, y1, spacing, sid, dz, t0):
    """First-and-only returns on a gently tilted plane, one per ``spacing`` metres, jittered."""
    xs, ys = np.meshgrid(np.arange(x0, x1, spacing), np.arange(y0, y1, spacing))
    x = xs.ravel() + rng.uniform(-0.2, 0.2, xs.size) * spacing
    y = ys.ravel() + rng.uniform(-0.2, 0.2, xs.size) * spacing
    z = 100.0 + 0.01 * x + 0.005 * y + rng.normal(0, 0.02, x.size) + dz
    n = x.size
    return {"xyz": np.c_[x, y, z], "psid": np.full(n, sid), "gps": t0 + np.arange(n) * 1e-4}


def _write(path, parts, crs="EPSG:32633", offset=(500000.0, 5000000.0)):
    import laspy

    xyz = np.vstack([p["xyz"] for p in parts]) + np.r_[offset, 0.0]
    n = len(xyz)
    h = laspy.LasHeader(point_format=6, version="1.4")
    h.offsets = np.floor(xyz.min(0))
    h.scales = np.array([0.001, 0.001, 0.001])
    h.add_crs(__import__("pyproj").CRS.from_user_input(crs))
    las = laspy.LasData(h)
    las.x, las.y, las.z = xyz.T
    las.return_number = np.ones(n, np.uint8)
    las.number_of_returns = np.ones(n, np.uint8)
    las.classification = np.full(n, 2, np.uint8)
    las.point_source_id = np.concatenate([p["psid"] for p in parts]).astype(np.uint16)
    las.gps_time = np.concatenate([p["gps"] for p in parts])
    las.write(str(path))


@pytest.fixture(scope="module")
def delivery(tmp_path_factory):
    """Two tiles side by side; two swaths overlapping over x 40-60 m (swath 2 raised by SHIFT);
    a 12 m × 12 m hole (a void) in tile a; checkpoints on the plane."""
    d = tmp_path_factory.mktemp("delivery")
    rng = np.random.default_rng(3)
    s1 = _swath(rng, 0, 60, 0, 100, 0.5, 1, 0.0, 1000.0)
    s2 = _swath(rng, 40, 100, 0, 100, 0.5, 2, SHIFT, 2000.0)
    hole = lambda s: (s["xyz"][:, 0] > 10) & (s["xyz"][:, 0] < 22) & (s["xyz"][:, 1] > 60) & (s["xyz"][:, 1] < 72)  # noqa: E731
    a = [{k: v[(s["xyz"][:, 1] < 50) | ~hole(s)] for k, v in s.items()} for s in (s1, s2)]
    _write(d / "a.las", [{k: v[p["xyz"][:, 0] < 50] for k, v in p.items()} for p in a])
    _write(d / "b.las", [{k: v[p["xyz"][:, 0] >= 50] for k, v in p.items()} for p in a])
    cx, cy = rng.uniform(5, 95, 40), rng.uniform(5, 45, 40)
    cz = 100.0 + 0.01 * cx + 0.005 * cy
    cover = np.where(np.arange(40) < 32, "open terrain", "forest")
    lines = ["id,x,y,z,cover"] + [f"cp{i},{x + 500000:.3f},{y + 5000000:.3f},{z:.3f},{c}"
                                  for i, (x, y, z, c) in enumerate(zip(cx, cy, cz, cover))]
    (d / "checkpoints.csv").write_text("\n".join(lines) + "\n")
    return d


@pytest.fixture(scope="module")
def report(delivery, tmp_path_factory):
    out = tmp_path_factory.mktemp("qc") / "report"
    import contextlib
    import io

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        rc = main(["qc", str(delivery / "a.las"), str(delivery / "b.las"), "-o", str(out), "--checkpoints",
                   str(delivery / "checkpoints.csv"), "--spec", "usgs-ql1", "--json"])
    assert rc == 0
    return out, json.loads(buf.getvalue())


def test_json_has_the_fields_the_issue_names_in_metres(report):
    _, doc = report
    for key in ("points", "anpd", "anps", "coverage", "voids", "swaths", "nva", "vva", "verdict", "findings"):
        assert key in doc, key
    assert doc["points"] > 30_000
    assert doc["anpd"] == pytest.approx(4.0, rel=0.05)  # one swath's density, not the doubled overlap
    assert doc["anps"] == pytest.approx(0.5, rel=0.05)
    assert doc["voids"] >= 1
    pair = doc["swaths"][0]
    assert {pair["a"], pair["b"]} == {1, 2}
    assert pair["rmsdz"] == pytest.approx(SHIFT, abs=0.01)
    assert abs(pair["mean_dz"]) == pytest.approx(SHIFT, abs=0.01)
    assert set(pair) >= {"a", "b", "rmsdz", "mean_dz", "max_abs_dz", "cells"}
    assert 0.0 < doc["nva"] < 0.15  # the checkpoints lie on the plane; swath 2 is 0.08 m high


def test_verdict_lists_each_criterion_and_fails_ql1_density(report):
    _, doc = report
    v = doc["verdict"]
    assert v["spec"] == "usgs-ql1"
    names = {c["name"]: c for c in v["criteria"]}
    anpd = next(c for n, c in names.items() if n.startswith("ANPD"))
    assert anpd["threshold"] == 8.0 and anpd["pass"] is False  # 4 pts/m² < QL1's 8
    assert v["pass"] is False
    assert all(set(c) >= {"name", "value", "threshold", "pass"} for c in v["criteria"])
    cov = next(c for n, c in names.items() if n.startswith("cells of 2×ANPS"))
    assert cov["value"] == pytest.approx(doc["coverage"]) and cov["pass"] is True
    rms = next(c for n, c in names.items() if n.startswith("interswath RMSDz"))
    assert rms["value"] == pytest.approx(SHIFT, abs=0.01) and rms["pass"] == (rms["value"] <= 0.08)


def test_report_folder_holds_the_page_the_document_and_the_maps(report):
    out, doc = report
    for name in ("report.html", "qc.json", "density.tif", "voids.tif", "dz.tif"):
        assert (out / name).exists(), name
    assert json.loads((out / "qc.json").read_text())["points"] == doc["points"]
    assert "FAIL" in (out / "report.html").read_text()


def test_refusals_exit_1_without_traceback(delivery, tmp_path, capsys):
    a = str(delivery / "a.las")
    assert main(["qc", a, "-o", str(tmp_path / "r1"), "--spec", "usgs-ql9"]) == 1
    assert "--spec" in capsys.readouterr().err
    txt = tmp_path / "pts.xyz"
    txt.write_text("0 0 0\n1 1 1\n")
    assert main(["qc", str(txt), "-o", str(tmp_path / "r2")]) == 1
    assert "LAS" in capsys.readouterr().err
    out = tmp_path / "r3"
    out.mkdir()
    assert main(["qc", a, "-o", str(out)]) == 1  # exists, no --overwrite
    err = capsys.readouterr().err
    assert "Traceback" not in err and "exists" in err


def test_mixed_crs_refused_naming_the_file(delivery, tmp_path, capsys):
    rng = np.random.default_rng(0)
    other = tmp_path / "other.las"
    _write(other, [_swath(rng, 0, 20, 0, 20, 1.0, 1, 0.0, 0.0)], crs="EPSG:32632")
    assert main(["qc", str(delivery / "a.las"), str(other), "-o", str(tmp_path / "r")]) == 1
    assert "other.las" in capsys.readouterr().err
    assert not (tmp_path / "r").exists()


def test_report_opens_in_headless_chromium_without_broken_images(report, tmp_path):
    exe = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if exe is None:
        pytest.skip("chromium is not installed (Debian: apt-get install -y chromium)")
    out, _ = report
    page = (out / "report.html").read_text()
    n_img = page.count("<img")
    assert n_img >= 4  # density, voids, DZ, residuals, classes
    probe = tmp_path / "probe.html"
    script = ("<script>window.onerror=()=>{document.title='JSERROR'};window.addEventListener('load',()=>{"
              "const im=[...document.images];if(document.title!=='JSERROR')document.title='IMAGES '+"
              "im.filter(i=>i.complete&&i.naturalWidth>0).length+'/'+im.length;});</script>")
    probe.write_text(page.replace("</body>", script + "</body>"))
    r = subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu", "--virtual-time-budget=10000",
                        "--dump-dom", probe.as_uri()], capture_output=True, text=True, timeout=120)
    m = re.search(r"<title>IMAGES (\d+)/(\d+)</title>", r.stdout)
    assert m, r.stdout[-500:] + r.stderr[-2000:]
    assert m.group(1) == m.group(2) == str(n_img)


def test_ws_run_qc_stage_checks_the_delivery_and_its_dtm_then_skips_on_rerun(delivery, tmp_path):
    for name in ("a.las", "b.las", "checkpoints.csv"):
        shutil.copy(delivery / name, tmp_path / name)
    (tmp_path / "project.toml").write_text(
        '[inputs]\nclouds = ["*.las"]\n[chunks]\nsize = 50.0\nbuffer = 10.0\n'
        '[stages.dem]\nkinds = ["dtm"]\nresolution = 1.0\n'
        '[stages.qc]\nspec = "usgs-ql2"\ncheckpoints = "checkpoints.csv"\n')
    out = tmp_path / "out"
    assert main(["run", str(tmp_path / "project.toml"), "--out", str(out), "--workers", "1"]) == 0
    doc = json.loads((out / "qc" / "qc.json").read_text())
    assert doc["points"] > 30_000 and doc["verdict"]["spec"] == "usgs-ql2"
    assert doc["swaths"][0]["rmsdz"] == pytest.approx(SHIFT, abs=0.01)
    assert doc["dem_accuracy"]["cell_m"] == pytest.approx(1.0)  # the run's DTM mosaic was checked
    assert (out / "qc" / "report.html").exists()
    run = json.loads((out / "run.json").read_text())
    assert run["tasks"]["qc/delivery"]["status"] == "done"
    stamp = (out / "qc" / "qc.json").stat().st_mtime_ns
    assert main(["run", str(tmp_path / "project.toml"), "--out", str(out), "--workers", "1"]) == 0
    assert (out / "qc" / "qc.json").stat().st_mtime_ns == stamp  # unchanged: skipped


@pytest.mark.realdata
def test_reserved_class_codes_are_one_finding(shared_data, tmp_path, capsys):
    """sample_c.las carries class 31 (reserved): qc.validate reports it once, with the file."""
    rc = main(["qc", str(shared_data / "lidar" / "sample_c.las"), "-o", str(tmp_path / "r"), "--json"])
    assert rc == 0
    doc = json.loads(capsys.readouterr().out)
    hits = [f for f in doc["findings"] if "reserved" in f["message"]]
    assert len(hits) == 1 and "class 31" in hits[0]["found"] and hits[0]["file"].endswith("sample_c.las")
