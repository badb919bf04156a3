"""`reconstruct_buildings` on the urban crop sample_c (PDAL test data, classes as delivered)."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.buildings.export import cityjson_document, validate_cityjson
from workstation.buildings.models import is_watertight
from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings
from workstation.io import read_cloud


@pytest.mark.realdata
def test_sample_c_gives_one_closed_low_pitched_building(shared_data):
    cloud = read_cloud(shared_data / "lidar" / "sample_c.las")
    r = reconstruct_buildings(cloud.xyz, np.asarray(cloud.attrs["classification"]), BuildingsParams(solar=None))
    assert len(r.models) == 1  # one large building; a 1 m wide row of class-6 points is dropped
    m = r.models[0]
    assert len(m.roofs) == 2 and all(f.tilt_deg < 15 for f in m.roofs)  # two low-pitched sides
    assert abs(((m.roofs[0].azimuth_deg - m.roofs[1].azimuth_deg) % 360) - 180) < 10
    assert 3000 < sum(f.area_m2 for f in m.roofs) < 4000 or 2000 < abs(_area(m.footprint)) < 3600
    assert all(is_watertight(s) for s in m.lod2)
    assert validate_cityjson(cityjson_document(r.models, r.solar_kwh_m2_year)) == []


def _area(p):
    return 0.5 * (np.dot(p[:, 0], np.roll(p[:, 1], -1)) - np.dot(p[:, 1], np.roll(p[:, 0], -1)))
