"""`ws buildings` end to end on a small simulated district."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.export import validate_cityjson
from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import write_cloud


@pytest.fixture(scope="module")
def district(tmp_path_factory):
    d = tmp_path_factory.mktemp("buildings_cli")
    xyz, cls, blds = synth.district(4, seed=8, density=8.0, kinds=("gabled", "hipped", "flat", "multilevel"))
    write_cloud(Cloud(np.round(xyz, 3), {"classification": cls}, crs="EPSG:25832"), d / "in.laz")
    return d, blds


def test_buildings_writes_the_four_products(district, capsys):
    d, blds = district
    out = d / "out"
    rc = main(["buildings", str(d / "in.laz"), "-o", str(out), "--json"])
    assert rc == 0
    info = json.loads(capsys.readouterr().out)
    assert info["buildings"] == 4
    assert info["roof_types"] == {"gabled": 1, "hipped": 1, "flat": 1, "multilevel": 1}
    assert 47 < info["solar"]["latitude"] < 49  # from the CRS (UTM 32N around 500 km E, 5300 km N)
    fp = json.loads((out / "footprints.geojson").read_text())
    assert {f["properties"]["roof_type"] for f in fp["features"]} == {"gabled", "hipped", "flat", "multilevel"}
    for f in fp["features"]:
        assert set(f["properties"]) >= {"id", "height", "ground_height", "roof_type"}
        assert 4 < f["properties"]["height"] < 15
    roofs = json.loads((out / "roofs.geojson").read_text())
    assert len(roofs["features"]) == 2 + 4 + 1 + 2
    for f in roofs["features"]:
        p = f["properties"]
        assert set(p) >= {"building_id", "tilt_deg", "azimuth_deg", "area_m2", "solar_kwh_m2_year"}
        assert 500 < p["solar_kwh_m2_year"] < 2600
    assert validate_cityjson(json.loads((out / "buildings.city.json").read_text())) == []
    import trimesh

    scene = trimesh.load(out / "buildings.glb")
    assert len(scene.geometry) == 4
    for g in scene.geometry.values():  # roofs red, walls light, bottoms dark (closure is tested on the CityJSON)
        colours = {tuple(c) for c in np.asarray(g.visual.vertex_colors)[:, :3].tolist()}
        assert {(200, 70, 60), (235, 230, 220), (90, 90, 90)} <= colours


def test_buildings_refuses_to_overwrite_and_uses_given_footprints(district, capsys, tmp_path):
    d, blds = district
    out = d / "out_given"
    gj = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
            np.vstack([b.footprint(), b.footprint()[:1]]).tolist()]}} for b in blds[:2]]}
    (tmp_path / "fp.geojson").write_text(json.dumps(gj))
    args = ["buildings", str(d / "in.laz"), "-o", str(out), "--footprints", str(tmp_path / "fp.geojson"), "--no-solar", "--json"]
    assert main(args) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["buildings"] == 2 and info["footprint_source"] == "given"
    assert info["coverage"]["footprints_without_points"] == 0
    assert 0.4 < info["coverage"]["building_points_outside"] < 0.6  # two of four buildings given
    roofs = json.loads((out / "roofs.geojson").read_text())
    assert all(f["properties"]["solar_kwh_m2_year"] is None for f in roofs["features"])
    assert main(args) == 1  # outputs exist
    assert "exists" in capsys.readouterr().err
