"""Radial distortion: images rendered through k1, k2 are undistorted before the plane sweep."""

from __future__ import annotations

import shutil
from dataclasses import replace

import pycolmap
import pytest

from workstation.core.products import Reconstruction
from workstation.photogrammetry.dense import DenseParams, evaluate, run_dense
from workstation.photogrammetry.rigs import (
    box_wall_rig,
    box_wall_scene,
    write_colmap_text,
)


@pytest.mark.slow
def test_dense_undistorts_radial_distortion(tmp_path):
    V, F, _ = box_wall_scene()
    rec = box_wall_rig(tmp_path, n=5, dist=(-0.15, 0.05, 0.0, 0.0, 0.0))  # ~6 px at the corners
    assert rec.cameras[1].model == "OPENCV"
    params = DenseParams(depth_range=(5.0, 20.0), device="cpu", num_sources=4)
    cloud, _ = run_dense(tmp_path, params=params)
    und = pycolmap.Reconstruction(str(tmp_path / "dense" / "sparse"))
    assert {str(c.model_name) for c in und.cameras.values()} == {"PINHOLE"}
    good = evaluate(cloud.xyz, V, F, 16.0, cloud.xyz[:10])["accuracy_median"]
    assert good < 0.05  # as without distortion (~0.04 m, half a pixel at 12 m)
    # the same images with the distortion ignored land farther from the surface
    shutil.rmtree(tmp_path / "sparse")
    pinhole = replace(rec.cameras[1], dist=(0.0,) * 5, model="PINHOLE")
    write_colmap_text(Reconstruction({1: pinhole}, rec.images), tmp_path / "sparse" / "0")
    cloud, _ = run_dense(tmp_path, params=params, overwrite=True)
    bad = evaluate(cloud.xyz, V, F, 16.0, cloud.xyz[:10])["accuracy_median"]
    assert bad > 1.5 * good
