"""Real tiles bcts_1 + bcts_2 (lasR example data): one mosaic, no seam at the common edge."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.raster.dem import DemParams, build_dem
from workstation.raster.grid import GridSpec


@pytest.mark.realdata
def test_bcts_mosaic_has_no_seam(shared_data):
    files = [shared_data / "lidar" / "bcts_1.laz", shared_data / "lidar" / "bcts_2.laz"]
    p = DemParams(kind="dtm", resolution=1.0)
    mosaic = build_dem(files, p)
    assert mosaic.crs == "EPSG:3005"
    grid = GridSpec.from_transform(mosaic.transform, mosaic.shape)
    south = build_dem(files[0], p, grid=grid).array
    X, Y = mosaic.cell_centers()
    edge = 629400.0
    r = int(np.argmax(Y[:, 0] < edge))  # first row south of the common edge
    a = mosaic.array

    def excess(arr, row):
        e = (arr[row - 1] - arr[row]) - 0.5 * ((arr[row - 2] - arr[row - 1]) + (arr[row] - arr[row + 1]))
        return float(np.nanmean(e))

    assert abs(excess(a, r)) <= 0.05
    # away from the edge the mosaic equals the tile gridded alone (the TIN is local)
    interior = (Y < edge - 10) & np.isfinite(south)
    np.testing.assert_allclose(a[interior], south[interior], atol=1e-4)
    # the single tile alone extrapolates nothing north of its edge
    assert np.isnan(south[Y > edge + 2]).all()
