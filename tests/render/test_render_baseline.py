"""Image baselines (after the numeric checks of test_render_numeric.py), with a tolerance.

Regenerate after an intended change with
``PYTHONPATH=. python tests/render/test_render_baseline.py --update`` and look at the images.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.products import Mesh
from workstation.render import RenderParams, render

BASELINES = Path(__file__).parent / "baselines"


def scene_cloud() -> Cloud:
    """An asymmetric scene: sloping ground, an L-shaped building, a tree-like blob."""
    rng = np.random.default_rng(7)
    n = 20000
    x, y = rng.uniform(0, 50, n), rng.uniform(0, 30, n)
    z = 0.05 * x + 0.02 * y
    cls = np.full(n, ASPRSClass.GROUND, np.uint8)
    bld = ((x > 30) & (x < 45) & (y > 15) & (y < 25)) | ((x > 30) & (x < 35) & (y > 5) & (y <= 15))
    z = np.where(bld, z + 8, z)
    cls[bld] = ASPRSClass.BUILDING
    tree = (x - 12) ** 2 + (y - 20) ** 2 < 16
    z = np.where(tree, z + 6 + rng.uniform(-1, 1, n), z)
    cls[tree] = ASPRSClass.HIGH_VEGETATION
    return Cloud(np.column_stack([x + 400_000, y + 5_000_000, z + 50]), {"classification": cls}, crs="EPSG:32633")


def scene_mesh() -> Mesh:
    import pymeshlab

    ms = pymeshlab.MeshSet()
    ms.create_torus(hradius=3, vradius=1)
    m = ms.current_mesh()
    v = m.vertex_matrix() * [1.0, 1.5, 1.0]  # squashed: asymmetric silhouette
    rgb = np.clip(np.column_stack([(v[:, 0] + 4) * 30, (v[:, 1] + 6) * 20, np.full(len(v), 128)]), 0, 255)
    return Mesh(v + [1000, 2000, 30], m.face_matrix(), {"rgb": rgb.astype(np.uint8)})


CASES = {
    "cloud_class_top": lambda: render(scene_cloud(), RenderParams(size=(240, 160), color="class", view="top")),
    "cloud_elevation_iso": lambda: render(scene_cloud(), RenderParams(size=(240, 160), color="elevation", view="iso")),
    "mesh_rgb_iso": lambda: render(scene_mesh(), RenderParams(size=(200, 150), view="iso")),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_matches_baseline(name):
    from PIL import Image

    path = BASELINES / f"{name}.png"
    assert path.exists(), f"missing baseline {path}; run this file with --update"
    ref = np.asarray(Image.open(path).convert("RGB")).astype(int)
    img = CASES[name]().astype(int)
    assert img.shape == ref.shape
    diff = np.abs(img - ref).max(axis=2)
    # tolerant to driver rounding (llvmpipe vs GPU), not to a moved or recoloured object
    assert diff.mean() < 3.0
    assert (diff > 60).mean() < 0.01


if __name__ == "__main__" and "--update" in sys.argv:
    from workstation.render import save_png

    for k, fn in CASES.items():
        save_png(fn(), BASELINES / f"{k}.png", overwrite=True)
        print(k, (BASELINES / f"{k}.png").stat().st_size, "bytes")
