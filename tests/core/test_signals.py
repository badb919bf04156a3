"""The signal latch of the Dask drivers: a signal is held until the driver checks for it."""

import os
import signal

import pytest

from workstation.core.signals import Terminated, caught_signals


@pytest.mark.parametrize("sig, raised", [(signal.SIGINT, KeyboardInterrupt), (signal.SIGTERM, Terminated),
                                         (signal.SIGHUP, Terminated)])
def test_a_signal_is_raised_at_the_check_and_not_where_it_arrives(sig, raised):
    before = signal.getsignal(sig)
    with caught_signals() as latch:
        os.kill(os.getpid(), sig)  # delivered to the main thread before kill returns
        assert latch.signum == sig
        with pytest.raises(raised) as e:
            latch.check()
    assert signal.getsignal(sig) is before
    if raised is Terminated:
        assert e.value.signum == sig


def test_sleep_returns_early_and_raises_when_a_signal_arrives():
    import threading
    import time

    with caught_signals() as latch:
        threading.Timer(0.1, os.kill, (os.getpid(), signal.SIGINT)).start()
        t0 = time.monotonic()
        with pytest.raises(KeyboardInterrupt):
            latch.sleep(10)
        assert time.monotonic() - t0 < 5


def test_no_signal_no_exception():
    with caught_signals() as latch:
        latch.sleep(0.01)
        latch.check()
    assert latch.signum is None
