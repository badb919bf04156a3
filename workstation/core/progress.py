"""Progress on stderr: a rich bar in a terminal or a notebook, plain lines otherwise.

In a Jupyter notebook the bar is a widget (rich draws it in an ``ipywidgets.Output``) that
stays under the cell when the work is done, showing the finished state; without
``ipywidgets`` rich cannot draw it there, so the notebook gets plain lines instead.

When stderr is not a terminal (a batch job, CI, a redirected log), :class:`PlainProgress`
writes a line now and then instead of a bar: at most one every ``min_interval`` seconds *and*
every ``min_fraction`` of the work (whichever is rarer), with the percentage, the rate and the
time left, plus a closing line when it wrote any. ``ws -q`` (``log.configure(quiet=True)``)
silences both. ``WS_PROGRESS`` overrides the choice: ``1`` rich bar, ``plain`` lines, ``0`` off.
"""

from __future__ import annotations

import contextlib
import os
import sys
import time
from typing import Callable, Iterable, Iterator, TextIO, TypeVar

T = TypeVar("T")
_console = None


def stderr_console():
    global _console
    if _console is None:
        from rich.console import Console

        _console = Console(stderr=True)
    return _console


def _in_notebook() -> bool:
    """Whether this runs in a Jupyter kernel where rich can draw a live bar (it needs
    ``ipywidgets`` for that; without it a notebook counts as a plain stream)."""
    try:
        if not stderr_console().is_jupyter:
            return False
        import ipywidgets  # noqa: F401 - rich's Live draws into an ipywidgets.Output
    except Exception:  # noqa: BLE001 - no rich console or no widgets: no live bar here
        return False
    return True


def progress_mode() -> str:
    """How progress is shown now: ``"rich"`` (terminal or notebook), ``"plain"`` (lines) or ``"off"``."""
    from workstation.core.log import is_quiet

    env = os.environ.get("WS_PROGRESS", "").strip().lower()
    if env == "0" or is_quiet():
        return "off"
    if env == "1":
        return "rich"
    if env == "plain":
        return "plain"
    stream = sys.stderr
    if (stream is not None and hasattr(stream, "isatty") and stream.isatty()) or _in_notebook():
        return "rich"
    return "plain" if stream is not None else "off"


def format_duration(seconds: float) -> str:
    """``"12 s"``, ``"3 min 05 s"``, ``"1 h 02 min"``."""
    s = max(0.0, float(seconds))
    if s < 60:
        return f"{s:.0f} s" if s >= 10 else f"{s:.1f} s"
    if s < 3600:
        return f"{int(s // 60)} min {int(s % 60):02d} s"
    return f"{int(s // 3600)} h {int(s % 3600 // 60):02d} min"


class PlainProgress:
    """Progress as occasional plain lines on a stream (stderr off a terminal).

    A line is written when at least ``min_interval`` seconds have passed since the last one
    *and* (when ``total`` is known) at least ``min_fraction`` of ``total`` has been done since:
    ``"ground tiles: 40 % (4/10 tiles), 0.8 tiles/s, ETA 7.5 s"``. :meth:`close` writes a last
    line, with the total time, only if any line was written.

    Parameters
    ----------
    description : str
    total : float, optional
        Units of work in all (None: unknown, no percentage or ETA).
    unit : str
        Name of a unit of work, plural (``"tiles"``, ``"points"``, ``"epochs"``).
    stream : text stream, optional
        Default ``sys.stderr`` at construction.
    clock : callable, optional
        Seconds, monotonic (``time.monotonic``); tests pass a fake one.
    min_interval : float
        Seconds between two lines at least.
    min_fraction : float
        Fraction of ``total`` between two lines at least.
    """

    def __init__(self, description: str, total: float | None = None, unit: str = "items",
                 stream: TextIO | None = None, clock: Callable[[], float] = time.monotonic,
                 min_interval: float = 5.0, min_fraction: float = 0.1):
        self.description, self.total, self.unit = description, (float(total) if total else None), unit
        self.stream = stream if stream is not None else sys.stderr
        self.clock, self.min_interval, self.min_fraction = clock, float(min_interval), float(min_fraction)
        self.t0 = self.last_t = clock()
        self.done = self.last_done = 0.0
        self.points = 0
        self.lines = 0

    def advance(self, n: float = 1, points: int = 0) -> None:
        """Count ``n`` more units of work (and ``points`` processed, shown as points/s)."""
        self.done += n
        self.points += int(points or 0)
        now = self.clock()
        if now - self.last_t < self.min_interval:
            return
        if self.total and (self.done - self.last_done) < self.min_fraction * self.total:
            return
        self._write(self.line(now))
        self.last_t, self.last_done = now, self.done

    def line(self, now: float | None = None) -> str:
        """The progress line for the state at ``now``."""
        now = self.clock() if now is None else now
        dt = max(now - self.t0, 1e-9)
        rate = self.done / dt
        cnt = f"{self.done:,.0f}" + (f"/{self.total:,.0f}" if self.total else "")
        parts = [f"{self.description}: " + (f"{100 * self.done / self.total:.0f} % ({cnt} {self.unit})"
                                             if self.total else f"{cnt} {self.unit}")]
        parts.append(f"{rate:,.3g} {self.unit}/s" if rate < 100 else f"{rate:,.0f} {self.unit}/s")
        if self.points:
            parts.append(f"{self.points / dt:,.0f} points/s")
        if self.total and rate > 0 and self.done < self.total:
            parts.append(f"ETA {format_duration((self.total - self.done) / rate)}")
        else:
            parts.append(f"elapsed {format_duration(dt)}")
        return ", ".join(parts)

    def close(self) -> None:
        """Write the closing line (done, total time) if any progress line was written."""
        if self.lines:
            now = self.clock()
            cnt = f"{self.done:,.0f} {self.unit}"
            extra = f", {self.points / max(now - self.t0, 1e-9):,.0f} points/s" if self.points else ""
            self._write(f"{self.description}: done, {cnt} in {format_duration(now - self.t0)}{extra}")

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text + "\n")
            self.stream.flush()
        except (OSError, ValueError):  # a closed or broken stream must not stop the work
            return
        self.lines += 1


@contextlib.contextmanager
def progress_bar(description: str, total: float | None = None, unit: str = "items"):
    """Context manager yielding ``advance(n)``: a rich bar on a terminal or in a notebook,
    :class:`PlainProgress` lines when stderr is not a terminal, nothing with ``-q``."""
    mode = progress_mode()
    if mode == "off":
        yield lambda n=1: None
        return
    if mode == "plain":
        plain = PlainProgress(description, total, unit)
        yield plain.advance
        plain.close()  # not reached on an error: no "done" line for a failed run
        return
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

    # a terminal's bar is erased when done; a notebook keeps its widget, redrawn here at the
    # finished state (rich's own redraws there are timed, and it makes none when it stops)
    notebook = _in_notebook()
    with Progress(
        TextColumn("[bold]{task.description}"), BarColumn(), TextColumn("{task.percentage:>5.1f}%"),
        TimeElapsedColumn(), TimeRemainingColumn(), console=stderr_console(), transient=not notebook,
    ) as prog:
        task = prog.add_task(description, total=total)
        yield lambda n=1: prog.advance(task, n)
        if notebook:
            prog.refresh()


def track(items: Iterable[T], description: str, total: int | None = None, unit: str = "items") -> Iterator[T]:
    """Iterate with progress on stderr (see :func:`progress_bar`)."""
    if total is None and hasattr(items, "__len__"):
        total = len(items)  # type: ignore[arg-type]
    with progress_bar(description, total, unit) as advance:
        for it in items:
            yield it
            advance(1)
