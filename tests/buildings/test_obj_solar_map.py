"""OBJ export of the LoD1.2/LoD2.2 models and the roof solar map (`ws buildings`)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.export import cityjson_document, glb_scene, model_origin, mtl_text, obj_text
from workstation.buildings.models import triangulate
from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings, solar_map
from workstation.buildings.solar import SolarParams, roof_cells, solar_map_png
from workstation.core.errors import InvalidInputError, OutputExistsError
from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import write_cloud

trimesh = pytest.importorskip("trimesh")


@pytest.fixture(scope="module")
def models():
    xyz, cls, _ = synth.district(6, seed=3, density=8.0, kinds=("gabled", "hipped", "multilevel", "lshape", "shed", "flat"))
    return reconstruct_buildings(xyz, cls, BuildingsParams(solar=None)).models


def _load_obj(text, tmp_path):
    """The OBJ as one trimesh mesh (trimesh splits it by material on loading)."""
    (tmp_path / "m.obj").write_text(text)
    (tmp_path / "buildings.mtl").write_text(mtl_text())
    return trimesh.load(tmp_path / "m.obj", force="mesh", process=False)


def _closed_shells(mesh) -> bool:
    """Whether every directed edge of the triangles (vertices matched at 0.1 mm) is met by its
    reverse as often as itself: a union of closed, consistently oriented shells (parts that
    share a wall each keep their own, opposite copy of it)."""
    q = np.round(mesh.vertices / 1e-4).astype(np.int64)
    _, vid = np.unique(q, axis=0, return_inverse=True)
    f = vid.ravel()[mesh.faces]
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    fwd, nf = np.unique(e, axis=0, return_counts=True)
    rev, nr = np.unique(e[:, ::-1], axis=0, return_counts=True)
    return bool(np.array_equal(fwd, rev) and np.array_equal(nf, nr))


def test_obj_lod22_matches_the_glb_triangles_and_the_cityjson_vertices(models, tmp_path):
    text = obj_text(models, "2.2")
    origin = model_origin(models)
    assert text.splitlines()[1] == "# origin " + " ".join(f"{v:.3f}" for v in origin)
    doc = cityjson_document(models, [np.full(len(m.roofs), np.nan) for m in models])
    assert doc["transform"]["translate"] == origin.tolist()
    mesh = _load_obj(text, tmp_path)
    glb = glb_scene(models)
    assert len(mesh.faces) == sum(len(g.faces) for g in glb.geometry.values())
    assert sum(line.startswith("o ") for line in text.splitlines()) == sum(len(m.lod2) for m in models)
    absolute = np.unique(np.vstack([s.vertices for m in models for s in m.lod2]).round(6), axis=0)
    got = np.unique((mesh.vertices + origin).round(6), axis=0)
    assert len(got) == len(absolute) and np.abs(got - absolute).max() <= 1e-3
    assert _closed_shells(mesh) and mesh.volume > 0


def test_obj_materials_follow_the_semantics(models):
    text = obj_text(models, "2.2")
    counts = {}
    current = None
    for line in text.splitlines():
        if line.startswith("usemtl "):
            current = line.split()[1]
        elif line.startswith("f "):
            counts[current] = counts.get(current, 0) + 1
    want = {}
    for m in models:
        for s in m.lod2:
            _, owner = triangulate(s)
            for k in np.array(s.semantics)[owner]:
                want[k] = want.get(k, 0) + 1
    assert counts == want and set(counts) == {"RoofSurface", "WallSurface", "GroundSurface"}


def test_obj_lod12_is_one_closed_block_per_building(models, tmp_path):
    text = obj_text(models, "1.2")
    mesh = _load_obj(text, tmp_path)
    assert sum(line.startswith("o ") for line in text.splitlines()) == len(models)
    assert _closed_shells(mesh) and mesh.volume > 0
    with pytest.raises(Exception, match="1.2"):
        obj_text(models, "3")


def test_roof_cells_keep_the_highest_face_and_align_on_the_cell():
    square = np.array([[0.2, 0.2], [4.2, 0.2], [4.2, 4.2], [0.2, 4.2]])
    rows, cols, xyz, owner, shape, (x0, y1) = roof_cells([square, square], [lambda p: np.full(len(p), 5.0),
                                                                         lambda p: np.full(len(p), 7.0)], 0.5)
    assert (x0, y1) == (0.0, 4.5) and shape == (9, 9)
    assert len(rows) == 64 and np.all(owner == 1) and np.all(xyz[:, 2] == 7.0)


def _gabled_scene(yaw=0.0):
    """One gabled house (ridge east-west: one roof face south, one north) with ground points."""
    rng = np.random.default_rng(4)
    b = synth.SynthBuilding("gabled", (500030.0, 5300030.0), 14.0, 9.0, yaw, 6.0, 4.0, 100.0)
    roof = synth.sample_building(b, 10.0, 0.02, rng)
    g = rng.uniform(500000.0, 500060.0, (36000, 2)) + [0.0, 4800000.0]
    g = g[~b.inside(g)]
    xyz = np.vstack([np.column_stack([g, np.full(len(g), 100.0)]), roof])
    cls = np.r_[np.full(len(g), 2), np.full(len(roof), 6)].astype(np.uint8)
    return xyz, cls


def _cell_frame(arr, tr, yaw):
    """(u, v) of each cell centre in the house's frame (u along the ridge, v < 0 the south face)."""
    rows, cols = np.indices(arr.shape)
    xy = np.column_stack([tr[2] + (cols.ravel() + 0.5) * tr[0], tr[5] + (rows.ravel() + 0.5) * tr[4]])
    c, s = np.cos(yaw), np.sin(yaw)
    d = xy - [500030.0, 5300030.0]
    return (d[:, 0] * c + d[:, 1] * s).reshape(arr.shape), (-d[:, 0] * s + d[:, 1] * c).reshape(arr.shape)


def test_solar_map_south_roof_beats_north_roof_and_nodata_off_roofs():
    xyz, cls = _gabled_scene(0.3)
    r = reconstruct_buildings(xyz, cls, BuildingsParams(solar=SolarParams(latitude=48.0, longitude=11.0),
                                                        solar_map_cell=0.5))
    arr, tr = r.solar_map
    assert tr[0] == 0.5 and tr[4] == -0.5 and tr[2] % 0.5 == 0 and tr[5] % 0.5 == 0
    u, v = _cell_frame(arr, tr, 0.3)
    south = (np.abs(u) < 6.0) & (v < -1.0) & (v > -4.0)
    north = (np.abs(u) < 6.0) & (v > 1.0) & (v < 4.0)
    assert np.isfinite(arr[south]).all() and np.isfinite(arr[north]).all()
    assert np.nanmin(arr[south]) > np.nanmax(arr[north])
    outside = (np.abs(u) > 7.5) | (np.abs(v) > 5.0)
    assert outside.sum() > 100 and np.isnan(arr[outside]).all()
    assert np.isfinite(arr).sum() * 0.25 == pytest.approx(14.0 * 9.0, rel=0.1)


def test_solar_map_cells_agree_with_the_per_face_values():
    xyz, cls = _gabled_scene(0.3)
    params = BuildingsParams(solar=SolarParams(latitude=48.0, longitude=11.0), solar_map_cell=None)
    r = reconstruct_buildings(xyz, cls, params)
    assert r.solar_map is None
    arr, tr = solar_map(r.models, xyz, params.solar, r.spacing, 0.5)
    _, v = _cell_frame(arr, tr, 0.3)
    faces = {"south" if 90 < f.azimuth_deg < 270 else "north": s for f, s in zip(r.models[0].roofs, r.solar_kwh_m2_year[0])}
    assert np.nanmean(arr[v < 0]) == pytest.approx(faces["south"], rel=0.03)
    assert np.nanmean(arr[v > 0]) == pytest.approx(faces["north"], rel=0.03)


def test_cli_writes_obj_and_solar_map(tmp_path, capsys):
    rasterio = pytest.importorskip("rasterio")
    xyz, cls = _gabled_scene(yaw=0.3)
    write_cloud(Cloud(np.round(xyz, 3), {"classification": cls}, crs="EPSG:25832"), tmp_path / "in.laz")
    out = tmp_path / "out"
    assert main(["buildings", str(tmp_path / "in.laz"), "-o", str(out), "--solar-cell", "1", "--json"]) == 0
    info = json.loads(capsys.readouterr().out)
    assert str(out / "solar_roofs.tif") in info["files"] and str(out / "buildings_lod22.obj") in info["files"]
    assert str(out / "solar_roofs.png") in info["files"]
    assert (out / "solar_roofs.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    origin = info["local_origin"]
    assert (out / "buildings_lod22.obj").read_text().splitlines()[1] == "# origin " + " ".join(f"{v:.3f}" for v in origin)
    assert "newmtl RoofSurface" in (out / "buildings.mtl").read_text()
    with rasterio.open(out / "solar_roofs.tif") as src:
        assert src.crs.to_epsg() == 25832 and src.res == (1.0, 1.0) and src.nodata == -9999.0
        a = src.read(1, masked=True)
        x, y = src.xy(*np.unravel_index(int(np.argmax(~a.mask)), a.shape))
        assert 500020 < x < 500040 and 5300020 < y < 5300040
        assert 500 < a.min() and a.max() < 2600  # clear sky at 48 N


def _inferno_hits(img: np.ndarray, values) -> list:
    """How many pixels of an RGB image lie within 6 levels of the inferno colour of each value (0-1)."""
    from matplotlib import colormaps

    rgb = img[..., :3].reshape(-1, 3).astype(int)
    cols = np.round(np.asarray(colormaps["inferno"](np.asarray(values, float)))[:, :3] * 255).astype(int)
    return [int((np.abs(rgb - c).max(axis=1) <= 6).sum()) for c in cols]


def test_solar_map_png_colours_cells_by_value_with_a_colour_bar(tmp_path):
    from PIL import Image

    arr = np.full((60, 100), np.nan, np.float32)
    arr[10:50, 10:50] = 900.0  # a north roof
    arr[10:50, 50:90] = 1500.0  # a south roof
    path = solar_map_png(arr, (0.5, 0.0, 500000.0, 0.0, -0.5, 5300030.0), tmp_path / "solar_roofs.png")
    img = np.asarray(Image.open(path).convert("RGB"))
    assert img.shape[0] > 200 and img.shape[1] > 300
    low, high, mid = _inferno_hits(img, [0.0, 1.0, 0.5])
    assert low > 2000 and high > 2000  # each roof in the colour of its value
    assert mid > 0  # only the colour bar holds the colours between them
    white = (img == 255).all(axis=2).sum()
    assert white > 0.2 * img.shape[0] * img.shape[1]  # cells off the roofs and the margins stay white
    with pytest.raises(OutputExistsError):
        solar_map_png(arr, (0.5, 0.0, 500000.0, 0.0, -0.5, 5300030.0), path)  # exists, no overwrite
    with pytest.raises(InvalidInputError, match="no roof cells"):
        solar_map_png(np.full((4, 4), np.nan), (0.5, 0.0, 0.0, 0.0, -0.5, 0.0), tmp_path / "empty.png")


def _gpkg(path, rings, srs_id):
    """Footprint rings (k, 2) as a GeoPackage layer 'houses' (each ring closed)."""
    from gpkg_synth import write_gpkg

    return write_gpkg(path, [[np.vstack([r, r[:1]])] for r in rings], srs_id, layer="houses")


def test_cli_uses_footprints_from_a_geopackage_and_checks_its_crs(tmp_path, capsys):
    xyz, cls, blds = synth.district(3, seed=2, density=8.0, kinds=("gabled", "flat", "hipped"))
    write_cloud(Cloud(np.round(xyz, 3), {"classification": cls}, crs="EPSG:25832"), tmp_path / "in.laz")
    rings = [b.footprint() for b in blds[:2]]
    args = ["buildings", str(tmp_path / "in.laz"), "--no-solar", "--json", "--footprints"]
    assert main([*args, str(_gpkg(tmp_path / "fp.gpkg", rings, 25832)), "-o", str(tmp_path / "a")]) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["buildings"] == 2 and info["footprint_source"] == "given"
    fp = json.loads((tmp_path / "a" / "footprints.geojson").read_text())
    for f, r in zip(fp["features"], rings):  # the given outlines are kept as they are
        assert np.allclose(np.asarray(f["geometry"]["coordinates"][0])[:-1], r, atol=1e-3)
    assert main([*args, str(_gpkg(tmp_path / "wrong.gpkg", rings, 32632)), "-o", str(tmp_path / "b")]) != 0
    err = capsys.readouterr().err
    assert "wrong.gpkg" in err and "EPSG:32632" in err
