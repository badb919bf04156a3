"""Dask helpers shared by the stages that run on a cluster (``ws run``, tiled ``ws ground``,
``ws buildings --workers``): connecting to a user's scheduler, and keeping a bounded number
of tasks in flight so that each task's arguments are made only when a worker is free for it."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterable

from workstation.core.errors import InvalidInputError


def connect(scheduler: str):
    """A client on the running Dask scheduler at ``scheduler`` (e.g. ``tcp://host:8786``), or a
    clear error naming the address when it cannot be reached within 20 s."""
    from distributed import Client

    try:
        return Client(scheduler, timeout="20s")
    except (OSError, TimeoutError) as e:
        raise InvalidInputError(f"cannot reach the Dask scheduler at {scheduler}: {e}",
                                "start it with `dask scheduler` and workers with `dask worker ADDRESS`",
                                field="scheduler") from None


def local_worker_settings() -> dict:
    """Dask settings (for ``dask.config.set``) of a local cluster of CPU-bound tasks started here:

    - no statistical profiler in the workers (its stack sampling every 10 ms costs a worker more
      CPU than a building's outline);
    - glibc's malloc left to its own thresholds: Dask's default ``MALLOC_TRIM_THRESHOLD_``
      (64 KiB) also fixes glibc's mmap threshold at 128 KiB, so every larger numpy array is
      mapped afresh and its pages faulted in again, in the kernel, on every allocation; without
      it, freed arrays are reused as in one process (a value exported in the environment still
      reaches the workers, which inherit it);
    - the system monitor every 2 s, without the host's disk counters (Dask's default: 0.5 s
      with disks): with the workers busy on every core, monitoring is CPU taken from the tasks.
      The memory checks keep Dask's pace, so spilling and pausing react as quickly as usual.
    """
    return {"distributed.worker.profile.enabled": False,
            "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None,
            "distributed.admin.system-monitor.interval": "2s", "distributed.admin.system-monitor.disk": False}


@contextlib.contextmanager
def local_client(workers: int):
    """A Dask client on a new local cluster of ``workers`` single-threaded processes started
    with :func:`local_worker_settings` (closed with the client)."""
    import logging

    import dask
    from distributed import Client, LocalCluster

    from workstation.core.signals import workers_starting

    with workers_starting(), dask.config.set(local_worker_settings()):  # a half-started cluster cannot be closed
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                               silence_logs=logging.CRITICAL)
    with cluster, Client(cluster) as client:
        yield client


def run_bounded(client, calls: Iterable[tuple[object, Callable[[], tuple]]], limit: int,
                on_result: Callable[[object, object], None], latch, pause: float = 0.05) -> None:
    """Submit ``calls`` to ``client`` with at most ``limit`` in flight.

    Each call is ``(key, make)``: ``make()`` returns ``(function, *arguments)`` and is called
    only when a slot is free, so large arguments (a tile's points) exist for the tasks in
    flight only. ``on_result(key, result)`` runs in this process as each task ends (a task's
    exception is raised here). ``latch`` (:func:`workstation.core.signals.caught_signals`)
    turns a Ctrl-C caught at any point, the last collection included, into an interruption."""
    running: dict = {}

    def collect_done(at_most: int) -> None:  # wait until no more than at_most tasks run
        while len(running) > at_most:
            for f in [f for f in running if f.done()]:
                on_result(running.pop(f), f.result())
            if len(running) > at_most:
                latch.sleep(pause)

    for key, make in calls:
        collect_done(limit - 1)
        fn, *args = make()
        running[client.submit(fn, *args, pure=False)] = key
    collect_done(0)
    latch.check()
