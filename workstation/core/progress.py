"""Progress on stderr (rich), silent when stderr is not a terminal unless forced."""

from __future__ import annotations

import contextlib
import os
import sys
from typing import Iterable, Iterator, TypeVar

T = TypeVar("T")
_console = None


def stderr_console():
    global _console
    if _console is None:
        from rich.console import Console

        _console = Console(stderr=True)
    return _console


def _enabled() -> bool:
    if os.environ.get("WS_PROGRESS") == "1":
        return True
    if os.environ.get("WS_PROGRESS") == "0":
        return False
    return sys.stderr.isatty()


@contextlib.contextmanager
def progress_bar(description: str, total: float | None = None):
    """Context manager yielding ``advance(n)``; draws a rich bar on stderr when interactive."""
    if not _enabled():
        yield lambda n=1: None
        return
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

    with Progress(
        TextColumn("[bold]{task.description}"), BarColumn(), TextColumn("{task.percentage:>5.1f}%"),
        TimeElapsedColumn(), TimeRemainingColumn(), console=stderr_console(), transient=True,
    ) as prog:
        task = prog.add_task(description, total=total)
        yield lambda n=1: prog.advance(task, n)


def track(items: Iterable[T], description: str, total: int | None = None) -> Iterator[T]:
    """Iterate with a progress bar on stderr."""
    if total is None and hasattr(items, "__len__"):
        total = len(items)  # type: ignore[arg-type]
    with progress_bar(description, total) as advance:
        for it in items:
            yield it
            advance(1)
