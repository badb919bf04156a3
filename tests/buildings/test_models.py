"""LoD1.2 / LoD2.2 models: watertight solids, roofs against the analytic roofs, roof types,
CityJSON 2.0 structure and the validator's own checks."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.export import cityjson_document, validate_cityjson
from workstation.buildings.footprints import extract_footprints
from workstation.buildings.models import (build_building, detach_raised, is_watertight, prism, split_holes, triangulate,
                                          weld)
from workstation.buildings.planes import segment_planes
from workstation.buildings.roof_faces import lower_envelope


def _model(kind, seed=5, yaw=0.5):
    rng = np.random.default_rng(seed)
    b = synth.SynthBuilding(kind, (500.0, 800.0), 15.0, 9.5, yaw, 6.0, 3.5, 100.0)
    pts = synth.sample_building(b, 10.0, 0.03, rng)
    fps, _ = extract_footprints(pts[:, :2])
    planes = segment_planes(pts)
    return b, build_building(0, fps[0].polygon, pts, planes.labels, planes, 100.0, cell=0.3)


def _roof_rms(b, m):
    import shapely

    # cell centres, so that no sample lies exactly on a step edge, where the roof is undefined
    g = np.stack(np.meshgrid(np.arange(-9, 9, 0.25) + 0.125, np.arange(-6, 6, 0.25) + 0.125), -1).reshape(-1, 2)
    xy = b.to_world(g)
    inside = shapely.contains_xy(shapely.Polygon(m.footprint), xy[:, 0], xy[:, 1])
    dz = synth.model_roof_z(m, xy[inside]) - b.roof_z(xy[inside])
    return float(np.sqrt(np.nanmean(dz ** 2)))


def test_prism_is_a_closed_solid():
    s = prism(np.array([[0, 0], [4, 0], [4, 3], [0, 3]], float), 10.0, 16.0)
    assert is_watertight(s)
    tris, _ = triangulate(s)
    import trimesh

    assert trimesh.Trimesh(s.vertices, tris).volume == pytest.approx(72.0)


@pytest.mark.parametrize("kind,rtype,faces", [("flat", "flat", 1), ("shed", "shed", 1), ("gabled", "gabled", 2),
                                              ("hipped", "hipped", 4), ("lshape", "flat", 1)])
def test_lod2_single_part_roofs(kind, rtype, faces):
    b, m = _model(kind)
    assert m.roof_type == rtype
    assert len(m.roofs) == faces
    assert len(m.lod2) == 1 and is_watertight(m.lod2[0]) and is_watertight(m.lod1)
    assert _roof_rms(b, m) < 0.05
    assert m.height == pytest.approx(np.nanpercentile(b.roof_z(b.to_world(
        np.random.default_rng(0).uniform([-7.5, -4.75], [7.5, 4.75], (20000, 2)))), 70), abs=0.1)


def test_lod2_multilevel_has_two_closed_parts():
    b, m = _model("multilevel")
    assert m.roof_type == "multilevel"
    assert len(m.lod2) == 2 and all(is_watertight(s) for s in m.lod2)
    tops = sorted(f.point[2] for f in m.roofs)
    assert tops[1] - tops[0] == pytest.approx(3.0, abs=0.05)
    assert _roof_rms(b, m) < 0.15  # the step edge refitted between the two parts' points


@pytest.mark.parametrize("yaw", [0.3, 0.9, 2.6])
def test_step_edge_is_placed_from_the_points_at_any_heading(yaw):
    """A rotated two-level building: the step edge (3 m high, 9.5 m long) within a few
    centimetres on average, well under the 0.32 m point spacing."""
    b, m = _model("multilevel", seed=3, yaw=yaw)
    assert len(m.lod2) == 2
    assert _roof_rms(b, m) < 0.15


def test_step_split_is_the_middle_of_the_best_gap():
    from workstation.buildings.models import step_split

    rng = np.random.default_rng(0)
    own, other = rng.uniform(-1.0, 0.0, 300) + 0.2, rng.uniform(0.0, 1.0, 300) + 0.2
    assert step_split(own, other) == pytest.approx(0.2, abs=0.01)
    # two stray points on the wrong side do not move it
    assert step_split(np.r_[own, 0.9], np.r_[other, -0.5]) == pytest.approx(0.2, abs=0.01)


def test_lower_envelope_of_a_hip_roof():
    import shapely

    sq = shapely.Polygon([(-5, -3), (5, -3), (5, 3), (-5, 3)])
    s = 1.0  # slope
    n = np.array([[0, -s, 1], [0, s, 1], [-s, 0, 1], [s, 0, 1]], float)  # rising from each edge
    n /= np.linalg.norm(n, axis=1)[:, None]
    pts = np.array([[0, -3, 0], [0, 3, 0], [-5, 0, 0], [5, 0, 0]], float)
    faces = lower_envelope(sq, n, pts)
    area = {k: f.area for k, f in faces}
    assert sum(area.values()) == pytest.approx(60.0)
    assert area[2] == pytest.approx(9.0) and area[3] == pytest.approx(9.0)  # hip triangles 6 x 3 / 2
    assert area[0] == pytest.approx(21.0) and area[1] == pytest.approx(21.0)  # trapezoids (10 + 4) x 3 / 2


def test_weld_splits_t_junctions():
    """A box whose top is split into two faces: the long walls must get the middle vertex."""
    top1 = np.array([[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    top2 = np.array([[1, 0, 1], [2, 0, 1], [2, 1, 1], [1, 1, 1]], float)
    bottom = np.array([[0, 0, 0], [0, 1, 0], [2, 1, 0], [2, 0, 0]], float)
    walls = [np.array([[0, 0, 0], [2, 0, 0], [2, 0, 1], [0, 0, 1]], float),
             np.array([[2, 0, 0], [2, 1, 0], [2, 1, 1], [2, 0, 1]], float),
             np.array([[2, 1, 0], [0, 1, 0], [0, 1, 1], [2, 1, 1]], float),
             np.array([[0, 1, 0], [0, 0, 0], [0, 0, 1], [0, 1, 1]], float)]
    s = weld([[top1], [top2], [bottom], *[[w] for w in walls]], ["RoofSurface"] * 2 + ["GroundSurface"] + ["WallSurface"] * 4)
    assert len(s.vertices) == 10
    assert len(s.faces[3][0]) == 5 and len(s.faces[5][0]) == 5  # front and back walls got the T vertex
    assert is_watertight(s)


def test_cityjson_document_is_valid_and_the_validator_catches_errors():
    models = [_model(k, seed=i)[1] for i, k in enumerate(["gabled", "multilevel"])]
    for i, m in enumerate(models):
        object.__setattr__(m, "id", i)
    doc = cityjson_document(models, [np.full(len(m.roofs), 1000.0) for m in models], "EPSG:25832")
    assert validate_cityjson(doc) == []
    assert doc["type"] == "CityJSON" and doc["version"] == "2.0"
    assert doc["metadata"]["referenceSystem"] == "https://www.opengis.net/def/crs/EPSG/0/25832"
    b1 = doc["CityObjects"]["building_1"]["geometry"]
    assert [g["lod"] for g in b1] == ["1.2", "2.2"] and b1[1]["type"] == "CompositeSolid"
    sem = doc["CityObjects"]["building_0"]["geometry"][1]["semantics"]
    kinds = {s["type"] for s in sem["surfaces"]}
    assert kinds == {"RoofSurface", "WallSurface", "GroundSurface"}
    # decoded vertices reproduce the model coordinates to the millimetre
    v = np.array(doc["vertices"]) * doc["transform"]["scale"] + doc["transform"]["translate"]
    assert np.abs(v.min(axis=0) - np.vstack([m.lod1.vertices for m in models]).min(axis=0)).max() < 1e-3
    broken = __import__("copy").deepcopy(doc)
    broken["CityObjects"]["building_0"]["geometry"][1]["boundaries"][0].pop()  # drop a face: shell opens
    assert any("not closed" in e for e in validate_cityjson(broken))
    broken = __import__("copy").deepcopy(doc)
    broken["vertices"][0] = [0.5, 1, 2]
    assert any("integers" in e for e in validate_cityjson(broken))


def test_weld_orders_vertices_and_inserts_several_t_vertices_along_an_edge():
    """Vertices come out in the order of their rounded coordinates (each from its first
    occurrence), and an edge with two vertices of other faces on it gets both, in order."""
    base = np.array([[0, 0, 0], [3, 0, 0], [3, 0, 1], [0, 0, 1]], float)  # its bottom edge holds x = 1, 2
    left = np.array([[0, 0, 0], [1, 0, 0], [1, -1, 0]], float)
    right = np.array([[2, 0, 0], [3, 0, 0], [3, -1, 0], [2.00000001, -1e-9, 0]], float)  # within tol of (2, 0, 0)
    s = weld([[base], [left], [right]], ["WallSurface"] * 3)
    allv = np.vstack([base, left, right])
    _, first = np.unique(np.round(allv / 1e-4).astype(np.int64), axis=0, return_index=True)
    assert np.array_equal(s.vertices, allv[first])
    ring = [tuple(s.vertices[v]) for v in s.faces[0][0]]
    assert ring[:4] == [(0, 0, 0), (1, 0, 0), (2, 0, 0), (3, 0, 0)]
    assert len(s.faces[2][0]) == 3  # the near-duplicate corner merged away


def test_dormer_is_a_raised_part_on_the_main_roof():
    """The dormer's planes meet the main slope in valleys but stand on it behind a front wall:
    they are split off into their own closed part, and the roof follows the analytic one."""
    b, m = _model("dormer", seed=6)
    assert len(m.lod2) >= 2 and all(is_watertight(s) for s in m.lod2)
    assert m.roof_type == "complex"
    normals = np.array([f.normal for f in m.roofs])
    for tilt, az in b.true_tilt_azimuth():
        t, a = np.radians(tilt), np.radians(az)
        f = m.roofs[int(np.argmax(normals @ [np.sin(t) * np.sin(a), np.sin(t) * np.cos(a), np.cos(t)]))]
        assert abs(f.tilt_deg - tilt) < 2.0 and abs((f.azimuth_deg - az + 180) % 360 - 180) < 3.0
    assert _roof_rms(b, m) < 0.15
    doc = cityjson_document([m], [np.full(len(m.roofs), 1000.0)])
    assert validate_cityjson(doc) == []


def test_detach_raised_splits_off_left_out_planes_on_a_step():
    # planes 0, 1 kept in part 0; 2 and 3 left out: 2 meets 1 in a step of 5 borders, 3 only touches 2
    steps = np.zeros((4, 4))
    steps[1, 2] = steps[2, 1] = 5
    part = np.zeros(4, int)
    dropped = np.array([False, False, True, True])
    assert detach_raised(part, dropped, steps).tolist() == [0, 0, 1, 0]
    steps[1, 2] = steps[2, 1] = 3  # under four cell borders: no wall
    assert detach_raised(part, dropped, steps).tolist() == [0, 0, 0, 0]


def test_split_holes_gives_pieces_without_holes():
    import shapely

    poly = shapely.Polygon([(0, 0), (10, 0), (10, 6), (0, 6)], [[(2, 2), (2, 4), (4, 4), (4, 2)],
                                                                [(6, 1), (6, 2), (8, 2), (8, 1)]])
    pieces = split_holes(poly)
    assert all(not len(p.interiors) for p in pieces) and len(pieces) >= 3
    assert sum(p.area for p in pieces) == pytest.approx(poly.area)
    assert shapely.union_all(pieces).equals(poly)


def test_weld_merges_vertices_that_rounding_puts_in_neighbouring_cells():
    """Two copies of a vertex 2e-5 m apart on either side of a rounding boundary are one vertex."""
    tri = [np.array([[0.0, 0, 0], [1, 0, 0], [0.00004999, 1, 0]])]
    tri2 = [np.array([[0.00005001, 1, 0], [1, 0, 0], [1, 1, 0]])]
    s = weld([tri, tri2], ["RoofSurface"] * 2)
    assert len(s.vertices) == 4


def test_split_holes_cuts_through_a_vertex_a_hair_off_the_centroid_line():
    """A hole whose centroid line passes 0.3 mm from one of its vertices is cut through that
    vertex: no piece keeps an edge under the CityJSON millimetre grid."""
    import shapely

    from workstation.buildings.models import MIN_FEATURE

    hole = [(2, 2), (4, 2), (4, 3.0003), (4, 4), (2, 4)]  # centroid y = 3, a vertex 0.3 mm above
    poly = shapely.Polygon([(0, 0), (10, 0), (10, 6), (0, 6)], [hole])
    y = shapely.Polygon(hole).centroid.y
    assert 0 < abs(3.0003 - y) < MIN_FEATURE
    pieces = split_holes(poly)
    assert sum(p.area for p in pieces) == pytest.approx(poly.area)
    for p in pieces:
        c = np.asarray(p.exterior.coords)
        assert np.linalg.norm(np.diff(c, axis=0), axis=1).min() >= MIN_FEATURE


def test_model_roof_planes_are_regularised():
    """The dormer model's sloped faces look along the building's direction or a quarter turn of
    it (to 1e-6 degrees), and the dormer's two sides share one tilt, within 1 degree of the true
    one (free fits of its 20-40 point faces scatter by 1-2 degrees)."""
    b, m = _model("dormer", seed=6)
    az = np.array([f.azimuth_deg for f in m.roofs if f.tilt_deg > 5.0])
    assert np.abs((az - az[0] + 45) % 90 - 45).max() < 1e-6
    normals = np.array([f.normal for f in m.roofs])
    tilts = []
    for tilt, a in b.true_tilt_azimuth()[2:]:  # the dormer's two sides
        t, a = np.radians(tilt), np.radians(a)
        f = m.roofs[int(np.argmax(normals @ [np.sin(t) * np.sin(a), np.sin(t) * np.cos(a), np.cos(t)]))]
        tilts.append(f.tilt_deg)
        assert abs(f.tilt_deg - tilt) < 1.0
    assert tilts[0] == pytest.approx(tilts[1], abs=1e-6)


def test_detach_raised_takes_a_touching_left_out_plane_along():
    # a dormer: 2 meets the main roof 1 in its front wall (5 step borders), 3 meets 1 in a valley
    # only (borders, no step) and 2 at the dormer's ridge: both stand on the roof as one part
    steps, borders = np.zeros((4, 4)), np.zeros((4, 4))
    steps[1, 2] = steps[2, 1] = 5
    borders[1, 2] = borders[2, 1] = 12
    borders[1, 3] = borders[3, 1] = borders[2, 3] = borders[3, 2] = 6
    part = np.zeros(4, int)
    dropped = np.array([False, False, True, True])
    assert detach_raised(part, dropped, steps, borders=borders).tolist() == [0, 0, 1, 1]
    borders[2, 3] = borders[3, 2] = 0  # not touching the detached plane: stays
    assert detach_raised(part, dropped, steps, borders=borders).tolist() == [0, 0, 1, 0]
