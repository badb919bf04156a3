"""The one-line summary every command writes on stderr when it ends (unless ``ws -q``).

One format for all: ``COMMAND: WHAT -> OUTPUTS (DETAILS) in SECONDS``, e.g.
``ground: 1,234,567 points -> out.laz (ground 41.2 %) in 12.3 s``. It goes to stderr whether
or not stderr is a terminal (a batch log keeps it); the ``--json`` document on stdout is not
affected.
"""

from __future__ import annotations

import time
from pathlib import Path

import click

#: Start of the process's command, for the time of a summary (set by the ``ws`` group).
_T0 = time.perf_counter()


def mark_start() -> None:
    """Start the clock of the command's summary (called by the ``ws`` group before a command)."""
    global _T0
    _T0 = time.perf_counter()


def elapsed() -> float:
    """Seconds since :func:`mark_start`."""
    return time.perf_counter() - _T0


def count(n, unit: str) -> str:
    """``count(1234567, "points")`` -> ``"1,234,567 points"``; singular for 1 (``"1 point"``)."""
    n = int(n)
    if n == 1 and unit.endswith("s") and not unit.endswith("ss"):
        unit = unit[:-1]
    return f"{n:,} {unit}"


def percent(part, whole) -> str:
    """``"41.2 %"`` of ``part / whole`` (``"0.0 %"`` of nothing)."""
    return f"{100.0 * float(part) / float(whole):.1f} %" if whole else "0.0 %"


def summary_line(command: str, what: str, outputs=None, seconds: float | None = None,
                 details=None) -> str:
    """The summary text: ``COMMAND: WHAT -> OUTPUTS (DETAILS) in SECONDS``.

    Parameters
    ----------
    command : str
        Command name (``"ground"``).
    what : str
        What was made or done: ``"1,234,567 points"`` (see :func:`count`).
    outputs : path or list of paths, optional
        Files written (None entries are left out).
    seconds : float, optional
        Duration; left out when None.
    details : str or list of str, optional
        Short figures in parentheses (empty entries are left out).

    Examples
    --------
    >>> summary_line("ground", "1,234,567 points", "out.laz", 12.34, "ground 41.2 %")
    'ground: 1,234,567 points -> out.laz (ground 41.2 %) in 12.3 s'
    """
    text = f"{command}: {what}"
    if outputs is not None:
        outs = [outputs] if isinstance(outputs, (str, Path)) else list(outputs)
        outs = [str(o) for o in outs if o is not None and str(o)]
        if outs:
            text += " -> " + ", ".join(outs)
    if details:
        ds = [details] if isinstance(details, str) else [d for d in details if d]
        if ds:
            text += f" ({'; '.join(ds)})"
    if seconds is not None:
        text += f" in {seconds:.2f} s" if seconds < 1 else f" in {seconds:.1f} s"
    return text


def emit_summary(command: str, what: str, outputs=None, seconds: float | None = None, details=None) -> None:
    """Write :func:`summary_line` on stderr unless ``ws -q``; ``seconds`` defaults to the time
    since the command started."""
    from workstation.core.log import is_quiet

    if is_quiet():
        return
    click.echo(summary_line(command, what, outputs, elapsed() if seconds is None else seconds, details), err=True)
