"""Rasters: grids sized from the data are estimated first; products of nodata are errors."""

import time

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.products import Raster
from workstation.io import write_cloud
from workstation.raster import terrain
from workstation.raster.dem import DemParams, build_dem


def test_hillshade_slope_aspect_of_an_all_nodata_dem_are_errors():
    r = Raster(np.full((20, 30), -9999.0, np.float32), (1, 0, 0, 0, -1, 20), None, -9999.0, {"path": "empty.tif"})
    for f in (lambda: terrain.hillshade(r), lambda: terrain.slope(r), lambda: terrain.aspect(r)):
        with pytest.raises(InvalidInputError, match="no valid cell") as e:
            f()
        assert "empty.tif" in str(e.value)


def test_far_coordinates_refused_in_milliseconds_naming_resolution():
    xyz = np.array([[0.0, 0.0, 0.0], [1e12, 1e12, 1.0], [5.0, 5.0, 0.2]])
    cloud = Cloud(xyz, {"classification": np.full(3, 2, np.uint8)}, meta={"source": "far.ply"})
    t0 = time.perf_counter()
    with pytest.raises(InvalidInputError, match="--resolution") as e:
        build_dem(cloud, DemParams(kind="dsm", resolution=1.0))
    assert time.perf_counter() - t0 < 1.0
    assert "far.ply" in str(e.value) and "--resolution" in e.value.hint


def test_dem_refuses_an_extension_it_does_not_write(tmp_path, capsys, small_cloud):
    src = tmp_path / "a.laz"
    write_cloud(small_cloud, src)
    assert main(["dem", str(src), "-o", str(tmp_path / "x.png"), "--kind", "dsm"]) == 2
    assert "x.png" in capsys.readouterr().err
    assert not (tmp_path / "x.png").exists()
