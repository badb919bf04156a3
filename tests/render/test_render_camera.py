"""`ws render --reconstruction WORKDIR --camera IMAGE`: a render through a COLMAP camera (its
intrinsics, pose and image size) overlays the projection of a known object."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.core.products import Camera, Image, Mesh, Reconstruction

O = np.array([500_000.0, 4_000_000.0, 100.0])  # map coordinates: float32 handling matters


def box(lo, hi):
    V = np.array([[x, y, z] for z in (lo[2], hi[2]) for y in (lo[1], hi[1]) for x in (lo[0], hi[0])], float)
    F = []
    for a, b, c, d in [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]:
        F += [[a, b, c], [a, c, d]]
    return V, np.asarray(F)


def hull_area(uv):
    from scipy.spatial import ConvexHull

    return float(ConvexHull(uv).volume)  # in 2-D, "volume" is the area


@pytest.fixture()
def workdir(tmp_path):
    """A COLMAP text model with two oblique images of one PINHOLE camera (fx != fy, off-centre
    principal point) looking at a 3 x 2 x 1.5 m box."""
    from workstation.io.mesh import write_mesh
    from workstation.photogrammetry.rigs import look_at, write_colmap_text

    V, F = box(O + [-1.5, -1.0, 0.0], O + [1.5, 1.0, 1.5])
    write_mesh(Mesh(V, F), tmp_path / "box.ply")
    cam = Camera(320, 240, 260.0, 250.0, 171.0, 109.0)
    images = {1: Image("left.jpg", 1, look_at(O + [-6.0, -7.0, 4.0], O + [0.2, 0.1, 0.6])),
              2: Image("right.jpg", 1, look_at(O + [7.0, -5.0, 2.5], O + [-0.3, 0.0, 0.9]))}
    rec = Reconstruction({1: cam}, images)
    write_colmap_text(rec, tmp_path / "work" / "sparse" / "0")
    return tmp_path, V, rec


@pytest.mark.parametrize("ref,iid", [("right.jpg", 2), ("1", 1)])
def test_render_camera_silhouette_matches_projection(workdir, capsys, ref, iid):
    from PIL import Image as PILImage

    from workstation.cli.main import main
    from workstation.photogrammetry.collinearity import project

    tmp, V, rec = workdir
    out = tmp / f"view_{iid}.png"
    rc = main(["render", str(tmp / "box.ply"), "-o", str(out), "--reconstruction", str(tmp / "work"),
               "--camera", ref, "--color", "uniform", "--background", "black", "--json"])
    assert rc == 0
    assert json.loads(capsys.readouterr().out)["size"] == [320, 240]
    img = np.asarray(PILImage.open(out).convert("RGB")).astype(float)
    assert img.shape == (240, 320, 3)
    im = rec.images[iid]
    uv = project(V, rec.cameras[1], im.pose)
    g = img.max(axis=2)
    # silhouette: pixels at least half as bright as their brightest neighbour (the box is
    # shaded, and multisampled edge pixels are partly covered: this keeps a pixel when about
    # half of it is covered, as the pixel-centre rule of the projection does)
    from matplotlib.path import Path
    from scipy.ndimage import maximum_filter
    from scipy.spatial import ConvexHull

    mask = (g > 0) & (g >= 0.5 * maximum_filter(g, 5))
    hull = uv[ConvexHull(uv).vertices]
    yy, xx = np.mgrid[0:240, 0:320]
    expected = Path(hull).contains_points(np.column_stack([xx.ravel(), yy.ravel()])).reshape(240, 320)
    area = hull_area(uv)
    assert mask.sum() == pytest.approx(area, rel=0.02)
    assert (mask ^ expected).sum() <= 0.03 * area  # only edge pixels differ
    ys, xs = np.nonzero(mask)
    assert xs.min() == pytest.approx(np.ceil(uv[:, 0].min()), abs=1)
    assert xs.max() == pytest.approx(np.floor(uv[:, 0].max()), abs=1)
    assert ys.min() == pytest.approx(np.ceil(uv[:, 1].min()), abs=1)
    assert ys.max() == pytest.approx(np.floor(uv[:, 1].max()), abs=1)

def test_render_camera_needs_both_options_and_a_known_image(workdir):
    from workstation.cli.main import main

    tmp, _, _ = workdir
    assert main(["render", str(tmp / "box.ply"), "-o", str(tmp / "a.png"), "--camera", "left.jpg"]) == 1
    assert main(["render", str(tmp / "box.ply"), "-o", str(tmp / "a.png"), "--reconstruction", str(tmp / "work"),
                 "--camera", "nope.jpg"]) == 1
    assert not (tmp / "a.png").exists()
