"""The QC stage of ``ws run`` in parts (a task per file, per block of swath fits, one merge)
gives the report of one ``ws qc`` over the same files: every figure of qc.json and every map.

Fields that may differ, and why: ``seconds`` (time); sums of floating values that one pass adds
in another order (swath RMSDz and mean DZ where a cell's points come from two files, areas
summed file by file), compared to 1e-9 relative.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from pipeline_synth import CRS, X0, Y0, tile_points

REL = 1e-9


def swath_tiles(folder: Path, cells=((0, 0), (0, 1), (1, 0), (1, 1)), density: float = 5.0) -> list[Path]:
    """The synthetic survey tiles with two overlapping swaths (ids 1 and 2, swath 2 three cm
    higher where they overlap), ground and building classes, a little noise and a hole."""
    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud

    folder.mkdir(parents=True, exist_ok=True)
    out = []
    for ix, iy in cells:
        xyz, ground = tile_points(ix, iy, density)
        rng = np.random.default_rng([ix, iy, 3])
        lx = xyz[:, 0] - X0
        sid = np.where(lx < 60, 1, np.where(lx >= 120, 2, rng.integers(1, 3, len(xyz)))).astype(np.uint16)
        xyz[:, 2] += np.where(sid == 2, 0.03, 0.0)
        cls = np.where(ground, 2, 6).astype(np.uint8)
        cls[rng.random(len(xyz)) < 0.001] = 7
        keep = np.hypot(lx - 45, xyz[:, 1] - Y0 - 100) >= 6  # a void across the chunk edge y = +100
        n = int(keep.sum())
        cloud = Cloud(xyz[keep], {"classification": cls[keep], "return_number": np.ones(n, np.uint8),
                                  "number_of_returns": np.ones(n, np.uint8), "point_source_id": sid[keep]}, crs=CRS)
        write_cloud(cloud, folder / f"t_{ix}_{iy}.laz", overwrite=True)
        out.append(folder / f"t_{ix}_{iy}.laz")
    return out


def differences(a, b, path: str = "", rel: float = REL) -> list[str]:
    """Where two JSON documents differ: numbers beyond ``rel`` relative, anything else unequal."""
    if isinstance(a, dict) and isinstance(b, dict):
        out = [f"{path}/{k}: only in one" for k in sorted(set(a) ^ set(b))]
        return out + [d for k in sorted(set(a) & set(b)) for d in differences(a[k], b[k], f"{path}/{k}", rel)]
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: {len(a)} != {len(b)} items"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{path}[{i}]", rel)]
    if isinstance(a, float) and isinstance(b, float):
        same = a == b or (math.isnan(a) and math.isnan(b)) or abs(a - b) <= rel * max(abs(a), abs(b))
        return [] if same else [f"{path}: {a!r} != {b!r}"]
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]


def assert_same_report(parts: Path, whole: Path) -> dict:
    """qc.json equal but for ``seconds``; the maps equal cell for cell."""
    import rasterio

    a, b = json.loads((parts / "qc.json").read_text()), json.loads((whole / "qc.json").read_text())
    a.pop("seconds"), b.pop("seconds")
    assert differences(a, b) == []
    assert a["maps"] == b["maps"]
    for name in a["maps"].values():
        if name.endswith(".tif"):
            with rasterio.open(parts / name) as x, rasterio.open(whole / name) as y:
                assert x.transform == y.transform
                np.testing.assert_allclose(x.read(), y.read(), rtol=REL, equal_nan=True)
    return a


@pytest.fixture(scope="module")
def survey(tmp_path_factory):
    folder = tmp_path_factory.mktemp("qcsurvey")
    return folder, swath_tiles(folder / "tiles")


def test_parts_equal_ws_qc_on_input_tiles(survey, tmp_path):
    """Tiles checked one by one, fits in 40 m blocks (cells owned across tile and block edges)."""
    from workstation.qc.partial import qc_in_parts
    from workstation.qc.run import QCParams, write_qc

    from pipeline_synth import terrain

    _, tiles = survey
    cp = tmp_path / "cp.csv"  # checkpoints on tile edges (x = +90, y = +90) and inside tiles
    xy = [(X0 + 90.0, Y0 + 30.0), (X0 + 50.0, Y0 + 90.0), (X0 + 90.0, Y0 + 90.0), (X0 + 140.0, Y0 + 150.0),
          (X0 + 5.0, Y0 + 170.0)]
    cp.write_text("id,x,y,z,cover\n" + "".join(f"c{i},{x},{y},{float(terrain(x, y)) + 0.01 * i:.3f},bare\n"
                                              for i, (x, y) in enumerate(xy)))
    params = QCParams(chunk_size=50_000, checkpoints=cp)
    qc_in_parts(tiles, tmp_path / "parts", params, tmp_path / "work", block_size=40.0)
    write_qc(tiles, tmp_path / "whole", params)
    doc = assert_same_report(tmp_path / "parts", tmp_path / "whole")
    # the survey exercises every check: two swaths overlap, one void, classes and noise
    assert doc["swaths"][0]["cells"] > 1000 and abs(doc["swaths"][0]["mean_dz"] - 0.03) < 0.005
    assert doc["voids"] == 1 and doc["classes"]["histogram"]["7"] > 0
    assert doc["nva"] is not None and len(doc["accuracy"]["checkpoints"]) == len(xy)
    assert len(list((tmp_path / "work" / "fits").glob("fit_*.npz"))) > len(tiles)


def test_block_smaller_than_the_swath_window_is_refused(survey, tmp_path):
    from workstation.core.errors import StageError
    from workstation.qc.partial import qc_in_parts
    from workstation.qc.run import QCParams

    with pytest.raises(StageError, match="does not fit in a block"):
        qc_in_parts(survey[1][:1], tmp_path / "parts", QCParams(), tmp_path / "work", block_size=2.0)


def test_every_cell_has_exactly_one_owner():
    """Cells straddling block edges, and cells whose centre lies in a block not in the set."""
    from workstation.core.units import METRES
    from workstation.qc.context import QCGrid
    from workstation.qc.partial import _block_key, cell_owner

    grid = QCGrid.over((3.0, 5.0, 157.0, 121.0), 1.7, METRES)
    blocks = np.array([(0, 0), (1, 0), (0, 1), (1, 1), (2, 0)], np.int64)  # (2, 1) is missing
    blocks = blocks[np.argsort(_block_key(blocks[:, 0], blocks[:, 1]))]
    rows, cols = np.divmod(np.arange(grid.rows * grid.cols), grid.cols)
    owner = cell_owner(rows, cols, grid, 60.0, blocks)
    cx, cy = grid.x0 + (cols + 0.5) * grid.cell, grid.y1 - (rows + 0.5) * grid.cell
    home = _block_key(np.floor(cx / 60).astype(np.int64), np.floor(cy / 60).astype(np.int64))
    keys = _block_key(blocks[:, 0], blocks[:, 1])
    listed = np.isin(home, keys)
    assert np.array_equal(keys[owner[listed]], home[listed])  # the centre's block when it is one
    corners = np.stack([_block_key(np.floor((cx + dx * grid.cell) / 60).astype(np.int64),
                                   np.floor((cy + dy * grid.cell) / 60).astype(np.int64))
                        for dx in (-0.5, 0.5) for dy in (-0.5, 0.5)])
    reach = np.isin(corners, keys)  # the listed blocks each unlisted cell touches
    assert ((owner[~listed] >= 0) == reach[:, ~listed].any(axis=0)).all()
    got = keys[owner[~listed & (owner >= 0)]]
    assert (corners[:, ~listed & (owner >= 0)] == got).any(axis=0).all()  # one it touches
    assert (~listed & (owner >= 0)).any() and (~listed & (owner < 0)).any()


def _project(folder: Path, name: str, stages: str) -> Path:
    p = folder / name
    p.write_text(f'[inputs]\nclouds = ["tiles/*.laz"]\n\n[chunks]\nsize = 100.0\nbuffer = 30.0\n\n{stages}'
                 '[stages.qc]\nspec = "usgs-ql2"\n')
    return p


def test_ws_run_qc_per_chunk_equals_ws_qc_of_its_point_outputs(survey, tmp_path):
    """Point stages (noise) on 100 m chunks across 90 m tiles, then QC per chunk output; a
    second run with nothing changed runs no QC task."""
    from workstation.pipeline.runner import RunOptions, run_project
    from workstation.qc.partial import read_json
    from workstation.qc.run import QCParams, write_qc

    folder, _ = survey
    project = _project(folder, "points.toml", "[stages.noise]\n\n")
    out = tmp_path / "out"
    r = run_project(project, RunOptions(out=out, workers=2))
    assert r.complete, r.failures
    cat = read_json(out / ".ws-cache" / "qc" / "catalog.json")
    assert [Path(f).parent.name for f in cat["files"]] == ["noise"] * 4
    write_qc(cat["files"], tmp_path / "whole", QCParams())
    assert_same_report(out / "qc", tmp_path / "whole")
    tasks = json.loads((out / "run.json").read_text())["tasks"]
    assert sum(k.startswith("qc/fit/") for k in tasks) == 4 and tasks["qc/delivery"]["status"] == "done"
    again = run_project(project, RunOptions(out=out, workers=1))
    assert again.summary["phases"]["qc"]["run"] == 0
