import json
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from regutil import shape_points  # noqa: E402

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import read_cloud, write_cloud
from workstation.registration.transforms import apply_transform, make_transform, random_rotation, transform_error

OFF = np.array([500_000.0, 5_000_000.0, 100.0])


def _pair(tmp_path):
    rng = np.random.default_rng(21)
    T = make_transform(random_rotation(rng, 150.0), [0.4, -0.2, 0.1])
    tgt = Cloud(np.round(shape_points(6000, seed=21) + OFF, 4), {"intensity": np.full(6000, 9)}, crs="EPSG:32632")
    src_local = apply_transform(np.linalg.inv(T), shape_points(6000, seed=22))
    src = Cloud(np.round(src_local + OFF, 4), {"intensity": np.full(6000, 5)}, crs="EPSG:32632")
    o = np.eye(4)
    o[:3, 3] = OFF
    write_cloud(src, tmp_path / "src.laz")
    write_cloud(tgt, tmp_path / "tgt.laz")
    return o @ T @ np.linalg.inv(o), src


@pytest.mark.slow
def test_ws_register_json_and_matrix(tmp_path, capsys):
    T_true, src = _pair(tmp_path)
    rc = main(["register", str(tmp_path / "src.laz"), str(tmp_path / "tgt.laz"), "-o", str(tmp_path / "out.laz"),
               "--voxel-size", "0.03", "--matrix-out", str(tmp_path / "m.txt"), "--json"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert {"transform", "scale", "fitness", "inlier_rmse", "converged"} <= set(d)
    rot, tr = transform_error(np.array(d["transform"]), T_true, center=src.xyz.mean(axis=0))
    assert rot < 0.5 and tr < 0.01
    assert np.allclose(np.loadtxt(tmp_path / "m.txt"), np.array(d["transform"]))
    moved = read_cloud(tmp_path / "out.laz")
    assert moved.n == src.n and np.all(moved.attrs["intensity"] == 5)
    assert np.abs(moved.xyz - apply_transform(np.array(d["transform"]), src.xyz)).max() < 0.002
    # refusing to overwrite
    rc = main(["register", str(tmp_path / "src.laz"), str(tmp_path / "tgt.laz"), "-o", str(tmp_path / "out.laz")])
    assert rc == 1


def test_ws_register_from_point_pairs(tmp_path, capsys):
    T_true, src = _pair(tmp_path)
    picks = src.xyz[[10, 2000, 4000, 5500]]
    rows = np.hstack([picks, apply_transform(T_true, picks)])
    np.savetxt(tmp_path / "pairs.csv", rows, delimiter=",", header="sx,sy,sz,tx,ty,tz", fmt="%.4f")
    rc = main(["register", str(tmp_path / "src.laz"), str(tmp_path / "tgt.laz"), "-o", str(tmp_path / "o.laz"),
               "--pairs", str(tmp_path / "pairs.csv"), "--method", "pairs", "--json"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert d["pairs_rmse"] < 0.001 and len(d["pairs_residuals"]) == 4


def test_ws_merge_and_low_overlap_error(tmp_path, capsys):
    _pair(tmp_path)
    rc = main(["merge", str(tmp_path / "src.laz"), str(tmp_path / "tgt.laz"), "-o", str(tmp_path / "m.laz"), "--json"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    m = read_cloud(tmp_path / "m.laz")
    assert d["points"] == m.n == 12000
    assert sorted(np.unique(m.attrs["point_source_id"]).tolist()) == [1, 2]
    # two clouds that do not overlap: an error with a hint, exit code 1
    far = Cloud(shape_points(2000, seed=3) + OFF + [50.0, 0, 0], crs="EPSG:32632")
    write_cloud(far, tmp_path / "far.laz")
    rc = main(["register", str(tmp_path / "far.laz"), str(tmp_path / "tgt.laz"), "-o", str(tmp_path / "x.laz"),
               "--method", "icp", "--voxel-size", "0.03"])
    err = capsys.readouterr().err
    assert rc == 1 and "Hint" in err
    assert not (tmp_path / "x.laz").exists()


def test_ws_merge_with_poses_file_and_with_pose_graph(tmp_path, capsys):
    T_true, src = _pair(tmp_path)
    (tmp_path / "poses.json").write_text(json.dumps({"poses": [T_true.tolist(), np.eye(4).tolist()]}))
    rc = main(["merge", str(tmp_path / "src.laz"), str(tmp_path / "tgt.laz"), "-o", str(tmp_path / "m.laz"),
               "--poses", str(tmp_path / "poses.json"), "--duplicate-distance", "0.005"])
    assert rc == 0
    m = read_cloud(tmp_path / "m.laz")
    s1 = m.attrs["point_source_id"] == 1
    assert np.abs(m.xyz[s1] - apply_transform(T_true, src.xyz)).max() < 0.002
    assert m.n < 12000  # overlapping points of the second input were thinned
    capsys.readouterr()
    rc = main(["merge", str(tmp_path / "tgt.laz"), str(tmp_path / "src.laz"), "-o", str(tmp_path / "g.laz"),
               "--register", "--poses-out", str(tmp_path / "graph.json"), "--json"])
    assert rc == 0
    graph = json.loads((tmp_path / "graph.json").read_text())
    pose_src = np.array(graph["poses"][1])  # src -> tgt frame
    rot, tr = transform_error(pose_src, T_true, center=src.xyz.mean(axis=0))
    assert rot < 0.5 and tr < 0.01
    assert graph["edges"][0]["kind"] == "odometry"
