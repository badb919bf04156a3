"""How many cores this process may use (for thread pools around GIL-releasing numpy work)."""

from __future__ import annotations

import os


def available_cores() -> int:
    """Cores this process may run on: its CPU affinity on Linux, else ``os.cpu_count()``.

    Examples
    --------
    >>> available_cores() >= 1
    True
    """
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not Linux
        return max(1, os.cpu_count() or 1)


def in_blocks(block, n: int, step: int, workers: int = -1) -> None:
    """Call ``block(s)`` for the starts ``s`` of ``n`` rows in blocks of ``step``, on up to
    ``workers`` threads (-1: :func:`available_cores`; KD-tree queries and numpy release the
    GIL); with one thread, or ``n <= step``, in the caller's thread. ``block`` must write only
    its own rows and treat rows independently (as KD-tree queries and row-wise numpy do): the
    result is then that of one call over all rows, whatever the threads, while each block's
    answers and temporaries stay small, reused from the heap instead of being fresh pages the
    kernel must clear."""
    from concurrent.futures import ThreadPoolExecutor

    starts = range(0, n, step)
    threads = available_cores() if workers in (-1, None) else max(int(workers), 1)
    if threads > 1 and n > step:
        with ThreadPoolExecutor(max_workers=threads) as pool:
            list(pool.map(block, starts))
    else:
        for s in starts:
            block(s)
