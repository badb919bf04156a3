import numpy as np

from workstation.core.cloud import Cloud
from workstation.interop.open3d import (from_legacy, from_tensor, local_transform, to_legacy, to_tensor,
                                        transformed_copy, world_transform)
from workstation.registration import voxelmap
from workstation.registration.transforms import make_transform, random_rotation


def test_float32_tensor_round_trip_keeps_millimetres_via_origin(rng):
    xyz = np.round(rng.uniform(0, 100, (500, 3)) + [500_000.0, 5_000_000.0, 300.0], 3)
    c = Cloud(xyz, {"rgb": rng.integers(0, 65535, (500, 3)), "intensity": rng.integers(0, 60000, 500),
                    "normal": np.tile([0, 0, 1.0], (500, 1))}, crs="EPSG:32632")
    t, origin = to_tensor(c)
    assert t.point.positions.numpy().dtype == np.float32
    back = from_tensor(t, origin, template=c)
    assert np.abs(back.xyz - xyz).max() < 1e-4  # float32 of local coordinates: sub-mm
    naive = xyz.astype(np.float32).astype(np.float64)
    assert np.abs(naive - xyz).max() > 0.05  # what float32 without an origin would lose
    assert np.array_equal(back.attrs["intensity"], c.attrs["intensity"])
    assert np.abs(back.attrs["rgb"].astype(int) - c.attrs["rgb"]).max() <= 1
    assert back.crs == "EPSG:32632"


def test_legacy_round_trip_and_transform_does_not_mutate(rng):
    c = Cloud(rng.normal(size=(50, 3)) + 1000.0)
    pcd, origin = to_legacy(c)
    before = np.asarray(pcd.points).copy()
    moved = transformed_copy(pcd, make_transform(np.eye(3), [1.0, 0, 0]))
    assert np.array_equal(np.asarray(pcd.points), before)
    assert np.allclose(np.asarray(moved.points), before + [1.0, 0, 0])
    assert np.allclose(from_legacy(pcd, origin).xyz, c.xyz)


def test_local_world_transform_inverse(rng):
    T = make_transform(random_rotation(rng), rng.normal(size=3))
    o1, o2 = rng.normal(size=3) * 1e5, rng.normal(size=3) * 1e5
    assert np.allclose(world_transform(local_transform(T, o1, o2), o1, o2), T)


def test_voxel_planes_hash_and_grid_agree(rng, monkeypatch):
    x = rng.uniform(0, 20, (20000, 2))
    pts = np.column_stack([x, 0.3 * np.sin(x[:, 0])])
    grid = voxelmap.VoxelPlanes.build(pts, 0.5)
    monkeypatch.setattr(voxelmap, "_DENSE_MAX", 0)  # force the hash table
    hashed = voxelmap.VoxelPlanes.build(pts, 0.5)
    assert isinstance(grid.index, voxelmap._Grid) and isinstance(hashed.index, voxelmap._Hash)
    q = pts + rng.normal(0, 0.2, pts.shape)
    assert np.array_equal(grid.lookup(q), hashed.lookup(q))
    assert (grid.lookup(q) >= 0).mean() > 0.9
    far = pts + [100.0, 0, 0]
    assert np.all(hashed.lookup(far) == -1) and np.all(grid.lookup(far) == -1)
