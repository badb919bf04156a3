"""The README's chain on one work folder, without --images after `ws sfm`:
`ws sfm PHOTOS -o WORK`, `ws dense WORK`, `ws mesh WORK/dense/fused.ply --reconstruction WORK`,
`ws report WORK`; every step leaves its record and the report lists them in order."""

from __future__ import annotations

import json
import re
import shutil

import pytest

from workstation.cli.main import main


@pytest.mark.slow
def test_sfm_dense_mesh_report_without_images(tmp_path, capsys):
    from workstation.io.mesh import read_mesh
    from workstation.photogrammetry.rigs import box_wall_rig

    box_wall_rig(tmp_path / "rig", n=6, width=200, height=150, focal_px=190.0)
    photos = tmp_path / "photos"
    shutil.move(str(tmp_path / "rig" / "images"), photos)  # no WORK/images to fall back on
    work = tmp_path / "work"
    assert main(["sfm", str(photos), "-o", str(work)]) == 0
    capsys.readouterr()
    assert main(["dense", str(work), "--device", "cpu", "--max-image-size", "200", "--json"]) == 0
    dense = json.loads(capsys.readouterr().out)
    assert dense["points"] > 1000
    rec = json.loads((work / "dense" / "summary.json").read_text())
    assert rec["stage"] == "dense" and rec["inputs"]["image_dir"] == str(photos.absolute())
    assert rec["points"] == dense["points"] and rec["params"]["max_image_size"] == 200

    assert main(["mesh", str(work / "dense" / "fused.ply"), "-o", str(work / "facade.obj"), "--reconstruction", str(work),
                 "--depth", "6", "--no-quality"]) == 0
    rec = json.loads((work / "mesh_facade.json").read_text())
    assert rec["stage"] == "mesh" and rec["inputs"]["image_dir"] == str(photos.absolute())
    tex = next(s for s in rec["steps"] if s["name"] == "texture")
    assert tex["summary"]["faces_textured"] > 0
    assert "texture" in read_mesh(work / "facade.obj").meta

    capsys.readouterr()
    assert main(["report", str(work), "-o", str(tmp_path / "report.html"), "--render-size", "160x120"]) == 0
    page = (tmp_path / "report.html").read_text()
    steps = page[page.index("<h2>Steps</h2>"):]
    steps = steps[:steps.index("</table>")]
    rows = re.findall(r"<tr><td>([^<]*)</td><td>[^<]*</td><td>[^<]*</td><td>([^<]*)</td>", steps)
    assert rows == [("sfm", "summary.json"), ("dense", "dense/summary.json"), ("mesh", "mesh_facade.json")]
