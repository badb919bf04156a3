"""Progress off a terminal: plain lines at most every 5 s and every 10 %, percent, rate and ETA."""

from __future__ import annotations

import io
import re

import pytest

from workstation.core import log, progress
from workstation.core.progress import PlainProgress, format_duration, progress_bar, progress_mode, track


class Clock:
    def __init__(self):
        self.t = 0.0

    def __call__(self):
        return self.t


def test_lines_are_rarer_of_5_s_and_10_percent():
    out, clock = io.StringIO(), Clock()
    p = PlainProgress("ground tiles", total=100, unit="tiles", stream=out, clock=clock)
    for _ in range(100):  # 100 units, 1 s apart: 10 % every 10 s, so the 10 % rule rules
        clock.t += 1.0
        p.advance(1)
    p.close()
    lines = out.getvalue().splitlines()
    assert len(lines) == 11  # 10 %, 20 %, ..., 100 %, then "done"
    assert lines[0] == "ground tiles: 10 % (10/100 tiles), 1 tiles/s, ETA 1 min 30 s"
    assert "100 %" in lines[9] and "elapsed" in lines[9]
    assert lines[-1] == "ground tiles: done, 100 tiles in 1 min 40 s"


def test_time_rule_when_work_is_fast():
    out, clock = io.StringIO(), Clock()
    p = PlainProgress("read", total=1_000_000, unit="points", stream=out, clock=clock)
    for i in range(1000):  # 10 % every second: the 5 s rule rules
        clock.t = (i + 1) / 100
        p.advance(1000)
    lines = out.getvalue().splitlines()
    assert lines == ["read: 50 % (500,000/1,000,000 points), 100,000 points/s, ETA 5.0 s",
                     "read: 100 % (1,000,000/1,000,000 points), 100,000 points/s, elapsed 10 s"]


def test_no_lines_for_short_work_and_unknown_total():
    out, clock = io.StringIO(), Clock()
    p = PlainProgress("quick", total=10, stream=out, clock=clock)
    for _ in range(10):
        clock.t += 0.1
        p.advance()
    p.close()
    assert out.getvalue() == ""  # under 5 s: nothing, not even "done"
    p = PlainProgress("stream", total=None, unit="chunks", stream=out, clock=clock, min_interval=5)
    for _ in range(12):
        clock.t += 1.0
        p.advance(2, points=500)
    lines = out.getvalue().splitlines()
    assert len(lines) == 2 and lines[0].startswith("stream: 10 chunks, 2 chunks/s, 500 points/s, elapsed")


def test_format_duration():
    assert [format_duration(s) for s in (3.25, 42, 125, 7260)] == ["3.2 s", "42 s", "2 min 05 s", "2 h 01 min"]


def test_progress_bar_is_plain_off_a_terminal_and_silent_with_quiet(monkeypatch, capsys):
    monkeypatch.delenv("WS_PROGRESS", raising=False)
    clock = Clock()
    monkeypatch.setattr(progress.time, "monotonic", clock)
    monkeypatch.setattr(PlainProgress.__init__, "__defaults__",
                        ("items", None, clock, 5.0, 0.1))
    assert progress_mode() == "plain"  # pytest's captured stderr is not a terminal
    with progress_bar("tiles", 4, unit="tiles") as advance:
        for _ in range(4):
            clock.t += 10
            advance(1)
    err = capsys.readouterr().err
    assert "tiles: 25 % (1/4 tiles)" in err and "tiles: done, 4 tiles" in err
    log.configure(quiet=True)
    try:
        assert progress_mode() == "off"
        for _ in track(range(3), "quiet"):
            clock.t += 10
        assert capsys.readouterr().err == ""
    finally:
        log.configure()
    monkeypatch.setenv("WS_PROGRESS", "0")
    assert progress_mode() == "off"
    monkeypatch.setenv("WS_PROGRESS", "1")
    assert progress_mode() == "rich"


def test_failed_work_has_no_done_line(monkeypatch, capsys):
    monkeypatch.setenv("WS_PROGRESS", "plain")
    clock = Clock()
    monkeypatch.setattr(PlainProgress.__init__, "__defaults__", ("items", None, clock, 5.0, 0.1))
    with pytest.raises(RuntimeError):
        with progress_bar("work", 2) as advance:
            clock.t += 10
            advance(1)
            raise RuntimeError("boom")
    err = capsys.readouterr().err
    assert "work: 50 %" in err and "done" not in err


def test_run_progress_plain_lines(monkeypatch, capsys):
    from types import SimpleNamespace

    from workstation.pipeline.progress import RunProgress

    monkeypatch.setenv("WS_PROGRESS", "plain")
    clock = Clock()
    monkeypatch.setattr(PlainProgress.__init__, "__defaults__", ("items", None, clock, 5.0, 0.1))
    seen = []
    tasks = [SimpleNamespace(phase="ground")] * 3 + [SimpleNamespace(phase="dem")]
    with RunProgress(tasks, on_progress=lambda *a: seen.append(a)) as rp:
        for phase in ("ground", "ground", "ground", "dem"):
            clock.t += 6
            rp.advance(phase, 1000)
    err = capsys.readouterr().err
    assert "ground: 33 % (1/3 tasks)" in err and "points/s" in err and "ground: done, 3 tasks" in err
    assert seen[-1] == ("dem", 1, 1, 1000)
