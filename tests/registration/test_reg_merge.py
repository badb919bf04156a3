import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.registration.merge import MergeParams, merge_clouds, transform_cloud
from workstation.registration.transforms import make_transform, random_rotation


def test_merge_keeps_union_of_attributes_and_tags_sources(rng):
    a = Cloud(rng.uniform(0, 10, (50, 3)), {"intensity": np.arange(50), "classification": np.full(50, 2),
                                            "normal": np.tile([0, 0, 1], (50, 1))}, crs="EPSG:32632")
    b = Cloud(rng.uniform(0, 10, (30, 3)), {"rgb": np.full((30, 3), 1000), "gps_time": np.linspace(0, 1, 30),
                                            "treeID": np.arange(30, dtype=np.int32)}, crs="EPSG:32632")
    R = random_rotation(rng, 90)
    T = make_transform(R, [100.0, 0.0, 5.0])
    m = merge_clouds([a, b], [np.eye(4), T])
    assert m.n == 80 and m.crs == "EPSG:32632"
    assert {"intensity", "classification", "normal", "rgb", "gps_time", "treeID", "point_source_id"} <= set(m.dims)
    assert m.attrs["point_source_id"].tolist() == [1] * 50 + [2] * 30
    assert np.array_equal(m.attrs["intensity"][:50], np.arange(50))
    assert np.array_equal(m.attrs["treeID"][50:], np.arange(30))
    assert np.allclose(m.xyz[50:], b.xyz @ R.T + [100.0, 0.0, 5.0])
    assert np.all(m.attrs["rgb"][:50] == 0) and np.all(m.attrs["rgb"][50:] == 1000)
    assert np.array_equal(a.xyz, a.xyz.copy())  # unchanged input


def test_transform_cloud_rotates_normals(rng):
    c = Cloud(rng.normal(size=(5, 3)), {"normal": np.tile([1.0, 0, 0], (5, 1))})
    Rz = np.array([[0.0, -1, 0], [1, 0, 0], [0, 0, 1]])
    out = transform_cloud(c, make_transform(Rz, [0, 0, 0]))
    assert np.allclose(out.attrs["normal"], [[0, 1, 0]] * 5)
    assert np.allclose(c.attrs["normal"], [[1, 0, 0]] * 5)


def test_duplicate_removal_and_voxel_thinning(rng):
    base = rng.uniform(0, 10, (2000, 3))
    a = Cloud(base)
    b = Cloud(np.vstack([base[:500] + 0.001, rng.uniform(20, 30, (300, 3))]))  # 500 duplicates of a
    m = merge_clouds([a, b], params=MergeParams(duplicate_distance=0.01))
    assert m.n == 2300
    assert (m.attrs["point_source_id"] == 2).sum() == 300
    full = merge_clouds([a, b])
    thin = merge_clouds([a, b], params=MergeParams(voxel_size=5.0))
    lo = full.xyz.min(axis=0)
    occupied = np.unique(np.floor((full.xyz - lo) / 5.0), axis=0).shape[0]
    assert thin.n == occupied < 100
    assert np.unique(np.floor((thin.xyz - lo) / 5.0), axis=0).shape[0] == thin.n  # one point per voxel


def test_merge_refuses_mixed_crs_and_bad_poses(rng):
    a = Cloud(rng.normal(size=(3, 3)), crs="EPSG:32632")
    b = Cloud(rng.normal(size=(3, 3)), crs="EPSG:2056")
    with pytest.raises(InvalidInputError, match="CRS"):
        merge_clouds([a, b])
    with pytest.raises(InvalidInputError):
        merge_clouds([a, a], [np.eye(4)])
