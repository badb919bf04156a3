"""`reconstruct_buildings` on a real local Dask cluster gives the serial models, in order."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.pipeline import BuildingsParams, batch_ranges, reconstruct_buildings
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
    assert "district_wait_s" in dask.timings and "district_s" in dask.timings


def test_a_running_scheduler_gives_the_serial_models():
    """With a scheduler's address the district pass runs beside the connection (on one thread)
    and the buildings on that cluster's workers: the serial models."""
    from distributed import LocalCluster

    xyz, cls, _ = synth.district(3, seed=2, density=8.0, kinds=("gabled", "hipped", "flat"))
    params = BuildingsParams(solar=None)
    serial = reconstruct_buildings(xyz, cls, params)
    with LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster:
        remote = reconstruct_buildings(xyz, cls, params, scheduler=cluster.scheduler_address)
    assert len(remote.models) == len(serial.models) == 3
    assert all(_same(_fields(a), _fields(b)) for a, b in zip(serial.models, remote.models))
    assert "cluster_s" in remote.timings


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


def test_batches_cover_the_buildings_and_shrink_towards_the_end():
    """Consecutive batches cover every building once, at most 32 at a time, a quarter of a
    worker's share of those left, the last ones single buildings."""
    for n_items, workers in ((1, 2), (7, 2), (100, 2), (2000, 2), (2000, 8)):
        b = batch_ranges(n_items, workers)
        assert b[0][0] == 0 and b[-1][1] == n_items and all(x[1] == y[0] for x, y in zip(b, b[1:]))
        sizes = [e - s for s, e in b]
        assert max(sizes) <= 32 and sizes[-1] == 1 and sizes == sorted(sizes, reverse=True)
    assert [e - s for s, e in batch_ranges(100, 2)][:3] == [13, 11, 10]


def test_local_worker_settings_reach_the_workers(monkeypatch):
    """A local cluster under :func:`local_worker_settings` starts workers without Dask's malloc
    trim threshold (unless exported here), with single-threaded BLAS and the slower monitors."""
    import os

    import dask
    from distributed import Client, LocalCluster

    from workstation.core.dasktasks import local_worker_settings

    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)

    def seen():
        return (os.environ.get("MALLOC_TRIM_THRESHOLD_"), os.environ.get("OPENBLAS_NUM_THREADS"),
                dask.config.get("distributed.admin.system-monitor.interval"))

    with dask.config.set(local_worker_settings()):
        with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                Client(cluster) as client:
            assert list(client.run(seen).values()) == [(None, "1", "2s")]


def _held_dtm(monkeypatch):
    """A DTM that takes until the returned event is set (at most 120 s)."""
    import threading

    from workstation.buildings import pipeline

    release = threading.Event()
    monkeypatch.setattr(pipeline, "_ground", lambda *a: release.wait(120))
    return release


def _children() -> set:
    """This process's child processes, with multiprocessing's resource tracker started first: the
    first cluster of a process starts it, a child that lives as long as the process, so a test
    run alone would count it as a process its cluster left behind."""
    import multiprocessing.resource_tracker

    import psutil

    multiprocessing.resource_tracker.ensure_running()
    return {p.pid for p in psutil.Process().children(recursive=True)}


def test_a_district_error_returns_without_waiting_for_the_dtm(monkeypatch):
    """The DTM gridded in a thread beside the district raster does not hold back the raster's error."""
    import time

    from workstation.buildings import pipeline
    from workstation.core.errors import StageError

    xyz, cls, _ = synth.district(2, seed=2, density=8.0)
    release = _held_dtm(monkeypatch)
    monkeypatch.setattr(pipeline, "_district", lambda *a: (_ for _ in ()).throw(StageError("buildings", "raster")))
    t = time.perf_counter()
    try:
        with pytest.raises(StageError, match="raster"):
            pipeline._district_pass(xyz, cls, xyz[cls == 6], BuildingsParams(solar=None), None, 2, {})
        assert time.perf_counter() - t < 20
    finally:
        release.set()


def test_a_district_error_beside_a_starting_cluster_closes_it(monkeypatch):
    """An error of the district pass made while the local cluster starts is raised once the
    cluster is up, without waiting for the DTM, and the cluster's processes are gone."""
    import time

    from workstation.buildings import pipeline
    from workstation.core.errors import StageError

    xyz, cls, _ = synth.district(2, seed=2, density=8.0)
    before = _children()
    release = _held_dtm(monkeypatch)
    monkeypatch.setattr(pipeline, "_district", lambda *a: (_ for _ in ()).throw(StageError("buildings", "raster")))
    t = time.perf_counter()
    try:
        with pytest.raises(StageError, match="raster"):
            reconstruct_buildings(xyz, cls, BuildingsParams(solar=None), workers=2)
        assert time.perf_counter() - t < 90
    finally:
        release.set()
    assert not _children() - before


def test_ctrl_c_during_the_district_pass_closes_the_cluster(monkeypatch):
    """A Ctrl-C once the local cluster is up (one while its workers start is lost) interrupts
    the wait for the district pass at once; the cluster's processes are gone."""
    import os
    import signal
    import threading
    import time

    from workstation.buildings import pipeline

    xyz, cls, _ = synth.district(2, seed=2, density=8.0)
    before = _children()
    release, stop = _held_dtm(monkeypatch), threading.Event()
    monkeypatch.setattr(pipeline, "_district", lambda *a: release.wait(120))

    def press():  # Ctrl-C every 0.1 s (to this process only) until stopped
        while not stop.wait(0.1):
            os.kill(os.getpid(), signal.SIGINT)

    old = signal.signal(signal.SIGINT, lambda *a: None)  # presses outside the stage do nothing
    threading.Thread(target=press, daemon=True).start()
    t = time.perf_counter()
    try:
        with pytest.raises(KeyboardInterrupt):
            reconstruct_buildings(xyz, cls, BuildingsParams(solar=None), workers=2)
        assert time.perf_counter() - t < 90
    finally:
        stop.set()
        release.set()
        time.sleep(0.2)
        signal.signal(signal.SIGINT, old)
    assert not _children() - before
