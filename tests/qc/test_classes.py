"""Classification checks of ``ws qc`` (workstation.qc.classes) on synthetic scenes with known answers."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.units import METRES
from workstation.io.crs import crs_units
from workstation.qc.classes import ClassParams, ClassPass1, ClassPass2, class_checks, class_findings, class_grid
from workstation.qc.context import QCGrid

GROUND_Z = 100.0


def grid_points(x0, y0, x1, y1, step=0.5):
    """Plan points on a regular lattice, half a step inside the rectangle."""
    xs, ys = np.arange(x0 + step / 2, x1, step), np.arange(y0 + step / 2, y1, step)
    return np.stack(np.meshgrid(xs, ys), -1).reshape(-1, 2)


def part(xy, z, code, withheld=0):
    """(xyz, classification, withheld) of points at height z (scalar or per point)."""
    xy = np.atleast_2d(np.asarray(xy, float))
    z = np.broadcast_to(np.asarray(z, float), (len(xy),))
    return np.column_stack([xy, z]), np.full(len(xy), code, np.uint8), np.full(len(xy), withheld, np.uint8)


def ground_except(x0, y0, x1, y1, holes=(), step=0.5, z=GROUND_Z, code=2):
    """Ground on a lattice, without the points inside the rectangles of ``holes``."""
    xy = grid_points(x0, y0, x1, y1, step)
    keep = np.ones(len(xy), bool)
    for hx0, hy0, hx1, hy1 in holes:
        keep &= ~((xy[:, 0] >= hx0) & (xy[:, 0] < hx1) & (xy[:, 1] >= hy0) & (xy[:, 1] < hy1))
    return part(xy[keep], z, code)


def scene(*parts, crs=None):
    xyz = np.vstack([p[0] for p in parts])
    attrs = {"classification": np.concatenate([p[1] for p in parts]), "withheld": np.concatenate([p[2] for p in parts])}
    return Cloud(xyz, attrs, crs=crs)


def run(cloud, params=ClassParams(), chunks=3, sources=("a.las",), units=METRES, grid=None):
    """Both passes over ``chunks`` pieces of the cloud, spread over ``sources``; (result, findings, p1)."""
    if grid is None:
        lo, hi = cloud.xyz.min(0), cloud.xyz.max(0)
        grid = class_grid((lo[0], lo[1], hi[0], hi[1]), units, params)
    pieces = [(cloud[s], sources[k % len(sources)]) for k, s in enumerate(np.array_split(np.arange(cloud.n), chunks))]
    p1 = ClassPass1(grid, params)
    for c, src in pieces:
        p1.add(c, src)
    p2 = p1.second_pass()
    for c, src in pieces:
        p2.add(c, src)
    res = class_checks(p1, p2)
    return res, class_findings(res), p1


def criterion(res, name):
    (c,) = [c for c in res["criteria"] if c["name"] == name]
    return c


def test_box_building_on_flat_ground_passes():
    foot = (15, 15, 25, 25)
    cloud = scene(ground_except(0, 0, 40, 40, holes=[foot]), part(grid_points(*foot), GROUND_Z + 6, 6))
    res, findings, p1 = run(cloud)
    assert res["classified"] is True
    assert res["histogram"] == {"2": 6400 - 400, "6": 400}
    assert res["names"]["6"] == "Building"
    assert res["buildings"]["count"] == 1 and res["buildings"]["without_ground"] == 0
    assert res["buildings"]["list"] == []
    assert criterion(res, "ground under every building")["pass"] is True
    # the surface under the roof is the TIN across the footprint: flat at ground level
    surf = p1.surface()
    row, col, _ = p1.grid.index(np.array([[20.0, 20.0]]))
    assert surf[row[0], col[0]] == pytest.approx(GROUND_Z, abs=1e-9)
    assert res["below_surface"] == 0 and res["above_surface"] == 0
    assert all(c["pass"] for c in res["criteria"])
    assert [f for f in findings if f.severity != "info"] == []


def test_building_without_ground_around_fails_and_is_listed():
    lone = (35, 15, 45, 25)  # amid unclassified points, ground only west of x = 20
    fine = (5, 5, 13, 13)  # amid ground
    cloud = scene(ground_except(0, 0, 20, 40, holes=[fine]), part(grid_points(*fine), GROUND_Z + 8, 6),
                  ground_except(20, 0, 60, 40, holes=[lone], code=1), part(grid_points(*lone), GROUND_Z + 6, 6))
    res, findings, _ = run(cloud)
    b = res["buildings"]
    assert b["count"] == 2 and b["without_ground"] == 1 and b["listed"] == 1
    (e,) = b["list"]
    assert e["centroid"] == pytest.approx([40.0, 20.0], abs=0.01)
    assert e["area_m2"] == pytest.approx(100.0)
    assert e["ring_ground_cells"] == 0 and e["reasons"] == ["no ground around"]
    assert criterion(res, "ground under every building") == {"name": "ground under every building", "value": 1,
                                                             "threshold": 0, "pass": False}
    warn = [f for f in findings if f.severity == "warning" and "building" in f.message]
    assert len(warn) == 1 and "(40.0, 20.0)" in warn[0].message


def test_unflagged_noise_counted_flagged_and_withheld_not():
    rng = np.random.default_rng(7)
    xy = lambda n: rng.uniform(2, 38, (n, 2))  # noqa: E731
    cloud = scene(ground_except(0, 0, 40, 40),
                  part(xy(50), GROUND_Z - 20, 1),  # unflagged low noise: counted
                  part(xy(20), GROUND_Z - 0.5, 3),  # within below_m: not counted
                  part(xy(30), GROUND_Z - 20, 7),  # flagged low noise
                  part(xy(20), GROUND_Z + 500, 18),  # flagged high noise
                  part(xy(10), GROUND_Z - 20, 1, withheld=1),  # withheld
                  part(xy(5), GROUND_Z + 200, 1),  # unflagged high noise: counted
                  part(xy(4), GROUND_Z + 150, 15))  # a tall tower: listed per class, not noise
    cloud = cloud[rng.permutation(cloud.n)]  # noise in every chunk of both files
    res, findings, _ = run(cloud, chunks=4, sources=("a.las", "b.las"))
    n = cloud.n
    assert res["points"] == n
    assert res["below_surface"] == 50 and res["below_by_class"] == {"1": 50}
    assert res["above_surface"] == 5 and res["above_by_class"] == {"1": 5, "15": 4}
    assert res["flags"]["withheld"] == 10
    assert res["noise_share"] == pytest.approx({"low": 30 / n, "high": 20 / n, "withheld": 10 / n})
    assert sum(f["below_surface"] for f in res["files"].values()) == 50
    assert sum(f["points"] for f in res["files"].values()) == n
    low = criterion(res, "unflagged low noise share")
    assert low["value"] == pytest.approx(50 / n) and low["pass"] is False
    assert criterion(res, "flagged noise share")["value"] == pytest.approx(50 / n)
    below = [f for f in findings if "below the ground" in f.message]
    assert sorted(f.file for f in below) == ["a.las", "b.las"] and sum(int(f.found) for f in below) == 50


def test_points_of_water_cells_are_not_low_noise():
    river = (18, 0, 22, 40)  # water 3 m under the banks: the TIN spans the banks
    cloud = scene(ground_except(0, 0, 40, 40, holes=[river]), part(grid_points(*river), GROUND_Z - 3, 9),
                  part(grid_points(18.2, 0, 22, 40, step=2.0), GROUND_Z - 3, 1))
    res, _, p1 = run(cloud)
    assert np.nanmax(p1.surface()) == pytest.approx(GROUND_Z)
    assert res["below_surface"] == 0 and res["tested"] == cloud.n


def test_bridge_deck_points_in_ground_are_counted():
    valley = (15, 0, 25, 40)
    deck = grid_points(14.5, 17, 25.5, 23)  # overlaps the plateau edges by one cell: the abutments
    in_ground = np.column_stack([np.linspace(19.1, 21.1, 10), np.full(10, 20.1)])
    cloud = scene(ground_except(0, 0, 40, 40, holes=[valley]), ground_except(*valley, z=GROUND_Z - 10),
                  part(deck, GROUND_Z + 0.3, 17), part(in_ground, GROUND_Z + 0.35, 2))
    res, findings, _ = run(cloud)
    assert res["bridge"] == {"deck_points": len(deck), "deck_in_ground": 10}
    assert criterion(res, "bridge decks not in ground")["pass"] is False
    assert any("bridge-deck level" in f.message for f in findings)


def test_feet_crs_thresholds_and_areas_in_metres():
    ft = 0.3048
    units = crs_units("EPSG:2994")
    assert units.h == ft
    tall, low = (30, 30, 70, 70), (100, 100, 130, 130)
    cloud = scene(ground_except(0, 0, 160, 160, holes=[tall, low], step=1.5, z=300.0),
                  part(grid_points(*tall, step=1.5), 320.0, 6),  # 6.1 m high: a building
                  part(grid_points(*low, step=1.5), 305.0, 6),  # 1.5 m high: not above the ground
                  part(grid_points(5, 5, 25, 25, step=4.5)[:20], 298.0, 1),  # 0.61 m under: not noise
                  part(grid_points(5, 135, 25, 155, step=3.5)[:30], 296.0, 1),  # 1.22 m under: noise
                  crs="EPSG:2994")
    res, _, p1 = run(cloud, units=units)
    assert p1.grid.cell == pytest.approx(1 / ft) and res["cell_m"] == pytest.approx(1.0)
    assert res["below_surface"] == 30
    b = res["buildings"]
    assert b["count"] == 2 and b["without_ground"] == 1
    (e,) = b["list"]
    assert e["reasons"] == ["not above the ground surface"]
    assert e["height_m"] == pytest.approx(5 * ft, abs=1e-3)
    assert e["centroid"] == pytest.approx([115.0, 115.0], abs=1.7)
    assert 0.75 * 900 * ft**2 < e["area_m2"] < 1.35 * 900 * ft**2


def test_unclassified_delivery_is_reported_not_failed():
    xy = grid_points(0, 0, 20, 20)
    cls = np.where(np.arange(len(xy)) % 3 == 0, 0, 1)
    cloud = scene(part(xy[cls == 0], GROUND_Z, 0), part(xy[cls == 1], GROUND_Z, 1))
    res, findings, _ = run(cloud)
    assert res["classified"] is False and res["criteria"] == []
    assert res["histogram"] == {"0": int((cls == 0).sum()), "1": int((cls == 1).sum())}
    assert res["below_surface"] is None
    assert [(f.severity, f.check) for f in findings] == [("info", "classes")]
    assert "not classified" in findings[0].message


def test_no_ground_fails_and_reserved_codes_are_listed():
    cloud = scene(part(grid_points(0, 0, 10, 10), GROUND_Z, 3), part(grid_points(0, 0, 2, 2), GROUND_Z, 31))
    res, findings, _ = run(cloud)
    assert criterion(res, "ground class present") == {"name": "ground class present", "value": 0, "threshold": 1,
                                                      "pass": False}
    assert res["reserved_codes"] == [31] and res["below_surface"] is None
    assert not any("reserved" in f.expected for f in findings)  # qc.validate reports them, once


def test_bad_parameters_and_shapes_are_refused():
    with pytest.raises(InvalidInputError, match="below_m"):
        ClassParams(below_m=-1.0)
    with pytest.raises(InvalidInputError, match="noise_share_warn"):
        ClassParams(noise_share_warn=2.0)
    grid = QCGrid.over((0, 0, 10, 10), 1.0, METRES)
    with pytest.raises(InvalidInputError, match="surface"):
        ClassPass2(grid, np.zeros((3, 3)))


def _stream(path):
    """Both passes over a real file's chunks (read once, held: the files are small)."""
    from workstation.io.registry import iter_chunks

    chunks = list(iter_chunks(path, 200_000))
    lo = np.min([c.xyz[:, :2].min(0) for c in chunks], axis=0)
    hi = np.max([c.xyz[:, :2].max(0) for c in chunks], axis=0)
    grid = class_grid((*lo, *hi), crs_units(chunks[0].crs))
    p1 = ClassPass1(grid)
    for c in chunks:
        p1.add(c, path.name)
    p2 = p1.second_pass()
    for c in chunks:
        p2.add(c, path.name)
    return class_checks(p1, p2)


@pytest.mark.realdata
def test_real_bcts_1(shared_data):
    res = _stream(shared_data / "lidar" / "bcts_1.laz")
    assert res["points"] == 531_662 and res["classified"]
    assert res["histogram"]["2"] == 48_729
    assert res["tested"] > 0.9 * res["points"]
    # a forest tile: trees stand tens of metres over the ground, none over 120 m, hardly any under it
    assert res["above_surface"] == 0
    assert res["below_surface"] < 0.001 * res["points"]


@pytest.mark.realdata
def test_real_sample_c(shared_data):
    res = _stream(shared_data / "lidar" / "sample_c.las")
    assert res["points"] == 14_408 and res["histogram"]["6"] == 12_525
    assert res["reserved_codes"] == [31]
    assert res["buildings"]["count"] >= 1
    assert res["below_surface"] < 0.01 * res["points"]
