"""Degenerate clouds are refused before Open3D / PoissonRecon / Qhull see them (one repeated
point made Open3D's Poisson crash the process with a segmentation fault)."""

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.mesh import MeshChainParams, PoissonParams, mesh_cloud
from workstation.mesh.reconstruct import ball_pivoting, delaunay25d, poisson

N = 300
SHAPES = {
    "identical": np.tile([500000.0, 4e6, 100.0], (N, 1)),
    "collinear": np.column_stack([np.linspace(0, 30, N), np.linspace(0, 10, N), np.linspace(0, 5, N)]) + [5e5, 4e6, 0],
}
UP = np.tile(np.float32([0, 0, 1]), (N, 1))


@pytest.mark.parametrize("shape", sorted(SHAPES))
@pytest.mark.parametrize("backend", ["open3d", "pymeshlab"])
def test_poisson_refuses_degenerate_points_before_the_library(shape, backend):
    cloud = Cloud(SHAPES[shape], {"normal": UP}, meta={"source": "bad.ply"})
    with pytest.raises(InvalidInputError, match=shape.replace("identical", "the same point")) as e:
        poisson(cloud, PoissonParams(backend=backend, depth=6))
    assert "bad.ply" in str(e.value)


@pytest.mark.parametrize("shape", sorted(SHAPES))
def test_ball_pivoting_and_chain_refuse_degenerate_points(shape):
    cloud = Cloud(SHAPES[shape], {"normal": UP})
    with pytest.raises(InvalidInputError):
        ball_pivoting(cloud)
    with pytest.raises(InvalidInputError):
        mesh_cloud(Cloud(SHAPES[shape]), MeshChainParams(method="poisson"))


def test_chain_needs_as_many_points_as_the_normal_neighbourhood():
    xyz = np.random.default_rng(0).uniform(0, 1, (5, 3))
    with pytest.raises(InvalidInputError, match="at least 10 points"):
        mesh_cloud(Cloud(xyz), MeshChainParams(method="bpa"))


def test_delaunay25d_refuses_points_on_one_vertical_plane():
    rng = np.random.default_rng(1)
    wall = np.column_stack([rng.uniform(0, 10, N), np.full(N, 3.0), rng.uniform(0, 5, N)])
    with pytest.raises(InvalidInputError, match="collinear"):
        delaunay25d(Cloud(wall))


def test_a_plane_still_meshes():
    rng = np.random.default_rng(2)
    xyz = np.column_stack([rng.uniform(0, 10, (N, 2)), np.zeros(N)])
    mesh, _ = poisson(Cloud(xyz, {"normal": UP}), PoissonParams(depth=5, trim_quantile=0.0))
    assert mesh.n_faces > 0
