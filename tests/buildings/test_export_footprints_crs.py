"""Footprints read for ``ws buildings`` are checked against the cloud's CRS with the one CRS
comparison of the workstation (:func:`workstation.io.crs.same_crs`, also the catalog's):
pyproj equality with the axis order ignored, exact text for a description pyproj cannot read."""

import json

import pytest

from workstation.buildings.export import read_footprints
from workstation.core.errors import InvalidInputError
from workstation.io.crs import same_crs

SQUARE = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0], [0.0, 0.0]]


def _geojson(path, crs_name: str):
    doc = {"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": crs_name}},
           "features": [{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [SQUARE]}}]}
    path.write_text(json.dumps(doc))
    return path


def test_same_crs_ignores_axis_order_and_compares_unreadable_text_exactly():
    from pyproj import CRS

    assert same_crs("EPSG:25832", CRS.from_epsg(25832).to_wkt())
    assert same_crs("EPSG:4326", "OGC:CRS84")  # the same coordinates, axes named in another order
    assert not same_crs("EPSG:25832", "EPSG:25833")
    assert same_crs("no such crs", "no such crs")
    assert not same_crs("no such crs", "NO SUCH CRS")


def test_read_footprints_checks_the_crs_as_the_catalog_does(tmp_path):
    utm = _geojson(tmp_path / "utm.geojson", "urn:ogc:def:crs:EPSG::25832")
    assert len(read_footprints(utm, "EPSG:25832")) == 1
    with pytest.raises(InvalidInputError, match="footprints are in EPSG:25832"):
        read_footprints(utm, "EPSG:25833")
    lonlat = _geojson(tmp_path / "lonlat.geojson", "urn:ogc:def:crs:OGC:1.3:CRS84")
    assert len(read_footprints(lonlat, "EPSG:4326")) == 1
    odd = _geojson(tmp_path / "odd.geojson", "local grid a")
    with pytest.raises(InvalidInputError, match="footprints are in local grid a"):
        read_footprints(odd, "LOCAL GRID A")
