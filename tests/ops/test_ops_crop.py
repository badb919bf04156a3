"""ws crop: boxes and polygons (holes, multipolygons, GeoJSON and GeoPackage), streamed."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io import read_cloud, write_cloud
from workstation.ops.crop import CropParams, crop, crop_mask, parse_bounds
from workstation.ops.stream import stream_select
from workstation.ops.vector import read_polygons

from gpkg_synth import write_gpkg  # noqa: E402 (tests/ is on the path, as for copc_synth)

SQUARE = [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]
HOLE = [[4, 4], [6, 4], [6, 6], [4, 6], [4, 4]]
FAR = [[20, 20], [22, 20], [22, 22], [20, 22], [20, 20]]


def _grid() -> Cloud:
    """Points at the centres of a 0.5 grid over [0, 25)^2, z = x, in UTM 32N."""
    g = np.arange(0.25, 25, 0.5)
    x, y = np.meshgrid(g, g)
    xyz = np.column_stack([x.ravel(), y.ravel(), x.ravel()])
    return Cloud(xyz, {"intensity": np.arange(len(xyz)) % 1000}, crs="EPSG:32632")


def _geojson(path, rings_list, crs=None):
    geom = {"type": "MultiPolygon", "coordinates": rings_list}
    doc = {"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, "geometry": geom}]}
    if crs:
        doc["crs"] = {"type": "name", "properties": {"name": crs}}
    path.write_text(json.dumps(doc))
    return path


def test_bounds_2d_3d_inclusive_and_inverted():
    c = _grid()
    inside = crop(c, CropParams(bounds=(0, 0, 10, 10)))
    assert inside.n == 400 and inside.xyz[:, :2].max() < 10
    assert crop(c, CropParams(bounds=(0.25, 0.25, 0.25, 0.25))).n == 1  # bounds included, as PDAL
    assert crop(c, CropParams(bounds=(0, 0, 10, 10, 0, 5))).n == 200
    assert crop(c, CropParams(bounds=(0, 0, 10, 10), invert=True)).n == c.n - 400
    assert parse_bounds("([0, 10], [1, 11])") == (0.0, 1.0, 10.0, 11.0)
    with pytest.raises(InvalidInputError, match="maximum below"):
        CropParams(bounds=(10, 0, 0, 10))


def test_polygon_with_hole_and_multipolygon_geojson(tmp_path):
    c = _grid()
    polys = read_polygons(_geojson(tmp_path / "p.geojson", [[SQUARE, HOLE], [FAR]]))
    keep = crop_mask(c, CropParams(polygons=polys))
    xy = c.xyz[:, :2]
    expect = ((xy < 10).all(axis=1) & ~((xy > 4) & (xy < 6)).all(axis=1)) | ((xy > 20) & (xy < 22)).all(axis=1)
    assert np.array_equal(keep, expect) and keep.sum() == 400 - 16 + 16
    assert np.array_equal(crop_mask(c, CropParams(polygons=polys, invert=True)), ~expect)


def test_geopackage_layer_and_polygon_crs(tmp_path):
    c = _grid()
    gpkg = write_gpkg(tmp_path / "z.gpkg", [[SQUARE, HOLE]])
    polys = read_polygons(gpkg, layer="zones")
    assert polys.crs == "EPSG:32632" and len(polys.polygons[0].holes) == 1
    assert crop_mask(c, CropParams(polygons=polys)).sum() == 400 - 16
    with pytest.raises(InvalidInputError, match="no layer 'roads'"):
        read_polygons(gpkg, layer="roads")
    # the same square in degrees (a GeoJSON with a crs member) is moved into the cloud's CRS
    import pyproj

    tr = pyproj.Transformer.from_crs("EPSG:32632", "EPSG:4326", always_xy=True)
    big = Cloud(c.xyz + [500000, 5000000, 0], crs="EPSG:32632")
    sq = np.array(SQUARE, float) + [500000, 5000000]
    lon, lat = tr.transform(sq[:, 0], sq[:, 1])
    geo = read_polygons(_geojson(tmp_path / "d.geojson", [[np.column_stack([lon, lat]).tolist()]], "EPSG:4326"))
    assert abs(int(crop_mask(big, CropParams(polygons=geo)).sum()) - 400) <= 4  # edges move by the projection


def test_streamed_crop_equals_in_memory_and_cli(tmp_path, capsys):
    c = _grid()
    src = tmp_path / "in.laz"
    write_cloud(c, src)
    params = CropParams(bounds=(3, 3, 17, 12))
    total, kept = stream_select(src, tmp_path / "s.laz", lambda k: crop_mask(k, params), stage="crop", chunk_size=333)
    s, m = read_cloud(tmp_path / "s.laz"), crop(read_cloud(src), params)
    assert (total, kept) == (c.n, m.n) and np.array_equal(s.xyz, m.xyz)
    assert np.array_equal(s.attrs["intensity"], m.attrs["intensity"])
    poly = _geojson(tmp_path / "p.geojson", [[SQUARE, HOLE]])
    assert main(["crop", str(src), "-o", str(tmp_path / "p.laz"), "--polygon", str(poly), "--json",
                 "--pipeline-out", str(tmp_path / "p.json")]) == 0
    assert json.loads(capsys.readouterr().out)["points_out"] == 384
    stage = json.loads((tmp_path / "p.json").read_text())[1]
    assert stage["type"] == "filters.crop" and stage["polygon"].startswith("POLYGON ((0.0")
    # nothing inside: exit 1, no output; both options or neither: usage error
    assert main(["crop", str(src), "-o", str(tmp_path / "e.laz"), "--bounds", "100,100,200,200"]) == 1
    assert not (tmp_path / "e.laz").exists()
    assert main(["crop", str(src), "-o", str(tmp_path / "e.laz")]) == 2
    assert main(["crop", str(src), "-o", str(tmp_path / "p.laz"), "--bounds", "0,0,1,1"]) == 1  # exists
