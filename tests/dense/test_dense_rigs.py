"""Photo rig layouts and rendering: geometry of ring / convergent / grid, deterministic images."""

from __future__ import annotations

import numpy as np

from workstation.photogrammetry.collinearity import project
from workstation.photogrammetry.rigs import RigSpec, box_wall_scene, render, rig_poses


def test_dense_rig_ring_and_convergent_look_at_target():
    centre = np.array([10.0, 20.0, 100.0])
    for layout in ("ring", "convergent"):
        spec = RigSpec(layout=layout, n_images=24, distance=50.0, camera_height=8.0, look_height=12.0)
        poses = rig_poses(spec, centre, np.array([30.0, 15.0, 40.0]))
        assert len(poses) == 24
        cam = spec.camera()
        uv = np.array([project(centre[None] + [0, 0, 12.0], cam, p)[0] for p in poses])
        assert np.allclose(uv, [cam.cx, cam.cy], atol=1e-6)  # the look-at point is the principal point
        az = np.degrees(np.arctan2(*(np.array([p.center for p in poses])[:, 1::-1] - centre[1::-1]).T))
        steps = np.diff(np.sort(az % 360))
        assert np.allclose(steps, 15.0, atol=1e-6)  # ring: 24 × 15°; convergent: 2 × 12 offset by 15°


def test_dense_rig_grid_overlap():
    spec = RigSpec(layout="grid", distance=100.0, width=400, height=300, focal_px=400.0,
                   forward_overlap=0.8, side_overlap=0.6)
    poses = rig_poses(spec, np.zeros(3), np.array([60.0, 40.0, 10.0]))
    C = np.array([p.center for p in poses])
    assert np.allclose(C[:, 2], 100.0)
    dx = np.diff(np.unique(C[:, 0].round(6)))
    dy = np.diff(np.unique(C[:, 1].round(6)))
    assert np.allclose(dx, (1 - 0.8) * 100.0), dx  # footprint 100 m along track
    assert np.allclose(dy, (1 - 0.6) * 75.0), dy  # 75 m across track
    assert all(np.allclose(p.R, np.diag([1.0, -1.0, -1.0])) for p in poses)  # nadir


def test_dense_rig_render_deterministic_and_textured():
    from workstation.core.products import Camera
    from workstation.photogrammetry.rigs import look_at

    V, F, alb = box_wall_scene()
    cam = Camera(64, 48, 60.0, 60.0, 31.5, 23.5)
    pose = look_at(np.array([0.0, 0.0, 0.0]), np.array([0.0, 10.0, 0.0]))
    a = render(V, F, alb, cam, pose, 2)
    b = render(V, F, alb, cam, pose, 2)
    assert a.shape == (48, 64, 3) and a.dtype == np.uint8 and np.array_equal(a, b)
    grey = a.mean(-1)
    assert grey.std() > 10  # texture, not a flat colour
