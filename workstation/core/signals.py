"""Signals around the Dask clusters of ``ws run`` and ``ws ground``: held while worker processes
start, and caught while the driver waits on them so they are raised only at safe points."""

from __future__ import annotations

import contextlib
import signal
import threading


class Terminated(KeyboardInterrupt):
    """SIGTERM or SIGHUP, raised where the program is so it unwinds as on Ctrl-C: temporary
    files are removed by the writers' ``finally`` blocks, and the exit code is 128 + signal."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


class Latch:
    """The first of SIGINT, SIGTERM or SIGHUP caught in a :func:`caught_signals` block; the
    block raises it where it chooses (:meth:`check`, :meth:`sleep`)."""

    def __init__(self):
        self.signum: int | None = None
        self._event = threading.Event()

    def catch(self, signum, frame) -> None:
        self.signum = self.signum or signum
        self._event.set()

    def check(self) -> None:
        """Raise KeyboardInterrupt (SIGINT) or :class:`Terminated` if a signal was caught."""
        if self.signum == signal.SIGINT:
            raise KeyboardInterrupt
        if self.signum is not None:
            raise Terminated(self.signum)

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds`` or until a signal arrives, then :meth:`check`."""
        self._event.wait(seconds)
        self.check()


@contextlib.contextmanager
def caught_signals():
    """Catch SIGINT, SIGTERM and SIGHUP into a :class:`Latch` for the block instead of raising
    them wherever the main thread is: an exception raised inside a lock's wait (Dask's
    ``as_completed``, ``wait``) leaves the lock half released ("cannot release un-acquired
    lock"). Outside the main thread signals cannot be caught and the latch stays empty."""
    latch = Latch()
    if threading.current_thread() is not threading.main_thread():
        yield latch
        return
    old = {s: signal.signal(s, latch.catch) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)}
    try:
        yield latch
    finally:
        for s, handler in old.items():
            signal.signal(s, handler)


@contextlib.contextmanager
def workers_starting():
    """Hold SIGTERM and SIGHUP until the block ends (then they are delivered), and ignore
    Ctrl-C meanwhile. The worker processes started in the block inherit the ignored Ctrl-C:
    a terminal's Ctrl-C reaches every process of its group, and the workers leave the
    shutdown to this process, which closes the cluster (a Ctrl-C during the start is lost)."""
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
