"""ws tile (streamed, named by lower-left corner, buffers) and ws merge of plain files (filters.merge)."""

from __future__ import annotations

import json

import numpy as np

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import read_cloud, write_cloud
from workstation.io.las import read_header
from workstation.ops import tile as tile_mod
from workstation.ops.tile import TileParams, tile_files, tile_memberships


def _cloud(rng, n, x0, y0, **attrs):
    xyz = np.round(np.column_stack([rng.uniform(x0, x0 + 250, n), rng.uniform(y0, y0 + 150, n), rng.uniform(0, 30, n)]), 2)
    return Cloud(xyz, {"intensity": rng.integers(0, 900, n), **attrs}, crs="EPSG:32632")


def test_memberships_with_buffer():
    xy = np.array([[5.0, 5.0], [99.0, 50.0], [99.0, 99.5], [0.5, 0.5]])
    got = {(int(i), int(a), int(b)) for idx, ix, iy in tile_memberships(xy, 100.0, 2.0) for i, a, b in zip(idx, ix, iy)}
    assert got == {(0, 0, 0), (1, 0, 0), (1, 1, 0), (2, 0, 0), (2, 1, 0), (2, 0, 1), (2, 1, 1),
                   (3, 0, 0), (3, -1, 0), (3, 0, -1), (3, -1, -1)}


def test_tiles_named_by_lower_left_streamed_and_buffered(tmp_path, rng, monkeypatch):
    a, b = _cloud(rng, 3000, 480010, 5450020), _cloud(rng, 2000, 480180, 5450100)
    write_cloud(a, tmp_path / "a.laz")
    write_cloud(b, tmp_path / "b.laz")
    out = tmp_path / "tiles"
    out.mkdir()
    monkeypatch.setattr(tile_mod, "MAX_OPEN", 3)  # several passes over the inputs
    counts = tile_files([tmp_path / "a.laz", tmp_path / "b.laz"], out, TileParams(100.0), chunk_size=700)
    assert sum(counts.values()) == 5000 and "480000_5450000.laz" in {p.name for p in out.iterdir()}
    for name, n in counts.items():
        t = read_cloud(out / f"{name}.laz")
        x0, y0 = (float(v) for v in name.split("_"))
        assert t.n == n and (t.xyz[:, 0] >= x0).all() and (t.xyz[:, 0] < x0 + 100).all() and (t.xyz[:, 1] >= y0).all()
    merged = np.concatenate([read_cloud(out / f"{k}.laz").xyz for k in counts])
    both = np.concatenate([a.xyz, b.xyz])
    assert np.abs(np.unique(merged, axis=0) - np.unique(both, axis=0)).max() < 1e-6
    buffered = tile_files([tmp_path / "a.laz"], tmp_path, TileParams(100.0, 5.0, ".las"))
    assert sum(buffered.values()) > 3000
    t = read_cloud(tmp_path / "480100_5450000.las")
    assert t.xyz[:, 0].min() >= 480095 and t.xyz[:, 0].max() <= 480205


def test_tile_cli_refuses_existing_tiles(tmp_path, rng, capsys):
    write_cloud(_cloud(rng, 500, 480010, 5450020), tmp_path / "a.laz")
    args = ["tile", str(tmp_path / "a.laz"), "-o", str(tmp_path / "t"), "--size", "100", "--json"]
    assert main([*args, "--pipeline-out", str(tmp_path / "t.json")]) == 0
    assert sum(json.loads(capsys.readouterr().out)["tiles"].values()) == 500
    splitter = json.loads((tmp_path / "t.json").read_text())[1]
    assert splitter == {"type": "filters.splitter", "length": 100.0, "origin_x": 0.0, "origin_y": 0.0, "buffer": 0.0}
    assert main(args) == 1 and "exists" in capsys.readouterr().err
    assert main([*args, "--overwrite"]) == 0


def test_merge_plain_files_of_different_formats_and_attributes(tmp_path, rng, capsys):
    a = _cloud(rng, 400, 480000, 5450000, gps_time=rng.uniform(0, 10, 400), point_source_id=np.full(400, 7))
    b = _cloud(rng, 300, 480100, 5450000, rgb=rng.integers(0, 65535, (300, 3)), point_source_id=np.full(300, 9))
    write_cloud(a, tmp_path / "a.las", point_format=1, scales=[0.01] * 3)
    write_cloud(b, tmp_path / "b.laz", point_format=2, scales=[0.001] * 3)
    out = tmp_path / "m.laz"
    assert main(["merge", str(tmp_path / "a.las"), str(tmp_path / "b.laz"), "-o", str(out), "--json",
                 "--pipeline-out", str(tmp_path / "m.json")]) == 0
    d = json.loads(capsys.readouterr().out)
    m, h = read_cloud(out), read_header(out)
    assert d["points_per_input"] == [400, 300] and m.n == 700
    assert h["point_format"] == 3 and h["scales"] == [0.001] * 3  # gps time + colour; the finest scale
    assert np.abs(m.xyz - np.concatenate([a.xyz, b.xyz])).max() < 1e-6
    assert (m.attrs["rgb"][:400] == 0).all() and np.array_equal(m.attrs["rgb"][400:], b.attrs["rgb"])
    assert np.unique(m.attrs["point_source_id"]).tolist() == [7, 9]  # kept, as PDAL's filters.merge does
    assert [s["type"] for s in json.loads((tmp_path / "m.json").read_text())] == [
        "readers.las", "readers.las", "filters.merge", "writers.las"]
    assert main(["merge", str(tmp_path / "a.las"), str(tmp_path / "b.laz"), "-o", str(tmp_path / "n.las"),
                 "--source-ids", "input"]) == 0
    assert np.unique(read_cloud(tmp_path / "n.las").attrs["point_source_id"]).tolist() == [1, 2]
