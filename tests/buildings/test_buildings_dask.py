"""`reconstruct_buildings` on a real local Dask cluster gives the serial models, in order."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings
from workstation.core.errors import InvalidInputError


def _same(a, b) -> bool:
    if isinstance(a, np.ndarray):
        return isinstance(b, np.ndarray) and a.shape == b.shape and np.array_equal(a, b)
    if isinstance(a, (list, tuple)):
        return isinstance(b, (list, tuple)) and len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return a == b


def _fields(m):
    return (m.id, m.footprint, m.ground, m.height, m.roof_type, m.lod1.vertices, m.lod1.faces,
            [(s.vertices, s.faces, s.semantics) for s in m.lod2],
            [(f.polygon, f.normal, f.point, f.part) for f in m.roofs])


def test_two_workers_give_the_serial_models():
    xyz, cls, _ = synth.district(5, seed=2, density=8.0, kinds=("gabled", "hipped", "flat", "multilevel", "lshape"))
    params = BuildingsParams(solar=None)
    serial = reconstruct_buildings(xyz, cls, params)
    dask = reconstruct_buildings(xyz, cls, params, workers=2)
    assert [m.id for m in dask.models] == list(range(5))
    assert all(_same(_fields(a), _fields(b)) for a, b in zip(serial.models, dask.models))
    assert len(serial.models) == len(dask.models) == 5
    assert serial.coverage == dask.coverage and serial.spacing == dask.spacing
    assert "cluster_s" in dask.timings and "cluster_s" not in serial.timings


def test_workers_below_one_is_an_error():
    xyz, cls, _ = synth.district(1, seed=2, density=8.0)
    with pytest.raises(InvalidInputError, match="workers"):
        reconstruct_buildings(xyz, cls, BuildingsParams(solar=None), workers=0)


def test_cli_refuses_workers_with_a_scheduler(tmp_path, capsys):
    from workstation.cli.main import main

    (tmp_path / "in.laz").write_bytes(b"")
    rc = main(["buildings", str(tmp_path / "in.laz"), "-o", str(tmp_path / "out"), "--workers", "2",
               "--scheduler", "tcp://127.0.0.1:8786"])
    assert rc == 2 and "an external --scheduler has its own workers" in capsys.readouterr().err
