"""The MLS refinement runs by default on clouds meshed with their cameras (photogrammetric) and
not on others (scans), and a chosen ``--refine-k`` projects every mesh."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Image, Reconstruction
from workstation.mesh import MeshChainParams, PoissonParams, mesh_cloud
from workstation.mesh.reconstruct import RefineParams
from workstation.photogrammetry.rigs import look_at

ORIGIN = np.array([500_000.0, 4_000_000.0, 100.0])


def noisy_sphere(n=15_000, noise=0.02, seed=0) -> Cloud:
    """A 2 m sphere on ORIGIN sampled by a Fibonacci lattice, radii with Gaussian ``noise`` (m)."""
    i = np.arange(n) + 0.5
    phi, th = np.arccos(1 - 2 * i / n), np.pi * (1 + 5 ** 0.5) * i
    u = np.column_stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)])
    r = 2.0 + np.random.default_rng(seed).normal(0, noise, n)
    return Cloud(ORIGIN + r[:, None] * u)


def ring_of_cameras(n=8, radius=10.0) -> Reconstruction:
    """``n`` cameras on a horizontal circle around ORIGIN, looking at it."""
    cam = Camera(400, 300, 300.0, 300.0, 199.5, 149.5)
    a = np.linspace(0, 2 * np.pi, n, endpoint=False)
    centres = ORIGIN + radius * np.column_stack([np.cos(a), np.sin(a), np.zeros(n)])
    return Reconstruction({1: cam}, {k + 1: Image(f"c{k}.png", 1, look_at(c, ORIGIN)) for k, c in enumerate(centres)})


def radial_rms(mesh) -> float:
    return float(np.sqrt(np.mean((np.linalg.norm(mesh.vertices - ORIGIN, axis=1) - 2.0) ** 2)))


PARAMS = dict(poisson=PoissonParams(depth=6, trim_quantile=0.0, support_trim=0.0, point_weight=4.0, threads=1),
              clean=None, color=None, quality=None, texture=None)


def test_refine_runs_by_default_with_cameras_only():
    cloud = noisy_sphere()
    cams = ring_of_cameras()
    photos = mesh_cloud(cloud, MeshChainParams(**PARAMS), cams)
    off = mesh_cloud(cloud, MeshChainParams(**PARAMS, refine=None), cams)
    scan = mesh_cloud(cloud, MeshChainParams(**PARAMS))  # no cameras: normals oriented by propagation
    every = mesh_cloud(cloud, MeshChainParams(**PARAMS, refine=RefineParams(photos_only=False)))
    names = lambda r: [s.name for s in r.steps]  # noqa: E731
    assert names(photos).count("refine_mls") == 1 and names(every).count("refine_mls") == 1
    assert "refine_mls" not in names(off) and "refine_mls" not in names(scan)
    assert next(s for s in photos.steps if s.name == "refine_mls").params["k"] == RefineParams().k
    # the same Poisson surfaces before the projection: the projection averages the 2 cm noise
    assert np.array_equal(photos.mesh.faces, off.mesh.faces)
    assert radial_rms(photos.mesh) < 0.6 * radial_rms(off.mesh)
    assert radial_rms(every.mesh) < 0.6 * radial_rms(scan.mesh)


def test_cli_refine_k(tmp_path, capsys):
    from workstation.cli.main import main
    from workstation.io import write_cloud

    src = tmp_path / "sphere.laz"
    write_cloud(noisy_sphere(6000), src)
    steps = {}
    for label, extra in (("default", []), ("k24", ["--refine-k", "24"]), ("off", ["--refine-k", "0"])):
        out = tmp_path / f"{label}.ply"
        assert main(["mesh", str(src), "-o", str(out), "--depth", "6", "--no-quality", "--json", *extra]) == 0
        doc = json.loads(capsys.readouterr().out)
        steps[label] = {s["name"]: s for s in doc["steps"]}
    assert "refine_mls" not in steps["default"] and "refine_mls" not in steps["off"]  # a cloud without cameras
    assert steps["k24"]["refine_mls"]["params"]["k"] == 24
    with pytest.raises(InvalidInputError):
        RefineParams(k=2)


@pytest.mark.parametrize("value", ["1", "2", "-1", "1001"])
def test_cli_refine_k_out_of_range_is_a_usage_error(tmp_path, value):
    """A k no plane fit takes is refused by the option, named as ``--refine-k`` (not the
    dataclass field ``k``) with its valid values, before the cloud is read."""
    from click.testing import CliRunner

    from workstation.cli.mesh import mesh

    src = tmp_path / "in.laz"
    src.write_bytes(b"not a cloud")  # never read: click refuses the option first
    res = CliRunner().invoke(mesh, [str(src), "-o", str(tmp_path / "out.ply"), "--refine-k", value])
    assert res.exit_code == 2, res.output
    assert "'--refine-k'" in res.output and "3<=x<=1000 or 0" in res.output
    assert "field 'k'" not in res.output


@pytest.mark.parametrize("value, k", [("0", 0), ("3", 3), ("1000", 1000)])
def test_cli_refine_k_accepts_off_and_plane_sizes(tmp_path, value, k):
    from workstation.cli.mesh import mesh

    src = tmp_path / "in.laz"
    src.write_bytes(b"")
    ctx = mesh.make_context("mesh", [str(src), "-o", str(tmp_path / "out.ply"), "--refine-k", value])
    assert ctx.params["refine_k"] == k
