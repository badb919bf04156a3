"""ws thin: voxel rules with known answers; Poisson disks equal to PDAL's sequential rule."""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.spatial import cKDTree

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import read_cloud, write_cloud
from workstation.ops.thin import PoissonParams, VoxelParams, poisson_mask, poisson_thin, voxel_thin


def _naive_greedy(xyz, r):
    """The definition: take points in order, keep one when no kept point is closer than r."""
    kept = []
    for i, p in enumerate(xyz):
        if not kept or np.linalg.norm(xyz[kept] - p, axis=1).min() >= r:
            kept.append(i)
    return kept


@pytest.fixture
def voxel_cloud():
    # two voxels of 1 m from the minimum corner (0.1, 0.1, 0): points 1-3 in the first, 4-6 in the second
    xyz = np.array([[0.9, 0.9, 0.5], [0.1, 0.1, 0.2], [0.6, 0.6, 0.8], [1.9, 0.1, 0.0], [1.5, 0.5, 0.5],
                    [1.4, 0.6, 0.6]])
    return Cloud(xyz, {"intensity": [1, 2, 3, 4, 5, 6]})


@pytest.mark.parametrize("keep, expected", [
    ("first", [1, 4]), ("lowest", [2, 4]), ("highest", [3, 6]), ("center", [3, 5]), ("centroid", [3, 5])])
def test_voxel_rules(voxel_cloud, keep, expected):
    out = voxel_thin(voxel_cloud, VoxelParams(1.0, keep))
    assert out.attrs["intensity"].tolist() == expected  # real points, input order


def test_poisson_equals_the_sequential_rule_and_is_block_invariant(rng):
    xyz = rng.uniform(0, 10, (800, 3))
    for r in (0.7, 1.5):
        mask = poisson_mask(xyz, PoissonParams(r))
        assert np.flatnonzero(mask).tolist() == _naive_greedy(xyz, r)
        assert np.array_equal(poisson_mask(xyz, PoissonParams(r, block=97)), mask)


def test_poisson_properties_on_scan_ordered_points(rng):
    # a dense scan-ordered strip: the order PDAL's filters.sample warns about
    t = np.linspace(0, 100, 40000)
    xyz = np.column_stack([t, np.sin(t * 7) * 2, rng.normal(0, 0.01, t.size)])
    out = poisson_thin(Cloud(xyz), PoissonParams(0.5))
    d, _ = cKDTree(out.xyz).query(out.xyz, k=2)
    assert d[:, 1].min() >= 0.5  # no two kept points closer than the radius
    d_all, _ = cKDTree(out.xyz).query(xyz)
    assert d_all.max() < 0.5  # every dropped point has a kept one within the radius (maximal)
    assert np.array_equal(poisson_thin(Cloud(xyz), PoissonParams(0.5)).xyz, out.xyz)  # deterministic


def test_thin_cli(tmp_path, rng, capsys):
    src = tmp_path / "in.laz"
    write_cloud(Cloud(np.round(rng.uniform(0, 20, (3000, 3)), 3), {"classification": rng.integers(1, 3, 3000)}), src)
    assert main(["thin", str(src), "-o", str(tmp_path / "v.laz"), "--voxel", "2", "--keep", "lowest", "--json",
                 "--pipeline-out", str(tmp_path / "v.json")]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["points_out"] == read_cloud(tmp_path / "v.laz").n <= 1000
    assert [s["type"] for s in json.loads((tmp_path / "v.json").read_text())] == [
        "readers.las", "filters.sort", "filters.voxeldownsize", "writers.las"]
    assert main(["thin", str(src), "-o", str(tmp_path / "p.laz"), "--poisson", "1.5"]) == 0
    assert main(["thin", str(src), "-o", str(tmp_path / "x.laz")]) == 2
    assert main(["thin", str(src), "-o", str(tmp_path / "x.laz"), "--voxel", "nan"]) == 2
