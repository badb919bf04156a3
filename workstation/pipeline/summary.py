"""The table printed on stderr at the end of ``ws run``."""

from __future__ import annotations

from workstation.core.progress import stderr_console


def print_summary(result) -> None:
    """One row per phase: tasks run / total, points, worker seconds, failures; then the errors."""
    import logging

    from rich.table import Table

    s = result.summary
    con = stderr_console()
    if logging.getLogger("workstation").getEffectiveLevel() > logging.WARNING:  # ws -q: errors only
        for f in s.get("failures", []):
            con.print(f"failed {f['task']}: {f['error']}")
        return
    table = Table(title=f"{s.get('name', 'project')}: {result.status}", title_justify="left")
    for col in ("phase", "tasks run", "of", "points", "task seconds", "failed"):
        table.add_column(col, justify="left" if col == "phase" else "right")
    for phase, c in s["phases"].items():
        table.add_row(phase, str(c["run"]), str(c["total"]), f"{c.get('points', 0):,}", f"{c.get('seconds', 0):.1f}",
                      str(c.get("failed", 0)))
    con.print(table)
    for f in s.get("failures", []):
        con.print(f"[red]failed[/red] {f['task']}: {f['error']}")
    if result.status == "planned":
        con.print("dry run: nothing was run")
    else:
        con.print(f"{result.out / 'run.json'} written in {s['seconds']:.1f} s")
