"""Good inputs for the fault corpus, made once with the package's own writers.

Every case copies them into its own folder and damages its copy; :func:`build` makes the
originals in ``folder``: a classified cloud in each point format, a DEM, a mesh, a camera, a
cameras JSON with two images, a project with two tiles.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

N = 3000  # points of the good cloud: small enough for every command to run in about a second


def good_cloud(seed: int = 7, x0: float = 500_000.0, y0: float = 4_000_000.0):
    """A 60 m x 60 m classified terrain with a few boxes on it (classes 1 and 2, intensities)."""
    from workstation.core.cloud import Cloud

    rng = np.random.default_rng(seed)
    xy = rng.uniform(0, 60, (N, 2))
    z = 100 + 0.05 * xy[:, 0] + 0.5 * np.sin(xy[:, 1] / 9)
    box = (np.abs(xy[:, 0] - 30) < 6) & (np.abs(xy[:, 1] - 30) < 6)
    z = np.where(box, z + 8, z)
    xyz = np.round(np.column_stack([xy[:, 0] + x0, xy[:, 1] + y0, z]), 3)
    return Cloud(xyz, {"classification": np.where(box, 1, 2).astype(np.uint8),
                       "intensity": rng.integers(0, 4000, N).astype(np.uint16),
                       "return_number": np.ones(N, np.uint8), "number_of_returns": np.ones(N, np.uint8)},
                 crs="EPSG:32632")


def _images_and_cameras(folder: Path) -> None:
    """``cameras.json`` with one camera and two 64x48 images in ``images/``."""
    import cv2

    from workstation.core.products import Camera, Image, Pose, Reconstruction
    from workstation.io.reconstruction import write_reconstruction_json

    (folder / "images").mkdir()
    cam = Camera(64, 48, 60.0, 60.0, 31.5, 23.5)
    R = np.diag([1.0, -1.0, -1.0])  # looking straight down
    images = {}
    for k in (1, 2):
        img = np.full((48, 64, 3), 40 * k, np.uint8)
        cv2.imwrite(str(folder / "images" / f"img_{k}.png"), img)
        centre = np.array([500_030.0 + 5 * k, 4_000_030.0, 200.0])
        images[k] = Image(f"img_{k}.png", 1, Pose(R, -R @ centre), f"images/img_{k}.png")
    write_reconstruction_json(Reconstruction({1: cam}, images, crs="EPSG:32632"), folder / "cameras.json")


def build(folder: Path) -> Path:
    """Write the good inputs into ``folder`` and return it."""
    from workstation.cli.main import main
    from workstation.core.products import Camera
    from workstation.io import write_cloud
    from workstation.io.camera import write_camera

    folder.mkdir(parents=True, exist_ok=True)
    cloud = good_cloud()
    for ext in ("laz", "las", "ply", "pcd", "xyz"):
        write_cloud(cloud, folder / f"cloud.{ext}")
    write_cloud(good_cloud(seed=8, x0=500_000.4), folder / "moved.laz")  # a second scan for register/merge
    assert main(["dem", str(folder / "cloud.laz"), "-o", str(folder / "dem.tif"), "--resolution", "1"]) == 0
    assert main(["mesh", str(folder / "cloud.laz"), "-o", str(folder / "mesh.ply"), "--method", "delaunay25d"]) == 0
    write_camera(Camera(640, 480, 500.0, 500.0, 319.5, 239.5), folder / "camera.json")
    _images_and_cameras(folder)
    (folder / "pairs.csv").write_text("\n".join(
        f"{x} {y} {z} {x + 0.4} {y} {z}" for x, y, z in cloud.xyz[:5]) + "\n")
    np.savetxt(folder / "matrix.txt", np.eye(4))
    (folder / "poses.json").write_text(json.dumps([np.eye(4).tolist()] * 2))
    (folder / "tiles").mkdir()
    write_cloud(cloud, folder / "tiles" / "a.laz")
    (folder / "project.toml").write_text('[inputs]\nclouds = ["tiles/*.laz"]\n[chunks]\nsize = 100\n'
                                         '[stages.dem]\nkinds = ["dsm"]\nresolution = 2.0\n')
    return folder
