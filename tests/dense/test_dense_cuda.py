"""The CUDA path (COLMAP PatchMatch) up to the GPU call: device choice, options, workspace.

No test here runs PatchMatch (it needs a CUDA build of pycolmap and a GPU); they check what
the CUDA path hands to COLMAP and that asking for CUDA without it is a clear, early error.
"""

from __future__ import annotations

import pycolmap
import pytest

from workstation.core.errors import MissingDependencyError
from workstation.photogrammetry.dense import (
    DenseParams,
    patch_match_options,
    prepare_patch_match,
    resolve_device,
    undistort,
)
from workstation.photogrammetry.rigs import box_wall_rig

no_cuda = pytest.mark.skipif(pycolmap.has_cuda, reason="pycolmap has CUDA here")


def test_dense_resolve_device():
    assert resolve_device("cpu") == "cpu"
    assert resolve_device("auto") == ("cuda" if pycolmap.has_cuda else "cpu")


@no_cuda
def test_dense_cuda_without_cuda_is_a_clear_error():
    with pytest.raises(MissingDependencyError, match="CUDA") as e:
        resolve_device("cuda")
    assert "--device cpu" in str(e.value.hint)


@no_cuda
def test_sfm_dense_cuda_fails_before_sfm(tmp_path, capsys):
    from workstation.cli.main import main

    (tmp_path / "images").mkdir()
    wd = tmp_path / "wd"
    rc = main(["sfm", str(tmp_path / "images"), "-o", str(wd), "--dense", "--device", "cuda"])
    assert rc == 1
    assert "CUDA" in capsys.readouterr().err
    assert not wd.exists()  # nothing was started


def test_dense_patch_match_options_follow_params():
    opt = patch_match_options(DenseParams(max_image_size=800, window=9, depth_range=(2.0, 30.0)))
    assert opt.geom_consistency  # fusion reads *.geometric.bin on both paths
    assert opt.max_image_size == 800 and opt.window_radius == 4
    assert (opt.depth_min, opt.depth_max) == (2.0, 30.0)
    opt = patch_match_options(DenseParams())
    assert opt.depth_min < 0 and opt.depth_max < 0  # COLMAP's own ranges from the sparse points


def test_dense_prepare_patch_match_on_true_cameras(tmp_path):
    box_wall_rig(tmp_path, n=4, width=96, height=72, focal_px=90.0)
    d = undistort(tmp_path, tmp_path / "images")
    cfg = (d / "stereo" / "patch-match.cfg").read_text().split("\n")
    assert cfg[1] == "__auto__, 20"  # COLMAP's default selection, replaced below
    with pytest.raises(Exception, match="depth range"):
        prepare_patch_match(d, DenseParams())  # no sparse points and no depth range
    sources = prepare_patch_match(d, DenseParams(depth_range=(5.0, 20.0), num_sources=2, top_k=1))
    assert set(sources) == {1, 2, 3, 4} and all(1 <= len(s) <= 2 for s in sources.values())
    lines = [ln for ln in (d / "stereo" / "patch-match.cfg").read_text().splitlines() if ln]
    names = {p.name for p in (d / "images").iterdir()}
    assert len(lines) == 8 and all(lines[k] in names for k in range(0, 8, 2))
    for k in range(1, 8, 2):  # explicit source names, never the reference itself
        srcs = [s.strip() for s in lines[k].split(",")]
        assert set(srcs) <= names and lines[k - 1] not in srcs
    rec = pycolmap.Reconstruction(str(d / "sparse"))
    assert rec.num_points3D() == 8  # one overlap point per (image, source) pair, for fusion: 4 images, 2 sources
    assert prepare_patch_match(d, DenseParams(depth_range=(5.0, 20.0))) is None  # now it has points
