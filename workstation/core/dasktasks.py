"""Dask helpers shared by the stages that run on a cluster (``ws run``, tiled ``ws ground``,
``ws buildings --workers``): connecting to a user's scheduler, and keeping a bounded number
of tasks in flight so that each task's arguments are made only when a worker is free for it,
and work run alongside a cluster's start (:func:`alongside`, :func:`wait_for`)."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterable
from concurrent.futures import Future
from concurrent.futures import TimeoutError as FuturesTimeout

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
def starting_local_workers():
    """The block in which a local cluster's workers start: signals held back (a half-started
    cluster cannot be closed cleanly) and :func:`local_worker_settings` in Dask's config."""
    import dask

    from workstation.core.signals import workers_starting

    with workers_starting(), dask.config.set(local_worker_settings()):
        yield


@contextlib.contextmanager
def local_client(workers: int):
    """A Dask client on a new local cluster of ``workers`` single-threaded processes started
    with :func:`local_worker_settings` (closed with the client)."""
    import logging

    from distributed import Client, LocalCluster

    with starting_local_workers():
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                               silence_logs=logging.CRITICAL)
    with cluster, Client(cluster) as client:
        yield client


def alongside(fn: Callable, *args) -> Future:
    """``fn(*args)`` started now in a daemon thread, its outcome in the returned future: work
    that overlaps a cluster's start (:func:`local_client`) in this thread.

    The thread starts with SIGINT, SIGTERM and SIGHUP blocked, so they reach the main thread
    only (threads it starts inherit the mask), and a signal held back during the cluster's
    start (:func:`workstation.core.signals.workers_starting`) is not taken there. Being a
    daemon, it is never joined: a caller that gives up on the future (an error, Ctrl-C)
    returns at once, while the thread runs ``fn`` to its end (nothing stops it, its CPU is
    not reclaimed) and its result is dropped."""
    import signal
    import threading

    fut: Future = Future()
    fut.set_running_or_notify_cancel()

    def run() -> None:
        try:
            fut.set_result(fn(*args))
        except BaseException as e:  # noqa: BLE001 - raised by the waiting thread
            fut.set_exception(e)

    thread = threading.Thread(target=run, name=f"ws-{getattr(fn, '__name__', 'work')}", daemon=True)
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM, signal.SIGHUP})
    try:  # a new thread inherits the mask of the one starting it
        thread.start()
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)
    return fut


def wait_for(fut: Future, latch, pause: float = 0.02):
    """The result of ``fut`` (its exception raised here), waited for in steps of ``pause``
    seconds on ``latch`` (:func:`workstation.core.signals.caught_signals`), so a Ctrl-C
    while waiting is raised at once."""
    while not fut.done():
        latch.check()
        with contextlib.suppress(FuturesTimeout):  # not done yet (or fn's own TimeoutError: done)
            return fut.result(timeout=pause)
    latch.check()
    return fut.result()


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
