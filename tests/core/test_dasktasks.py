"""Shared Dask helpers against a real in-process Dask cluster."""

from __future__ import annotations

import time

import pytest

from workstation.core.dasktasks import run_bounded
from workstation.core.signals import caught_signals


def _slow_square(x):
    time.sleep(0.05)
    return x * x


def test_run_bounded_makes_arguments_only_for_free_slots_and_collects_every_result():
    from distributed import Client, LocalCluster

    made, results = [], {}

    def calls():
        for k in range(8):
            def make(k=k):
                made.append((k, len(made) - len(results)))  # tasks made but not yet collected
                return _slow_square, k
            yield k, make

    with LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster, \
            Client(cluster) as client, caught_signals() as latch:
        run_bounded(client, calls(), 2, results.__setitem__, latch, pause=0.01)
    assert results == {k: k * k for k in range(8)}
    assert max(in_flight for _, in_flight in made) <= 2 - 1  # the limit held when each was made


def test_alongside_runs_in_a_thread_that_takes_no_signals_and_wait_for_gives_its_outcome():
    import signal
    import threading

    from workstation.core.dasktasks import alongside, wait_for

    def where():
        return threading.current_thread().daemon, signal.pthread_sigmask(signal.SIG_BLOCK, [])

    with caught_signals() as latch:
        daemon, mask = wait_for(alongside(where), latch)
        assert daemon and {signal.SIGINT, signal.SIGTERM, signal.SIGHUP} <= mask
        with pytest.raises(ZeroDivisionError):
            wait_for(alongside(lambda: 1 / 0), latch)


def test_wait_for_raises_a_caught_ctrl_c_without_waiting_for_the_thread():
    import signal
    import threading

    from workstation.core.dasktasks import alongside, wait_for

    release = threading.Event()
    with caught_signals() as latch:
        pending = alongside(release.wait, 60)
        latch.catch(signal.SIGINT, None)
        t = time.perf_counter()
        with pytest.raises(KeyboardInterrupt):
            wait_for(pending, latch)
    release.set()
    assert time.perf_counter() - t < 5
