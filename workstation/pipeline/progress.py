"""Progress of a project run on stderr: one rich bar per phase (tasks done / total, points/s)."""

from __future__ import annotations

import time

from workstation.core.progress import PlainProgress, progress_mode, stderr_console


class RunProgress:
    """Bars for the phases of ``tasks``; ``advance(phase, points)`` as each task ends.

    Drawn when stderr is a terminal or a notebook (or ``WS_PROGRESS=1``), plain lines per phase
    otherwise (:class:`~workstation.core.progress.PlainProgress`), nothing with ``-q``;
    ``on_progress(phase, done, total, points)`` is called either way.
    """

    def __init__(self, tasks, dashboard: str | None = None, on_progress=None):
        self.totals: dict[str, int] = {}
        for t in tasks:
            self.totals[t.phase] = self.totals.get(t.phase, 0) + 1
        self.done = {p: 0 for p in self.totals}
        self.points = {p: 0 for p in self.totals}
        self.t0 = time.perf_counter()
        self.dashboard, self.on_progress = dashboard, on_progress
        self._progress, self._bars, self._plain = None, {}, {}

    def __enter__(self):
        import logging

        if self.dashboard and logging.getLogger("workstation").getEffectiveLevel() <= logging.WARNING:
            stderr_console().print(f"Dask dashboard: {self.dashboard}")
        mode = progress_mode()
        if mode == "plain":
            self._plain = {phase: PlainProgress(phase, total, "tasks") for phase, total in self.totals.items()}
        if mode == "rich":
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

            self._progress = Progress(TextColumn("[bold]{task.description:<10}"), BarColumn(), MofNCompleteColumn(),
                                      TextColumn("{task.fields[rate]}"), TimeElapsedColumn(), console=stderr_console())
            self._progress.__enter__()
            for phase, total in self.totals.items():
                self._bars[phase] = self._progress.add_task(phase, total=total, rate="")
        return self

    def advance(self, phase: str, points: int = 0) -> None:
        now = time.perf_counter()
        self.done[phase] += 1
        self.points[phase] += int(points or 0)
        if self._progress is not None:
            dt = max(now - self.t0, 1e-3)
            rate = f"{self.points[phase] / dt:,.0f} points/s" if self.points[phase] else ""
            self._progress.update(self._bars[phase], advance=1, rate=rate)
        if phase in self._plain:
            self._plain[phase].advance(1, points=int(points or 0))
        if self.on_progress:
            self.on_progress(phase, self.done[phase], self.totals[phase], self.points[phase])

    def __exit__(self, *exc):
        if exc[0] is None:
            for plain in self._plain.values():
                plain.close()
        if self._progress is not None:
            self._progress.__exit__(*exc)
        return False
