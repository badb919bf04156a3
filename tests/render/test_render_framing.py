"""Default render views frame an upright model from a human viewpoint (issue 24)."""

from __future__ import annotations

import importlib
import math

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.render import RenderParams, render

rmod = importlib.import_module("workstation.render.render")

O = np.array([500_000.0, 4_000_000.0, 100.0])
W, H = 240, 180
COLOURS = {"south": (220, 0, 0), "east": (0, 0, 220), "west": (0, 200, 0), "north": (230, 230, 0),
           "roof": (90, 90, 90), "ground": (150, 100, 40)}


def building_cloud(long_axis: str = "x", strays: int = 40, seed: int = 0) -> Cloud:
    """A 24 m × 8 m × 10 m building (flat roof) on a 44 m × 28 m ground patch, one colour per
    face, z up, plus far floating outliers (as dense matching leaves them)."""
    rng = np.random.default_rng(seed)
    L, D, Hb = 24.0, 8.0, 10.0
    n = 6000

    def face(name, pts):
        return pts, np.tile(COLOURS[name], (len(pts), 1))

    u = lambda a, b, k: rng.uniform(a, b, k)  # noqa: E731
    parts = [
        face("south", np.column_stack([u(-L / 2, L / 2, n), np.full(n, -D / 2), u(0, Hb, n)])),
        face("north", np.column_stack([u(-L / 2, L / 2, n), np.full(n, D / 2), u(0, Hb, n)])),
        face("east", np.column_stack([np.full(n // 3, L / 2), u(-D / 2, D / 2, n // 3), u(0, Hb, n // 3)])),
        face("west", np.column_stack([np.full(n // 3, -L / 2), u(-D / 2, D / 2, n // 3), u(0, Hb, n // 3)])),
        face("roof", np.column_stack([u(-L / 2, L / 2, n), u(-D / 2, D / 2, n), np.full(n, Hb)])),
    ]
    g = np.column_stack([u(-22, 22, 3 * n), u(-14, 14, 3 * n), np.zeros(3 * n)])
    g = g[(np.abs(g[:, 0]) > L / 2) | (np.abs(g[:, 1]) > D / 2)]
    parts.append(face("ground", g))
    xyz = np.vstack([p for p, _ in parts])
    rgb = np.vstack([c for _, c in parts]).astype(np.uint16) * 257
    if strays:  # floating outliers 100-300 m away, in every direction
        d = rng.normal(size=(strays, 3))
        xyz = np.vstack([xyz, d / np.linalg.norm(d, axis=1, keepdims=True) * rng.uniform(100, 300, (strays, 1))])
        rgb = np.vstack([rgb, np.full((strays, 3), 0, np.uint16)])
    if long_axis == "y":  # the same building turned 90° (long side facing east)
        xyz = xyz @ np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1.0]]).T
    return Cloud(O + xyz, {"rgb": rgb})


def colour_mask(img, name, tol=40):
    return np.abs(img.astype(int) - COLOURS[name]).max(axis=2) < tol


def occupied(img):
    return np.any(img < 245, axis=2)


def test_default_view_fills_the_frame_sky_above_ground_below():
    img = render(building_cloud(), RenderParams(size=(W, H), legend=False))
    occ = occupied(img)
    ys, xs = np.nonzero(occ)
    # the model fills the frame in spite of the strays 100-300 m away
    assert (xs.max() - xs.min() + 1) >= 0.6 * W or (ys.max() - ys.min() + 1) >= 0.6 * H
    # sky above (top rows empty), model bottom in the lower half
    assert not occ[: int(0.04 * H)].any()
    assert ys.max() > H / 2
    # seen from above, up is up: the roof is drawn above the ground around the building
    roof, ground = colour_mask(img, "roof"), colour_mask(img, "ground")
    assert roof.sum() > 100 and ground.sum() > 100
    assert np.nonzero(roof)[0].mean() < np.nonzero(ground)[0].mean()
    # bottom of the frame: ground in front of the building, not the roof
    low = np.nonzero(occ)[0] > np.percentile(ys, 90)
    assert colour_mask(img, "ground")[ys[low], xs[low]].mean() > 0.5


def test_without_stray_removal_the_model_is_a_small_blob():
    """The check above fails when every point is framed (what the strays did before)."""
    img = render(building_cloud(), RenderParams(size=(W, H), legend=False, stray_share=0.0))
    ys, xs = np.nonzero(colour_mask(img, "ground") | colour_mask(img, "roof") | colour_mask(img, "south"))
    assert ys.size > 0
    assert (xs.max() - xs.min() + 1) < 0.3 * W and (ys.max() - ys.min() + 1) < 0.3 * H


@pytest.mark.parametrize("long_axis, front, side, hidden", [("x", "south", "east", ("north", "west")),
                                                             ("y", "east", "south", ("west", "north"))])
def test_iso_view_faces_the_longest_wall(long_axis, front, side, hidden):
    """The long wall faces the camera (30° off its normal), the short one shows at an angle,
    the far walls are hidden. Turning the building turns the view with it (``names`` maps the
    side of the turned building to the colour of the wall now there)."""
    names = {"x": {"south": "south", "east": "east", "north": "north", "west": "west"},
             "y": {"east": "south", "north": "east", "west": "north", "south": "west"}}[long_axis]
    img = render(building_cloud(long_axis, strays=0), RenderParams(size=(W, H), legend=False))
    count = {k: int(colour_mask(img, names[k]).sum()) for k in (front, side) + hidden}
    assert count[front] > 2 * count[side] > 0
    assert all(count[h] < 0.05 * count[front] for h in hidden)  # roof-edge points and gaps only


def test_iso_direction_is_30_degrees_up_and_off_the_long_face():
    d = rmod.iso_direction(np.zeros(3), np.array([30.0, 10.0, 5.0]))
    assert math.degrees(math.asin(d[2])) == pytest.approx(30.0)
    assert math.degrees(math.atan2(d[1], d[0])) == pytest.approx(-60.0)  # south, turned 30° east
    d = rmod.iso_direction(np.zeros(3), np.array([10.0, 30.0, 5.0]))
    assert math.degrees(math.atan2(d[1], d[0])) == pytest.approx(-30.0)  # east, turned 30° south


def test_framing_bounds_keep_spires_and_drop_strays():
    rng = np.random.default_rng(1)
    body = rng.uniform([0, 0, 0], [20, 10, 10], (20000, 3))
    # a thin spire on the roof: 0.3 % of the points, sampled about as densely as the body
    spire = np.column_stack([rng.normal(10, 0.05, 60), rng.normal(5, 0.05, 60), np.linspace(10, 30, 60)])
    strays = np.array([[10, 5, 400.0], [-250, 5, 5], [10, 180, 5]])
    lo, hi = rmod.framing_bounds(np.vstack([body, spire, strays]))
    assert hi[2] == pytest.approx(spire[:, 2].max())  # 0.3 % of the points, but joined to the roof
    assert lo[0] == pytest.approx(body[:, 0].min()) and hi[1] == pytest.approx(body[:, 1].max())
    # every point framed with stray_share = 0
    lo0, hi0 = rmod.framing_bounds(np.vstack([body, strays]), 0.0)
    assert lo0[0] == -250 and hi0[2] == 400
