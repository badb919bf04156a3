"""Dask helpers shared by the stages that run on a cluster (``ws run``, tiled ``ws ground``,
``ws buildings --workers``): connecting to a user's scheduler, and keeping a bounded number
of tasks in flight so that each task's arguments are made only when a worker is free for it."""

from __future__ import annotations

import os
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


#: The user's own glibc trim threshold, read before any Dask nanny copies its default into
#: this process's environment.
_USER_MALLOC_TRIM = os.environ.get("MALLOC_TRIM_THRESHOLD_")


def local_worker_settings() -> dict:
    """Dask settings (for ``dask.config.set``) of a local cluster of CPU-bound tasks started here:

    - no statistical profiler in the workers (its stack sampling every 10 ms costs a worker more
      CPU than a building's outline);
    - glibc's malloc left to its own thresholds: Dask's default ``MALLOC_TRIM_THRESHOLD_``
      (64 KiB) also fixes glibc's mmap threshold at 128 KiB, so every larger numpy array is
      mapped afresh and its pages faulted in again, in the kernel, on every allocation; without
      it, freed arrays are reused as in one process. A value the user exported is kept;
    - the system monitor every 2 s, without the host's disk counters, and the nannies' memory
      check every 0.5 s (Dask's defaults: 0.5 s with disks, 0.1 s): with the workers busy on
      every core, the scheduler's and each process's own monitoring is CPU taken from the tasks.
    """
    return {"distributed.worker.profile.enabled": False,
            "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": _USER_MALLOC_TRIM,
            "distributed.admin.system-monitor.interval": "2s", "distributed.admin.system-monitor.disk": False,
            "distributed.worker.memory.monitor-interval": "500ms"}


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
