"""Dense stereo: COLMAP array format, plane sweep on a known scene, fusion near the surface."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.products import Camera, Image, Reconstruction
from workstation.photogrammetry.dense import DenseParams, read_array, write_array
from workstation.photogrammetry.rigs import (
    box_wall_scene,
    look_at,
    render,
    write_colmap_text,
)


def test_dense_array_roundtrip_and_layout(tmp_path):
    rng = np.random.default_rng(0)
    d = rng.random((5, 7)).astype(np.float32)
    n = rng.random((5, 7, 3)).astype(np.float32)
    write_array(d, tmp_path / "d.bin")
    write_array(n, tmp_path / "n.bin")
    assert np.array_equal(read_array(tmp_path / "d.bin"), d)
    assert np.array_equal(read_array(tmp_path / "n.bin"), n)
    raw = (tmp_path / "n.bin").read_bytes()
    assert raw.startswith(b"7&5&3&")
    # COLMAP: column-major (width, height, channels): x fastest, then y, then channel planes
    data = np.frombuffer(raw[len(b"7&5&3&"):], "<f4")
    assert data.size == 105
    assert data[1] == n[0, 1, 0] and data[7] == n[1, 0, 0] and data[35] == n[0, 0, 1]


def _box_scene():
    return box_wall_scene()


def _rig(n=4, w=160, h=120, f=150.0):
    cam = Camera(w, h, f, f, (w - 1) / 2, (h - 1) / 2)
    poses = [look_at(np.array([x, 0.0, 0.5 * (k % 2)]), np.array([0.0, 10.0, 0.0])) for k, x in enumerate(np.linspace(-2.5, 2.5, n))]
    return cam, poses


def _true_depth(V, F, cam, pose):
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.photogrammetry.collinearity import camera_rays

    rays = camera_rays(cam, 1).reshape(-1, 3)
    t, _ = RaycastScene(V, F).cast(np.broadcast_to(pose.center, rays.shape), rays @ pose.R)
    return (t * rays[:, 2]).reshape(cam.height, cam.width)


def test_dense_plane_sweep_recovers_box_and_wall():
    from workstation.photogrammetry.dense import _View, plane_sweep

    V, F, alb = _box_scene()
    cam, poses = _rig(3)
    imgs = [render(V, F, alb, cam, p, 2).astype(np.float32).mean(-1) for p in poses]
    K = np.array([[cam.fx, 0, cam.cx], [0, cam.fy, cam.cy], [0, 0, 1.0]])
    views = [_View(f"{i}", K, np.asarray(p.R), np.asarray(p.t), cam.width, cam.height, 5.0, 20.0) for i, p in enumerate(poses)]
    depth, _score = plane_sweep(imgs[1], views[1], [imgs[0], imgs[2]], [views[0], views[2]], DenseParams(top_k=1, num_sources=2))
    z = _true_depth(V, F, cam, poses[1])
    ok = (depth > 0) & np.isfinite(z)
    assert ok.mean() > 0.5
    rel = np.abs(depth[ok] - z[ok]) / z[ok]
    assert np.median(rel) < 0.01
    assert np.mean(rel < 0.03) > 0.85
    # the box (near) and the wall (far) are both recovered
    near = ok & (z < 9.5)
    assert near.sum() > 200 and np.median(np.abs(depth[near] - z[near]) / z[near]) < 0.01


def test_dense_fusion_points_near_surface(tmp_path):
    import cv2

    from workstation.photogrammetry.dense import evaluate, run_dense

    V, F, alb = _box_scene()
    cam, poses = _rig(5)
    (tmp_path / "images").mkdir()
    images = {}
    for k, p in enumerate(poses, start=1):
        cv2.imwrite(str(tmp_path / "images" / f"im{k}.png"), render(V, F, alb, cam, p, 2)[:, :, ::-1])
        images[k] = Image(f"im{k}.png", 1, p)
    write_colmap_text(Reconstruction({1: cam}, images), tmp_path / "sparse" / "0")
    cloud, _summary = run_dense(tmp_path, params=DenseParams(depth_range=(5.0, 20.0), device="cpu", num_sources=4))
    assert (tmp_path / "dense" / "fused.ply").exists()
    assert cloud.n > 500 and "rgb" in cloud.attrs and "normal" in cloud.attrs
    ev = evaluate(cloud.xyz, V, F, 16.0, cloud.xyz[:10])
    # one pixel covers ~8 cm on the wall at 160 x 120 px: accept half a pixel
    assert ev["accuracy_median"] < 0.04
    wall = cloud.xyz[:, 1] > 11.8
    assert wall.sum() > 100 and np.median(np.abs(np.asarray(cloud.attrs["normal"])[wall, 1])) > 0.9
    from workstation.core.errors import OutputExistsError

    with pytest.raises(OutputExistsError):
        run_dense(tmp_path, params=DenseParams(depth_range=(5.0, 20.0)))  # dense/ exists, no overwrite


def test_dense_cli_writes_fused_and_output(tmp_path, capsys):
    import json

    import cv2

    from workstation.cli.main import main
    from workstation.io import read_cloud

    V, F, alb = _box_scene()
    cam, poses = _rig(4, 128, 96, 120.0)
    (tmp_path / "images").mkdir()
    images = {}
    for k, p in enumerate(poses, start=1):
        cv2.imwrite(str(tmp_path / "images" / f"im{k}.png"), render(V, F, alb, cam, p, 2)[:, :, ::-1])
        images[k] = Image(f"im{k}.png", 1, p)
    write_colmap_text(Reconstruction({1: cam}, images), tmp_path / "sparse" / "0")
    out = tmp_path / "dense.ply"
    rc = main(["dense", str(tmp_path), "--device", "cpu", "--depth-range", "5", "20", "--sources", "3", "--fusion-cache-gb", "0.5", "-o", str(out), "--json"])
    assert rc in (0, None)
    summary = json.loads(capsys.readouterr().out)
    assert summary["device"] == "cpu" and summary["points"] > 100
    c = read_cloud(out)
    assert c.n == summary["points"]
    between = (c.xyz[:, 1] > 7.5) & (c.xyz[:, 1] < 12.5)  # between the box front and the wall
    assert between.mean() > 0.98
    import pycolmap

    if not pycolmap.has_cuda:  # --device cuda without a CUDA build is a clear user error
        rc = main(["dense", str(tmp_path), "--device", "cuda", "--overwrite", "--depth-range", "5", "20"])
        assert rc == 1 and "CUDA" in capsys.readouterr().err
