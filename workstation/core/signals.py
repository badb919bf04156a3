"""Signals around starting worker processes (the Dask clusters of ``ws run`` and ``ws ground``)."""

from __future__ import annotations

import contextlib


@contextlib.contextmanager
def workers_starting():
    """Hold SIGTERM and SIGHUP until the block ends (then they are delivered), and ignore
    Ctrl-C meanwhile. The worker processes started in the block inherit the ignored Ctrl-C:
    a terminal's Ctrl-C reaches every process of its group, and the workers leave the
    shutdown to this process, which closes the cluster (a Ctrl-C during the start is lost)."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM, signal.SIGHUP})
    old_int = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old_int)
        signal.pthread_sigmask(signal.SIG_SETMASK, old)
