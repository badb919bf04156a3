"""Every command ends with one summary line on stderr (``COMMAND: WHAT -> OUT (...) in S s``),
also when stderr is not a terminal; ``-q`` silences it; the --json document on stdout is
unchanged. Covered here on a tiny input: convert, ground, dem, hillshade, contours, mesh,
evaluate, merge, render, report, calibrate. (classify, simulate, train, sfm, dense, ortho,
colorize, register use the same helper, workstation.cli.summary.emit_summary.)"""

from __future__ import annotations

import contextlib
import io
import json
import re

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.cli.summary import count, summary_line

LINE = re.compile(r"^(?P<cmd>[a-z ]+): (?P<what>.+?)( -> (?P<out>.+?))?( \((?P<details>.*)\))? in [0-9.]+ s$")


def _run(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Run the chain once on a 3000-point cloud; {name: (rc, stdout, stderr)}."""
    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud
    from workstation.photogrammetry.synthetic import dlt_case

    d = tmp_path_factory.mktemp("summary")
    rng = np.random.default_rng(0)
    n = 3000
    x, y = rng.uniform(0, 30, n), rng.uniform(0, 30, n)
    z = 100 + 0.05 * x + 0.5 * np.sin(y / 6)
    box = (x > 10) & (x < 15) & (y > 10) & (y < 15)
    z = np.where(box, z + 6, z)
    cls = np.where(box, 6, 2).astype(np.uint8)
    write_cloud(Cloud(np.column_stack([x + 500000, y + 5000000, z]), {"classification": cls}, crs="EPSG:32633"),
                d / "in.laz")
    _, _, X, uv, _ = dlt_case(np.random.default_rng(4), 0.1, 20)
    (d / "points.csv").write_text("name,X,Y,Z,u,v\n" + "\n".join(
        f"P{i},{a[0]},{a[1]},{a[2]},{b[0]},{b[1]}" for i, (a, b) in enumerate(zip(X, uv))) + "\n")
    cmds = {
        "convert": ["convert", d / "in.laz", d / "in.ply"],
        "ground": ["ground", d / "in.laz", "-o", d / "ground.laz", "--reclassify"],
        "ground_json": ["ground", d / "in.laz", "-o", d / "ground2.laz", "--json"],
        "ground_quiet": ["-q", "ground", d / "in.laz", "-o", d / "ground3.laz"],
        "dem": ["dem", d / "ground.laz", "-o", d / "dtm.tif", "--resolution", "1"],
        "hillshade": ["hillshade", d / "dtm.tif", "-o", d / "hs.tif", "--png", d / "hs.png"],
        "contours": ["contours", d / "dtm.tif", "-o", d / "c.geojson", "--interval", "0.5"],
        "mesh": ["mesh", d / "ground.laz", "-o", d / "mesh.ply", "--method", "delaunay25d", "--no-quality"],
        "evaluate": ["evaluate", d / "ground.laz", "--reference", d / "in.laz"],
        "merge": ["merge", d / "in.laz", d / "ground.laz", "-o", d / "merged.laz"],
        "render": ["render", d / "ground.laz", "-o", d / "r.png", "--size", "160x120"],
        "calibrate": ["calibrate", "dlt", d / "points.csv", "--image-size", "4000x3000", "-o", d / "camera.json"],
        "report": ["report", d, "-o", d / "report.html", "--render-size", "160x120"],
    }
    return {name: _run(*args) for name, args in cmds.items()}


@pytest.mark.parametrize("name, what, output", [
    ("convert", "3,000 points", "in.ply"),
    ("ground", "3,000 points", "ground.laz"),
    ("dem", "dtm 30 x 30 cells", "dtm.tif"),
    ("hillshade", "hillshade 30 x 30 cells", "hs.png"),
    ("contours", "lines", "c.geojson"),
    ("mesh", "faces", "mesh.ply"),
    ("evaluate", "3,000 points compared", None),
    ("merge", "6,000 points from 2 clouds", "merged.laz"),
    ("render", "1 image", "r.png"),
    ("calibrate", "camera fx", "camera.json"),
    ("report", "work folder", "report.html"),
])
def test_every_command_ends_with_one_summary_line(runs, name, what, output):
    rc, _, err = runs[name]
    assert rc == 0, err
    lines = [ln for ln in err.splitlines() if LINE.match(ln) and ln.startswith(name)]
    assert len(lines) == 1, err
    m = LINE.match(lines[0])
    assert what in m["what"], lines[0]
    if output:
        assert output in (m["out"] or ""), lines[0]
    assert err.splitlines()[-1] == lines[0]  # the last thing on stderr


def test_ground_summary_has_the_ground_share(runs):
    line = runs["ground"][2].splitlines()[-1]
    assert re.match(r"ground: 3,000 points -> .*ground\.laz \(ground \d+\.\d %; smrf\) in \d+\.\d+ s$", line), line


def test_json_stays_alone_on_stdout_and_quiet_silences(runs):
    rc, out, err = runs["ground_json"]
    assert rc == 0 and json.loads(out)["point_count"] == 3000
    assert err.startswith("ground: 3,000 points")
    rc, out, err = runs["ground_quiet"]
    assert rc == 0 and out == "" and err == ""


def test_summary_line_format():
    assert count(1, "points") == "1 point" and count(1234567, "points") == "1,234,567 points"
    assert summary_line("ground", "1,234,567 points", "out.laz", 12.34, "ground 41.2 %") == \
        "ground: 1,234,567 points -> out.laz (ground 41.2 %) in 12.3 s"
    assert summary_line("x", "y", ["a", None, "b"], 0.5, ["", "k"]) == "x: y -> a, b (k) in 0.50 s"
