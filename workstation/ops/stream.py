"""Streamed inputs and outputs: a command reads one chunk, keeps what it wants, writes it on.

:func:`input_chunks` yields a file's points chunk by chunk (LAS/LAZ truly streamed, other
formats read whole and given as one chunk) and :func:`input_bounds` the extent of all of
them without reading points (the LAS header), so the writer can choose offsets that fit
every chunk before the first is written. :func:`cloud_sink` writes an output atomically:
LAS/LAZ chunk by chunk through :class:`~workstation.io.las.ChunkWriter`, other formats
gathered and written at the end. :func:`stream_select` is the loop of ``ws crop`` and
``ws filter``: a mask per chunk, the selected points to the sink.
"""

from __future__ import annotations

import contextlib
import importlib
from pathlib import Path
from typing import Callable, Iterator

import numpy as np

from workstation.core.cloud import Cloud, concatenate
from workstation.core.errors import InvalidInputError, StageError
from workstation.io import atomic_path, format_of, iter_chunks, read_cloud

CHUNK = 1_000_000  # points per streamed chunk: ~100 MB of arrays for a full LAS 1.4 record
LAS_FORMATS = ("las", "laz")


def is_las(path) -> bool:
    """Whether ``path`` names a LAS or LAZ file (by extension)."""
    return format_of(path)[0] in LAS_FORMATS


def input_chunks(path, chunk_size: int = CHUNK, **read_opts) -> Iterator[Cloud]:
    """The points of ``path`` as clouds of at most ``chunk_size`` points (LAS/LAZ streamed;
    other formats read whole, as one chunk, so the first chunk's bounds are the file's).

    ``bounds``/``resolution``/``level`` (None = not given) select points as
    :func:`workstation.io.read_cloud` does: a LAS/LAZ file is streamed and filtered chunk by
    chunk, a COPC file queried through its octree. Chunks left empty by the selection are
    skipped; a ``bounds`` holding no point of the file is an :class:`InvalidInputError`.
    """
    sel = {k: v for k, v in read_opts.items() if v is not None}
    if not is_las(path):
        yield read_cloud(path, **sel)
        return
    if not sel:
        yield from iter_chunks(path, chunk_size)
        return
    found = False
    for chunk in iter_chunks(path, chunk_size, **sel):
        if chunk.n:
            found = True
            yield chunk
    if not found and sel.get("bounds") is not None:
        raise InvalidInputError(f"no points inside --bounds {','.join(f'{v:g}' for v in sel['bounds'])}",
                                "compare the box with the file's bounds (ws info --summary FILE)", path=path,
                                field="--bounds")


def input_bounds(path) -> tuple[np.ndarray, np.ndarray] | None:
    """(lo, hi) of a LAS/LAZ file from its header (no points read); None for other formats."""
    if not is_las(path):
        return None
    from workstation.io.las import read_header

    h = read_header(path)
    return np.asarray(h["mins"], dtype=np.float64), np.asarray(h["maxs"], dtype=np.float64)


def union_bounds(bounds) -> tuple[np.ndarray, np.ndarray] | None:
    """The box around several (lo, hi) boxes; None if any is unknown."""
    bounds = list(bounds)
    if not bounds or any(b is None for b in bounds):
        return None
    return np.min([b[0] for b in bounds], axis=0), np.max([b[1] for b in bounds], axis=0)


class _GatherSink:
    """Collects chunks for a writer that needs the whole cloud (PLY, PCD, text, E57)."""

    def __init__(self, template: Cloud):
        self.parts = [template[:0]]
        self.count = 0

    def write(self, cloud: Cloud) -> None:
        self.parts.append(cloud)
        self.count += cloud.n

    def cloud(self) -> Cloud:
        return concatenate(self.parts, check_crs=False)


@contextlib.contextmanager
def cloud_sink(path, template: Cloud, *, overwrite: bool = False, inputs=(), bounds=None, **write_opts):
    """A writer for ``path`` with ``.write(cloud)`` and ``.count``, published atomically when the
    block ends without error (nothing is left behind otherwise).

    Parameters
    ----------
    template : Cloud
        A cloud with the attributes, CRS and metadata of every chunk to come (the first one).
    bounds : (lo, hi), optional
        Extent of all the points to come, for LAS offsets that fit them all.
    **write_opts
        Writer options (``point_format``, ``scales``, ``offsets`` ... for LAS).
    """
    with atomic_path(path, overwrite, inputs) as tmp:
        if is_las(path):
            from workstation.io.las import ChunkWriter

            with ChunkWriter(tmp, template, bounds=bounds, **write_opts) as writer:
                yield writer
        else:
            sink = _GatherSink(template)
            yield sink
            importlib.import_module(format_of(path)[1]).write(sink.cloud(), tmp, **write_opts)


def stream_select(src, output, select: Callable[[Cloud], np.ndarray], *, stage: str, overwrite: bool = False,
                  chunk_size: int = CHUNK, hint: str = "", read_opts: dict | None = None,
                  **write_opts) -> tuple[int, int]:
    """Write the points of ``src`` for which ``select(chunk)`` is True to ``output``, chunk by chunk
    (``read_opts``: the ``bounds``/``resolution``/``level`` selection of :func:`input_chunks`).

    Returns (points read, points written). Raises :class:`StageError` when no point is
    selected (the output is then not written), as PDAL users would otherwise find an empty
    file only later.
    """
    chunks = input_chunks(src, chunk_size, **(read_opts or {}))
    first = next(chunks, None)
    if first is None:
        raise InvalidInputError("has no points", path=src)
    total = 0
    first_mask = np.asarray(select(first), dtype=bool)  # a bad parameter fails here, before any file is made
    with cloud_sink(output, first, overwrite=overwrite, inputs=[src], bounds=input_bounds(src), **write_opts) as sink:
        for k, chunk in enumerate(chain_first(first, chunks)):
            total += chunk.n
            mask = first_mask if k == 0 else np.asarray(select(chunk), dtype=bool)
            if mask.any():
                sink.write(chunk[mask])
        if sink.count == 0:
            raise StageError(stage, f"no point of the {total:,} in {Path(src).name} was selected; nothing written",
                             hint or "check the parameters against the data (ws info)")
    return total, sink.count


def chain_first(first: Cloud, rest: Iterator[Cloud]) -> Iterator[Cloud]:
    """``first`` then the rest of its stream: the chunk a caller looked at is not read twice."""
    yield first
    yield from rest
